// SPDX-License-Identifier: Apache-2.0
// The fixed-point formats are defined once in C++ (widths.hpp) and once as Verilog parameters;
// this test reads the parameter defaults from the RTL sources and requires them to agree.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "hexstep/widths.hpp"

namespace {
std::map<std::string, unsigned> verilog_params(const std::string& file) {
  std::ifstream in(std::string(HEXSTEP_RTL_DIR) + "/" + file);
  EXPECT_TRUE(in.good()) << file;
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::map<std::string, unsigned> p;
  const std::regex re(R"(parameter\s+integer\s+(\w+)\s*=\s*(\d+))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
    p[(*it)[1]] = static_cast<unsigned>(std::stoul((*it)[2]));
  return p;
}
}  // namespace

TEST(Widths, VerilogDefaultsEqualTheCppFormats) {
  const hexstep::Widths w;
  for (const char* file : {"hexstep_core.v", "hexstep_axis.v"}) {
    auto p = verilog_params(file);
    EXPECT_EQ(p.at("SPEED_W"), w.speed_frac) << file;
    EXPECT_EQ(p.at("ACC_W"), w.acc) << file;
    EXPECT_EQ(p.at("STEP_W"), w.steps) << file;
    EXPECT_EQ(p.at("DFRAC_W"), w.dec_frac) << file;
    EXPECT_EQ(p.at("PULSE_W"), w.pulse) << file;
    EXPECT_EQ(p.at("POS_W"), w.pos) << file;
    EXPECT_EQ(p.at("OWE_W"), w.owe) << file;
  }
  EXPECT_EQ(verilog_params("hexstep_core.v").at("NAXES"), hexstep::kNumAxes);
  EXPECT_EQ(verilog_params("hexstep_pulse.v").at("PULSE_W"), w.pulse);
}
