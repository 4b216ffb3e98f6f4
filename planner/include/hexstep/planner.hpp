// SPDX-License-Identifier: Apache-2.0
// hexstep planner: decides the linear-ramp profile of a move (host side) and turns it into the
// core's registers. No I/O. docs/PLANNER.md derives every equation used here.
//
//   units       distance/speed/acceleration in steps, rev, deg, rad or mm -> steps
//   plan_min_time   fastest move within the limits (Stoychitch 2018, section 2, generalised)
//   plan_timed      N steps in a given time (Ranade 2009), triangular or trapezoidal
//   stoychitch_counts, avr446_counts   the seeds' own integer step counts, literally
//   encode          PhasePlan -> registers (hexstep::encode_ramp), range checks named by flag
//   independent, coordinated_line      six axes: each alone, or a straight line together
//
// Every error is a PlanError (std::invalid_argument) whose one-line message starts with the
// command-line flag of the offending value (`--max-speed: ...`) and states the accepted range.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hexstep/encoding.hpp"

namespace hexstep::plan {

using hexstep::real;

class PlanError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A time budget shorter than the fastest move the limits allow.
class InfeasibleTime : public PlanError {
 public:
  InfeasibleTime(const std::string& what, real requested_s, real min_time_s)
      : PlanError(what), requested_(requested_s), min_time_(min_time_s) {}
  real requested_time() const { return requested_; }
  // Duration of the minimum-time plan for the same steps and limits (s).
  real min_time() const { return min_time_; }

 private:
  real requested_;
  real min_time_;
};

// Largest step count of one move (STEP_W = 32 bits).
constexpr uint64_t kMaxSteps = 0xFFFFFFFFull;

// ---------------------------------------------------------------------------------------------
// Units

enum class Unit { Steps, Rev, Deg, Rad, Mm };

// "steps", "rev", "deg", "rad", "mm". Throws PlanError naming --unit.
Unit parse_unit(const std::string& name);
const char* unit_name(Unit u);

// Scale factors; a factor that is not given is std::nullopt. Every factor given must be finite
// and > 0 (--steps-per-rev, --steps-per-mm, --pitch-mm), whether the unit uses it or not.
struct Scale {
  std::optional<real> steps_per_rev;  // K: steps per revolution (rev, deg, rad; mm with pitch)
  std::optional<real> steps_per_mm;   // linear axis: steps per mm
  std::optional<real> pitch_mm;       // lead screw: mm per revolution (mm = K / pitch steps)
};

// Steps per unit: steps 1; rev K; deg K/360; rad K/(2 pi); mm steps_per_mm, else K/pitch_mm
// (both given: they must agree to 1e-9). Throws PlanError naming the missing/invalid factor.
real steps_per_unit(Unit u, const Scale& s);

// value * steps_per_unit: the same factor converts distance, speed (/s) and acceleration (/s^2).
real to_steps(real value, Unit u, const Scale& s);

struct StepCount {
  uint32_t steps = 0;  // N = round(|distance| in steps) (Stoychitch: nearest integer)
  bool dir = true;     // true: distance >= 0 (positive direction)
  real exact = 0;      // |distance| in steps before rounding
};

// A signed distance in `u` -> N and direction. Throws PlanError naming --distance if it is not
// finite or N would exceed kMaxSteps.
StepCount distance_to_steps(real distance, Unit u, const Scale& s);

// ---------------------------------------------------------------------------------------------
// Limits

// Limits of one move. In steps/s and steps/s^2 for the planners; limits_to_steps() converts
// from another unit.
struct Limits {
  real max_speed = 0;             // --max-speed v_max: > 0
  real accel = 0;                 // --accel a: > 0
  std::optional<real> decel;      // --decel d: > 0. Default: accel / ratio
  std::optional<real> ratio;      // --ratio m = a/d (Stoychitch): > 0. Default 1. Not with --decel
  real start_speed = 0;           // --start-speed v_s: in [0, max_speed]
  std::optional<real> end_speed;  // --end-speed: in [0, max_speed]. Default: start_speed
};

// Every speed and acceleration multiplied by steps_per_unit(u, s) (ratio unchanged). Validates
// the limits first (finite, positive where required), so messages quote the caller's values.
Limits limits_to_steps(const Limits& lim, Unit u, const Scale& s);

// Limits with the defaults applied, validated, in steps/s and steps/s^2.
struct RampLimits {
  real v_start = 0, v_end = 0, v_max = 0, accel = 0, decel = 0;
};
// Throws PlanError naming the flag: NaN, infinite, negative or zero where > 0 is required,
// start or end speed above the maximum speed, --decel together with --ratio.
RampLimits resolve(const Limits& lim);

// ---------------------------------------------------------------------------------------------
// Plans

enum class Profile {
  Empty,        // N = 0
  Constant,     // one speed throughout (v_start == v_end == v_max, or a slow timed move)
  Triangular,   // accelerate, then decelerate; the peak is below v_max (no cruise)
  Trapezoidal,  // accelerate to v_max, cruise, decelerate (a ramp may have zero length)
  AccelOnly,    // too short to reach the higher end speed: accelerates all the way (warning)
  DecelOnly,    // too short to slow to the lower end speed: decelerates all the way (warning)
};
const char* profile_name(Profile p);  // "empty", "constant", "triangular", ...

// A decided linear-ramp profile: v_start -> (accelerate at a) -> v_peak -> (cruise) ->
// (decelerate at d) -> v_end, exactly `steps` steps. Speeds in steps/s, accelerations in
// steps/s^2, times in s, distances in (real-valued) steps.
struct PhasePlan {
  Profile profile = Profile::Empty;
  uint32_t steps = 0;  // N
  bool dir = true;
  real v_start = 0, v_peak = 0, v_end = 0;  // v_end: the end speed actually reached
  real end_speed_requested = 0;             // the end speed asked for
  real end_speed_reached = 0;               // == v_end (differs from the request: see warning)
  real a = 0, d = 0;  // ramp rates; a == 0 iff there is no accelerating phase, d likewise
  real t_acc = 0, t_cruise = 0, t_dec = 0, duration = 0;
  real s_acc = 0, s_cruise = 0, s_dec = 0;  // sum to N
  // Integer step counts, accel + cruise + decel == N (docs/PLANNER.md, "Step counts"):
  // accel = floor(s_acc): the steps travelled wholly while accelerating; with a cruise phase,
  // decel = floor(s_dec) (wholly while decelerating) and the steps that straddle a phase
  // boundary count as cruise; without one, decel = N - accel (Stoychitch eq. 5).
  uint32_t accel_steps = 0, cruise_steps = 0, decel_steps = 0;
  std::string warning;  // non-empty when the end speed could not be met

  real position(real t) const;  // steps travelled at time t (0 <= t <= duration)
  real speed(real t) const;     // steps/s at time t
  real time_at(real x) const;   // instant at which the position reaches x steps
};

// The fastest move of `steps` steps within the limits (Stoychitch section 2, generalised to
// separate start and end speeds). Throws PlanError on invalid limits or steps > kMaxSteps.
PhasePlan plan_min_time(uint64_t steps, const Limits& lim, bool dir = true);
// Same on already resolved limits (steps/s, steps/s^2).
PhasePlan plan_min_time(uint64_t steps, const RampLimits& lim, bool dir = true);

// `steps` steps in exactly `time_s` seconds (Ranade 2009): start and end at --start-speed,
// accelerate and decelerate at the same rate (at most --accel), never above --max-speed.
// Triangular where it can, else trapezoidal cruising at --max-speed; constant at N/T if
// N/T <= start speed. --decel/--ratio/--end-speed, if given, must equal the symmetric case.
// Throws InfeasibleTime (naming --time, carrying the minimum time) if time_s is too short.
PhasePlan plan_timed(uint64_t steps, real time_s, const Limits& lim, bool dir = true);

// ---------------------------------------------------------------------------------------------
// The seeds' integer step counts, implemented literally (for comparison with the plans).

// Stoychitch (2018) section 2 in step units (alpha = 1 step): start and end speed vs, maximum
// speed vM, acceleration aM, ratio m = a/d. Equation 4 for T, triangular if vs + aM*T/(1+m) <=
// vM, then equation 5 (N_a = floor(N/(1+m)), N_d = N - N_a); else equations 6-8 with
// N_ad = floor(s_ad) (the appendix program's `int(ss/alfa)`), N_a = ceil(N_ad/(1+m)),
// N_d = N_ad - N_a, N_v = N - N_ad.
struct StoychitchCounts {
  bool triangular = true;
  real T = 0;       // total time (eq. 4 or 7)
  real v_peak = 0;  // vs + aM*ta, or vM
  real s_ad = 0;    // trapezoidal: steps in both ramps (eq. 6)
  uint64_t Na = 0, Nv = 0, Nd = 0;
};
StoychitchCounts stoychitch_counts(uint64_t N, real vs, real vM, real aM, real m);

// AVR446 section 3.2.1 (speed_cntr_Move() of the app note's code) in step units: from rest,
// n = v^2/(2a) steps to reach a speed. With C integer truncation (trunc) and its fix-ups:
//   max_s_lim = trunc(speed^2 / (2 accel))          (0 -> 1)
//   accel_lim = trunc(steps * decel / (accel + decel))   (0 -> 1)
//   accel_lim <= max_s_lim: decel_val = accel_lim - steps     (deceleration before speed)
//   else:                   decel_val = -trunc(max_s_lim * accel / decel)
//   decel_val == 0 -> -1;   decel_start = steps + decel_val;  steps == 1: decel_val = -1.
struct Avr446Counts {
  bool speed_reached = false;  // scenario 3.2.1.1 (max_s_lim < accel_lim)
  uint64_t max_s_lim = 0, accel_lim = 0;
  int64_t decel_val = 0;
  uint64_t decel_start = 0;
  uint64_t accel_steps = 0, cruise_steps = 0, decel_steps = 0;  // sum to steps
};
Avr446Counts avr446_counts(uint64_t steps, real accel, real decel, real speed);

// ---------------------------------------------------------------------------------------------
// Registers

// Encodes the plan with hexstep::encode_ramp (v_peak = the plan's peak). Refuses with a
// PlanError naming the flag (--max-speed, --start-speed, --end-speed, --accel, --decel,
// --steps, --clock-hz) and the range at this clock any value the registers cannot represent.
EncodedMove encode(const PhasePlan& p, real clock_hz, const Widths& w = Widths{});

// The pulse stage makes at most one step per step_high + step_low cycles (0 acts as 1):
// requires v_peak <= clock_hz / (step_high + step_low), else PlanError naming --max-speed.
void check_pulse_rate(real v_peak, real clock_hz, uint32_t step_high, uint32_t step_low);

// ---------------------------------------------------------------------------------------------
// Six axes

struct AxisRequest {
  unsigned axis = 0;   // 0 .. kNumAxes-1, each at most once
  int64_t steps = 0;   // signed distance in steps; the sign is the direction
  Limits limits;       // in steps/s, steps/s^2
};

struct AxisPlan {
  unsigned axis = 0;
  PhasePlan plan;
};

// Plans every axis alone (plan_min_time). Same order as the requests. Errors are prefixed
// with "axis k: ".
std::vector<AxisPlan> independent(const std::vector<AxisRequest>& requests);

struct LinePlan {
  PhasePlan path;  // the path in units of the longest axis's steps L
  std::vector<AxisPlan> axes;  // same order as the requests
};

// A straight line: all axes start together, every axis's position stays |N_i|/L times the
// path position (L = max |N_i|), all arrive together, each axis within its own limits. The path
// is planned with plan_min_time on L steps with limits min over axes of limit_i * L/|N_i| (speed,
// accel, decel, start and end speed); each axis's plan is the path scaled by |N_i|/L (same
// phase times). Axes with 0 steps get an empty plan.
LinePlan coordinated_line(const std::vector<AxisRequest>& requests);

}  // namespace hexstep::plan
