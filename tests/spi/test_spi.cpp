// SPDX-License-Identifier: Apache-2.0
// SPI-to-Wishbone bridge (rtl/hexstep_spi_wb.v) in front of the real hexstep_top, driven by the
// SPI master model sim/spi_master.*: register reads and writes (readback, byte enables, the
// reply CRC), a move started over SPI compared with the golden register-block model WbModel
// at every clock edge (tests/common/wb_ref.hpp), and
// malformed frames (truncated, overlong, bad CRC, bad command, address out of range, CS_N
// without clock), which must not start any Wishbone cycle and must change no register.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "Vspi_tb_top.h"
#include "hexstep/core.hpp"
#include "hexstep_regs.hpp"
#include "spi_master.hpp"
#include "trace.hpp"
#include "vectors.hpp"
#include "verilated.h"
#include "verilated_fst_c.h"
#include "wb_ref.hpp"

using namespace hexstep;
using namespace hexstep::test;
namespace R = hexstep::regs;

namespace {

// The Verilated spi_tb_top behind the SpiPins interface; counts Wishbone cycles and acks, and
// hands the Wishbone pins hexstep_top samples at each edge to pre_edge (for WbModel; the
// monitor shows cyc & stb as one signal, which is all hexstep_top decodes).
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
    for (int i = 0; i < 3; ++i) tick();
    top_->rst_i = 0;
    top_->eval();
    cycles_ = acks_ = bus_requests_ = 0;
  }
  ~SpiTop() override {
    if (trace_) trace_->close();
    top_->final();
  }
  void set_pins(bool sck, bool cs_n, bool mosi) override {
    top_->spi_sck_i = sck;
    top_->spi_cs_n_i = cs_n;
    top_->spi_mosi_i = mosi;
  }
  bool miso() const override {
    top_->eval();
    return top_->spi_miso_o;
  }
  void tick() override {
    top_->eval();
    if (pre_edge) {
      WbPins p;
      p.cyc = p.stb = top_->mon_cyc_o;
      p.we = top_->mon_we_o;
      p.adr = top_->mon_adr_o;
      p.dat = top_->mon_dat_o;
      p.sel = top_->mon_sel_o;
      p.estop = top_->estop_i;
      pre_edge(p);
    }
    if (trace_) trace_->dump(cycles_ * 10);
    top_->clk_i = 1;
    top_->eval();
    if (trace_) trace_->dump(cycles_ * 10 + 5);
    top_->clk_i = 0;
    top_->eval();
    ++cycles_;
    if (top_->mon_cyc_o && !prev_cyc_) ++bus_requests_;  // a new request after this edge
    prev_cyc_ = top_->mon_cyc_o;
    if (top_->mon_ack_o) {
      ++acks_;
      last_ack_ = {top_->mon_we_o != 0, top_->mon_adr_o, top_->mon_dat_o, top_->mon_sel_o};
    }
    if (on_edge) on_edge();
  }
  bool step(unsigned k) const { return (top_->step_o >> k) & 1u; }
  bool dir(unsigned k) const { return (top_->dir_o >> k) & 1u; }
  bool ack() const { return top_->mon_ack_o; }
  bool irq() const { return top_->irq_o; }
  bool miso_oe() const { return top_->spi_miso_oe_o; }
  uint64_t acks() const { return acks_; }
  uint64_t bus_requests() const { return bus_requests_; }
  uint64_t cycles() const { return cycles_; }
  struct Access { bool we; uint32_t adr, dat, sel; };
  Access last_ack() const { return last_ack_; }
  std::function<void()> on_edge;
  std::function<void(const WbPins&)> pre_edge;

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vspi_tb_top> top_;
  std::unique_ptr<VerilatedFstC> trace_;
  uint64_t cycles_ = 0, acks_ = 0, bus_requests_ = 0;
  bool prev_cyc_ = false;
  Access last_ack_{};
};

}  // namespace

TEST(SpiCrc, KnownCheckValue) {
  // CRC-8/SMBUS check value from the CRC catalogue: "123456789" -> 0xF4.
  const uint8_t s[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(spi::crc8(s, sizeof s), 0xF4);
}

TEST(Spi, ReadIdVersionAndStatus) {
  SpiTop dut;
  SpiMaster m(dut, 1);
  EXPECT_FALSE(dut.miso_oe());
  EXPECT_EQ(m.read(R::ID), R::ID_RESET);
  EXPECT_EQ(m.last_status(), spi::kStatusIdle);  // nothing before the first frame
  EXPECT_EQ(m.last_rstat(), spi::kStatusOk);
  EXPECT_EQ(m.read(R::VERSION), R::VERSION_RESET);
  EXPECT_EQ(m.last_status(), spi::kStatusOk);      // the ID read was accepted
  EXPECT_EQ(dut.bus_requests(), 2u);
  EXPECT_EQ(dut.acks(), 2u);
}

TEST(Spi, WriteReadbackByteEnablesAndTiming) {
  SpiTop dut;
  SpiMaster m(dut, 2);
  const uint32_t regs[][2] = {{ax(0, R::axis::STEPS), R::axis::STEPS_RWMASK},
                              {ax(5, R::axis::V_MAX_HI), R::axis::V_MAX_HI_RWMASK},
                              {ax(3, R::axis::ACC_HI), R::axis::ACC_HI_RWMASK},
                              {ax(2, R::axis::STEP_HIGH), R::axis::STEP_HIGH_RWMASK},
                              {R::IRQ_ENABLE, R::IRQ_ENABLE_RWMASK}};
  // SCK half periods from the minimum (4 core cycles) to slow, random per half period.
  const unsigned timing[][2] = {{4, 4}, {4, 9}, {11, 23}};
  uint64_t frames = 0;
  for (const auto& t : timing) {
    m.set_timing(t[0], t[1]);
    for (const auto& r : regs) {
      m.write(r[0], 0xFFFFFFFFu);
      ++frames;
      EXPECT_EQ(m.read(r[0]), r[1]) << std::hex << r[0];
      EXPECT_EQ(m.last_status(), spi::kStatusOk) << "the write before was executed";
      m.write(r[0], 0);
      m.write(r[0], 0xA5C3E1F7u, 0x5);  // lanes 0 and 2
      EXPECT_EQ(m.read(r[0]), 0x00C300F7u & r[1]) << std::hex << r[0];
      m.write(r[0], 0x12345678u, 0xA);  // lanes 1 and 3
      EXPECT_EQ(m.read(r[0]), 0x12C356F7u & r[1]) << std::hex << r[0];
      frames += 6;
    }
  }
  // Exactly one Wishbone cycle per frame, each acked once.
  EXPECT_EQ(dut.bus_requests(), frames);
  EXPECT_EQ(dut.acks(), frames);
  // The last write reached the bus with its address, data and byte enables.
  m.write(ax(4, R::axis::DEC_FRAC), 0xCAFEF00Du, 0x9);
  const auto a = dut.last_ack();
  EXPECT_TRUE(a.we);
  EXPECT_EQ(a.adr, ax(4, R::axis::DEC_FRAC));
  EXPECT_EQ(a.dat, 0xCAFEF00Du);
  EXPECT_EQ(a.sel, 0x9u);
}

TEST(Spi, MoveOverSpiMatchesGoldenModel) {
  SpiTop dut;
  WbRef ref(dut);
  SpiMaster m(dut, 3);
  m.set_timing(4, 7);
  const AxisMove a = bus_trapezoid(60, true), b = bus_trapezoid(36, false);
  ASSERT_EQ(validate_move(a), 0u);
  ASSERT_EQ(validate_move(b), 0u);
  const Widths w;  // the moves fit the registers as they are (the bus keeps ACC_W bits)
  ASSERT_EQ((a.acc | a.dec | b.acc | b.dec) & ~w.acc_mask(), 0u);
  push(m, 1, a);
  ASSERT_EQ(ref.model.queued(1), 1u);
  push(m, 4, b);
  ASSERT_EQ(ref.model.queued(4), 1u);
  const size_t acks_before_start = ref.acks.size();
  m.write(R::START, 0x12u);
  // The write reaches the bus a few cycles after CS_N rises: wait for its ack.
  for (int i = 0; i < 100 && ref.acks.size() == acks_before_start; ++i) dut.tick();
  ASSERT_EQ(ref.acks.size(), acks_before_start + 1) << "START write not acked";
  const uint64_t start_ack = ref.acks.back();
  dut.tick();  // the core starts on the edge after the write's
  ASSERT_EQ(ref.starts[1].size(), 1u);
  ASSERT_EQ(ref.starts[4].size(), 1u);
  EXPECT_EQ(ref.starts[1][0], start_ack + 1);
  EXPECT_EQ(ref.starts[4][0], start_ack + 1);
  ASSERT_TRUE(ref.model.running(1) && ref.model.running(4));
  for (unsigned k : {0u, 2u, 3u, 5u}) EXPECT_TRUE(ref.starts[k].empty()) << "axis " << k;
  for (int i = 0; i < 200000 && !ref.idle(); ++i) dut.tick();
  for (int i = 0; i < 20; ++i) dut.tick();
  ASSERT_TRUE(ref.idle());
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
  EXPECT_EQ(ref.rises[1], 60u);
  EXPECT_EQ(ref.rises[4], 36u);
  // The position registers, read over SPI, show the moves (signed, by direction).
  EXPECT_EQ(m.read(ax(1, R::axis::POS_LO)), 60u);
  EXPECT_EQ(m.read(ax(4, R::axis::POS_LO)), static_cast<uint32_t>(-36));
  EXPECT_EQ(ref.mismatches, 0u) << ref.report_text();
}

TEST(Spi, MalformedFramesHaveNoBusSideEffect) {
  SpiTop dut;
  SpiMaster m(dut, 4);
  m.set_timing(4, 6);
  const uint32_t target = ax(2, R::axis::STEPS);
  m.write(target, 0x11111111u);
  const uint32_t before = m.read(target);
  ASSERT_EQ(before, 0x11111111u & R::axis::STEPS_RWMASK);
  const uint64_t req0 = dut.bus_requests();
  const auto good = spi::write_frame(target, 0x2222AAAAu, 0xF);
  std::mt19937 rng(5);
  std::vector<std::pair<std::vector<uint8_t>, long>> bad;
  for (long n = 0; n < 64; ++n) bad.push_back({good, n});               // truncated, CS_N early
  for (long n : {65L, 66L, 71L, 72L, 80L, 100L}) {                       // overlong
    auto f = good;
    f.resize(13, 0x00);
    bad.push_back({f, n});
  }
  for (int i = 0; i < 64; ++i) {                                         // one bit flipped
    auto f = good;
    f[i / 8] ^= static_cast<uint8_t>(0x80u >> (i % 8));
    bad.push_back({f, -1});
  }
  for (int i = 0; i < 20; ++i) {                                         // random bytes
    std::vector<uint8_t> f(8);
    for (auto& x : f) x = static_cast<uint8_t>(rng());
    if (f == good) continue;
    bad.push_back({f, -1});
  }
  auto with_crc = [](std::vector<uint8_t> f) {
    f.push_back(spi::crc8(f.data(), f.size()));
    return f;
  };
  for (uint8_t cmd : {0x00, 0xFF, 0xB0, 0x2F, 0x51, 0x5F, 0x80}) {       // unknown commands
    bad.push_back({with_crc({cmd, 0x02, 0x00, 0x22, 0x22, 0xAA, 0xAA}), -1});
  }
  bad.push_back({with_crc({0xAF, 0x12, 0x00, 0x22, 0x22, 0xAA, 0xAA}), -1});  // adr >= 2^12
  bad.push_back({with_crc({0xAF, 0x80, 0x00, 0x22, 0x22, 0xAA, 0xAA}), -1});
  bad.push_back({spi::read_frame(0x1000), -1});                         // read, adr >= 2^12
  auto rf = spi::read_frame(target);
  rf[3] ^= 0x01;                                                          // read, bad CRC
  bad.push_back({rf, -1});
  bad.push_back({spi::read_frame(target), 31});                          // read cut in request
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
  EXPECT_EQ(m.read(target), 0x2222AAAAu & R::axis::STEPS_RWMASK);
}
