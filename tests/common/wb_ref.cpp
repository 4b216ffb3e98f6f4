// SPDX-License-Identifier: Apache-2.0
// hexstep tests: WbModel beside a Verilated hexstep_top (wb_ref.hpp).
#include "wb_ref.hpp"

#include <sstream>

namespace hexstep::test {

void WbRef::after_edge(const TopPins& o) {
  const CoreInputs& ci = model.core_inputs();
  std::ostringstream bad;
  if (o.ack != model.ack()) bad << " ack rtl " << o.ack << " model " << model.ack() << ";";
  if (o.dat && *o.dat != model.dat())
    bad << std::hex << " dat rtl 0x" << *o.dat << " model 0x" << model.dat() << std::dec << ";";
  if (o.irq != model.irq()) bad << " irq rtl " << o.irq << " model " << model.irq() << ";";
  for (unsigned k = 0; k < kNumAxes; ++k) {
    const bool step = (o.step >> k) & 1u, dir = (o.dir >> k) & 1u;
    if (step != model.step(k) || dir != model.dir(k))
      bad << " axis " << k << " step/dir rtl " << step << dir << " model " << model.step(k)
          << model.dir(k) << ";";
    const bool lvl = model.core().axis(k).step_level();
    if (lvl && !prev_step_[k]) ++rises[k];
    prev_step_[k] = lvl;
    if ((ci.start_mask >> k) & 1u) starts[k].push_back(edges);
    if (model.core().out(k).done) dones[k].push_back(edges);
  }
  if (model.ack()) acks.push_back(edges);
  if (!bad.str().empty()) {
    if (report.size() < 10)
      report.push_back("edge " + std::to_string(edges) + ":" + bad.str() +
                       (context.empty() ? "" : " (" + context + ")"));
    ++mismatches;
  }
  ++edges;
}

bool WbRef::idle() const {
  for (unsigned k = 0; k < kNumAxes; ++k)
    if (model.core().out(k).busy || model.running(k)) return false;
  return true;
}

std::string WbRef::report_text() const {
  std::string t;
  for (const std::string& r : report) t += r + "\n";
  return t;
}

}  // namespace hexstep::test
