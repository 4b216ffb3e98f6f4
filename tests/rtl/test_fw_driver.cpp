// SPDX-License-Identifier: Apache-2.0
// Firmware driver (firmware/hexstep_drv.c, compiled as C) on the Verilated hexstep_top beside
// TopModel in lock step (tests/common/bench.hpp: every output after every edge): the driver's
// register accessors are the bench's Wishbone master. Moves come from a header that the built
// CLI writes at build time (`hexstep plan --format c`, tests/rtl/fw_plan_request.json); every
// STEP rising edge of the planned moves is also compared with the one-axis frame runner
// (tests/common/axis_run), relative to the frame the driver's START took effect in.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "axis_run.hpp"
#include "bench.hpp"
#include "hexstep_drv.h"
#include "hexstep_fw_plan.h"  // generated: hexstep plan --format c
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;
namespace R = hexstep::regs;

// ---- the plan header's structs are the driver's, field for field ----
static_assert(sizeof(hexstep_move_t) == sizeof(hexstep_plan_move_t), "move struct size");
static_assert(alignof(hexstep_move_t) == alignof(hexstep_plan_move_t), "move struct alignment");
#define SAME_FIELD(A, B, f)                                                  \
  static_assert(offsetof(A, f) == offsetof(B, f), "offset of " #f);         \
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

// The bench behind the driver's accessors; STEP rising edges (first high cycle) per axis and
// the request cycle of the last START write.
struct Board {
  explicit Board(uint32_t seed = 1) : b(seed) {
    b.bus.on_edge = [this] {
      for (unsigned k = 0; k < kNumAxes; ++k) {
        const bool s = b.m().pulse(k).step_level();
        if (s && !prev[k]) rises[k].push_back(b.cycle());
        prev[k] = s;
      }
    };
    EXPECT_EQ(hexstep_init(&dev, 0, &Board::rd, &Board::wr, this), HEXSTEP_OK);
  }
  static uint32_t rd(void* ctx, uint32_t off) { return static_cast<Board*>(ctx)->b.bus.read(off); }
  static void wr(void* ctx, uint32_t off, uint32_t v) {
    auto* p = static_cast<Board*>(ctx);
    p->b.bus.write(off, v);
    if (off == R::START) p->start_request = p->b.bus.last_request_cycle();
  }
  void ticks(unsigned n) { b.idle(n); }
  Bench b;
  hexstep_dev_t dev{};
  uint64_t start_request = 0;
  std::array<std::vector<uint64_t>, kNumAxes> rises;
  std::array<bool, kNumAxes> prev{};
};

const hexstep_move_t* plan_move(unsigned k) { return reinterpret_cast<const hexstep_move_t*>(&hexstep_plan_moves[k]); }
const hexstep_pulse_t* plan_pulse(unsigned k) {
  return reinterpret_cast<const hexstep_pulse_t*>(&hexstep_plan_pulse[k]);
}
AxisMove to_model(const hexstep_plan_move_t& m) {
  AxisMove a;
  a.steps = m.steps;
  a.dir = (m.dir & 1u) != 0;
  a.jog = (m.dir & HEXSTEP_MOVE_JOG) != 0;
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
  return (m.dir & 1u) ? static_cast<int64_t>(m.steps) : -static_cast<int64_t>(m.steps);
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
// A constant-speed move at 1/16 step per tick (512 cycles per step).
hexstep_move_t slow_cruise(uint32_t steps, bool positive) { return to_fw(cruise(steps, 1ull << 60, positive)); }

}  // namespace

TEST(FwDriver, InitChecksIdentityAndReadsTheBuild) {
  Board b;
  hexstep_dev_t d{};
  EXPECT_EQ(hexstep_init(&d, 0, &Board::rd, &Board::wr, &b), HEXSTEP_OK);
  auto zero = [](void*, uint32_t) -> uint32_t { return 0; };
  auto sink = [](void*, uint32_t, uint32_t) {};
  EXPECT_EQ(hexstep_init(&d, 0, zero, sink, nullptr), HEXSTEP_ERR_NODEV);
  EXPECT_EQ(hexstep_init(nullptr, 0, zero, sink, nullptr), HEXSTEP_ERR_ARG);
  hexstep_info_t info{};
  ASSERT_EQ(hexstep_read_info(&b.dev, &info), HEXSTEP_OK);
  const Widths w = RtlTop::rtl_widths();
  EXPECT_EQ(info.naxes, RtlTop::rtl_naxes());
  EXPECT_EQ(info.speed_w, w.speed_frac);
  EXPECT_EQ(info.acc_w, w.acc);
  EXPECT_EQ(info.step_w, w.steps);
  EXPECT_EQ(info.dfrac_w, w.dec_frac);
  EXPECT_EQ(info.pulse_w, w.pulse);
  EXPECT_EQ(info.pos_w, w.pos);
  EXPECT_EQ(info.frame_log2, kFrameLog2);
  EXPECT_EQ(info.slots, kSlots);
  EXPECT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  EXPECT_EQ(hexstep_start(&b.dev, 0x40u), HEXSTEP_ERR_ARG);
  EXPECT_EQ(hexstep_queue_move(&b.dev, 6, plan_move(0)), HEXSTEP_ERR_ARG);
  hexstep_pulse_t p = *plan_pulse(0);
  p.step_high = 4096;
  EXPECT_EQ(hexstep_set_pulse(&b.dev, 0, &p), HEXSTEP_ERR_RANGE);
  hexstep_move_t m = *plan_move(0);
  m.acc = 1ull << 48;  // ACC_W = 48
  EXPECT_EQ(hexstep_load_move(&b.dev, 0, &m), HEXSTEP_ERR_RANGE);
  EXPECT_EQ(b.b.problems(), "");
}

// The planned moves on axes 0 and 3: queue, start both, wait; positions are the planned signed
// totals, and every STEP rising edge is where the frame runner puts it for the same move,
// relative to the frame after START's frame boundary.
TEST(FwDriver, PlannedMovesMatchTheModel) {
  Board b(7);
  b.b.bus.set_timing(2, 2);  // random idle/wait cycles between the driver's accesses
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  ASSERT_EQ(hexstep_irq_enable(&b.dev, HEXSTEP_IRQ_DONE(kPlanMask)), HEXSTEP_OK);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (!((kPlanMask >> k) & 1u)) continue;
    ASSERT_EQ(hexstep_set_pulse(&b.dev, k, plan_pulse(k)), HEXSTEP_OK);
    ASSERT_EQ(hexstep_queue_move(&b.dev, k, plan_move(k)), HEXSTEP_OK);
    unsigned free_slots = 9;
    ASSERT_EQ(hexstep_queue_free(&b.dev, k, &free_slots), HEXSTEP_OK);
    EXPECT_EQ(free_slots, 1u);
  }
  for (auto& r : b.rises) r.clear();
  ASSERT_EQ(hexstep_start(&b.dev, kPlanMask), HEXSTEP_OK);
  const uint64_t f0 = start_frame(b.start_request);
  uint32_t busy = 0;
  ASSERT_EQ(hexstep_busy(&b.dev, kPlanMask, &busy), HEXSTEP_OK);
  EXPECT_EQ(busy, kPlanMask) << "a poll right after hexstep_start sees the axes running";
  ASSERT_EQ(hexstep_wait(&b.dev, kPlanMask, 1000000u), HEXSTEP_OK);
  EXPECT_TRUE(hexstep_done(&b.dev, HEXSTEP_ALL_AXES));
  for (unsigned k = 0; k < kNumAxes; ++k) {
    int64_t pos = 12345;
    ASSERT_EQ(hexstep_read_position(&b.dev, k, &pos), HEXSTEP_OK);
    const bool planned = (kPlanMask >> k) & 1u;
    EXPECT_EQ(pos, planned ? planned_total(k) : 0) << "axis " << k;
    uint32_t err = 9;
    ASSERT_EQ(hexstep_read_errors(&b.dev, k, &err), HEXSTEP_OK);
    EXPECT_EQ(err, 0u) << "axis " << k;
    if (!planned) {
      EXPECT_TRUE(b.rises[k].empty()) << "axis " << k;
      continue;
    }
    AxisRunOptions o;
    o.axis = k;
    o.pulse = to_model(hexstep_plan_pulse[k]);
    const AxisRun run = run_axis(to_model(hexstep_plan_moves[k]), o);
    ASSERT_EQ(b.rises[k].size(), hexstep_plan_moves[k].steps) << "axis " << k;
    ASSERT_EQ(run.rises.size(), b.rises[k].size()) << "axis " << k;
    size_t bad = 0;
    for (size_t i = 0; i < run.rises.size(); ++i)
      if (b.rises[k][i] - f0 != run.rises[i].cycle && bad++ < 5)
        ADD_FAILURE() << "axis " << k << " step " << i + 1 << ": cycle " << b.rises[k][i] - f0 << " from time zero, "
                      << "frame runner " << run.rises[i].cycle;
    EXPECT_EQ(bad, 0u) << "axis " << k;
  }
  uint32_t pend = 0;
  ASSERT_EQ(hexstep_irq_pending(&b.dev, &pend), HEXSTEP_OK);
  EXPECT_EQ(pend & HEXSTEP_IRQ_DONE(HEXSTEP_ALL_AXES), HEXSTEP_IRQ_DONE(kPlanMask));
  EXPECT_EQ(pend & HEXSTEP_IRQ_SLOT(HEXSTEP_ALL_AXES), HEXSTEP_IRQ_SLOT(kPlanMask));
  EXPECT_TRUE(b.b.mon.irq());
  ASSERT_EQ(hexstep_irq_clear(&b.dev, HEXSTEP_IRQ_ALL), HEXSTEP_OK);
  ASSERT_EQ(hexstep_irq_pending(&b.dev, &pend), HEXSTEP_OK);
  EXPECT_EQ(pend, 0u);
  b.ticks(2);
  EXPECT_FALSE(b.b.mon.irq());
  uint32_t en = 0;
  ASSERT_EQ(hexstep_irq_enabled(&b.dev, &en), HEXSTEP_OK);
  EXPECT_EQ(en, HEXSTEP_IRQ_DONE(kPlanMask));
  EXPECT_EQ(b.b.problems(), "");
}

TEST(FwDriver, QueueFullReturnsError) {
  Board b;
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  const hexstep_move_t mv = slow_cruise(40, true);
  EXPECT_EQ(hexstep_queue_move(&b.dev, 0, &mv), HEXSTEP_OK);
  EXPECT_EQ(hexstep_queue_move(&b.dev, 0, &mv), HEXSTEP_OK);
  EXPECT_EQ(hexstep_queue_move(&b.dev, 0, &mv), HEXSTEP_ERR_QUEUE_FULL);
  EXPECT_EQ(hexstep_push(&b.dev, 0), HEXSTEP_ERR_QUEUE_FULL);
  unsigned n = 9;
  ASSERT_EQ(hexstep_queue_free(&b.dev, 0, &n), HEXSTEP_OK);
  EXPECT_EQ(n, 0u);
  uint32_t err = 9;
  ASSERT_EQ(hexstep_read_errors(&b.dev, 0, &err), HEXSTEP_OK);
  EXPECT_EQ(err, 0u) << "the driver refused the push itself: no hardware overrun";
  EXPECT_EQ(hexstep_queue_move(&b.dev, 1, &mv), HEXSTEP_OK) << "other axes are unaffected";
  // Two queued moves run back to back; a slot frees when the first starts.
  ASSERT_EQ(hexstep_start(&b.dev, 0x1u), HEXSTEP_OK);
  b.ticks(2 * kFrameCycles);
  ASSERT_EQ(hexstep_queue_free(&b.dev, 0, &n), HEXSTEP_OK);
  EXPECT_EQ(n, 1u);
  EXPECT_EQ(hexstep_wait(&b.dev, 0x1u, 5u), HEXSTEP_ERR_TIMEOUT);
  ASSERT_EQ(hexstep_wait(&b.dev, 0x1u, 1000000u), HEXSTEP_OK);
  int64_t pos = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 0, &pos), HEXSTEP_OK);
  EXPECT_EQ(pos, 80);
  EXPECT_EQ(b.rises[0].size(), 80u);
  ASSERT_EQ(hexstep_read_position(&b.dev, 1, &pos), HEXSTEP_OK);
  EXPECT_EQ(pos, 0) << "axis 1 was queued but not started";
  EXPECT_EQ(b.b.problems(), "");
}

TEST(FwDriver, AbortStopsAndFlushes) {
  Board b;
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  const hexstep_move_t fwd = slow_cruise(300, true), back = slow_cruise(300, false);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 2, &back), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 2, &fwd), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 4, &fwd), HEXSTEP_OK);
  ASSERT_EQ(hexstep_start(&b.dev, 0x14u), HEXSTEP_OK);
  b.ticks(50000);  // about 100 steps at 512 cycles per step
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
  EXPECT_GT(p2, -300);
  const size_t rises = b.rises[2].size();
  b.ticks(5000);
  ASSERT_EQ(hexstep_read_position(&b.dev, 2, &p2_later), HEXSTEP_OK);
  EXPECT_EQ(p2_later, p2);
  EXPECT_EQ(b.rises[2].size(), rises) << "no STEP edge after the abort";
  EXPECT_EQ(static_cast<int64_t>(rises), -p2);
  ASSERT_EQ(hexstep_wait(&b.dev, 0x10u, 1000000u), HEXSTEP_OK);
  int64_t p4 = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 4, &p4), HEXSTEP_OK);
  EXPECT_EQ(p4, 300) << "axis 4 ran on";
  EXPECT_EQ(b.b.problems(), "");
}

TEST(FwDriver, EstopFlagsAndClear) {
  Board b;
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  ASSERT_EQ(hexstep_irq_enable(&b.dev, HEXSTEP_IRQ_ERR(0x1u)), HEXSTEP_OK);
  const hexstep_move_t fwd = slow_cruise(300, true);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 0, &fwd), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 0, &fwd), HEXSTEP_OK);
  ASSERT_EQ(hexstep_start(&b.dev, 0x1u), HEXSTEP_OK);
  b.ticks(20000);
  bool latched = true, pin = true;
  ASSERT_EQ(hexstep_estop_status(&b.dev, &latched, &pin), HEXSTEP_OK);
  EXPECT_FALSE(latched);
  EXPECT_FALSE(pin);
  b.b.bus.set_estop(true);
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
  EXPECT_LT(pos, 300);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    uint32_t err = 0;
    ASSERT_EQ(hexstep_read_errors(&b.dev, k, &err), HEXSTEP_OK);
    EXPECT_EQ(err, HEXSTEP_AXERR_ESTOP) << "axis " << k;
  }
  uint32_t pend = 0;
  ASSERT_EQ(hexstep_irq_pending(&b.dev, &pend), HEXSTEP_OK);
  EXPECT_EQ(pend & HEXSTEP_IRQ_ERR(HEXSTEP_ALL_AXES), HEXSTEP_IRQ_ERR(HEXSTEP_ALL_AXES));
  EXPECT_TRUE(b.b.mon.irq());
  EXPECT_EQ(hexstep_queue_move(&b.dev, 0, &fwd), HEXSTEP_ERR_ESTOP);
  EXPECT_EQ(hexstep_push(&b.dev, 1), HEXSTEP_ERR_ESTOP);
  EXPECT_EQ(hexstep_start(&b.dev, 0x1u), HEXSTEP_ERR_ESTOP);
  EXPECT_EQ(hexstep_estop_clear(&b.dev), HEXSTEP_ERR_ESTOP) << "pin still high";
  b.b.bus.set_estop(false);
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
  EXPECT_EQ(b.b.problems(), "");
}

// hexstep_stop on a planned move and on a jog move: both come to rest, the planned one short of
// its end, the queued move behind it never starts; the stopping distances follow v^2 / (2 d).
TEST(FwDriver, StopAndJog) {
  Board b(3);
  ASSERT_EQ(hexstep_reset(&b.dev), HEXSTEP_OK);
  // At 100 MHz: axis 1 a 4,000-step move, 0 -> 500 k steps/s at 1e8 steps/s^2 (5 ms, 1,250
  // steps of ramp), a second queued behind; axis 5 a negative jog to 500 k steps/s at 1.4e8
  // (3.6 ms), stopping at 1e8.
  const real f = 100e6;
  hexstep_move_t mv = to_fw(encode({4000, true, 0, 5e5, 0, 1e8, 1e8}, f).regs);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 1, &mv), HEXSTEP_OK);
  ASSERT_EQ(hexstep_queue_move(&b.dev, 1, &mv), HEXSTEP_OK);
  hexstep_move_t jog{};
  ASSERT_TRUE(speed_to_reg(5e5, f, jog.v_max));
  ASSERT_TRUE(accel_to_reg(1.4e8, f, jog.acc));
  ASSERT_TRUE(accel_to_reg(1e8, f, jog.dec));
  jog.dir = HEXSTEP_MOVE_JOG;  // negative, jog
  ASSERT_EQ(hexstep_queue_move(&b.dev, 5, &jog), HEXSTEP_OK);
  ASSERT_EQ(hexstep_start(&b.dev, 0x22u), HEXSTEP_OK);
  b.ticks(600'000);  // 6 ms: both cruising at 500 k steps/s
  int64_t p1_at = 0, p5_at = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 1, &p1_at), HEXSTEP_OK);
  ASSERT_EQ(hexstep_read_position(&b.dev, 5, &p5_at), HEXSTEP_OK);
  ASSERT_EQ(hexstep_stop(&b.dev, 0x22u), HEXSTEP_OK);
  ASSERT_EQ(hexstep_wait(&b.dev, 0x22u, 10000000u), HEXSTEP_OK);
  int64_t p1 = 0, p5 = 0;
  ASSERT_EQ(hexstep_read_position(&b.dev, 1, &p1), HEXSTEP_OK);
  ASSERT_EQ(hexstep_read_position(&b.dev, 5, &p5), HEXSTEP_OK);
  // Kinematics: both stop from 500 k steps/s at 1e8 steps/s^2: v^2 / 2d = 1,250 steps (and a
  // step or so for the bus latency between the position reads and the STOP).
  EXPECT_NEAR(double(p1 - p1_at), 1250.0, 10.0);
  EXPECT_LT(p1, 4000) << "stopped short of the end; the queued move never started";
  EXPECT_NEAR(double(p5_at - p5), 1250.0, 10.0);
  EXPECT_EQ(static_cast<int64_t>(b.rises[1].size()), p1);
  EXPECT_EQ(static_cast<int64_t>(b.rises[5].size()), -p5);
  unsigned n = 0;
  ASSERT_EQ(hexstep_queue_free(&b.dev, 1, &n), HEXSTEP_OK);
  EXPECT_EQ(n, 2u) << "STOP flushes the queue";
  EXPECT_EQ(hexstep_stop(&b.dev, 0x40u), HEXSTEP_ERR_ARG);
  EXPECT_EQ(b.b.problems(), "");
}
