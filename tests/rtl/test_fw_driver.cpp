// SPDX-License-Identifier: Apache-2.0
// Firmware driver (firmware/hexstep_drv.c, compiled as C) on the Verilated hexstep_top: the
// driver's register accessors call the Wishbone BFM (sim/wb_bfm.hpp). Moves come from a header
// that the built CLI writes at build time (`hexstep plan --format c`, tests/rtl/fw_plan_request.json);
// the STEP rising edges are compared, cycle by cycle, with the golden model run on the same moves
// (hexstep::run_job on hexstep::CoreModel).
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "hexstep/core.hpp"
#include "hexstep/job.hpp"
#include "hexstep/wb_model.hpp"
#include "hexstep_drv.h"
#include "hexstep_fw_plan.h"  // generated: hexstep plan --format c
#include "hexstep_regs.hpp"
#include "vectors.hpp"
#include "wb_bfm.hpp"

using namespace hexstep;
namespace R = hexstep::regs;

// ---- the plan header's structs are the driver's, field for field ----
static_assert(sizeof(hexstep_move_t) == sizeof(hexstep_plan_move_t), "move struct size");
static_assert(alignof(hexstep_move_t) == alignof(hexstep_plan_move_t), "move struct alignment");
#define SAME_FIELD(A, B, f)                                                                  \
  static_assert(offsetof(A, f) == offsetof(B, f), "offset of " #f);                         \
  static_assert(std::is_same<decltype(A::f), decltype(B::f)>::value, "type of " #f)
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, steps);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, dir);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, v_start);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, v_max);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, v_end);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, acc);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, dec);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, v_dec);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, acc_steps);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, dec_step);
SAME_FIELD(hexstep_move_t, hexstep_plan_move_t, dec_frac);
static_assert(sizeof(hexstep_pulse_t) == sizeof(hexstep_plan_pulse_t), "pulse struct size");
SAME_FIELD(hexstep_pulse_t, hexstep_plan_pulse_t, step_high);
SAME_FIELD(hexstep_pulse_t, hexstep_plan_pulse_t, step_low);
SAME_FIELD(hexstep_pulse_t, hexstep_plan_pulse_t, dir_setup);
SAME_FIELD(hexstep_pulse_t, hexstep_plan_pulse_t, dir_hold);
SAME_FIELD(hexstep_pulse_t, hexstep_plan_pulse_t, step_invert);
SAME_FIELD(hexstep_pulse_t, hexstep_plan_pulse_t, dir_invert);
#undef SAME_FIELD
static_assert(HEXSTEP_PLAN_NUM_AXES == HEXSTEP_NUM_AXES, "axes");
static_assert(HEXSTEP_NUM_AXES == kNumAxes, "driver and model disagree on the number of axes");

namespace {

constexpr uint32_t kPlanMask = HEXSTEP_PLAN_AXIS_MASK;
static_assert(kPlanMask == 0x09u, "fw_plan_request.json plans axes 0 and 3");

// The BFM behind the driver's accessors, recording STEP rising edges (RTL cycle count after the
// edge) and the cycle count at the ack of the last START write.
struct Board {
  explicit Board(uint32_t seed = 1) : bus(seed) {
    bus.on_edge = [this] {
      for (unsigned k = 0; k < kNumAxes; ++k) {
        const bool s = bus.step(k);
        if (s && !prev[k]) rises[k].push_back(bus.cycles());
        prev[k] = s;
      }
    };
    EXPECT_EQ(hexstep_init(&dev, 0, &Board::rd, &Board::wr, this), HEXSTEP_OK);
  }
  static uint32_t rd(void* ctx, uint32_t off) { return static_cast<Board*>(ctx)->bus.read(off); }
  static void wr(void* ctx, uint32_t off, uint32_t v) {
    auto* b = static_cast<Board*>(ctx);
    b->bus.write(off, v);
    if (off == R::START) b->start_ack = b->bus.cycles();
  }
  void ticks(unsigned n) {
    for (unsigned i = 0; i < n; ++i) bus.tick();
  }
  WbTop bus;
  hexstep_dev_t dev{};
  uint64_t start_ack = 0;
  std::array<std::vector<uint64_t>, kNumAxes> rises;
  std::array<bool, kNumAxes> prev{};
};

const hexstep_move_t* plan_move(unsigned k) {
  return reinterpret_cast<const hexstep_move_t*>(&hexstep_plan_moves[k]);
}
const hexstep_pulse_t* plan_pulse(unsigned k) {
  return reinterpret_cast<const hexstep_pulse_t*>(&hexstep_plan_pulse[k]);
}
AxisMove to_model(const hexstep_plan_move_t& m) {
  AxisMove a;
  a.steps = m.steps;
  a.dir = m.dir != 0;
  a.v_start = m.v_start;
  a.v_max = m.v_max;
  a.v_end = m.v_end;
  a.acc = m.acc;
  a.dec = m.dec;
  a.v_dec = m.v_dec;
  a.acc_steps = m.acc_steps;
  a.dec_step = m.dec_step;
  a.dec_frac = m.dec_frac;
  return a;
}
PulseConfig to_model(const hexstep_plan_pulse_t& p) {
  PulseConfig c;
  c.step_high = p.step_high;
  c.step_low = p.step_low;
  c.dir_setup = p.dir_setup;
  c.dir_hold = p.dir_hold;
  c.step_invert = p.step_invert != 0;
  c.dir_invert = p.dir_invert != 0;
  return c;
}
int64_t planned_total(unsigned k) {
  const auto& m = hexstep_plan_moves[k];
  return m.dir ? static_cast<int64_t>(m.steps) : -static_cast<int64_t>(m.steps);
}

hexstep_move_t to_fw(const AxisMove& a) {
  hexstep_move_t m{};
  m.steps = a.steps;
  m.dir = (a.dir ? 1u : 0u) | (a.jog ? HEXSTEP_MOVE_JOG : 0u);
  m.v_start = a.v_start;
  m.v_max = a.v_max;
  m.v_end = a.v_end;
  m.acc = a.acc;
  m.dec = a.dec;
  m.v_dec = a.v_dec;
  m.acc_steps = a.acc_steps;
  m.dec_step = a.dec_step;
  m.dec_frac = a.dec_frac;
  return m;
}

// A long constant-speed move (1/16 step per cycle) for the abort and e-stop tests.
hexstep_move_t slow_cruise(uint32_t steps, bool positive) {
  hexstep_move_t m{};
  m.steps = steps;
  m.dir = positive ? 1u : 0u;
  m.v_start = m.v_max = m.v_end = m.v_dec = 1ull << 60;
  m.dec_step = steps;
  return m;
}

}  // namespace

TEST(FwDriver, InitChecksIdentity) {
  Board b;
  hexstep_dev_t d{};
  EXPECT_EQ(hexstep_init(&d, 0, &Board::rd, &Board::wr, &b), HEXSTEP_OK);
  auto zero = [](void*, uint32_t) -> uint32_t { return 0; };
  auto sink = [](void*, uint32_t, uint32_t) {};
  EXPECT_EQ(hexstep_init(&d, 0, zero, sink, nullptr), HEXSTEP_ERR_NODEV);
  EXPECT_EQ(hexstep_init(nullptr, 0, zero, sink, nullptr), HEXSTEP_ERR_ARG);
  EXPECT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  EXPECT_EQ(hexstep_start(&b.dev, 0x40u), HEXSTEP_ERR_ARG);
  EXPECT_EQ(hexstep_queue_move(&b.dev, 6, plan_move(0)), HEXSTEP_ERR_ARG);
  hexstep_pulse_t p = *plan_pulse(0);
  p.step_high = 4096;
  EXPECT_EQ(hexstep_set_pulse(&b.dev, 0, &p), HEXSTEP_ERR_RANGE);
  hexstep_move_t m = *plan_move(0);
  m.acc = 1ull << 44;
  EXPECT_EQ(hexstep_load_move(&b.dev, 0, &m), HEXSTEP_ERR_RANGE);
  EXPECT_EQ(b.bus.protocol_errors(), 0u);
}

// The planned moves on axes 0 and 3: queue, start both, wait; positions are the planned signed
// totals and every STEP rising edge is at the golden model's cycle.
TEST(FwDriver, PlannedMovesMatchGoldenModel) {
  Board b(7);
  b.bus.set_timing(2, 2);  // random idle/wait cycles between the driver's accesses
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  ASSERT_EQ(hexstep_irq_enable(&b.dev, HEXSTEP_IRQ_DONE(kPlanMask)), HEXSTEP_OK);

  Job job;
  job.clock_hz = HEXSTEP_PLAN_CLOCK_HZ;
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (!((kPlanMask >> k) & 1u)) continue;
    ASSERT_EQ(hexstep_set_pulse(&b.dev, k, plan_pulse(k)), HEXSTEP_OK);
    ASSERT_EQ(hexstep_queue_move(&b.dev, k, plan_move(k)), HEXSTEP_OK);
    unsigned free_slots = 9;
    ASSERT_EQ(hexstep_queue_free(&b.dev, k, &free_slots), HEXSTEP_OK);
    EXPECT_EQ(free_slots, 1u);
    job.axes[k].pulse = to_model(hexstep_plan_pulse[k]);
    job.axes[k].moves.push_back(to_model(hexstep_plan_moves[k]));
  }
  for (auto& r : b.rises) r.clear();  // pulse writes may move a pin; count from the start only

  ASSERT_EQ(hexstep_start(&b.dev, kPlanMask), HEXSTEP_OK);
  const uint64_t ack = b.start_ack;
  uint32_t busy = 0;
  ASSERT_EQ(hexstep_busy(&b.dev, kPlanMask, &busy), HEXSTEP_OK);
  EXPECT_EQ(busy, kPlanMask) << "a poll right after hexstep_start sees the axes running";
  ASSERT_EQ(hexstep_wait(&b.dev, kPlanMask, 1000000u), HEXSTEP_OK);
  EXPECT_TRUE(hexstep_done(&b.dev, HEXSTEP_ALL_AXES));

  CoreModel model;
  std::array<std::vector<uint64_t>, kNumAxes> golden;
  const RunResult rr = run_job(model, job, [&](const StepEvent& e) { golden[e.axis].push_back(e.cycle); });
  ASSERT_FALSE(rr.timed_out);

  for (unsigned k = 0; k < kNumAxes; ++k) {
    int64_t pos = 12345;
    ASSERT_EQ(hexstep_read_position(&b.dev, k, &pos), HEXSTEP_OK);
    const bool planned = (kPlanMask >> k) & 1u;
    EXPECT_EQ(pos, planned ? planned_total(k) : 0) << "axis " << k;
    EXPECT_EQ(pos, rr.position[k]) << "axis " << k;
    uint32_t err = 9;
    ASSERT_EQ(hexstep_read_errors(&b.dev, k, &err), HEXSTEP_OK);
    EXPECT_EQ(err, 0u) << "axis " << k;
    ASSERT_EQ(b.rises[k].size(), golden[k].size()) << "axis " << k;
    if (planned) {
      EXPECT_EQ(b.rises[k].size(), hexstep_plan_moves[k].steps);
    }
    // Exact alignment. The START write's ack is raised at one edge; the strobe acts at the next
    // edge, which is also the edge at which the BFM master samples the ack and ends the write
    // (sim/wb_bfm.cpp transfer()), so the RTL cycle counter when the driver's write accessor
    // returns (`ack`) is that of the strobe edge. run_job counts the strobe edge as cycle 0 and
    // the STEP pin shows a model edge after the same RTL edge (as in test_wb's Ref): a rise
    // seen after RTL edge `ack + c` is the model's rise at cycle c.
    size_t bad = 0;
    for (size_t i = 0; i < b.rises[k].size(); ++i) {
      const uint64_t rel = b.rises[k][i] - ack;
      if (rel != golden[k][i] && bad++ < 5)
        ADD_FAILURE() << "axis " << k << " step " << i + 1 << ": rtl cycle " << rel << ", model " << golden[k][i];
    }
    EXPECT_EQ(bad, 0u) << "axis " << k;
  }

  uint32_t pend = 0;
  ASSERT_EQ(hexstep_irq_pending(&b.dev, &pend), HEXSTEP_OK);
  EXPECT_EQ(pend & HEXSTEP_IRQ_DONE(HEXSTEP_ALL_AXES), HEXSTEP_IRQ_DONE(kPlanMask));
  EXPECT_EQ(pend & HEXSTEP_IRQ_SLOT(HEXSTEP_ALL_AXES), HEXSTEP_IRQ_SLOT(kPlanMask));
  EXPECT_TRUE(b.bus.irq());
  ASSERT_EQ(hexstep_irq_clear(&b.dev, HEXSTEP_IRQ_ALL), HEXSTEP_OK);
  ASSERT_EQ(hexstep_irq_pending(&b.dev, &pend), HEXSTEP_OK);
  EXPECT_EQ(pend, 0u);
  b.ticks(2);
  EXPECT_FALSE(b.bus.irq());
  uint32_t en = 0;
  ASSERT_EQ(hexstep_irq_enabled(&b.dev, &en), HEXSTEP_OK);
  EXPECT_EQ(en, HEXSTEP_IRQ_DONE(kPlanMask));
  EXPECT_EQ(b.bus.protocol_errors(), 0u);
}

TEST(FwDriver, QueueFullReturnsError) {
  Board b;
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  EXPECT_EQ(hexstep_queue_move(&b.dev, 0, plan_move(0)), HEXSTEP_OK);
  EXPECT_EQ(hexstep_queue_move(&b.dev, 0, plan_move(0)), HEXSTEP_OK);
  EXPECT_EQ(hexstep_queue_move(&b.dev, 0, plan_move(0)), HEXSTEP_ERR_QUEUE_FULL);
  EXPECT_EQ(hexstep_push(&b.dev, 0), HEXSTEP_ERR_QUEUE_FULL);
  unsigned n = 9;
  ASSERT_EQ(hexstep_queue_free(&b.dev, 0, &n), HEXSTEP_OK);
  EXPECT_EQ(n, 0u);
  uint32_t err = 9;
  ASSERT_EQ(hexstep_read_errors(&b.dev, 0, &err), HEXSTEP_OK);
  EXPECT_EQ(err, 0u) << "the driver refused the push itself: no hardware overrun";
  // Other axes are unaffected.
  EXPECT_EQ(hexstep_queue_move(&b.dev, 1, plan_move(0)), HEXSTEP_OK);

  // Two queued moves run back to back; a slot frees when the first starts.
  ASSERT_EQ(hexstep_start(&b.dev, 0x1u), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_free(&b.dev, 0, &n), HEXSTEP_OK);
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(hexstep_wait(&b.dev, 0x1u, 5u), HEXSTEP_ERR_TIMEOUT);
  ASSERT_EQ(hexstep_wait(&b.dev, 0x1u, 1000000u), HEXSTEP_OK);
  int64_t pos = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 0, &pos), HEXSTEP_OK);
  EXPECT_EQ(pos, 2 * planned_total(0));
  EXPECT_EQ(b.rises[0].size(), 2u * hexstep_plan_moves[0].steps);
  ASSERT_EQ(hexstep_read_position(&b.dev, 1, &pos), HEXSTEP_OK);
  EXPECT_EQ(pos, 0) << "axis 1 was queued but not started";
  EXPECT_EQ(b.bus.protocol_errors(), 0u);
}

TEST(FwDriver, AbortStopsAndFlushes) {
  Board b;
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  const hexstep_move_t fwd = slow_cruise(1000, true), back = slow_cruise(1000, false);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 2, &back), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 2, &fwd), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 4, &fwd), HEXSTEP_OK);
  ASSERT_EQ(hexstep_start(&b.dev, 0x14u), HEXSTEP_OK);
  b.ticks(1600);  // ~100 steps at 1/16 step per cycle
  uint32_t busy = 0;
  ASSERT_EQ(hexstep_busy(&b.dev, HEXSTEP_ALL_AXES, &busy), HEXSTEP_OK);
  EXPECT_EQ(busy, 0x14u);
  ASSERT_EQ(hexstep_abort(&b.dev, 0x4u), HEXSTEP_OK);
  EXPECT_TRUE(hexstep_done(&b.dev, 0x4u));
  unsigned n = 0;
  ASSERT_EQ(hexstep_queue_free(&b.dev, 2, &n), HEXSTEP_OK);
  EXPECT_EQ(n, 2u) << "abort flushes the queue";
  int64_t p2 = 0, p2_later = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 2, &p2), HEXSTEP_OK);
  EXPECT_LT(p2, -50);
  EXPECT_GT(p2, -1000);
  const size_t rises = b.rises[2].size();
  b.ticks(2000);
  ASSERT_EQ(hexstep_read_position(&b.dev, 2, &p2_later), HEXSTEP_OK);
  EXPECT_EQ(p2_later, p2);
  EXPECT_EQ(b.rises[2].size(), rises) << "no STEP edge after the abort";
  EXPECT_EQ(static_cast<int64_t>(rises), -p2);
  // Axis 4 ran on.
  ASSERT_EQ(hexstep_wait(&b.dev, 0x10u, 1000000u), HEXSTEP_OK);
  int64_t p4 = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 4, &p4), HEXSTEP_OK);
  EXPECT_EQ(p4, 1000);
  EXPECT_EQ(b.bus.protocol_errors(), 0u);
}

TEST(FwDriver, EstopFlagsAndClear) {
  Board b;
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  ASSERT_EQ(hexstep_irq_enable(&b.dev, HEXSTEP_IRQ_ERR(0x1u)), HEXSTEP_OK);
  const hexstep_move_t fwd = slow_cruise(1000, true);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 0, &fwd), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 0, &fwd), HEXSTEP_OK);
  ASSERT_EQ(hexstep_start(&b.dev, 0x1u), HEXSTEP_OK);
  b.ticks(800);
  bool latched = true, pin = true;
  ASSERT_EQ(hexstep_estop_status(&b.dev, &latched, &pin), HEXSTEP_OK);
  EXPECT_FALSE(latched);
  EXPECT_FALSE(pin);

  b.bus.set_estop(true);
  b.ticks(5);
  ASSERT_EQ(hexstep_estop_status(&b.dev, &latched, &pin), HEXSTEP_OK);
  EXPECT_TRUE(latched);
  EXPECT_TRUE(pin);
  EXPECT_EQ(hexstep_wait(&b.dev, 0x1u, 100u), HEXSTEP_ERR_ESTOP) << "e-stop stops the axis";
  unsigned n = 0;
  ASSERT_EQ(hexstep_queue_free(&b.dev, 0, &n), HEXSTEP_OK);
  EXPECT_EQ(n, 2u) << "e-stop flushes the queue";
  int64_t pos = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 0, &pos), HEXSTEP_OK);
  EXPECT_GT(pos, 0);
  EXPECT_LT(pos, 1000);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    uint32_t err = 0;
    ASSERT_EQ(hexstep_read_errors(&b.dev, k, &err), HEXSTEP_OK);
    EXPECT_EQ(err, HEXSTEP_AXERR_ESTOP) << "axis " << k;
  }
  uint32_t pend = 0;
  ASSERT_EQ(hexstep_irq_pending(&b.dev, &pend), HEXSTEP_OK);
  EXPECT_EQ(pend & HEXSTEP_IRQ_ERR(HEXSTEP_ALL_AXES), HEXSTEP_IRQ_ERR(HEXSTEP_ALL_AXES));
  EXPECT_TRUE(b.bus.irq());
  EXPECT_EQ(hexstep_queue_move(&b.dev, 0, &fwd), HEXSTEP_ERR_ESTOP);
  EXPECT_EQ(hexstep_push(&b.dev, 1), HEXSTEP_ERR_ESTOP);
  EXPECT_EQ(hexstep_start(&b.dev, 0x1u), HEXSTEP_ERR_ESTOP);
  EXPECT_EQ(hexstep_estop_clear(&b.dev), HEXSTEP_ERR_ESTOP) << "pin still high";

  b.bus.set_estop(false);
  b.ticks(5);
  EXPECT_EQ(hexstep_estop_clear(&b.dev), HEXSTEP_OK);
  ASSERT_EQ(hexstep_estop_status(&b.dev, &latched, &pin), HEXSTEP_OK);
  EXPECT_FALSE(latched);
  EXPECT_FALSE(pin);
  for (unsigned k = 0; k < kNumAxes; ++k) ASSERT_EQ(hexstep_clear_errors(&b.dev, k, HEXSTEP_AXERR_ALL), HEXSTEP_OK);
  ASSERT_EQ(hexstep_irq_clear(&b.dev, HEXSTEP_IRQ_ALL), HEXSTEP_OK);
  uint32_t err = 9;
  ASSERT_EQ(hexstep_read_errors(&b.dev, 0, &err), HEXSTEP_OK);
  EXPECT_EQ(err, 0u);

  // Usable again: a move from where the e-stop left the axis.
  ASSERT_EQ(hexstep_queue_move(&b.dev, 0, plan_move(0)), HEXSTEP_OK);
  ASSERT_EQ(hexstep_start(&b.dev, 0x1u), HEXSTEP_OK);
  ASSERT_EQ(hexstep_wait(&b.dev, 0x1u, 1000000u), HEXSTEP_OK);
  int64_t pos2 = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 0, &pos2), HEXSTEP_OK);
  EXPECT_EQ(pos2, pos + planned_total(0));
  EXPECT_EQ(b.bus.protocol_errors(), 0u);
}

// hexstep_stop on a planned move and on a jog move: both come to rest short of / without an
// end, the queued move behind the first never starts, and every position and STEP edge equals
// the register-block model (hexstep::WbModel) fed the same bus cycles.
TEST(FwDriver, StopAndJog) {
  Board b(3);
  WbModel model;
  uint64_t pin_mismatches = 0;
  b.bus.pre_edge = [&](const WbPins& p) { model.tick(p); };
  auto record = b.bus.on_edge;
  b.bus.on_edge = [&] {
    record();
    for (unsigned k = 0; k < kNumAxes; ++k)
      pin_mismatches += b.bus.step(k) != model.step(k) || b.bus.dir(k) != model.dir(k);
  };
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  // Axis 1: a 4,000-step move, 0 -> 1 M steps/s at 1e9 steps/s^2 (500 steps of ramp), plus a
  // second move queued behind it. Axis 5: a negative jog to 2 M steps/s.
  hexstep_move_t mv = to_fw(test::encode({4000, true, 0, 1e6, 0, 1e9, 1e9}).regs);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 1, &mv), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 1, &mv), HEXSTEP_OK);
  hexstep_move_t jog{};
  const real clk = real(kDefaultClockHz);
  ASSERT_TRUE(speed_to_reg(2e6, clk, jog.v_max));
  ASSERT_TRUE(accel_to_reg(2e9, clk, jog.acc));
  ASSERT_TRUE(accel_to_reg(4e9, clk, jog.dec));
  jog.dir = HEXSTEP_MOVE_JOG;  // negative, jog
  ASSERT_EQ(hexstep_queue_move(&b.dev, 5, &jog), HEXSTEP_OK);
  ASSERT_EQ(hexstep_start(&b.dev, 0x22u), HEXSTEP_OK);
  b.ticks(150000);  // 1.5 ms: axis 1 cruising at step ~1,000; the jog at full speed
  ASSERT_EQ(hexstep_stop(&b.dev, 0x22u), HEXSTEP_OK);
  ASSERT_EQ(hexstep_wait(&b.dev, 0x22u, 1000000u), HEXSTEP_OK);
  int64_t p1 = 0, p5 = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 1, &p1), HEXSTEP_OK);
  ASSERT_EQ(hexstep_read_position(&b.dev, 5, &p5), HEXSTEP_OK);
  EXPECT_EQ(p1, model.core().axis(1).position());
  EXPECT_EQ(p5, model.core().axis(5).position());
  // Kinematics: axis 1 stops from 1 M steps/s at 1e9 steps/s^2 (+500 steps) after ~1,000
  // steps; the jog reached 2 M steps/s after 1 ms (1,000 steps), ran 0.5 ms (1,000 steps) and
  // stops at 4e9 steps/s^2 (+500 steps).
  EXPECT_NEAR(double(p1), 1000.0 + 500.0, 20.0);
  EXPECT_LT(p1, 4000) << "the second queued move never started";
  EXPECT_NEAR(double(p5), -2500.0, 20.0);
  EXPECT_EQ(static_cast<int64_t>(b.rises[1].size()), p1);
  EXPECT_EQ(static_cast<int64_t>(b.rises[5].size()), -p5);
  unsigned n = 0;
  ASSERT_EQ(hexstep_queue_free(&b.dev, 1, &n), HEXSTEP_OK);
  EXPECT_EQ(n, 2u) << "STOP flushes the queue";
  EXPECT_EQ(pin_mismatches, 0u);
  EXPECT_EQ(hexstep_stop(&b.dev, 0x40u), HEXSTEP_ERR_ARG);
  EXPECT_EQ(b.bus.protocol_errors(), 0u);
}
