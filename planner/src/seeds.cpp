// SPDX-License-Identifier: Apache-2.0
// hexstep planner: the seeds' own integer step counts, implemented literally, so the tests can
// compare the planner with them. Stoychitch (2018) section 2 and appendix; AVR446 3.2.1.
#include <cmath>

#include "detail.hpp"

namespace hexstep::plan {

StoychitchCounts stoychitch_counts(uint64_t N, real vs, real vM, real aM, real m) {
  detail::require_steps(N);
  detail::require_positive("--max-speed", vM, "steps/s");
  detail::require_positive("--accel", aM, "steps/s^2");
  detail::require_positive("--ratio", m);
  detail::require_nonnegative("--start-speed", vs, "steps/s");
  if (vs > vM) detail::fail("--start-speed", "must be in [0, --max-speed = " + detail::num(vM) + "]");
  StoychitchCounts c;
  if (N == 0) return c;
  const real s = static_cast<real>(N);  // s = N * alpha, alpha = 1 step
  // Equation 4: T of the triangular profile, T = -k + sqrt(k^2 + c), k = vs(1+m)/aM,
  // c = 2s(1+m)/aM; evaluated as c / (k + sqrt(k^2 + c)), the same value without the
  // cancellation of -k + sqrt(...) when k^2 >> c.
  const real k = vs * (1 + m) / aM;
  const real c4 = 2 * s * (1 + m) / aM;
  const real T = c4 / (k + std::sqrt(k * k + c4));
  const real ta = T / (1 + m);  // equation 2
  const real v = vs + aM * ta;
  if (v <= vM) {
    // Equation 5.
    c.triangular = true;
    c.T = T;
    c.v_peak = v;
    c.Na = static_cast<uint64_t>(std::floor(s / (1 + m)));
    c.Nd = N - c.Na;
    c.Nv = 0;
    return c;
  }
  // Trapezoidal: equations 6, 7, 8.
  c.triangular = false;
  c.v_peak = vM;
  const real ta2 = (vM - vs) / aM;
  const real Tad = ta2 * (1 + m);
  c.s_ad = vs * Tad + aM * Tad * Tad / (2 * (1 + m));  // (6)
  const real tv = (s - c.s_ad) / vM;                   // (7)
  c.T = Tad + tv;
  // (8): N_ad = s_ad / alpha, an integer count: the appendix program's np = int(ss/alfa).
  uint64_t Nad = static_cast<uint64_t>(std::floor(c.s_ad));
  if (Nad > N) Nad = N;
  c.Na = static_cast<uint64_t>(std::ceil(static_cast<real>(Nad) / (1 + m)));
  if (c.Na > Nad) c.Na = Nad;
  c.Nd = Nad - c.Na;
  c.Nv = N - Nad;
  return c;
}

namespace {
// C integer division of the note's exact integers, on real-valued inputs: truncation, with a
// 1e-12 relative guard so that a quotient that is an integer mathematically (e.g. 6d/(d+d))
// is not truncated to one less by floating-point rounding.
uint64_t int_div(real x) { return static_cast<uint64_t>(std::trunc(x * (1 + 1e-12L))); }
}  // namespace

Avr446Counts avr446_counts(uint64_t steps, real accel, real decel, real speed) {
  detail::require_steps(steps);
  detail::require_positive("--accel", accel, "steps/s^2");
  detail::require_positive("--decel", decel, "steps/s^2");
  detail::require_positive("--max-speed", speed, "steps/s");
  Avr446Counts c;
  if (steps == 0) return c;
  if (steps == 1) {
    // "If moving only 1 step": straight to DECEL with accel_count = -1.
    c.decel_val = -1;
    c.decel_start = 0;
    c.decel_steps = 1;
    return c;
  }
  // max_s_lim = speed^2 / (2*alpha*accel): in steps units n = v^2 / (2a). Integer division.
  c.max_s_lim = int_div(speed * speed / (2 * accel));
  if (c.max_s_lim == 0) c.max_s_lim = 1;
  // accel_lim = n1 = (n1 + n2) decel / (accel + decel).
  c.accel_lim = int_div(static_cast<real>(steps) * decel / (accel + decel));
  if (c.accel_lim == 0) c.accel_lim = 1;
  if (c.accel_lim <= c.max_s_lim) {
    c.speed_reached = false;  // 3.2.1.2: deceleration starts before the speed is reached
    c.decel_val = static_cast<int64_t>(c.accel_lim) - static_cast<int64_t>(steps);
  } else {
    c.speed_reached = true;  // 3.2.1.1: decel_val = -max_s_lim * accel / decel
    c.decel_val = -static_cast<int64_t>(int_div(static_cast<real>(c.max_s_lim) * accel / decel));
  }
  if (c.decel_val == 0) c.decel_val = -1;
  const int64_t start = static_cast<int64_t>(steps) + c.decel_val;
  c.decel_start = start < 0 ? 0 : static_cast<uint64_t>(start);
  c.decel_steps = steps - c.decel_start;
  // ACCEL ends at decel_start (3.2.1.2) or once the speed is reached (max_s_lim steps).
  c.accel_steps = c.speed_reached ? std::min(c.max_s_lim, c.decel_start) : c.decel_start;
  c.cruise_steps = steps - c.accel_steps - c.decel_steps;
  return c;
}

}  // namespace hexstep::plan
