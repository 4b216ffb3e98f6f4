// SPDX-License-Identifier: Apache-2.0
// STOP (controlled deceleration to rest) and jog moves of the per-tick generator.
// The stopping distance and duration are predicted independently of the model: from the speed
// s and position fraction p the generator holds after the stop frame's tick, the rule of
// docs/ARCHITECTURE.md ("each later tick subtracts dec; the move ends on the tick whose old
// speed is below dec") sums in closed form to J = floor(s / dec) + 1 ticks covering
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

struct StopCase {
  uint32_t steps_at_stop = 0;  // steps_done() right after the stop frame's tick
  uint32_t final_steps = 0;    // steps_done() at rest
  uint64_t ticks = 0;          // ticks from the stop until the move ended
  uint64_t s = 0, p = 0, dec = 0;  // state when the stop took effect
  bool ended_before = false;   // the move ended in the stop frame's own tick
};

// Runs `m` until `when(gen)` holds, then the stop frame: its tick runs as usual, then the
// generator enters the stop (docs/ARCHITECTURE.md, "STOP"); runs to rest.
StopCase run_stop(const AxisMove& m, const std::function<bool(const AxisGen&)>& when) {
  StopCase c;
  AxisGen g;
  g.begin(make_slot(m));
  uint64_t guard = 0;
  while (!when(g)) {
    g.tick();
    if (++guard > 50'000'000 || !g.run()) {
      ADD_FAILURE() << "stop condition never reached";
      return c;
    }
  }
  g.tick();
  if (!g.run()) {
    c.ended_before = true;
    c.final_steps = c.steps_at_stop = g.steps_done();
    return c;
  }
  g.enter_stop();
  c.steps_at_stop = g.steps_done();
  c.s = g.speed();
  c.p = g.frac();
  c.dec = m.dec;
  EXPECT_TRUE(g.stopping());
  EXPECT_EQ(g.phase(), Phase::Decel);
  uint64_t prev = g.speed();
  while (g.run()) {
    g.tick();
    ++c.ticks;
    if (g.run()) {
      EXPECT_EQ(g.speed(), prev - m.dec) << "each stopping tick subtracts dec";
      prev = g.speed();
    }
    if (c.ticks > 50'000'000) {
      ADD_FAILURE() << "stop never completed";
      return c;
    }
  }
  c.final_steps = g.steps_done();
  return c;
}

// The independent prediction of a stop from the state it started from.
void expect_predicted(const StopCase& c, uint32_t n) {
  ASSERT_GT(c.dec, 0u);
  const uint64_t j = c.s / c.dec + 1;
  const u128 dist = u128(j) * c.s - u128(c.dec) * (u128(j) * (j - 1) / 2);
  const uint64_t whole = static_cast<uint64_t>((u128(c.p) + dist) >> 64);
  const uint64_t expect_steps = std::min<uint64_t>(uint64_t(c.steps_at_stop) + whole, n);
  EXPECT_EQ(c.final_steps, expect_steps);
  if (expect_steps < n) {
    EXPECT_EQ(c.ticks, j);
  }
  // Kinematics: from speed v (steps/tick) at deceleration a (steps/tick^2) the motion covers
  // v^2/(2a) + v/2 steps in this discrete form; the whole steps issued differ by < 1 + 1.
  const real v = real(c.s) / kTwo64, a = real(c.dec) / kTwo64;
  if (expect_steps < n) {
    EXPECT_NEAR(real(c.final_steps - c.steps_at_stop), v * v / (2 * a), 2.0L + v / 2)
        << "v=" << double(v) << " a=" << double(a);
  }
}
}  // namespace

TEST(Stop, InEachPhaseEndsWherePredicted) {
  // 100 MHz: 0 -> 200 k steps/s at 2e6 steps/s^2 (0.1 s, 10,000 steps), cruise, decelerate at
  // 1e6 steps/s^2 (20,000 steps).
  const EncodedMove em = encode({60000, true, 0, 200000, 0, 2e6, 1e6});
  const AxisMove& m = em.regs;
  struct Where {
    const char* name;
    std::function<bool(const AxisGen&)> when;
    bool before_decel;  // stopping at the planned deceleration itself ends at N
  };
  const std::vector<Where> cases = {
      {"accel early", [](const AxisGen& a) { return a.steps_done() >= 50; }, true},
      {"accel late", [](const AxisGen& a) { return a.steps_done() >= 9000; }, true},
      {"cruise", [](const AxisGen& a) { return a.phase() == Phase::Cruise && a.steps_done() >= 20000; }, true},
      {"decel first tick", [](const AxisGen& a) { return a.phase() == Phase::Decel; }, false},
      {"decel mid", [](const AxisGen& a) { return a.phase() == Phase::Decel && a.steps_done() >= 50000; }, false},
  };
  for (const auto& w : cases) {
    SCOPED_TRACE(w.name);
    const StopCase c = run_stop(m, w.when);
    ASSERT_FALSE(c.ended_before);
    expect_predicted(c, m.steps);
    if (w.before_decel) EXPECT_LT(c.final_steps, m.steps) << "a stop ends before the planned end";
    else EXPECT_LE(c.final_steps, m.steps);
    std::printf("%-16s stop at step %u, %.1f steps/s -> rest at step %u after %llu ticks\n", w.name,
                c.steps_at_stop, double(reg_to_speed(c.s, 100e6)), c.final_steps,
                static_cast<unsigned long long>(c.ticks));
  }
}

TEST(Stop, NeverOvershootsTheMoveEnd) {
  // Stop late in the deceleration: the planned end comes first and the move ends at N.
  const EncodedMove em = encode({3000, false, 0, 50000, 0, 1e6, 1e5});
  const StopCase c = run_stop(em.regs, [](const AxisGen& a) { return a.steps_done() >= 2990; });
  EXPECT_FALSE(c.ended_before);
  EXPECT_EQ(c.final_steps, 3000u);
}

TEST(Stop, WithZeroDecEndsOnTheNextTick) {
  // Constant-speed move with dec = 0 (allowed: v_end is the floor).
  const AxisMove m = cruise(1000, 1ull << 60);
  ASSERT_EQ(m.dec, 0u);
  const StopCase c = run_stop(m, [](const AxisGen& a) { return a.steps_done() >= 100; });
  EXPECT_EQ(c.ticks, 1u);
  EXPECT_LE(c.final_steps, c.steps_at_stop + 1);
}

TEST(Stop, OnAnIdleGeneratorDoesNothing) {
  AxisGen g;
  g.enter_stop();
  EXPECT_FALSE(g.run());
  EXPECT_FALSE(g.stopping());
  EXPECT_EQ(g.phase(), Phase::Idle);
  // After a move ended, a stop does not revive it; a new move runs to its N.
  const AxisMove m = cruise(5, 1ull << 62);
  g.begin(make_slot(m));
  while (g.run()) g.tick();
  g.enter_stop();
  EXPECT_FALSE(g.run());
  g.begin(make_slot(m));
  EXPECT_FALSE(g.stopping());
  uint64_t steps = 0;
  while (g.run()) steps += g.tick().step;
  EXPECT_EQ(steps, 5u);
}

TEST(Jog, RampsHoldsAndStopsOnlyOnStop) {
  // 0 -> 100 k steps/s at 1e6 steps/s^2 (0.1 s, 5,000 steps) at 100 MHz; the counts are ignored.
  const real clk = real(kDefaultClockHz), ft = tick_rate(clk);
  AxisMove m;
  ASSERT_TRUE(speed_to_reg(100000, clk, m.v_max));
  ASSERT_TRUE(accel_to_reg(1e6, clk, m.acc));
  ASSERT_TRUE(accel_to_reg(4e6, clk, m.dec));
  m.dir = false;
  m.jog = true;
  m.steps = 5;
  m.acc_steps = 1;
  m.dec_step = 2;
  ASSERT_EQ(validate_move(m), 0u);
  AxisGen g;
  g.begin(make_slot(m));
  EXPECT_EQ(g.phase(), Phase::Accel);
  uint64_t ticks = 0;
  while (g.phase() == Phase::Accel && ++ticks < 20'000'000) g.tick();
  EXPECT_EQ(g.phase(), Phase::Cruise);
  EXPECT_EQ(g.speed(), m.v_max);
  // Ramp time v/a = 0.1 s, within the register rounding.
  EXPECT_NEAR(double(ticks), double(0.1L * ft), 2.0);
  for (uint64_t i = 0; i < static_cast<uint64_t>(0.03L * ft); ++i) g.tick();  // 30 ms more
  EXPECT_EQ(g.phase(), Phase::Cruise);
  EXPECT_TRUE(g.run());
  // 5,000 ramp steps + 3,000 cruise steps, far beyond steps = 5.
  EXPECT_NEAR(double(g.steps_done()), 8000.0, 2.0);
  g.tick();  // the stop frame
  g.enter_stop();
  StopCase c;
  c.steps_at_stop = g.steps_done();
  c.s = g.speed();
  c.p = g.frac();
  c.dec = m.dec;
  while (g.run()) g.tick(), ++c.ticks;
  c.final_steps = g.steps_done();
  expect_predicted(c, ~0u);
  // 100 k steps/s at 4e6 steps/s^2: v^2 / 2a = 1,250 steps.
  EXPECT_NEAR(double(c.final_steps - c.steps_at_stop), 1250.0, 2.0);
}

TEST(Jog, WithoutAccelerationCruisesAtVStart) {
  AxisMove m;
  m.jog = true;
  m.v_start = m.v_max = 1ull << 60;
  m.dec = 1ull << 50;
  ASSERT_EQ(validate_move(m), 0u);
  AxisGen g;
  g.begin(make_slot(m));
  EXPECT_EQ(g.phase(), Phase::Cruise);
  for (int i = 0; i < 16 * 1000; ++i) g.tick();
  EXPECT_EQ(g.steps_done(), 1000u);
  EXPECT_EQ(g.speed(), m.v_start);
  EXPECT_TRUE(g.run());
}
