// SPDX-License-Identifier: Apache-2.0
// hexstep fuzz targets: what a target does when an oracle fails. abort() is what libFuzzer
// (and the corpus replay, replay_main.cpp) reports as a crash, with the input saved.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace hexstep::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "hexstep fuzz oracle failed: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

inline void check(bool ok, const std::string& what) {
  if (!ok) fail(what);
}

// Error messages of every reader are one line (the CLI prints them after "hexstep: error:").
inline void check_one_line(const std::string& msg, const char* who) {
  check(!msg.empty(), std::string(who) + ": empty error message");
  check(msg.find('\n') == std::string::npos && msg.find('\r') == std::string::npos,
        std::string(who) + ": error message is not one line: " + msg);
}

}  // namespace hexstep::fuzz
