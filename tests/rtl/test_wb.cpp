// SPDX-License-Identifier: Apache-2.0
// The register block of rtl/hexstep_top.v on its Wishbone bus: the map (offsets, reset values
// and implemented bits generated from rdl/hexstep.rdl, so a hand-written decode that disagrees
// with the map fails here), the bus timing of docs/ARCHITECTURE.md ("Bus interface"), the move
// queue, START/STOP/ABORT/E-STOP and the interrupts ("Moves, queue and chaining"). Every test
// runs the Verilated RTL and TopModel in lock step (tests/common/bench.hpp) and ends requiring
// RTL == model at every edge, a clean output-timing monitor and no protocol error; the
// expectations themselves come from the documents, not from either simulator.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "bench.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;
namespace R = hexstep::regs;
namespace A = hexstep::regs::axis;

namespace {
constexpr uint32_t kAll = (1u << kNumAxes) - 1u;
constexpr uint64_t kQuarter = 1ull << 62;  // 1/4 step per tick: a step on every 4th tick, q = 0

// With 1/4 step per tick the k-th step of a move crosses exactly at the end of tick 4k.
uint64_t quarter_rise(uint64_t f0, uint64_t k) { return rise_cycle(f0, 4 * k, 0); }

// The first edge after which ack is high, for a request first driven in the cycle in progress
// (the master holds it; returns the number of edges until the ack was seen).
uint64_t edges_to_ack(Bench& b, bool we, uint32_t adr, uint32_t dat = 0, unsigned sel = 0xF) {
  b.bus.drive(true, true, we, adr, dat, sel);
  uint64_t n = 0;
  do {
    b.bus.tick();
    ++n;
  } while (!b.mon.ack() && n < 1000);
  b.bus.tick();  // the ack cycle; the master samples ack at its end
  b.bus.drive(false, false, false, 0, 0, 0);
  return n;
}

// The bus cycle a memory access of a request acted on at the edge ending cycle c uses: the first
// bus cycle (frame cycle 4i + 3) after the cycle that follows the request edge, which decodes it.
uint64_t next_bus_cycle_after(uint64_t c) {
  uint64_t b = c + 2;
  while (b % kSlotCycles != kSlotCycles - 1) ++b;
  return b;
}

// Rising edges of STEP (levels before polarity) with their first high cycle, per axis.
struct Rises {
  std::array<std::vector<uint64_t>, kNumAxes> at;
  std::array<bool, kNumAxes> prev{};
  void attach(Bench& b) {
    b.bus.on_edge = [this, &b] {
      for (unsigned k = 0; k < kNumAxes; ++k) {
        const bool l = b.m().pulse(k).step_level();
        if (l && !prev[k]) at[k].push_back(b.cycle());
        prev[k] = l;
      }
    };
  }
};
}  // namespace

TEST(Wb, MovesUsedHereAreValid) {
  EXPECT_EQ(validate_move(trapezoid(40)), 0u);
  EXPECT_EQ(validate_move(cruise(10, kQuarter)), 0u);
  const Widths w;
  EXPECT_EQ(trapezoid(40).acc & ~w.acc_mask(), 0u);
  EXPECT_EQ(trapezoid(40).dec & ~w.acc_mask(), 0u);
}

TEST(Wb, ResetValuesOfEveryRegister) {
  Bench b(1);
  b.bus.set_timing(2, 2);
  EXPECT_EQ(b.read(R::ID), R::ID_RESET);
  EXPECT_EQ(b.read(R::VERSION), R::VERSION_RESET);
  EXPECT_EQ(b.read(R::START), R::START_RESET & R::START_RMASK);
  EXPECT_EQ(b.read(R::ABORT), R::ABORT_RESET & R::ABORT_RMASK);
  EXPECT_EQ(b.read(R::STOP), R::STOP_RESET & R::STOP_RMASK);
  EXPECT_EQ(b.read(R::GSTATUS), R::GSTATUS_RESET);
  EXPECT_EQ(b.read(R::IRQ_ENABLE), R::IRQ_ENABLE_RESET);
  EXPECT_EQ(b.read(R::IRQ_PENDING), R::IRQ_PENDING_RESET);
  EXPECT_EQ(b.read(R::INFO0), R::INFO0_RESET);
  EXPECT_EQ(b.read(R::INFO1), R::INFO1_RESET);
  static_assert(R::AXIS_COUNT == kNumAxes, "map and model disagree on the number of axes");
  const uint32_t resets[] = {
      A::STEPS_RESET,      A::DIR_RESET,      A::V_START_LO_RESET, A::V_START_HI_RESET, A::V_MAX_LO_RESET,
      A::V_MAX_HI_RESET,   A::V_END_LO_RESET, A::V_END_HI_RESET,   A::V_DEC_LO_RESET,   A::V_DEC_HI_RESET,
      A::ACC_LO_RESET,     A::ACC_HI_RESET,   A::DEC_LO_RESET,     A::DEC_HI_RESET,     A::ACC_STEPS_RESET,
      A::DEC_STEP_RESET,   A::DEC_FRAC_RESET, A::CMD_RESET & A::CMD_RMASK, A::STATUS_RESET, A::ERR_RESET,
      A::POS_LO_RESET,     A::POS_HI_RESET,   A::STEP_HIGH_RESET,  A::STEP_LOW_RESET,   A::DIR_SETUP_RESET,
      A::DIR_HOLD_RESET,   A::POLARITY_RESET};
  static_assert(sizeof(resets) / sizeof(resets[0]) == sizeof(A::kAll) / sizeof(uint32_t), "");
  for (unsigned k = 0; k < kNumAxes; ++k)
    for (size_t i = 0; i < sizeof(resets) / sizeof(resets[0]); ++i)
      EXPECT_EQ(b.axr(k, A::kAll[i]), resets[i]) << "axis " << k << " reg 0x" << std::hex << A::kAll[i];
  EXPECT_EQ(b.problems(), "");
}

// INFO0/INFO1 report the widths of the build and the frame.
TEST(Wb, InfoRegistersReportWidthsAndFrame) {
  Bench b(2);
  const Widths w = RtlTop::rtl_widths();
  const uint32_t i0 = b.read(R::INFO0), i1 = b.read(R::INFO1);
  EXPECT_EQ((i0 & R::INFO0_SPEED_W_MASK) >> R::INFO0_SPEED_W_SHIFT, w.speed_frac);
  EXPECT_EQ((i0 & R::INFO0_ACC_W_MASK) >> R::INFO0_ACC_W_SHIFT, w.acc);
  EXPECT_EQ((i0 & R::INFO0_STEP_W_MASK) >> R::INFO0_STEP_W_SHIFT, w.steps);
  EXPECT_EQ((i0 & R::INFO0_DFRAC_W_MASK) >> R::INFO0_DFRAC_W_SHIFT, w.dec_frac);
  EXPECT_EQ((i1 & R::INFO1_PULSE_W_MASK) >> R::INFO1_PULSE_W_SHIFT, w.pulse);
  EXPECT_EQ((i1 & R::INFO1_POS_W_MASK) >> R::INFO1_POS_W_SHIFT, w.pos);
  EXPECT_EQ((i1 & R::INFO1_FRAME_LOG2_MASK) >> R::INFO1_FRAME_LOG2_SHIFT, kFrameLog2);
  EXPECT_EQ((i1 & R::INFO1_SLOTS_MASK) >> R::INFO1_SLOTS_SHIFT, kSlots);
  EXPECT_EQ((b.read(R::VERSION) & R::VERSION_NAXES_MASK) >> R::VERSION_NAXES_SHIFT, RtlTop::rtl_naxes());
  EXPECT_EQ(b.problems(), "");
}

// Every read-write register: all ones read back as its implemented bits, byte enables change
// only the selected lanes, no lane changes nothing; read-only registers ignore writes.
TEST(Wb, ReadWriteAndByteEnables) {
  Bench b(3);
  b.bus.set_timing(3, 3);
  struct RW { uint32_t adr, mask, reset; };
  std::vector<RW> rw = {{R::IRQ_ENABLE, R::IRQ_ENABLE_RWMASK, R::IRQ_ENABLE_RESET}};
  const uint32_t axis_rw[][3] = {
      {A::STEPS, A::STEPS_RWMASK, 0},           {A::DIR, A::DIR_RWMASK, 0},
      {A::V_START_LO, A::V_START_LO_RWMASK, 0}, {A::V_START_HI, A::V_START_HI_RWMASK, 0},
      {A::V_MAX_LO, A::V_MAX_LO_RWMASK, 0},     {A::V_MAX_HI, A::V_MAX_HI_RWMASK, 0},
      {A::V_END_LO, A::V_END_LO_RWMASK, 0},     {A::V_END_HI, A::V_END_HI_RWMASK, 0},
      {A::V_DEC_LO, A::V_DEC_LO_RWMASK, 0},     {A::V_DEC_HI, A::V_DEC_HI_RWMASK, 0},
      {A::ACC_LO, A::ACC_LO_RWMASK, 0},         {A::ACC_HI, A::ACC_HI_RWMASK, 0},
      {A::DEC_LO, A::DEC_LO_RWMASK, 0},         {A::DEC_HI, A::DEC_HI_RWMASK, 0},
      {A::ACC_STEPS, A::ACC_STEPS_RWMASK, 0},   {A::DEC_STEP, A::DEC_STEP_RWMASK, 0},
      {A::DEC_FRAC, A::DEC_FRAC_RWMASK, 0},     {A::STEP_HIGH, A::STEP_HIGH_RWMASK, A::STEP_HIGH_RESET},
      {A::STEP_LOW, A::STEP_LOW_RWMASK, A::STEP_LOW_RESET},
      {A::DIR_SETUP, A::DIR_SETUP_RWMASK, 0},   {A::DIR_HOLD, A::DIR_HOLD_RWMASK, 0},
      {A::POLARITY, A::POLARITY_RWMASK, 0}};
  for (unsigned k = 0; k < kNumAxes; ++k)
    for (auto& r : axis_rw) rw.push_back({ax_reg(k, r[0]), r[1], r[2]});
  EXPECT_EQ(A::ACC_HI_RWMASK, 0xFFFFu);  // ACC_W = 48
  for (const RW& r : rw) {
    b.write(r.adr, 0xFFFFFFFFu);
    EXPECT_EQ(b.read(r.adr), r.mask) << std::hex << r.adr;
    b.write(r.adr, 0);
    EXPECT_EQ(b.read(r.adr), 0u) << std::hex << r.adr;
    b.write(r.adr, 0xA5C3E1F7u, 0x5);  // lanes 0 and 2
    EXPECT_EQ(b.read(r.adr), 0x00C300F7u & r.mask) << std::hex << r.adr;
    b.write(r.adr, 0x12345678u, 0xA);  // lanes 1 and 3
    EXPECT_EQ(b.read(r.adr), 0x12C356F7u & r.mask) << std::hex << r.adr;
    b.write(r.adr, 0xFFFFFFFFu, 0x0);  // no lane: nothing changes
    EXPECT_EQ(b.read(r.adr), 0x12C356F7u & r.mask) << std::hex << r.adr;
    b.write(r.adr, r.reset);
  }
  for (uint32_t a : {R::ID, R::VERSION, R::INFO0, R::INFO1, R::GSTATUS, ax_reg(3, A::STATUS), ax_reg(3, A::POS_LO),
                     ax_reg(3, A::POS_HI), ax_reg(3, A::ERR)}) {
    const uint32_t before = b.read(a);
    b.write(a, 0xFFFFFFFEu);
    EXPECT_EQ(b.read(a), before) << std::hex << a;
  }
  EXPECT_EQ(b.problems(), "");
}

TEST(Wb, UnmappedReadsZeroAndAck) {
  Bench b(4);
  b.bus.set_timing(1, 1);
  std::vector<uint32_t> unmapped = {0x028, 0x07C, 0x080, 0x0FC, 0x400, 0x800, 0xFFC};
  for (unsigned k : {0u, 2u, 5u})
    for (uint32_t off = A::POLARITY + 4; off < R::AXIS_STRIDE; off += 4) unmapped.push_back(ax_reg(k, off));
  for (uint32_t a : unmapped) {
    b.write(a, 0xFFFFFFFFu);
    EXPECT_EQ(b.read(a), 0u) << std::hex << a;
  }
  // Nothing else changed: the writable registers still hold their reset values.
  EXPECT_EQ(b.read(R::IRQ_ENABLE), 0u);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_EQ(b.axr(k, A::STEPS), 0u);
    EXPECT_EQ(b.axr(k, A::POLARITY), 0u);
    EXPECT_EQ(b.axr(k, A::STEP_HIGH), A::STEP_HIGH_RESET);
  }
  // adr[1:0] are ignored: a byte address inside a word reaches that word.
  b.write(ax_reg(1, A::STEPS) + 2, 0x1234u);
  EXPECT_EQ(b.axr(1, A::STEPS), 0x1234u);
  EXPECT_EQ(b.read(ax_reg(1, A::STEPS) + 3), 0x1234u);
  EXPECT_EQ(b.problems(), "");
}

// The ack timing of docs/ARCHITECTURE.md ("Bus interface"), for requests in every phase of
// the 4-cycle slot: a request is taken at the edge ending its first cycle r and acted on at the
// edge ending r + kTakeCycles (the request edge); flip-flop registers ack in the cycle after
// the request edge; staging and configuration reads wait for the next bus cycle b (cycle 4i+3,
// the first after the decode cycle that follows the request edge) and ack on edge b+2, writes
// on b+4; CMD.push on b+100. After reset, requests wait for the initialization (32 * NAXES
// cycles).
TEST(Wb, AckTiming) {
  Bench b(5);
  // Reset: a request from cycle 0 on is acted on once the initialization is over.
  {
    const uint64_t n = edges_to_ack(b, false, R::ID);
    EXPECT_EQ(n, uint64_t(kFrameCycles) * RtlTop::rtl_naxes() + 1 + kTakeCycles) << "first ack after reset";
  }
  for (unsigned phase = 0; phase < kSlotCycles; ++phase) {
    SCOPED_TRACE("request in slot cycle " + std::to_string(phase));
    auto align = [&] {
      b.idle(1);
      while (b.cycle() % kSlotCycles != phase) b.idle(1);
    };
    align();
    EXPECT_EQ(edges_to_ack(b, false, R::IRQ_ENABLE), 1u + kTakeCycles);
    align();
    EXPECT_EQ(edges_to_ack(b, true, R::IRQ_ENABLE, 0), 1u + kTakeCycles);
    align();
    EXPECT_EQ(edges_to_ack(b, false, ax_reg(2, A::STATUS)), 1u + kTakeCycles);
    align();
    EXPECT_EQ(edges_to_ack(b, true, ax_reg(2, A::CMD), 0), 1u + kTakeCycles) << "CMD without push";
    align();
    EXPECT_EQ(edges_to_ack(b, false, 0x800), 1u + kTakeCycles) << "unmapped";
    for (uint32_t reg : {A::STEPS, A::DEC_FRAC, A::STEP_HIGH, A::POLARITY}) {
      align();
      uint64_t r = b.cycle(), bc = next_bus_cycle_after(r + kTakeCycles);
      EXPECT_EQ(edges_to_ack(b, false, ax_reg(4, reg)), bc + 2 - r + 1) << "read 0x" << std::hex << reg;
      align();
      r = b.cycle();
      bc = next_bus_cycle_after(r + kTakeCycles);
      EXPECT_EQ(edges_to_ack(b, true, ax_reg(4, reg), reg == A::STEP_HIGH ? 1 : 0), bc + 4 - r + 1)
          << "write 0x" << std::hex << reg;
    }
    align();
    const uint64_t r = b.cycle(), bc = next_bus_cycle_after(r + kTakeCycles);
    EXPECT_EQ(edges_to_ack(b, true, ax_reg(phase, A::CMD), A::CMD_PUSH_MASK), bc + 100 - r + 1) << "push";
  }
  EXPECT_EQ(b.problems(), "");
}

// The ack is a register, one cycle per request: cyc or stb alone is no request, a request held
// through its ack cycle is acted on once, back-to-back and randomly spaced requests each get one.
TEST(Wb, AckProtocol) {
  Bench b(6);
  b.idle(300);  // past the initialization
  b.bus.drive(true, false, true, ax_reg(0, A::STEPS), 77, 0xF);
  for (int i = 0; i < 10; ++i) {
    b.bus.tick();
    EXPECT_FALSE(b.mon.ack());
  }
  b.bus.drive(false, true, true, ax_reg(0, A::STEPS), 77, 0xF);
  for (int i = 0; i < 10; ++i) {
    b.bus.tick();
    EXPECT_FALSE(b.mon.ack());
  }
  b.bus.drive(false, false, false, 0, 0, 0);
  b.bus.tick();
  EXPECT_EQ(b.axr(0, A::STEPS), 0u);
  // A register read: taken at the request's first edge, acted on at the next, acked after it,
  // one cycle long, the data with it.
  b.bus.drive(true, true, false, R::ID, 0, 0xF);
  EXPECT_FALSE(b.mon.ack());
  for (unsigned i = 0; i < kTakeCycles; ++i) {
    b.bus.tick();
    EXPECT_FALSE(b.mon.ack());
  }
  b.bus.tick();
  EXPECT_TRUE(b.mon.ack());
  EXPECT_EQ(b.mon.dat(), R::ID_RESET);
  b.bus.tick();  // still requested through the ack cycle: not acked again at once
  EXPECT_FALSE(b.mon.ack());
  b.bus.drive(false, false, false, 0, 0, 0);
  b.bus.tick();
  EXPECT_FALSE(b.mon.ack());
  // Random idle and wait cycles, and back to back: a shadow of random writes reads back; exactly
  // one ack per request.
  for (unsigned timing = 0; timing < 3; ++timing) {
    b.bus.set_timing(timing * 2, timing);
    std::mt19937 rng(timing);
    std::array<uint32_t, kNumAxes> shadow{};
    for (unsigned k = 0; k < kNumAxes; ++k) shadow[k] = b.axr(k, A::STEPS);
    const uint64_t acks0 = b.bus.acks();
    unsigned n = 0;
    for (int i = 0; i < 200; ++i, ++n) {
      const unsigned k = rng() % kNumAxes;
      if (rng() & 1) {
        shadow[k] = rng();
        b.axw(k, A::STEPS, shadow[k]);
      } else {
        EXPECT_EQ(b.axr(k, A::STEPS), shadow[k]);
      }
    }
    EXPECT_EQ(b.bus.acks() - acks0, n);
  }
  EXPECT_EQ(b.problems(), "");
}

TEST(Wb, QueuePushAndOverrun) {
  Bench b(7);
  b.bus.set_timing(2, 1);
  b.write(R::IRQ_ENABLE, R::IRQ_ENABLE_ERR_MASK);
  EXPECT_EQ(b.free_slots(2), 2u);
  b.push(2, trapezoid(40));
  EXPECT_EQ(b.free_slots(2), 1u);
  b.axw(2, A::CMD, A::CMD_PUSH_MASK);  // the same staging words again
  EXPECT_EQ(b.free_slots(2), 0u);
  EXPECT_EQ(b.axr(2, A::ERR), 0u);
  EXPECT_FALSE(b.mon.irq());
  b.axw(2, A::CMD, A::CMD_PUSH_MASK, 0xE);  // lane 0 not selected: no push, no overrun
  EXPECT_EQ(b.axr(2, A::ERR), 0u);
  b.axw(2, A::CMD, A::CMD_PUSH_MASK);  // full: overrun
  EXPECT_EQ(b.axr(2, A::ERR), A::ERR_OVERRUN_MASK);
  EXPECT_EQ(b.free_slots(2), 0u);
  EXPECT_EQ(b.read(R::IRQ_PENDING), 1u << (R::IRQ_PENDING_ERR_SHIFT + 2));
  EXPECT_TRUE(b.mon.irq());
  b.axw(2, A::ERR, A::ERR_OVERRUN_MASK);  // write 1 to clear
  EXPECT_EQ(b.axr(2, A::ERR), 0u);
  b.write(R::IRQ_PENDING, 0xFFFFFFFFu);
  EXPECT_EQ(b.read(R::IRQ_PENDING), 0u);
  EXPECT_FALSE(b.mon.irq());
  EXPECT_EQ(b.status(1), A::STATUS_RESET) << "other axes untouched";
  // ABORT flushes the queue: both entries free, the slot interrupt pends.
  b.write(R::ABORT, 1u << 2);
  EXPECT_EQ(b.free_slots(2), 2u);
  EXPECT_EQ(b.read(R::IRQ_PENDING), 1u << (R::IRQ_PENDING_SLOT_SHIFT + 2));
  // The queued moves never ran.
  b.write(R::START, 1u << 2);
  b.idle(2000);
  EXPECT_EQ(b.rises(2), 0u);
  EXPECT_EQ(b.problems(), "");
}

// START: all axes of the mask start in the same frame, the first after the frame boundary that
// follows the write; each step then rises exactly where the timing rules put it.
TEST(Wb, StartStartsAllMaskedAxesInTheSameFrame) {
  Bench b(8);
  b.bus.set_timing(3, 2);
  Rises rs;
  rs.attach(b);
  const unsigned axes[] = {0, 2, 5};
  for (unsigned k : axes) b.push(k, cruise(12, kQuarter, k != 2));
  b.push(3, cruise(5, kQuarter));  // queued but not started
  b.write(R::START, (1u << 0) | (1u << 2) | (1u << 5));
  const uint64_t f0 = start_frame(b.bus.last_request_cycle());
  EXPECT_NE(b.status(0) & A::STATUS_RUN_MASK, 0u);
  ASSERT_TRUE(b.settle());
  for (unsigned k : axes) {
    ASSERT_EQ(rs.at[k].size(), 12u) << "axis " << k;
    for (unsigned i = 0; i < 12; ++i) EXPECT_EQ(rs.at[k][i], quarter_rise(f0, i + 1)) << "axis " << k << " step " << i + 1;
  }
  EXPECT_TRUE(rs.at[3].empty());
  EXPECT_EQ(b.position(0), 12);
  EXPECT_EQ(b.position(2), -12);
  EXPECT_EQ(b.axr(2, A::POS_HI), 0xFFFFFFFFu);  // latched sign extension
  EXPECT_EQ(b.free_slots(3), 1u);
  EXPECT_EQ(b.status(3) & (A::STATUS_RUN_MASK | A::STATUS_BUSY_MASK), 0u);
  EXPECT_EQ(b.problems(), "");
}

// Chained moves continue on the next tick: with 1/4 step per tick throughout, every rise of the
// chain is 4 ticks after the one before, across every move boundary (a move pushed while the
// first runs included). When the queue runs dry the axis stops running; a later push waits for
// the next START.
TEST(Wb, ChainedMovesRunWithoutGap) {
  Bench b(9);
  b.bus.set_timing(2, 2);
  Rises rs;
  rs.attach(b);
  b.push(1, cruise(10, kQuarter));
  b.push(1, cruise(7, kQuarter));
  b.write(R::START, 1u << 1);
  const uint64_t f0 = start_frame(b.bus.last_request_cycle());
  b.idle(200);
  b.push(1, cruise(9, kQuarter));
  ASSERT_TRUE(b.settle());
  ASSERT_EQ(rs.at[1].size(), 26u);
  for (unsigned i = 0; i < 26; ++i) EXPECT_EQ(rs.at[1][i], quarter_rise(f0, i + 1)) << "step " << i + 1;
  EXPECT_EQ(b.position(1), 26);
  EXPECT_EQ(b.status(1) & A::STATUS_RUN_MASK, 0u) << "ran out of moves";
  b.push(1, cruise(3, kQuarter, false));
  b.idle(1000);
  EXPECT_EQ(rs.at[1].size(), 26u) << "a move pushed after the queue ran dry waits for START";
  b.write(R::START, 1u << 1);
  ASSERT_TRUE(b.settle());
  EXPECT_EQ(b.position(1), 23);
  EXPECT_EQ(b.axr(1, A::ERR), 0u);
  EXPECT_EQ(b.problems(), "");
}

// Planned moves of every shape chained on one axis (reversals included) and a refused and an
// empty move in between: consumed with done (and ERR.move for the refused one), the chain goes
// on; every move's steps exactly.
TEST(Wb, ChainWithPlannedRefusedAndEmptyMoves) {
  Bench b(10);
  b.bus.set_timing(1, 1);
  b.set_pulse(4, PulseConfig{3, 4, 20, 15, false, true});
  AxisMove bad = trapezoid(30);
  bad.v_max = 0;
  AxisMove empty = trapezoid(30);
  empty.steps = 0;
  const std::vector<AxisMove> moves = {encode({300, true, 2e5, 1.5e6, 1e5, 1.2e8, 6e7}).regs, bad,
                                       encode({200, false, 0, 1e6, 0, 1e8, 1e8}).regs, empty, trapezoid(50)};
  b.write(R::IRQ_ENABLE, R::IRQ_ENABLE_ERR_MASK | R::IRQ_ENABLE_DONE_MASK);
  b.push(4, moves[0]);
  b.push(4, moves[1]);
  b.write(R::START, 1u << 4);
  size_t next = 2;
  int64_t want = 0;
  unsigned errs = 0;
  while (next < moves.size() || !b.all_idle()) {
    if (next < moves.size() && b.free_slots(4) > 0) b.push(4, moves[next++]);
    if (b.axr(4, A::ERR) & A::ERR_MOVE_MASK) {
      ++errs;
      b.axw(4, A::ERR, A::ERR_MOVE_MASK);
    }
    b.idle(50);
    ASSERT_LT(b.cycle(), 5'000'000u);
  }
  for (const AxisMove& m : moves) want += m.steps == 0 || m.v_max == 0 ? 0 : (m.dir ? 1 : -1) * int64_t(m.steps);
  EXPECT_EQ(errs, 1u);
  EXPECT_EQ(b.position(4), want);
  EXPECT_EQ(b.rises(4), 300u + 200u + 50u);
  EXPECT_EQ(b.problems(), "");
}

// STOP in each phase of a move (and in the frame of a pending START, and on an idle axis): the
// queue is flushed (the queued second move never starts), running is cleared, the axis comes to
// rest (before the move's end when stopped before its deceleration), and START acts only once
// it is idle.
TEST(Wb, StopFromEveryPhase) {
  // 1/64 -> 1/32 step per tick at 2^-18 step/tick^2 (4,096 ticks, about 96 steps), cruise,
  // back to 1/64: a stop from 1/32 at that rate takes about 128 steps.
  AxisMove m;
  m.steps = 400;
  m.v_start = m.v_end = 1ull << 58;
  m.v_max = 1ull << 59;
  m.acc = m.dec = 1ull << 46;
  m.v_dec = m.v_max - (m.dec >> 1);
  m.acc_steps = 200;
  m.dec_step = 304;
  ASSERT_EQ(validate_move(m), 0u);
  for (unsigned want = 1; want <= 3; ++want) {
    SCOPED_TRACE("phase " + std::to_string(want));
    Bench b(11 + want);
    const unsigned k = want;
    b.push(k, m);
    b.push(k, m);
    b.write(R::START, 1u << k);
    uint32_t st = 0;
    for (int i = 0; i < 200000; ++i) {
      st = b.status(k);
      const unsigned ph = (st & A::STATUS_PHASE_MASK) >> A::STATUS_PHASE_SHIFT;
      if (ph == want && (want != 2 || b.rises(k) > 150)) break;
    }
    ASSERT_EQ((st & A::STATUS_PHASE_MASK) >> A::STATUS_PHASE_SHIFT, want);
    b.write(R::STOP, 1u << k);
    b.idle(2 * kFrameCycles);  // the STOP acts at the next frame boundary, in the axis's slot
    st = b.status(k);
    EXPECT_EQ((st & A::STATUS_FREE_MASK) >> A::STATUS_FREE_SHIFT, 2u) << "queue flushed";
    EXPECT_EQ(st & A::STATUS_RUN_MASK, 0u);
    while (b.status(k) & A::STATUS_BUSY_MASK) {
      b.write(R::START, 1u << k);  // nothing queued: no effect
      b.idle(50);
      ASSERT_LT(b.cycle(), 3'000'000u);
    }
    const int64_t pos = b.position(k);
    EXPECT_EQ(uint64_t(pos), b.rises(k));
    if (want < 3) EXPECT_LT(pos, int64_t(m.steps)) << "stopped before the planned end";
    else EXPECT_LE(pos, int64_t(m.steps));
    EXPECT_EQ(b.axr(k, A::ERR), 0u);
    EXPECT_EQ(b.problems(), "");
  }
  {  // STOP and START reaching the same frame: nothing starts, the queue is flushed.
    Bench b(20);
    b.push(0, m);
    b.write(R::START, 1);
    b.write(R::STOP, 1);
    b.idle(3000);
    EXPECT_EQ(b.rises(0), 0u);
    EXPECT_EQ(b.free_slots(0), 2u);
    EXPECT_EQ(b.status(0) & (A::STATUS_RUN_MASK | A::STATUS_BUSY_MASK), 0u);
    // STOP on an idle axis: nothing happens; the next move runs normally.
    b.write(R::STOP, 1);
    b.idle(100);
    b.push(0, cruise(9, kQuarter));
    b.write(R::START, 1);
    ASSERT_TRUE(b.settle());
    EXPECT_EQ(b.position(0), 9);
    EXPECT_EQ(b.axr(0, A::ERR), 0u);
    EXPECT_EQ(b.problems(), "");
  }
}

// A flush of the queue while a push loads drops the push: STOP written just before a push
// flushes at the next frame boundary, in the middle of the push's ~106 cycles.
TEST(Wb, FlushDuringAPushDropsIt) {
  Bench b(21);
  b.push(3, cruise(400, kQuarter));
  b.write(R::START, 1u << 3);
  b.idle(500);
  write_move(b.bus, 3, cruise(50, kQuarter));
  b.write(R::STOP, 1u << 3);
  b.axw(3, A::CMD, A::CMD_PUSH_MASK);
  EXPECT_EQ(b.free_slots(3), 2u) << "the push loading across the flush is dropped";
  ASSERT_TRUE(b.settle());
  EXPECT_LT(b.position(3), 400);
  b.write(R::START, 1u << 3);
  b.idle(2000);
  EXPECT_EQ(uint64_t(b.position(3)), b.rises(3)) << "nothing left to start";
  EXPECT_EQ(b.problems(), "");
}

// ABORT stops the axis on the edge after the write: no STEP rises from then on, a pulse already
// high completes, the queue is flushed, the other axes run on.
TEST(Wb, AbortStopsAndFlushes) {
  Bench b(22);
  b.bus.set_timing(1, 0);
  b.set_pulse(0, PulseConfig{9, 3, 0, 0, false, false});
  Rises rs;
  rs.attach(b);
  b.push(0, cruise(1000, kQuarter));
  b.push(0, cruise(1000, kQuarter));
  b.push(5, cruise(300, kQuarter, false));
  b.write(R::START, 1u | (1u << 5));
  b.idle(3001);
  EXPECT_NE(b.status(0) & A::STATUS_BUSY_MASK, 0u);
  b.write(R::ABORT, 1u);
  const uint64_t stop_edge = abort_edge(b.bus.last_request_cycle());
  b.idle(200);
  for (uint64_t c : rs.at[0]) EXPECT_LE(c, stop_edge) << "STEP rose after the abort edge";
  const uint32_t s = b.status(0);
  EXPECT_EQ(s & (A::STATUS_BUSY_MASK | A::STATUS_RUN_MASK), 0u);
  EXPECT_EQ((s & A::STATUS_FREE_MASK) >> A::STATUS_FREE_SHIFT, 2u);
  const int64_t pos = b.position(0);
  EXPECT_EQ(uint64_t(pos), rs.at[0].size());
  EXPECT_GT(pos, 0);
  EXPECT_LT(pos, 1000);
  ASSERT_TRUE(b.settle());
  EXPECT_EQ(b.position(5), -300) << "axis 5 ran on";
  EXPECT_EQ(b.problems(), "");  // the monitor saw the pulse high at the abort complete its 9 cycles
}

// E-STOP: pin -> 2-flop synchronizer -> latch, which aborts every axis on the edge after it is
// set and on every edge while set: no STEP rises from the fourth edge after the pin rises,
// queues are flushed, ERR.estop is set on every axis, pushes and starts are dropped; the latch
// clears only with the pin low.
TEST(Wb, EstopLatchesAbortsAllAxesAndClears) {
  Bench b(23);
  b.bus.set_timing(1, 1);
  Rises rs;
  rs.attach(b);
  for (unsigned k = 0; k < kNumAxes; ++k) b.push(k, cruise(1000, 1ull << 61));
  b.write(R::IRQ_ENABLE, R::IRQ_ENABLE_ERR_MASK);
  b.write(R::START, kAll);
  b.idle(1000);
  for (unsigned k = 0; k < kNumAxes; ++k) EXPECT_NE(b.status(k) & A::STATUS_BUSY_MASK, 0u);
  b.bus.set_estop(true);
  const uint64_t pin = b.cycle();  // first cycle with the pin high
  b.idle(300);
  for (unsigned k = 0; k < kNumAxes; ++k)
    for (uint64_t c : rs.at[k]) EXPECT_LE(c, pin + 3) << "rising STEP after e-stop, axis " << k;
  EXPECT_EQ(b.read(R::GSTATUS), R::GSTATUS_ESTOP_MASK | R::GSTATUS_ESTOP_PIN_MASK);
  EXPECT_TRUE(b.mon.irq());
  for (unsigned k = 0; k < kNumAxes; ++k) {
    EXPECT_EQ(b.status(k), A::STATUS_RESET) << k;  // idle, empty
    EXPECT_EQ(b.axr(k, A::ERR), A::ERR_ESTOP_MASK) << k;
    EXPECT_EQ(uint64_t(b.position(k)), rs.at[k].size()) << k;
  }
  write_move(b.bus, 0, cruise(10, 1ull << 61));
  b.axw(0, A::CMD, A::CMD_PUSH_MASK);
  b.write(R::START, 1u);
  EXPECT_EQ(b.status(0), A::STATUS_RESET) << "push and start dropped while latched";
  b.write(R::GSTATUS, R::GSTATUS_ESTOP_MASK);  // pin still high: sets again at once
  EXPECT_EQ(b.read(R::GSTATUS) & R::GSTATUS_ESTOP_MASK, R::GSTATUS_ESTOP_MASK);
  b.bus.set_estop(false);
  b.idle(4);
  EXPECT_EQ(b.read(R::GSTATUS), R::GSTATUS_ESTOP_MASK) << "latched after the pin fell";
  b.write(R::GSTATUS, R::GSTATUS_ESTOP_MASK);
  EXPECT_EQ(b.read(R::GSTATUS), 0u);
  b.axw(0, A::CMD, A::CMD_PUSH_MASK);
  b.write(R::START, 1u);
  EXPECT_NE(b.status(0) & A::STATUS_RUN_MASK, 0u) << "works again after the clear";
  const int64_t p0 = b.position(0);
  ASSERT_TRUE(b.settle());
  EXPECT_EQ(b.position(0), p0 + 10);
  EXPECT_EQ(b.problems(), "");
}

// IRQ_PENDING: slot when a queue entry becomes free (the start's pop), done when busy falls
// and when a move is consumed, err with any AXIS_ERR flag; irq = pending & enable; write 1 to
// clear; a set wins over a clear in the same cycle.
TEST(Wb, InterruptsSetAndClear) {
  Bench b(24);
  b.bus.set_timing(1, 1);
  EXPECT_FALSE(b.mon.irq());
  b.push(3, cruise(5, kQuarter));
  b.write(R::IRQ_ENABLE, 1u << (R::IRQ_ENABLE_DONE_SHIFT + 3));
  b.write(R::START, 1u << 3);
  b.idle(kFrameCycles + 20);
  EXPECT_EQ(b.read(R::IRQ_PENDING), 1u << (R::IRQ_PENDING_SLOT_SHIFT + 3)) << "the pop freed an entry";
  EXPECT_FALSE(b.mon.irq()) << "slot is not enabled";
  ASSERT_TRUE(b.settle());
  b.idle(4);
  EXPECT_TRUE(b.mon.irq());
  EXPECT_EQ(b.read(R::IRQ_PENDING), (1u << (R::IRQ_PENDING_DONE_SHIFT + 3)) | (1u << (R::IRQ_PENDING_SLOT_SHIFT + 3)));
  b.write(R::IRQ_PENDING, 1u << (R::IRQ_PENDING_DONE_SHIFT + 3));
  EXPECT_FALSE(b.mon.irq());
  b.write(R::IRQ_ENABLE, 1u << (R::IRQ_ENABLE_SLOT_SHIFT + 3));
  EXPECT_TRUE(b.mon.irq());
  b.write(R::IRQ_PENDING, 0xFFFFFFFFu);
  EXPECT_FALSE(b.mon.irq());
  EXPECT_EQ(b.read(R::IRQ_PENDING), 0u);
  // A refused move (v_max = 0) is consumed at its start: done, ERR.move, the error interrupt.
  b.write(R::IRQ_ENABLE, R::IRQ_ENABLE_ERR_MASK);
  AxisMove bad = cruise(5, kQuarter);
  bad.v_max = 0;
  b.push(3, bad);
  b.write(R::START, 1u << 3);
  b.idle(2 * kFrameCycles);
  EXPECT_EQ(b.axr(3, A::ERR), A::ERR_MOVE_MASK);
  EXPECT_TRUE(b.mon.irq());
  EXPECT_EQ(b.read(R::IRQ_PENDING), (1u << (R::IRQ_PENDING_DONE_SHIFT + 3)) | (1u << (R::IRQ_PENDING_SLOT_SHIFT + 3)) |
                                        (1u << (R::IRQ_PENDING_ERR_SHIFT + 3)));
  EXPECT_EQ(b.rises(3), 5u);
  // An empty move (steps = 0) is consumed with done and no error.
  b.axw(3, A::ERR, 0xFFFFFFFFu);
  b.write(R::IRQ_PENDING, 0xFFFFFFFFu);
  AxisMove empty = cruise(0, kQuarter);
  b.push(3, empty);
  b.write(R::START, 1u << 3);
  b.idle(2 * kFrameCycles);
  EXPECT_EQ(b.axr(3, A::ERR), 0u);
  EXPECT_EQ(b.read(R::IRQ_PENDING), (1u << (R::IRQ_PENDING_DONE_SHIFT + 3)) | (1u << (R::IRQ_PENDING_SLOT_SHIFT + 3)));
  // Set wins over clear: a write-1-to-clear of every pending bit acted on at the very edge of
  // the pop (axis 3's sample edge of the START's frame, F0 + 4*3 - 1) leaves slot set.
  b.write(R::IRQ_PENDING, 0xFFFFFFFFu);
  b.push(3, cruise(2, kQuarter));
  b.write(R::START, 1u << 3);
  const uint64_t pop = start_frame(b.bus.last_request_cycle()) + kSlotCycles * 3 - 1;
  while (b.cycle() < pop - kTakeCycles) b.bus.tick();
  b.bus.drive(true, true, true, R::IRQ_PENDING, 0xFFFFFFFFu, 0xF);  // acted on at the edge ending `pop`
  for (unsigned i = 0; i < kTakeCycles + 2; ++i) b.bus.tick();
  b.bus.drive(false, false, false, 0, 0, 0);
  EXPECT_EQ(b.read(R::IRQ_PENDING) & (1u << (R::IRQ_PENDING_SLOT_SHIFT + 3)), 1u << (R::IRQ_PENDING_SLOT_SHIFT + 3));
  EXPECT_EQ(b.problems(), "");
}

// POS_LO then POS_HI is one 64-bit read even when the position changes sign between the two
// reads: the pair always equals the position at the POS_LO read.
TEST(Wb, PositionReadIsAtomicWhileTheCounterCrossesZero) {
  Bench b(25);
  const AxisMove up = cruise(40, kQuarter);
  AxisMove jog = cruise(0, kQuarter, false);
  jog.jog = true;
  jog.dec = 1ull << 40;
  b.push(1, up);
  b.push(1, jog);
  b.bus.set_timing(4, 6);
  b.write(R::START, 1u << 1);
  unsigned crossings = 0, reads = 0;
  int64_t prev = 0;
  while (b.cycle() < 60000 && b.pair.mismatches() == 0) {
    const uint32_t lo = b.axr(1, A::POS_LO);
    const int64_t at_lo = b.m().pulse(1).position();
    b.idle(reads % 37);  // the counter moves on meanwhile
    const uint32_t hi = b.axr(1, A::POS_HI);
    const int64_t pos = static_cast<int64_t>((uint64_t(hi) << 32) | lo);
    ASSERT_EQ(hi, static_cast<int32_t>(lo) < 0 ? 0xFFFFFFFFu : 0u) << "read " << reads;
    ASSERT_LE(std::llabs(pos - at_lo), 1) << "read " << reads;
    if ((pos < 0) != (prev < 0)) ++crossings;
    prev = pos;
    ++reads;
  }
  b.write(R::STOP, 1u << 1);
  EXPECT_GE(crossings, 1u);
  EXPECT_LT(prev, -10);
  EXPECT_EQ(b.problems(), "");
}

// A jog move runs past its STEPS field and ends only on STOP.
TEST(Wb, JogRunsUntilStop) {
  Bench b(26);
  AxisMove m;
  m.v_max = 1ull << 61;
  m.acc = 1ull << 47;  // 2^-17 step/tick^2: 16,384 ticks to 1/8 step per tick
  m.dec = 1ull << 47;
  m.steps = 3;
  m.jog = true;
  b.push(0, m);
  b.write(R::START, 1);
  b.idle(20000 * kFrameCycles);  // the ramp (1,024 steps), then 3,616 ticks at 1/8: 452 steps
  EXPECT_NE(b.status(0) & A::STATUS_BUSY_MASK, 0u);
  EXPECT_NEAR(double(b.position(0)), 1024.0 + 452.0, 10.0);
  b.write(R::STOP, 1);
  b.idle(20000 * kFrameCycles);  // stopping from 1/8 takes 16,384 ticks, 1,024 steps
  EXPECT_EQ(b.status(0) & A::STATUS_BUSY_MASK, 0u);
  EXPECT_NEAR(double(b.position(0)), 1024.0 + 452.0 + 1024.0, 12.0);
  EXPECT_EQ(b.problems(), "");
}

// The pulse timing and polarity registers reach the pins: the monitor checks the written high,
// low, setup and hold times; the pins invert.
TEST(Wb, PulseTimingAndPolarityReachThePins) {
  Bench b(27);
  b.bus.set_timing(1, 1);
  const PulseConfig pc{7, 11, 25, 13, true, true};
  b.set_pulse(5, pc);
  EXPECT_TRUE(b.mon.step(5)) << "STEP inverted at rest";
  EXPECT_FALSE(b.mon.dir(5)) << "DIR inverted (positive reads low)";
  const PulseConfig got = b.m().pulse_config(5);
  EXPECT_EQ(got.step_high, 7u);
  EXPECT_EQ(got.step_low, 11u);
  EXPECT_EQ(got.dir_setup, 25u);
  EXPECT_EQ(got.dir_hold, 13u);
  b.push(5, trapezoid(40, false));
  b.push(5, trapezoid(30, true));
  b.write(R::START, 1u << 5);
  ASSERT_TRUE(b.settle());
  EXPECT_EQ(b.rises(5), 70u);
  EXPECT_EQ(b.position(5), -10);
  EXPECT_EQ(b.problems(), "");
}

// Rewriting every staging word while a move runs and another is queued changes neither.
TEST(Wb, StagingWritesNeverChangeTheQueuedMoves) {
  Bench b(28);
  b.bus.set_timing(1, 1);
  b.push(4, trapezoid(40));
  b.push(4, trapezoid(35, false));
  b.write(R::START, 1u << 4);
  write_move(b.bus, 4, cruise(3, ~0ull, false));
  ASSERT_TRUE(b.settle());
  EXPECT_EQ(b.rises(4), 75u);
  EXPECT_EQ(b.position(4), 5);
  EXPECT_EQ(b.axr(4, A::STEPS), 3u) << "the staging registers keep what was written";
  EXPECT_EQ(b.problems(), "");
}
