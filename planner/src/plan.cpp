// SPDX-License-Identifier: Apache-2.0
// hexstep planner: minimum-time plans (Stoychitch 2018, section 2, generalised) and
// time-constrained plans (Ranade 2009). docs/PLANNER.md derives every formula used here.
#include <algorithm>
#include <cmath>

#include "detail.hpp"

namespace hexstep::plan {

using detail::fail;
using detail::num;

const char* profile_name(Profile p) {
  switch (p) {
    case Profile::Empty: return "empty";
    case Profile::Constant: return "constant";
    case Profile::Triangular: return "triangular";
    case Profile::Trapezoidal: return "trapezoidal";
    case Profile::AccelOnly: return "accel-only";
    case Profile::DecelOnly: return "decel-only";
  }
  return "?";
}

real PhasePlan::position(real t) const {
  if (t <= 0) return 0;
  if (t <= t_acc) return v_start * t + a * t * t / 2;
  t -= t_acc;
  if (t <= t_cruise) return s_acc + v_peak * t;
  t -= t_cruise;
  if (t <= t_dec) return s_acc + s_cruise + v_peak * t - d * t * t / 2;
  return static_cast<real>(steps);
}

real PhasePlan::speed(real t) const {
  if (t <= t_acc) return v_start + a * std::max<real>(t, 0);
  t -= t_acc;
  if (t <= t_cruise) return v_peak;
  t -= t_cruise;
  if (t <= t_dec) return v_peak - d * t;
  return v_end;
}

real PhasePlan::time_at(real x) const {
  if (x <= 0) return 0;
  if (x <= s_acc) return 2 * x / (v_start + std::sqrt(v_start * v_start + 2 * a * x));
  x -= s_acc;
  if (x <= s_cruise) return t_acc + x / v_peak;
  x -= s_cruise;
  if (x <= s_dec) {
    const real disc = std::max<real>(v_peak * v_peak - 2 * d * x, 0);
    return t_acc + t_cruise + 2 * x / (v_peak + std::sqrt(disc));
  }
  return duration;
}

namespace detail {

void fill_counts(PhasePlan& p) {
  const real n = p.steps;
  // floor() that counts a boundary landing exactly on an integer (up to rounding) as reached.
  auto whole = [n](real x) -> uint32_t {
    const real f = std::floor(x + 1e-9L + std::fabs(x) * 1e-15L);
    return static_cast<uint32_t>(std::clamp<real>(f, 0, n));
  };
  p.accel_steps = whole(p.s_acc);
  if (p.s_cruise > 0)
    p.decel_steps = std::min<uint32_t>(whole(p.s_dec), p.steps - p.accel_steps);
  else
    p.decel_steps = p.steps - p.accel_steps;  // the step straddling the peak decelerates
  p.cruise_steps = p.steps - p.accel_steps - p.decel_steps;
}

}  // namespace detail

namespace {

constexpr real kMaxRampRatio = 1e12L;
constexpr real kMaxSpeed = 1e12L;  // steps/s
constexpr real kMaxAccel = 1e24L;  // steps/s^2
// Lower ends, far below a register's resolution at any clock (1.7e-13 steps/s at 100 MHz):
// they keep a*d and the squared speeds far from underflow, where a plan degenerated to
// 0 steps/s.
constexpr real kMinSpeed = 1e-30L;  // steps/s
constexpr real kMinAccel = 1e-30L;  // steps/s^2

void validate(const RampLimits& L) {
  detail::require_positive("--max-speed", L.v_max, "steps/s");
  detail::require_positive("--accel", L.accel, "steps/s^2");
  detail::require_positive("--decel", L.decel, "steps/s^2");
  detail::require_nonnegative("--start-speed", L.v_start, "steps/s");
  detail::require_nonnegative("--end-speed", L.v_end, "steps/s");
  // Ramp rates more than 1e12 apart leave the smaller one below the rounding of the larger in
  // the triangle's peak (a + d), and the plan would degenerate (found by fuzz_planner).
  if (L.decel > L.accel * kMaxRampRatio || L.accel > L.decel * kMaxRampRatio)
    fail("--decel", "must be within a factor " + num(kMaxRampRatio) + " of --accel = " + num(L.accel) +
                        " steps/s^2, i.e. in [" + num(L.accel / kMaxRampRatio) + ", " +
                        num(L.accel * kMaxRampRatio) + "] (got " + num(L.decel) +
                        "; with --ratio: in [1e-12, 1e12])");
  // The upper ends lie beyond any clock (a speed register holds < 1 step per cycle) and keep
  // the arithmetic far from overflow (found by fuzz_planner at 1e40 steps/s).
  const std::string speeds = "[" + num(kMinSpeed) + ", " + num(kMaxSpeed) + "] steps/s";
  const std::string accels = "[" + num(kMinAccel) + ", " + num(kMaxAccel) + "] steps/s^2";
  // The lower ends with a relative 1e-15 of slack: 1e-30 given as a double is below 1e-30L.
  auto below = [](real x, real lo) { return x < lo * (1 - 1e-15L); };
  if (below(L.v_max, kMinSpeed) || L.v_max > kMaxSpeed)
    fail("--max-speed", "must be in " + speeds + " (got " + num(L.v_max) + ")");
  if (below(L.accel, kMinAccel) || L.accel > kMaxAccel)
    fail("--accel", "must be in " + accels + " (got " + num(L.accel) + ")");
  if (below(L.decel, kMinAccel) || L.decel > kMaxAccel)
    fail("--decel", "must be in " + accels + " (got " + num(L.decel) + "; --accel/--ratio where --ratio is given)");
  if (L.v_start > L.v_max)
    fail("--start-speed", "must be in [0, --max-speed = " + num(L.v_max) + "] (got " + num(L.v_start) + ")");
  if (L.v_end > L.v_max)
    fail("--end-speed", "must be in [0, --max-speed = " + num(L.v_max) + "] (got " + num(L.v_end) + ")");
}

void make_constant(PhasePlan& p, real v) {
  p.profile = Profile::Constant;
  p.v_start = p.v_peak = p.v_end = v;
  p.a = p.d = 0;
  p.s_acc = p.s_dec = 0;
  p.s_cruise = p.steps;
  p.t_acc = p.t_dec = 0;
  p.t_cruise = p.s_cruise / v;
}

void finish(PhasePlan& p) {
  p.end_speed_reached = p.v_end;
  p.duration = p.t_acc + p.t_cruise + p.t_dec;
  detail::fill_counts(p);
}

}  // namespace

PhasePlan plan_min_time(uint64_t steps, const Limits& lim, bool dir) {
  detail::require_steps(steps);
  return plan_min_time(steps, resolve(lim), dir);
}

PhasePlan plan_min_time(uint64_t steps, const RampLimits& L, bool dir) {
  detail::require_steps(steps);
  validate(L);
  PhasePlan p;
  p.steps = static_cast<uint32_t>(steps);
  p.dir = dir;
  p.end_speed_requested = L.v_end;
  if (steps == 0) {
    finish(p);
    return p;
  }
  const real n = static_cast<real>(steps);
  const real v0 = L.v_start, ve = L.v_end, vM = L.v_max, a = L.accel, d = L.decel;
  // Peak of the triangular profile: (vp^2 - v0^2)/(2a) + (vp^2 - ve^2)/(2d) = N.
  real vt2 = (2 * a * d * n + d * v0 * v0 + a * ve * ve) / (a + d);
  const real hi = std::max(v0, ve);
  // Too short for the speed change (the triangle's peak would lie below an end speed):
  // ve^2 - v0^2 > 2aN or v0^2 - ve^2 > 2dN. A relative 1e-12 keeps the exact boundary normal.
  const bool short_up = ve > v0 && (ve - v0) * (ve + v0) > 2 * a * n * (1 + 1e-12L);
  const bool short_down = v0 > ve && (v0 - ve) * (v0 + ve) > 2 * d * n * (1 + 1e-12L);
  if (short_up || short_down) {
    if (short_up) {
      // v0^2 + 2aN < ve^2: accelerate all the way.
      const real vr = std::sqrt(v0 * v0 + 2 * a * n);
      p.profile = Profile::AccelOnly;
      p.v_start = v0;
      p.v_peak = p.v_end = vr;
      p.a = a;
      p.s_acc = n;
      p.t_acc = 2 * n / (v0 + vr);
      p.warning = "--end-speed: " + num(ve) + " steps/s cannot be reached in " + std::to_string(steps) +
                  " steps from --start-speed " + num(v0) + " at --accel " + num(a) +
                  "; the move accelerates all the way and ends at " + num(vr) + " steps/s";
    } else {
      // v0^2 - 2dN > ve^2: decelerate all the way.
      const real vr = std::sqrt(std::max<real>(v0 * v0 - 2 * d * n, 0));
      p.profile = Profile::DecelOnly;
      p.v_start = p.v_peak = v0;
      p.v_end = vr;
      p.d = d;
      p.s_dec = n;
      p.t_dec = 2 * n / (v0 + vr);
      p.warning = "--end-speed: " + num(ve) + " steps/s cannot be reached in " + std::to_string(steps) +
                  " steps from --start-speed " + num(v0) + " at --decel " + num(d) +
                  "; the move decelerates all the way and ends at " + num(vr) + " steps/s";
    }
    finish(p);
    return p;
  }
  vt2 = std::max(vt2, hi * hi);
  const real vt = std::sqrt(vt2);
  real vp;
  p.v_start = v0;
  p.v_end = ve;
  if (vt <= vM) {
    // Stoychitch: the triangular peak respects v_max, so the move is triangular.
    p.profile = Profile::Triangular;
    vp = vt;
    p.s_acc = std::clamp<real>((2 * d * n + (ve - v0) * (ve + v0)) / (2 * (a + d)), 0, n);
    p.s_cruise = 0;
    p.s_dec = n - p.s_acc;
  } else {
    // Trapezoidal: accelerate to v_max, cruise, decelerate.
    p.profile = Profile::Trapezoidal;
    vp = vM;
    p.s_acc = (vM - v0) * (vM + v0) / (2 * a);
    p.s_dec = (vM - ve) * (vM + ve) / (2 * d);
    p.s_cruise = std::max<real>(n - p.s_acc - p.s_dec, 0);
  }
  p.v_peak = vp;
  p.a = vp > v0 ? a : 0;
  p.d = vp > ve ? d : 0;
  if (p.a == 0 && p.d == 0) {
    // vp = v0 = ve: no ramp. Either v0 = ve = v_max, or the triangle's rise 2adN/(a+d) in vp^2
    // is below the rounding of v0^2 (e.g. 1.4e8 steps/s with a ramp rate of 1.8e-7 steps/s^2,
    // found by fuzz_planner): the move is one speed, not a triangle of zero duration.
    make_constant(p, vp);
    finish(p);
    return p;
  }
  if (p.a == 0) p.s_acc = 0;
  if (p.d == 0) p.s_dec = 0;
  if (p.profile == Profile::Triangular) {
    // Keep s_acc + s_dec == N exactly where a ramp vanished.
    if (p.d == 0) p.s_acc = n;
    else p.s_dec = n - p.s_acc;
  }
  // Times from distances, not from speed differences: no cancellation when vp ~ v0.
  p.t_acc = p.a > 0 ? 2 * p.s_acc / (v0 + vp) : 0;
  p.t_dec = p.d > 0 ? 2 * p.s_dec / (vp + ve) : 0;
  p.t_cruise = p.s_cruise / vp;
  finish(p);
  return p;
}

PhasePlan plan_timed(uint64_t steps, real T, const Limits& lim, bool dir) {
  detail::require_steps(steps);
  if (!std::isfinite(T) || !(T > 0)) fail("--time", "must be a finite number > 0 s (got " + num(T) + ")");
  const RampLimits L = resolve(lim);
  // Ranade's profile is symmetric: decelerate at the acceleration, end at the start speed.
  if (lim.decel && std::fabs(*lim.decel - lim.accel) > 1e-12L * lim.accel)
    fail("--decel", "a move with --time decelerates at its acceleration (at most --accel = " + num(lim.accel) +
                        "); leave --decel out or equal to --accel (got " + num(*lim.decel) + ")");
  if (lim.ratio && std::fabs(*lim.ratio - 1) > 1e-12L)
    fail("--ratio", "a move with --time accelerates and decelerates alike; leave --ratio out or 1 (got " +
                        num(*lim.ratio) + ")");
  if (lim.end_speed && *lim.end_speed != lim.start_speed)
    fail("--end-speed", "a move with --time ends at --start-speed = " + num(lim.start_speed) +
                            "; leave --end-speed out or equal to it (got " + num(*lim.end_speed) + ")");
  PhasePlan p;
  p.steps = static_cast<uint32_t>(steps);
  p.dir = dir;
  p.end_speed_requested = L.v_start;
  if (steps == 0) {
    finish(p);
    return p;
  }
  validate(L);
  const real n = static_cast<real>(steps);
  const real v0 = L.v_start, vl = L.v_max, al = L.accel;
  if (n / T <= v0) {
    // Slow enough to run at one speed below the start speed: N/T throughout.
    make_constant(p, n / T);
    p.t_cruise = T;
    finish(p);
    return p;
  }
  RampLimits sym = L;
  sym.v_end = v0;
  sym.decel = al;
  const PhasePlan fastest = plan_min_time(steps, sym, dir);
  const real t_min = fastest.duration;
  if (T < t_min * (1 - 1e-12L))
    throw InfeasibleTime("--time: " + num(T) + " s is shorter than the minimum achievable time " + num(t_min) +
                             " s for " + std::to_string(steps) + " steps at these limits (must be >= " +
                             num(t_min) + " s)",
                         T, t_min);
  if (vl * T <= n) {
    // T >= t_min >= N/v_limit, so only where T equals t_min to rounding: the fastest plan.
    p = fastest;
    p.end_speed_requested = v0;
    return p;
  }
  p.v_start = p.v_end = v0;
  real acc;
  if ((vl + v0) / 2 * T >= n) {
    // Ranade: the triangle reaches the required speed in half the time.
    p.profile = Profile::Triangular;
    const real required_max_speed = 2 * n / T - v0;
    acc = (required_max_speed - v0) * 2 / T;
    p.v_peak = std::min(required_max_speed, vl);  // <= vl but for rounding
    p.t_acc = p.t_dec = T / 2;
    p.t_cruise = 0;
    p.s_acc = n / 2;
    p.s_cruise = 0;
    p.s_dec = n - p.s_acc;
  } else {
    // Trapezoid cruising at v_limit: N = v0*T + (vl - v0)*(T - t_r).
    p.profile = Profile::Trapezoidal;
    const real t_r = (vl * T - n) / (vl - v0);
    acc = (vl - v0) / t_r;
    p.v_peak = vl;
    p.t_acc = p.t_dec = t_r;
    p.t_cruise = T - 2 * t_r;
    p.s_acc = p.s_dec = (v0 + vl) / 2 * t_r;
    p.s_cruise = std::max<real>(n - 2 * p.s_acc, 0);
  }
  if (acc > al) {
    // Above the limit only by rounding: T equals t_min to rounding (vl*T - N and t_r are
    // ill-conditioned there), and the minimum-time plan is the profile that takes it.
    p = fastest;
    p.end_speed_requested = v0;
    return p;
  }
  p.a = p.d = acc;
  finish(p);
  return p;
}

}  // namespace hexstep::plan
