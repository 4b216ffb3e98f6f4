// SPDX-License-Identifier: Apache-2.0
// hexstep CLI: `hexstep plan`, plan linear-ramp moves with the host-side planner
// (hexstep_planner, docs/PLANNER.md) and print them as JSON, a C header, CSV or a job file.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace hexstep::cli {

// Command-line values as typed (numbers are parsed, with flag-named messages, by run_plan).
struct PlanOptions {
  std::string steps, distance, unit = "steps";
  std::string steps_per_rev, steps_per_mm, pitch_mm;
  std::string start_speed, end_speed, max_speed, accel, decel, ratio, time;
  std::string clock_hz;
  std::string widths;  // "SPEED_W=24,ACC_W=12,...": the core build the registers are for
  std::string axis = "0";
  std::string step_high = "1", step_low = "1", dir_setup = "0", dir_hold = "0";
  std::string job;  // planning request file (JSON), "-" for stdin
  std::string format = "json";
  std::string out;  // output file; empty or "-": stdout
  CLI::App* sub = nullptr;  // to ask which flags were given
};

// Registers the subcommand and its options (stored in `o`) on `app`.
CLI::App* add_plan(CLI::App& app, PlanOptions& o);

// Runs it; returns the exit status or throws CliError.
int run_plan(const PlanOptions& o);

}  // namespace hexstep::cli
