// SPDX-License-Identifier: Apache-2.0
// The SPI-to-Wishbone bridge (rtl/hexstep_spi_wb.v) alone, in front of a C++ Wishbone slave
// with random wait states (0 to hundreds of cycles), under random frames: valid writes and
// reads, malformed frames, frames arriving while the previous request still waits. Checked on
// every clock edge and independently of the bridge's code, from the frame format in its header:
//   - the B4 classic master rules: stb only with cyc; cyc, stb, we, adr, dat, sel held from the
//     request through the cycle in which ack is sampled; cyc low in the cycle after that;
//   - every bus transaction belongs to exactly one frame: a write frame the next STATUS reports
//     as accepted (with its address, data and byte enables), or a read frame answered with RSTAT
//     0xA1; no other frame causes one;
//   - a read the host accepts (RSTAT 0xA1 and RCRC matching) carries the slave's data; a read
//     acked too late for its data bytes fails the host's check and is reported rejected.
#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Vhexstep_spi_wb.h"
#include "spi_master.hpp"
#include "vectors.hpp"
#include "verilated.h"

using namespace hexstep;
using namespace hexstep::test;

namespace {

struct Transaction {
  bool we = false;
  uint32_t adr = 0, dat = 0, sel = 0;  // dat: write data, or the data the slave returned
  uint64_t request = 0, ack = 0;       // cycles
};

// The bridge and a slave with a word memory; wait states drawn per request from [lo, hi].
class BridgeBench : public SpiPins {
 public:
  explicit BridgeBench(uint32_t seed) : top_(new Vhexstep_spi_wb(&ctx_, "hexstep_spi_wb")), rng_(seed) {
    top_->clk_i = 0;
    top_->rst_i = 1;
    top_->spi_cs_n_i = 1;
    top_->spi_sck_i = 0;
    top_->spi_mosi_i = 0;
    top_->wb_ack_i = 0;
    top_->wb_dat_i = 0;
    top_->eval();
    for (int i = 0; i < 2; ++i) edge();
    top_->rst_i = 0;
    top_->eval();
    for (uint32_t i = 0; i < mem_.size(); ++i) mem_[i] = i * 0x9E3779B9u;
  }
  ~BridgeBench() override { top_->final(); }
  void set_waits(unsigned lo, unsigned hi) { lo_ = lo, hi_ = hi; }

  void set_pins(bool sck, bool cs_n, bool mosi) override {
    hexstep::set_spi_pins(*top_, sck, cs_n, mosi);
  }
  bool miso() const override { return hexstep::spi_miso(*top_); }
  void tick() override {
    top_->eval();
    const bool cyc = top_->wb_cyc_o, stb = top_->wb_stb_o, we = top_->wb_we_o;
    const uint32_t adr = top_->wb_adr_o, dat = top_->wb_dat_o, sel = top_->wb_sel_o;
    if (stb && !cyc) error("stb without cyc");
    if (after_ack_ && cyc) error("cyc still high in the cycle after the ack");
    after_ack_ = false;
    if (pending_) {
      if (!(cyc && stb)) error("request dropped before its ack");
      else if (we != cur_.we || adr != cur_.adr || sel != cur_.sel || (we && dat != cur_.dat))
        error("request changed while waiting for its ack");
    }
    // The slave: a registered ack `wait` cycles after the request; the transfer completes at the
    // edge that ends the ack cycle.
    const bool ack_now = top_->wb_ack_i;
    if (ack_now) {
      cur_.ack = cycles_;
      if (cur_.we) {
        uint32_t& w = mem_[(cur_.adr >> 2) % mem_.size()];
        for (unsigned b = 0; b < 4; ++b)
          if ((cur_.sel >> b) & 1u) w = (w & ~(0xFFu << (8 * b))) | (cur_.dat & (0xFFu << (8 * b)));
      } else {
        cur_.dat = top_->wb_dat_i;
      }
      log.push_back(cur_);
      pending_ = false;
      after_ack_ = true;
    } else if (!pending_ && cyc && stb) {
      pending_ = true;
      cur_ = Transaction{we, adr, we ? dat : 0, sel, cycles_, 0};
      wait_ = std::uniform_int_distribution<unsigned>(lo_, hi_)(rng_);
    } else if (pending_ && wait_ > 0) {
      --wait_;
    }
    const bool ack_next = pending_ && wait_ == 0 && !ack_now;
    edge();
    top_->wb_ack_i = ack_next;
    top_->wb_dat_i = ack_next && !cur_.we ? mem_[(cur_.adr >> 2) % mem_.size()] : 0xDEADBEEFu;
  }
  uint32_t mem(uint32_t adr) const { return mem_[(adr >> 2) % mem_.size()]; }
  uint64_t cycles() const { return cycles_; }
  bool busy() const { return pending_; }

  std::vector<Transaction> log;
  std::vector<std::string> errors;

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vhexstep_spi_wb> top_;
  std::mt19937 rng_;
  std::array<uint32_t, 64> mem_{};
  unsigned lo_ = 0, hi_ = 0, wait_ = 0;
  bool pending_ = false, after_ack_ = false;
  Transaction cur_{};
  uint64_t cycles_ = 0;

  void edge() {
    top_->clk_i = 1;
    top_->eval();
    top_->clk_i = 0;
    top_->eval();
    ++cycles_;
  }
  void error(const std::string& what) {
    if (errors.size() < 10) errors.push_back("cycle " + std::to_string(cycles_) + ": " + what);
  }
};

// What the host sent and learnt, frame by frame.
struct Frame {
  enum Kind { kWrite, kRead, kBad } kind;
  uint32_t adr = 0, dat = 0, sel = 0;
  uint8_t rstat = 0;
  bool read_ok = false;     // RSTAT 0xA1 and RCRC matched
  uint32_t got = 0;         // the data a read returned
  uint8_t outcome = 0;      // the STATUS byte of the next frame
};

}  // namespace

TEST(SpiBridge, RandomFramesAgainstAWaitStateSlave) {
  const uint64_t seed = test_seed();
  std::printf("SEED=%llu\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  BridgeBench dut(static_cast<uint32_t>(seed));
  SpiMaster m(dut, static_cast<uint32_t>(seed >> 32));
  std::vector<Frame> frames;
  const unsigned n = static_cast<unsigned>(env_count("SPI_BRIDGE_FRAMES", 1500));
  unsigned late = 0, busy_rejects = 0;
  for (unsigned i = 0; i < n; ++i) {
    // Mostly quick slaves, sometimes one slower than a read's data deadline or than a frame.
    switch (rng() % 8) {
      case 0: dut.set_waits(60, 200); break;
      case 1: dut.set_waits(200, 700); break;
      default: dut.set_waits(0, 12); break;
    }
    const unsigned half = 4 + static_cast<unsigned>(rng() % 3);
    m.set_timing(4, half);
    const uint32_t adr = static_cast<uint32_t>(rng() % 64) * 4 + static_cast<uint32_t>(rng() % 4);
    Frame f{Frame::kBad};
    uint8_t status = 0;  // this frame's STATUS byte: the outcome of the frame before
    const unsigned what = static_cast<unsigned>(rng() % 10);
    if (what < 4) {
      f.kind = Frame::kWrite;
      f.adr = adr;
      f.dat = static_cast<uint32_t>(rng());
      f.sel = static_cast<uint32_t>(rng() % 16);
      status = m.write(f.adr, f.dat, f.sel);
    } else if (what < 8) {
      f.kind = Frame::kRead;
      f.adr = adr;
      f.read_ok = m.read(f.adr, f.got);
      f.rstat = m.last_rstat();
      status = m.last_status();
    } else {  // malformed: a valid frame cut short, lengthened or with a bit flipped
      auto fr = rng() % 2 ? spi::write_frame(adr, static_cast<uint32_t>(rng()), 0xF) : spi::read_frame(adr);
      const unsigned how = static_cast<unsigned>(rng() % 3);
      long bits = -1;
      // (at least the 8 bits of STATUS, the outcome of the frame before)
      if (how == 0) bits = 8 + static_cast<long>(rng() % (fr.size() == spi::kReadBytes ? 24 : 56));
      else if (how == 1) fr.push_back(static_cast<uint8_t>(rng()));
      else fr[rng() % 4] ^= static_cast<uint8_t>(1u << (rng() % 8));
      const auto in = m.transfer(fr, bits);
      status = in.empty() ? 0 : in[0];
      f.rstat = in.size() > 4 ? in[4] : 0;
    }
    if (!frames.empty()) frames.back().outcome = status;
    frames.push_back(f);
    if (rng() % 4 == 0)  // sometimes a pause between frames
      for (unsigned c = rng() % 800; c > 0; --c) dut.tick();
  }
  frames.back().outcome = m.status();
  for (unsigned c = 0; c < 2000; ++c) dut.tick();

  EXPECT_TRUE(dut.errors.empty()) << "SEED=" << seed << ": " << dut.errors[0];
  // Each frame's transaction, in order.
  size_t t = 0;
  unsigned writes = 0, reads = 0, rejected_writes = 0, issued_by_bad = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    const std::string where = "SEED=" + std::to_string(seed) + " frame " + std::to_string(i);
    if (f.kind == Frame::kWrite && f.outcome == spi::kStatusOk) {
      ASSERT_LT(t, dut.log.size()) << where << ": an accepted write never reached the bus";
      const Transaction& x = dut.log[t++];
      EXPECT_TRUE(x.we) << where;
      EXPECT_EQ(x.adr, f.adr) << where;
      EXPECT_EQ(x.dat, f.dat) << where;
      EXPECT_EQ(x.sel, f.sel) << where;
      ++writes;
    } else if (f.kind == Frame::kWrite) {
      EXPECT_EQ(f.outcome, spi::kStatusRejected) << where;
      ++rejected_writes;
    } else if (f.kind == Frame::kRead && f.rstat == spi::kStatusOk) {
      ASSERT_LT(t, dut.log.size()) << where << ": an answered read never reached the bus";
      const Transaction& x = dut.log[t++];
      EXPECT_FALSE(x.we) << where;
      EXPECT_EQ(x.adr, f.adr) << where;
      if (f.read_ok) {
        EXPECT_EQ(f.got, x.dat) << where << ": a read the host accepts carries the slave's data";
        EXPECT_EQ(f.outcome, spi::kStatusOk) << where;
        ++reads;
      } else {
        // Its ack came after the first data byte had to go out: at least 68 cycles late.
        EXPECT_GE(x.ack - x.request, 60u) << where << ": a quick read failed the host's check";
        EXPECT_EQ(f.outcome, spi::kStatusRejected) << where;
        ++late;
      }
    } else if (f.kind == Frame::kRead) {
      EXPECT_EQ(f.rstat, spi::kStatusRejected) << where;
      EXPECT_EQ(f.outcome, spi::kStatusRejected) << where;
      EXPECT_FALSE(f.read_ok) << where;
      ++busy_rejects;
    } else {
      EXPECT_EQ(f.outcome, spi::kStatusRejected) << where << ": a malformed frame was accepted";
      // A read frame lengthened after its valid request has issued its read (RSTAT 0xA1).
      if (f.rstat == spi::kStatusOk) {
        ASSERT_LT(t, dut.log.size()) << where;
        const Transaction& x = dut.log[t++];
        EXPECT_FALSE(x.we) << where;
        ++issued_by_bad;
      }
    }
  }
  EXPECT_EQ(t, dut.log.size()) << "SEED=" << seed << ": bus transactions that no frame asked for";
  std::printf("%zu frames: %u writes executed, %u rejected (bus busy), %u reads answered, %u late, %u rejected "
              "(bus busy), %u reads of lengthened frames, %zu bus transactions\n",
              frames.size(), writes, rejected_writes, reads, late, busy_rejects, issued_by_bad, dut.log.size());
  // The mix exercised every path (fails if a generator above stops working).
  EXPECT_GT(writes, n / 10);
  EXPECT_GT(reads, n / 10);
  EXPECT_GT(late, 0u);
  EXPECT_GT(rejected_writes + busy_rejects, 0u);
}

// With a slave that always acks within the read deadline, every valid frame is executed and
// every read returns the memory's word.
TEST(SpiBridge, QuickSlaveExecutesEveryFrame) {
  BridgeBench dut(9);
  dut.set_waits(0, 40);
  SpiMaster m(dut, 9, 4, 5);
  std::mt19937 rng(9);
  std::vector<uint32_t> shadow(64);
  for (uint32_t i = 0; i < 64; ++i) shadow[i] = dut.mem(i * 4);
  for (int i = 0; i < 300; ++i) {
    const uint32_t w = rng() % 64;
    if (rng() & 1) {
      const uint32_t v = rng();
      EXPECT_NE(m.write(w * 4, v), spi::kStatusRejected) << i;
      shadow[w] = v;
    } else {
      uint32_t got = 0;
      ASSERT_TRUE(m.read(w * 4, got)) << i;
      EXPECT_EQ(got, shadow[w]) << i;
    }
  }
  EXPECT_EQ(m.status(), spi::kStatusOk);
  EXPECT_TRUE(dut.errors.empty()) << dut.errors[0];
  EXPECT_EQ(dut.log.size(), 300u);
}
