// SPDX-License-Identifier: Apache-2.0
// hexstep tests: the golden model of the whole block (ModelSim) and the Verilated hexstep_top
// (RtlTop) ticked together behind one TopSim, every output (ack, read data, IRQ, every STEP and
// DIR pin) compared after every edge by sim/rtl_top.hpp's Lockstep. For the soak driver
// (tests/soak/) and the fault tests (tests/rtl/test_faults.cpp): drive it with a Bus or run_job
// like either simulator alone; mismatches are kept as text so each user reports them its own
// way (GoogleTest failure, soak log).
#pragma once

#include <cstdint>
#include <string>

#include "hexstep/top_sim.hpp"
#include "rtl_top.hpp"

namespace hexstep::test {

class LockstepPair : public TopSim {
 public:
  // trace_path: FST trace of the RTL (empty: none; TRACE=1 in the environment writes one).
  explicit LockstepPair(const std::string& trace_path = "") : rtl_(trace_path), pair_(model_, rtl_) {}
  void reset() override { pair_.reset(); }
  void tick(const WbPins& in) override { pair_.tick(in); }
  bool ack() const override { return pair_.ack(); }
  uint32_t dat() const override { return pair_.dat(); }
  bool irq() const override { return pair_.irq(); }
  bool step(unsigned k) const override { return pair_.step(k); }
  bool dir(unsigned k) const override { return pair_.dir(k); }
  unsigned naxes() const override { return pair_.naxes(); }
  Widths widths() const override { return pair_.widths(); }
  std::string name() const override { return pair_.name(); }

  // The model's state, for oracles beyond the pins (positions, queues, the running move).
  const TopModel& model() const { return model_.model(); }
  uint64_t mismatches() const { return pair_.mismatches(); }
  uint64_t edges() const { return pair_.edges(); }
  // The first mismatches, one line each (with `context` when set).
  const std::string& report() const { return pair_.report(); }
  std::string& context() { return pair_.context; }

 private:
  ModelSim model_;
  RtlTop rtl_;
  Lockstep pair_;
};

}  // namespace hexstep::test
