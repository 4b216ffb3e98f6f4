// SPDX-License-Identifier: Apache-2.0
// hexstep: the command line (app.hpp). Each subcommand lives in its own file (simulate.cpp,
// plan.cpp; send is to come) and registers itself on the CLI11 app here.
#include "app.hpp"

#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "common.hpp"
#include "plan.hpp"
#include "send.hpp"
#include "simulate.hpp"

namespace hexstep::cli {

int run_cli(int argc, const char* const* argv) {
  CLI::App app{
      "hexstep: tools for the hexstep FPGA six-axis stepper STEP/DIR generator.\n"
      "Jobs are JSON files of per-axis register-level moves (docs/FORMATS.md).",
      "hexstep"};
  app.require_subcommand(1);
  app.footer(
      "Run 'hexstep SUBCOMMAND --help' for the options of a subcommand.\n"
      "Exit status: 0 success; 1 internal error; 2 bad command line, unreadable or invalid job\n"
      "or request file, engine not built, or a move the planner, the registers or the pulse\n"
      "timing cannot do; 3 (plan) the --time budget is shorter than the fastest possible move;\n"
      "4 (simulate) the run did not finish within --max-cycles; 5 (simulate) the core refused a\n"
      "move the job reader accepted; 6 (send) serial link error; 7 (send) the board refused a\n"
      "request or reported a fault (E-STOP, refused move, stream underrun).");

  SimulateOptions sim_opt;
  CLI::App* sim = add_simulate(app, sim_opt);
  PlanOptions plan_opt;
  CLI::App* plan = add_plan(app, plan_opt);
  SendOptions send_opt;
  CLI::App* send = add_send(app, send_opt);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "hexstep: error: " << e.what() << " (see hexstep --help)\n";
    return kExitUsage;
  }
  try {
    if (sim->parsed()) return run_simulate(sim_opt);
    if (plan->parsed()) return run_plan(plan_opt);
    if (send->parsed()) return run_send(send_opt);
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

}  // namespace hexstep::cli
