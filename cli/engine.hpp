// SPDX-License-Identifier: Apache-2.0
// hexstep CLI: the simulation engines behind hexstep::TopSim (cpp_model/top_sim.hpp). Both are
// the whole block, hexstep_top, played through the same Wishbone job runner (run_job), so their
// STEP/DIR output is the same for every job.
#pragma once

#include <memory>
#include <string>

#include "hexstep/top_sim.hpp"

namespace hexstep::cli {

enum class Engine { kModel, kRtl };

// Whether this binary was built with the Verilated RTL (CMake target hexstep_rtl).
bool rtl_available();

// Register widths of a job file without a "widths" object (the default widths for both engines).
Widths engine_widths(Engine e);

// Throws CliError(kExitUsage) if engine e is not built into this binary, or if a trace is asked
// for where the engine cannot write one.
void check_engine(Engine e, const std::string& trace_path);

// A fresh simulator (after check_engine) for a core with widths w. trace_path: FST waveform
// file (RTL only; empty: none). The model takes any widths and has kNumAxes axes; the Verilated
// RTL has the widths and the axis count (naxes()) it was built with. Throws CliError(kExitUsage) if
// the engine is not built, the trace is not supported, or w is not the RTL's (naming both).
std::unique_ptr<TopSim> make_engine(Engine e, const std::string& trace_path, const Widths& w);

}  // namespace hexstep::cli
