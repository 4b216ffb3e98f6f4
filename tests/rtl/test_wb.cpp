// SPDX-License-Identifier: Apache-2.0
// Wishbone register interface (rtl/hexstep_wb.v inside rtl/hexstep_top.v): the bus, the
// register map (offsets and reset values generated from rdl/hexstep.rdl, so a hand-written
// decode that disagrees with the map fails here), the move queue, START/ABORT/E-stop and IRQ.
// Motion is checked against the golden model hexstep::CoreModel, fed the same moves at the
// edges the documented queue semantics give (class Ref), STEP/DIR compared after every edge.
#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <functional>
#include <vector>

#include "hexstep/core.hpp"
#include "hexstep_regs.hpp"
#include "wb_bfm.hpp"

using namespace hexstep;
namespace R = hexstep::regs;

namespace {

constexpr uint32_t ax(unsigned k, uint32_t reg) { return R::AXIS_BASE + k * R::AXIS_STRIDE + reg; }
constexpr uint32_t kAllAxes = (1u << kNumAxes) - 1u;

// Reference of the bus block's queue semantics around the golden core model. edge() runs after
// every RTL edge: it ticks the model with the inputs the RTL core saw at that edge and compares
// the pins. Commands written over the bus take effect when their ack is seen (the slave acts at
// the edge that raises ack): arm() registers what to do then.
struct Ref {
  explicit Ref(WbTop& b) : bus(b) { b.on_edge = [this] { edge(); }; }
  WbTop& bus;
  CoreModel model;
  CoreInputs in;
  std::array<std::deque<AxisMove>, kNumAxes> q;
  uint32_t run = 0, start_next = 0, abort_next = 0;
  std::function<void()> on_ack;
  bool skip_compare = false;
  uint64_t mismatches = 0, edges = 0;
  std::array<std::vector<uint64_t>, kNumAxes> starts;  // edge index of every core start
  std::array<std::vector<uint64_t>, kNumAxes> dones;   // edge index after which done was high
  std::array<uint64_t, kNumAxes> rises{};

  // skip_at_ack: do not compare the pins at the ack edge (a polarity write shows on the RTL pins
  // at once, while the model takes it with the inputs of the next edge).
  void arm(std::function<void()> f, bool skip_at_ack = false) {
    on_ack = std::move(f);
    skip_at_ack_ = skip_at_ack;
  }
  bool skip_at_ack_ = false;
  void edge() {
    if (bus.ack() && on_ack && skip_at_ack_) skip_compare = true;
    uint32_t start = 0;
    const uint32_t abort = abort_next;
    for (unsigned k = 0; k < kNumAxes; ++k) {
      const uint32_t b = 1u << k;
      const bool chain = (run & b) && model.out(k).done;
      if (abort & b) {
        q[k].clear();
        run &= ~b;
        continue;
      }
      if (!q[k].empty() && (((start_next & b) && !(run & b)) || chain)) {
        in.move[k] = q[k].front();
        q[k].pop_front();
        start |= b;
        run |= b;
        starts[k].push_back(edges);
      } else if (chain) {
        run &= ~b;
      }
    }
    in.start_mask = start;
    in.abort_mask = abort;
    std::array<bool, kNumAxes> prev{};
    for (unsigned k = 0; k < kNumAxes; ++k) prev[k] = model.axis(k).step_level();
    model.tick(in);
    start_next = abort_next = 0;
    for (unsigned k = 0; k < kNumAxes; ++k) {
      if (model.axis(k).step_level() && !prev[k]) ++rises[k];
      if (model.out(k).done) dones[k].push_back(edges);
      if (skip_compare) continue;
      const AxisOutputs o = model.out(k);
      if (o.step != bus.step(k) || o.dir != bus.dir(k)) {
        if (mismatches < 10)
          ADD_FAILURE() << "edge " << edges << " axis " << k << ": model step/dir " << o.step << o.dir
                        << ", rtl " << bus.step(k) << bus.dir(k);
        ++mismatches;
      }
    }
    skip_compare = false;
    ++edges;
    if (bus.ack() && on_ack) {
      auto f = std::move(on_ack);
      on_ack = nullptr;
      f();
    }
  }
  bool idle() const {
    for (unsigned k = 0; k < kNumAxes; ++k)
      if (model.out(k).busy || ((run >> k) & 1u)) return false;
    return true;
  }
};

void write_move(WbTop& bus, unsigned k, const AxisMove& m) {
  auto w64 = [&](uint32_t lo, uint64_t v) {
    bus.write(ax(k, lo), static_cast<uint32_t>(v));
    bus.write(ax(k, lo + 4), static_cast<uint32_t>(v >> 32));
  };
  bus.write(ax(k, R::axis::STEPS), m.steps);
  bus.write(ax(k, R::axis::DIR), m.dir ? 1u : 0u);
  w64(R::axis::V_START_LO, m.v_start);
  w64(R::axis::V_MAX_LO, m.v_max);
  w64(R::axis::V_END_LO, m.v_end);
  w64(R::axis::V_DEC_LO, m.v_dec);
  w64(R::axis::ACC_LO, m.acc);
  w64(R::axis::DEC_LO, m.dec);
  bus.write(ax(k, R::axis::ACC_STEPS), m.acc_steps);
  bus.write(ax(k, R::axis::DEC_STEP), m.dec_step);
  bus.write(ax(k, R::axis::DEC_FRAC), m.dec_frac);
}
// Stage and push a move; the reference queue gets it at the push's ack.
void push(WbTop& bus, Ref* ref, unsigned k, const AxisMove& m) {
  write_move(bus, k, m);
  if (ref) ref->arm([ref, k, m] { if (ref->q[k].size() < 2) ref->q[k].push_back(m); });
  bus.write(ax(k, R::axis::CMD), R::axis::CMD_PUSH_MASK);
}
void start(WbTop& bus, Ref& ref, uint32_t mask) {
  ref.arm([&ref, mask] { ref.start_next = mask; });
  bus.write(R::START, mask);
}
void run_until_idle(WbTop& bus, Ref& ref, uint64_t limit = 200000) {
  for (uint64_t i = 0; i < limit && !ref.idle(); ++i) bus.tick();
  for (int i = 0; i < 20; ++i) bus.tick();
  ASSERT_TRUE(ref.idle());
}

// Trapezoid: accelerate, cruise at 1/8 step per tick, decelerate (validated below).
AxisMove trapezoid(uint32_t steps, bool dir = true) {
  AxisMove m;
  m.steps = steps;
  m.dir = dir;
  m.v_start = 1ull << 58;
  m.v_max = 1ull << 61;
  m.acc = 1ull << 43;  // the largest power of two in the 44-bit ACC/DEC registers
  m.dec = 1ull << 43;
  m.v_end = 1ull << 58;
  m.v_dec = (1ull << 61) - (1ull << 54);
  m.acc_steps = steps / 4;
  m.dec_step = steps - steps / 4;
  m.dec_frac = 0x80000000u;
  return m;
}
AxisMove cruise(uint32_t steps, uint64_t speed, bool dir = true) {
  AxisMove m;
  m.steps = steps;
  m.dir = dir;
  m.v_start = m.v_max = m.v_end = m.v_dec = speed;
  m.dec_step = steps;
  return m;
}

TEST(Wb, MovesUsedHereAreValid) {
  EXPECT_EQ(validate_move(trapezoid(40)), 0u);
  EXPECT_EQ(validate_move(cruise(10, 1ull << 62)), 0u);
  // Every value fits its register (the bus keeps only ACC_W bits of ACC/DEC).
  const Widths w;
  EXPECT_EQ(trapezoid(40).acc & ~w.acc_mask(), 0u);
  EXPECT_EQ(trapezoid(40).dec & ~w.acc_mask(), 0u);
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
  write_move(bus, 2, trapezoid(40));
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
  Ref ref(bus);
  const unsigned axes[] = {0, 2, 5};
  for (unsigned k : axes) push(bus, &ref, k, trapezoid(40, k != 2));
  push(bus, &ref, 3, trapezoid(30));  // queued but not started
  start(bus, ref, (1u << 0) | (1u << 2) | (1u << 5));
  run_until_idle(bus, ref, 5000);
  for (unsigned k : axes) {
    ASSERT_EQ(ref.starts[k].size(), 1u);
    EXPECT_EQ(ref.starts[k][0], ref.starts[0][0]) << "axis " << k;
    EXPECT_EQ(ref.rises[k], 40u);
  }
  EXPECT_EQ(ref.starts[3].size(), 0u);
  EXPECT_EQ(ref.mismatches, 0u);
  EXPECT_EQ(ref.q[3].size(), 1u);  // the RTL still holds it too (STATUS.free below)
  EXPECT_EQ(static_cast<int32_t>(bus.read(ax(0, R::axis::POS_LO))), 40);
  EXPECT_EQ(static_cast<int32_t>(bus.read(ax(2, R::axis::POS_LO))), -40);
  EXPECT_EQ(bus.read(ax(2, R::axis::POS_HI)), 0xFFFFFFFFu);  // latched sign extension
  EXPECT_EQ(bus.read(ax(3, R::axis::STATUS)) & R::axis::STATUS_FREE_MASK, 1u << R::axis::STATUS_FREE_SHIFT);
  EXPECT_EQ(bus.protocol_errors(), 0u);
}

TEST(Wb, ChainedMovesRunWithoutGap) {
  WbTop bus(7);
  bus.set_timing(2, 2);
  Ref ref(bus);
  push(bus, &ref, 1, trapezoid(40));
  push(bus, &ref, 1, cruise(12, 1ull << 62, false));
  start(bus, ref, 1u << 1);
  // While the first runs, a third move fills the freed slot and chains too.
  for (int i = 0; i < 30; ++i) bus.tick();
  push(bus, &ref, 1, trapezoid(20));
  run_until_idle(bus, ref, 5000);
  ASSERT_EQ(ref.starts[1].size(), 3u);
  ASSERT_GE(ref.dones[1].size(), 2u);
  // The core's start for move n+1 is at the edge right after the cycle move n's done was high.
  EXPECT_EQ(ref.starts[1][1], ref.dones[1][0] + 1);
  EXPECT_EQ(ref.starts[1][2], ref.dones[1][1] + 1);
  EXPECT_EQ(ref.rises[1], 72u);
  EXPECT_EQ(ref.mismatches, 0u);
  EXPECT_EQ(static_cast<int32_t>(bus.read(ax(1, R::axis::POS_LO))), 40 - 12 + 20);
  EXPECT_EQ(bus.read(ax(1, R::axis::STATUS)) & R::axis::STATUS_RUN_MASK, 0u);  // ran out of moves
  EXPECT_EQ(bus.read(ax(1, R::axis::ERR)), 0u);
}

TEST(Wb, StagingWritesNeverChangeTheRunningMove) {
  WbTop bus(8);
  bus.set_timing(1, 1);
  Ref ref(bus);
  push(bus, &ref, 4, trapezoid(40));
  start(bus, ref, 1u << 4);
  // Rewrite every staging word with other values while the move runs (no push).
  write_move(bus, 4, cruise(3, 1ull << 63, false));
  run_until_idle(bus, ref, 5000);
  EXPECT_EQ(ref.rises[4], 40u);
  EXPECT_EQ(ref.mismatches, 0u);
  EXPECT_EQ(static_cast<int32_t>(bus.read(ax(4, R::axis::POS_LO))), 40);
}

TEST(Wb, AbortStopsAndFlushes) {
  WbTop bus(9);
  bus.set_timing(1, 0);
  Ref ref(bus);
  push(bus, &ref, 0, cruise(1000, 1ull << 60));
  push(bus, &ref, 0, cruise(1000, 1ull << 60));
  start(bus, ref, 1u);
  for (int i = 0; i < 200; ++i) bus.tick();
  EXPECT_NE(bus.read(ax(0, R::axis::STATUS)) & R::axis::STATUS_BUSY_MASK, 0u);
  ref.arm([&ref] { ref.abort_next = 1u; });
  bus.write(R::ABORT, 1u);
  for (int i = 0; i < 100; ++i) bus.tick();
  EXPECT_TRUE(ref.idle());
  EXPECT_EQ(ref.mismatches, 0u);
  const uint32_t s = bus.read(ax(0, R::axis::STATUS));
  EXPECT_EQ(s & (R::axis::STATUS_BUSY_MASK | R::axis::STATUS_RUN_MASK), 0u);
  EXPECT_EQ((s & R::axis::STATUS_FREE_MASK) >> R::axis::STATUS_FREE_SHIFT, 2u);
  EXPECT_EQ(static_cast<int64_t>(static_cast<int32_t>(bus.read(ax(0, R::axis::POS_LO)))),
            ref.model.out(0).pos);
  EXPECT_GT(ref.model.out(0).pos, 0);
  EXPECT_LT(ref.model.out(0).pos, 1000);
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
  Ref ref(bus);
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
  ref.arm([&ref, pc] { ref.in.pulse[5] = pc; }, true);
  bus.write(ax(5, R::axis::POLARITY), R::axis::POLARITY_STEP_INV_MASK | R::axis::POLARITY_DIR_INV_MASK);
  // The model sees the new timing from the edge after the write; polarity shows at once on
  // the RTL pins, so the ack edge is not compared.
  push(bus, &ref, 5, trapezoid(40, false));
  start(bus, ref, 1u << 5);
  run_until_idle(bus, ref, 5000);
  EXPECT_EQ(ref.rises[5], 40u);
  EXPECT_EQ(ref.mismatches, 0u);
}

}  // namespace
