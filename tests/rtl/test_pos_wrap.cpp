// SPDX-License-Identifier: Apache-2.0
// Position counter wrap-around: hexstep_top verilated with POS_W = 8 (tests/CMakeLists.txt,
// hexstep_rtl_pos8) against TopModel with Widths::pos = 8, every output after every edge
// (tests/common/bench.hpp), through +127 -> -128 and back. The 32-bit counter itself would
// need 2^31 steps (about 2^37 cycles) and is not run (docs/TESTING.md).
#include <gtest/gtest.h>

#include <array>

#include "bench.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;
namespace R = hexstep::regs;
namespace A = hexstep::regs::axis;

TEST(PosWrap, EightBitCounterWrapsBothWays) {
  ASSERT_EQ(RtlTop::rtl_widths().pos, 8u) << "this binary must link the POS_W = 8 build";
  Bench b(3);
  EXPECT_EQ((b.read(R::INFO1) & R::INFO1_POS_W_MASK) >> R::INFO1_POS_W_SHIFT, 8u);
  std::array<bool, kNumAxes> up{}, down{};
  std::array<int64_t, kNumAxes> prev{};
  b.bus.on_edge = [&] {
    for (unsigned k = 0; k < kNumAxes; ++k) {
      const int64_t p = b.m().pulse(k).position();
      up[k] |= prev[k] == 127 && p == -128;
      down[k] |= prev[k] == -128 && p == 127;
      prev[k] = p;
    }
  };
  // Axis 0: +300 then -600 (through +127 -> -128 twice, and back twice); axis 3: -129 then +1.
  b.push(0, cruise(300, 1ull << 62));
  b.push(0, cruise(600, 1ull << 62, false));
  b.push(3, cruise(129, 1ull << 61, false));
  b.push(3, cruise(1, 1ull << 61));
  b.write(R::START, (1u << 0) | (1u << 3));
  ASSERT_TRUE(b.settle());
  // 300 - 600 = -300 = -44 (mod 256); -129 + 1 = -128.
  EXPECT_EQ(b.m().pulse(0).position(), -44);
  EXPECT_EQ(b.m().pulse(3).position(), -128);
  EXPECT_EQ(b.position(0), -44) << "POS_LO sign-extends, POS_HI is the sign";
  EXPECT_EQ(b.position(3), -128);
  EXPECT_EQ(b.axr(0, A::POS_LO), static_cast<uint32_t>(-44));
  EXPECT_TRUE(up[0] && down[0]);
  EXPECT_TRUE(down[3]);
  EXPECT_EQ(b.rises(0), 900u);
  EXPECT_EQ(b.rises(3), 130u);
  EXPECT_EQ(b.problems(), "");
}
