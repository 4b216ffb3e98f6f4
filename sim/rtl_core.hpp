// SPDX-License-Identifier: Apache-2.0
// hexstep: the Verilated rtl/hexstep_core.v behind the CoreSim interface.
#pragma once

#include <memory>
#include <string>

#include "hexstep/core.hpp"

namespace hexstep {

class RtlCore : public CoreSim {
 public:
  // trace_path: write an FST trace there (empty: no trace). Also enabled by TRACE=1 in the
  // environment, which writes hexstep_<n>.fst in the working directory.
  explicit RtlCore(const std::string& trace_path = "");
  ~RtlCore() override;
  void reset() override;
  void tick(const CoreInputs& in) override;
  AxisOutputs out(unsigned axis) const override;
  uint64_t cycles() const;

  // The Verilog parameters of the built core, read from the Verilated model.
  static Widths rtl_widths();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hexstep
