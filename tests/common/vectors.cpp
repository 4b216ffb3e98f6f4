// SPDX-License-Identifier: Apache-2.0
#include "vectors.hpp"

#include <cmath>
#include <cstdlib>

namespace hexstep::test {

real ramp_peak(const Ramp& r) {
  const real N = r.steps, a = r.accel, d = r.decel, v0 = r.v_start, ve = r.v_end;
  // Triangular peak: (vp^2 - v0^2)/2a + (vp^2 - ve^2)/2d = N.
  real vp = std::sqrt((2 * a * d * N + d * v0 * v0 + a * ve * ve) / (a + d));
  return std::min(vp, r.v_max);
}

EncodedMove encode(const Ramp& r, real f) {
  RampProfile p;
  p.steps = r.steps;
  p.dir = r.dir;
  p.v_start = r.v_start;
  p.v_end = r.v_end;
  p.v_peak = std::max({ramp_peak(r), r.v_start, r.v_end});
  p.accel = r.accel;
  p.decel = r.decel;
  return encode_ramp(p, f);
}

namespace {
constexpr uint64_t kP62 = 1ull << 62;

AxisMove constant_speed(uint32_t n, bool dir, uint64_t s) {
  AxisMove m;
  m.steps = n;
  m.dir = dir;
  m.v_start = m.v_max = m.v_end = s;
  m.dec_step = n;
  return m;
}

NamedJob single(const std::string& name, const std::vector<Ramp>& ramps, unsigned axis = 0,
                PulseConfig pc = PulseConfig{}) {
  NamedJob j{name, Job{}, std::vector<std::vector<IdealProfile>>(kNumAxes)};
  j.job.axes[axis].pulse = pc;
  for (const Ramp& r : ramps) {
    EncodedMove e = encode(r);
    j.job.axes[axis].moves.push_back(e.regs);
    j.ideal[axis].push_back(e.ideal);
  }
  return j;
}
}  // namespace

std::vector<NamedJob> directed_jobs() {
  std::vector<NamedJob> v;
  PulseConfig fast;  // defaults: 1 cycle high, 1 cycle low, no setup/hold
  PulseConfig drv8825{190, 190, 65, 65, false, false};  // 1.9 us / 650 ns at 100 MHz
  // Ranade 2009, Table 1: 0.2 step per update, a pulse every 5 updates.
  {
    NamedJob j{"ranade_table1", Job{}, std::vector<std::vector<IdealProfile>>(kNumAxes)};
    uint64_t s = static_cast<uint64_t>(std::ceil(std::ldexp(0.2L, 64)));
    j.job.axes[0].moves.push_back(constant_speed(5, true, s));
    v.push_back(j);
  }
  v.push_back(single("triangular_rest_to_rest", {{200, true, 0, 5e6, 0, 5e8, 5e8}}));
  v.push_back(single("trapezoid_asymmetric", {{2000, true, 1e4, 2.5e5, 5e4, 2e8, 1e8}}, 0, drv8825));
  v.push_back(single("trapezoid_decel_4x", {{1500, false, 0, 2e5, 0, 5e7, 2e8}}, 1, drv8825));
  v.push_back(single("triangular_nonzero_ends", {{300, true, 2e5, 5e6, 1e5, 3e9, 1e9}}, 2));
  v.push_back(single("zero_one_two_steps",
                     {{0, true, 0, 1e6, 0, 1e9, 1e9},
                      {1, true, 0, 1e6, 0, 1e9, 1e9},
                      {2, false, 0, 1e6, 0, 1e9, 1e9},
                      {1, false, 5e5, 1e6, 5e5, 1e9, 1e9}},
                     3, PulseConfig{4, 4, 10, 10, false, false}));
  v.push_back(single("fastest_5M_steps_per_s", {{3000, true, 1e6, 5e6, 1e6, 9e9, 9e9}}, 4, fast));
  v.push_back(single("direction_changes",
                     {{120, true, 0, 2e6, 0, 4e9, 4e9},
                      {80, false, 0, 2e6, 0, 4e9, 4e9},
                      {40, true, 3e5, 2e6, 3e5, 4e9, 4e9}},
                     5, PulseConfig{20, 30, 50, 60, false, false}));
  {  // register extremes: the largest speed (pulse stage limits the rate, generator stalls)
    NamedJob j{"max_speed_register_stall", Job{}, std::vector<std::vector<IdealProfile>>(kNumAxes)};
    j.job.axes[0].pulse = fast;
    j.job.axes[0].moves.push_back(constant_speed(50, true, ~0ull));
    j.job.axes[1].pulse = PulseConfig{3, 5, 0, 0, true, true};
    j.job.axes[1].moves.push_back(constant_speed(20, false, kP62));
    v.push_back(j);
  }
  {  // the slowest speed a co-simulation can afford, and the longest pulse timing registers
    NamedJob j{"slow_and_max_pulse", Job{}, std::vector<std::vector<IdealProfile>>(kNumAxes)};
    j.job.axes[0].moves.push_back(constant_speed(3, true, (~0ull) / 200000));
    j.job.axes[1].pulse = PulseConfig{4095, 4095, 4095, 4095, false, true};
    j.job.axes[1].moves.push_back(constant_speed(4, true, (~0ull) / 9000));
    j.job.axes[1].moves.push_back(constant_speed(4, false, (~0ull) / 9000));
    v.push_back(j);
  }
  {  // six axes, six different moves, one start strobe
    NamedJob j{"six_axes_one_strobe", Job{}, std::vector<std::vector<IdealProfile>>(kNumAxes)};
    const Ramp r[kNumAxes] = {{400, true, 0, 1e6, 0, 1e9, 1e9},      {250, false, 1e4, 2e6, 1e4, 3e9, 1e9},
                              {600, true, 0, 5e5, 0, 2e8, 8e8},       {90, false, 2e5, 3e6, 0, 9e9, 5e9},
                              {1000, true, 5e4, 4e6, 5e4, 5e9, 5e9},  {33, true, 0, 1e6, 0, 1e8, 1e8}};
    for (unsigned a = 0; a < kNumAxes; ++a) {
      EncodedMove e = encode(r[a]);
      j.job.axes[a].pulse = PulseConfig{10 + a, 12, 5 * a, 3 * a, a % 2 == 1, a % 3 == 1};
      j.job.axes[a].moves.push_back(e.regs);
      j.ideal[a].push_back(e.ideal);
    }
    v.push_back(j);
  }
  return v;
}

AxisMove cruise(uint32_t steps, uint64_t speed, bool dir) {
  AxisMove m;
  m.steps = steps;
  m.dir = dir;
  m.v_start = m.v_max = m.v_end = m.v_dec = speed;
  m.dec_step = steps;
  return m;
}

AxisMove bus_trapezoid(uint32_t steps, bool dir) {
  AxisMove m;
  m.steps = steps;
  m.dir = dir;
  m.v_start = 1ull << 58;
  m.v_max = 1ull << 61;
  m.acc = 1ull << 43;
  m.dec = 1ull << 43;
  m.v_end = 1ull << 58;
  m.v_dec = (1ull << 61) - (1ull << 54);
  m.acc_steps = steps / 4;
  m.dec_step = steps - steps / 4;
  m.dec_frac = 0x80000000u;
  return m;
}

uint64_t test_seed() {
  if (const char* s = std::getenv("SEED")) return std::strtoull(s, nullptr, 0);
  return std::random_device{}() ^ (uint64_t(std::random_device{}()) << 32);
}

namespace {
real log_uniform(std::mt19937_64& rng, real lo, real hi) {
  std::uniform_real_distribution<double> u(std::log(static_cast<double>(lo)), std::log(static_cast<double>(hi)));
  return std::exp(static_cast<real>(u(rng)));
}
}  // namespace

Ramp random_ramp(std::mt19937_64& rng) {
  Ramp r;
  r.steps = std::uniform_int_distribution<uint32_t>(0, 400)(rng);
  r.dir = rng() & 1;
  r.v_max = log_uniform(rng, 2e4, 5e6);
  r.accel = log_uniform(rng, 3e8, 9e9);
  r.decel = r.accel * log_uniform(rng, 0.25, 4);
  if (r.decel > 9e9) r.decel = 9e9;
  r.v_start = (rng() % 3 == 0) ? 0 : std::min(r.v_max, log_uniform(rng, 1e3, 5e5));
  r.v_end = (rng() % 3 == 0) ? 0 : std::min(r.v_max, log_uniform(rng, 1e3, 5e5));
  return r;
}

AxisMove random_raw_move(std::mt19937_64& rng) {
  AxisMove m;
  auto speed = [&]() -> uint64_t {
    switch (rng() % 6) {
      case 0: return 0;
      case 1: return ~0ull >> (rng() % 3);
      default: return (rng() >> 2) >> (rng() % 12);  // >= ~2^50: a step within ~16k ticks
    }
  };
  m.steps = rng() % 4 == 0 ? static_cast<uint32_t>(rng() % 3) : static_cast<uint32_t>(rng() % 60);
  m.dir = rng() & 1;
  m.v_start = speed();
  m.v_max = speed();
  m.v_end = speed();
  m.acc = rng() % 3 == 0 ? 0 : (rng() & ((1ull << 44) - 1)) >> (rng() % 8);
  m.dec = rng() % 3 == 0 ? 0 : (rng() & ((1ull << 44) - 1)) >> (rng() % 8);
  m.v_dec = speed();
  // A zero floor is either refused (no deceleration either) or replaced by a real end speed:
  // a floor of `dec` alone would crawl for millions of cycles in a co-simulation.
  if (m.v_end == 0 && rng() % 2) m.dec = 0;
  else if (m.v_end == 0) m.v_end = (rng() >> 4) | (1ull << 58);
  auto count = [&]() { return static_cast<uint32_t>(rng() % (m.steps + 3)); };
  m.acc_steps = count();
  m.dec_step = count();
  m.dec_frac = static_cast<uint32_t>(rng());
  if (rng() % 4 == 0) m.dec_frac = 0;
  return m;
}

PulseConfig random_pulse(std::mt19937_64& rng) {
  PulseConfig p;
  auto t = [&]() -> uint32_t {
    switch (rng() % 5) {
      case 0: return 0;
      case 1: return 1;
      case 2: return 4095;
      default: return static_cast<uint32_t>(rng() % 200);
    }
  };
  p.step_high = t();
  p.step_low = t();
  p.dir_setup = t();
  p.dir_hold = t();
  p.step_invert = rng() & 1;
  p.dir_invert = rng() & 1;
  return p;
}

NamedJob random_job(std::mt19937_64& rng, unsigned moves_per_axis, bool raw_too) {
  NamedJob j{"random", Job{}, std::vector<std::vector<IdealProfile>>(kNumAxes)};
  // The same physical moves at the clocks users run: slower clocks also mean fewer cycles.
  static const real clocks[] = {12e6, 25e6, 48e6, 100e6};
  const real f = clocks[rng() % 4];
  j.job.clock_hz = static_cast<uint64_t>(f);
  const real a_lim = 0.9L * max_accel(f);
  for (unsigned a = 0; a < kNumAxes; ++a) {
    PulseConfig p;
    p.step_high = 1 + rng() % 40;
    p.step_low = 1 + rng() % 40;
    p.dir_setup = rng() % 100;
    p.dir_hold = rng() % 100;
    p.step_invert = rng() & 1;
    p.dir_invert = rng() & 1;
    j.job.axes[a].pulse = p;
    for (unsigned k = 0; k < moves_per_axis; ++k) {
      if (raw_too && rng() % 5 == 0) {
        j.job.axes[a].moves.push_back(random_raw_move(rng));
        j.ideal[a].push_back(IdealProfile{});
      } else {
        Ramp r = random_ramp(rng);
        r.accel = std::min(r.accel, a_lim);
        r.decel = std::min(r.decel, a_lim);
        EncodedMove e = encode(r, f);
        j.job.axes[a].moves.push_back(e.regs);
        j.ideal[a].push_back(e.ideal);
      }
    }
  }
  return j;
}

}  // namespace hexstep::test
