// SPDX-License-Identifier: Apache-2.0
// hexstep_top (Verilated) against the golden register-block model hexstep::WbModel, cycle by
// cycle: ack, read data, IRQ and every STEP/DIR pin after every clock edge, under random bus
// traffic with random wait states and idle cycles on all six axes (moves, jog moves, START,
// STOP, ABORT, E-stop, IRQ and error registers, pulse configuration, stray writes anywhere),
// and STOP through the bus in each phase of a move.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "hexstep/wb_model.hpp"
#include "hexstep_regs.hpp"
#include "vectors.hpp"
#include "wb_bfm.hpp"

using namespace hexstep;
namespace R = hexstep::regs;
namespace A = hexstep::regs::axis;

namespace {

constexpr uint32_t ax(unsigned k, uint32_t reg) { return R::AXIS_BASE + k * R::AXIS_STRIDE + reg; }

uint64_t env_u64(const char* name, uint64_t dflt) {
  const char* s = std::getenv(name);
  return s && *s ? std::strtoull(s, nullptr, 0) : dflt;
}

// The Verilated top and the model, fed the same pins before every edge and compared after it.
struct Pair {
  explicit Pair(uint32_t seed) : bus(seed) {
    bus.pre_edge = [this](const WbPins& p) { model.tick(p); };
    bus.on_edge = [this] { compare(); };
  }
  WbTop bus;
  WbModel model;
  uint64_t mismatches = 0, rises = 0, stop_edges = 0;
  std::array<bool, kNumAxes> prev_step{};

  void compare() {
    bool bad = bus.ack() != model.ack() || bus.dat_o() != model.dat() || bus.irq() != model.irq();
    for (unsigned k = 0; k < kNumAxes; ++k) {
      bad |= bus.step(k) != model.step(k) || bus.dir(k) != model.dir(k);
      const bool lvl = model.core().axis(k).step_level();
      if (lvl && !prev_step[k]) ++rises;
      prev_step[k] = lvl;
      if (model.core().axis(k).stopping()) ++stop_edges;
    }
    if (bad) {
      if (mismatches < 5) {
        std::string pins;
        for (unsigned k = 0; k < kNumAxes; ++k)
          pins += " " + std::to_string(bus.step(k)) + std::to_string(model.step(k)) +
                  std::to_string(bus.dir(k)) + std::to_string(model.dir(k));
        ADD_FAILURE() << "cycle " << bus.cycles() << ": ack rtl " << bus.ack() << " model "
                      << model.ack() << ", dat rtl 0x" << std::hex << bus.dat_o() << " model 0x"
                      << model.dat() << std::dec << ", irq rtl " << bus.irq() << " model "
                      << model.irq() << ", step/dir rtl-model per axis" << pins;
      }
      ++mismatches;
    }
  }
  void idle(unsigned n) {
    bus.drive(false, false, false, 0, 0, 0);
    for (unsigned i = 0; i < n; ++i) bus.tick();
  }
};

void write_move(WbTop& bus, unsigned k, const AxisMove& m) {
  bus.write(ax(k, A::STEPS), m.steps);
  bus.write(ax(k, A::DIR), (m.dir ? 1u : 0u) | (m.jog ? 2u : 0u));
  const std::pair<uint32_t, uint64_t> wide[] = {{A::V_START_LO, m.v_start}, {A::V_MAX_LO, m.v_max},
                                                {A::V_END_LO, m.v_end},     {A::V_DEC_LO, m.v_dec},
                                                {A::ACC_LO, m.acc},         {A::DEC_LO, m.dec}};
  for (const auto& [off, v] : wide) {
    bus.write(ax(k, off), static_cast<uint32_t>(v));
    bus.write(ax(k, off + 4), static_cast<uint32_t>(v >> 32));
  }
  bus.write(ax(k, A::ACC_STEPS), m.acc_steps);
  bus.write(ax(k, A::DEC_STEP), m.dec_step);
  bus.write(ax(k, A::DEC_FRAC), m.dec_frac);
}

// A short planned move (a few hundred steps at up to 2 M steps/s) so that many complete.
AxisMove short_move(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  test::Ramp r{};
  r.steps = 1 + static_cast<uint32_t>(rng() % 400);
  r.dir = rng() & 1;
  r.v_max = 2e4 + u(rng) * 2e6;
  r.v_start = (rng() % 3 == 0) ? 0 : u(rng) * r.v_max * 0.5;
  r.v_end = (rng() % 3 == 0) ? 0 : u(rng) * r.v_max * 0.5;
  r.accel = 1e8 + u(rng) * 4e9;
  r.decel = std::min<real>(r.accel * (0.25 + u(rng) * 3.75), 9e9);  // 9.5e9: largest at 100 MHz
  return test::encode(r).regs;
}

}  // namespace

TEST(WbModel, RandomBusTrafficMatchesModelEveryCycle) {
  const uint64_t seed = test::test_seed();
  std::printf("SEED=%llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  Pair p(static_cast<uint32_t>(seed));
  p.bus.set_timing(3, 3);
  const uint64_t cycles = env_u64("WB_MODEL_CYCLES", 1'500'000);
  unsigned ops[16] = {};
  while (p.bus.cycles() < cycles && p.mismatches == 0) {
    const unsigned k = static_cast<unsigned>(rng() % kNumAxes);
    const unsigned op = static_cast<unsigned>(rng() % 100);
    if (op < 22) {  // stage and push a move (planned, raw, or jog)
      AxisMove m = short_move(rng);
      if (rng() % 8 == 0) m = test::random_raw_move(rng);
      if (rng() % 10 == 0) m.jog = true;
      write_move(p.bus, k, m);
      p.bus.write(ax(k, A::CMD), 1);
      ++ops[0];
    } else if (op < 32) {  // START on a random mask
      p.bus.write(R::START, static_cast<uint32_t>(rng()) & 0x3F);
      ++ops[1];
    } else if (op < 36) {  // STOP
      p.bus.write(R::STOP, 1u << k);
      ++ops[2];
    } else if (op < 37) {  // ABORT
      p.bus.write(R::ABORT, 1u << k);
      ++ops[3];
    } else if (op < 38) {  // E-stop pin pulse, later cleared
      p.bus.set_estop(true);
      p.idle(static_cast<unsigned>(rng() % 6));
      p.bus.set_estop(false);
      p.idle(3);
      p.bus.write(R::GSTATUS, 1);
      ++ops[4];
    } else if (op < 58) {  // reads of status-like registers
      static const uint32_t regs[] = {A::STATUS, A::ERR, A::POS_LO, A::POS_HI, A::STEPS,
                                      A::DIR, A::POLARITY};
      p.bus.read(ax(k, regs[rng() % 7]));
      if (rng() & 1) p.bus.read(R::IRQ_PENDING);
      ++ops[5];
    } else if (op < 61) {  // interrupts: enable, clear pending, clear errors
      p.bus.write(R::IRQ_ENABLE, static_cast<uint32_t>(rng()), static_cast<unsigned>(rng() % 16));
      p.bus.write(R::IRQ_PENDING, static_cast<uint32_t>(rng()));
      p.bus.write(ax(k, A::ERR), static_cast<uint32_t>(rng()));
      ++ops[6];
    } else if (op < 63) {  // live pulse timing and polarity (small values keep moves going)
      static const uint32_t regs[] = {A::STEP_HIGH, A::STEP_LOW, A::DIR_SETUP, A::DIR_HOLD,
                                      A::POLARITY};
      p.bus.write(ax(k, regs[rng() % 5]), static_cast<uint32_t>(rng() % 8),
                  static_cast<unsigned>(rng() % 16));
      ++ops[7];
    } else if (op < 65) {  // stray access anywhere in the 4 KiB window, random byte enables
      const uint32_t adr = static_cast<uint32_t>(rng() % 4096);
      if (adr >= R::AXIS_BASE && (adr & 0x7F) >= A::STEP_HIGH && (adr & 0x7F) <= A::POLARITY) {
        p.bus.read(adr);  // keep pulse timing sane (a 4095-cycle STEP would stall the test)
      } else if (rng() & 1) {
        p.bus.write(adr, static_cast<uint32_t>(rng()), static_cast<unsigned>(rng() % 16));
      } else {
        p.bus.read(adr);
      }
      ++ops[8];
    } else {  // let the axes move
      p.idle(static_cast<unsigned>(rng() % 3000));
      ++ops[9];
    }
  }
  EXPECT_EQ(p.mismatches, 0u) << "SEED=" << seed;
  EXPECT_EQ(p.bus.protocol_errors(), 0u);
  // The traffic exercised what it claims to (fails if a generator above stops working).
  EXPECT_GT(p.rises, cycles / 2000);
  EXPECT_GT(p.stop_edges, cycles / 1000);
  std::printf("%llu cycles, %llu STEP edges, %llu stopping axis-cycles, ops:",
              static_cast<unsigned long long>(p.bus.cycles()),
              static_cast<unsigned long long>(p.rises),
              static_cast<unsigned long long>(p.stop_edges));
  for (unsigned i = 0; i < 10; ++i) std::printf(" %u", ops[i]);
  std::printf("\n");
}

// STOP through the bus in each phase: the queue is flushed (the queued second move never
// starts), the axis comes to rest before N, pins equal the model at every edge, and the
// position read over the bus is the model's.
TEST(WbModel, StopInEachPhaseThroughTheBus) {
  // 200 steps of acceleration (1 ms), 4,400 of cruise at 400 k steps/s, 400 of deceleration.
  test::Ramp r{5000, true, 0, 400000, 0, 4e8, 2e8};
  const AxisMove m = test::encode(r).regs;
  for (unsigned want = 1; want <= 3; ++want) {
    SCOPED_TRACE("phase " + std::to_string(want));
    Pair p(11 + want);
    const unsigned k = want;  // a different axis each time
    write_move(p.bus, k, m);
    p.bus.write(ax(k, A::CMD), 1);
    p.bus.write(ax(k, A::CMD), 1);  // the second move must never run
    p.bus.write(R::START, 1u << k);
    // Poll STATUS until the phase is reached (and some steps into it for accel/cruise).
    uint32_t st = 0;
    for (int i = 0; i < 200000; ++i) {
      st = p.bus.read(ax(k, A::STATUS));
      const unsigned ph = (st & A::STATUS_PHASE_MASK) >> A::STATUS_PHASE_SHIFT;
      const uint32_t done = p.model.core().axis(k).steps_done();
      if (ph == want && (want == 3 || done > (want == 1 ? 50u : 2000u))) break;
      p.idle(want == 1 ? 0 : 20);
    }
    ASSERT_EQ((st & A::STATUS_PHASE_MASK) >> A::STATUS_PHASE_SHIFT, want);
    const uint32_t at_stop = p.model.core().axis(k).steps_done();
    p.bus.write(R::STOP, 1u << k);
    st = p.bus.read(ax(k, A::STATUS));
    EXPECT_EQ((st & A::STATUS_FREE_MASK) >> A::STATUS_FREE_SHIFT, 2u) << "queue flushed";
    EXPECT_EQ(st & A::STATUS_RUN_MASK, 0u);
    for (int i = 0; i < 100000 && (p.bus.read(ax(k, A::STATUS)) & A::STATUS_BUSY_MASK); ++i) {
      p.bus.write(R::START, 1u << k);  // ignored while stopping: the queue is empty anyway
      p.idle(20);
    }
    EXPECT_EQ(p.bus.read(ax(k, A::STATUS)) & A::STATUS_BUSY_MASK, 0u);
    const int32_t pos = static_cast<int32_t>(p.bus.read(ax(k, A::POS_LO)));
    EXPECT_EQ(pos, p.model.core().axis(k).position());
    EXPECT_GE(uint32_t(pos), at_stop);
    EXPECT_LT(uint32_t(pos), r.steps) << "stopped before the planned end";
    EXPECT_EQ(p.bus.read(ax(k, A::ERR)), 0u);
    EXPECT_EQ(p.mismatches, 0u);
  }
}

// A jog move over the bus runs past its STEPS field and ends only on STOP.
TEST(WbModel, JogRunsUntilStop) {
  Pair p(5);
  AxisMove m;
  const real clk = real(kDefaultClockHz);
  ASSERT_TRUE(speed_to_reg(1e6, clk, m.v_max));
  ASSERT_TRUE(accel_to_reg(1e9, clk, m.acc));
  ASSERT_TRUE(accel_to_reg(1e9, clk, m.dec));
  m.steps = 3;
  m.jog = true;
  write_move(p.bus, 0, m);
  p.bus.write(ax(0, A::CMD), 1);
  p.bus.write(R::START, 1);
  p.idle(200000);  // 2 ms: 1 ms ramp (500 steps), then 1,000 steps at 1 M steps/s
  EXPECT_TRUE(p.bus.read(ax(0, A::STATUS)) & A::STATUS_BUSY_MASK);
  EXPECT_NEAR(double(int32_t(p.bus.read(ax(0, A::POS_LO)))), 1500.0, 5.0);
  p.bus.write(R::STOP, 1);
  p.idle(150000);  // stopping from 1 M steps/s at 1e9 steps/s^2 takes 1 ms, 500 steps
  EXPECT_EQ(p.bus.read(ax(0, A::STATUS)) & A::STATUS_BUSY_MASK, 0u);
  EXPECT_NEAR(double(int32_t(p.bus.read(ax(0, A::POS_LO)))), 2000.0, 10.0);
  EXPECT_EQ(p.mismatches, 0u);
}

// POS_LO then POS_HI is one atomic 64-bit read even when the position changes sign between the
// two reads (the upper word flips between 0 and all ones there): the pair always equals the
// position at the POS_LO read.
TEST(WbModel, PositionReadIsAtomicWhileTheCounterCrossesZero) {
  Pair p(9);
  AxisMove m;
  const real clk = real(kDefaultClockHz);
  ASSERT_TRUE(speed_to_reg(5e6, clk, m.v_start));  // one step every 20 cycles, from the start
  m.v_max = m.v_start;
  ASSERT_TRUE(accel_to_reg(1e9, clk, m.dec));
  m.jog = true;
  m.dir = false;
  // First +40 steps, then the jog runs negative through zero.
  AxisMove up = m;
  up.jog = false;
  up.dir = true;
  up.steps = 40;
  up.v_end = up.v_start;
  up.dec_step = 40;
  write_move(p.bus, 1, up);
  p.bus.write(ax(1, A::CMD), 1);
  write_move(p.bus, 1, m);
  p.bus.write(ax(1, A::CMD), 1);
  p.bus.set_timing(4, 6);
  p.bus.write(R::START, 1u << 1);
  unsigned crossings = 0, reads = 0;
  int64_t prev = 0;
  while (p.bus.cycles() < 4000 && p.mismatches == 0) {
    const uint32_t lo = p.bus.read(ax(1, A::POS_LO));
    const int64_t at_lo = p.model.core().axis(1).position();
    p.idle(static_cast<unsigned>(reads % 37));  // the counter moves on meanwhile
    const uint32_t hi = p.bus.read(ax(1, A::POS_HI));
    const int64_t pos = static_cast<int64_t>((uint64_t(hi) << 32) | lo);
    // POS_W = 32: the upper word is the sign extension of the lower word read before it.
    ASSERT_EQ(hi, static_cast<int32_t>(lo) < 0 ? 0xFFFFFFFFu : 0u) << "read " << reads;
    // The data left the slave one or two edges before the model's state seen here.
    ASSERT_LE(std::llabs(pos - at_lo), 1) << "read " << reads;
    if ((pos < 0) != (prev < 0)) ++crossings;
    prev = pos;
    ++reads;
  }
  p.bus.write(R::STOP, 1u << 1);
  EXPECT_GE(crossings, 1u);
  EXPECT_LT(prev, -10);
  EXPECT_EQ(p.mismatches, 0u);
}
