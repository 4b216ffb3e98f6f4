// SPDX-License-Identifier: Apache-2.0
// Event mode (skipping quiet cycles with closed-form jumps) must give exactly the cycle-mode
// result: the same STEP edges at the same cycles and the same final state.
#include <gtest/gtest.h>

#include <cstdio>

#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
void same(const Job& j, const std::string& name) {
  std::vector<StepEvent> a, b;
  CoreModel m1, m2;
  RunOptions cyc, evm;
  evm.event_mode = true;
  RunResult r1 = run_job(m1, j, [&](const StepEvent& e) { a.push_back(e); }, cyc);
  RunResult r2 = run_job(m2, j, [&](const StepEvent& e) { b.push_back(e); }, evm);
  ASSERT_EQ(a.size(), b.size()) << name;
  for (size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(a[i] == b[i]) << name << " event " << i;
  EXPECT_EQ(r1.cycles, r2.cycles) << name;
  EXPECT_EQ(r1.position, r2.position) << name;
  EXPECT_EQ(r1.refused, r2.refused) << name;
}
}  // namespace

TEST(EventMode, DirectedJobsIdenticalToCycleMode) {
  for (const NamedJob& nj : directed_jobs()) same(nj.job, nj.name);
}

TEST(EventMode, RandomJobsIdenticalToCycleMode) {
  const uint64_t seed = test_seed();
  std::printf("SEED=%llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 25; ++i) same(random_job(rng, 4, true).job, "random#" + std::to_string(i));
}

TEST(EventMode, SlowAcceleratingMoveIdentical) {
  // 10 steps/s^2 would take hours in cycle mode; at 2e4 steps/s^2 and 60 steps it is ~1.1e7 cycles.
  Job j;
  j.axes[0].moves.push_back(encode({60, true, 0, 1e4, 0, 2e4, 3e4}).regs);
  j.axes[3].moves.push_back(encode({25, false, 50, 1e4, 10, 1e4, 1e4}).regs);
  same(j, "slow");
}
