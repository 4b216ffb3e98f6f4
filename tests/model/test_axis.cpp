// SPDX-License-Identifier: Apache-2.0
// Model tests: behaviour required by the core issue, checked against the seeds and against
// independent expectations (never against the model's own earlier output).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
std::vector<StepEvent> run(CoreSim& c, const Job& j, bool event_mode = false, RunResult* res = nullptr) {
  std::vector<StepEvent> ev;
  RunOptions o;
  o.event_mode = event_mode;
  RunResult r = run_job(c, j, [&](const StepEvent& e) { ev.push_back(e); }, o);
  EXPECT_FALSE(r.timed_out);
  if (res) *res = r;
  return ev;
}

NamedJob find(const std::string& name) {
  for (auto& j : directed_jobs())
    if (j.name == name) return j;
  ADD_FAILURE() << "no vector " << name;
  return {};
}
}  // namespace

// Ranade 2009, Table 1: at 0.2 step per update a pulse is due at updates 5, 10, 15, 20, 25.
// The STEP pin rises one cycle after the update that crosses the step (kStepLatency).
TEST(Axis, RanadeTable1PulseEveryFiveUpdates) {
  CoreModel m;
  auto ev = run(m, find("ranade_table1").job);
  ASSERT_EQ(ev.size(), 5u);
  for (unsigned i = 0; i < 5; ++i) {
    EXPECT_EQ(ev[i].cycle, 5u * (i + 1) + kStepLatency) << "pulse " << i + 1;
    EXPECT_EQ(ev[i].step, i + 1);
  }
}

TEST(Axis, EveryDirectedJobMakesExactlyNStepsAndEndsAtTheSignedSum) {
  for (const NamedJob& nj : directed_jobs()) {
    CoreModel m;
    RunResult r;
    auto ev = run(m, nj.job, false, &r);
    for (unsigned a = 0; a < kNumAxes; ++a) {
      int64_t want_pos = 0;
      uint64_t want_steps = 0;
      for (const AxisMove& mv : nj.job.axes[a].moves) {
        want_steps += mv.steps;
        want_pos += mv.dir ? int64_t(mv.steps) : -int64_t(mv.steps);
      }
      EXPECT_EQ(r.steps[a], want_steps) << nj.name << " axis " << a;
      EXPECT_EQ(r.position[a], want_pos) << nj.name << " axis " << a;
      EXPECT_EQ(r.refused[a], 0u) << nj.name << " axis " << a;
    }
    // Step indices count 1..N within each move, DIR matches the move.
    std::vector<std::vector<uint32_t>> last(kNumAxes, std::vector<uint32_t>(8, 0));
    for (const StepEvent& e : ev) {
      EXPECT_EQ(e.step, ++last[e.axis][e.move]) << nj.name;
      EXPECT_EQ(e.dir, nj.job.axes[e.axis].moves[e.move].dir) << nj.name;
    }
  }
}

// Pulse shape and DIR timing, cycle by cycle, on every directed job and random pulse settings.
TEST(Axis, PulseHighLowSetupHoldAreRespectedEveryCycle) {
  std::mt19937_64 rng(7);
  std::vector<NamedJob> jobs = directed_jobs();
  for (int i = 0; i < 20; ++i) jobs.push_back(random_job(rng, 3, false));
  for (const NamedJob& nj : jobs) {
    CoreModel m;
    m.reset();
    CoreInputs in;
    std::array<size_t, kNumAxes> next{};
    for (unsigned a = 0; a < kNumAxes; ++a) {
      in.pulse[a] = nj.job.axes[a].pulse;
      if (!nj.job.axes[a].moves.empty()) {
        in.start_mask |= 1u << a;
        in.move[a] = nj.job.axes[a].moves[next[a]++];
      }
    }
    std::array<int64_t, kNumAxes> last_rise, last_fall, last_dir;
    last_rise.fill(-1000000);
    last_fall.fill(-1000000);
    last_dir.fill(-1000000);
    std::array<bool, kNumAxes> lvl{}, dir{};
    for (unsigned a = 0; a < kNumAxes; ++a) dir[a] = true;
    for (int64_t cyc = 0; cyc < 3000000; ++cyc) {
      m.tick(in);
      in.start_mask = 0;
      bool any = false;
      for (unsigned a = 0; a < kNumAxes; ++a) {
        const PulseConfig& p = in.pulse[a];
        const int64_t H = std::max<uint32_t>(p.step_high, 1), L = std::max<uint32_t>(p.step_low, 1);
        AxisOutputs o = m.out(a);
        bool l = o.step != p.step_invert, d = o.dir != p.dir_invert;
        if (d != dir[a]) {
          EXPECT_GE(cyc - last_rise[a], int64_t(p.dir_hold)) << nj.name << " DIR hold, axis " << a;
          last_dir[a] = cyc;
          dir[a] = d;
        }
        if (l && !lvl[a]) {
          EXPECT_GE(cyc - last_fall[a], L) << nj.name << " low time, axis " << a;
          EXPECT_GE(cyc - last_dir[a], int64_t(p.dir_setup)) << nj.name << " DIR setup, axis " << a;
          last_rise[a] = cyc;
        }
        if (!l && lvl[a]) {
          EXPECT_EQ(cyc - last_rise[a], H) << nj.name << " high time, axis " << a;
          last_fall[a] = cyc;
        }
        lvl[a] = l;
        if (o.done && next[a] < nj.job.axes[a].moves.size()) {
          in.start_mask |= 1u << a;
          in.move[a] = nj.job.axes[a].moves[next[a]++];
        }
        if (o.busy || l || ((in.start_mask >> a) & 1u)) any = true;
      }
      if (!any) break;
    }
  }
}

TEST(Axis, InvalidMovesAreRefusedWithoutMotion) {
  AxisMove ok;
  ok.steps = 10;
  ok.v_start = ok.v_max = ok.v_end = 1ull << 60;
  ok.dec_step = 10;
  ASSERT_EQ(validate_move(ok), 0u);
  struct Case { const char* what; AxisMove m; uint32_t bit; };
  std::vector<Case> cases;
  { AxisMove m = ok; m.v_max = 0; m.v_start = m.v_end = 0; cases.push_back({"v_max zero", m, kErrVmaxZero}); }
  { AxisMove m = ok; m.v_start = m.v_max + 1; cases.push_back({"start above max", m, kErrStartAboveMax}); }
  { AxisMove m = ok; m.v_end = m.v_max + 1; cases.push_back({"end above max", m, kErrEndAboveMax}); }
  { AxisMove m = ok; m.dec_step = 11; cases.push_back({"decel count past N", m, kErrCountPastN}); }
  { AxisMove m = ok; m.acc_steps = 11; cases.push_back({"accel count past N", m, kErrCountPastN}); }
  { AxisMove m = ok; m.v_end = 0; m.dec = 0; cases.push_back({"no floor", m, kErrNoFloor}); }
  // Floor dec above v_max (the formal speed-bound proof's counterexample, formal/, scaled up).
  { AxisMove m = ok; m.v_end = 0; m.dec = (1ull << 40) + 1; m.v_max = m.v_start = 1ull << 40;
    cases.push_back({"floor dec above max", m, kErrEndAboveMax}); }
  { AxisMove m = ok; m.v_start = 0; m.acc = 0; m.acc_steps = 3; cases.push_back({"zero speed, zero accel", m, kErrNoStart}); }
  for (const Case& c : cases) {
    EXPECT_NE(validate_move(c.m) & c.bit, 0u) << c.what;
    AxisModel ax;
    PulseConfig pc;
    ax.tick(true, false, c.m, pc);
    EXPECT_TRUE(ax.err()) << c.what;
    EXPECT_TRUE(ax.done()) << c.what;
    EXPECT_FALSE(ax.busy()) << c.what;
    for (int i = 0; i < 1000; ++i) {
      ax.tick(false, false, c.m, pc);
      EXPECT_FALSE(ax.step_level()) << c.what;
    }
  }
}

TEST(Axis, StartWhileBusyIsRefusedAndDoesNotDisturbTheMove) {
  AxisMove m;
  m.steps = 10;
  m.v_start = m.v_max = m.v_end = 1ull << 60;  // 1/16 step per tick
  m.dec_step = 10;
  AxisMove other = m;
  other.steps = 3;
  other.dir = false;
  AxisModel ax;
  PulseConfig pc;
  ax.tick(true, false, m, pc);
  ASSERT_TRUE(ax.busy());
  int steps = 0;
  for (int i = 0; i < 400; ++i) {
    ax.tick(i == 20, false, other, pc);
    if (i == 20) {
      EXPECT_TRUE(ax.err());
    }
    steps += ax.rose();
  }
  EXPECT_EQ(steps, 10);
  EXPECT_EQ(ax.position(), 10);
}

TEST(Axis, AbortStopsNewPulsesAndLetsTheCurrentOneFinish) {
  AxisMove m;
  m.steps = 100;
  m.v_start = m.v_max = m.v_end = 1ull << 61;  // 1/8 step per tick
  m.dec_step = 100;
  PulseConfig pc{3, 2, 0, 0, false, false};
  AxisModel ax;
  ax.tick(true, false, m, pc);
  while (!ax.rose()) ax.tick(false, false, m, pc);
  int high = 1;                 // the cycle after the rising edge
  ax.tick(false, true, m, pc);  // abort one cycle after a rising edge
  EXPECT_FALSE(ax.busy());
  EXPECT_TRUE(ax.done());
  EXPECT_TRUE(ax.step_level());  // the pulse is not cut short into a runt
  high += ax.step_level();
  while (ax.step_level()) {
    ax.tick(false, false, m, pc);
    high += ax.step_level();
  }
  EXPECT_EQ(high, 3);  // the programmed high time
  for (int k = 0; k < 200; ++k) {
    ax.tick(false, false, m, pc);
    EXPECT_FALSE(ax.rose());
  }
  EXPECT_EQ(ax.position(), 1);
}

TEST(Axis, PositionCounterWrapsAtItsWidth) {
  Widths w;
  w.pos = 4;  // tiny counter: -8..7
  AxisModel ax(w);
  AxisMove m;
  m.steps = 9;
  m.v_start = m.v_max = m.v_end = 1ull << 62;
  m.dec_step = 9;
  PulseConfig pc;
  ax.tick(true, false, m, pc);
  for (int i = 0; i < 200; ++i) ax.tick(false, false, m, pc);
  EXPECT_EQ(ax.position(), -7);  // 9 wraps to -7 in 4 bits
}
