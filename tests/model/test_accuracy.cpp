// SPDX-License-Identifier: Apache-2.0
// Accuracy of the core against the continuous profile its registers describe: every step within
// allowance_cycles() (2 clock cycles plus the time the ideal motion needs for 0.001 step) of
// ideal_rise_cycle() (docs/ARCHITECTURE.md, "Accuracy"). The ideal instants come from
// IdealProfile's closed form, independent of the add-only loop; the core's rises from the frame
// runner (tests/common/axis_run, equal to the cycle-exact TopModel by test_event_mode.cpp),
// whose time zero is the frame of the move's first tick. Moves from encode_ramp at 12, 48 and
// 100 MHz, speeds 1 .. 3e6 steps/s and accelerations 10 .. 1e8 steps/s^2 where the registers
// can hold them (below one step per tick, below the ACC_W range).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "axis_run.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
struct Worst {
  real ratio = 0;  // worst |error| / allowance
  real err = 0;    // worst |error| in cycles
  std::string where;
  uint64_t steps = 0, moves = 0, stalls = 0;
  void print(const char* what) const {
    std::printf("%s: %llu moves, %llu steps, worst error %.3f cycles, worst error/allowance %.3f at %s%s\n", what,
                static_cast<unsigned long long>(moves), static_cast<unsigned long long>(steps),
                static_cast<double>(err), static_cast<double>(ratio), where.c_str(),
                stalls ? (", " + std::to_string(stalls) + " ticks paused by the output stage").c_str() : "");
  }
};

// Runs one encoded move alone (the fastest pulse timing, so the output stage never delays a step
// for its pulse shape) and checks every step.
void check_move(const EncodedMove& e, const std::string& name, Worst& w) {
  const AxisRun r = run_axis(e.regs);
  ASSERT_FALSE(r.refused) << name;
  ASSERT_FALSE(r.timed_out) << name;
  EXPECT_EQ(r.rises.size(), e.regs.steps) << name;
  unsigned bad = 0;
  for (const AxisRise& x : r.rises) {
    const real ideal = ideal_rise_cycle(e.ideal, x.step);
    const real err = std::fabs(static_cast<real>(x.cycle) - ideal);
    const real allow = allowance_cycles(e.ideal, x.step);
    if (err > w.err) w.err = err;
    if (err / allow > w.ratio) {
      w.ratio = err / allow;
      w.where = name + " step " + std::to_string(x.step);
    }
    if (err > allow && bad++ < 3)
      ADD_FAILURE() << name << " step " << x.step << ": cycle " << x.cycle << ", ideal "
                    << static_cast<double>(ideal) << ", error " << static_cast<double>(err) << " > allowance "
                    << static_cast<double>(allow);
  }
  if (bad > 3) ADD_FAILURE() << name << ": " << bad << " of " << r.rises.size() << " steps outside the allowance";
  w.steps += r.rises.size();
  w.stalls += r.stalled;
  ++w.moves;
}

// The largest speed and acceleration of the ranges that the registers hold at clock f.
real vmax_at(real f) { return std::min<real>(3e6, 0.96L * tick_rate(f)); }
real amax_at(real f) { return std::min<real>(1e8, 0.9L * max_accel(f)); }

const real kClocks[] = {12e6, 48e6, 100e6};
}  // namespace

TEST(Accuracy, DirectedRampsLandWithinTheAllowance) {
  Worst w;
  for (const NamedJob& nj : directed_jobs())
    for (unsigned a = 0; a < kNumAxes; ++a)
      for (size_t k = 0; k < nj.ideal[a].size(); ++k) {
        if (nj.ideal[a][k].steps == 0) continue;
        check_move(EncodedMove{nj.job.axes[a].moves[k], nj.ideal[a][k]}, nj.name, w);
      }
  w.print("directed");
}

// The ends of the ranges at each clock.
TEST(Accuracy, RangeExtremes) {
  for (real f : kClocks) {
    Worst w;
    const real vm = vmax_at(f), am = amax_at(f);
    const Ramp cases[] = {
        {3, true, 1, 1, 1, 10, 10},                      // 1 step/s, constant
        {2000, true, 0, 100, 0, 10, 10},                 // 10 steps/s^2: a trapezoid over 30 s
        {400, false, 1, vm, 1, 10, 10},                  // the slowest ramps, triangular, from 1 step/s
        {120000, true, 0, vm, 0, am, am},                // the fastest speed at the largest acceleration
        {60000, true, vm / 50, vm, 0, am, am / 4},       // deceleration a quarter of the acceleration
        {60000, true, 0, vm, vm / 50, am / 4, am},       // deceleration four times the acceleration
        {20000, false, vm / 2, vm, vm / 3, am, am},      // from and to high speeds
        {5000, true, vm * 0.9L, vm, vm * 0.9L, am, am},  // near one step per tick throughout
        {1, true, 0, vm, 0, am, am},                     // one step from rest
        {2, true, 0, vm, 0, am, am},
        {3, true, 0, 1e6, 0, 10, 10},                    // three steps at 10 steps/s^2
    };
    int i = 0;
    for (const Ramp& r : cases) {
      const std::string name = "extreme#" + std::to_string(i++) + " at " + std::to_string(int(f / 1e6)) + " MHz";
      check_move(encode(r, f), name, w);
    }
    w.print(("extremes at " + std::to_string(int(f / 1e6)) + " MHz").c_str());
  }
}

// Random ramps over the whole ranges (log-uniform speeds and accelerations, 1 .. 20,000 steps,
// zero and non-zero ends, acc != dec) at each clock.
TEST(Accuracy, RandomRampsLandWithinTheAllowance) {
  const uint64_t seed = test_seed();
  std::printf("SEED=%llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  auto lu = [&](real lo, real hi) {
    std::uniform_real_distribution<double> u(std::log(static_cast<double>(lo)), std::log(static_cast<double>(hi)));
    return static_cast<real>(std::exp(u(rng)));
  };
  const unsigned n = static_cast<unsigned>(env_count("ACCURACY_MOVES", 300));
  for (real f : kClocks) {
    Worst w;
    const real vm = vmax_at(f), am = amax_at(f);
    for (unsigned i = 0; i < n; ++i) {
      Ramp r;
      r.steps = static_cast<uint32_t>(lu(1, 20000));
      r.dir = rng() & 1;
      r.v_max = lu(1, vm);
      r.accel = lu(10, am);
      r.decel = std::min(am, r.accel * lu(0.25L, 4));
      r.v_start = rng() % 3 == 0 ? 0 : r.v_max * lu(0.01L, 1);
      r.v_end = rng() % 3 == 0 ? 0 : r.v_max * lu(0.01L, 1);
      const EncodedMove e = encode(r, f);
      if (e.ideal.duration() > 600) {  // hours of motion at a few steps/s: drawn again
        --i;
        continue;
      }
      check_move(e, "SEED=" + std::to_string(seed) + " random#" + std::to_string(i) + " at " +
                        std::to_string(int(f / 1e6)) + " MHz",
                 w);
    }
    w.print(("random at " + std::to_string(int(f / 1e6)) + " MHz").c_str());
  }
}
