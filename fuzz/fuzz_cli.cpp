// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the `hexstep` command line (cli/app.cpp, run_cli), argument handling end to end.
// Input: the arguments after "hexstep", separated by NUL bytes (at most 24).
// Sandbox: the target runs in a fresh temporary directory holding job.json (a copy of
// examples/six_axis.json, longer than the cycle bound below), small.json (a 20-step move that
// finishes within it) and req.json (tests/rtl/fw_plan_request.json); arguments containing
// '/' are skipped so nothing outside it is read or written, files the CLI writes are removed
// after each input, stdin is empty and stdout/stderr are discarded. A `simulate` run is bounded
// by --max-cycles 20000 (any --max-cycles of the input is dropped) so that no input can hang.
// Oracle: the exit status is one of the documented ones (0, 2..7) and not 1 (internal error: an
// exception the CLI did not turn into a clear message).
#include <dirent.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app.hpp"
#include "fuzz_check.hpp"

using hexstep::fuzz::check;
using hexstep::fuzz::fail;

namespace {

const std::set<std::string> kFixtures = {"job.json", "small.json", "req.json"};
const char kSmallJob[] =
    "{\"format\": \"hexstep-job\", \"version\": 1, \"clock_hz\": 100000000, \"axes\": [{\"axis\": 2,\n"
    " \"moves\": [{\"steps\": 20, \"dir\": 0, \"v_start\": 4611686018427387904,\n"
    " \"v_max\": 4611686018427387904, \"v_end\": 4611686018427387904, \"acc\": 0, \"dec\": 0,\n"
    " \"v_dec\": 4611686018427387904, \"acc_steps\": 0, \"dec_step\": 20, \"dec_frac\": 0}]}]}\n";
std::ostringstream g_null;  // std::cout / std::cerr sink

void copy_file(const std::string& from, const std::string& to) {
  std::ifstream in(from, std::ios::binary);
  if (!in) fail("fuzz_cli: cannot read " + from);
  std::ofstream out(to, std::ios::binary);
  out << in.rdbuf();
}

void remove_outputs() {
  DIR* d = opendir(".");
  if (!d) return;
  std::vector<std::string> names;
  while (dirent* e = readdir(d)) {
    const std::string n = e->d_name;
    if (n != "." && n != ".." && !kFixtures.count(n)) names.push_back(n);
  }
  closedir(d);
  for (const std::string& n : names) std::remove(n.c_str());
}

std::string g_dir;
void remove_sandbox() {
  remove_outputs();
  for (const std::string& n : kFixtures) std::remove(n.c_str());
  if (chdir("/") == 0) rmdir(g_dir.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  char tmpl[] = "/tmp/hexstep_fuzz_cli_XXXXXX";
  const char* dir = mkdtemp(tmpl);
  if (!dir || chdir(dir) != 0) fail("fuzz_cli: cannot make a temporary directory");
  g_dir = dir;
  std::atexit(remove_sandbox);
  copy_file(HEXSTEP_SOURCE_DIR "/examples/six_axis.json", "job.json");
  copy_file(HEXSTEP_SOURCE_DIR "/tests/rtl/fw_plan_request.json", "req.json");
  std::ofstream("small.json") << kSmallJob;
  if (!std::freopen("/dev/null", "r", stdin) || !std::freopen("/dev/null", "w", stdout))
    fail("fuzz_cli: cannot redirect stdin/stdout");
  std::cout.rdbuf(g_null.rdbuf());
  std::cerr.rdbuf(g_null.rdbuf());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 2048) return 0;
  std::vector<std::string> args{"hexstep"};
  std::string cur;
  bool simulate = false;
  auto flush = [&] {
    if (args.size() > 24) return;
    if (cur.find('/') != std::string::npos || cur.rfind("--max-cycles", 0) == 0) {
      cur.clear();
      return;
    }
    args.push_back(cur);
    if (cur == "simulate" && !simulate) {
      simulate = true;
      args.push_back("--max-cycles=20000");
    }
    cur.clear();
  };
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == 0) flush();
    else cur += static_cast<char>(data[i]);
  }
  if (!cur.empty()) flush();
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);

  const int rc = hexstep::cli::run_cli(static_cast<int>(args.size()), argv.data());
  g_null.str("");
  g_null.clear();
  std::clearerr(stdout);
  remove_outputs();
  if (rc == 1 || rc < 0 || rc > 7) {
    std::string line;
    for (const std::string& a : args) line += " '" + a + "'";
    fail("hexstep exited with status " + std::to_string(rc) + ":" + line);
  }
  return 0;
}
