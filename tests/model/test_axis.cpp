// SPDX-License-Identifier: Apache-2.0
// The per-tick generator AxisGen and the loader's rules (validate_move, make_slot), checked
// against the seeds' worked examples and formulas and against independent expectations
// (never against the model's own earlier output). A tick is one frame: speeds count steps per
// tick, accelerations steps per tick^2 (docs/ARCHITECTURE.md, "One tick").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "axis_run.hpp"
#include "rules.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
using u128 = unsigned __int128;

// Ticks a move to its end; the ticks that stepped (1-based) and the phase after every tick.
struct Ticked {
  std::vector<uint64_t> step_ticks;
  std::vector<Phase> phase;   // phase() after tick k at index k - 1
  std::vector<uint64_t> speed;  // speed() after tick k
  uint64_t ticks = 0;
  bool ended = false;
};
Ticked tick_all(const AxisMove& m, uint64_t limit = 50'000'000, bool keep_phase = false) {
  Ticked t;
  AxisGen g;
  g.begin(make_slot(m));
  while (g.run() && t.ticks < limit) {
    const TickOut o = g.tick();
    ++t.ticks;
    if (o.step) t.step_ticks.push_back(t.ticks);
    if (keep_phase) {
      t.phase.push_back(g.phase());
      t.speed.push_back(g.speed());
    }
    if (o.ended) t.ended = true;
  }
  return t;
}

// The sub-tick offset as docs/ARCHITECTURE.md states it: floor(32 e_t / s_t) on the top
// kSubtickBits bits, at most 31, 0 when s_t is 0.
unsigned doc_subtick(uint64_t e, uint64_t s) {
  const uint64_t et = e >> (64 - kSubtickBits), st = s >> (64 - kSubtickBits);
  if (st == 0) return 0;
  return static_cast<unsigned>(std::min<uint64_t>(31, (uint64_t(kFrameCycles) * et) / st));
}
}  // namespace

// Ranade 2009, Table 1: at 0.2 step per update the speed-time product crosses a whole step at
// updates 5, 10, 15, 20, 25, and columns C - D (the fraction) run 0.2, 0.4, 0.6, 0.8, 1.0/0.0.
TEST(Axis, RanadeTable1PulseEveryFiveTicks) {
  const AxisMove m = directed("ranade_table1").job.axes[0].moves[0];
  ASSERT_EQ(m.steps, 5u);
  AxisGen g;
  g.begin(make_slot(m));
  std::vector<uint64_t> pulses;
  for (uint64_t k = 1; k <= 25; ++k) {
    ASSERT_TRUE(g.run()) << "tick " << k;
    const TickOut o = g.tick();
    if (o.step) pulses.push_back(k);
    // Column E (expected - current position) as a 64-bit fraction: k * s mod 2^64.
    EXPECT_EQ(g.frac(), static_cast<uint64_t>(u128(k) * m.v_start)) << "tick " << k;
    EXPECT_EQ(g.steps_done(), k / 5) << "tick " << k;  // column D after the pulse of tick k
    EXPECT_EQ(o.ended, k == 25) << "tick " << k;
  }
  EXPECT_EQ(pulses, (std::vector<uint64_t>{5, 10, 15, 20, 25}));
  EXPECT_FALSE(g.run());
  // On the pins: tick 5i's step rises on F0 + 32 (5i - 1) + 68 - q + 2, q from the overshoot.
  const AxisRun r = run_axis(m);
  ASSERT_EQ(r.rises.size(), 5u);
  for (unsigned i = 1; i <= 5; ++i) {
    const uint64_t e = static_cast<uint64_t>(u128(5 * i) * m.v_start);  // overshoot after the carry
    EXPECT_EQ(r.rises[i - 1].cycle, rise_cycle(0, 5 * i, doc_subtick(e, m.v_start))) << "pulse " << i;
  }
}

// The sub-tick division (a 5-step restoring division on the top bits) equals the documented
// quotient on random and boundary operands.
TEST(Axis, SubtickIsTheDocumentedQuotient) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 200000; ++i) {
    uint64_t s = rng() >> (rng() % 64);
    if (s == 0) s = 1;
    const uint64_t e = s == 1 ? 0 : rng() % s;  // the overshoot is below the speed
    ASSERT_EQ(subtick(e, s), doc_subtick(e, s)) << e << " / " << s;
  }
  EXPECT_EQ(subtick(0, ~0ull), 0u);
  EXPECT_EQ(subtick(~0ull - 1, ~0ull), 31u);
  EXPECT_EQ(subtick(1ull << 62, 1ull << 63), 16u);
  EXPECT_EQ(subtick(5, (1ull << (64 - kSubtickBits)) - 1), 0u);  // s_t = 0
}

// Ranade's triangular profile: from start_speed the move must cover desired_position in
// available_time; required_max_speed = 2 N / T - start_speed and required_acceleration =
// (required_max_speed - start_speed) * 2 / T. Start 1000 steps/s, 500 steps in 0.25 s give
// 3000 steps/s and 16000 steps/s^2; the core must take 0.25 s, reach 3000 steps/s at half time
// and end at exactly 500 steps.
TEST(Axis, RanadeTriangularExampleTakesTheAvailableTime) {
  const real f = 100e6, ft = tick_rate(f);
  const real start = 1000, T = 0.25L, N = 500;
  const real vmax = 2 * N / T - start, acc = (vmax - start) * 2 / T;
  ASSERT_NEAR(static_cast<double>(vmax), 3000.0, 1e-9);
  ASSERT_NEAR(static_cast<double>(acc), 16000.0, 1e-9);
  RampProfile p{500, true, start, vmax, start, acc, acc};
  const EncodedMove e = encode_ramp(p, f);
  const Ticked t = tick_all(e.regs, 50'000'000, true);
  ASSERT_TRUE(t.ended);
  EXPECT_EQ(t.step_ticks.size(), 500u);
  EXPECT_NEAR(static_cast<double>(t.ticks), static_cast<double>(T * ft), 2.0);
  uint64_t peak = 0, peak_tick = 0;
  for (size_t k = 0; k < t.speed.size(); ++k)
    if (t.speed[k] > peak) peak = t.speed[k], peak_tick = k + 1;
  EXPECT_NEAR(static_cast<double>(reg_to_speed(peak, f)), 3000.0, 0.1);
  EXPECT_NEAR(static_cast<double>(peak_tick), static_cast<double>(T / 2 * ft), 3.0);
}

// Stoychitch 2018, the Arduino program's inputs: K = 4096 steps per revolution, s = 2 pi rad,
// vs = 0.5 rad/s, vM = 2 rad/s, aM = 2 rad/s^2, m = a/d = 2. The triangular test (eq. 2-4)
// fails (v = vs + a t_a > vM), so the profile is trapezoidal: eq. 6-8 give N_a, N_v, N_d and
// the total time. The core must switch phases at those steps (+-1) and take that time.
TEST(Axis, StoychitchArduinoExampleTrapezoid) {
  const real K = 4096, alpha = 2 * 3.14159265358979323846264338327950288L / K;
  const real s = 2 * 3.14159265358979323846264338327950288L, vs = 0.5L, vM = 2, a = 2, m = 2;
  // Eq. 4: the triangular time, eq. 2: t_a; the peak it would need is above vM.
  const real T3 = -vs / a * (1 + m) + std::sqrt(std::pow(vs / a * (1 + m), 2) + 2 * s / a * (1 + m));
  ASSERT_GT(vs + a * T3 / (1 + m), vM);
  // Eq. 6-8.
  const real ta = (vM - vs) / a, Tad = ta * (1 + m);
  const real sad = vs * Tad + a * Tad * Tad / (2 * (1 + m));
  const real tv = (s - sad) / vM, T = Tad + tv;
  const real Nad = sad / alpha;
  const real Na = std::ceil(Nad / (1 + m)), Nd = Nad - Na;
  const uint32_t N = static_cast<uint32_t>(std::llround(s / alpha));
  ASSERT_EQ(N, 4096u);
  // In steps: speeds and accelerations divided by alpha; the move ends at vs (eq. 1's profile).
  const real f = 12e6, ft = tick_rate(f);
  RampProfile p{N, true, vs / alpha, vM / alpha, vs / alpha, a / alpha, a / m / alpha};
  const EncodedMove e = encode_ramp(p, f);
  ASSERT_EQ(validate_move(e.regs), 0u);
  AxisGen g;
  g.begin(make_slot(e.regs));
  uint64_t ticks = 0;
  uint32_t cruise_at = 0, decel_at = 0;
  Phase prev = g.phase();
  while (g.run()) {
    g.tick();
    ++ticks;
    const Phase ph = g.phase();
    if (ph != prev && ph == Phase::Cruise) cruise_at = g.steps_done();
    if (ph != prev && ph == Phase::Decel) decel_at = g.steps_done();
    prev = ph;
  }
  EXPECT_EQ(g.steps_done(), N);
  std::printf("Stoychitch: N_a %.2f N_d %.2f T %.4f s; core: cruise from step %u, decel from %u, %.4f s\n",
              static_cast<double>(Na), static_cast<double>(Nd), static_cast<double>(T), cruise_at, decel_at,
              static_cast<double>(ticks / ft));
  // Eq. 8 rounds N_a up (by up to one step, moving N_d down by as much), and the core's phase
  // changes are seen at whole steps: within two steps.
  EXPECT_NEAR(static_cast<double>(cruise_at), static_cast<double>(Na), 2.0);
  EXPECT_NEAR(static_cast<double>(decel_at), static_cast<double>(N - Nd), 2.0);
  // The core's time equals T within the rounding of the register values and one tick for the
  // last step.
  EXPECT_NEAR(static_cast<double>(ticks / ft), static_cast<double>(T), static_cast<double>(2 / ft));
}

// AVR446: from rest at acceleration a the n-th step is at t_n = sqrt(2 n / a) (eq. 9 with
// alpha = 1 step); a triangular move of N steps starts to decelerate at n1 = N d / (a + d).
TEST(Axis, Avr446StepInstantsFromRestAndDecelerationPoint) {
  const real f = 48e6, ft = tick_rate(f);
  const real a = 3e6, d = 1.2e7;  // acc != dec (4x), both representable at 48 MHz
  const uint32_t N = 5000;
  Ramp r{N, true, 0, 1e9, 0, a, d};  // no speed limit in reach: triangular
  const EncodedMove e = encode(r, f);
  ASSERT_LT(e.ideal.s_cruise, 1e-6L);
  const AxisRun run = run_axis(e.regs);
  ASSERT_EQ(run.rises.size(), N);
  const real n1 = real(N) * d / (a + d);
  unsigned checked = 0;
  for (const AxisRise& x : run.rises) {
    if (x.step >= n1 - 1) break;
    const real tn = std::sqrt(2 * real(x.step) / a);
    const real want = tn * f + kStepLatency;
    const real allow = 2 + 0.001L / (a * tn) * f;
    EXPECT_LE(std::fabs(real(x.cycle) - want), allow) << "step " << x.step;
    ++checked;
  }
  EXPECT_GT(checked, 3000u);
  AxisGen g;
  g.begin(make_slot(e.regs));
  uint32_t decel_at = 0;
  while (g.run() && !decel_at) {
    g.tick();
    if (g.phase() == Phase::Decel) decel_at = g.steps_done();
  }
  EXPECT_NEAR(static_cast<double>(decel_at), static_cast<double>(n1), 1.5);
  (void)ft;
}

// Every accepted move ends after exactly its N steps: directed vectors and thousands of random
// planned ramps (triangular and trapezoidal, v_start/v_end zero or not, acc != dec) and raw
// register values, at every clock.
TEST(Axis, EveryAcceptedMoveMakesExactlyNSteps) {
  for (const NamedJob& nj : directed_jobs())
    for (unsigned a = 0; a < kNumAxes; ++a)
      for (const AxisMove& m : nj.job.axes[a].moves) {
        if (make_slot(m).empty) continue;
        const Ticked t = tick_all(m);
        EXPECT_TRUE(t.ended) << nj.name;
        EXPECT_EQ(t.step_ticks.size(), m.steps) << nj.name;
      }
  const uint64_t seed = test_seed();
  std::printf("SEED=%llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  static const real clocks[] = {12e6, 25e6, 48e6, 100e6};
  unsigned trap = 0, tri = 0, ends = 0, asym = 0, raw = 0;
  for (int i = 0; i < 3000; ++i) {
    const real f = clocks[i % 4];
    const EncodedMove e = encode(random_ramp(rng, f), f);
    if (e.regs.steps == 0) continue;
    ASSERT_EQ(validate_move(e.regs), 0u) << "SEED=" << seed << " move " << i;
    const Ticked t = tick_all(e.regs);
    ASSERT_TRUE(t.ended) << "SEED=" << seed << " move " << i;
    ASSERT_EQ(t.step_ticks.size(), e.regs.steps) << "SEED=" << seed << " move " << i;
    if (e.ideal.a > 0 && e.ideal.d > 0) ++(e.ideal.s_cruise > 0.5L ? trap : tri);
    if (e.ideal.v0 > 0 || e.ideal.ve > 0) ++ends;
    if (e.ideal.a > 0 && e.ideal.d > 0 && e.ideal.a != e.ideal.d) ++asym;
  }
  for (int i = 0; i < 3000; ++i) {
    const AxisMove m = random_raw_move(rng);
    const SlotMove s = make_slot(m);
    if (s.bad || s.empty) continue;
    const Ticked t = tick_all(m);
    ASSERT_TRUE(t.ended) << "SEED=" << seed << " raw move " << i;
    ASSERT_EQ(t.step_ticks.size(), m.steps) << "SEED=" << seed << " raw move " << i;
    ++raw;
  }
  std::printf("%u trapezoids, %u triangles, %u with non-zero ends, %u with acc != dec, %u raw\n", trap, tri, ends, asym,
              raw);
  EXPECT_GT(trap, 100u);
  EXPECT_GT(tri, 100u);
  EXPECT_GT(ends, 1000u);
  EXPECT_GT(asym, 1000u);
  EXPECT_GT(raw, 300u);
}

// The phase sequence of docs/ARCHITECTURE.md ("One tick"): the first phase from the counts,
// the speed clamped at v_max while accelerating and held above the floor while decelerating,
// never above v_max at all.
TEST(Axis, PhasesClampAndFloor) {
  {  // DECEL from the first tick when dec_step == 0 and dec_frac == 0; v_dec loaded once.
    AxisMove m = cruise(10, 1ull << 62);
    m.dec_step = 0;
    m.dec = 1ull << 40;
    m.v_dec = 1ull << 61;
    m.v_end = 1ull << 60;
    AxisGen g;
    g.begin(make_slot(m));
    EXPECT_EQ(g.phase(), Phase::Decel);
    g.tick();
    EXPECT_EQ(g.speed(), m.v_dec);
    g.tick();
    EXPECT_EQ(g.speed(), m.v_dec - m.dec);
  }
  {  // ACCEL when acc_steps != 0: S + acc each tick, clamped at v_max, then CRUISE.
    AxisMove m = cruise(50, 1ull << 58);
    m.v_max = (1ull << 58) + 5 * (1ull << 46) + 7;
    m.acc = 1ull << 46;
    m.acc_steps = 50;
    AxisGen g;
    g.begin(make_slot(m));
    EXPECT_EQ(g.phase(), Phase::Accel);
    for (int k = 1; k <= 5; ++k) {
      g.tick();
      EXPECT_EQ(g.speed(), (1ull << 58) + k * (1ull << 46)) << k;
      EXPECT_EQ(g.phase(), Phase::Accel) << k;
    }
    g.tick();  // 2^58 + 6 * 2^46 >= v_max: clamped, and the phase becomes CRUISE
    EXPECT_EQ(g.speed(), m.v_max);
    EXPECT_EQ(g.phase(), Phase::Cruise);
    g.tick();
    EXPECT_EQ(g.speed(), m.v_max);
  }
  {  // acc_steps ends the acceleration before v_max.
    AxisMove m = cruise(50, 1ull << 62);
    m.v_start = 1ull << 60;
    m.acc = 1ull << 46;
    m.acc_steps = 2;
    AxisGen g;
    g.begin(make_slot(m));
    while (g.steps_done() < 2) {
      ASSERT_EQ(g.phase(), Phase::Accel);
      g.tick();
    }
    EXPECT_EQ(g.phase(), Phase::Cruise);
    EXPECT_LT(g.speed(), m.v_max);
  }
  {  // CRUISE from the start when acc_steps == 0.
    AxisGen g;
    g.begin(make_slot(cruise(5, 1ull << 62)));
    EXPECT_EQ(g.phase(), Phase::Cruise);
  }
  // Random accepted raw moves: S never above v_max; never below the floor while decelerating.
  std::mt19937_64 rng(11);
  unsigned checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const AxisMove m = random_raw_move(rng);
    const SlotMove s = make_slot(m);
    if (s.bad || s.empty) continue;
    const Ticked t = tick_all(m, 1'000'000, true);
    for (size_t k = 0; k < t.speed.size(); ++k) {
      ASSERT_LE(t.speed[k], m.v_max) << "raw move " << i << " tick " << k + 1;
      if (t.phase[k] == Phase::Decel && k > 0 && t.phase[k - 1] == Phase::Decel) {
        ASSERT_GE(t.speed[k], s.floor) << "raw move " << i << " tick " << k + 1;
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, 300u);
}

// The refusal rules of docs/ARCHITECTURE.md, each broken alone on a valid move, next to the
// boundary value the same rule still accepts (tests/common/rules.hpp); make_slot marks exactly
// the refused ones bad.
TEST(Axis, RefusalRulesEachAloneAndAtTheBoundary) {
  const AxisMove ok = trapezoid(40);
  ASSERT_EQ(validate_move(ok), 0u);
  for (const RuleCase& c : rule_cases(ok)) {
    EXPECT_EQ(validate_move(c.m), c.bits) << c.what;
    const SlotMove s = make_slot(c.m);
    EXPECT_EQ(s.bad, c.bits != 0) << c.what;
    EXPECT_FALSE(s.empty) << c.what;
  }
  // steps == 0 (not jog) is empty, whatever else the registers hold.
  AxisMove e = ok;
  e.steps = 0;
  e.v_max = 0;
  EXPECT_EQ(validate_move(e), 0u);
  EXPECT_TRUE(make_slot(e).empty);
  EXPECT_FALSE(make_slot(e).bad);
}

// make_slot keeps what the staging registers hold: the implemented bits of each word, the floor
// resolved (v_end, or dec if v_end is 0), dec_frac aligned to 32 bits.
TEST(Axis, SlotHoldsTheImplementedBits) {
  Widths w;
  w.acc = 40;
  w.steps = 12;
  w.dec_frac = 8;
  AxisMove m = trapezoid(40);
  m.acc = (1ull << 30) | (1ull << 45);  // bit 45 is above ACC_W = 40: dropped
  m.steps |= 1u << 20;  // above STEP_W = 12
  m.dec_frac = 0x1A5;   // 9 bits, DFRAC_W = 8
  const SlotMove s = make_slot(m, w);
  EXPECT_EQ(s.m.acc, 1ull << 30);
  EXPECT_EQ(s.m.steps, 40u);
  EXPECT_EQ(s.m.dec_frac, 0xA5u);
  EXPECT_EQ(s.dfa, 0xA5u << 24);
  EXPECT_EQ(s.floor, m.v_end);
  AxisMove z = trapezoid(40);
  z.v_end = 0;
  EXPECT_EQ(make_slot(z).floor, z.dec);
  EXPECT_TRUE(make_slot(cruise(3, 1ull << 60)).init == Phase::Cruise);
  AxisMove dz = trapezoid(40);
  dz.dec = 0;
  EXPECT_TRUE(make_slot(dz).dec_zero);
}
