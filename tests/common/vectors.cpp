// SPDX-License-Identifier: Apache-2.0
#include "vectors.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

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
constexpr real kF = static_cast<real>(kDefaultClockHz);
// Physical speed and acceleration at 100 MHz of u steps per tick and u steps per tick^2.
real per_tick(real u) { return u * tick_rate(kF); }
real per_tick2(real u) { return u * tick_rate(kF) * tick_rate(kF); }
constexpr real kMaxAcc = 1.0L / 65536;  // 2^(ACC_W - 64) step per tick^2, ACC_W = 48

NamedJob make(const std::string& name) {
  return NamedJob{name, Job{}, std::vector<std::vector<IdealProfile>>(kNumAxes)};
}

NamedJob single(const std::string& name, const std::vector<Ramp>& ramps, unsigned axis = 0,
                PulseConfig pc = PulseConfig{}) {
  NamedJob j = make(name);
  j.job.axes[axis].pulse = pc;
  for (const Ramp& r : ramps) {
    EncodedMove e = encode(r);
    j.job.axes[axis].moves.push_back(e.regs);
    j.ideal[axis].push_back(e.ideal);
  }
  return j;
}

std::vector<NamedJob> build_directed() {
  std::vector<NamedJob> v;
  const PulseConfig fast;                                 // 1 cycle high, 1 cycle low
  const PulseConfig drv8825{190, 190, 65, 65, false, false};  // 1.9 us / 650 ns at 100 MHz
  // Ranade 2009, Table 1: 0.2 step per update, a pulse every 5 updates (an update is a tick).
  {
    NamedJob j = make("ranade_table1");
    const uint64_t s = static_cast<uint64_t>(std::ceil(0.2L * kTwo64));
    j.job.axes[0].moves.push_back(cruise(5, s));
    v.push_back(j);
  }
  // Rest to rest at the largest acceleration: triangular, peak sqrt(a N).
  v.push_back(single("triangular_rest_to_rest", {{200, true, 0, per_tick(0.9L), 0, per_tick2(0.9L * kMaxAcc),
                                                  per_tick2(0.9L * kMaxAcc)}}));
  // Trapezoid from and to non-zero speeds, deceleration half the acceleration, at the DRV8825's
  // pulse timing (the speed stays below its 263 k steps/s).
  v.push_back(single("trapezoid_asymmetric", {{1600, true, 5e4, 2.5e5, 3e4, 1.2e8, 6e7}}, 0, drv8825));
  // Deceleration four times the acceleration, negative direction.
  v.push_back(single("trapezoid_decel_4x", {{1000, false, 0, 2e5, 0, 3e7, 1.2e8}}, 1, drv8825));
  // Triangular with non-zero ends, acc != dec.
  v.push_back(single("triangular_nonzero_ends", {{400, true, 6e5, 3e6, 4e5, 1.4e8, 7e7}}, 2));
  v.push_back(single("zero_one_two_steps",
                     {{0, true, 0, 1e6, 0, 1e8, 1e8},
                      {1, true, 0, 1e6, 0, 1e8, 1e8},
                      {2, false, 0, 1e6, 0, 1e8, 1e8},
                      {1, false, 5e5, 1e6, 5e5, 1e8, 1e8}},
                     3, PulseConfig{4, 4, 10, 10, false, false}));
  // Near the one-step-per-tick limit, with ramps at both ends.
  v.push_back(single("fastest_near_one_step_per_tick", {{3000, true, 2.6e6, per_tick(0.96L), 2.6e6, 1.4e8, 1.4e8}}, 4,
                     fast));
  v.push_back(single("direction_changes",
                     {{120, true, 0, 2e6, 0, 1e8, 1e8},
                      {80, false, 0, 2e6, 0, 1e8, 1e8},
                      {40, true, 3e5, 2e6, 3e5, 1e8, 1e8}},
                     5, PulseConfig{20, 30, 50, 60, false, false}));
  {  // register extremes: the largest speed (1 step per tick less one LSB: the output stage
     // limits the rate, the generator pauses) and a pulse timing slower than the steps
    NamedJob j = make("max_speed_register_stall");
    j.job.axes[0].pulse = fast;
    j.job.axes[0].moves.push_back(cruise(50, ~0ull));
    j.job.axes[1].pulse = PulseConfig{30, 50, 0, 0, true, true};
    j.job.axes[1].moves.push_back(cruise(20, 1ull << 63, false));
    v.push_back(j);
  }
  {  // slow speeds, below the sub-tick division's resolution, and the longest pulse timing
    NamedJob j = make("slow_and_max_pulse");
    j.job.axes[0].moves.push_back(cruise(3, (~0ull) / 5000));
    j.job.axes[1].pulse = PulseConfig{4095, 4095, 4095, 4095, false, true};
    j.job.axes[1].moves.push_back(cruise(4, (~0ull) / 300));
    j.job.axes[1].moves.push_back(cruise(4, (~0ull) / 300, false));
    v.push_back(j);
  }
  {  // six axes, six different moves, one START
    NamedJob j = make("six_axes_one_start");
    const Ramp r[kNumAxes] = {{400, true, 0, 1e6, 0, 1e8, 1e8},         {250, false, 1e5, 2e6, 1e5, 1.4e8, 5e7},
                              {600, true, 4e5, 8e5, 4e5, 6e7, 1.2e8},    {90, false, 2e5, 3e6, 0, 1.4e8, 1e8},
                              {1000, true, 5e5, 2.5e6, 5e5, 1.4e8, 1.4e8}, {33, true, 0, 1e6, 0, 1e8, 1e8}};
    for (unsigned a = 0; a < kNumAxes; ++a) {
      EncodedMove e = encode(r[a]);
      j.job.axes[a].pulse = PulseConfig{2 + a, 3, 5 * a, 3 * a, a % 2 == 1, a % 3 == 1};
      j.job.axes[a].moves.push_back(e.regs);
      j.ideal[a].push_back(e.ideal);
    }
    v.push_back(j);
  }
  return v;
}
}  // namespace

std::vector<NamedJob> directed_jobs() {
  static const std::vector<NamedJob> v = build_directed();
  return v;
}

const NamedJob& directed(const std::string& name) {
  static const std::vector<NamedJob> v = build_directed();
  for (const NamedJob& j : v)
    if (j.name == name) return j;
  throw std::invalid_argument("no directed vector " + name);
}

AxisMove cruise(uint32_t steps, uint64_t speed, bool dir) {
  AxisMove m;
  m.steps = steps;
  m.dir = dir;
  m.v_start = m.v_max = m.v_end = m.v_dec = speed;
  m.dec_step = steps;
  return m;
}

AxisMove trapezoid(uint32_t steps, bool dir) {
  AxisMove m;
  m.steps = steps;
  m.dir = dir;
  m.v_start = 1ull << 61;
  m.v_max = (1ull << 61) + (1ull << 54);
  m.acc = 1ull << 47;
  m.dec = 1ull << 47;
  m.v_end = 1ull << 61;
  m.v_dec = m.v_max - (m.dec >> 1);
  m.acc_steps = steps / 2;
  m.dec_step = steps > 32 ? steps - 16 : steps / 2;
  m.dec_frac = 0x80000000u;
  return m;
}

uint64_t test_seed() {
  if (const char* s = std::getenv("SEED")) return std::strtoull(s, nullptr, 0);
  return std::random_device{}() ^ (uint64_t(std::random_device{}()) << 32);
}

uint64_t env_count(const char* name, uint64_t dflt) {
  const char* s = std::getenv(name);
  return s && *s ? std::strtoull(s, nullptr, 0) : dflt;
}

namespace {
real log_uniform(std::mt19937_64& rng, real lo, real hi) {
  std::uniform_real_distribution<double> u(std::log(static_cast<double>(lo)), std::log(static_cast<double>(hi)));
  return std::exp(static_cast<real>(u(rng)));
}
}  // namespace

Ramp random_ramp(std::mt19937_64& rng, real f) {
  const real ft = tick_rate(f);
  // Drawn in steps per tick (the cycle count of a move depends on these alone); moves longer
  // than kMaxTicks are drawn again, which keeps a co-simulated move below 10^5 cycles. The
  // speeds are drawn relative to the triangular peak sqrt(a N) of the move from rest, so that
  // trapezoids, triangles and one-sided ramps all occur; one move in eight is a fast one
  // (0.1 to 0.9 step per tick) whose ramps are short against its cruise.
  constexpr real kMaxTicks = 2500;
  for (;;) {
    Ramp r;
    r.dir = rng() & 1;
    r.steps = std::uniform_int_distribution<uint32_t>(0, 400)(rng);
    const real acc = log_uniform(rng, kMaxAcc / 32, 0.9L * kMaxAcc);
    const real dec = std::min(acc * log_uniform(rng, 0.25L, 4), 0.9L * kMaxAcc);
    real v0, ve, vmax;
    if (rng() % 8 == 0) {
      vmax = log_uniform(rng, 0.1L, 0.9L);
      v0 = vmax * log_uniform(rng, 0.7L, 1);
      ve = vmax * log_uniform(rng, 0.7L, 1);
    } else {
      const real vref = std::sqrt(acc * std::max<uint32_t>(r.steps, 1));
      v0 = rng() % 4 == 0 ? 0 : vref * log_uniform(rng, 0.05L, 1.2L);
      ve = rng() % 4 == 0 ? 0 : vref * log_uniform(rng, 0.05L, 1.2L);
      Ramp t{r.steps, r.dir, v0, 1, ve, acc, dec};
      vmax = std::min(0.9L, std::max({v0, ve, ramp_peak(t) * log_uniform(rng, 0.4L, 1.5L)}));
    }
    r.v_max = vmax * ft;
    r.v_start = std::min(v0, vmax) * ft;
    r.v_end = std::min(ve, vmax) * ft;
    r.accel = acc * ft * ft;
    r.decel = dec * ft * ft;
    if (encode(r, f).ideal.duration() * ft <= kMaxTicks) return r;
  }
}

AxisMove random_raw_move(std::mt19937_64& rng) {
  AxisMove m;
  auto speed = [&]() -> uint64_t {
    switch (rng() % 6) {
      case 0: return 0;
      case 1: return ~0ull >> (rng() % 3);
      default: return (rng() >> 1) >> (rng() % 6);  // >= ~2^57: a step within ~128 ticks
    }
  };
  m.steps = rng() % 4 == 0 ? static_cast<uint32_t>(rng() % 3) : static_cast<uint32_t>(rng() % 60);
  m.dir = rng() & 1;
  m.v_start = speed();
  m.v_max = speed();
  m.v_end = speed();
  // Accelerations of at least 2^-19 step/tick^2: a move from rest to its first steps within a
  // few thousand ticks.
  m.acc = rng() % 3 == 0 ? 0 : ((rng() & ((1ull << 48) - 1)) >> (rng() % 3)) | (1ull << 45);
  m.dec = rng() % 3 == 0 ? 0 : ((rng() & ((1ull << 48) - 1)) >> (rng() % 3)) | (1ull << 45);
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
  // The same moves in ticks at the clocks users run: the register values differ, the cycle
  // counts do not.
  static const real clocks[] = {12e6, 25e6, 48e6, 100e6};
  const real f = clocks[rng() % 4];
  j.job.clock_hz = static_cast<uint64_t>(f);
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
        EncodedMove e = encode(random_ramp(rng, f), f);
        j.job.axes[a].moves.push_back(e.regs);
        j.ideal[a].push_back(e.ideal);
      }
    }
  }
  return j;
}

uint64_t abort_edge(uint64_t request_cycle) { return request_cycle + kTakeCycles + 1; }

uint64_t start_frame(uint64_t request_cycle) {
  // The first frame boundary after the edge that acts on it (the one ending r + kTakeCycles).
  uint64_t b = request_cycle + kTakeCycles + 1;
  while (b % kFrameCycles != kBoundaryCycle) ++b;
  return b + (kFrameCycles - kBoundaryCycle);
}

}  // namespace hexstep::test
