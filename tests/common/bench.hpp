// SPDX-License-Identifier: Apache-2.0
// hexstep tests: the Verilated hexstep_top and TopModel in lock step (sim/rtl_top.hpp Lockstep:
// ack, read data, IRQ and every STEP/DIR pin compared after every edge), the output-timing
// monitor on every axis (monitor.hpp), and a Wishbone master (hexstep/bus.hpp) in front of
// them. The model's state is there for oracles beyond the pins. Only one Bench (one RtlTop) may
// exist at a time: the Verilated model's destructor hangs while a second one is alive
// (reported to the lead; sim/rtl_top.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "hexstep/bus.hpp"
#include "hexstep/job.hpp"
#include "monitor.hpp"
#include "rtl_top.hpp"

namespace hexstep::test {

class Bench {
 public:
  // The model is built with the Verilated build's axes and widths.
  explicit Bench(uint32_t bus_seed = 1)
      : model(RtlTop::rtl_naxes(), RtlTop::rtl_widths()), pair(model, rtl), mon(pair, model.model()),
        bus(mon, bus_seed) {
    bus.reset();
  }
  Bench(const Bench&) = delete;
  Bench& operator=(const Bench&) = delete;

  ModelSim model;
  RtlTop rtl;
  Lockstep pair;
  Monitored mon;
  Bus bus;

  const TopModel& m() const { return model.model(); }
  uint64_t cycle() const { return bus.cycles(); }
  void idle(uint64_t n) { bus.idle(n); }
  // Edges until pred() holds after one (false if `limit` edges pass first).
  bool run_until(const std::function<bool()>& pred, uint64_t limit = 2'000'000) {
    for (uint64_t i = 0; i < limit; ++i) {
      bus.idle(1);
      if (pred()) return true;
    }
    return false;
  }
  // Every axis at rest (nothing running, nothing pending in the output stages).
  bool all_idle() const {
    for (unsigned k = 0; k < m().naxes(); ++k)
      if (m().busy(k) || m().running(k)) return false;
    return true;
  }
  // A START or STOP written just before acts within two frames; then every axis comes to rest.
  bool settle(uint64_t limit = 2'000'000) {
    idle(2 * kFrameCycles + kSlotCycles * kSlots);
    return run_until([this] { return all_idle(); }, limit);
  }

  uint32_t read(uint32_t adr) { return bus.read(adr); }
  void write(uint32_t adr, uint32_t dat, unsigned sel = 0xF) { bus.write(adr, dat, sel); }
  uint32_t axr(unsigned k, uint32_t reg) { return bus.read(ax_reg(k, reg)); }
  void axw(unsigned k, uint32_t reg, uint32_t dat, unsigned sel = 0xF) { bus.write(ax_reg(k, reg), dat, sel); }
  void push(unsigned k, const AxisMove& mv) { push_move(bus, k, mv); }
  void set_pulse(unsigned k, const PulseConfig& p) {
    namespace A = regs::axis;
    axw(k, A::STEP_HIGH, p.step_high);
    axw(k, A::STEP_LOW, p.step_low);
    axw(k, A::DIR_SETUP, p.dir_setup);
    axw(k, A::DIR_HOLD, p.dir_hold);
    axw(k, A::POLARITY, (p.step_invert ? 1u : 0u) | (p.dir_invert ? 2u : 0u));
  }
  int64_t position(unsigned k) {
    const uint32_t lo = axr(k, regs::axis::POS_LO);
    const uint32_t hi = axr(k, regs::axis::POS_HI);
    return static_cast<int64_t>((uint64_t(hi) << 32) | lo);
  }
  uint32_t status(unsigned k) { return axr(k, regs::axis::STATUS); }
  unsigned free_slots(unsigned k) {
    return (status(k) & regs::axis::STATUS_FREE_MASK) >> regs::axis::STATUS_FREE_SHIFT;
  }
  uint64_t rises(unsigned k) const { return mon.monitor(k).rises; }

  // RTL == model so far, the timing monitor clean, no Wishbone protocol error; as one message
  // ("" if all is well).
  std::string problems() const {
    std::string t;
    if (pair.mismatches())
      t += std::to_string(pair.mismatches()) + " RTL/model mismatches:\n" + pair.report();
    t += mon.errors();
    if (bus.protocol_errors()) t += std::to_string(bus.protocol_errors()) + " Wishbone protocol errors\n";
    return t;
  }
};

}  // namespace hexstep::test
