// SPDX-License-Identifier: Apache-2.0
// STOP (controlled deceleration to rest) and jog moves of the axis model.
// The stopping distance and duration are predicted independently of the model: from the speed
// s and position fraction p the axis holds after the stop edge, the rule "each later tick adds
// the old speed to the position and subtracts dec from the speed; the tick whose old speed is
// below dec is the last" sums in closed form to J = floor(s / dec) + 1 ticks covering
// J*s - dec*J*(J-1)/2 (units 2^-64 step). The physical check is v^2 / (2 dec) from kinematics.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
using u128 = unsigned __int128;
constexpr real kTwo64 = 18446744073709551616.0L;

PulseConfig fast_pulse() { return PulseConfig{}; }  // 1 cycle high, 1 low: never the bottleneck

struct StopCase {
  uint32_t steps_at_stop;  // steps_done() right after the stop edge
  uint32_t final_steps;    // steps_done() at rest
  uint64_t ticks;          // generator ticks from the stop edge until the move ended
  uint64_t s, p, dec;      // state after the stop edge
};

// Runs `m` on a fresh axis, issues STOP on the first tick where `when(axis)` holds, runs to
// idle. Returns what happened; fails the test if the axis never got there.
template <typename When>
StopCase run_stop(const AxisMove& m, When when) {
  AxisModel ax;
  const PulseConfig pc = fast_pulse();
  ax.tick(true, false, m, pc);
  EXPECT_TRUE(ax.busy());
  uint64_t guard = 0;
  while (!when(ax)) {
    ax.tick(false, false, m, pc);
    if (++guard > 50'000'000 || !ax.busy()) {
      ADD_FAILURE() << "stop condition never reached";
      return {};
    }
  }
  ax.tick(false, false, true, m, pc);
  StopCase c{ax.steps_done(), 0, 0, ax.speed(), ax.frac(), m.dec};
  EXPECT_TRUE(ax.stopping());
  EXPECT_EQ(ax.phase(), Phase::Decel);
  uint64_t prev_speed = ax.speed();
  while (ax.stopping()) {
    ax.tick(false, false, m, pc);
    ++c.ticks;
    if (ax.stopping()) {
      EXPECT_LT(ax.speed(), prev_speed) << "speed must fall every tick while stopping";
      prev_speed = ax.speed();
    }
    if (c.ticks > 50'000'000) {
      ADD_FAILURE() << "stop never completed";
      return c;
    }
  }
  while (ax.busy()) ax.tick(false, false, m, pc);  // owed steps are still pulsed
  c.final_steps = ax.steps_done();
  EXPECT_EQ(ax.position(), m.dir ? int64_t(c.final_steps) : -int64_t(c.final_steps));
  return c;
}

// The independent prediction of a stop from the state after the stop edge.
void expect_predicted(const StopCase& c, uint32_t n) {
  ASSERT_GT(c.dec, 0u);
  const uint64_t j = c.s / c.dec + 1;
  const u128 dist = u128(j) * c.s - u128(c.dec) * (u128(j) * (j - 1) / 2);
  const u128 total = u128(c.p) + dist;
  const uint64_t whole = static_cast<uint64_t>(total >> 64);
  const uint64_t expect_steps = std::min<uint64_t>(uint64_t(c.steps_at_stop) + whole, n);
  EXPECT_EQ(c.final_steps, expect_steps);
  if (expect_steps < n) EXPECT_EQ(c.ticks, j);
  // Kinematics: from speed v (steps/tick) at deceleration a (steps/tick^2) the motion covers
  // v^2/(2a) + v/2 steps in this discrete form; the whole steps issued differ by < 1 + 1.
  const real v = real(c.s) / kTwo64, a = real(c.dec) / kTwo64;
  const real physical = v * v / (2 * a);
  if (expect_steps < n)
    EXPECT_NEAR(real(c.final_steps - c.steps_at_stop), physical, 2.0L + v / 2)
        << "v=" << double(v) << " a=" << double(a);
}
}  // namespace

TEST(Stop, InEachPhaseEndsWherePredicted) {
  // 100 MHz: 0 -> 200 k steps/s at 2e6 steps/s^2 (accel 0.1 s, 10,000 steps), cruise, decel.
  const EncodedMove em = encode({60000, true, 0, 200000, 0, 2e6, 1e6});
  const AxisMove& m = em.regs;
  struct Where {
    const char* name;
    std::function<bool(const AxisModel&)> when;
  };
  const std::vector<Where> cases = {
      {"accel early", [](const AxisModel& a) { return a.steps_done() >= 50; }},
      {"accel late", [](const AxisModel& a) { return a.steps_done() >= 9000; }},
      {"cruise", [](const AxisModel& a) { return a.phase() == Phase::Cruise && a.steps_done() >= 20000; }},
      {"decel first tick", [](const AxisModel& a) { return a.phase() == Phase::Decel; }},
      {"decel mid", [](const AxisModel& a) { return a.phase() == Phase::Decel && a.steps_done() >= 50000; }},
  };
  for (const auto& w : cases) {
    SCOPED_TRACE(w.name);
    const StopCase c = run_stop(m, w.when);
    expect_predicted(c, m.steps);
    EXPECT_LT(c.final_steps, m.steps) << "a stop ends before the planned end";
    std::printf("%-16s stop at step %u, speed %.1f steps/s -> rest at step %u after %llu ticks\n",
                w.name, c.steps_at_stop, double(real(c.s) / kTwo64 * 1e8), c.final_steps,
                static_cast<unsigned long long>(c.ticks));
  }
}

TEST(Stop, NeverOvershootsTheMoveEnd) {
  // Stop late in the deceleration: the planned end comes first and the move ends at N.
  const EncodedMove em = encode({3000, false, 0, 50000, 0, 1e6, 1e5});
  const StopCase c = run_stop(em.regs, [](const AxisModel& a) { return a.steps_done() >= 2990; });
  EXPECT_EQ(c.final_steps, 3000u);
}

TEST(Stop, WithZeroDecEndsOnTheNextTick) {
  // Constant-speed move: v_start = v_max = v_end, dec = 0 (allowed, v_end is the floor).
  AxisMove m;
  m.steps = 1000;
  m.v_start = m.v_max = m.v_end = uint64_t(1) << 60;  // 1/16 step per cycle
  m.dec_step = 1000;
  const StopCase c = run_stop(m, [](const AxisModel& a) { return a.steps_done() >= 100; });
  EXPECT_EQ(c.ticks, 1u);
  EXPECT_LE(c.final_steps, c.steps_at_stop + 1);
}

TEST(Stop, IdleOrFinishedAxisIgnoresStop) {
  AxisModel ax;
  const PulseConfig pc = fast_pulse();
  const EncodedMove em = encode({5, true, 0, 1e6, 0, 1e9, 1e9});
  ax.tick(false, false, true, em.regs, pc);
  EXPECT_FALSE(ax.busy());
  EXPECT_FALSE(ax.stopping());
  ax.tick(true, false, em.regs, pc);
  while (ax.busy()) ax.tick(false, false, em.regs, pc);
  ax.tick(false, false, true, em.regs, pc);
  EXPECT_FALSE(ax.busy());
  EXPECT_FALSE(ax.err());
  EXPECT_EQ(ax.position(), 5);
  // A new move after a stop runs normally to its N.
  ax.tick(true, false, em.regs, pc);
  while (ax.busy()) ax.tick(false, false, em.regs, pc);
  EXPECT_EQ(ax.position(), 10);
}

TEST(Stop, StartWhileStoppingIsRefused) {
  AxisModel ax;
  const PulseConfig pc = fast_pulse();
  const EncodedMove em = encode({20000, true, 0, 100000, 0, 1e6, 1e6});
  ax.tick(true, false, em.regs, pc);
  while (ax.steps_done() < 3000) ax.tick(false, false, em.regs, pc);
  ax.tick(false, false, true, em.regs, pc);
  ASSERT_TRUE(ax.stopping());
  ax.tick(true, false, em.regs, pc);
  EXPECT_TRUE(ax.err());
  EXPECT_TRUE(ax.stopping());
}

TEST(Jog, RampsHoldsAndStopsOnlyOnStop) {
  AxisModel ax;
  const PulseConfig pc = fast_pulse();
  // 0 -> 100 k steps/s at 1e6 steps/s^2 (0.1 s, 5,000 steps), at 100 MHz; steps field ignored.
  AxisMove m;
  const real clk = real(kDefaultClockHz);
  ASSERT_TRUE(speed_to_reg(100000, clk, m.v_max));
  ASSERT_TRUE(accel_to_reg(1e6, clk, m.acc));
  ASSERT_TRUE(accel_to_reg(4e6, clk, m.dec));
  m.dir = false;
  m.jog = true;
  m.steps = 5;
  m.acc_steps = 1;
  m.dec_step = 2;
  ASSERT_EQ(validate_move(m), 0u);
  ax.tick(true, false, m, pc);
  ASSERT_TRUE(ax.busy());
  EXPECT_EQ(ax.phase(), Phase::Accel);
  uint64_t ticks = 0;
  while (ax.phase() == Phase::Accel && ++ticks < 20'000'000) ax.tick(false, false, m, pc);
  EXPECT_EQ(ax.phase(), Phase::Cruise);
  EXPECT_EQ(ax.speed(), m.v_max);
  // Ramp time v/a = 0.1 s = 1e7 ticks, within the register rounding.
  EXPECT_NEAR(double(ticks), 1e7, 2.0);
  for (int i = 0; i < 3'000'000; ++i) ax.tick(false, false, m, pc);  // 30 ms more
  EXPECT_EQ(ax.phase(), Phase::Cruise);
  EXPECT_TRUE(ax.busy());
  // 5,000 ramp steps + 3,000 cruise steps, far beyond steps = 5.
  EXPECT_NEAR(double(ax.steps_done()), 8000.0, 2.0);
  const StopCase c = [&] {
    ax.tick(false, false, true, m, pc);
    StopCase r{ax.steps_done(), 0, 0, ax.speed(), ax.frac(), m.dec};
    while (ax.stopping()) ax.tick(false, false, m, pc), ++r.ticks;
    while (ax.busy()) ax.tick(false, false, m, pc);
    r.final_steps = ax.steps_done();
    return r;
  }();
  expect_predicted(c, ~0u);
  // 100 k steps/s at 4e6 steps/s^2: v^2 / 2a = 1,250 steps.
  EXPECT_NEAR(double(c.final_steps - c.steps_at_stop), 1250.0, 2.0);
  EXPECT_EQ(ax.position(), -int64_t(c.final_steps));
}

TEST(Jog, RefusedWithoutAWayToStartOrStop) {
  AxisMove ok;
  ok.jog = true;
  ok.v_max = 1ull << 50;
  ok.acc = 1000;
  ok.dec = 1000;
  EXPECT_EQ(validate_move(ok), 0u);
  AxisMove m = ok;
  m.dec = 0;
  EXPECT_EQ(validate_move(m), uint32_t(kErrJogNoDec));
  m = ok;
  m.v_max = 0;
  EXPECT_NE(validate_move(m) & kErrVmaxZero, 0u);
  m = ok;
  m.v_start = ok.v_max + 1;
  EXPECT_EQ(validate_move(m), uint32_t(kErrStartAboveMax));
  m = ok;
  m.acc = 0;
  EXPECT_EQ(validate_move(m), uint32_t(kErrNoStart));
  m.v_start = 5;  // constant-speed jog
  EXPECT_EQ(validate_move(m), 0u);
  // A refused jog pulses done and err and does not move.
  AxisModel ax;
  m = ok;
  m.dec = 0;
  ax.tick(true, false, m, PulseConfig{});
  EXPECT_TRUE(ax.done());
  EXPECT_TRUE(ax.err());
  EXPECT_FALSE(ax.busy());
}

// Event mode with STOP strobes at given cycles equals cycle mode (the same rising edges at the
// same cycles and the same final state).
TEST(Stop, EventModeIdenticalToCycleMode) {
  const uint64_t seed = test_seed() + 7;
  std::printf("SEED=%llu (this test uses SEED+7)\n", static_cast<unsigned long long>(seed - 7));
  std::mt19937_64 rng(seed);
  for (int iter = 0; iter < 60; ++iter) {
    AxisMove m = encode(random_ramp(rng)).regs;
    if (iter % 3 == 0) {
      m.jog = true;
      if (m.dec == 0) m.dec = 1ull << 30;
      if (m.v_start == 0 && m.acc == 0) m.acc = 1ull << 30;
    }
    const PulseConfig pc = fast_pulse();
    // Find the move's length in cycle mode first, then stop somewhere inside it.
    AxisModel probe;
    probe.tick(true, false, m, pc);
    uint64_t len = 1;
    while (probe.busy() && len < 3'000'000) probe.tick(false, false, m, pc), ++len;
    const uint64_t stop_at = 1 + rng() % len;
    std::vector<uint64_t> r1, r2;
    AxisModel a, b;
    a.tick(true, false, m, pc);
    b.tick(true, false, m, pc);
    uint64_t t = 1;
    for (; a.busy() && t < 50'000'000; ++t) {
      a.tick(false, false, t == stop_at, m, pc);
      if (a.rose()) r1.push_back(t);
    }
    uint64_t u = 1;
    while (b.busy() && u < 50'000'000) {
      uint64_t q = b.quiet_ticks(pc);
      if (u <= stop_at) q = std::min<uint64_t>(q, stop_at - u);
      else q = std::min<uint64_t>(q, 50'000'000 - u);
      if (q > 0) {
        b.skip(q);
        u += q;
        continue;
      }
      b.tick(false, false, u == stop_at, m, pc);
      if (b.rose()) r2.push_back(u);
      ++u;
    }
    ASSERT_EQ(r1, r2) << "iteration " << iter << " stop at " << stop_at;
    EXPECT_EQ(t, u) << "iteration " << iter;
    EXPECT_EQ(a.position(), b.position());
    EXPECT_EQ(a.steps_done(), b.steps_done());
  }
}
