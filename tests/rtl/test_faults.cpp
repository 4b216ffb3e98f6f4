// SPDX-License-Identifier: Apache-2.0
// Fault and bad-input tests, co-simulated against the golden model (docs/TESTING.md):
//   core (rtl/hexstep_core.v == CoreModel, every output of every axis after every edge):
//     reset and ABORT in every phase of a move, then a new move; direction reversal between
//     chained moves with DIR setup/hold; every refusal rule of docs/ARCHITECTURE.md; position
//     counter wrap-around (a POS_W = 8 build of the same RTL against CoreModel with pos = 8);
//   bus (rtl/hexstep_top.v through sim/wb_bfm == the register-block model WbModel at every
//     edge, tests/common/wb_ref.hpp): E-STOP during chained moves, queue overrun during
//     motion, bus writes to every register during motion.
// In every test the other axes run moves of their own; besides RTL == model, an independent
// pin monitor checks the documented pulse timing (exact high time, minimum low time, DIR setup
// and hold) and each axis's step count and position are checked against the moves it ran.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Vhexstep_core_pos8.h"
#include "hexstep/core.hpp"
#include "hexstep/job.hpp"
#include "hexstep_regs.hpp"
#include "lockstep.hpp"
#include "vectors.hpp"
#include "verilated.h"
#include "wb_bfm.hpp"
#include "wb_ref.hpp"

using namespace hexstep;
using namespace hexstep::test;
namespace R = hexstep::regs;

namespace {

// ---------------------------------------------------------------------------------------------
// Moves. Speeds in 2^-64 step per tick.

// Accelerate from 1/4096 to 1/256 step per tick at 2^-21 step/tick^2 (acc and dec must fit
// ACC_W = 44 bits), cruise, decelerate to 1/4096: about 16 steps per ramp, so moves of more than
// 32 steps have all three phases, each thousands of cycles long.
AxisMove trapezoid(uint32_t steps, bool dir = true) {
  AxisMove m;
  m.steps = steps;
  m.dir = dir;
  m.v_start = 1ull << 52;
  m.v_max = 1ull << 56;
  m.acc = 1ull << 43;
  m.dec = 1ull << 43;
  m.v_end = 1ull << 52;
  m.v_dec = (1ull << 56) - (1ull << 43);
  m.acc_steps = steps / 2;
  m.dec_step = steps > 32 ? steps - 16 : steps / 2;
  m.dec_frac = 0x80000000u;
  return m;
}
int64_t signed_steps(const AxisMove& m) { return m.dir ? int64_t(m.steps) : -int64_t(m.steps); }

TEST(Faults, MovesUsedHereFitTheRegistersAndAreValid) {
  const Widths w;
  for (const AxisMove& m : {trapezoid(120), trapezoid(40), trapezoid(1), cruise(10, 1ull << 63)}) {
    EXPECT_EQ(validate_move(m), 0u);
    EXPECT_EQ(m.acc & ~w.acc_mask(), 0u);
    EXPECT_EQ(m.dec & ~w.acc_mask(), 0u);
  }
}

// ---------------------------------------------------------------------------------------------
// Pin monitor: the documented output timing, checked on the pins (polarity removed) without
// the model. Records the first violations as text.
struct PinMonitor {
  int64_t last_rise = -1000000, last_fall = -1000000, last_dir = -1000000;
  bool lvl = false, dir = true, have = false;
  uint64_t rises = 0;
  std::vector<std::string> errors;

  void clear() { *this = PinMonitor{}; }
  void sample(int64_t cyc, const AxisOutputs& o, const PulseConfig& p) {
    const bool l = o.step != p.step_invert, d = o.dir != p.dir_invert;
    const int64_t H = std::max<uint32_t>(p.step_high, 1), L = std::max<uint32_t>(p.step_low, 1);
    if (have && d != dir) {
      if (cyc - last_rise < int64_t(p.dir_hold)) add(cyc, "DIR changed inside the hold window");
      last_dir = cyc;
    }
    if (l && !(have && lvl)) {
      if (cyc - last_fall < L) add(cyc, "STEP low time below step_low");
      if (cyc - last_dir < int64_t(p.dir_setup)) add(cyc, "STEP rose inside the DIR setup window");
      last_rise = cyc;
      ++rises;
    }
    if (!l && have && lvl && cyc - last_rise != H) add(cyc, "STEP high time differs from step_high");
    if (!l && have && lvl) last_fall = cyc;
    lvl = l;
    dir = d;
    have = true;
  }
  void add(int64_t cyc, const char* what) {
    if (errors.size() < 5) errors.push_back("cycle " + std::to_string(cyc) + ": " + what);
  }
};

// ---------------------------------------------------------------------------------------------
// Core bench: LockstepCore (RTL == model after every edge) plus pin monitors, and background
// moves on every axis but the one under test: each background axis restarts with a new move
// on the cycle after its done pulse, and must end with exactly the steps it was given.
class CoreBench {
 public:
  explicit CoreBench(std::string name, unsigned axis_under_test, uint64_t seed = 1)
      : name_(std::move(name)), k_(axis_under_test), rng_(seed) {
    static const PulseConfig pcs[kNumAxes] = {{1, 1, 0, 0, false, false}, {3, 5, 7, 2, true, false},
                                              {2, 2, 40, 40, false, true}, {7, 3, 0, 9, true, true},
                                              {1, 4, 3, 0, false, false},  {5, 5, 11, 13, false, true}};
    for (unsigned a = 0; a < kNumAxes; ++a) in.pulse[a] = pcs[a];
    ls.reset();  // the monitors start with the first edge (the pins show the polarity from then)
  }

  LockstepCore ls;
  CoreInputs in;

  unsigned axis() const { return k_; }
  AxisOutputs out(unsigned a) const { return ls.out(a); }
  const AxisModel& model(unsigned a) const { return ls.model().axis(a); }
  int64_t cycle() const { return static_cast<int64_t>(ls.cycles()); }
  const PinMonitor& monitor(unsigned a) const { return mon_[a]; }

  void start(unsigned a, const AxisMove& m) {
    in.move[a] = m;
    in.start_mask |= 1u << a;
  }
  void abort(unsigned a) { in.abort_mask |= 1u << a; }
  void stop(unsigned a) { in.stop_mask |= 1u << a; }
  // Background moves on every other axis from now on (each expected to finish exactly).
  void background(bool on) { bg_ = on; }

  void tick() {
    if (bg_)
      for (unsigned a = 0; a < kNumAxes; ++a)
        if (a != k_ && !((in.start_mask >> a) & 1u) && !out(a).busy && (!started_[a] || out(a).done)) {
          const AxisMove m = rng_() % 2 ? trapezoid(40 + rng_() % 60, rng_() & 1)
                                        : cruise(5 + rng_() % 30, (1ull << 60) >> (rng_() % 4), rng_() & 1);
          start(a, m);
          bg_expect_[a] += signed_steps(m);
          started_[a] = true;
        }
    ls.tick(in);
    in.start_mask = 0;
    in.abort_mask = 0;
    in.stop_mask = 0;
    for (unsigned a = 0; a < kNumAxes; ++a) mon_[a].sample(cycle(), ls.out(a), in.pulse[a]);
  }
  // Resets RTL and model together: all axes idle at position 0; the monitors start again.
  void reset() {
    ls.reset();
    ls.compare();
    for (unsigned a = 0; a < kNumAxes; ++a) {
      mon_[a].clear();
      mon_[a].sample(cycle(), ls.out(a), in.pulse[a]);
      bg_expect_[a] = 0;
      started_[a] = false;
    }
  }
  // Ticks until pred() holds after an edge; false if `limit` edges pass first.
  bool run_until(const std::function<bool()>& pred, uint64_t limit = 200000) {
    for (uint64_t i = 0; i < limit; ++i) {
      tick();
      if (pred()) return true;
    }
    return false;
  }
  // Stops the background, lets every axis finish, checks RTL == model, the pin timing and
  // each background axis's final position.
  void finish() {
    bg_ = false;
    const bool idle = run_until([this] {
      for (unsigned a = 0; a < kNumAxes; ++a)
        if (out(a).busy) return false;
      return true;
    });
    EXPECT_TRUE(idle) << name_ << ": an axis still busy after 200000 cycles";
    tick();
    EXPECT_EQ(ls.mismatches(), 0u) << name_ << ": RTL != model\n" << ls.report_text();
    for (unsigned a = 0; a < kNumAxes; ++a) {
      for (const std::string& e : mon_[a].errors) ADD_FAILURE() << name_ << ": axis " << a << " " << e;
      if (a != k_) EXPECT_EQ(out(a).pos, bg_expect_[a]) << name_ << ": background axis " << a << " disturbed";
    }
  }

 private:
  std::string name_;
  unsigned k_;
  std::mt19937_64 rng_;
  bool bg_ = false;
  std::array<PinMonitor, kNumAxes> mon_{};
  std::array<int64_t, kNumAxes> bg_expect_{};
  std::array<bool, kNumAxes> started_{};
};

// Points in a move at which a fault is injected.
enum class When { Accel, Cruise, Decel, StepHigh, DirSetupWait, DoneCycle, StartCycle };
const When kEveryPhase[] = {When::Accel,     When::Cruise,       When::Decel,     When::StepHigh,
                            When::DirSetupWait, When::DoneCycle, When::StartCycle};
const char* when_name(When w) {
  switch (w) {
    case When::Accel: return "accel";
    case When::Cruise: return "cruise";
    case When::Decel: return "decel";
    case When::StepHigh: return "step-high";
    case When::DirSetupWait: return "dir-setup-wait";
    case When::DoneCycle: return "done-cycle";
    case When::StartCycle: return "start-cycle";
  }
  return "?";
}

// Starts a move on the bench's axis and runs until `w` (the fault goes in with the next edge).
// The move reverses the direction so that it first waits for the DIR setup time.
void run_to(CoreBench& b, When w, unsigned extra) {
  const unsigned k = b.axis();
  const bool reverse = b.out(k).dir == b.in.pulse[k].dir_invert;  // DIR pin shows negative
  // A fast first step, so that it waits for the DIR setup time with the step owed.
  const AxisMove m = w == When::DirSetupWait ? cruise(120, 1ull << 63, reverse) : trapezoid(120, reverse);
  b.start(k, m);
  if (w == When::StartCycle) return;  // fault on the start edge itself
  const AxisModel& ax = b.model(k);
  std::function<bool()> pred;
  switch (w) {
    case When::Accel: pred = [&] { return ax.phase() == Phase::Accel; }; break;
    case When::Cruise: pred = [&] { return ax.phase() == Phase::Cruise; }; break;
    case When::Decel: pred = [&] { return ax.phase() == Phase::Decel; }; break;
    case When::StepHigh: pred = [&] { return ax.step_level() && ax.steps_done() > 10; }; break;
    case When::DirSetupWait: pred = [&] { return ax.owed() != 0 && ax.position() == 0 && !ax.step_level(); }; break;
    case When::DoneCycle: pred = [&] { return ax.done(); }; break;
    default: break;
  }
  ASSERT_TRUE(b.run_until(pred, 100000)) << "never reached " << when_name(w);
  if (w == When::DoneCycle || w == When::DirSetupWait) return;
  for (unsigned i = 0; i < extra && ax.busy(); ++i) b.tick();
}

// After a fault: a new move runs to exactly its steps.
void new_move_runs(CoreBench& b, const std::string& name) {
  const unsigned k = b.axis();
  ASSERT_TRUE(b.run_until([&] { return !b.out(k).busy; }, 100000)) << name;
  const int64_t p0 = b.out(k).pos;
  const uint64_t r0 = b.monitor(k).rises;
  const AxisMove m = trapezoid(77, b.out(k).pos < 0);
  b.start(k, m);
  b.tick();
  EXPECT_TRUE(b.out(k).busy) << name << ": new move not running";
  EXPECT_FALSE(b.out(k).err) << name << ": new move refused";
  ASSERT_TRUE(b.run_until([&] { return b.out(k).done; }, 100000)) << name << ": new move never ends";
  b.tick();
  EXPECT_EQ(b.out(k).pos - p0, signed_steps(m)) << name;
  EXPECT_EQ(b.monitor(k).rises - r0, m.steps) << name;
}

// The DIR setup of the reversing moves above needs a pulse configuration with one.
void use_slow_pulse(CoreBench& b) { b.in.pulse[b.axis()] = PulseConfig{4, 6, 25, 15, false, true}; }

// ---------------------------------------------------------------------------------------------
// Reset and ABORT in every phase.

TEST(Faults, ResetInEveryPhaseThenNewMove) {
  for (When w : kEveryPhase)
    for (unsigned extra : {0u, 3u}) {
      const unsigned k = static_cast<unsigned>(w) % kNumAxes;
      const std::string name = std::string("reset at ") + when_name(w) + " +" + std::to_string(extra);
      CoreBench b(name, k, 100 + static_cast<unsigned>(w));
      use_slow_pulse(b);
      b.background(true);
      for (int i = 0; i < 50; ++i) b.tick();
      run_to(b, w, extra);
      if (w == When::StartCycle) b.tick();  // the start edge, then reset
      b.background(false);
      b.reset();
      for (unsigned a = 0; a < kNumAxes; ++a) {
        const AxisOutputs o = b.out(a);
        EXPECT_FALSE(o.busy || o.done || o.err) << name << " axis " << a;
        EXPECT_EQ(o.phase, Phase::Idle) << name << " axis " << a;
        EXPECT_EQ(o.pos, 0) << name << " axis " << a;
        EXPECT_EQ(o.step, b.in.pulse[a].step_invert) << name << " axis " << a << ": STEP not at rest";
      }
      b.tick();
      for (unsigned a = 0; a < kNumAxes; ++a) EXPECT_FALSE(b.out(a).busy) << name << " axis " << a;
      b.background(true);
      new_move_runs(b, name);
      b.finish();
    }
}

TEST(Faults, AbortInEveryPhaseThenNewMove) {
  for (When w : kEveryPhase)
    for (unsigned extra : {0u, 1u, 5u}) {
      const unsigned k = (static_cast<unsigned>(w) + extra) % kNumAxes;
      const std::string name = std::string("abort at ") + when_name(w) + " +" + std::to_string(extra);
      CoreBench b(name, k, 200 + static_cast<unsigned>(w) * 7 + extra);
      use_slow_pulse(b);
      b.background(true);
      for (int i = 0; i < 30; ++i) b.tick();
      run_to(b, w, extra);
      const uint64_t rises = b.monitor(k).rises;
      b.abort(k);
      b.tick();
      // ABORT stops the generator and drops owed steps at once; a pulse already high finishes.
      EXPECT_FALSE(b.out(k).busy) << name << ": busy after the abort edge";
      for (int i = 0; i < 300; ++i) b.tick();
      EXPECT_EQ(b.monitor(k).rises, rises) << name << ": STEP rose after the abort edge";
      EXPECT_FALSE(b.model(k).step_level()) << name;  // a pulse high at the abort completed
      new_move_runs(b, name);
      b.finish();
    }
}

// ---------------------------------------------------------------------------------------------
// STOP (controlled deceleration) in every phase, then a new move: the axis comes to rest with
// every pulse whole (pin monitor), never beyond the move's N, its speed never rising while it
// stops, RTL == model every cycle, other axes undisturbed. Also STOP then ABORT in the same
// stop, ABORT and STOP on the same edge, and STOP on an idle axis. (STOP through the bus with
// the queue flush: tests/rtl/test_wb_model.cpp.)
TEST(Faults, StopInEveryPhaseThenNewMove) {
  for (When w : kEveryPhase)
    for (unsigned extra : {0u, 2u}) {
      const unsigned k = (static_cast<unsigned>(w) + 2 * extra) % kNumAxes;
      const std::string name = std::string("stop at ") + when_name(w) + " +" + std::to_string(extra);
      CoreBench b(name, k, 300 + static_cast<unsigned>(w) * 5 + extra);
      use_slow_pulse(b);
      b.background(true);
      for (int i = 0; i < 20; ++i) b.tick();
      run_to(b, w, extra);
      const int64_t p0 = b.out(k).pos;
      // On the start edge itself the axis is still idle: the STOP does nothing and the new move
      // runs all its 120 steps (docs/ARCHITECTURE.md: a STOP while not running does nothing).
      const bool at_start = w == When::StartCycle;
      b.stop(k);
      b.tick();
      uint64_t prev = b.model(k).speed();
      bool rising = false;
      const bool ended = b.run_until([&] {
        if (b.model(k).stopping()) {
          rising |= b.model(k).speed() > prev;
          prev = b.model(k).speed();
        }
        return !b.out(k).busy;
      }, 100000);
      EXPECT_TRUE(ended) << name << ": the stop never came to rest";
      EXPECT_FALSE(rising) << name << ": speed rose while stopping";
      if (at_start)
        EXPECT_EQ(std::llabs(b.out(k).pos - p0), 120) << name;
      else
        EXPECT_LT(std::llabs(b.out(k).pos - p0), 120) << name << ": a stop ends before N";
      new_move_runs(b, name);
      b.finish();
    }
}

TEST(Faults, StopCombinedWithAbortAndOnIdleAxis) {
  CoreBench b("stop/abort", 2, 77);
  use_slow_pulse(b);
  b.background(true);
  for (int i = 0; i < 20; ++i) b.tick();
  // STOP, then ABORT while stopping: the abort wins at once.
  run_to(b, When::Cruise, 3);
  b.stop(2);
  b.tick();
  ASSERT_TRUE(b.model(2).stopping());
  for (int i = 0; i < 40; ++i) b.tick();
  const uint64_t r = b.monitor(2).rises;
  b.abort(2);
  b.tick();
  EXPECT_FALSE(b.out(2).busy);
  for (int i = 0; i < 300; ++i) b.tick();
  EXPECT_EQ(b.monitor(2).rises, r) << "STEP rose after the abort";
  // ABORT and STOP on the same edge: abort.
  run_to(b, When::Accel, 2);
  const uint64_t r2 = b.monitor(2).rises;
  b.abort(2);
  b.stop(2);
  b.tick();
  EXPECT_FALSE(b.out(2).busy);
  for (int i = 0; i < 300; ++i) b.tick();
  EXPECT_EQ(b.monitor(2).rises, r2);
  // STOP on an idle axis: nothing happens, the next move runs normally.
  b.stop(2);
  b.tick();
  EXPECT_FALSE(b.out(2).busy || b.out(2).err || b.out(2).done);
  new_move_runs(b, "after stop on idle");
  b.finish();
}

// ---------------------------------------------------------------------------------------------
// Direction reversal between chained moves: every move reverses, short and fast moves so that
// the DIR setup and hold windows are what limits the timing; the pin monitor checks them.

class MonitoredCore : public CoreSim {
 public:
  explicit MonitoredCore(LockstepCore& ls) : ls_(ls) {}
  void reset() override { ls_.reset(); }
  void tick(const CoreInputs& in) override {
    ls_.tick(in);
    for (unsigned a = 0; a < kNumAxes; ++a) mon[a].sample(cyc_, ls_.out(a), in.pulse[a]);
    ++cyc_;
  }
  AxisOutputs out(unsigned a) const override { return ls_.out(a); }
  std::array<PinMonitor, kNumAxes> mon{};

 private:
  LockstepCore& ls_;
  int64_t cyc_ = 0;
};

TEST(Faults, DirectionReversalBetweenChainedMoves) {
  const PulseConfig pcs[] = {{1, 1, 1, 1, false, false},   {2, 3, 60, 5, false, false},
                             {2, 3, 5, 60, true, true},     {1, 1, 200, 200, false, true},
                             {9, 1, 4095, 0, false, false}, {1, 9, 0, 4095, true, false}};
  for (unsigned variant = 0; variant < 3; ++variant) {
    Job job;
    std::array<int64_t, kNumAxes> expect{};
    for (unsigned a = 0; a < kNumAxes; ++a) {
      job.axes[a].pulse = pcs[(a + variant) % kNumAxes];
      for (unsigned i = 0; i < 8; ++i) {
        const bool dir = (i + a) % 2 == 0;
        AxisMove m = (i + variant) % 3 == 0 ? cruise(1 + i % 3, ~0ull >> (1 + variant), dir)
                                            : (i % 3 == 1 ? trapezoid(8 + i, dir) : cruise(2, 1ull << 62, dir));
        job.axes[a].moves.push_back(m);
        expect[a] += signed_steps(m);
      }
    }
    LockstepCore ls;
    MonitoredCore mc(ls);
    const RunResult r = run_job(mc, job, [](const StepEvent&) {});
    EXPECT_FALSE(r.timed_out);
    EXPECT_EQ(ls.mismatches(), 0u) << "variant " << variant << "\n" << ls.report_text();
    for (unsigned a = 0; a < kNumAxes; ++a) {
      EXPECT_EQ(r.position[a], expect[a]) << "variant " << variant << " axis " << a;
      EXPECT_EQ(r.refused[a], 0u);
      for (const std::string& e : mc.mon[a].errors)
        ADD_FAILURE() << "variant " << variant << " axis " << a << ": " << e;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Register values out of range: every refusal rule of docs/ARCHITECTURE.md ("Registers of a
// move"), each case built from a valid move by breaking exactly one rule, next to the boundary
// case that the same rule still accepts. A refused start pulses done and err on the next cycle
// and never moves; the axis takes a new move at once (no hang).

struct RuleCase {
  const char* name;
  std::function<void(AxisMove&)> apply;
  bool refused;
};

std::vector<RuleCase> rule_cases() {
  return {
      {"v_max == 0", [](AxisMove& m) { m.v_max = 0; m.v_start = m.v_end = m.v_dec = 0; }, true},
      {"v_start > v_max", [](AxisMove& m) { m.v_start = m.v_max + 1; }, true},
      {"v_start == v_max (accepted)", [](AxisMove& m) { m.v_start = m.v_max; }, false},
      {"v_end > v_max", [](AxisMove& m) { m.v_end = m.v_max + 1; }, true},
      {"v_end == v_max (accepted)", [](AxisMove& m) { m.v_end = m.v_max; }, false},
      {"v_dec > v_max", [](AxisMove& m) { m.v_dec = m.v_max + 1; }, true},
      {"v_dec == v_max (accepted)", [](AxisMove& m) { m.v_dec = m.v_max; }, false},
      {"all speeds all-ones (accepted)", [](AxisMove& m) { m.v_start = m.v_max = m.v_end = m.v_dec = ~0ull; }, false},
      {"acc_steps > steps", [](AxisMove& m) { m.acc_steps = m.steps + 1; }, true},
      {"acc_steps == steps (accepted)", [](AxisMove& m) { m.acc_steps = m.steps; }, false},
      {"acc_steps all-ones", [](AxisMove& m) { m.acc_steps = ~0u; }, true},
      {"dec_step > steps (decel count past N)", [](AxisMove& m) { m.dec_step = m.steps + 1; }, true},
      {"dec_step == steps (accepted)", [](AxisMove& m) { m.dec_step = m.steps; }, false},
      {"dec_step all-ones", [](AxisMove& m) { m.dec_step = ~0u; }, true},
      {"v_end == 0 && dec == 0", [](AxisMove& m) { m.v_end = 0; m.dec = 0; }, true},
      // (the floor dec <= 2^-20 step/tick would crawl: deceleration starts only at the last step)
      {"v_end == 0, dec != 0 (accepted: floor = dec)",
       [](AxisMove& m) { m.v_end = 0; m.dec = (1ull << 44) - 1; m.dec_step = m.steps; }, false},
      {"v_end != 0, dec == 0 (accepted)", [](AxisMove& m) { m.dec = 0; }, false},
      {"v_start == 0 && acc == 0 (zero speed, zero acceleration)", [](AxisMove& m) { m.v_start = 0; m.acc = 0; }, true},
      {"v_start == 0 && acc_steps == 0", [](AxisMove& m) { m.v_start = 0; m.acc_steps = 0; }, true},
      {"v_start == 0, accelerating (accepted)", [](AxisMove& m) { m.v_start = 0; }, false},
      {"v_start == 0, acc == 0, decelerating from the first tick (accepted)",
       [](AxisMove& m) { m.v_start = 0; m.acc = 0; m.dec_step = 0; m.dec_frac = 0; m.v_dec = m.v_max; }, false},
      {"v_start == 0, acc == 0, dec_frac != 0 (not decelerating at once)",
       [](AxisMove& m) { m.v_start = 0; m.acc = 0; m.dec_step = 0; m.dec_frac = 1; m.v_dec = m.v_max; }, true},
      {"several rules at once", [](AxisMove& m) { m.v_max = 0; m.acc_steps = ~0u; m.dec = 0; m.v_end = 0; }, true},
      {"v_end == 0 && dec > v_max (floor above v_max)",
       [](AxisMove& m) { m.v_end = 0; m.v_max = m.v_start = m.v_dec = 1ull << 40; m.dec = (1ull << 40) + 1; }, true},
      // Jog moves (accepted ones run until STOP: tests/model/test_stop.cpp, test_wb_model.cpp).
      {"jog with dec == 0", [](AxisMove& m) { m.jog = true; m.dec = 0; }, true},
      {"jog with v_start == 0 && acc == 0", [](AxisMove& m) { m.jog = true; m.v_start = 0; m.acc = 0; }, true},
      {"jog with v_start > v_max", [](AxisMove& m) { m.jog = true; m.v_start = m.v_max + 1; }, true},
      {"jog with v_max == 0", [](AxisMove& m) { m.jog = true; m.v_max = m.v_start = 0; }, true},
  };
}

TEST(Faults, RefusalRulesRefuseCleanlyAndNeverHang) {
  unsigned n = 0;
  for (const RuleCase& rc : rule_cases()) {
    for (unsigned steps : {1u, 40u}) {
      const unsigned k = n++ % kNumAxes;
      const std::string name = std::string(rc.name) + ", steps " + std::to_string(steps);
      AxisMove m = trapezoid(steps, n % 2 == 0);
      if (steps == 1) m.acc_steps = 1, m.dec_step = 1;
      rc.apply(m);
      CoreBench b(name, k, 300 + n);
      b.background(true);
      for (int i = 0; i < 40; ++i) b.tick();
      const int64_t p0 = b.out(k).pos;
      const uint64_t r0 = b.monitor(k).rises;
      EXPECT_FALSE(b.out(k).busy) << name << ": axis busy before the start (phase "
                                  << int(b.out(k).phase) << ", pos " << b.out(k).pos << ")";
      b.start(k, m);
      b.tick();  // the start edge
      if (rc.refused) {
        EXPECT_TRUE(b.out(k).done && b.out(k).err) << name << ": no done+err on the cycle after the start";
        EXPECT_FALSE(b.out(k).busy) << name;
        for (int i = 0; i < 2000; ++i) b.tick();
        EXPECT_EQ(b.monitor(k).rises, r0) << name << ": a refused move stepped";
        EXPECT_EQ(b.out(k).pos, p0) << name;
      } else {
        EXPECT_FALSE(b.out(k).err) << name << ": refused (validate_move " << validate_move(m) << ") "
                                   << show_outputs(b.out(k));
        if (!b.run_until([&] { return b.out(k).done; }, 400000)) {
          ADD_FAILURE() << name << ": never ends: " << show_outputs(b.out(k)) << " speed " << b.model(k).speed()
                        << " steps done " << b.model(k).steps_done();
          continue;
        }
        b.tick();
        EXPECT_EQ(b.out(k).pos - p0, signed_steps(m)) << name;
        EXPECT_EQ(b.monitor(k).rises - r0, m.steps) << name;
      }
      new_move_runs(b, name);
      b.finish();
    }
  }
}

TEST(Faults, StartOnABusyAxisIsRefusedAndLeavesTheMoveAlone) {
  CoreBench b("busy start", 2, 7);
  b.background(true);
  const AxisMove m = trapezoid(90);
  b.start(2, m);
  b.tick();
  for (When w : {When::Accel, When::Cruise, When::Decel}) {
    ASSERT_TRUE(b.run_until([&] {
      const Phase p = b.model(2).phase();
      return (w == When::Accel && p == Phase::Accel) || (w == When::Cruise && p == Phase::Cruise) ||
             (w == When::Decel && p == Phase::Decel);
    }));
    b.start(2, cruise(5, 1ull << 63, false));
    b.tick();
    EXPECT_TRUE(b.out(2).err) << when_name(w) << ": no err pulse";
    EXPECT_TRUE(b.out(2).busy) << when_name(w) << ": the running move stopped";
  }
  ASSERT_TRUE(b.run_until([&] { return b.out(2).done; }));
  b.tick();
  EXPECT_EQ(b.out(2).pos, 90);
  EXPECT_EQ(b.monitor(2).rises, 90u);
  b.finish();
}

// ---------------------------------------------------------------------------------------------
// Position counter wrap-around: the same RTL built with POS_W = 8 (tests/CMakeLists.txt,
// Vhexstep_core_pos8) against CoreModel with Widths::pos = 8, every output after every edge,
// through +127 -> -128 and back. (The 32-bit counter needs 2^31 steps; see docs/TESTING.md.)

template <std::size_t N>
void put_bits(VlWide<N>& v, unsigned lsb, unsigned width, uint64_t value) {
  for (unsigned b = 0; b < width; ++b) {
    const unsigned bit = lsb + b;
    const uint32_t m = 1u << (bit % 32);
    if ((value >> b) & 1u) v[bit / 32] |= m; else v[bit / 32] &= ~m;
  }
}
template <typename T>
void put_bits(T& v, unsigned lsb, unsigned width, uint64_t value) {
  for (unsigned b = 0; b < width; ++b) {
    const T m = static_cast<T>(T(1) << (lsb + b));
    if ((value >> b) & 1u) v |= m; else v &= static_cast<T>(~m);
  }
}

class RtlCorePos8 {
 public:
  static constexpr unsigned kPosW = 8;
  RtlCorePos8() : top_(new Vhexstep_core_pos8(&ctx_, "hexstep_core")) {
    top_->clk_i = 0;
    top_->rst_i = 1;
    top_->eval();
    for (int i = 0; i < 2; ++i) edge();
    top_->rst_i = 0;
    top_->eval();
  }
  ~RtlCorePos8() { top_->final(); }
  void tick(const CoreInputs& in) {
    const Widths w;
    auto& t = *top_;
    t.start_i = static_cast<uint8_t>(in.start_mask);
    t.abort_i = static_cast<uint8_t>(in.abort_mask);
    for (unsigned k = 0; k < kNumAxes; ++k) {
      const AxisMove& m = in.move[k];
      const PulseConfig& p = in.pulse[k];
      put_bits(t.steps_i, k * w.steps, w.steps, m.steps);
      put_bits(t.dir_i, k, 1, m.dir);
      put_bits(t.v_start_i, k * w.speed_frac, w.speed_frac, m.v_start);
      put_bits(t.v_max_i, k * w.speed_frac, w.speed_frac, m.v_max);
      put_bits(t.v_end_i, k * w.speed_frac, w.speed_frac, m.v_end);
      put_bits(t.v_dec_i, k * w.speed_frac, w.speed_frac, m.v_dec);
      put_bits(t.acc_i, k * w.acc, w.acc, m.acc);
      put_bits(t.dec_i, k * w.acc, w.acc, m.dec);
      put_bits(t.acc_steps_i, k * w.steps, w.steps, m.acc_steps);
      put_bits(t.dec_step_i, k * w.steps, w.steps, m.dec_step);
      put_bits(t.dec_frac_i, k * w.dec_frac, w.dec_frac, m.dec_frac);
      put_bits(t.step_high_i, k * w.pulse, w.pulse, p.step_high);
      put_bits(t.step_low_i, k * w.pulse, w.pulse, p.step_low);
      put_bits(t.dir_setup_i, k * w.pulse, w.pulse, p.dir_setup);
      put_bits(t.dir_hold_i, k * w.pulse, w.pulse, p.dir_hold);
      put_bits(t.step_inv_i, k, 1, p.step_invert);
      put_bits(t.dir_inv_i, k, 1, p.dir_invert);
    }
    edge();
  }
  int64_t pos(unsigned k) const {
    const int64_t v = static_cast<int64_t>((static_cast<uint64_t>(top_->pos_o) >> (k * kPosW)) & 0xFFu);
    return v >= 128 ? v - 256 : v;
  }
  bool busy(unsigned k) const { return (top_->busy_o >> k) & 1u; }
  bool step(unsigned k) const { return (top_->step_o >> k) & 1u; }
  bool dir(unsigned k) const { return (top_->dir_o >> k) & 1u; }

 private:
  void edge() {
    top_->eval();
    top_->clk_i = 1;
    top_->eval();
    top_->clk_i = 0;
    top_->eval();
  }
  VerilatedContext ctx_;
  std::unique_ptr<Vhexstep_core_pos8> top_;
};

TEST(Faults, PositionCounterWrapsAround) {
  Widths w;
  w.pos = RtlCorePos8::kPosW;
  CoreModel model(w);
  RtlCorePos8 rtl;
  CoreInputs in;
  // Axis 0: +300 then -600 (through +127 -> -128 and back); axis 3: -129 then +1; others idle.
  std::array<std::vector<AxisMove>, kNumAxes> moves;
  moves[0] = {cruise(300, 1ull << 62), cruise(600, 1ull << 62, false)};
  moves[3] = {cruise(129, 1ull << 61, false), cruise(1, 1ull << 61)};
  std::array<size_t, kNumAxes> next{};
  std::array<bool, kNumAxes> saw_wrap{};
  std::array<int64_t, kNumAxes> prev{};
  uint64_t mismatches = 0;
  for (unsigned a = 0; a < kNumAxes; ++a)
    if (!moves[a].empty()) in.move[a] = moves[a][next[a]++], in.start_mask |= 1u << a;
  for (int cyc = 0; cyc < 20000; ++cyc) {
    model.tick(in);
    rtl.tick(in);
    in.start_mask = 0;
    for (unsigned a = 0; a < kNumAxes; ++a) {
      const AxisOutputs o = model.out(a);
      if (o.pos != rtl.pos(a) || o.busy != rtl.busy(a) || o.step != rtl.step(a) || o.dir != rtl.dir(a)) {
        if (mismatches++ < 5)
          ADD_FAILURE() << "cycle " << cyc << " axis " << a << ": model pos " << o.pos << " busy " << o.busy
                        << ", rtl pos " << rtl.pos(a) << " busy " << rtl.busy(a);
      }
      if ((prev[a] == 127 && o.pos == -128) || (prev[a] == -128 && o.pos == 127)) saw_wrap[a] = true;
      prev[a] = o.pos;
      if (o.done && next[a] < moves[a].size()) in.move[a] = moves[a][next[a]++], in.start_mask |= 1u << a;
    }
  }
  EXPECT_EQ(mismatches, 0u);
  // 300 - 600 = -300 == -44 (mod 256); -129 + 1 = -128.
  EXPECT_EQ(model.out(0).pos, -44);
  EXPECT_EQ(rtl.pos(0), -44);
  EXPECT_EQ(model.out(3).pos, -128);
  EXPECT_EQ(rtl.pos(3), -128);
  EXPECT_TRUE(saw_wrap[0] && saw_wrap[3]);
  for (unsigned a = 0; a < kNumAxes; ++a) EXPECT_FALSE(rtl.busy(a));
}

// ---------------------------------------------------------------------------------------------
// Through the Wishbone top (hexstep_top): the golden register-block model WbModel beside it
// (tests/common/wb_ref.hpp: ack, read data, IRQ, STEP/DIR after every edge), plus the E-STOP
// timing of docs/ARCHITECTURE.md checked directly: the pin's first sampled-high edge is edge E,
// the core is aborted at edge E+3 and at every edge while the latch is set; pushes and starts
// are dropped.

void start(WbTop& bus, uint32_t mask) { bus.write(R::START, mask); }
uint32_t free_slots(WbTop& bus, unsigned k) {
  return (bus.read(ax(k, R::axis::STATUS)) & R::axis::STATUS_FREE_MASK) >> R::axis::STATUS_FREE_SHIFT;
}
int64_t bus_pos(WbTop& bus, unsigned k) { return static_cast<int32_t>(bus.read(ax(k, R::axis::POS_LO))); }
bool run_until_idle(WbTop& bus, WbRef& ref, uint64_t limit = 400000) {
  for (uint64_t i = 0; i < limit && !ref.idle(); ++i) bus.tick();
  for (int i = 0; i < 20; ++i) bus.tick();
  return ref.idle();
}

// E-STOP while all six axes run chained moves: swept over the edges around the first chain
// boundary of axis 0 and inside the moves. No STEP rises from the core's abort edge on, every
// pulse already high completes, queues are flushed, ERR.estop is set on every axis, positions
// equal the model's; after the pin falls and the latch is cleared, a new chained sequence runs.
TEST(Faults, EstopDuringChainedMoves) {
  // Where the first chain boundary of axis 0 falls (edge of the second start), from a run
  // without E-STOP.
  auto load = [](WbTop& bus) {
    for (unsigned k = 0; k < kNumAxes; ++k) {
      push(bus, k, trapezoid(40 + 4 * k, k % 2 == 0));
      push(bus, k, cruise(30, 1ull << 61, k % 2 == 1));
    }
  };
  uint64_t chain_edge = 0, start_edge = 0;
  {
    WbTop bus(21);
    WbRef ref(bus);
    load(bus);
    start(bus, kAllAxes);
    ASSERT_TRUE(run_until_idle(bus, ref));
    ASSERT_EQ(ref.starts[0].size(), 2u);
    start_edge = ref.starts[0][0];
    chain_edge = ref.starts[0][1];
    EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
  }
  std::vector<int64_t> offsets;  // E-STOP pin edges relative to the chain boundary
  for (int64_t d = -6; d <= 3; ++d) offsets.push_back(d);
  offsets.push_back(-int64_t(chain_edge - start_edge) / 2);  // inside the first moves
  offsets.push_back(40);                                      // inside the second moves
  for (int64_t off : offsets) {
    const std::string name = "E-STOP at chain boundary " + std::to_string(off);
    WbTop bus(22);
    bus.set_timing(1, 1);
    WbRef ref(bus);
    load(bus);
    start(bus, kAllAxes);
    // The reference's edge count equals the edge count of the first run at the same point (the
    // bus traffic before the start differs only in its random idle cycles): find the start.
    ASSERT_FALSE(ref.starts[0].empty()) << name;
    const uint64_t target = ref.starts[0][0] + (chain_edge - start_edge) + off;
    while (ref.edges + 1 < target) bus.tick();
    bus.set_estop(true);  // the next edge, E, samples the pin high
    std::array<uint64_t, kNumAxes> rises_at_abort{};
    for (int i = 0; i < 4; ++i) {  // edges E .. E+3: the core is aborted at E+3, not before
      bus.tick();
      EXPECT_EQ(ref.model.core_inputs().abort_mask, i == 3 ? kAllAxes : 0u) << name << ", edge E+" << i;
    }
    rises_at_abort = ref.rises;
    for (int i = 0; i < 400; ++i) {  // and at every edge while latched
      bus.tick();
      if (ref.model.core_inputs().abort_mask != kAllAxes) {
        ADD_FAILURE() << name << ": latched E-STOP does not abort every axis at edge " << ref.edges - 1;
        break;
      }
    }
    EXPECT_EQ(ref.mismatches, 0u) << name << "\n" << ref.report_text();
    EXPECT_EQ(ref.rises, rises_at_abort) << name << ": STEP rose after the core's abort edge";
    EXPECT_EQ(bus.read(R::GSTATUS), R::GSTATUS_ESTOP_MASK | R::GSTATUS_ESTOP_PIN_MASK) << name;
    for (unsigned k = 0; k < kNumAxes; ++k) {
      EXPECT_EQ(bus.read(ax(k, R::axis::STATUS)), R::axis::STATUS_RESET) << name << " axis " << k;
      EXPECT_NE(bus.read(ax(k, R::axis::ERR)) & R::axis::ERR_ESTOP_MASK, 0u) << name << " axis " << k;
      EXPECT_EQ(bus_pos(bus, k), ref.out(k).pos) << name << " axis " << k;
    }
    // Pushes and starts are dropped while latched.
    push(bus, 1, cruise(10, 1ull << 61));
    start(bus, 2u);
    EXPECT_EQ(free_slots(bus, 1), 2u) << name;
    bus.set_estop(false);
    for (int i = 0; i < 6; ++i) bus.tick();
    bus.write(R::GSTATUS, R::GSTATUS_ESTOP_MASK);
    EXPECT_EQ(bus.read(R::GSTATUS), 0u) << name;
    for (unsigned k = 0; k < kNumAxes; ++k) bus.write(ax(k, R::axis::ERR), 0xFFFFFFFFu);
    // A new chained sequence, all axes, reversed directions.
    std::array<int64_t, kNumAxes> p0{};
    for (unsigned k = 0; k < kNumAxes; ++k) p0[k] = ref.out(k).pos;
    for (unsigned k = 0; k < kNumAxes; ++k) {
      push(bus, k, cruise(12, 1ull << 61, k % 2 == 1));
      push(bus, k, trapezoid(40, k % 2 == 0));
    }
    start(bus, kAllAxes);
    ASSERT_TRUE(run_until_idle(bus, ref)) << name;
    EXPECT_EQ(ref.mismatches, 0u) << name << "\n" << ref.report_text();
    for (unsigned k = 0; k < kNumAxes; ++k) {
      const int64_t want = p0[k] + (k % 2 == 1 ? 12 : -12) + (k % 2 == 0 ? 40 : -40);
      EXPECT_EQ(ref.out(k).pos, want) << name << " axis " << k;
      EXPECT_EQ(bus_pos(bus, k), want) << name << " axis " << k;
      EXPECT_EQ(bus.read(ax(k, R::axis::ERR)), 0u) << name << " axis " << k;
    }
  }
}

// Queue overrun while the axis runs: the third push is dropped with ERR.overrun, the two queued
// moves run exactly, the other axes (running their own chains) are untouched.
TEST(Faults, QueueOverrunDuringMotion) {
  WbTop bus(23);
  bus.set_timing(2, 1);
  WbRef ref(bus);
  const AxisMove a = cruise(200, 1ull << 60), b = trapezoid(50, false), c = cruise(30, 1ull << 61);
  std::array<int64_t, kNumAxes> expect{};
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (k == 4) continue;
    push(bus, k, trapezoid(60 + k, k % 2 == 0));
    expect[k] = (k % 2 == 0 ? 1 : -1) * int64_t(60 + k);
  }
  push(bus, 4, a);
  start(bus, kAllAxes);
  for (int i = 0; i < 50; ++i) bus.tick();
  push(bus, 4, b);
  push(bus, 4, c);
  EXPECT_EQ(free_slots(bus, 4), 0u);
  EXPECT_EQ(bus.read(ax(4, R::axis::ERR)), 0u);
  push(bus, 4, cruise(7, 1ull << 62));  // full: dropped
  EXPECT_EQ(bus.read(ax(4, R::axis::ERR)), R::axis::ERR_OVERRUN_MASK);
  push(bus, 4, cruise(7, 1ull << 62));  // again
  EXPECT_EQ(free_slots(bus, 4), 0u);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (k != 4) EXPECT_EQ(bus.read(ax(k, R::axis::ERR)), 0u) << "axis " << k;
  }
  ASSERT_TRUE(run_until_idle(bus, ref));
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
  expect[4] = signed_steps(a) + signed_steps(b) + signed_steps(c);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_EQ(bus_pos(bus, k), expect[k]) << "axis " << k;
    EXPECT_EQ(ref.out(k).pos, expect[k]) << "axis " << k;
  }
  EXPECT_EQ(ref.starts[4].size(), 3u);
  EXPECT_EQ(bus.protocol_errors(), 0u);
}

// Bus writes to every register (and a few unmapped addresses) of every axis while axis 2 runs a
// move and the others run theirs: all ones, zero, random values under random byte enables.
// Staging words, CMD without the push bit, STATUS/POS (read only), ERR and IRQ_PENDING
// (write-1-to-clear), IRQ_ENABLE, START of running axes, ABORT with no lane selected, other
// global commands (STOP) with an empty mask: none may change a running move. The pulse timing
// and polarity registers are live by design (docs/ARCHITECTURE.md), so they are rewritten with
// the value they hold.
TEST(Faults, BusWritesToEveryRegisterDuringMotion) {
  WbTop bus(24);
  bus.set_timing(1, 1);
  WbRef ref(bus);
  std::mt19937 rng(24);
  const AxisMove main = cruise(1500, 1ull << 59, false);
  std::array<int64_t, kNumAxes> expect{};
  for (unsigned k = 0; k < kNumAxes; ++k) {
    const AxisMove m = k == 2 ? main : cruise(1200 + 100 * k, (1ull << 59) + (uint64_t(k) << 50), k % 2 == 0);
    push(bus, k, m);
    expect[k] = signed_steps(m);
  }
  start(bus, kAllAxes);
  std::vector<uint32_t> pulse_regs = {R::axis::STEP_HIGH, R::axis::STEP_LOW, R::axis::DIR_SETUP, R::axis::DIR_HOLD,
                                      R::axis::POLARITY};
  unsigned writes = 0;
  for (unsigned k = 0; k < kNumAxes; ++k)
    for (uint32_t reg : R::axis::kAll) {
      const uint32_t adr = ax(k, reg);
      char ctx[64];
      std::snprintf(ctx, sizeof ctx, "writing 0x%03x", adr);
      ref.context = ctx;
      if (std::find(pulse_regs.begin(), pulse_regs.end(), reg) != pulse_regs.end()) {
        bus.write(adr, bus.read(adr));
        ++writes;
        continue;
      }
      if (reg == R::axis::CMD) {  // no command bit, and all bits with lane 0 disabled
        bus.write(adr, 0);
        bus.write(adr, 0xFFFFFFFFu, 0xE);
        writes += 2;
        continue;
      }
      for (uint32_t v : {0xFFFFFFFFu, 0u, static_cast<uint32_t>(rng())}) {
        bus.write(adr, v, v == 0 || v == 0xFFFFFFFFu ? 0xFu : (rng() & 0xFu));
        ++writes;
      }
    }
  // Global registers: each written in the way that must leave running moves alone.
  for (uint32_t adr : R::kAll) {
    char ctx[64];
    std::snprintf(ctx, sizeof ctx, "writing global 0x%03x", adr);
    ref.context = ctx;
    if (adr == R::START) {
      bus.write(adr, 1u << 2);  // axis 2 is running: nothing to start
    } else if (adr == R::ABORT) {
      bus.write(adr, kAllAxes, 0x0);  // no byte lane selected: no abort
    } else if (adr == R::GSTATUS || adr == R::IRQ_ENABLE || adr == R::IRQ_PENDING || adr == R::ID ||
               adr == R::VERSION) {
      bus.write(adr, 0xFFFFFFFFu);  // W1C of an e-stop that is not latched, IRQs, read-only
      bus.write(adr, 0);
    } else {
      bus.write(adr, 0);  // other commands (STOP, ...): an empty axis mask
    }
    writes += 2;
  }
  ref.context = "writing unmapped addresses";
  for (uint32_t adr : {0x080u, 0x0FCu, ax(2, 0x7C), 0xFFCu}) bus.write(adr, 0xFFFFFFFFu);
  writes += 4;
  ref.context.clear();
  ASSERT_TRUE(ref.out(2).busy) << "the writes outlasted the move; lengthen it";
  ASSERT_TRUE(run_until_idle(bus, ref));
  EXPECT_GT(writes, 400u);
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_EQ(bus_pos(bus, k), expect[k]) << "axis " << k;
    EXPECT_EQ(ref.rises[k], static_cast<uint64_t>(std::llabs(expect[k]))) << "axis " << k;
    EXPECT_EQ(ref.starts[k].size(), 1u) << "axis " << k;
  }
  EXPECT_EQ(bus.protocol_errors(), 0u);
}

}  // namespace
