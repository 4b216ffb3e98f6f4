// SPDX-License-Identifier: Apache-2.0
// Co-simulation: the Verilated RTL and the golden model run the same vectors and every output
// of every axis is compared after every clock edge.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "rtl_core.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {
const char* phase_name(Phase p) {
  static const char* n[] = {"idle", "accel", "cruise", "decel"};
  return n[static_cast<int>(p)];
}
// $name if set (the sanitizer build uses smaller counts, mk/abuse.mk), else the default.
uint64_t env_count(const char* name, uint64_t dflt) {
  const char* s = std::getenv(name);
  return s && *s ? std::strtoull(s, nullptr, 0) : dflt;
}
std::string show(const AxisOutputs& o) {
  std::ostringstream s;
  s << "step=" << o.step << " dir=" << o.dir << " busy=" << o.busy << " done=" << o.done
    << " err=" << o.err << " phase=" << phase_name(o.phase) << " pos=" << o.pos;
  return s.str();
}

// Ticks the model and the RTL together and compares all outputs after each edge.
class Lockstep : public CoreSim {
 public:
  explicit Lockstep(std::string name) : name_(std::move(name)) {}
  void reset() override {
    model_.reset();
    rtl_.reset();
    cycle_ = 0;
  }
  void tick(const CoreInputs& in) override {
    model_.tick(in);
    rtl_.tick(in);
    for (unsigned a = 0; a < kNumAxes; ++a) {
      const AxisOutputs m = model_.out(a), r = rtl_.out(a);
      if (m != r) {
        if (mismatches_ < 10)
          ADD_FAILURE() << name_ << ": cycle " << cycle_ << " axis " << a << "\n  model " << show(m)
                        << "\n  rtl   " << show(r);
        ++mismatches_;
      }
    }
    ++cycle_;
  }
  AxisOutputs out(unsigned a) const override { return model_.out(a); }
  uint64_t mismatches() const { return mismatches_; }
  uint64_t cycles() const { return cycle_; }

 private:
  std::string name_;
  CoreModel model_;
  RtlCore rtl_;
  uint64_t cycle_ = 0;
  uint64_t mismatches_ = 0;
};
}  // namespace

TEST(Cosim, DirectedJobs) {
  for (const NamedJob& nj : directed_jobs()) {
    Lockstep ls(nj.name);
    RunResult r = run_job(ls, nj.job, [](const StepEvent&) {});
    EXPECT_FALSE(r.timed_out) << nj.name;
    EXPECT_EQ(ls.mismatches(), 0u) << nj.name;
  }
}

// At least 2,000 planned and raw moves over all six axes, chained through the job runner
// ($COSIM_MOVES moves instead if set).
TEST(Cosim, RandomJobs2000Moves) {
  const uint64_t seed = test_seed();
  std::printf("SEED=%llu (rerun with SEED=%llu)\n", static_cast<unsigned long long>(seed),
              static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  unsigned moves = 0;
  uint64_t cycles = 0;
  const uint64_t target = env_count("COSIM_MOVES", 2004);
  for (int j = 0; moves < target; ++j) {
    NamedJob nj = random_job(rng, 28, true);
    moves += 28 * kNumAxes;
    Lockstep ls("random job " + std::to_string(j) + " seed " + std::to_string(seed));
    RunResult r = run_job(ls, nj.job, [](const StepEvent&) {});
    EXPECT_FALSE(r.timed_out);
    ASSERT_EQ(ls.mismatches(), 0u) << "SEED=" << seed;
    cycles += ls.cycles();
  }
  std::printf("%u moves, %llu cycles, 0 mismatches\n", moves, static_cast<unsigned long long>(cycles));
}

// Random strobes, aborts, controlled stops, jog moves, starts on busy axes, live pulse-timing
// and polarity changes
// (1,500,000 cycles, or $COSIM_CYCLES).
TEST(Cosim, RandomStimulusWithAbortsAndBusyStarts) {
  const uint64_t seed = test_seed() + 1;
  std::printf("SEED=%llu (this test uses SEED+1)\n", static_cast<unsigned long long>(seed - 1));
  std::mt19937_64 rng(seed);
  Lockstep ls("random stimulus seed " + std::to_string(seed - 1));
  ls.reset();
  CoreInputs in;
  for (unsigned a = 0; a < kNumAxes; ++a) in.pulse[a] = random_pulse(rng);
  unsigned starts = 0, stops = 0;
  const uint64_t cycles = env_count("COSIM_CYCLES", 1500000);
  for (uint64_t cyc = 0; cyc < cycles; ++cyc) {
    in.start_mask = 0;
    in.abort_mask = 0;
    in.stop_mask = 0;
    for (unsigned a = 0; a < kNumAxes; ++a) {
      const AxisOutputs o = ls.out(a);
      const unsigned r = static_cast<unsigned>(rng() % 100000);
      if ((!o.busy && r < 1500) || r < 3) {  // mostly when idle, sometimes while busy
        in.start_mask |= 1u << a;
        in.move[a] = (rng() % 4) ? random_raw_move(rng) : encode(random_ramp(rng)).regs;
        in.move[a].jog = rng() % 6 == 0;  // jog: runs until a stop or an abort
        ++starts;
      }
      if (r >= 99990) in.abort_mask |= 1u << a;
      if (r >= 99980 && r < 99985) in.pulse[a] = random_pulse(rng);
      if (r >= 99940 && r < 99980) ++stops, in.stop_mask |= 1u << a;
    }
    if (rng() % 1000 == 0) in.start_mask |= (1u << kNumAxes) - 1;  // all axes, one strobe
    ls.tick(in);
    if (ls.mismatches() != 0) break;
  }
  EXPECT_EQ(ls.mismatches(), 0u) << "SEED=" << seed - 1;
  EXPECT_GT(starts, 2000u * cycles / 1500000);
  std::printf("%u start strobes, %u stop strobes over %llu cycles\n", starts, stops,
              static_cast<unsigned long long>(ls.cycles()));
}
