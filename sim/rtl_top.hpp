// SPDX-License-Identifier: Apache-2.0
// hexstep: the Verilated rtl/hexstep_top.v behind the TopSim interface (cpp_model/top_sim.hpp).
#pragma once

#include <memory>
#include <string>

#include "hexstep/top_sim.hpp"

namespace hexstep {

class RtlTop : public TopSim {
 public:
  // trace_path: write an FST trace there (empty: none; TRACE=1 in the environment writes
  // hexstep_<n>.fst in the working directory).
  explicit RtlTop(const std::string& trace_path = "");
  ~RtlTop() override;
  void reset() override;
  void tick(const WbPins& in) override;
  bool ack() const override;
  uint32_t dat() const override;
  bool irq() const override;
  bool step(unsigned axis) const override;
  bool dir(unsigned axis) const override;
  unsigned naxes() const override;
  Widths widths() const override { return rtl_widths(); }
  std::string name() const override { return "rtl"; }
  uint64_t cycles() const;

  // The Verilog parameters of the built design, read from the Verilated model.
  static Widths rtl_widths();
  static unsigned rtl_naxes();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Two simulators in lock step: every edge goes to both, and every output is compared after it.
// The first differences are kept as text; the pair reports the reference's (a's) outputs.
class Lockstep : public TopSim {
 public:
  Lockstep(TopSim& a, TopSim& b) : a_(a), b_(b) {}
  void reset() override;
  void tick(const WbPins& in) override;
  bool ack() const override { return a_.ack(); }
  uint32_t dat() const override { return a_.dat(); }
  bool irq() const override { return a_.irq(); }
  bool step(unsigned k) const override { return a_.step(k); }
  bool dir(unsigned k) const override { return a_.dir(k); }
  unsigned naxes() const override { return a_.naxes(); }
  Widths widths() const override { return a_.widths(); }
  std::string name() const override { return a_.name() + "+" + b_.name(); }

  uint64_t mismatches() const { return mismatches_; }
  uint64_t edges() const { return edges_; }
  const std::string& report() const { return report_; }
  std::string context;  // what the test is doing (in reports)

 private:
  TopSim& a_;
  TopSim& b_;
  uint64_t mismatches_ = 0, edges_ = 0;
  std::string report_;
};

}  // namespace hexstep
