// SPDX-License-Identifier: Apache-2.0
// The STEP/DIR output stage (PulseStage, rtl/hexstep_pulse.v) driven directly, and on the pins
// of the whole model: pulse shape, DIR setup/hold, the accept rule, abort, polarity, the
// position counter's wrap-around. Expectations come from docs/ARCHITECTURE.md ("Output stage
// and pulse timing") and from the independent monitor of tests/common/monitor.hpp.
#include <gtest/gtest.h>

#include <vector>

#include "hexstep/bus.hpp"
#include "monitor.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
// Edges of a stage with requests at given cycles; records the first cycle with STEP high of
// every pulse, and the monitor's verdict.
struct Drive {
  PulseStage ps;
  PinMonitor mon;
  uint64_t c = 0;  // the next edge ends cycle c
  std::vector<uint64_t> rises;
  explicit Drive(const Widths& w = Widths{}) : ps(w) {}
  void edge(const PulseConfig& pc, uint64_t due = 0, int tgt = -1, bool abort = false) {
    ps.edge(c, abort, pc, due, tgt);
    ++c;
    const bool was = mon.lvl;
    mon.sample(static_cast<int64_t>(c), ps.step_level(), ps.dir_level(), pc);
    if (!was && ps.step_level()) rises.push_back(c);
  }
  void run(const PulseConfig& pc, uint64_t n) {
    for (uint64_t i = 0; i < n; ++i) edge(pc);
  }
};
}  // namespace

// A request due on cycle d rises on d + 2 when the stage is free; the pulse lasts exactly
// step_high cycles (0 acts as 1).
TEST(Pulse, RisesTwoCyclesAfterDueAndLastsStepHigh) {
  for (uint32_t high : {0u, 1u, 2u, 7u, 4095u}) {
    PulseConfig pc;
    pc.step_high = high;
    Drive d;
    d.run(pc, 10);
    d.edge(pc, 40);  // request committed at the edge ending cycle 10, due on cycle 40
    d.run(pc, 100 + high);
    ASSERT_EQ(d.rises.size(), 1u) << high;
    EXPECT_EQ(d.rises[0], 42u) << high;
    EXPECT_TRUE(d.mon.errors.empty()) << d.mon.errors[0];
    EXPECT_FALSE(d.ps.step_level());
    EXPECT_EQ(d.ps.position(), 1);
  }
}

// Requests faster than the pulse timing: rises step_high + step_low apart, none lost, the
// owed counter holds them; the stage accepts a step while fewer than three wait.
TEST(Pulse, BackToBackStepsRespectHighAndLowAndAreNeverLost) {
  PulseConfig pc;
  pc.step_high = 5;
  pc.step_low = 9;
  Drive d;
  d.run(pc, 4);
  EXPECT_TRUE(d.ps.accepts());
  d.edge(pc, 20);
  d.edge(pc, 20);
  EXPECT_TRUE(d.ps.accepts()) << "two steps wait";
  d.edge(pc, 20);  // three requests due on the same cycle
  EXPECT_FALSE(d.ps.accepts()) << "three steps wait";
  d.run(pc, 14);   // the edges up to the one that ends cycle 20: all due, now owed
  EXPECT_EQ(d.ps.requests(), 0u);
  EXPECT_EQ(d.ps.owed(), 3u);
  EXPECT_FALSE(d.ps.accepts());
  d.edge(pc, 30);  // the first rises at this edge; a fourth request
  d.run(pc, 200);
  ASSERT_EQ(d.rises.size(), 4u);
  EXPECT_EQ(d.rises[0], 22u);
  EXPECT_EQ(d.rises[1], 22u + 14);
  EXPECT_EQ(d.rises[2], 22u + 28);
  EXPECT_EQ(d.rises[3], 22u + 42);
  EXPECT_TRUE(d.mon.errors.empty()) << d.mon.errors[0];
  EXPECT_EQ(d.ps.position(), 4);
  EXPECT_FALSE(d.ps.pending());
}

// The accept rule, from the outside: a step is taken whenever the stage accepts; the stage
// accepts exactly while fewer than three of the steps taken have not risen yet, and every step
// taken rises.
TEST(Pulse, AcceptRule) {
  std::mt19937_64 rng(5);
  for (uint32_t high : {1u, 3u, 40u}) {
    PulseConfig pc;
    pc.step_high = high;
    pc.step_low = 1 + static_cast<uint32_t>(rng() % 7);
    Drive d;
    uint64_t taken = 0;
    unsigned refusals = 0;
    for (int i = 0; i < 5000; ++i) {
      const uint64_t waiting = taken - d.rises.size();
      ASSERT_EQ(d.ps.accepts(), waiting < 3) << "high " << high << " edge " << i << ": " << waiting << " waiting";
      if (d.ps.accepts() && rng() % 3 != 0) {
        d.edge(pc, d.c + 1 + rng() % 60);
        ++taken;
      } else {
        refusals += !d.ps.accepts();
        d.edge(pc);
      }
    }
    d.run(pc, 1000);
    EXPECT_EQ(d.rises.size(), taken) << "high " << high;
    EXPECT_TRUE(d.mon.errors.empty()) << d.mon.errors[0];
    if (high == 40) {
      EXPECT_GT(refusals, 100u);
    }
  }
}

// DIR changes to a new target only when the hold interval after the last rise is over, and the
// next rise waits for the setup interval after the change.
TEST(Pulse, DirSetupAndHold) {
  for (uint32_t setup : {0u, 1u, 13u}) {
    for (uint32_t hold : {0u, 1u, 17u}) {
      PulseConfig pc;
      pc.dir_setup = setup;
      pc.dir_hold = hold;
      Drive d;
      d.run(pc, 3);
      d.edge(pc, 10, 1);  // positive: no change
      d.run(pc, 8);       // rises on 12
      ASSERT_EQ(d.rises.size(), 1u);
      d.edge(pc, 13, 0);  // a negative step owed right after the first: the DIR change waits
      d.run(pc, 300);
      ASSERT_EQ(d.rises.size(), 2u);
      EXPECT_TRUE(d.mon.errors.empty()) << "setup " << setup << " hold " << hold << ": " << d.mon.errors[0];
      EXPECT_EQ(d.mon.last_dir - 12, std::max<int64_t>(hold, 2)) << "setup " << setup << " hold " << hold;
      EXPECT_EQ(int64_t(d.rises[1]) - d.mon.last_dir, std::max<int64_t>(setup, 1)) << setup << " " << hold;
      EXPECT_EQ(d.ps.position(), 0);
      EXPECT_FALSE(d.ps.dir_level());
    }
  }
}

// ABORT clears the requests and owed steps and suppresses a rise in its cycle; a pulse already
// high completes its high time.
TEST(Pulse, AbortDropsStepsAndLetsTheHighPulseFinish) {
  PulseConfig pc;
  pc.step_high = 6;
  Drive d;
  d.edge(pc, 4);
  d.edge(pc, 5);
  d.run(pc, 5);  // first rises on 6
  ASSERT_EQ(d.rises.size(), 1u);
  ASSERT_TRUE(d.ps.step_level());
  d.edge(pc, 0, -1, true);
  EXPECT_FALSE(d.ps.pending());
  d.run(pc, 100);
  EXPECT_EQ(d.rises.size(), 1u);
  EXPECT_TRUE(d.mon.errors.empty()) << d.mon.errors[0];  // a whole 6-cycle pulse
  EXPECT_EQ(d.ps.position(), 1);
  // An abort on the edge a rise would happen at: no rise.
  Drive e;
  e.edge(pc, 3);
  e.run(pc, 3);  // due on 3: owed after the edge ending 3; the rise would be at the edge ending 4
  e.edge(pc, 0, -1, true);
  e.run(pc, 50);
  EXPECT_TRUE(e.rises.empty());
  EXPECT_EQ(e.ps.position(), 0);
}

// A configuration change applies from the next interval that starts after it.
TEST(Pulse, ConfigurationAppliesFromTheNextInterval) {
  PulseConfig a;
  a.step_high = 10;
  PulseConfig b;
  b.step_high = 3;
  Drive d;
  d.edge(a, 2);
  d.run(a, 4);  // rises on 4 with step_high 10
  ASSERT_EQ(d.rises.size(), 1u);
  d.edge(b, 30);
  d.run(b, 60);
  ASSERT_EQ(d.rises.size(), 2u);
  EXPECT_TRUE(d.mon.errors.empty()) << d.mon.errors[0];  // 10 cycles, then 3
}

TEST(Pulse, PositionCounterWrapsAtItsWidth) {
  Widths w;
  w.pos = 4;  // -8..7
  Drive d(w);
  PulseConfig pc;
  for (int i = 0; i < 9; ++i) {
    d.edge(pc, d.c + 2);
    d.run(pc, 8);
  }
  EXPECT_EQ(d.rises.size(), 9u);
  EXPECT_EQ(d.ps.position(), -7);  // 9 wraps to -7 in 4 bits
  for (int i = 0; i < 10; ++i) {
    d.edge(pc, d.c + 2, 0);
    d.run(pc, 8);
  }
  EXPECT_EQ(d.ps.position(), -1);  // -7 - 10 = -17 = -1 (mod 16)
}

// On the model's pins, every directed job and random jobs with random pulse timing: the
// monitor sees every pulse whole and the DIR windows kept, and every accepted move's steps.
TEST(Pulse, ModelPinsKeepTheTimingOnEveryJob) {
  std::vector<NamedJob> jobs = directed_jobs();
  std::mt19937_64 rng(7);
  for (int i = 0; i < 6; ++i) jobs.push_back(random_job(rng, 3, false));
  for (const NamedJob& nj : jobs) {
    ModelSim sim;
    Monitored mon(sim, sim.model());
    const RunResult r = run_job(mon, nj.job, [](const StepEvent&) {});
    EXPECT_FALSE(r.timed_out) << nj.name;
    EXPECT_EQ(mon.errors(), "") << nj.name;
    for (unsigned a = 0; a < kNumAxes; ++a) {
      uint64_t want = 0;
      for (const AxisMove& m : nj.job.axes[a].moves) {
        const SlotMove s = make_slot(m);
        if (!s.bad && !s.empty) want += m.steps;
      }
      EXPECT_EQ(mon.monitor(a).rises, want) << nj.name << " axis " << a;
    }
  }
}

// POLARITY inverts the pins at once, with no motion: after reset STEP is low and DIR high
// (positive); with step_inv and dir_inv set, STEP reads high and DIR low, on that axis only.
TEST(Pulse, PolarityInvertsThePinsAtOnce) {
  ModelSim sim;
  Bus bus(sim);
  bus.reset();
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_FALSE(sim.step(k)) << k;
    EXPECT_TRUE(sim.dir(k)) << k;
  }
  bus.write(ax_reg(2, regs::axis::POLARITY), regs::axis::POLARITY_STEP_INV_MASK);
  bus.write(ax_reg(4, regs::axis::POLARITY), regs::axis::POLARITY_DIR_INV_MASK);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_EQ(sim.step(k), k == 2) << k;
    EXPECT_EQ(sim.dir(k), k != 4) << k;
  }
  // A move on axis 2 pulses STEP low (active-low) exactly its steps.
  push_move(bus, 2, cruise(7, 1ull << 62, true));
  bus.write(regs::START, 1u << 2);
  unsigned falls = 0;
  bool prev = sim.step(2);
  for (int i = 0; i < 2000; ++i) {
    bus.idle(1);
    falls += prev && !sim.step(2);
    prev = sim.step(2);
  }
  EXPECT_EQ(falls, 7u);
  EXPECT_TRUE(sim.step(2));
}
