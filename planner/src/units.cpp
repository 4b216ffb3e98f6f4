// SPDX-License-Identifier: Apache-2.0
// hexstep planner: units and limits (docs/PLANNER.md, "Units").
#include <cmath>

#include "detail.hpp"

namespace hexstep::plan {

using detail::fail;
using detail::num;

namespace {
constexpr real kPi = 3.14159265358979323846264338327950288L;

void check_factor(const char* flag, const std::optional<real>& f) {
  if (f && (!std::isfinite(*f) || !(*f > 0)))
    fail(flag, "must be a finite number > 0 (got " + num(*f) + ")");
}

real need_k(const Scale& s, Unit u) {
  if (!s.steps_per_rev)
    fail("--steps-per-rev", std::string("is required for --unit ") + unit_name(u) +
                                " (a finite number > 0)");
  return *s.steps_per_rev;
}
}  // namespace

Unit parse_unit(const std::string& name) {
  if (name == "steps") return Unit::Steps;
  if (name == "rev") return Unit::Rev;
  if (name == "deg") return Unit::Deg;
  if (name == "rad") return Unit::Rad;
  if (name == "mm") return Unit::Mm;
  fail("--unit", "must be one of steps, rev, deg, rad, mm (got '" + name + "')");
}

const char* unit_name(Unit u) {
  switch (u) {
    case Unit::Steps: return "steps";
    case Unit::Rev: return "rev";
    case Unit::Deg: return "deg";
    case Unit::Rad: return "rad";
    case Unit::Mm: return "mm";
  }
  return "?";
}

real steps_per_unit(Unit u, const Scale& s) {
  check_factor("--steps-per-rev", s.steps_per_rev);
  check_factor("--steps-per-mm", s.steps_per_mm);
  check_factor("--pitch-mm", s.pitch_mm);
  switch (u) {
    case Unit::Steps: return 1;
    case Unit::Rev: return need_k(s, u);
    case Unit::Deg: return need_k(s, u) / 360;
    case Unit::Rad: return need_k(s, u) / (2 * kPi);
    case Unit::Mm: {
      const bool screw = s.steps_per_rev && s.pitch_mm;
      if (s.steps_per_mm) {
        if (screw) {
          const real k = *s.steps_per_rev / *s.pitch_mm;
          if (std::fabs(k - *s.steps_per_mm) > 1e-9L * *s.steps_per_mm)
            fail("--steps-per-mm", num(*s.steps_per_mm) + " disagrees with --steps-per-rev / --pitch-mm = " +
                                       num(k) + " (give one or the other)");
        }
        return *s.steps_per_mm;
      }
      if (screw) return *s.steps_per_rev / *s.pitch_mm;
      if (s.steps_per_rev)
        fail("--pitch-mm", "is required for --unit mm with --steps-per-rev (a finite number > 0), or give --steps-per-mm");
      if (s.pitch_mm)
        fail("--steps-per-rev", "is required for --unit mm with --pitch-mm (a finite number > 0), or give --steps-per-mm");
      fail("--steps-per-mm", "is required for --unit mm (a finite number > 0), or give --steps-per-rev and --pitch-mm");
    }
  }
  fail("--unit", "must be one of steps, rev, deg, rad, mm");
}

real to_steps(real value, Unit u, const Scale& s) { return value * steps_per_unit(u, s); }

StepCount distance_to_steps(real distance, Unit u, const Scale& s) {
  if (!std::isfinite(distance)) fail("--distance", "must be a finite number (got " + num(distance) + ")");
  const real k = steps_per_unit(u, s);
  StepCount c;
  c.exact = std::fabs(distance) * k;
  c.dir = !(distance < 0);
  const real n = std::round(c.exact);  // nearest integer, halves away from zero (as C round())
  if (!(n <= static_cast<real>(kMaxSteps)))
    fail("--distance", "is " + num(c.exact) + " steps; must be at most " + std::to_string(kMaxSteps) +
                           " steps per move (|distance| <= " + num(static_cast<real>(kMaxSteps) / k) + " " +
                           unit_name(u) + ")");
  c.steps = static_cast<uint32_t>(n);
  if (c.steps == 0) c.dir = true;
  return c;
}

namespace {
void validate_values(const Limits& lim) {
  using detail::require_nonnegative;
  using detail::require_positive;
  require_positive("--max-speed", lim.max_speed);
  require_positive("--accel", lim.accel);
  if (lim.decel) require_positive("--decel", *lim.decel);
  if (lim.ratio) require_positive("--ratio", *lim.ratio);
  if (lim.decel && lim.ratio) fail("--ratio", "give either --decel or --ratio (m = accel/decel), not both");
  require_nonnegative("--start-speed", lim.start_speed);
  if (lim.end_speed) require_nonnegative("--end-speed", *lim.end_speed);
}
}  // namespace

Limits limits_to_steps(const Limits& lim, Unit u, const Scale& s) {
  validate_values(lim);
  const real k = steps_per_unit(u, s);
  Limits r = lim;
  r.max_speed *= k;
  r.accel *= k;
  if (r.decel) *r.decel *= k;
  r.start_speed *= k;
  if (r.end_speed) *r.end_speed *= k;
  return r;
}

RampLimits resolve(const Limits& lim) {
  validate_values(lim);
  RampLimits r;
  r.v_max = lim.max_speed;
  r.accel = lim.accel;
  r.decel = lim.decel ? *lim.decel : lim.ratio ? lim.accel / *lim.ratio : lim.accel;
  if (!std::isfinite(r.decel) || !(r.decel > 0))
    fail("--ratio", "gives a deceleration --accel/--ratio = " + num(r.decel) + "; it must be a finite number > 0");
  r.v_start = lim.start_speed;
  r.v_end = lim.end_speed ? *lim.end_speed : lim.start_speed;
  if (r.v_start > r.v_max)
    fail("--start-speed", "must be in [0, --max-speed = " + num(r.v_max) + "] (got " + num(r.v_start) + ")");
  if (r.v_end > r.v_max)
    fail("--end-speed", "must be in [0, --max-speed = " + num(r.v_max) + "] (got " + num(r.v_end) + ")");
  return r;
}

}  // namespace hexstep::plan
