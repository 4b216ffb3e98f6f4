// SPDX-License-Identifier: Apache-2.0
// Accuracy of the core against the continuous profile its registers describe (core issue):
// every step within 2 clock cycles plus the time the ideal motion needs for 0.001 step.
// The ideal instants come from IdealProfile's closed form, independent of the add-only loop.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
struct Worst {
  real ratio = 0;  // worst |error| / allowance
  real err = 0;    // worst |error| in cycles
  std::string where;
};

// Runs one encoded move alone on axis 0 with the fastest pulse timing (so the pulse stage
// never delays a step) and checks every step.
void check_move(const EncodedMove& e, const std::string& name, Worst& w) {
  Job j;
  j.axes[0].moves.push_back(e.regs);
  CoreModel m;
  RunOptions o;
  o.event_mode = true;
  uint32_t n = 0;
  run_job(m, j, [&](const StepEvent& ev) {
    ++n;
    const real ideal = ideal_rise_cycle(e.ideal, ev.step);
    const real err = std::fabs(static_cast<real>(ev.cycle) - ideal);
    const real allow = allowance_cycles(e.ideal, ev.step);
    if (err > w.err) w.err = err;
    if (err / allow > w.ratio) {
      w.ratio = err / allow;
      w.where = name + " step " + std::to_string(ev.step);
    }
    EXPECT_LE(err, allow) << name << " step " << ev.step << " cycle " << ev.cycle << " ideal "
                          << static_cast<double>(ideal);
  }, o);
  EXPECT_EQ(n, e.regs.steps) << name;
}
}  // namespace

TEST(Accuracy, DirectedRampsLandWithinTheAllowance) {
  Worst w;
  for (const NamedJob& nj : directed_jobs())
    for (unsigned a = 0; a < kNumAxes; ++a)
      for (size_t k = 0; k < nj.ideal[a].size(); ++k) {
        if (nj.ideal[a][k].steps == 0) continue;
        EncodedMove e{nj.job.axes[a].moves[k], nj.ideal[a][k]};
        check_move(e, nj.name, w);
      }
  std::printf("directed: worst error %.3f cycles, worst error/allowance %.3f at %s\n",
              static_cast<double>(w.err), static_cast<double>(w.ratio), w.where.c_str());
}

// The ends of the ranges the core issue names: speeds 1..5e6 steps/s, accelerations
// 10..1e8 steps/s^2, at 100 MHz.
TEST(Accuracy, RangeExtremesAt100MHz) {
  Worst w;
  const Ramp cases[] = {
      {3, true, 1, 1, 1, 10, 10},                    // 1 step/s constant
      {2000, true, 0, 100, 0, 10, 10},               // 10 steps/s^2, trapezoid over 30 s
      {400, false, 1, 5e6, 1, 10, 10},               // slowest accel, triangular from 1 step/s
      {500000, true, 0, 5e6, 0, 1e8, 1e8},           // fastest speed at the largest accel
      {200000, true, 5e4, 5e6, 0, 1e8, 2.5e7},       // decel a quarter of the accel
      {100000, true, 0, 5e6, 5e4, 2.5e7, 1e8},       // decel four times the accel
      {1, true, 0, 5e6, 0, 1e8, 1e8},                // one step from rest
      {2, true, 0, 5e6, 0, 1e8, 1e8},
  };
  int i = 0;
  for (const Ramp& r : cases) check_move(encode(r), "extreme#" + std::to_string(i++), w);
  std::printf("extremes: worst error %.3f cycles, worst error/allowance %.3f at %s\n",
              static_cast<double>(w.err), static_cast<double>(w.ratio), w.where.c_str());
}

TEST(Accuracy, RandomRampsLandWithinTheAllowance) {
  const uint64_t seed = test_seed();
  std::printf("SEED=%llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  Worst w;
  for (int i = 0; i < 600; ++i) {
    Ramp r = random_ramp(rng);
    check_move(encode(r), "random#" + std::to_string(i), w);
  }
  std::printf("random: worst error %.3f cycles, worst error/allowance %.3f at %s\n",
              static_cast<double>(w.err), static_cast<double>(w.ratio), w.where.c_str());
}
