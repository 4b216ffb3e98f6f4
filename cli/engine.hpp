// SPDX-License-Identifier: Apache-2.0
// hexstep CLI: the simulation engines behind hexstep::CoreSim.
#pragma once

#include <memory>
#include <string>

#include "hexstep/core.hpp"

namespace hexstep::cli {

enum class Engine { kModel, kRtl };

// Whether this binary was built with the Verilated RTL (CMake target hexstep_rtl).
bool rtl_available();

// Register widths that a job must fit for this engine.
Widths engine_widths(Engine e);

// Throws CliError(kExitUsage) if engine e is not built into this binary, or if a trace is asked
// for where the engine cannot write one.
void check_engine(Engine e, const std::string& trace_path);

// A fresh simulator (after check_engine). trace_path: FST waveform file (RTL only; empty: none).
// Throws CliError(kExitUsage) if the engine is not built or the trace is not supported.
std::unique_ptr<CoreSim> make_engine(Engine e, const std::string& trace_path);

}  // namespace hexstep::cli
