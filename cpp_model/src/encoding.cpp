// SPDX-License-Identifier: Apache-2.0
// hexstep: the fixed-point encoding. docs/ARCHITECTURE.md ("Fixed-point formats" and
// "Encoding a ramp") derives every rule used here.
#include "hexstep/encoding.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hexstep {

namespace {
real two_pow(unsigned n) { return std::ldexp(static_cast<real>(1), static_cast<int>(n)); }

bool to_reg(real x, unsigned frac_bits, unsigned width, uint64_t& reg) {
  if (!std::isfinite(x) || x < 0) return false;
  real scaled = std::floor(x * two_pow(frac_bits));
  if (scaled >= two_pow(width)) return false;
  reg = static_cast<uint64_t>(scaled);
  return true;
}

[[noreturn]] void bad(const std::string& field, const std::string& why) {
  throw std::invalid_argument(field + ": " + why);
}

std::string num(real x) {
  std::ostringstream o;
  o.precision(6);
  o << static_cast<double>(x);
  return o.str();
}
}  // namespace

// The registers count in ticks: one tick is one frame of kFrameCycles clock cycles.
real tick_rate(real clock_hz) { return clock_hz / static_cast<real>(kFrameCycles); }

bool speed_to_reg(real v, real f, uint64_t& reg, const Widths& w) {
  return to_reg(v / tick_rate(f), w.speed_frac, w.speed_frac, reg);
}
bool accel_to_reg(real a, real f, uint64_t& reg, const Widths& w) {
  const real ft = tick_rate(f);
  return to_reg(a / (ft * ft), w.speed_frac, w.acc, reg);
}
real reg_to_speed(uint64_t reg, real f, const Widths& w) {
  return static_cast<real>(reg) / two_pow(w.speed_frac) * tick_rate(f);
}
real reg_to_accel(uint64_t reg, real f, const Widths& w) {
  const real ft = tick_rate(f);
  return static_cast<real>(reg) / two_pow(w.speed_frac) * ft * ft;
}
real max_speed(real f, const Widths& w) { return reg_to_speed(w.speed_mask(), f, w); }
real max_accel(real f, const Widths& w) { return reg_to_accel(w.acc_mask(), f, w); }

real IdealProfile::position(real t) const {
  if (t <= 0) return 0;
  if (t <= t_acc) return v0 * t + a * t * t / 2;
  t -= t_acc;
  if (t <= t_cruise) return s_acc + vp * t;
  t -= t_cruise;
  if (t <= t_dec) return s_acc + s_cruise + vp * t - d * t * t / 2;
  return s_acc + s_cruise + s_dec + ve * (t - t_dec);
}

real IdealProfile::speed(real t) const {
  if (t <= t_acc) return v0 + a * std::max<real>(t, 0);
  t -= t_acc;
  if (t <= t_cruise) return vp;
  t -= t_cruise;
  if (t <= t_dec) return vp - d * t;
  return ve;
}

real IdealProfile::time_at(real x) const {
  if (x <= 0) return 0;
  if (x <= s_acc) {
    if (a == 0) return x / v0;
    return 2 * x / (v0 + std::sqrt(v0 * v0 + 2 * a * x));
  }
  x -= s_acc;
  if (x <= s_cruise) return t_acc + x / vp;
  x -= s_cruise;
  if (x <= s_dec) {
    real disc = vp * vp - 2 * d * x;
    if (disc < 0) disc = 0;
    return t_acc + t_cruise + 2 * x / (vp + std::sqrt(disc));
  }
  x -= s_dec;
  return t_acc + t_cruise + t_dec + (ve > 0 ? x / ve : 0);
}

EncodedMove encode_ramp(const RampProfile& p, real f, const Widths& w) {
  EncodedMove e;
  AxisMove& r = e.regs;
  IdealProfile& id = e.ideal;
  id.clock_hz = f;
  r.steps = p.steps;
  r.dir = p.dir;
  id.steps = p.steps;
  if (!(f > 0) || !std::isfinite(f)) bad("clock_hz", "must be a finite frequency > 0");
  if (p.steps == 0) return e;
  if (static_cast<uint64_t>(p.steps) > w.steps_mask())
    bad("steps", "must be in [0, " + std::to_string(w.steps_mask()) + "]");
  const std::string vrange = "must be in [0, " + num(max_speed(f, w)) + "] steps/s at this clock";
  const std::string arange = "must be in (0, " + num(max_accel(f, w)) + "] steps/s^2 at this clock";
  uint64_t v0r, vpr, ver, ar = 0, dr = 0;
  if (!speed_to_reg(p.v_start, f, v0r, w)) bad("v_start", vrange);
  if (!speed_to_reg(p.v_peak, f, vpr, w)) bad("v_peak", vrange);
  if (!speed_to_reg(p.v_end, f, ver, w)) bad("v_end", vrange);
  if (!(p.v_peak > 0)) bad("v_peak", "must be > 0");
  if (p.v_start > p.v_peak) bad("v_start", "must be <= the peak speed " + num(p.v_peak));
  if (p.v_end > p.v_peak) bad("v_end", "must be <= the peak speed " + num(p.v_peak));
  const bool has_acc = p.v_peak > p.v_start;
  const bool has_dec = p.v_peak > p.v_end;
  if (has_acc && (!accel_to_reg(p.accel, f, ar, w) || ar == 0))
    bad("accel", arange + " (smallest: " + num(reg_to_accel(1, f, w)) + ")");
  if (has_dec && (!accel_to_reg(p.decel, f, dr, w) || dr == 0))
    bad("decel", arange + " (smallest: " + num(reg_to_accel(1, f, w)) + ")");

  const real N = p.steps;
  real v0 = reg_to_speed(v0r, f, w), ve = reg_to_speed(ver, f, w);
  const real aq = reg_to_accel(ar, f, w), dq = reg_to_accel(dr, f, w);
  // Rounding a and d down may make the requested peak unreachable within N steps; lower the
  // peak to what the quantized ramps allow, then round it down too.
  real vp_lim2;
  if (has_acc && has_dec) vp_lim2 = (2 * aq * dq * N + dq * v0 * v0 + aq * ve * ve) / (aq + dq);
  else if (has_acc) vp_lim2 = v0 * v0 + 2 * aq * N;
  else if (has_dec) vp_lim2 = ve * ve + 2 * dq * N;
  else vp_lim2 = std::numeric_limits<real>::infinity();
  if (reg_to_speed(vpr, f, w) > std::sqrt(vp_lim2)) {
    uint64_t lim;
    if (speed_to_reg(std::sqrt(vp_lim2), f, lim, w) && lim < vpr) vpr = lim;
  }
  if (vpr < v0r) vpr = v0r;
  if (vpr < ver) vpr = ver;

  // The speed accumulator holds the speed at the middle of the next tick, so that position
  // after k ticks equals v0*k + a*k^2/2 exactly: preload v_start + a/2 (ARCHITECTURE.md).
  bool acc_phase = has_acc && vpr > v0r;
  uint64_t s0 = v0r;
  if (acc_phase) {
    s0 = v0r + (ar >> 1);
    if (s0 >= vpr) {  // the ramp is shorter than one tick: start at the peak
      acc_phase = false;
      s0 = vpr;
    }
  }
  const bool dec_phase = has_dec && vpr > ver;
  r.v_start = s0;
  r.v_max = vpr;
  r.v_end = ver;
  r.acc = acc_phase ? ar : 0;
  r.dec = dec_phase ? dr : 0;
  if (!dec_phase && ver == 0) r.v_end = vpr;  // constant speed to the end: floor = peak
  // A deceleration faster than the peak speed per tick ends within one tick; the core refuses a
  // floor (dec, when v_end is 0) above v_max, so the floor is the peak (docs/ARCHITECTURE.md).
  if (r.v_end == 0 && r.dec > r.v_max) r.v_end = vpr;

  id.vp = reg_to_speed(vpr, f, w);
  id.a = acc_phase ? aq : 0;
  id.d = dec_phase ? dq : 0;
  id.v0 = acc_phase ? (static_cast<real>(s0) - static_cast<real>(ar) / 2) / two_pow(w.speed_frac) * tick_rate(f)
                    : id.vp;
  id.ve = dec_phase ? ve : id.vp;
  if (dec_phase && ver == 0) id.ve = 0;
  id.s_acc = acc_phase ? (id.vp * id.vp - id.v0 * id.v0) / (2 * id.a) : 0;
  id.s_dec = dec_phase ? (id.vp * id.vp - id.ve * id.ve) / (2 * id.d) : 0;
  id.s_cruise = N - id.s_acc - id.s_dec;
  if (id.s_cruise < 0) id.s_cruise = 0;
  id.t_acc = acc_phase ? (id.vp - id.v0) / id.a : 0;
  id.t_cruise = id.s_cruise / id.vp;
  id.t_dec = dec_phase ? (id.vp - id.ve) / id.d : 0;

  r.acc_steps = 0;
  if (acc_phase) {
    // Acceleration ends at v_max by the clamp; the count is a backstop one step later.
    real s = std::floor(id.s_acc) + 2;
    r.acc_steps = s >= N ? p.steps : static_cast<uint32_t>(s);
  }
  if (!dec_phase) {
    r.dec_step = p.steps;
    r.dec_frac = 0;
    r.v_dec = vpr;
    return e;
  }
  // Deceleration (ARCHITECTURE.md, "Entering deceleration"). The ideal profile begins to
  // decelerate at t_x ticks. Let j = ceil(t_x): tick interval (j, j+1] is the first one that
  // lies wholly in the ramp down, and its mean ideal speed is vp - dec * (j + 1/2 - t_x).
  // The core loads exactly that value (v_dec) on its first decelerating tick and subtracts
  // dec on every later one, so its position keeps matching the ideal. For that first
  // decelerating tick to be tick j, the threshold must be crossed at tick j-1: it lies in
  // (P(j-2), P(j-1)], where P(k) is the core's exact position after k ticks.
  const real t_x = (id.t_acc + id.t_cruise) * tick_rate(f);
  uint64_t j = static_cast<uint64_t>(std::ceil(t_x));
  if (t_x <= 0) {
    // No ramp up and no cruise: the first tick is already decelerating.
    j = 1;
    r.v_start = vpr - std::min<uint64_t>(vpr, dr / 2);
  }
  if (j < 1) j = 1;
  {
    const real v = static_cast<real>(vpr) - static_cast<real>(dr) * (static_cast<real>(j) + 0.5L - t_x);
    // Rounded to the nearest LSB; llround would overflow above 2^63 (half a step per tick).
    const real rv = std::floor(v + 0.5L);
    r.v_dec = v <= 0 ? 0 : (rv >= two_pow(64) ? vpr : static_cast<uint64_t>(rv));
    if (r.v_dec > vpr) r.v_dec = vpr;
  }
  if (j <= 1) {  // decelerate from the first tick
    r.dec_step = 0;
    r.dec_frac = 0;
    return e;
  }
  // Exact core position after k ticks, in 2^-SPEED_W steps.
  using u128 = unsigned __int128;
  const uint64_t S0 = r.v_start, A = r.acc, VM = r.v_max;
  uint64_t jc = ~0ull;  // first tick whose speed update clamps at v_max
  if (!acc_phase) jc = 0;
  else if (S0 >= VM) jc = 1;
  else jc = (VM - S0) / A + ((VM - S0) % A != 0);  // ceil, without overflow
  auto P = [&](uint64_t k) -> u128 {
    if (k <= jc) return u128(k) * S0 + u128(A) * (u128(k) * (k - 1) / 2);
    const u128 pc = u128(jc) * S0 + u128(A) * (u128(jc) * (jc - 1) / 2);
    return pc + u128(k - jc) * VM;
  };
  const unsigned g = w.speed_frac - w.dec_frac;
  const u128 lo = P(j - 2), hi = P(j - 1);
  u128 thr = (hi >> g) << g;
  if (thr <= lo) thr = ((lo >> g) + 1) << g;  // no grid point in between: one tick late
  const u128 int_part = thr >> w.speed_frac;
  if (int_part >= p.steps) {
    r.dec_step = p.steps;
    r.dec_frac = 0;
  } else {
    r.dec_step = static_cast<uint32_t>(int_part);
    r.dec_frac = static_cast<uint32_t>((thr & w.speed_mask()) >> g);
    if (r.dec_step == 0 && r.dec_frac == 0) r.dec_frac = 1;
  }
  return e;
}

real ideal_rise_cycle(const IdealProfile& p, uint32_t i) {
  return static_cast<real>(kStepLatency) + p.time_at(i) * p.clock_hz;
}

real allowance_cycles(const IdealProfile& p, uint32_t i) {
  const real v = p.speed(p.time_at(i));
  if (!(v > 0)) return std::numeric_limits<real>::infinity();
  return 2 + 0.001L / v * p.clock_hz;
}

}  // namespace hexstep
