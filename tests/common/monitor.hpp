// SPDX-License-Identifier: Apache-2.0
// hexstep tests: an output-timing monitor written from the rules of docs/ARCHITECTURE.md
// ("Output stage and pulse timing"), not from the model's code: every pulse exactly
// step_high cycles high (0 acts as 1), at least step_low (0 acts as 1) low before the next
// rise, DIR changing at least dir_hold cycles after a rise and at least dir_setup cycles before
// the next one. Each interval uses the configuration live at the edge that starts it.
// Monitored wraps any TopSim (the model, or a Lockstep pair) and feeds one monitor per axis
// after every edge, with the levels before polarity and the configuration before the edge taken
// from the model beside it.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hexstep/top_sim.hpp"

namespace hexstep::test {

struct PinMonitor {
  // Cycle numbers are "the first cycle with the new level".
  int64_t last_rise = -1000000, last_fall = -1000000, last_dir = -1000000;
  uint32_t high = 1, low = 1, hold = 0, setup = 0;  // the intervals started last
  bool lvl = false, dir = true;
  uint64_t rises = 0;
  std::vector<uint64_t> rise_cycles;  // when keep is set
  bool keep = false;
  std::vector<std::string> errors;

  // The levels during cycle `cyc`, after the edge whose configuration was `pc`.
  void sample(int64_t cyc, bool l, bool d, const PulseConfig& pc) {
    if (d != dir) {
      if (cyc - last_rise < int64_t(hold)) add(cyc, "DIR changed " + std::to_string(cyc - last_rise) +
                                                        " cycles after a rise, dir_hold " + std::to_string(hold));
      last_dir = cyc;
      setup = pc.dir_setup;
    }
    if (l && !lvl) {
      if (cyc - last_fall < int64_t(low)) add(cyc, "STEP low for " + std::to_string(cyc - last_fall) +
                                                       " cycles, step_low " + std::to_string(low));
      if (cyc - last_dir < int64_t(setup)) add(cyc, "STEP rose " + std::to_string(cyc - last_dir) +
                                                        " cycles after DIR changed, dir_setup " + std::to_string(setup));
      last_rise = cyc;
      high = std::max<uint32_t>(pc.step_high, 1);
      hold = pc.dir_hold;
      ++rises;
      if (keep) rise_cycles.push_back(static_cast<uint64_t>(cyc));
    }
    if (!l && lvl) {
      if (cyc - last_rise != int64_t(high)) add(cyc, "STEP high for " + std::to_string(cyc - last_rise) +
                                                         " cycles, step_high " + std::to_string(high));
      last_fall = cyc;
      low = std::max<uint32_t>(pc.step_low, 1);
    }
    lvl = l;
    dir = d;
  }
  void add(int64_t cyc, const std::string& what) {
    if (errors.size() < 5) errors.push_back("cycle " + std::to_string(cyc) + ": " + what);
  }
};

class Monitored : public TopSim {
 public:
  // `drive` is ticked; `model` is the TopModel it contains (or that runs beside it in a
  // Lockstep): its output levels and live configuration feed the monitors.
  Monitored(TopSim& drive, const TopModel& model) : s_(drive), m_(model) {}
  void reset() override {
    s_.reset();
    cyc_ = 0;
    for (auto& mon : mon_) {
      mon = PinMonitor{};
      mon.keep = keep_;
    }
  }
  void tick(const WbPins& in) override {
    std::array<PulseConfig, kSlots> pc;
    for (unsigned k = 0; k < s_.naxes(); ++k) pc[k] = m_.pulse_config(k);
    s_.tick(in);
    ++cyc_;
    for (unsigned k = 0; k < s_.naxes(); ++k)
      mon_[k].sample(static_cast<int64_t>(cyc_), m_.pulse(k).step_level(), m_.pulse(k).dir_level(), pc[k]);
  }
  bool ack() const override { return s_.ack(); }
  uint32_t dat() const override { return s_.dat(); }
  bool irq() const override { return s_.irq(); }
  bool step(unsigned k) const override { return s_.step(k); }
  bool dir(unsigned k) const override { return s_.dir(k); }
  unsigned naxes() const override { return s_.naxes(); }
  Widths widths() const override { return s_.widths(); }
  std::string name() const override { return s_.name(); }

  const PinMonitor& monitor(unsigned k) const { return mon_[k]; }
  void keep_rises(bool on) {
    keep_ = on;
    for (auto& mon : mon_) mon.keep = on;
  }
  // All timing violations seen, one per line ("" if none).
  std::string errors() const {
    std::string t;
    for (unsigned k = 0; k < s_.naxes(); ++k)
      for (const std::string& e : mon_[k].errors) t += "axis " + std::to_string(k) + " " + e + "\n";
    return t;
  }
  uint64_t cycle() const { return cyc_; }

 private:
  TopSim& s_;
  const TopModel& m_;
  uint64_t cyc_ = 0;
  bool keep_ = false;
  std::array<PinMonitor, kSlots> mon_{};
};

}  // namespace hexstep::test
