// SPDX-License-Identifier: Apache-2.0
// hexstep: the interface that both the cycle-exact model (TopModel) and the Verilated RTL
// (sim/rtl_top.hpp) implement, so that one bus master, one job runner and one set of tests
// drive either, and a lock-step pair (Lockstep) compares them after every edge.
#pragma once

#include <cstdint>
#include <string>

#include "hexstep/top_model.hpp"

namespace hexstep {

class TopSim {
 public:
  virtual ~TopSim() = default;
  // Synchronous reset; afterwards the block runs its initialization (the bus waits for it).
  virtual void reset() = 0;
  // One rising clock edge with these inputs applied during the cycle before it.
  virtual void tick(const WbPins& in) = 0;
  virtual bool ack() const = 0;
  virtual uint32_t dat() const = 0;
  virtual bool irq() const = 0;
  virtual bool step(unsigned axis) const = 0;  // STEP pin
  virtual bool dir(unsigned axis) const = 0;   // DIR pin
  virtual unsigned naxes() const = 0;
  virtual Widths widths() const = 0;
  // Event mode (where supported): edges that can be skipped with `in` held; 0 if none.
  virtual uint64_t quiet_cycles(const WbPins&) const { return 0; }
  virtual void skip(uint64_t) {}
  // A name for messages ("model", "rtl").
  virtual std::string name() const = 0;
};

// The model behind the interface.
class ModelSim : public TopSim {
 public:
  explicit ModelSim(unsigned naxes = kNumAxes, const Widths& w = Widths{}) : m_(naxes, w) {}
  void reset() override { m_.reset(); }
  void tick(const WbPins& in) override { m_.tick(in); }
  bool ack() const override { return m_.ack(); }
  uint32_t dat() const override { return m_.dat(); }
  bool irq() const override { return m_.irq(); }
  bool step(unsigned k) const override { return m_.step(k); }
  bool dir(unsigned k) const override { return m_.dir(k); }
  unsigned naxes() const override { return m_.naxes(); }
  Widths widths() const override { return m_.widths(); }
  uint64_t quiet_cycles(const WbPins& in) const override { return m_.quiet_cycles(in); }
  void skip(uint64_t k) override { m_.skip(k); }
  std::string name() const override { return "model"; }
  TopModel& model() { return m_; }
  const TopModel& model() const { return m_; }

 private:
  TopModel m_;
};

}  // namespace hexstep
