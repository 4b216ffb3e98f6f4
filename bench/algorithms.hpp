// SPDX-License-Identifier: Apache-2.0
// hexstep bench: the step-timing algorithms hexstep is compared with, each written from its
// source document in /work/shared/seeds (docs/BENCH.md, "Comparison algorithms"). Every
// algorithm reports its pulses through a callback: 1-based step index and the pulse instant in
// seconds after the move's time zero. None of them shares code with planner/ or cpp_model/.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace hexstep::bench {

using real = long double;
// (step index i, 1-based; instant in seconds)
using PulseFn = std::function<void(uint64_t, real)>;

struct AlgoResult {
  uint64_t pulses = 0;    // pulses emitted
  bool finished = true;   // false: stopped by the harness's time limit (stall)
};

// ---- AVR446 / Austin (avr446-linear-speed-control.txt) --------------------------------------
// Rest to rest: step count, acceleration, deceleration (steps/s^2) and speed (steps/s), on an
// integer timer counting f_clk. c0 = 0.676 * f * sqrt(2/a) (section 2.3.1), recurrence
// c_n = c_(n-1) - (2 c_(n-1) + rest) / (4 n + 1) with the remainder carried (3.2.2.1), the
// ACCEL/RUN/DECEL state machine of 3.2.2 with max_s_lim, accel_lim, decel_val, decel_start of
// 3.2.1. Pulse i is emitted when the i-th timer delay expires (the first delay is c0).
struct Avr446Setup {
  int64_t c0 = 0, min_delay = 0;
  int64_t max_s_lim = 0, accel_lim = 0, decel_val = 0, decel_start = 0;
  bool start_in_run = false;
};
Avr446Setup avr446_setup(uint64_t steps, real accel, real decel, real speed, real f_clk);
AlgoResult avr446_run(uint64_t steps, real accel, real decel, real speed, real f_clk, const PulseFn& fn);

// ---- Stoychitch (2018), section 3.1: time per step --------------------------------------------
// Start/end speed vs > 0, maximum speed vM, acceleration aM, ratio m = a/d. Phase step counts
// from section 2 (eq. 4-8), delays from eq. 11-13 in double precision, the corrections of
// eq. 14 on the first and last five delays, each delay rounded to whole f_clk timer counts.
struct StoychitchPlan {
  bool triangular = true;
  uint64_t Na = 0, Nv = 0, Nd = 0;
};
StoychitchPlan stoychitch_plan(uint64_t N, real vs, real vM, real aM, real m);
AlgoResult stoychitch_run(uint64_t N, real vs, real vM, real aM, real m, real f_clk, const PulseFn& fn);
// eq. 11/12 one step: c_i = c_(i-1) / (1 + R c_(i-1)^2)
double stoychitch_next(double c, double R);

// ---- Stoychitch (2018) appendix: the Arduino steps-per-time program ---------------------------
// float arithmetic, an interrupt at f_isr (10 kHz in the paper), planTrajek() with alfa = 1
// step; loop()'s phase switches evaluated after every interrupt. At most one step per
// interrupt: moves faster than f_isr steps/s cannot be represented.
struct ArduinoPlan {
  long N = 0, Na = 0, Nv = 0, Nd = 0;
  float Vsf = 0, Af = 0, Df = 0;
};
ArduinoPlan arduino_plan(long N, float vs, float vM, float aM, float m, float f_isr);
AlgoResult arduino_run(long N, float vs, float vM, float aM, float m, float f_isr, real time_limit_s,
                       const PulseFn& fn);

// ---- hostmot2-style first-order DDA -----------------------------------------------------------
// A 32-bit-fraction accumulator adds a rate register every f_clk cycle; a step is emitted when
// the integer part grows. Every servo period the rate is set to reach the ideal position at
// the end of the period from the accumulator's current position (mean ideal speed of the
// period plus the accumulator's own error; rounded up), as LinuxCNC's position-mode stepgen
// drives a Mesa card. `ideal_position(t)` is the commanded motion.
AlgoResult dda_run(uint64_t N, real duration_s, const std::function<real(real)>& ideal_position,
                   real f_clk, real f_servo, const PulseFn& fn);

}  // namespace hexstep::bench
