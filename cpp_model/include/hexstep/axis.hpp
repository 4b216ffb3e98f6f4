// SPDX-License-Identifier: Apache-2.0
// hexstep: cycle-exact model of one axis (rtl/hexstep_axis.v + rtl/hexstep_pulse.v).
#pragma once

#include <cstdint>

#include "hexstep/widths.hpp"

namespace hexstep {

// Everything one move needs, in register units (docs/ARCHITECTURE.md, "Registers of a move").
struct AxisMove {
  uint32_t steps = 0;       // N: exact number of steps
  bool dir = true;          // true: positive direction
  uint64_t v_start = 0;     // initial value of the speed accumulator, 2^-64 step/tick
  uint64_t v_max = 0;       // speed ceiling (accelerate clamps here)
  uint64_t v_end = 0;       // speed floor while decelerating (0: floor = dec)
  uint64_t acc = 0;         // added to speed every tick while accelerating
  uint64_t dec = 0;         // subtracted from speed every tick while decelerating
  uint64_t v_dec = 0;       // speed accumulator value loaded on the first decelerating tick
  uint32_t acc_steps = 0;   // acceleration ends when this many steps are done (or at v_max)
  uint32_t dec_step = 0;    // deceleration starts at position dec_step + dec_frac / 2^DFRAC_W
  uint32_t dec_frac = 0;
  bool jog = false;         // continuous move: ignores steps/acc_steps/dec_*, ends by STOP
};

// Output timing of STEP/DIR, in clock cycles. Static configuration, sampled every cycle.
struct PulseConfig {
  uint32_t step_high = 1;   // STEP high time (0 acts as 1)
  uint32_t step_low = 1;    // minimum STEP low time (0 acts as 1)
  uint32_t dir_setup = 0;   // DIR stable this many cycles before a STEP rising edge
  uint32_t dir_hold = 0;    // DIR stable this many cycles after a STEP rising edge
  bool step_invert = false; // STEP pin active low
  bool dir_invert = false;  // DIR pin low for positive motion
};

enum class Phase : uint8_t { Idle = 0, Accel = 1, Cruise = 2, Decel = 3 };

// Why a move was refused at its start strobe (the axis does not move; done and err pulse).
enum MoveError : uint32_t {
  kErrNone = 0,
  kErrVmaxZero = 1u << 0,       // v_max == 0
  kErrStartAboveMax = 1u << 1,  // v_start > v_max
  kErrEndAboveMax = 1u << 2,    // floor above v_max: v_end > v_max, or v_end == 0 && dec > v_max
  kErrCountPastN = 1u << 3,     // acc_steps > steps or dec_step > steps
  kErrNoFloor = 1u << 4,        // v_end == 0 and dec == 0: deceleration could stall
  kErrNoStart = 1u << 5,        // v_start == 0 and nothing accelerates it: would stall
  kErrDecAboveMax = 1u << 6,    // v_dec > v_max
  kErrJogNoDec = 1u << 7,       // jog move with dec == 0: STOP could never bring it to rest
};

// Checks a move the way the core's start logic does. Returns a MoveError bit set.
uint32_t validate_move(const AxisMove& m, const Widths& w = Widths{});

class AxisModel {
 public:
  explicit AxisModel(const Widths& w = Widths{}) : w_(w) { reset(); }

  void reset();
  // One rising clock edge. start: this axis is selected by the start strobe. abort: stop now.
  // stop: controlled stop strobe (decelerate by dec to rest; docs/ARCHITECTURE.md).
  void tick(bool start, bool abort, bool stop, const AxisMove& move, const PulseConfig& pc);
  void tick(bool start, bool abort, const AxisMove& move, const PulseConfig& pc) {
    tick(start, abort, false, move, pc);
  }

  // Registered outputs after the last edge.
  bool step_pin(const PulseConfig& pc) const { return step_q_ != pc.step_invert; }
  bool dir_pin(const PulseConfig& pc) const { return dir_q_ != pc.dir_invert; }
  bool step_level() const { return step_q_; }  // before polarity: 1 while the pulse is high
  bool dir_level() const { return dir_q_; }    // before polarity: 1 for positive motion
  bool busy() const { return run_q_ || owed_q_ != 0; }
  bool done() const { return done_q_; }
  bool err() const { return err_q_; }
  Phase phase() const { return phase_q_; }
  bool stopping() const { return run_q_ && stop_q_; }
  int64_t position() const;  // signed, POS_W bits, wraps
  uint32_t steps_done() const { return cnt_q_; }
  uint64_t speed() const { return s_q_; }
  uint64_t frac() const { return p_q_; }
  unsigned owed() const { return owed_q_; }
  // True when a rising STEP edge happened at the last tick.
  bool rose() const { return rose_q_; }

  // Event mode support: number of ticks that can be skipped from now without any output or
  // control-relevant change, assuming no start/abort input meanwhile (0 if none can be).
  uint64_t quiet_ticks(const PulseConfig& pc) const;
  // Advances the state by k ticks known to be quiet (k <= quiet_ticks()).
  void skip(uint64_t k);

 private:
  Widths w_;
  // Move registers latched at start.
  AxisMove cfg_{};
  uint64_t floor_ = 0;
  // Generator state.
  bool run_q_ = false;
  Phase phase_q_ = Phase::Idle;
  uint64_t s_q_ = 0;   // speed accumulator
  uint64_t p_q_ = 0;   // position fraction
  uint32_t cnt_q_ = 0; // steps generated in this move
  bool dec_first_q_ = false;  // the next decelerating tick loads v_dec
  bool stop_q_ = false;       // controlled stop in progress
  unsigned owed_q_ = 0;
  // Pulse stage.
  bool step_q_ = false;
  bool dir_q_ = true;
  bool dir_tgt_q_ = true;
  uint32_t c_q_ = 0;  // cycles since the last STEP rising edge, saturating (PULSE_W+1 bits)
  uint32_t d_q_ = 0;  // cycles since the last DIR change, saturating (PULSE_W bits)
  uint64_t pos_q_ = 0;
  bool done_q_ = false;
  bool err_q_ = false;
  bool rose_q_ = false;

  uint32_t c_max() const { return (1u << (w_.pulse + 1)) - 1u; }
  uint32_t d_max() const { return (1u << w_.pulse) - 1u; }
  // Generator ticks (from now) until its next event; helper of quiet_ticks().
  uint64_t gen_quiet_ticks() const;
};

}  // namespace hexstep
