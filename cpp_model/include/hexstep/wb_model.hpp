// SPDX-License-Identifier: Apache-2.0
// hexstep: cycle-exact model of rtl/hexstep_top.v: the Wishbone register block (hexstep_wb)
// around the core model. Every state element and rule here has its counterpart in
// rtl/hexstep_wb.v; the register map is rdl/hexstep.rdl (docs/REGISTERS.md).
#pragma once

#include <array>
#include <cstdint>

#include "hexstep/core.hpp"

namespace hexstep {

// The inputs of hexstep_top during one clock cycle (sampled at its rising edge).
struct WbPins {
  bool cyc = false;
  bool stb = false;
  bool we = false;
  uint32_t adr = 0;  // byte address (ADDR_W = 12 bits used)
  uint32_t dat = 0;
  unsigned sel = 0;  // byte enables, 4 bits
  bool estop = false;
};

class WbModel {
 public:
  // The word layout of the map (rdl/hexstep.rdl), shared with the tests.
  static constexpr unsigned kNw = 17;  // staging words per axis (STEPS..DEC_FRAC)
  static constexpr unsigned kNc = 5;   // pulse config words per axis (STEP_HIGH..POLARITY)
  static constexpr uint32_t kId = 0x48585354u;
  static constexpr uint32_t kVersionMajor = 0, kVersionMinor = 2;

  explicit WbModel(const Widths& w = Widths{});
  void reset();
  // One rising clock edge with these inputs.
  void tick(const WbPins& in);

  // Registered outputs after the last edge.
  bool ack() const { return ack_q_; }
  uint32_t dat() const { return dat_q_; }
  bool irq() const { return irq_q_; }
  // STEP/DIR pins: the core's levels through the polarity register as it is now (the RTL
  // applies POLARITY combinationally).
  bool step(unsigned k) const { return core_.axis(k).step_level() != bool(cfg_[k][kNc - 1] & 1u); }
  bool dir(unsigned k) const { return core_.axis(k).dir_level() != bool(cfg_[k][kNc - 1] & 2u); }
  const CoreModel& core() const { return core_; }
  // Moves queued for axis k (0..2).
  unsigned queued(unsigned k) const { return cnt_[k]; }
  bool running(unsigned k) const { return run_[k]; }
  // What the core was given at the last edge (start/abort/stop strobes, queue head, pulse
  // configuration): lets a test see when the block starts or aborts an axis.
  const CoreInputs& core_inputs() const { return core_in_; }

 private:
  using Words = std::array<uint32_t, kNw>;
  Widths w_;
  CoreModel core_;
  CoreInputs core_in_;
  bool ack_q_ = false, irq_q_ = false;
  uint32_t dat_q_ = 0;
  bool es1_ = false, es2_ = false, estop_ = false;
  uint32_t start_cmd_ = 0, abort_cmd_ = 0, stop_cmd_ = 0;
  uint32_t irq_en_ = 0, pend_ = 0;
  std::array<bool, kNumAxes> run_{};
  std::array<unsigned, kNumAxes> cnt_{};
  std::array<uint32_t, kNumAxes> errf_{};   // {estop, overrun, move}
  std::array<uint32_t, kNumAxes> poshi_{};
  std::array<Words, kNumAxes> stg_{}, q0_{}, q1_{};
  std::array<std::array<uint32_t, kNc>, kNumAxes> cfg_{};

  uint32_t stg_mask(unsigned i) const;
  uint32_t cfg_mask(unsigned i) const;
  AxisMove move_of(const Words& wds) const;
  PulseConfig pulse_of(unsigned k) const;
};

}  // namespace hexstep
