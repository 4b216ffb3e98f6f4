// SPDX-License-Identifier: Apache-2.0
// SPI-to-Wishbone bridge (rtl/hexstep_spi_wb.v) in front of the real hexstep_top, driven by the
// SPI master model sim/spi_master.*: register reads and writes (readback, byte enables, the reply
// CRC) through the memory-backed staging and configuration words and the ~105-cycle CMD.push,
// moves started over SPI, and malformed frames (truncated, overlong, bad CRC, bad command,
// address out of range, CS_N without clock), which must not start any Wishbone cycle and must
// change no register. TopModel is fed the bus pins hexstep_top samples before every edge; after
// it ack, read data, IRQ and every STEP/DIR pin are compared.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Vspi_tb_top.h"
#include "hexstep/top_model.hpp"
#include "spi_master.hpp"
#include "trace.hpp"
#include "vectors.hpp"
#include "verilated.h"
#include "verilated_fst_c.h"

using namespace hexstep;
using namespace hexstep::test;
namespace R = hexstep::regs;
namespace A = hexstep::regs::axis;

namespace {

// The Verilated spi_tb_top behind the SpiPins interface, with TopModel beside its hexstep_top.
class SpiTop : public SpiPins {
 public:
  SpiTop() : top_(new Vspi_tb_top(&ctx_, "spi_tb_top")) {
    trace_ = open_trace(ctx_, *top_, "", "spi");
    top_->clk_i = 0;
    top_->rst_i = 1;
    top_->spi_cs_n_i = 1;
    top_->spi_sck_i = 0;
    top_->spi_mosi_i = 0;
    top_->estop_i = 0;
    top_->eval();
    for (int i = 0; i < 2; ++i) edge();
    top_->rst_i = 0;
    top_->eval();
    model.reset();
  }
  ~SpiTop() override {
    if (trace_) trace_->close();
    top_->final();
  }
  void set_pins(bool sck, bool cs_n, bool mosi) override {
    hexstep::set_spi_pins(*top_, sck, cs_n, mosi);
  }
  bool miso() const override { return hexstep::spi_miso(*top_); }
  void tick() override {
    top_->eval();
    WbPins p;
    p.cyc = p.stb = top_->mon_cyc_o;
    p.we = top_->mon_we_o;
    p.adr = top_->mon_adr_o;
    p.dat = top_->mon_dat_o;
    p.sel = top_->mon_sel_o;
    p.estop = top_->estop_i;
    if (p.cyc && !prev_cyc_) ++bus_requests_;
    prev_cyc_ = p.cyc;
    model.tick(p);
    edge();
    compare();
    if (top_->mon_ack_o) {
      ++acks_;
      last_ack_ = {top_->mon_we_o != 0, top_->mon_adr_o, top_->mon_dat_o, top_->mon_sel_o};
    }
  }
  void set_estop(bool on) { top_->estop_i = on; }
  uint64_t acks() const { return acks_; }
  uint64_t bus_requests() const { return bus_requests_; }
  uint64_t cycles() const { return cycles_; }
  bool miso_oe() const { return top_->spi_miso_oe_o; }
  bool step(unsigned k) const { return (top_->step_o >> k) & 1u; }
  struct Access {
    bool we;
    uint32_t adr, dat, sel;
  };
  Access last_ack() const { return last_ack_; }
  uint64_t mismatches() const { return mismatches_; }
  const std::string& report() const { return report_; }

  TopModel model;

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vspi_tb_top> top_;
  std::unique_ptr<VerilatedFstC> trace_;
  uint64_t cycles_ = 0, acks_ = 0, bus_requests_ = 0, mismatches_ = 0;
  bool prev_cyc_ = false;
  Access last_ack_{};
  std::string report_;

  void edge() {
    if (trace_) trace_->dump(cycles_ * 10);
    top_->clk_i = 1;
    top_->eval();
    if (trace_) trace_->dump(cycles_ * 10 + 5);
    top_->clk_i = 0;
    top_->eval();
    ++cycles_;
  }
  void compare() {
    std::string bad;
    auto cmp = [&](const std::string& what, uint64_t rtl, uint64_t mod) {
      if (rtl != mod) bad += " " + what + " rtl=" + std::to_string(rtl) + " model=" + std::to_string(mod);
    };
    cmp("ack", top_->mon_ack_o, model.ack());
    if (top_->mon_ack_o || model.ack()) cmp("dat", top_->mon_rdat_o, model.dat());
    cmp("irq", top_->irq_o, model.irq());
    for (unsigned k = 0; k < kNumAxes; ++k) {
      cmp("step" + std::to_string(k), (top_->step_o >> k) & 1u, model.step(k));
      cmp("dir" + std::to_string(k), (top_->dir_o >> k) & 1u, model.dir(k));
    }
    if (!bad.empty() && mismatches_++ < 10) report_ += "edge " + std::to_string(cycles_ - 1) + ":" + bad + "\n";
  }
};

// Register access over SPI in the way of job.hpp's write_move (any bus with write(adr, dat)).
struct SpiBus {
  SpiMaster& m;
  void write(uint32_t adr, uint32_t dat) { m.write(adr, dat); }
};

}  // namespace

TEST(SpiCrc, KnownCheckValue) {
  // CRC-8/SMBUS check value from the CRC catalogue: "123456789" -> 0xF4.
  const uint8_t s[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(spi::crc8(s, sizeof s), 0xF4);
}

TEST(Spi, ReadIdVersionInfoAndStatus) {
  SpiTop dut;
  SpiMaster m(dut, 1);
  EXPECT_FALSE(dut.miso_oe());
  EXPECT_EQ(m.read(R::ID), R::ID_RESET);
  EXPECT_EQ(m.last_status(), spi::kStatusIdle);  // nothing before the first frame
  EXPECT_EQ(m.last_rstat(), spi::kStatusOk);
  EXPECT_EQ(m.read(R::VERSION), R::VERSION_RESET);
  EXPECT_EQ(m.last_status(), spi::kStatusOk);  // the ID read was answered
  EXPECT_EQ(m.read(R::INFO0), R::INFO0_RESET);
  EXPECT_EQ(m.read(R::INFO1), R::INFO1_RESET);
  EXPECT_EQ(dut.bus_requests(), 4u);
  EXPECT_EQ(dut.acks(), 4u);
  EXPECT_EQ(dut.mismatches(), 0u) << dut.report();
}

// Flip-flop, memory-backed staging and configuration registers, at SCK half periods from the
// minimum (4 core cycles) to slow: readback, byte enables, one Wishbone cycle per frame.
TEST(Spi, WriteReadbackByteEnablesAndTiming) {
  SpiTop dut;
  SpiMaster m(dut, 2);
  const uint32_t regs[][2] = {{ax_reg(0, A::STEPS), A::STEPS_RWMASK},      {ax_reg(5, A::V_MAX_HI), A::V_MAX_HI_RWMASK},
                              {ax_reg(3, A::ACC_HI), A::ACC_HI_RWMASK},    {ax_reg(2, A::STEP_HIGH), A::STEP_HIGH_RWMASK},
                              {ax_reg(1, A::POLARITY), A::POLARITY_RWMASK}, {R::IRQ_ENABLE, R::IRQ_ENABLE_RWMASK}};
  const unsigned timing[][2] = {{4, 4}, {4, 9}, {11, 23}};
  uint64_t frames = 0;
  for (const auto& t : timing) {
    m.set_timing(t[0], t[1]);
    for (const auto& r : regs) {
      m.write(r[0], 0xFFFFFFFFu);
      EXPECT_EQ(m.read(r[0]), r[1]) << std::hex << r[0];
      EXPECT_EQ(m.last_status(), spi::kStatusOk) << "the write before was executed";
      m.write(r[0], 0);
      m.write(r[0], 0xA5C3E1F7u, 0x5);  // lanes 0 and 2
      EXPECT_EQ(m.read(r[0]), 0x00C300F7u & r[1]) << std::hex << r[0];
      m.write(r[0], 0x12345678u, 0xA);  // lanes 1 and 3
      EXPECT_EQ(m.read(r[0]), 0x12C356F7u & r[1]) << std::hex << r[0];
      frames += 7;
      m.write(r[0], r[0] == ax_reg(2, A::STEP_HIGH) ? 1 : 0);
      ++frames;
    }
  }
  EXPECT_EQ(dut.bus_requests(), frames);
  EXPECT_EQ(dut.acks(), frames);
  m.write(ax_reg(4, A::DEC_FRAC), 0xCAFEF00Du, 0x9);
  const auto a = dut.last_ack();
  EXPECT_TRUE(a.we);
  EXPECT_EQ(a.adr, ax_reg(4, A::DEC_FRAC));
  EXPECT_EQ(a.dat, 0xCAFEF00Du);
  EXPECT_EQ(a.sel, 0x9u);
  EXPECT_EQ(dut.mismatches(), 0u) << dut.report();
}

// Moves staged and pushed over SPI at the fastest SCK (CMD.push acks ~106 cycles after its
// request, within the gap to the next frame) and started there: every push executed, the moves
// run on the pins exactly as the model runs them, positions read back over SPI.
TEST(Spi, MovesOverSpiMatchTheModel) {
  SpiTop dut;
  SpiMaster m(dut, 3);
  m.set_timing(4, 4);
  SpiBus bus{m};
  const AxisMove a = trapezoid(60, true), b = trapezoid(36, false);
  push_move(bus, 1, a);
  push_move(bus, 1, cruise(10, 1ull << 62));
  push_move(bus, 4, b);
  EXPECT_EQ(m.status(), spi::kStatusOk) << "the last push was executed";
  for (int i = 0; i < 200; ++i) dut.tick();  // its ack comes about 106 cycles after CS_N rose
  EXPECT_EQ(dut.model.queued(1), 2u);
  EXPECT_EQ(dut.model.queued(4), 1u);
  m.write(R::START, 0x12u);
  for (int i = 0; i < 400000 && (dut.model.busy(1) || dut.model.busy(4) || dut.model.running(1) ||
                                 dut.model.running(4) || i < 1000);
       ++i)
    dut.tick();
  EXPECT_EQ(dut.model.pulse(1).position(), 70);
  EXPECT_EQ(dut.model.pulse(4).position(), -36);
  EXPECT_EQ(m.read(ax_reg(1, A::POS_LO)), 70u);
  EXPECT_EQ(m.read(ax_reg(4, A::POS_LO)), static_cast<uint32_t>(-36));
  EXPECT_EQ(m.read(ax_reg(4, A::POS_HI)), 0xFFFFFFFFu);
  for (unsigned k : {0u, 2u, 3u, 5u}) EXPECT_EQ(dut.model.pulse(k).position(), 0) << "axis " << k;
  EXPECT_EQ(dut.mismatches(), 0u) << dut.report();
}

TEST(Spi, MalformedFramesHaveNoBusSideEffect) {
  SpiTop dut;
  SpiMaster m(dut, 4);
  m.set_timing(4, 6);
  const uint32_t target = ax_reg(2, A::STEPS);
  m.write(target, 0x11111111u);
  const uint32_t before = m.read(target);
  ASSERT_EQ(before, 0x11111111u & A::STEPS_RWMASK);
  const uint64_t req0 = dut.bus_requests();
  const auto good = spi::write_frame(target, 0x2222AAAAu, 0xF);
  std::mt19937 rng(5);
  std::vector<std::pair<std::vector<uint8_t>, long>> bad;
  for (long n = 0; n < 64; ++n) bad.push_back({good, n});  // truncated, CS_N early
  for (long n : {65L, 66L, 71L, 72L, 80L, 100L}) {          // overlong
    auto f = good;
    f.resize(13, 0x00);
    bad.push_back({f, n});
  }
  for (int i = 0; i < 64; ++i) {  // one bit flipped
    auto f = good;
    f[i / 8] ^= static_cast<uint8_t>(0x80u >> (i % 8));
    bad.push_back({f, -1});
  }
  for (int i = 0; i < 20; ++i) {  // random bytes
    std::vector<uint8_t> f(8);
    for (auto& x : f) x = static_cast<uint8_t>(rng());
    if (f == good) continue;
    bad.push_back({f, -1});
  }
  auto with_crc = [](std::vector<uint8_t> f) {
    f.push_back(spi::crc8(f.data(), f.size()));
    return f;
  };
  for (uint8_t cmd : {0x00, 0xFF, 0xB0, 0x2F, 0x51, 0x5F, 0x80})  // unknown commands
    bad.push_back({with_crc({cmd, 0x02, 0x00, 0x22, 0x22, 0xAA, 0xAA}), -1});
  bad.push_back({with_crc({0xAF, 0x12, 0x00, 0x22, 0x22, 0xAA, 0xAA}), -1});  // adr >= 2^12
  bad.push_back({with_crc({0xAF, 0x80, 0x00, 0x22, 0x22, 0xAA, 0xAA}), -1});
  bad.push_back({spi::read_frame(0x1000), -1});  // read, adr >= 2^12
  auto rf = spi::read_frame(target);
  rf[3] ^= 0x01;  // read, bad CRC
  bad.push_back({rf, -1});
  bad.push_back({spi::read_frame(target), 31});  // read cut in its request
  for (const auto& b : bad) {
    const auto in = m.transfer(b.first, b.second);
    // A write frame's MISO bytes after STATUS are 0 (no read data leaks into it).
    if (b.first.size() != spi::kReadBytes)
      for (size_t i = 1; i < in.size(); ++i) EXPECT_EQ(in[i] & 0xFFu, 0u) << "MISO byte " << i;
    if (b.first.size() == spi::kReadBytes && b.second < 0) {
      EXPECT_EQ(in[4], spi::kStatusRejected) << "RSTAT of a rejected read";
      for (int i = 5; i < 10; ++i) EXPECT_EQ(in[i], 0u);
    }
    EXPECT_EQ(m.status(), spi::kStatusRejected) << "frame of " << b.second << " bits";
  }
  m.cs_pulse();  // CS_N without any clock
  EXPECT_EQ(m.status(), spi::kStatusRejected);
  EXPECT_EQ(dut.bus_requests(), req0) << "a malformed frame reached the bus";
  // Nothing changed, and the bridge still works: the good frame is executed.
  EXPECT_EQ(m.read(target), before);
  EXPECT_EQ(m.write(target, 0x2222AAAAu), spi::kStatusOk);
  EXPECT_EQ(m.status(), spi::kStatusOk);
  EXPECT_EQ(m.read(target), 0x2222AAAAu & A::STEPS_RWMASK);
  EXPECT_EQ(dut.mismatches(), 0u) << dut.report();
}
