// SPDX-License-Identifier: Apache-2.0
// Event mode: skipping quiet ticks with closed-form jumps (AxisGen::quiet_ticks/skip) must give
// exactly what ticking gives: the same steps on the same ticks, the same phase changes, the
// same final state, with STOP at any tick and for jog moves. The frame runner of
// tests/common/axis_run (used by the accuracy and planner tests) must equal the cycle-exact
// TopModel on the pins, in both of its modes.
#include <gtest/gtest.h>

#include <cstdio>

#include "axis_run.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
struct Trace {
  std::vector<uint64_t> steps;                          // tick of every step
  std::vector<std::pair<uint64_t, Phase>> phases;       // tick of every phase change
  uint64_t ticks = 0, speed = 0, frac = 0;
  uint32_t done = 0;
};

// Runs the move to its end (or `limit` ticks), entering a stop after tick `stop_at` (0: never).
Trace run(const AxisMove& m, bool event, uint64_t stop_at, uint64_t limit) {
  Trace t;
  AxisGen g;
  g.begin(make_slot(m));
  Phase ph = g.phase();
  while (g.run() && t.ticks < limit) {
    if (event) {
      uint64_t q = g.quiet_ticks();
      if (stop_at > t.ticks) q = std::min(q, stop_at - t.ticks - 1);  // tick stop_at itself runs
      q = std::min(q, limit - t.ticks);
      if (q > 0) {
        g.skip(q);
        t.ticks += q;
        if (g.phase() != ph) ADD_FAILURE() << "phase changed inside a skip at tick " << t.ticks;
        continue;
      }
    }
    const TickOut o = g.tick();
    ++t.ticks;
    if (o.step) t.steps.push_back(t.ticks);
    if (t.ticks == stop_at) g.enter_stop();
    if (g.phase() != ph) t.phases.push_back({t.ticks, g.phase()});
    ph = g.phase();
  }
  t.speed = g.speed();
  t.frac = g.frac();
  t.done = g.steps_done();
  return t;
}

void same(const AxisMove& m, uint64_t stop_at, uint64_t limit, const std::string& name) {
  const Trace a = run(m, false, stop_at, limit), b = run(m, true, stop_at, limit);
  ASSERT_EQ(a.steps, b.steps) << name;
  ASSERT_EQ(a.phases, b.phases) << name;
  EXPECT_EQ(a.ticks, b.ticks) << name;
  EXPECT_EQ(a.speed, b.speed) << name;
  EXPECT_EQ(a.frac, b.frac) << name;
  EXPECT_EQ(a.done, b.done) << name;
}
}  // namespace

TEST(EventMode, GeneratorSkipEqualsTicking) {
  const uint64_t seed = test_seed();
  std::printf("SEED=%llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  static const real clocks[] = {12e6, 48e6, 100e6};
  for (int i = 0; i < 600; ++i) {
    const std::string name = "SEED=" + std::to_string(seed) + " move " + std::to_string(i);
    AxisMove m;
    switch (i % 4) {
      case 0: case 1: m = encode(random_ramp(rng, clocks[i % 3]), clocks[i % 3]).regs; break;
      case 2: m = random_raw_move(rng); break;
      default:  // jog: ramps, cruises, ends only by the stop
        m = encode(random_ramp(rng), 100e6).regs;
        m.jog = true;
        if (m.dec == 0) m.dec = 1ull << 40;
        if (m.v_start == 0 && m.acc == 0) m.acc = 1ull << 40;
        break;
    }
    const SlotMove s = make_slot(m);
    if (s.bad || s.empty) continue;
    // Its length without a stop, then a stop somewhere inside it (or none).
    const uint64_t len = run(m, false, 0, 200'000).ticks;
    const uint64_t stop_at = (i % 5 == 0 && !m.jog) ? 0 : 1 + rng() % len;
    same(m, stop_at, 2'000'000, name);
  }
  // The largest v_max (all ones) from rest: the ticks to the clamp, (v_max - S) / acc rounded
  // up, must not overflow.
  {
    AxisMove m = cruise(38, 0);
    m.v_max = ~0ull;
    m.acc = 1ull << 47;
    m.acc_steps = 12;
    m.v_end = m.v_dec = 1ull << 60;
    ASSERT_EQ(validate_move(m), 0u);
    same(m, 0, 2'000'000, "v_max all ones from rest");
  }
  // Long quiet stretches: slow ramps at 100 MHz (10 steps/s^2: hours of cycles).
  same(encode({60, true, 0, 1e4, 0, 10, 30}).regs, 0, 1ull << 40, "slow ramp");
  same(encode({25, false, 50, 1e4, 10, 1e4, 1e4}).regs, 0, 1ull << 40, "slow ends");
  same(encode({20000, true, 0, 5e4, 0, 1e5, 1e5}).regs, 150000, 1ull << 40, "stop in a long move");
}

// The frame runner gives exactly TopModel's STEP edges for the same move (time zero from the
// START write, docs/ARCHITECTURE.md), on every axis, with random pulse timing; and the same
// edges with and without its quiet-stretch jumps.
TEST(EventMode, FrameRunnerEqualsTheCycleExactModel) {
  const uint64_t seed = test_seed() + 1;
  std::printf("SEED=%llu (this test uses SEED+1)\n", static_cast<unsigned long long>(seed - 1));
  std::mt19937_64 rng(seed);
  unsigned stalls = 0;
  for (int i = 0; i < 160; ++i) {
    const real f = i % 2 ? 100e6 : 12e6;
    AxisMove m;
    if (i % 8 == 0) m = cruise(40 + rng() % 80, (~0ull >> 1) + (rng() >> 1), rng() & 1);  // > 0.5 step/tick
    else if (i % 8 == 1) m = random_raw_move(rng);
    else m = encode(random_ramp(rng, f), f).regs;
    const unsigned axis = static_cast<unsigned>(rng() % kNumAxes);
    PulseConfig pc;
    pc.step_high = rng() % 24;
    pc.step_low = rng() % 24;
    pc.dir_setup = rng() % 60;
    pc.dir_hold = rng() % 60;
    Job j;
    j.axes[axis].pulse = pc;
    j.axes[axis].moves.push_back(m);
    ModelSim sim;
    std::vector<uint64_t> model;
    const RunResult rr = run_job(sim, j, [&](const StepEvent& e) { model.push_back(e.cycle); });
    ASSERT_FALSE(rr.timed_out);
    const uint64_t f0 = start_frame(rr.setup_cycles);
    AxisRunOptions o;
    o.axis = axis;
    o.pulse = pc;
    const AxisRun ev = run_axis(m, o);
    o.event_mode = false;
    const AxisRun cy = run_axis(m, o);
    const std::string name = "SEED=" + std::to_string(seed - 1) + " move " + std::to_string(i);
    ASSERT_EQ(ev.rises.size(), model.size()) << name;
    ASSERT_EQ(cy.rises.size(), model.size()) << name;
    for (size_t k = 0; k < model.size(); ++k) {
      ASSERT_EQ(ev.rises[k].cycle, model[k] + rr.setup_cycles - f0) << name << " step " << k + 1;
      ASSERT_EQ(cy.rises[k].cycle, ev.rises[k].cycle) << name << " step " << k + 1;
    }
    EXPECT_EQ(ev.stalled, cy.stalled) << name;
    stalls += ev.stalled != 0;
  }
  std::printf("%u moves paused by the output stage\n", stalls);
}
