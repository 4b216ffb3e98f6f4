// SPDX-License-Identifier: Apache-2.0
// hexstep CLI: exit codes and helpers shared by the subcommands.
#pragma once

#include <stdexcept>
#include <string>

namespace hexstep::cli {

// Exit statuses of every subcommand (also listed in `hexstep --help`).
enum Exit : int {
  kExitOk = 0,
  kExitInternal = 1,  // unexpected failure (a bug, or stdout could not be written)
  kExitUsage = 2,       // bad command line, unreadable or invalid job/request file, engine not
                        // built, a move the planner or the registers cannot do
  kExitInfeasible = 3,  // plan --time: the time budget is shorter than the fastest possible move
  kExitTimeout = 4,     // the run did not finish within --max-cycles
  kExitRefused = 5,     // the core refused a move that the job reader accepted (model/RTL mismatch)
};

// Ends a subcommand: main() prints "hexstep: error: <what>" on stderr and exits with `code`.
class CliError : public std::runtime_error {
 public:
  CliError(int code, const std::string& what) : std::runtime_error(what), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// Whole contents of a file, or of stdin for "-". Throws CliError(kExitUsage).
std::string read_input(const std::string& path);

// Name of an input for messages: the path, or "<stdin>" for "-".
std::string input_name(const std::string& path);

// Writes all of `text` to stdout and flushes. Throws CliError(kExitInternal) on failure.
void write_stdout(const std::string& text);

// Writes all of `text` to the file `path` (created or truncated), or to stdout if `path` is
// empty or "-". `flag` names the option in messages. Throws CliError(kExitUsage) if the file
// cannot be opened, CliError(kExitInternal) if writing fails (the partial file is removed).
void write_output(const std::string& path, const std::string& text, const std::string& flag);

// t = cycle / clock_hz seconds in fixed point, with as many decimals as it takes to tell every
// cycle apart (the smallest d with 10^d >= clock_hz), rounded to nearest. Exact whenever
// clock_hz divides a power of ten (e.g. 100 MHz: 8 decimals); round(t * clock_hz) == cycle always.
std::string format_seconds(uint64_t cycle, uint64_t clock_hz);

}  // namespace hexstep::cli
