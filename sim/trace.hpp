// SPDX-License-Identifier: Apache-2.0
// hexstep: FST tracing for the Verilated test benches. A trace is written to `path`, or, when
// path is empty and TRACE=1 is set in the environment, to <prefix>_<n>.fst in the working
// directory (n counts the models traced by this process).
#pragma once

#include <atomic>
#include <cstdlib>
#include <memory>
#include <string>

#include "verilated.h"
#include "verilated_fst_c.h"

namespace hexstep {

template <typename Top>
std::unique_ptr<VerilatedFstC> open_trace(VerilatedContext& ctx, Top& top, std::string path,
                                          const std::string& prefix) {
  static std::atomic<int> seq{0};
  const char* env = std::getenv("TRACE");
  if (path.empty() && env && std::string(env) == "1") path = prefix + "_" + std::to_string(seq++) + ".fst";
  if (path.empty()) return nullptr;
  ctx.traceEverOn(true);
  std::unique_ptr<VerilatedFstC> t(new VerilatedFstC);
  top.trace(t.get(), 99);
  t->open(path.c_str());
  return t;
}

}  // namespace hexstep
