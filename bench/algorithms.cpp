// SPDX-License-Identifier: Apache-2.0
// hexstep bench: the comparison algorithms, each from its seed document (see algorithms.hpp).
#include "algorithms.hpp"

#include <algorithm>
#include <cmath>

namespace hexstep::bench {

// ---- AVR446 -------------------------------------------------------------------------------------

Avr446Setup avr446_setup(uint64_t steps, real accel, real decel, real speed, real f) {
  Avr446Setup s;
  // Section 3.2.1: integer (truncating) arithmetic as in speed_cntr.c, here in step units.
  s.c0 = static_cast<int64_t>(0.676L * f * std::sqrt(2.0L / accel));
  s.min_delay = static_cast<int64_t>(f / speed);
  if (s.min_delay < 1) s.min_delay = 1;
  s.max_s_lim = static_cast<int64_t>(speed * speed / (2 * accel));
  if (s.max_s_lim == 0) s.max_s_lim = 1;
  s.accel_lim = static_cast<int64_t>(static_cast<real>(steps) * decel / (accel + decel));
  if (s.accel_lim == 0) s.accel_lim = 1;
  if (s.max_s_lim < s.accel_lim)  // 3.2.1.1: the speed is reached first
    s.decel_val = -static_cast<int64_t>(static_cast<real>(s.max_s_lim) * accel / decel);
  else  // 3.2.1.2: deceleration starts before the speed is reached
    s.decel_val = -(static_cast<int64_t>(steps) - s.accel_lim);
  if (s.decel_val == 0) s.decel_val = -1;
  s.decel_start = static_cast<int64_t>(steps) + s.decel_val;
  if (s.c0 <= s.min_delay) {
    s.c0 = s.min_delay;
    s.start_in_run = true;
  }
  return s;
}

AlgoResult avr446_run(uint64_t steps, real accel, real decel, real speed, real f, const PulseFn& fn) {
  AlgoResult r;
  if (steps == 0) return r;
  const Avr446Setup s = avr446_setup(steps, accel, decel, speed, f);
  enum { STOP, ACCEL, RUN, DECEL } state = s.start_in_run ? RUN : ACCEL;
  int64_t accel_count = 0;
  if (steps == 1) {  // one step: straight to DECEL (3.2.2)
    state = DECEL;
    accel_count = -1;
  }
  int64_t delay = s.c0, rest = 0, last_accel_delay = s.c0, step_count = 0;
  int64_t t = 0;  // timer counts since the move's time zero
  // The recurrence of 3.2.2.1; C's truncating division and remainder (signed in DECEL).
  auto next = [&](int64_t d) {
    const int64_t num = 2 * d + rest, den = 4 * accel_count + 1;
    rest = num % den;
    return d - num / den;
  };
  while (state != STOP) {
    t += delay;
    ++step_count;
    fn(static_cast<uint64_t>(step_count), static_cast<real>(t) / f);
    int64_t nd = delay;
    switch (state) {
      case ACCEL:
        ++accel_count;
        nd = next(delay);
        if (step_count >= s.decel_start) {
          accel_count = s.decel_val;
          state = DECEL;
        } else if (nd <= s.min_delay) {
          last_accel_delay = nd;
          nd = s.min_delay;
          rest = 0;
          state = RUN;
        }
        break;
      case RUN:
        nd = s.min_delay;
        if (step_count >= s.decel_start) {
          accel_count = s.decel_val;
          nd = last_accel_delay;
          state = DECEL;
        }
        break;
      case DECEL:
        ++accel_count;
        nd = next(delay);
        if (accel_count >= 0) state = STOP;
        break;
      case STOP: break;
    }
    delay = std::max<int64_t>(nd, 1);
    if (static_cast<uint64_t>(step_count) >= 2 * steps + 2) break;  // runaway guard
  }
  r.pulses = static_cast<uint64_t>(step_count);
  return r;
}

// ---- Stoychitch, time per step ------------------------------------------------------------------

StoychitchPlan stoychitch_plan(uint64_t N, real vs, real vM, real aM, real m) {
  StoychitchPlan p;
  const real s = static_cast<real>(N);  // alfa = 1 step
  const real k = vs * (1 + m) / aM;
  const real T = -k + std::sqrt(k * k + 2 * s * (1 + m) / aM);  // eq. 4
  const real ta = T / (1 + m);
  if (vs + aM * ta <= vM) {  // eq. 5
    p.triangular = true;
    p.Na = static_cast<uint64_t>(std::floor(s / (1 + m) + 1e-9L * std::max<real>(1, s)));
    p.Nd = N - p.Na;
    p.Nv = 0;
    return p;
  }
  p.triangular = false;  // eq. 6-8
  const real ta2 = (vM - vs) / aM;
  const real Tad = ta2 * (1 + m);
  const real sad = vs * Tad + aM * Tad * Tad / (2 * (1 + m));
  // floor() that counts a value landing on an integer up to rounding (2.7 is not binary) as reached
  uint64_t Nad = static_cast<uint64_t>(std::floor(sad + 1e-9L * std::max<real>(1, sad)));
  if (Nad > N) Nad = N;
  p.Na = static_cast<uint64_t>(std::ceil(static_cast<real>(Nad) / (1 + m)));
  if (p.Na > Nad) p.Na = Nad;
  p.Nd = Nad - p.Na;
  p.Nv = N - Nad;
  return p;
}

double stoychitch_next(double c, double R) { return c / (1.0 + R * c * c); }

AlgoResult stoychitch_run(uint64_t N, real vs, real vM, real aM, real m, real f, const PulseFn& fn) {
  AlgoResult r;
  if (N == 0) return r;
  const StoychitchPlan p = stoychitch_plan(N, vs, vM, aM, m);
  // Double precision, as the paper states for eq. 11-13.
  const double fd = static_cast<double>(f);
  const double c0 = fd / static_cast<double>(vs), cm = fd / static_cast<double>(vM);  // eq. 13
  const double Ra = static_cast<double>(aM) / (fd * fd);                               // eq. 11
  const double Rd = -static_cast<double>(aM / m) / (fd * fd);                          // eq. 12
  double c = c0;
  int64_t t = 0;
  for (uint64_t k = 0; k < N; ++k) {
    if (k >= 1) {
      if (k <= p.Na) {
        c = stoychitch_next(c, Ra);
        if (c < cm) c = cm;  // never above the maximum speed
      } else if (k <= p.Na + p.Nv) {
        c = cm;
      } else {
        const double den = 1.0 + Rd * c * c;
        // Eq. 12 has no solution once d * dt exceeds the speed; the paper's start speed is also
        // the lowest speed the motor needs, so the delay stops growing at c0.
        c = den > 0 ? c / den : c0;
        if (c > c0) c = c0;
      }
    }
    double out = c;  // eq. 14: corrections of the first and last five delays (timer value only)
    if (k >= 1 && k <= 5) out *= 1.0 + 0.08 / static_cast<double>(k);
    if (N - k >= 1 && N - k <= 5 && k >= 1) out *= 1.0 + 0.08 / static_cast<double>(N - k);
    int64_t counts = std::llround(out);
    if (counts < 1) counts = 1;
    t += counts;
    fn(k + 1, static_cast<real>(t) / f);
  }
  r.pulses = N;
  return r;
}

// ---- The Arduino steps-per-time program -------------------------------------------------------

ArduinoPlan arduino_plan(long N, float vs, float vM, float aM, float m, float F) {
  // planTrajek() with alfa = 1 step, aa = aM, in float as on the ATmega328.
  ArduinoPlan p;
  p.N = N;
  const float aa = aM, alfa = 1.0f;
  const float s_ = static_cast<float>(N) * alfa;
  float T = std::sqrt(std::pow(vs * (1 + m) / aa, 2.0f) + 2 * s_ * (1 + m) / aa) - vs * (1 + m) / aa;
  float ta = T / (1 + m);
  const float vv = vs + aa * ta;
  if (vv <= vM) {
    p.Na = static_cast<long>(static_cast<float>(N) / (1 + m));
    p.Nd = N - p.Na;
    p.Nv = 0;
  } else {
    ta = (vM - vs) / aa;
    T = (1 + m) * ta;
    const float ss = vs * T + aa * std::pow(T, 2.0f) / (2 * (1 + m));
    const long np = static_cast<long>(ss / alfa);
    p.Na = static_cast<long>(static_cast<float>(np) / (m + 1));
    p.Nd = np - p.Na;
    p.Nv = N - np;
  }
  p.Vsf = vs / alfa / F;
  p.Af = aa / alfa / F / F;
  p.Df = -p.Af / m;
  return p;
}

AlgoResult arduino_run(long N, float vs, float vM, float aM, float m, float F, real time_limit_s,
                       const PulseFn& fn) {
  AlgoResult r;
  if (N <= 0) return r;
  const ArduinoPlan p = arduino_plan(N, vs, vM, aM, m, F);
  float Af = p.Af, brzina = p.Vsf, pozicija = 0;
  long np = 0;
  bool stoj = false;
  auto loop = [&] {  // loop(): the phase switches
    if (np >= p.Na && np < p.N - p.Nd) Af = 0;
    if (np >= p.N - p.Nd) Af = p.Df;
    if (np >= p.N) stoj = true;
  };
  loop();
  const uint64_t kmax = static_cast<uint64_t>(time_limit_s * F) + 1;
  for (uint64_t k = 1; !stoj; ++k) {
    if (k > kmax) {
      r.finished = false;
      break;
    }
    // ISR(TIMER1_COMPA_vect)
    // Speed at or below zero with no acceleration left: the program would wait forever.
    if (brzina <= 0 && Af <= 0) {
      r.finished = false;
      break;
    }
    brzina = brzina + Af;
    pozicija = pozicija + brzina;
    if (pozicija - static_cast<float>(np) >= 1) {
      ++np;
      fn(static_cast<uint64_t>(np), static_cast<real>(k) / F);
    }
    loop();
  }
  r.pulses = static_cast<uint64_t>(np);
  return r;
}

// ---- hostmot2-style DDA -------------------------------------------------------------------------

AlgoResult dda_run(uint64_t N, real duration, const std::function<real(real)>& ideal_position, real f,
                   real f_servo, const PulseFn& fn) {
  AlgoResult r;
  if (N == 0) return r;
  constexpr int kFrac = 32;
  constexpr int64_t kOne = int64_t(1) << kFrac;
  const int64_t P = std::llround(f / f_servo);  // clock cycles per servo period
  const int64_t target_end = static_cast<int64_t>(N) * kOne;
  int64_t acc = 0;  // position in 2^-32 steps
  uint64_t pulses = 0;
  const uint64_t periods = static_cast<uint64_t>(std::ceil(duration * f_servo)) + 5;
  for (uint64_t k = 0; k < periods && pulses < N; ++k) {
    const real t_end = static_cast<real>(k + 1) / f_servo;
    const int64_t X = t_end >= duration ? target_end
                                         : std::min<int64_t>(target_end, std::llround(ideal_position(t_end) * kOne));
    int64_t R = X > acc ? (X - acc + P - 1) / P : 0;  // rounded up: the target is reached
    if (R >= kOne) R = kOne - 1;                        // below one step per cycle
    int64_t used = 0;  // cycles of this period already accumulated
    while (R > 0 && pulses < N) {
      const int64_t next = (acc / kOne + 1) * kOne;  // the next whole step
      const int64_t c = (next - acc + R - 1) / R;   // cycles until the accumulator reaches it
      if (used + c > P) break;
      used += c;
      acc += c * R;
      ++pulses;
      fn(pulses, static_cast<real>(static_cast<int64_t>(k) * P + used) / f);
    }
    acc += (P - used) * R;
  }
  r.pulses = pulses;
  r.finished = pulses >= N;
  return r;
}

}  // namespace hexstep::bench
