// SPDX-License-Identifier: Apache-2.0
// hexstep CLI: `hexstep simulate`, run a job file on the model or the Verilated RTL.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "hexstep/job.hpp"

namespace hexstep::cli {

struct SimulateOptions {
  std::string job;             // path, or "-" for stdin
  std::string engine = "model";
  bool event_mode = false;
  uint64_t max_cycles = 10000000000ull;
  bool summary = false;
  std::string trace;           // FST file (RTL only)
};

// Registers the subcommand and its options (stored in `o`) on `app`.
CLI::App* add_simulate(CLI::App& app, SimulateOptions& o);

// Runs it; returns the exit status or throws CliError.
int run_simulate(const SimulateOptions& o);

// Output formats, exposed for reuse by later subcommands.
std::string format_csv(const std::vector<StepEvent>& events, uint64_t clock_hz);
std::string format_summary(const Job& job, const RunResult& r, const std::vector<StepEvent>& events,
                           const std::string& source, const std::string& engine);

}  // namespace hexstep::cli
