// SPDX-License-Identifier: Apache-2.0
// hexstep: command-line entry point; the command line itself is run_cli() in app.cpp.
#include "app.hpp"

int main(int argc, char** argv) { return hexstep::cli::run_cli(argc, argv); }
