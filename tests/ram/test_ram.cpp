// SPDX-License-Identifier: Apache-2.0
// rtl/hexstep_ram.v: STYLE "DELAY" (iCE40, generic) and STYLE "ECP5" (DP16KD block RAM, on the
// model tests/ram/dp16kd_sim.v) on the same ports, every cycle, against a reference memory kept
// here from the timing rule of hexstep_ram's header alone: a read address driven in cycle c gives
// the word in cycle c+2; a write in cycle c lands at the edge that ends c; no write touches a word
// in the cycle its used read address is driven or the cycle after. Only words written before are
// compared (the memory has no reset).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>

#include "Vram_tb_top.h"
#include "verilated.h"

namespace {

constexpr int kWords = 256;  // the bank's words (8-bit addresses)

struct Port {
  bool re = false, we = false;
  uint8_t raddr = 0, waddr = 0;
  uint32_t wdata = 0;
};

class RamBench {
 public:
  RamBench() : top_(new Vram_tb_top(&ctx_, "ram_tb_top")) {
    top_->clk_i = 0;
    top_->eval();
  }
  ~RamBench() { top_->final(); }

  // The rule: a write to waddr is allowed unless waddr is the read address of this cycle (p)
  // or of the cycle before.
  bool write_allowed(uint8_t waddr, const Port& p) const {
    return !(p.re && waddr == p.raddr) && !(prev_re_ && waddr == prev_raddr_);
  }

  // One cycle with these port values, checking the read data the edge brings.
  void cycle(const Port& p) {
    ASSERT_TRUE(!p.we || write_allowed(p.waddr, p)) << "bench breaks the rule";
    top_->re_i = p.re;
    top_->raddr_i = p.raddr;
    top_->we_i = p.we;
    top_->waddr_i = p.waddr;
    top_->wdata_i = p.wdata;
    top_->eval();
    // The word a read of this cycle must return: the memory before this cycle's write (a
    // write to it now or in the next cycle is excluded by the rule).
    std::optional<uint32_t> want;
    if (p.re && written_[p.raddr]) want = ref_[p.raddr];
    if (p.we) {
      ref_[p.waddr] = p.wdata;
      written_[p.waddr] = true;
    }
    top_->clk_i = 1;
    top_->eval();
    top_->clk_i = 0;
    top_->eval();
    ++cyc_;
    // The cycle now starting is c+1: its outputs show the read of cycle c-1.
    const std::optional<uint32_t> due = last_;
    last_ = want;
    prev_re_ = p.re;
    prev_raddr_ = p.raddr;
    if (due) {
      ASSERT_EQ(top_->rdata_delay_o, *due) << "DELAY, cycle " << cyc_;
      ASSERT_EQ(top_->rdata_ecp5_o, *due) << "ECP5, cycle " << cyc_;
      ++checked_;
    }
  }

  uint64_t checked() const { return checked_; }

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vram_tb_top> top_;
  std::array<uint32_t, kWords> ref_{};
  std::array<bool, kWords> written_{};
  std::optional<uint32_t> last_;  // the word the read of the cycle before must return
  bool prev_re_ = false;
  uint8_t prev_raddr_ = 0;
  uint64_t cyc_ = 0;
  uint64_t checked_ = 0;
};

// Every word written with a pattern whose 16-bit halves and bytes all differ, then read back in
// address order and in reverse: a lost byte lane, a swapped half or a wrong address bit shows.
TEST(Ram, WriteAllThenReadBack) {
  RamBench b;
  for (int a = 0; a < kWords; ++a) {
    Port p;
    p.we = true;
    p.waddr = static_cast<uint8_t>(a);
    p.wdata = 0x01000000u * static_cast<uint32_t>(a ^ 0x5A) +
              0x00010000u * static_cast<uint32_t>(a) +
              0x00000100u * static_cast<uint32_t>(255 - a) + static_cast<uint32_t>(a ^ 0xC3);
    b.cycle(p);
    if (::testing::Test::HasFatalFailure()) return;
  }
  for (int i = 0; i < 2 * kWords; ++i) {  // every word forward, then backward
    Port p;
    p.re = true;
    p.raddr = static_cast<uint8_t>(i < kWords ? i : 2 * kWords - 1 - i);
    b.cycle(p);
    if (::testing::Test::HasFatalFailure()) return;
  }
  for (int i = 0; i < 2; ++i) b.cycle(Port{});
  EXPECT_EQ(b.checked(), 512u);
}

// Random reads and writes in the same cycles, the writes kept off the words being read (the
// rule), with every 32-bit value shape: all ones, all zeros, single bits, random.
TEST(Ram, RandomTrafficUnderTheRule) {
  RamBench b;
  std::mt19937 rng(20261207);
  auto pick_data = [&]() -> uint32_t {
    switch (rng() % 4) {
      case 0: return 0xFFFFFFFFu;
      case 1: return 0u;
      case 2: return 1u << (rng() % 32);
      default: return static_cast<uint32_t>(rng());
    }
  };
  for (int i = 0; i < 200000; ++i) {
    Port p;
    p.re = (rng() % 4) != 0;
    p.raddr = static_cast<uint8_t>(rng());
    p.we = (rng() % 3) != 0;
    do {
      p.waddr = static_cast<uint8_t>(rng());
    } while (!b.write_allowed(p.waddr, p));
    p.wdata = pick_data();
    b.cycle(p);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(b.checked(), 100000u);
}

}  // namespace
