// SPDX-License-Identifier: Apache-2.0
// hexstep CLI: the whole command line as a function, so that main() and the argument fuzzer
// (fuzz/fuzz_cli.cpp) run the same code.
#pragma once

namespace hexstep::cli {

// Parses argv (argv[0] is the program name), runs the subcommand, prints errors on stderr and
// returns the exit status (enum Exit in common.hpp). Never throws.
int run_cli(int argc, const char* const* argv);

}  // namespace hexstep::cli
