// SPDX-License-Identifier: Apache-2.0
// Wishbone register interface (rtl/hexstep_wb.v inside rtl/hexstep_top.v): the bus, the
// register map (offsets and reset values generated from rdl/hexstep.rdl, so a hand-written
// decode that disagrees with the map fails here), the move queue, START/ABORT/E-stop and IRQ.
// Motion is checked against the golden register-block model hexstep::WbModel (tests/common/
// wb_ref.hpp: ack, read data, IRQ, STEP/DIR compared after every edge), and the queue timing
// (same-cycle starts, gap-free chaining) against the documented rules below.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "hexstep/core.hpp"
#include "hexstep_regs.hpp"
#include "vectors.hpp"
#include "wb_bfm.hpp"
#include "wb_ref.hpp"

using namespace hexstep;
using namespace hexstep::test;
namespace R = hexstep::regs;

namespace {

void start(WbTop& bus, uint32_t mask) { bus.write(R::START, mask); }
void run_until_idle(WbTop& bus, WbRef& ref, uint64_t limit = 200000) {
  for (uint64_t i = 0; i < limit && !ref.idle(); ++i) bus.tick();
  for (int i = 0; i < 20; ++i) bus.tick();
  ASSERT_TRUE(ref.idle());
}

TEST(Wb, MovesUsedHereAreValid) {
  EXPECT_EQ(validate_move(bus_trapezoid(40)), 0u);
  EXPECT_EQ(validate_move(cruise(10, 1ull << 62)), 0u);
  // Every value fits its register (the bus keeps only ACC_W bits of ACC/DEC).
  const Widths w;
  EXPECT_EQ(bus_trapezoid(40).acc & ~w.acc_mask(), 0u);
  EXPECT_EQ(bus_trapezoid(40).dec & ~w.acc_mask(), 0u);
}

TEST(Wb, ResetValuesOfEveryRegister) {
  WbTop bus(1);
  bus.set_timing(2, 2);
  EXPECT_EQ(bus.read(R::ID), R::ID_RESET);
  EXPECT_EQ(bus.read(R::VERSION), R::VERSION_RESET);
  EXPECT_EQ(bus.read(R::START), 0u);
  EXPECT_EQ(bus.read(R::ABORT), 0u);
  EXPECT_EQ(bus.read(R::GSTATUS), R::GSTATUS_RESET);
  EXPECT_EQ(bus.read(R::IRQ_ENABLE), R::IRQ_ENABLE_RESET);
  EXPECT_EQ(bus.read(R::IRQ_PENDING), R::IRQ_PENDING_RESET);
  static_assert(R::AXIS_COUNT == kNumAxes, "map and model disagree on the number of axes");
  const uint32_t resets[] = {
      R::axis::STEPS_RESET,     R::axis::DIR_RESET,       R::axis::V_START_LO_RESET,
      R::axis::V_START_HI_RESET, R::axis::V_MAX_LO_RESET, R::axis::V_MAX_HI_RESET,
      R::axis::V_END_LO_RESET,  R::axis::V_END_HI_RESET,  R::axis::V_DEC_LO_RESET,
      R::axis::V_DEC_HI_RESET,  R::axis::ACC_LO_RESET,    R::axis::ACC_HI_RESET,
      R::axis::DEC_LO_RESET,    R::axis::DEC_HI_RESET,    R::axis::ACC_STEPS_RESET,
      R::axis::DEC_STEP_RESET,  R::axis::DEC_FRAC_RESET,  R::axis::CMD_RESET & R::axis::CMD_RMASK,
      R::axis::STATUS_RESET,    R::axis::ERR_RESET,       R::axis::POS_LO_RESET,
      R::axis::POS_HI_RESET,    R::axis::STEP_HIGH_RESET, R::axis::STEP_LOW_RESET,
      R::axis::DIR_SETUP_RESET, R::axis::DIR_HOLD_RESET,  R::axis::POLARITY_RESET};
  static_assert(sizeof(resets) / sizeof(resets[0]) == sizeof(R::axis::kAll) / sizeof(uint32_t), "");
  for (unsigned k = 0; k < kNumAxes; ++k)
    for (size_t i = 0; i < sizeof(resets) / sizeof(resets[0]); ++i)
      EXPECT_EQ(bus.read(ax(k, R::axis::kAll[i])), resets[i]) << "axis " << k << " reg 0x" << std::hex
                                                              << R::axis::kAll[i];
  EXPECT_EQ(bus.protocol_errors(), 0u);
}

// Every read-write register: all ones read back as its implemented bits (reserved bits read 0),
// byte enables change only the selected lanes, read-only registers ignore writes.
TEST(Wb, ReadWriteAndByteEnables) {
  WbTop bus(2);
  bus.set_timing(3, 3);
  struct RW { uint32_t adr, mask, reset; };
  std::vector<RW> rw = {{R::IRQ_ENABLE, R::IRQ_ENABLE_RWMASK, R::IRQ_ENABLE_RESET}};
  const uint32_t axis_rw[][3] = {
      {R::axis::STEPS, R::axis::STEPS_RWMASK, 0},       {R::axis::DIR, R::axis::DIR_RWMASK, 0},
      {R::axis::V_START_LO, R::axis::V_START_LO_RWMASK, 0},
      {R::axis::V_START_HI, R::axis::V_START_HI_RWMASK, 0},
      {R::axis::V_MAX_LO, R::axis::V_MAX_LO_RWMASK, 0}, {R::axis::V_MAX_HI, R::axis::V_MAX_HI_RWMASK, 0},
      {R::axis::V_END_LO, R::axis::V_END_LO_RWMASK, 0}, {R::axis::V_END_HI, R::axis::V_END_HI_RWMASK, 0},
      {R::axis::V_DEC_LO, R::axis::V_DEC_LO_RWMASK, 0}, {R::axis::V_DEC_HI, R::axis::V_DEC_HI_RWMASK, 0},
      {R::axis::ACC_LO, R::axis::ACC_LO_RWMASK, 0},     {R::axis::ACC_HI, R::axis::ACC_HI_RWMASK, 0},
      {R::axis::DEC_LO, R::axis::DEC_LO_RWMASK, 0},     {R::axis::DEC_HI, R::axis::DEC_HI_RWMASK, 0},
      {R::axis::ACC_STEPS, R::axis::ACC_STEPS_RWMASK, 0},
      {R::axis::DEC_STEP, R::axis::DEC_STEP_RWMASK, 0}, {R::axis::DEC_FRAC, R::axis::DEC_FRAC_RWMASK, 0},
      {R::axis::STEP_HIGH, R::axis::STEP_HIGH_RWMASK, R::axis::STEP_HIGH_RESET},
      {R::axis::STEP_LOW, R::axis::STEP_LOW_RWMASK, R::axis::STEP_LOW_RESET},
      {R::axis::DIR_SETUP, R::axis::DIR_SETUP_RWMASK, 0}, {R::axis::DIR_HOLD, R::axis::DIR_HOLD_RWMASK, 0},
      {R::axis::POLARITY, R::axis::POLARITY_RWMASK, 0}};
  for (unsigned k = 0; k < kNumAxes; ++k)
    for (auto& r : axis_rw) rw.push_back({ax(k, r[0]), r[1], r[2]});
  EXPECT_EQ(R::axis::ACC_HI_RWMASK, 0xFFFu);  // ACC_W = 44
  for (const RW& r : rw) {
    bus.write(r.adr, 0xFFFFFFFFu);
    EXPECT_EQ(bus.read(r.adr), r.mask) << std::hex << r.adr;
    bus.write(r.adr, 0);
    EXPECT_EQ(bus.read(r.adr), 0u) << std::hex << r.adr;
    bus.write(r.adr, 0xA5C3E1F7u, 0x5);  // lanes 0 and 2
    EXPECT_EQ(bus.read(r.adr), 0x00C300F7u & r.mask) << std::hex << r.adr;
    bus.write(r.adr, 0x12345678u, 0xA);  // lanes 1 and 3
    EXPECT_EQ(bus.read(r.adr), 0x12C356F7u & r.mask) << std::hex << r.adr;
    bus.write(r.adr, 0xFFFFFFFFu, 0x0);  // no lane: nothing changes
    EXPECT_EQ(bus.read(r.adr), 0x12C356F7u & r.mask) << std::hex << r.adr;
    bus.write(r.adr, r.reset);
  }
  // Read-only registers ignore writes.
  for (uint32_t a : {R::ID, R::VERSION, R::GSTATUS, ax(3, R::axis::STATUS), ax(3, R::axis::POS_LO),
                     ax(3, R::axis::POS_HI)}) {
    const uint32_t before = bus.read(a);
    bus.write(a, 0xFFFFFFFEu);
    EXPECT_EQ(bus.read(a), before) << std::hex << a;
  }
  EXPECT_EQ(bus.protocol_errors(), 0u);
}

TEST(Wb, UnmappedReadsZeroAndAck) {
  WbTop bus(3);
  bus.set_timing(1, 1);
  const uint32_t unmapped[] = {0x01C, 0x07C, 0x080, 0x0FC, ax(0, 0x6C), ax(2, 0x7C), ax(5, 0x70),
                               0x400, 0x800, 0xFFC};
  for (uint32_t a : unmapped) {
    bus.write(a, 0xFFFFFFFFu);
    EXPECT_EQ(bus.read(a), 0u) << std::hex << a;
  }
  // Nothing else changed: the writable registers still hold their reset values.
  EXPECT_EQ(bus.read(R::IRQ_ENABLE), 0u);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_EQ(bus.read(ax(k, R::axis::STEPS)), 0u);
    EXPECT_EQ(bus.read(ax(k, R::axis::POLARITY)), 0u);
  }
  // adr[1:0] are ignored: a byte address inside a word reaches that word.
  bus.write(ax(1, R::axis::STEPS) + 2, 0x1234u);
  EXPECT_EQ(bus.read(ax(1, R::axis::STEPS)), 0x1234u);
  EXPECT_EQ(bus.protocol_errors(), 0u);
}

TEST(Wb, AckProtocol) {
  WbTop bus(4);
  // cyc without stb, stb without cyc: no ack, no write.
  bus.drive(true, false, true, ax(0, R::axis::STEPS), 77, 0xF);
  for (int i = 0; i < 5; ++i) { bus.tick(); EXPECT_FALSE(bus.ack()); }
  bus.drive(false, true, true, ax(0, R::axis::STEPS), 77, 0xF);
  for (int i = 0; i < 5; ++i) { bus.tick(); EXPECT_FALSE(bus.ack()); }
  bus.drive(false, false, false, 0, 0, 0);
  bus.tick();
  EXPECT_EQ(bus.read(ax(0, R::axis::STEPS)), 0u);
  // The ack is registered: it rises one edge after the request and lasts one cycle.
  bus.drive(true, true, false, R::ID, 0, 0xF);
  EXPECT_FALSE(bus.ack());
  bus.tick();
  EXPECT_TRUE(bus.ack());
  EXPECT_EQ(bus.dat_o(), R::ID_RESET);
  bus.tick();  // request still held through the ack cycle: not acked twice
  EXPECT_FALSE(bus.ack());
  bus.drive(false, false, false, 0, 0, 0);
  bus.tick();
  EXPECT_FALSE(bus.ack());
  // Random idle and wait cycles, and back-to-back: a shadow of random writes reads back; exactly
  // one ack per request.
  for (unsigned timing = 0; timing < 3; ++timing) {
    bus.set_timing(timing * 2, timing);
    std::mt19937 rng(timing);
    std::array<uint32_t, kNumAxes> shadow{};
    for (unsigned k = 0; k < kNumAxes; ++k) shadow[k] = bus.read(ax(k, R::axis::STEPS));
    const uint64_t acks0 = bus.acks();
    unsigned n = 0;
    for (int i = 0; i < 300; ++i, ++n) {
      const unsigned k = rng() % kNumAxes;
      if (rng() & 1) {
        shadow[k] = rng();
        bus.write(ax(k, R::axis::STEPS), shadow[k]);
      } else {
        EXPECT_EQ(bus.read(ax(k, R::axis::STEPS)), shadow[k]);
      }
    }
    EXPECT_EQ(bus.acks() - acks0, n);
  }
  EXPECT_EQ(bus.protocol_errors(), 0u);
}

TEST(Wb, QueuePushAndOverrun) {
  WbTop bus(5);
  bus.set_timing(2, 1);
  bus.write(R::IRQ_ENABLE, R::IRQ_ENABLE_ERR_MASK);
  const uint32_t st = ax(2, R::axis::STATUS);
  auto free_slots = [&] { return (bus.read(st) & R::axis::STATUS_FREE_MASK) >> R::axis::STATUS_FREE_SHIFT; };
  EXPECT_EQ(free_slots(), 2u);
  write_move(bus, 2, bus_trapezoid(40));
  bus.write(ax(2, R::axis::CMD), 1);
  EXPECT_EQ(free_slots(), 1u);
  bus.write(ax(2, R::axis::CMD), 1);
  EXPECT_EQ(free_slots(), 0u);
  EXPECT_EQ(bus.read(ax(2, R::axis::ERR)), 0u);
  EXPECT_FALSE(bus.irq());
  bus.write(ax(2, R::axis::CMD), 1, 0xE);  // lane 0 not selected: no push
  EXPECT_EQ(bus.read(ax(2, R::axis::ERR)), 0u);
  bus.write(ax(2, R::axis::CMD), 1);  // full: overrun
  EXPECT_EQ(bus.read(ax(2, R::axis::ERR)), R::axis::ERR_OVERRUN_MASK);
  EXPECT_EQ(free_slots(), 0u);
  EXPECT_EQ(bus.read(R::IRQ_PENDING), 1u << (R::IRQ_PENDING_ERR_SHIFT + 2));
  EXPECT_TRUE(bus.irq());
  bus.write(ax(2, R::axis::ERR), R::axis::ERR_OVERRUN_MASK);  // write 1 to clear
  EXPECT_EQ(bus.read(ax(2, R::axis::ERR)), 0u);
  bus.write(R::IRQ_PENDING, 0xFFFFFFFFu);
  EXPECT_EQ(bus.read(R::IRQ_PENDING), 0u);
  EXPECT_FALSE(bus.irq());
  // Other axes untouched.
  EXPECT_EQ(bus.read(ax(1, R::axis::STATUS)), R::axis::STATUS_RESET);
  // ABORT flushes the queue.
  bus.write(R::ABORT, 1u << 2);
  EXPECT_EQ(free_slots(), 2u);
}

TEST(Wb, StartMaskStartsAxesOnTheSameCycle) {
  WbTop bus(6);
  bus.set_timing(3, 2);
  WbRef ref(bus);
  const unsigned axes[] = {0, 2, 5};
  for (unsigned k : axes) push(bus, k, bus_trapezoid(40, k != 2));
  push(bus, 3, bus_trapezoid(30));  // queued but not started
  start(bus, (1u << 0) | (1u << 2) | (1u << 5));
  const uint64_t start_ack = ref.acks.back();
  run_until_idle(bus, ref, 5000);
  for (unsigned k : axes) {
    ASSERT_EQ(ref.starts[k].size(), 1u);
    // START takes effect at the edge after its write's ack, on all axes of the mask at once.
    EXPECT_EQ(ref.starts[k][0], start_ack + 1) << "axis " << k;
    EXPECT_EQ(ref.rises[k], 40u);
  }
  EXPECT_EQ(ref.starts[3].size(), 0u);
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
  EXPECT_EQ(ref.model.queued(3), 1u);  // the RTL still holds it too (STATUS.free below)
  EXPECT_EQ(static_cast<int32_t>(bus.read(ax(0, R::axis::POS_LO))), 40);
  EXPECT_EQ(static_cast<int32_t>(bus.read(ax(2, R::axis::POS_LO))), -40);
  EXPECT_EQ(bus.read(ax(2, R::axis::POS_HI)), 0xFFFFFFFFu);  // latched sign extension
  EXPECT_EQ(bus.read(ax(3, R::axis::STATUS)) & R::axis::STATUS_FREE_MASK, 1u << R::axis::STATUS_FREE_SHIFT);
  EXPECT_EQ(bus.protocol_errors(), 0u);
}

TEST(Wb, ChainedMovesRunWithoutGap) {
  WbTop bus(7);
  bus.set_timing(2, 2);
  WbRef ref(bus);
  push(bus, 1, bus_trapezoid(40));
  push(bus, 1, cruise(12, 1ull << 62, false));
  start(bus, 1u << 1);
  const uint64_t start_ack = ref.acks.back();
  // While the first runs, a third move fills the freed slot and chains too.
  for (int i = 0; i < 30; ++i) bus.tick();
  push(bus, 1, bus_trapezoid(20));
  run_until_idle(bus, ref, 5000);
  ASSERT_EQ(ref.starts[1].size(), 3u);
  EXPECT_EQ(ref.starts[1][0], start_ack + 1);
  ASSERT_GE(ref.dones[1].size(), 2u);
  // The core's start for move n+1 is at the edge right after the cycle move n's done was high.
  EXPECT_EQ(ref.starts[1][1], ref.dones[1][0] + 1);
  EXPECT_EQ(ref.starts[1][2], ref.dones[1][1] + 1);
  EXPECT_EQ(ref.rises[1], 72u);
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
  EXPECT_EQ(static_cast<int32_t>(bus.read(ax(1, R::axis::POS_LO))), 40 - 12 + 20);
  EXPECT_EQ(bus.read(ax(1, R::axis::STATUS)) & R::axis::STATUS_RUN_MASK, 0u);  // ran out of moves
  EXPECT_EQ(bus.read(ax(1, R::axis::ERR)), 0u);
}

TEST(Wb, StagingWritesNeverChangeTheRunningMove) {
  WbTop bus(8);
  bus.set_timing(1, 1);
  WbRef ref(bus);
  push(bus, 4, bus_trapezoid(40));
  start(bus, 1u << 4);
  // Rewrite every staging word with other values while the move runs (no push).
  write_move(bus, 4, cruise(3, 1ull << 63, false));
  run_until_idle(bus, ref, 5000);
  EXPECT_EQ(ref.rises[4], 40u);
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
  EXPECT_EQ(static_cast<int32_t>(bus.read(ax(4, R::axis::POS_LO))), 40);
}

TEST(Wb, AbortStopsAndFlushes) {
  WbTop bus(9);
  bus.set_timing(1, 0);
  WbRef ref(bus);
  push(bus, 0, cruise(1000, 1ull << 60));
  push(bus, 0, cruise(1000, 1ull << 60));
  start(bus, 1u);
  for (int i = 0; i < 200; ++i) bus.tick();
  EXPECT_NE(bus.read(ax(0, R::axis::STATUS)) & R::axis::STATUS_BUSY_MASK, 0u);
  bus.write(R::ABORT, 1u);
  // The core is aborted at the edge after the write's ack: the last edge of write(), which
  // holds the request through the ack cycle.
  ASSERT_EQ(ref.acks.back() + 2, ref.edges);
  EXPECT_EQ(ref.model.core_inputs().abort_mask, 1u);
  for (int i = 0; i < 100; ++i) bus.tick();
  EXPECT_TRUE(ref.idle());
  EXPECT_EQ(ref.model.queued(0), 0u);
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
  const uint32_t s = bus.read(ax(0, R::axis::STATUS));
  EXPECT_EQ(s & (R::axis::STATUS_BUSY_MASK | R::axis::STATUS_RUN_MASK), 0u);
  EXPECT_EQ((s & R::axis::STATUS_FREE_MASK) >> R::axis::STATUS_FREE_SHIFT, 2u);
  EXPECT_EQ(static_cast<int64_t>(static_cast<int32_t>(bus.read(ax(0, R::axis::POS_LO)))),
            ref.out(0).pos);
  EXPECT_GT(ref.out(0).pos, 0);
  EXPECT_LT(ref.out(0).pos, 1000);
}

TEST(Wb, EstopLatchesAbortsAllAxesAndClears) {
  WbTop bus(10);
  bus.set_timing(1, 1);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    write_move(bus, k, cruise(1000, 1ull << 60));
    bus.write(ax(k, R::axis::CMD), 1);
  }
  bus.write(R::IRQ_ENABLE, R::IRQ_ENABLE_ERR_MASK);
  bus.write(R::START, kAllAxes);
  for (int i = 0; i < 100; ++i) bus.tick();
  for (unsigned k = 0; k < kNumAxes; ++k)
    EXPECT_NE(bus.read(ax(k, R::axis::STATUS)) & R::axis::STATUS_BUSY_MASK, 0u);
  bus.set_estop(true);
  // Pin -> 2-flop synchronizer -> latch -> core abort: no STEP edge may rise after 4 edges
  // (a pulse already high completes).
  std::array<bool, kNumAxes> prev{};
  for (int i = 0; i < 4; ++i) bus.tick();
  for (unsigned k = 0; k < kNumAxes; ++k) prev[k] = bus.step(k);
  for (int i = 0; i < 200; ++i) {
    bus.tick();
    for (unsigned k = 0; k < kNumAxes; ++k) {
      EXPECT_FALSE(bus.step(k) && !prev[k]) << "rising STEP after e-stop, axis " << k;
      prev[k] = bus.step(k);
    }
  }
  EXPECT_EQ(bus.read(R::GSTATUS), R::GSTATUS_ESTOP_MASK | R::GSTATUS_ESTOP_PIN_MASK);
  EXPECT_TRUE(bus.irq());
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_EQ(bus.read(ax(k, R::axis::STATUS)), R::axis::STATUS_RESET) << k;  // idle, empty
    EXPECT_EQ(bus.read(ax(k, R::axis::ERR)), R::axis::ERR_ESTOP_MASK) << k;
  }
  // While latched, pushes and starts are dropped.
  write_move(bus, 0, cruise(10, 1ull << 60));
  bus.write(ax(0, R::axis::CMD), 1);
  bus.write(R::START, 1u);
  EXPECT_EQ(bus.read(ax(0, R::axis::STATUS)), R::axis::STATUS_RESET);
  // Clearing while the pin is still high does not clear.
  bus.write(R::GSTATUS, R::GSTATUS_ESTOP_MASK);
  EXPECT_EQ(bus.read(R::GSTATUS) & R::GSTATUS_ESTOP_MASK, R::GSTATUS_ESTOP_MASK);
  bus.set_estop(false);
  for (int i = 0; i < 4; ++i) bus.tick();
  EXPECT_EQ(bus.read(R::GSTATUS), R::GSTATUS_ESTOP_MASK);  // latched
  bus.write(R::GSTATUS, R::GSTATUS_ESTOP_MASK);
  EXPECT_EQ(bus.read(R::GSTATUS), 0u);
  // Works again after the clear.
  bus.write(ax(0, R::axis::CMD), 1);
  bus.write(R::START, 1u);
  EXPECT_NE(bus.read(ax(0, R::axis::STATUS)) & R::axis::STATUS_RUN_MASK, 0u);
}

TEST(Wb, InterruptsSetAndClear) {
  WbTop bus(11);
  bus.set_timing(1, 1);
  EXPECT_FALSE(bus.irq());
  write_move(bus, 3, cruise(5, 1ull << 62));
  bus.write(ax(3, R::axis::CMD), 1);
  bus.write(R::IRQ_ENABLE, 1u << (R::IRQ_ENABLE_DONE_SHIFT + 3));
  bus.write(R::START, 1u << 3);
  // The start popped the queue: slot-free pending (not enabled, no irq yet).
  EXPECT_NE(bus.read(R::IRQ_PENDING) & (1u << (R::IRQ_PENDING_SLOT_SHIFT + 3)), 0u);
  for (int i = 0; i < 100; ++i) bus.tick();
  EXPECT_TRUE(bus.irq());
  EXPECT_EQ(bus.read(R::IRQ_PENDING), (1u << (R::IRQ_PENDING_DONE_SHIFT + 3)) |
                                          (1u << (R::IRQ_PENDING_SLOT_SHIFT + 3)));
  bus.write(R::IRQ_PENDING, 1u << (R::IRQ_PENDING_DONE_SHIFT + 3));
  EXPECT_FALSE(bus.irq());
  bus.write(R::IRQ_ENABLE, 1u << (R::IRQ_ENABLE_SLOT_SHIFT + 3));
  EXPECT_TRUE(bus.irq());
  bus.write(R::IRQ_PENDING, 0xFFFFFFFFu);
  EXPECT_FALSE(bus.irq());
  EXPECT_EQ(bus.read(R::IRQ_PENDING), 0u);
  // A refused move (v_max = 0) sets AXIS_ERR.move and the error interrupt.
  bus.write(R::IRQ_ENABLE, R::IRQ_ENABLE_ERR_MASK);
  AxisMove bad = cruise(5, 1ull << 62);
  bad.v_max = 0;
  write_move(bus, 3, bad);
  bus.write(ax(3, R::axis::CMD), 1);
  bus.write(R::START, 1u << 3);
  for (int i = 0; i < 5; ++i) bus.tick();
  EXPECT_EQ(bus.read(ax(3, R::axis::ERR)), R::axis::ERR_MOVE_MASK);
  EXPECT_TRUE(bus.irq());
}

TEST(Wb, PulseTimingAndPolarityReachTheCore) {
  WbTop bus(12);
  bus.set_timing(1, 1);
  WbRef ref(bus);
  PulseConfig pc;
  pc.step_high = 3;
  pc.step_low = 5;
  pc.dir_setup = 2;
  pc.dir_hold = 4;
  pc.step_invert = true;
  pc.dir_invert = true;
  bus.write(ax(5, R::axis::STEP_HIGH), pc.step_high);
  bus.write(ax(5, R::axis::STEP_LOW), pc.step_low);
  bus.write(ax(5, R::axis::DIR_SETUP), pc.dir_setup);
  bus.write(ax(5, R::axis::DIR_HOLD), pc.dir_hold);
  bus.write(ax(5, R::axis::POLARITY), R::axis::POLARITY_STEP_INV_MASK | R::axis::POLARITY_DIR_INV_MASK);
  // WbModel applies polarity at once, as the RTL pins do: every edge is compared, the write's
  // ack edge included.
  push(bus, 5, bus_trapezoid(40, false));
  start(bus, 1u << 5);
  run_until_idle(bus, ref, 5000);
  // The core ran the move with the written timing and polarity.
  const PulseConfig& got = ref.model.core_inputs().pulse[5];
  EXPECT_EQ(got.step_high, pc.step_high);
  EXPECT_EQ(got.step_low, pc.step_low);
  EXPECT_EQ(got.dir_setup, pc.dir_setup);
  EXPECT_EQ(got.dir_hold, pc.dir_hold);
  EXPECT_EQ(got.step_invert, pc.step_invert);
  EXPECT_EQ(got.dir_invert, pc.dir_invert);
  EXPECT_EQ(ref.rises[5], 40u);
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
}

}  // namespace
