// SPDX-License-Identifier: Apache-2.0
// The fixed-point formats and the frame schedule are defined once in C++ (widths.hpp,
// TopModel's constants, regs.hpp generated from rdl/hexstep.rdl) and once in the Verilog; this
// test reads the parameter and localparam defaults from the RTL sources and requires them to
// agree, and the Verilated build's parameters (RtlTop::rtl_widths) to be the defaults.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "hexstep/regs.hpp"
#include "hexstep/top_model.hpp"
#include "hexstep/widths.hpp"
#ifdef HEXSTEP_HAVE_RTL
#include "rtl_top.hpp"
#endif

namespace {
std::string source(const std::string& file) {
  std::ifstream in(std::string(HEXSTEP_RTL_DIR) + "/" + file);
  EXPECT_TRUE(in.good()) << file;
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// `parameter integer NAME = value` and `localparam [..] NAME = W'dV` / `integer NAME = V`
// (the first declaration of a localparam line), values in decimal or hex.
std::map<std::string, uint64_t> verilog_params(const std::string& file) {
  const std::string text = source(file);
  std::map<std::string, uint64_t> p;
  const std::regex re(R"((?:parameter|localparam)\s+(?:integer\s+|\[[^\]]*\]\s*)?(\w+)\s*=\s*(?:\d+'([dhDH]))?([0-9a-fA-F_]+))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it) {
    std::string v = (*it)[3];
    v.erase(std::remove(v.begin(), v.end(), '_'), v.end());
    const bool hex = (*it)[2] == "h" || (*it)[2] == "H";
    if (!hex && v.find_first_not_of("0123456789") != std::string::npos) continue;
    if (!p.count((*it)[1])) p[(*it)[1]] = std::stoull(v, nullptr, hex ? 16 : 10);
  }
  return p;
}

uint64_t at(const std::map<std::string, uint64_t>& p, const std::string& name, const std::string& file) {
  auto it = p.find(name);
  if (it == p.end()) {
    ADD_FAILURE() << file << ": no parameter/localparam " << name;
    return ~0ull;
  }
  return it->second;
}
}  // namespace

TEST(Widths, VerilogParameterDefaultsEqualTheCppFormats) {
  const hexstep::Widths w;
  for (const char* file : {"hexstep_top.v", "hexstep_wb.v"}) {
    const auto p = verilog_params(file);
    EXPECT_EQ(at(p, "NAXES", file), hexstep::kNumAxes) << file;
    EXPECT_EQ(at(p, "ACC_W", file), w.acc) << file;
    EXPECT_EQ(at(p, "STEP_W", file), w.steps) << file;
    EXPECT_EQ(at(p, "DFRAC_W", file), w.dec_frac) << file;
    EXPECT_EQ(at(p, "PULSE_W", file), w.pulse) << file;
    EXPECT_EQ(at(p, "POS_W", file), w.pos) << file;
    // SPEED_W is fixed at 64 (two 32-bit halves), not a parameter.
    EXPECT_EQ(p.count("SPEED_W"), 0u) << file;
  }
  EXPECT_EQ(w.speed_frac, 64u);
  const auto pulse = verilog_params("hexstep_pulse.v");
  EXPECT_EQ(at(pulse, "PULSE_W", "hexstep_pulse.v"), w.pulse);
  EXPECT_EQ(at(pulse, "POS_W", "hexstep_pulse.v"), w.pos);
  EXPECT_EQ(at(verilog_params("hexstep_engine.v"), "NAXES", "hexstep_engine.v"), hexstep::kNumAxes);
}

TEST(Widths, FrameConstantsEqualTheEngine) {
  using namespace hexstep;
  const auto e = verilog_params("hexstep_engine.v");
  EXPECT_EQ(at(e, "NS", "hexstep_engine.v"), kSlots);
  EXPECT_EQ(at(e, "DUE_OFFSET", "hexstep_engine.v"), kDueOffset);
  EXPECT_EQ(at(e, "SUB_W", "hexstep_engine.v"), kSubtickBits);
  // The frame boundary (START/STOP masks taken) is the edge that ends this frame cycle.
  const std::string text = source("hexstep_engine.v");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(boundary\s*=\s*\(f\s*==\s*5'd(\d+)\))")))
      << "hexstep_engine.v: no `boundary = (f == 5'dN)`";
  EXPECT_EQ(std::stoul(m[1]), kBoundaryCycle);
  EXPECT_EQ(kFrameCycles, 1u << kFrameLog2);
  EXPECT_EQ(kFrameCycles, kSlots * kSlotCycles);
  EXPECT_EQ(kStepLatency, kDueOffset - kFrameCycles + 2);
  EXPECT_LE(kNumAxes, kSlots);
}

TEST(Widths, BusBlockConstantsEqualTheModelAndTheRegisterMap) {
  using namespace hexstep;
  const auto b = verilog_params("hexstep_wb.v");
  EXPECT_EQ(at(b, "NW", "hexstep_wb.v"), TopModel::kNw);
  EXPECT_EQ(at(b, "NC", "hexstep_wb.v"), TopModel::kNc);
  EXPECT_EQ(at(b, "LOADER_STEPS", "hexstep_wb.v"), TopModel::kLoaderSteps);
  EXPECT_EQ(at(b, "ID_VALUE", "hexstep_wb.v"), TopModel::kId);
  EXPECT_EQ(at(b, "VER_MAJOR", "hexstep_wb.v"), TopModel::kVersionMajor);
  EXPECT_EQ(at(b, "VER_MINOR", "hexstep_wb.v"), TopModel::kVersionMinor);
  EXPECT_EQ(regs::ID_RESET, TopModel::kId);
  EXPECT_EQ(regs::VERSION_RESET, (kNumAxes << regs::VERSION_NAXES_SHIFT) |
                                     (TopModel::kVersionMajor << regs::VERSION_MAJOR_SHIFT) |
                                     (TopModel::kVersionMinor << regs::VERSION_MINOR_SHIFT));
  EXPECT_EQ(regs::AXIS_COUNT, kNumAxes);
  // INFO0/INFO1 reset values (rdl/hexstep.rdl) are the default widths and the frame.
  const Widths w;
  EXPECT_EQ(regs::INFO0_RESET, (w.speed_frac << regs::INFO0_SPEED_W_SHIFT) | (w.acc << regs::INFO0_ACC_W_SHIFT) |
                                   (w.steps << regs::INFO0_STEP_W_SHIFT) | (w.dec_frac << regs::INFO0_DFRAC_W_SHIFT));
  EXPECT_EQ(regs::INFO1_RESET, (w.pulse << regs::INFO1_PULSE_W_SHIFT) | (w.pos << regs::INFO1_POS_W_SHIFT) |
                                   (kFrameLog2 << regs::INFO1_FRAME_LOG2_SHIFT) | (kSlots << regs::INFO1_SLOTS_SHIFT));
  // The implemented bits of the staging registers follow the widths.
  EXPECT_EQ(regs::axis::ACC_HI_RWMASK, uint32_t(w.acc_mask() >> 32));
  EXPECT_EQ(regs::axis::DEC_HI_RWMASK, uint32_t(w.acc_mask() >> 32));
  EXPECT_EQ(regs::axis::STEPS_RWMASK, uint32_t(w.steps_mask()));
  EXPECT_EQ(regs::axis::DEC_FRAC_RWMASK, uint32_t(w.dec_frac_mask()));
  EXPECT_EQ(regs::axis::STEP_HIGH_RWMASK, uint32_t(w.pulse_mask()));
}

#ifdef HEXSTEP_HAVE_RTL
TEST(Widths, VerilatedBuildHasTheDefaults) {
  const hexstep::Widths w, r = hexstep::RtlTop::rtl_widths();
  EXPECT_EQ(r.speed_frac, w.speed_frac);
  EXPECT_EQ(r.acc, w.acc);
  EXPECT_EQ(r.steps, w.steps);
  EXPECT_EQ(r.dec_frac, w.dec_frac);
  EXPECT_EQ(r.pulse, w.pulse);
  EXPECT_EQ(r.pos, w.pos);
  EXPECT_EQ(hexstep::RtlTop::rtl_naxes(), hexstep::kNumAxes);
}
#endif
