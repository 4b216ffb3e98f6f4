// SPDX-License-Identifier: Apache-2.0
// hexstep: the six-axis core as seen from its ports, and the cycle-exact model of it.
// CoreSim is the interface that both the model and the Verilated RTL (sim/) implement, so
// that one job runner and one set of test vectors drive both.
#pragma once

#include <array>
#include <cstdint>

#include "hexstep/axis.hpp"

namespace hexstep {

struct CoreInputs {
  uint32_t start_mask = 0;  // start strobe, one bit per axis
  uint32_t abort_mask = 0;
  uint32_t stop_mask = 0;   // controlled stop strobe
  std::array<AxisMove, kNumAxes> move{};
  std::array<PulseConfig, kNumAxes> pulse{};
};

struct AxisOutputs {
  bool step = false;  // STEP pin (after polarity)
  bool dir = false;   // DIR pin (after polarity)
  bool busy = false;
  bool done = false;
  bool err = false;
  Phase phase = Phase::Idle;
  int64_t pos = 0;
  bool operator==(const AxisOutputs& o) const {
    return step == o.step && dir == o.dir && busy == o.busy && done == o.done && err == o.err &&
           phase == o.phase && pos == o.pos;
  }
  bool operator!=(const AxisOutputs& o) const { return !(*this == o); }
};

class CoreSim {
 public:
  virtual ~CoreSim() = default;
  virtual void reset() = 0;
  // One rising clock edge with these inputs applied before it.
  virtual void tick(const CoreInputs& in) = 0;
  virtual AxisOutputs out(unsigned axis) const = 0;
  // Event mode: ticks that may be skipped with these (start/abort/stop-free) inputs; 0 if
  // unsupported.
  virtual uint64_t quiet_ticks(const CoreInputs&) const { return 0; }
  virtual void skip(uint64_t) {}
};

class CoreModel : public CoreSim {
 public:
  explicit CoreModel(const Widths& w = Widths{}) {
    for (auto& a : ax_) a = AxisModel(w);
  }
  void reset() override {
    for (auto& a : ax_) a.reset();
  }
  void tick(const CoreInputs& in) override {
    for (unsigned i = 0; i < kNumAxes; ++i)
      ax_[i].tick((in.start_mask >> i) & 1u, (in.abort_mask >> i) & 1u, (in.stop_mask >> i) & 1u,
                  in.move[i], in.pulse[i]);
    pulse_ = in.pulse;
  }
  AxisOutputs out(unsigned i) const override {
    const AxisModel& a = ax_[i];
    return AxisOutputs{a.step_pin(pulse_[i]), a.dir_pin(pulse_[i]), a.busy(), a.done(), a.err(),
                       a.phase(),             a.position()};
  }
  uint64_t quiet_ticks(const CoreInputs& in) const override {
    if (in.start_mask != 0 || in.abort_mask != 0 || in.stop_mask != 0) return 0;
    uint64_t k = ~0ull;
    for (unsigned i = 0; i < kNumAxes; ++i) {
      uint64_t q = ax_[i].quiet_ticks(in.pulse[i]);
      if (q < k) k = q;
    }
    return k;
  }
  void skip(uint64_t k) override {
    for (auto& a : ax_) a.skip(k);
  }
  const AxisModel& axis(unsigned i) const { return ax_[i]; }

 private:
  std::array<AxisModel, kNumAxes> ax_;
  std::array<PulseConfig, kNumAxes> pulse_{};
};

}  // namespace hexstep
