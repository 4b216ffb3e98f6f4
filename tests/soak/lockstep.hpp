// SPDX-License-Identifier: Apache-2.0
// hexstep tests: the golden model and the Verilated core ticked together, every output of every
// axis compared after every edge (the approach of tests/rtl/test_cosim.cpp), for the soak
// driver (tests/soak/) and the fault tests (tests/rtl/test_faults.cpp). Mismatches are
// collected as text so each user reports them its own way (GoogleTest failure, soak log).
#pragma once

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "hexstep/core.hpp"
#include "rtl_core.hpp"

namespace hexstep::test {

inline std::string show_outputs(const AxisOutputs& o) {
  static const char* phase[] = {"idle", "accel", "cruise", "decel"};
  const unsigned p = static_cast<unsigned>(o.phase);
  std::ostringstream s;
  s << "step=" << o.step << " dir=" << o.dir << " busy=" << o.busy << " done=" << o.done << " err=" << o.err
    << " phase=" << (p < 4 ? phase[p] : "?") << " pos=" << o.pos;
  return s.str();
}

class LockstepCore : public CoreSim {
 public:
  explicit LockstepCore(const std::string& trace_path = "") : rtl_(trace_path) {}
  void reset() override {
    model_.reset();
    rtl_.reset();
  }
  void tick(const CoreInputs& in) override {
    model_.tick(in);
    rtl_.tick(in);
    compare();
    ++cycle_;
  }
  // Compares the outputs now (tick() does after every edge; also useful right after reset()).
  void compare() {
    for (unsigned a = 0; a < kNumAxes; ++a) {
      const AxisOutputs m = model_.out(a), r = rtl_.out(a);
      if (m != r) {
        if (report_.size() < 10) {
          std::ostringstream s;
          s << "cycle " << cycle_ << " axis " << a << "\n  model " << show_outputs(m) << "\n  rtl   "
            << show_outputs(r);
          report_.push_back(s.str());
        }
        ++mismatches_;
      }
    }
  }
  AxisOutputs out(unsigned a) const override { return model_.out(a); }
  AxisOutputs rtl_out(unsigned a) const { return rtl_.out(a); }
  const CoreModel& model() const { return model_; }
  uint64_t mismatches() const { return mismatches_; }
  uint64_t cycles() const { return cycle_; }
  // The first (up to 10) mismatches, one entry each.
  const std::vector<std::string>& report() const { return report_; }
  std::string report_text() const {
    std::string t;
    for (const std::string& r : report_) t += r + "\n";
    return t;
  }

 private:
  CoreModel model_;
  RtlCore rtl_;
  uint64_t cycle_ = 0;
  uint64_t mismatches_ = 0;
  std::vector<std::string> report_;
};

}  // namespace hexstep::test
