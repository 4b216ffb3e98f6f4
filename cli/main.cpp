// SPDX-License-Identifier: Apache-2.0
// hexstep: command-line entry point. Each subcommand lives in its own file (simulate.cpp; plan
// and send are to come) and registers itself on the CLI11 app here.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "common.hpp"
#include "simulate.hpp"

int main(int argc, char** argv) {
  using namespace hexstep::cli;
  CLI::App app{
      "hexstep: tools for the hexstep FPGA six-axis stepper STEP/DIR generator.\n"
      "Jobs are JSON files of per-axis register-level moves (docs/FORMATS.md).",
      "hexstep"};
  app.require_subcommand(1);
  app.footer(
      "Run 'hexstep SUBCOMMAND --help' for the options of a subcommand.\n"
      "Exit status: 0 success; 1 internal error; 2 bad command line, unreadable or invalid job\n"
      "file, or engine not built; 3 the core refused a move the job reader accepted;\n"
      "4 the run did not finish within --max-cycles.");

  SimulateOptions sim_opt;
  CLI::App* sim = add_simulate(app, sim_opt);
  // Later: add_plan(app, ...), add_send(app, ...).

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "hexstep: error: " << e.what() << " (see hexstep --help)\n";
    return kExitUsage;
  }
  try {
    if (sim->parsed()) return run_simulate(sim_opt);
    std::cerr << "hexstep: error: no subcommand (see hexstep --help)\n";
    return kExitUsage;
  } catch (const CliError& e) {
    std::cerr << "hexstep: error: " << e.what() << "\n";
    return e.code();
  } catch (const std::exception& e) {
    std::cerr << "hexstep: error: internal: " << e.what() << "\n";
    return kExitInternal;
  }
}
