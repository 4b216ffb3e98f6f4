// SPDX-License-Identifier: Apache-2.0
// hexstep: one axis of the frame engine. AxisGen is the per-tick generator (the arithmetic of
// rtl/hexstep_engine.v for one axis and one slot), PulseStage the cycle-level STEP/DIR output
// stage (rtl/hexstep_pulse.v). hexstep::TopModel (top_model.hpp) schedules them cycle by cycle
// as rtl/hexstep_top.v does; docs/ARCHITECTURE.md describes the semantics in prose.
#pragma once

#include <cstdint>
#include <vector>

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
  bool operator==(const AxisMove& o) const {
    return steps == o.steps && dir == o.dir && v_start == o.v_start && v_max == o.v_max &&
           v_end == o.v_end && acc == o.acc && dec == o.dec && v_dec == o.v_dec &&
           acc_steps == o.acc_steps && dec_step == o.dec_step && dec_frac == o.dec_frac && jog == o.jog;
  }
};

// Output timing of STEP/DIR, in clock cycles. Live configuration, used every cycle.
struct PulseConfig {
  uint32_t step_high = 1;   // STEP high time (0 acts as 1)
  uint32_t step_low = 1;    // minimum STEP low time (0 acts as 1)
  uint32_t dir_setup = 0;   // DIR stable this many cycles before a STEP rising edge
  uint32_t dir_hold = 0;    // DIR stable this many cycles after a STEP rising edge
  bool step_invert = false; // STEP pin active low
  bool dir_invert = false;  // DIR pin low for positive motion
};

enum class Phase : uint8_t { Idle = 0, Accel = 1, Cruise = 2, Decel = 3 };

// Why a move is refused (the axis does not move; done and ERR.move are reported).
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

// The refusal rules of the core (the loader of rtl/hexstep_loader.v evaluates them when a move
// is pushed). Returns a MoveError bit set; kErrNone for a valid move and for an empty one
// (steps == 0, not jog), which the core completes at once without an error.
uint32_t validate_move(const AxisMove& m, const Widths& w = Widths{});

// A move as the loader stores it in a queue slot: the registers the engine reads, with the
// deceleration floor resolved, and the flags the start logic needs.
struct SlotMove {
  AxisMove m;               // the staged move, masked to the register widths
  uint64_t floor = 0;       // v_end != 0 ? v_end : dec
  uint32_t dfa = 0;         // dec_frac aligned to the top of 32 bits (<< (32 - DFRAC_W))
  bool bad = false;         // refused (validate_move != kErrNone)
  bool empty = false;       // steps == 0 and not jog: completes at once
  Phase init = Phase::Idle; // phase of the first tick
  bool dec_zero = false;    // dec == 0 (a STOP then ends the move at once)
};
SlotMove make_slot(const AxisMove& staged, const Widths& w = Widths{});

// What one tick produced.
struct TickOut {
  bool step = false;     // a whole step was crossed during the tick
  unsigned q = 0;        // its sub-tick offset: cycles before the end of the tick (0..31)
  bool ended = false;    // the move's last tick (N-th step generated, or the stop came to rest)
};

// The per-tick generator of one axis (the arithmetic of one slot of rtl/hexstep_engine.v).
class AxisGen {
 public:
  // Loads a move (the start of a slot with a new move); the first tick follows at once.
  void begin(const SlotMove& s);
  // One tick of the running move (run() must be true).
  TickOut tick();
  // Controlled stop from the next tick on: decelerate by dec to rest, no v_dec, no floor.
  void enter_stop();
  void halt() { run_ = false; phase_ = Phase::Idle; }  // abort

  bool run() const { return run_; }
  Phase phase() const { return run_ ? phase_ : Phase::Idle; }
  bool stopping() const { return run_ && stop_; }
  bool jog() const { return cfg_.m.jog; }
  uint64_t speed() const { return s_; }
  uint64_t frac() const { return p_; }
  // Steps generated in this move (for a jog move: modulo 2^32).
  uint32_t steps_done() const { return static_cast<uint32_t>(cfg_.m.steps - re_); }
  const SlotMove& slot() const { return cfg_; }

  // Event mode: ticks that can pass from now with no step, no phase change, no clamp and no
  // end of the move (quiet ticks), and the jump over k of them.
  uint64_t quiet_ticks() const;
  void skip(uint64_t k);

 private:
  SlotMove cfg_{};
  bool run_ = false;
  Phase phase_ = Phase::Idle;
  bool dec_first_ = false;  // the next decelerating tick loads v_dec
  bool stop_ = false;       // controlled stop in progress
  uint64_t s_ = 0;          // speed accumulator (mid-tick speed)
  uint64_t p_ = 0;          // position fraction
  uint32_t re_ = 0, ra_ = 0, rd_ = 0;  // steps to the end, to acc_steps, to dec_step
};

// Sub-tick offset of a step: floor(32 * e / s) on the top kSubtickBits bits of the overshoot e
// (the position fraction after the carry) and of the speed s, by a 5-step restoring division
// (at most 31); 0 when the top bits of s are all zero. rtl/hexstep_engine.v, "sub-tick".
unsigned subtick(uint64_t e, uint64_t s);

// The STEP/DIR output stage of one axis (rtl/hexstep_pulse.v), cycle by cycle.
class PulseStage {
 public:
  PulseStage() { reset(); }
  explicit PulseStage(const Widths& w) : w_(w) { reset(); }
  void reset();
  // One rising clock edge at the end of cycle `cycle`. abort: the axis's abort line during that
  // cycle. req_due: a step request committed at this edge, due at that cycle (0: none).
  // tgt: the direction of a move started at this edge (-1: none).
  void edge(uint64_t cycle, bool abort, const PulseConfig& pc, uint64_t req_due, int tgt);

  bool step_level() const { return step_; }  // before polarity: 1 while the pulse is high
  bool dir_level() const { return dir_; }    // before polarity: 1 for positive motion
  bool dir_target() const { return tgt_; }
  int64_t position() const;                  // signed, POS_W bits, wraps
  unsigned owed() const { return owed_; }
  unsigned requests() const { return static_cast<unsigned>(due_.size()); }
  // Steps generated but not yet pulsed (requests waiting for their cycle, and owed steps).
  bool pending() const { return owed_ != 0 || !due_.empty(); }
  // The generator may produce a step this tick: fewer than 3 steps wait (requests and owed
  // together; there are 3 request entries).
  bool accepts() const { return owed_ + due_.size() < 3; }
  // Event mode: cycles from the end of `cycle` on that change nothing but the saturating
  // counters (0 if something happens at the next edge).
  uint64_t quiet_cycles(uint64_t cycle, const PulseConfig& pc) const;
  void skip(uint64_t k);

 private:
  Widths w_;
  std::vector<uint64_t> due_;  // due cycles of the request entries (at most 3)
  unsigned owed_ = 0;
  bool step_ = false, dir_ = true, tgt_ = true;
  // Interval counters (rtl/hexstep_pulse.v): loaded at the event that starts the interval,
  // counting down to 0; the interval is over at 1 or 0.
  uint32_t h_ = 0;  // high time left (loaded at a rise)
  uint32_t l_ = 0;  // low time left (loaded at a fall)
  uint32_t u_ = 0;  // DIR hold left (loaded at a rise)
  uint32_t s_ = 0;  // DIR setup left (loaded at a DIR change)
  uint64_t pos_ = 0;
};

}  // namespace hexstep
