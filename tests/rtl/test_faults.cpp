// SPDX-License-Identifier: Apache-2.0
// Fault and bad-input tests through the Wishbone bus, the Verilated hexstep_top and TopModel in
// lock step (tests/common/bench.hpp: every output after every edge), with the independent
// output-timing monitor on every pin (exact high time, low time, DIR setup and hold):
//   reset, ABORT and STOP in every phase of a move (accelerating, cruising, decelerating, STEP
//   high, a step owed while DIR waits for its setup time, the edge the axis comes to rest, the
//   start's slot between sample and commit), each followed by a new move that must run exactly;
//   E-STOP swept around a chain boundary of six chained axes; direction reversal between chained
//   moves with DIR setup/hold of 0 to 4095 cycles; a queue overrun during motion; every refusal
//   rule through the bus (refused moves consumed with ERR.move, never stepping, the axis taking
//   the next move at once); writes to every register while all axes move.
// In every test the other axes run moves of their own and must end exactly at their positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "bench.hpp"
#include "rules.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;
namespace R = hexstep::regs;
namespace A = hexstep::regs::axis;

namespace {
constexpr uint32_t kAllAxes = (1u << kNumAxes) - 1u;
int64_t signed_steps(const AxisMove& m) { return m.dir ? int64_t(m.steps) : -int64_t(m.steps); }

const PulseConfig kPulses[kNumAxes] = {{1, 1, 0, 0, false, false}, {3, 5, 7, 2, true, false},
                                       {2, 2, 40, 40, false, true}, {7, 3, 0, 9, true, true},
                                       {1, 4, 3, 0, false, false},  {5, 5, 11, 13, false, true}};
// The axis under test: a DIR setup long enough that a reversing move's first step waits for it.
const PulseConfig kSlowPulse{4, 6, 300, 15, false, true};

// Moves on every axis but one, topped up whenever their queue has room; each must end with
// exactly the steps it was given.
class Background {
 public:
  Background(Bench& b, unsigned skip, uint64_t seed, unsigned moves_per_axis = 3)
      : b_(b), skip_(skip), rng_(seed), per_axis_(moves_per_axis) {
    restart();
  }
  void service() {
    for (unsigned a = 0; a < kNumAxes; ++a) {
      if (a == skip_) continue;
      const uint32_t st = b_.status(a);
      const unsigned free = (st & A::STATUS_FREE_MASK) >> A::STATUS_FREE_SHIFT;
      bool pushed = false;
      if (free > 0 && left_[a] > 0) {
        const AxisMove m = rng_() % 2 ? trapezoid(40 + rng_() % 60, rng_() & 1)
                                      : cruise(5 + rng_() % 30, (1ull << 61) >> (rng_() % 3), rng_() & 1);
        b_.push(a, m);
        expect_[a] += signed_steps(m);
        --left_[a];
        pushed = true;
      }
      // Idle with moves queued (also when the queue ran dry while a push loaded): START.
      if (!(st & (A::STATUS_RUN_MASK | A::STATUS_BUSY_MASK)) && (pushed || free < 2)) b_.write(R::START, 1u << a);
    }
  }
  // After a reset: nothing ran yet.
  void restart() {
    expect_.fill(0);
    left_.fill(per_axis_);
    left_[skip_] = 0;
  }
  // Lets the given moves finish and checks the positions.
  void finish(const std::string& name) {
    while (std::any_of(left_.begin(), left_.end(), [](unsigned n) { return n != 0; })) {
      service();
      b_.idle(500);
    }
    for (int i = 0; i < 3; ++i) {  // moves pushed after a queue ran dry need their START
      ASSERT_TRUE(b_.settle()) << name;
      service();
    }
    for (unsigned a = 0; a < kNumAxes; ++a)
      if (a != skip_) EXPECT_EQ(b_.position(a), expect_[a]) << name << ": background axis " << a << " disturbed";
  }

 private:
  Bench& b_;
  unsigned skip_;
  std::mt19937_64 rng_;
  unsigned per_axis_;
  std::array<unsigned, kNumAxes> left_{};
  std::array<int64_t, kNumAxes> expect_{};
};

void configure(Bench& b, unsigned k) {
  for (unsigned a = 0; a < kNumAxes; ++a) b.set_pulse(a, a == k ? kSlowPulse : kPulses[a]);
}

// Points in a move at which a fault is injected.
enum class When { Accel, Cruise, Decel, StepHigh, DirSetupWait, RestEdge, StartSlot };
const When kEveryPhase[] = {When::Accel, When::Cruise, When::Decel, When::StepHigh, When::DirSetupWait,
                            When::RestEdge, When::StartSlot};
const char* when_name(When w) {
  switch (w) {
    case When::Accel: return "accel";
    case When::Cruise: return "cruise";
    case When::Decel: return "decel";
    case When::StepHigh: return "step-high";
    case When::DirSetupWait: return "dir-setup-wait";
    case When::RestEdge: return "rest-edge";
    case When::StartSlot: return "start-slot";
  }
  return "?";
}

// Starts a move on axis k that reverses its direction (so its first step waits for the DIR
// setup time) and runs until `w` holds after an edge, then `extra` edges more; the fault goes
// in with the next edge. Returns false if the point was never reached.
bool run_to(Bench& b, unsigned k, When w, unsigned extra) {
  const bool dir = !b.m().pulse(k).dir_level();
  b.push(k, trapezoid(120, dir));
  b.write(R::START, 1u << k);
  const TopModel& m = b.m();
  const int64_t p0 = m.pulse(k).position();
  bool was_busy = false;
  std::function<bool()> pred;
  switch (w) {
    case When::Accel: pred = [&] { return m.gen(k).phase() == Phase::Accel && m.gen(k).steps_done() > 2; }; break;
    case When::Cruise: pred = [&] { return m.gen(k).phase() == Phase::Cruise; }; break;
    case When::Decel: pred = [&] { return m.gen(k).phase() == Phase::Decel; }; break;
    case When::StepHigh: pred = [&] { return m.pulse(k).step_level() && m.gen(k).steps_done() > 10; }; break;
    case When::DirSetupWait:
      pred = [&] { return m.pulse(k).owed() != 0 && m.pulse(k).position() == p0 && !m.pulse(k).step_level(); };
      break;
    case When::RestEdge:  // the edge after which the axis is no longer busy
      pred = [&] {
        const bool busy = m.busy(k);
        const bool fell = was_busy && !busy;
        was_busy = busy;
        return fell;
      };
      break;
    case When::StartSlot:  // between the start's sample and its commit
      pred = [&] { return m.running(k) && !m.gen(k).run(); };
      break;
  }
  if (!b.run_until(pred, 200000)) return false;
  for (unsigned i = 0; i < extra && m.busy(k); ++i) b.idle(1);
  return true;
}

// A request acted on at the very next edge (the bus is idle between the test's accesses).
void write_now(Bench& b, uint32_t adr, uint32_t dat) {
  b.bus.drive(true, true, true, adr, dat, 0xF);
  for (unsigned i = 0; i < kTakeCycles; ++i) b.bus.tick();  // taken
  b.bus.tick();  // acted on here
  b.bus.tick();  // the ack cycle
  b.bus.drive(false, false, false, 0, 0, 0);
}

// After a fault: a new move on axis k runs to exactly its steps.
void new_move_runs(Bench& b, unsigned k, const std::string& name) {
  ASSERT_TRUE(b.run_until([&] { return !b.m().busy(k) && !b.m().running(k); }, 400000)) << name;
  const int64_t p0 = b.position(k);
  const uint64_t r0 = b.rises(k);
  const AxisMove m = trapezoid(77, p0 < 0);
  b.push(k, m);
  b.write(R::START, 1u << k);
  b.idle(2 * kFrameCycles);
  EXPECT_NE(b.status(k) & A::STATUS_BUSY_MASK, 0u) << name << ": new move not running";
  ASSERT_TRUE(b.run_until([&] { return !b.m().busy(k) && !b.m().running(k); }, 400000)) << name;
  EXPECT_EQ(b.position(k) - p0, signed_steps(m)) << name;
  EXPECT_EQ(b.rises(k) - r0, m.steps) << name;
  EXPECT_EQ(b.axr(k, A::ERR) & A::ERR_MOVE_MASK, 0u) << name << ": new move refused";
}

// Rising edges of STEP (before polarity) per axis, first high cycle, from the model's levels.
struct Rises {
  std::array<std::vector<uint64_t>, kNumAxes> at;
  std::array<int64_t, kNumAxes> pos{};  // +1/-1 by the DIR level at each rise
  std::array<bool, kNumAxes> prev{};
  void attach(Bench& b) {
    b.bus.on_edge = [this, &b] {
      for (unsigned a = 0; a < kNumAxes; ++a) {
        const bool l = b.m().pulse(a).step_level();
        if (l && !prev[a]) {
          at[a].push_back(b.cycle());
          pos[a] += b.m().pulse(a).dir_level() ? 1 : -1;
        }
        prev[a] = l;
      }
    };
  }
};
}  // namespace

TEST(Faults, MovesUsedHereFitTheRegistersAndAreValid) {
  const Widths w;
  for (const AxisMove& m : {trapezoid(120), trapezoid(77), trapezoid(40), trapezoid(1), cruise(10, 1ull << 63)}) {
    EXPECT_EQ(validate_move(m), 0u);
    EXPECT_EQ(m.acc & ~w.acc_mask(), 0u);
    EXPECT_EQ(m.dec & ~w.acc_mask(), 0u);
  }
}

// Reset in every phase: both simulators reset together; every axis idle at position 0 with its
// pins at rest (polarity reset too), and a new move runs exactly.
TEST(Faults, ResetInEveryPhaseThenNewMove) {
  for (When w : kEveryPhase)
    for (unsigned extra : {0u, 3u}) {
      const unsigned k = static_cast<unsigned>(w) % kNumAxes;
      const std::string name = std::string("reset at ") + when_name(w) + " +" + std::to_string(extra);
      SCOPED_TRACE(name);
      Bench b(100 + static_cast<unsigned>(w) * 2 + extra);
      configure(b, k);
      Background bg(b, k, 100 + static_cast<unsigned>(w));
      bg.service();
      b.idle(50);
      ASSERT_TRUE(run_to(b, k, w, extra)) << "never reached " << when_name(w);
      b.bus.reset();
      bg.restart();
      for (unsigned a = 0; a < kNumAxes; ++a) {
        EXPECT_FALSE(b.mon.step(a)) << "axis " << a << ": STEP not at rest";
        EXPECT_TRUE(b.mon.dir(a)) << "axis " << a;
      }
      b.idle(kFrameCycles * kNumAxes + 8);  // the initialization after reset
      for (unsigned a = 0; a < kNumAxes; ++a) {
        EXPECT_EQ(b.status(a), A::STATUS_RESET) << "axis " << a;
        EXPECT_EQ(b.position(a), 0) << "axis " << a;
        EXPECT_EQ(b.axr(a, A::ERR), 0u) << "axis " << a;
      }
      EXPECT_EQ(b.read(R::IRQ_PENDING), 0u);
      configure(b, k);
      bg.service();
      new_move_runs(b, k, name);
      bg.finish(name);
      EXPECT_EQ(b.problems(), "");
    }
}

// ABORT in every phase: the axis stops on the edge after the write, no STEP rises from then on,
// a pulse already high completes, the queue is flushed; then a new move runs exactly.
TEST(Faults, AbortInEveryPhaseThenNewMove) {
  for (When w : kEveryPhase)
    for (unsigned extra : {0u, 1u, 5u}) {
      const unsigned k = (static_cast<unsigned>(w) + extra) % kNumAxes;
      const std::string name = std::string("abort at ") + when_name(w) + " +" + std::to_string(extra);
      SCOPED_TRACE(name);
      Bench b(200 + static_cast<unsigned>(w) * 7 + extra);
      configure(b, k);
      Rises rs;
      rs.attach(b);
      Background bg(b, k, 200 + static_cast<unsigned>(w) * 7 + extra);
      bg.service();
      b.idle(30);
      ASSERT_TRUE(run_to(b, k, w, extra)) << "never reached " << when_name(w);
      b.push(k, trapezoid(20));  // queued behind: must be flushed
      const uint64_t stop_edge = abort_edge(b.cycle());
      write_now(b, R::ABORT, 1u << k);
      EXPECT_FALSE(b.m().busy(k) && b.m().gen(k).run()) << "generator running after the abort edge";
      b.idle(400);
      for (uint64_t c : rs.at[k]) EXPECT_LE(c, stop_edge) << "STEP rose after the abort edge";
      EXPECT_FALSE(b.m().pulse(k).step_level());  // a pulse high at the abort completed
      EXPECT_EQ(b.free_slots(k), 2u) << "queue flushed";
      EXPECT_EQ(b.position(k), rs.pos[k]);
      new_move_runs(b, k, name);
      bg.finish(name);
      EXPECT_EQ(b.problems(), "");
    }
}

// STOP in every phase: the queue is flushed, the axis comes to rest with every pulse whole, its
// speed never rising while it stops, never beyond the move's end; then a new move runs exactly.
// Also STOP then ABORT while stopping, and ABORT and STOP on the same edge.
TEST(Faults, StopInEveryPhaseThenNewMove) {
  for (When w : kEveryPhase)
    for (unsigned extra : {0u, 2u}) {
      const unsigned k = (static_cast<unsigned>(w) + 2 * extra) % kNumAxes;
      const std::string name = std::string("stop at ") + when_name(w) + " +" + std::to_string(extra);
      SCOPED_TRACE(name);
      Bench b(300 + static_cast<unsigned>(w) * 5 + extra);
      configure(b, k);
      Background bg(b, k, 300 + static_cast<unsigned>(w) * 5 + extra);
      bg.service();
      b.idle(20);
      const int64_t start = b.m().pulse(k).position();
      ASSERT_TRUE(run_to(b, k, w, extra)) << "never reached " << when_name(w);
      b.push(k, trapezoid(20));  // queued behind: must be flushed
      write_now(b, R::STOP, 1u << k);
      uint64_t prev = ~0ull;  // the speed at the last stopping edge
      bool rising = false;
      b.idle(2 * kFrameCycles);  // the STOP acts in the axis's slot of the next frame
      const bool rest = b.run_until([&] {
        if (b.m().gen(k).stopping()) {
          rising |= b.m().gen(k).speed() > prev;
          prev = b.m().gen(k).speed();
        }
        return !b.m().busy(k) && !b.m().running(k);
      }, 400000);
      EXPECT_TRUE(rest) << "the stop never came to rest";
      EXPECT_FALSE(rising) << "speed rose while stopping";
      EXPECT_EQ(b.free_slots(k), 2u) << "queue flushed";
      // A stop never runs past the move's 120 steps.
      EXPECT_LE(std::llabs(b.m().pulse(k).position() - start), 120) << name;
      new_move_runs(b, k, name);
      bg.finish(name);
      EXPECT_EQ(b.problems(), "");
    }
}

TEST(Faults, StopCombinedWithAbort) {
  Bench b(77);
  configure(b, 2);
  Rises rs;
  rs.attach(b);
  Background bg(b, 2, 77);
  bg.service();
  // STOP, then ABORT while stopping: the abort wins at once.
  ASSERT_TRUE(run_to(b, 2, When::Cruise, 3));
  write_now(b, R::STOP, 1u << 2);
  ASSERT_TRUE(b.run_until([&] { return b.m().gen(2).stopping(); }, 200));
  b.idle(40);
  uint64_t stop_edge = abort_edge(b.cycle());
  write_now(b, R::ABORT, 1u << 2);
  b.idle(300);
  for (uint64_t c : rs.at[2]) EXPECT_LE(c, stop_edge) << "STEP rose after the abort";
  EXPECT_FALSE(b.m().busy(2));
  // ABORT and STOP on the same edge: abort.
  ASSERT_TRUE(run_to(b, 2, When::Accel, 2));
  write_now(b, R::STOP, 1u << 2);
  stop_edge = abort_edge(b.cycle());  // the ABORT right behind it: within the same frame
  write_now(b, R::ABORT, 1u << 2);
  b.idle(300);
  for (uint64_t c : rs.at[2]) EXPECT_LE(c, stop_edge) << "STEP rose after the abort";
  EXPECT_FALSE(b.m().busy(2));
  new_move_runs(b, 2, "after stop and abort");
  bg.finish("stop/abort");
  EXPECT_EQ(b.problems(), "");
}

// E-STOP while all six axes run chained moves, swept over the edges around the first chain
// boundary of axis 0 and inside the moves: no STEP rises from the fourth edge after the pin
// (2-flop synchronizer, latch, abort), every pulse already high completes, queues are flushed,
// ERR.estop is set on every axis, positions equal the steps pulsed; after the pin falls and the
// latch is cleared, a new chained sequence runs exactly.
TEST(Faults, EstopDuringChainedMoves) {
  auto load = [](Bench& b) {
    for (unsigned k = 0; k < kNumAxes; ++k) b.set_pulse(k, kPulses[k]);
    for (unsigned k = 0; k < kNumAxes; ++k) {
      b.push(k, trapezoid(40 + 4 * k, k % 2 == 0));
      b.push(k, cruise(30, 1ull << 61, k % 2 == 1));
    }
    b.write(R::START, kAllAxes);
  };
  // Where axis 0's second move starts (its time zero changes), in a run without E-STOP: the
  // same bus seed gives the same bus timing, so the same edges.
  uint64_t chain_edge = 0, first_edge = 0;
  {
    Bench b(21);
    uint64_t t0 = ~0ull;
    unsigned changes = 0;
    b.bus.on_edge = [&] {
      if (b.m().gen(0).run() && b.m().move_t0(0) != t0) {
        t0 = b.m().move_t0(0);
        (++changes == 1 ? first_edge : chain_edge) = b.cycle();
      }
    };
    load(b);
    ASSERT_TRUE(b.settle());
    ASSERT_EQ(changes, 2u);
    EXPECT_EQ(b.problems(), "");
  }
  std::vector<int64_t> offsets;
  for (int64_t d = -6; d <= 3; ++d) offsets.push_back(d);
  offsets.push_back(-int64_t(chain_edge - first_edge) / 2);  // inside the first moves
  offsets.push_back(400);                                     // inside the second moves
  for (int64_t off : offsets) {
    const std::string name = "E-STOP at chain boundary " + std::to_string(off);
    SCOPED_TRACE(name);
    Bench b(21);
    Rises rs;
    rs.attach(b);
    load(b);
    while (int64_t(b.cycle()) < int64_t(chain_edge) + off) b.idle(1);
    b.bus.set_estop(true);
    const uint64_t pin = b.cycle();  // the first cycle with the pin high
    b.idle(400);
    for (unsigned k = 0; k < kNumAxes; ++k)
      for (uint64_t c : rs.at[k]) EXPECT_LE(c, pin + 3) << "axis " << k << ": STEP rose after the e-stop abort";
    EXPECT_EQ(b.read(R::GSTATUS), R::GSTATUS_ESTOP_MASK | R::GSTATUS_ESTOP_PIN_MASK);
    for (unsigned k = 0; k < kNumAxes; ++k) {
      EXPECT_EQ(b.status(k), A::STATUS_RESET) << "axis " << k;
      EXPECT_NE(b.axr(k, A::ERR) & A::ERR_ESTOP_MASK, 0u) << "axis " << k;
      EXPECT_EQ(b.position(k), rs.pos[k]) << "axis " << k;
    }
    // Pushes and starts are dropped while latched.
    b.push(1, cruise(10, 1ull << 61));
    b.write(R::START, 2u);
    EXPECT_EQ(b.free_slots(1), 2u);
    b.bus.set_estop(false);
    b.idle(6);
    b.write(R::GSTATUS, R::GSTATUS_ESTOP_MASK);
    EXPECT_EQ(b.read(R::GSTATUS), 0u);
    for (unsigned k = 0; k < kNumAxes; ++k) b.axw(k, A::ERR, 0xFFFFFFFFu);
    std::array<int64_t, kNumAxes> p0{};
    for (unsigned k = 0; k < kNumAxes; ++k) p0[k] = b.position(k);
    for (unsigned k = 0; k < kNumAxes; ++k) {
      b.push(k, cruise(12, 1ull << 61, k % 2 == 1));
      b.push(k, trapezoid(40, k % 2 == 0));
    }
    b.write(R::START, kAllAxes);
    ASSERT_TRUE(b.settle());
    for (unsigned k = 0; k < kNumAxes; ++k) {
      const int64_t want = p0[k] + (k % 2 == 1 ? 12 : -12) + (k % 2 == 0 ? 40 : -40);
      EXPECT_EQ(b.position(k), want) << "axis " << k;
      EXPECT_EQ(b.axr(k, A::ERR), 0u) << "axis " << k;
    }
    EXPECT_EQ(b.problems(), "");
  }
}

// Direction reversal between chained moves: every move reverses, short and fast moves so that
// the DIR setup and hold windows (0 to 4095 cycles) are what limits the timing; the monitor
// checks them on every pin, the positions are the signed sums.
TEST(Faults, DirectionReversalBetweenChainedMoves) {
  const PulseConfig pcs[] = {{1, 1, 1, 1, false, false},   {2, 3, 60, 5, false, false}, {2, 3, 5, 60, true, true},
                             {1, 1, 200, 200, false, true}, {9, 1, 4095, 0, false, false}, {1, 9, 0, 4095, true, false}};
  for (unsigned variant = 0; variant < 3; ++variant) {
    SCOPED_TRACE("variant " + std::to_string(variant));
    Job job;
    std::array<int64_t, kNumAxes> expect{};
    for (unsigned a = 0; a < kNumAxes; ++a) {
      job.axes[a].pulse = pcs[(a + variant) % kNumAxes];
      for (unsigned i = 0; i < 8; ++i) {
        const bool dir = (i + a) % 2 == 0;
        const AxisMove m = (i + variant) % 3 == 0 ? cruise(1 + i % 3, ~0ull >> (1 + variant), dir)
                                                  : (i % 3 == 1 ? trapezoid(8 + i, dir) : cruise(2, 1ull << 62, dir));
        job.axes[a].moves.push_back(m);
        expect[a] += signed_steps(m);
      }
    }
    Bench b(400 + variant);
    RunOptions o;
    o.bus_seed = 400 + variant;
    o.bus_idle = 2;
    o.bus_wait = 2;
    const RunResult r = run_job(b.mon, job, [](const StepEvent&) {}, o);
    EXPECT_FALSE(r.timed_out);
    for (unsigned a = 0; a < kNumAxes; ++a) {
      EXPECT_EQ(r.position[a], expect[a]) << "axis " << a;
      EXPECT_EQ(r.refused[a], 0u);
    }
    EXPECT_EQ(b.problems(), "");
  }
}

// Queue overrun while the axis runs: the third push is dropped with ERR.overrun, the two queued
// moves run exactly, the other axes (running moves of their own) are untouched.
TEST(Faults, QueueOverrunDuringMotion) {
  Bench b(23);
  b.bus.set_timing(2, 1);
  const AxisMove a = cruise(200, 1ull << 60), m2 = trapezoid(50, false), m3 = cruise(30, 1ull << 61);
  std::array<int64_t, kNumAxes> expect{};
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (k == 4) continue;
    b.push(k, trapezoid(60 + k, k % 2 == 0));
    expect[k] = (k % 2 == 0 ? 1 : -1) * int64_t(60 + k);
  }
  b.push(4, a);
  b.write(R::START, kAllAxes);
  b.idle(50);
  b.push(4, m2);
  b.push(4, m3);
  EXPECT_EQ(b.free_slots(4), 0u);
  EXPECT_EQ(b.axr(4, A::ERR), 0u);
  b.push(4, cruise(7, 1ull << 62));  // full: dropped
  EXPECT_EQ(b.axr(4, A::ERR), A::ERR_OVERRUN_MASK);
  b.push(4, cruise(7, 1ull << 62));  // again
  EXPECT_EQ(b.free_slots(4), 0u);
  for (unsigned k = 0; k < kNumAxes; ++k)
    if (k != 4) EXPECT_EQ(b.axr(k, A::ERR), 0u) << "axis " << k;
  ASSERT_TRUE(b.settle());
  expect[4] = signed_steps(a) + signed_steps(m2) + signed_steps(m3);
  for (unsigned k = 0; k < kNumAxes; ++k) EXPECT_EQ(b.position(k), expect[k]) << "axis " << k;
  EXPECT_EQ(b.problems(), "");
}

// Every refusal rule through the bus, on a running system: a refused move is consumed at its
// start with ERR.move and done, never steps, and the move queued behind it runs at once; an
// accepted boundary case runs exactly its steps (jog and far too slow cases: it starts, then
// STOP or ABORT).
TEST(Faults, RefusalRulesRefuseCleanlyAndNeverHang) {
  for (uint32_t steps : {1u, 40u}) {
    Bench b(500 + steps);
    unsigned n = 0;
    for (unsigned k = 0; k < kNumAxes; ++k) b.set_pulse(k, kPulses[k]);
    AxisMove ok = trapezoid(steps, true);
    if (steps == 1) ok.acc_steps = ok.dec_step = 1;
    for (const RuleCase& rc : rule_cases(ok)) {
      const unsigned k = n++ % kNumAxes;
      const std::string name = rc.what + ", steps " + std::to_string(steps);
      SCOPED_TRACE(name);
      ASSERT_TRUE(b.run_until([&] { return !b.m().busy(k) && !b.m().running(k); }, 400000));
      b.axw(k, A::ERR, 0xFFFFFFFFu);
      const int64_t p0 = b.position(k);
      const uint64_t r0 = b.rises(k);
      const AxisMove after = cruise(3, 1ull << 62, p0 < 0);
      b.push(k, rc.m);
      b.push(k, after);
      b.write(R::START, 1u << k);
      b.idle(3 * kFrameCycles);
      const uint32_t err = b.axr(k, A::ERR);
      if (rc.bits != 0) {
        EXPECT_EQ(err & A::ERR_MOVE_MASK, A::ERR_MOVE_MASK) << "no ERR.move";
        ASSERT_TRUE(b.run_until([&] { return !b.m().busy(k) && !b.m().running(k); }, 400000)) << "hangs";
        EXPECT_EQ(b.position(k) - p0, signed_steps(after)) << "only the move behind it ran";
        EXPECT_EQ(b.rises(k) - r0, after.steps);
      } else if (rc.runs_long) {
        EXPECT_EQ(err & A::ERR_MOVE_MASK, 0u) << "refused";
        EXPECT_NE(b.status(k) & A::STATUS_BUSY_MASK, 0u) << "not running";
        b.write(R::ABORT, 1u << k);
        ASSERT_TRUE(b.run_until([&] { return !b.m().busy(k) && !b.m().running(k); }, 400000)) << "hangs";
        EXPECT_EQ(uint64_t(std::llabs(b.position(k) - p0)), b.rises(k) - r0);
      } else {
        EXPECT_EQ(err & A::ERR_MOVE_MASK, 0u) << "refused (validate_move " << validate_move(rc.m) << ")";
        ASSERT_TRUE(b.run_until([&] { return !b.m().busy(k) && !b.m().running(k); }, 400000)) << "never ends";
        EXPECT_EQ(b.position(k) - p0, signed_steps(rc.m) + signed_steps(after));
        EXPECT_EQ(b.rises(k) - r0, rc.m.steps + after.steps);
      }
    }
    EXPECT_EQ(b.problems(), "");
  }
}

// Bus writes to every register of every axis while axis 2 runs a move and the others run
// theirs: all ones, zero, random values under random byte enables. Staging words, CMD without
// the push bit, STATUS/POS (read only), ERR and IRQ_PENDING (write-1-to-clear), IRQ_ENABLE,
// START of running axes, ABORT with no lane selected, STOP with an empty mask: none may change
// a running move. The pulse timing and polarity registers are live by design, so they are
// rewritten with the value they hold.
TEST(Faults, BusWritesToEveryRegisterDuringMotion) {
  Bench b(24);
  b.bus.set_timing(1, 1);
  std::mt19937 rng(24);
  std::array<int64_t, kNumAxes> expect{};
  for (unsigned k = 0; k < kNumAxes; ++k) {
    const AxisMove m = cruise(300 + 20 * k, (1ull << 59) + (uint64_t(k) << 52), k % 2 == 0);
    b.push(k, m);
    expect[k] = signed_steps(m);
  }
  b.write(R::START, kAllAxes);
  const std::vector<uint32_t> pulse_regs = {A::STEP_HIGH, A::STEP_LOW, A::DIR_SETUP, A::DIR_HOLD, A::POLARITY};
  unsigned writes = 0;
  for (unsigned k = 0; k < kNumAxes; ++k)
    for (uint32_t reg : A::kAll) {
      const uint32_t adr = ax_reg(k, reg);
      b.pair.context = "writing 0x" + std::to_string(adr);
      if (std::find(pulse_regs.begin(), pulse_regs.end(), reg) != pulse_regs.end()) {
        b.write(adr, b.read(adr));
        ++writes;
        continue;
      }
      if (reg == A::CMD) {  // no command bit, and all bits with lane 0 disabled
        b.write(adr, 0);
        b.write(adr, 0xFFFFFFFFu, 0xE);
        writes += 2;
        continue;
      }
      for (uint32_t v : {0xFFFFFFFFu, 0u, static_cast<uint32_t>(rng())}) {
        b.write(adr, v, v == 0 || v == 0xFFFFFFFFu ? 0xFu : (rng() & 0xFu));
        ++writes;
      }
    }
  for (uint32_t adr : R::kAll) {
    b.pair.context = "writing global 0x" + std::to_string(adr);
    if (adr == R::START) {
      b.write(adr, 1u << 2);  // axis 2 is running: nothing to start
    } else if (adr == R::ABORT) {
      b.write(adr, kAllAxes, 0x0);  // no byte lane selected: no abort
    } else if (adr == R::STOP) {
      b.write(adr, 0);  // an empty axis mask
    } else {
      b.write(adr, 0xFFFFFFFFu);  // W1C of a latch that is not set, IRQs, read-only registers
      b.write(adr, 0);
    }
    writes += 2;
  }
  b.pair.context = "writing unmapped addresses";
  for (uint32_t adr : {0x080u, 0x0FCu, ax_reg(2, 0x7C), 0xFFCu}) b.write(adr, 0xFFFFFFFFu);
  writes += 4;
  b.pair.context.clear();
  ASSERT_TRUE(b.m().busy(2)) << "the writes outlasted the move; lengthen it";
  ASSERT_TRUE(b.settle());
  EXPECT_GT(writes, 400u);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_EQ(b.position(k), expect[k]) << "axis " << k;
    EXPECT_EQ(b.rises(k), static_cast<uint64_t>(std::llabs(expect[k]))) << "axis " << k;
  }
  EXPECT_EQ(b.problems(), "");
}

// A start in the frame in which the move before it lets go of the axis. A move starts at its
// sample only if the axis is not busy, and a chained move whose direction differs only once no
// step of the move before waits; with a long DIR setup the last thing that keeps the axis busy
// is the owed step of a reversing one-step move, so its rise (the output stage's pending flag
// falling) decides. The setup time is swept over 32 consecutive values, which moves that rise
// over every cycle of the frame, among them the edge just before the axis's sample: the start
// decision must take the flag after that edge, as the model does (the RTL registers the
// decision one edge early, from the stage's next flags). Two ways a move follows: chained
// behind the one-step move (queued with it), and started by START, written in every frame
// after the one-step move ended, where a START whose sample finds the axis busy is dropped.
TEST(Faults, StartSweptOverTheLastRiseOfTheMoveBefore) {
  const unsigned k = 3;
  for (bool chained : {true, false}) {
    std::array<bool, kFrameCycles> rise_at{};  // frame cycles of the one-step move's rise
    for (uint32_t setup = 800; setup < 800 + kFrameCycles; ++setup) {
      const std::string name = std::string(chained ? "chained" : "START") + ", dir_setup " + std::to_string(setup);
      SCOPED_TRACE(name);
      Bench b(11);
      b.set_pulse(k, PulseConfig{2, 2, setup, 0, false, false});
      bool prev = false;
      uint64_t first_rise = 0;
      b.bus.on_edge = [&] {
        const bool l = b.m().pulse(k).step_level();
        if (l && !prev && first_rise == 0) first_rise = b.cycle();
        prev = l;
      };
      const bool dir = !b.m().pulse(k).dir_level();  // reversing: the step waits for the setup
      const AxisMove one = cruise(1, 1ull << 62, dir), next = cruise(3, 1ull << 62, !dir);
      b.push(k, one);
      if (chained) b.push(k, next);
      b.write(R::START, 1u << k);
      ASSERT_TRUE(b.run_until([&] { return b.m().running(k); }, 200)) << "the one-step move never started";
      if (!chained) {
        // The one-step move ends (its generator) with its step still waiting for the setup.
        ASSERT_TRUE(b.run_until([&] { return b.m().gen(k).steps_done() == 1 && !b.m().running(k); }, 2000));
        ASSERT_TRUE(b.m().pulse(k).pending()) << "the step rose before the move ended";
        b.push(k, next);
        ASSERT_TRUE(b.m().pulse(k).pending()) << "the step rose before the push";
        for (unsigned i = 0; i < 400 && !b.m().running(k); ++i) b.write(R::START, 1u << k);
        ASSERT_TRUE(b.m().running(k)) << "the second move never started";
      }
      ASSERT_TRUE(b.run_until([&] { return !b.m().busy(k) && !b.m().running(k); }, 20000));
      ASSERT_NE(first_rise, 0u);
      rise_at[first_rise % kFrameCycles] = true;
      EXPECT_EQ(b.position(k), signed_steps(one) + signed_steps(next));
      EXPECT_EQ(b.rises(k), one.steps + next.steps);
      EXPECT_EQ(b.problems(), "");
    }
    // The sweep put the rise on every cycle of the frame.
    for (unsigned c = 0; c < kFrameCycles; ++c) EXPECT_TRUE(rise_at[c]) << (chained ? "chained" : "START") << ": no rise at frame cycle " << c;
  }
}
