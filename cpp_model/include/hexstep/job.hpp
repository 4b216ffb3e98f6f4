// SPDX-License-Identifier: Apache-2.0
// hexstep: a register-level job (per axis, a list of moves) and the runner that plays it on
// any CoreSim, cycle by cycle or, where the simulator supports it, event by event.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "hexstep/core.hpp"

namespace hexstep {

struct AxisJob {
  PulseConfig pulse{};
  std::vector<AxisMove> moves;
};

struct Job {
  uint64_t clock_hz = kDefaultClockHz;
  // The core build the registers are meant for (units: 2^-SPEED_W step per cycle, ...): a
  // board build may have narrower registers than the default (synth/targets.json).
  Widths widths{};
  std::array<AxisJob, kNumAxes> axes{};
};

// One STEP rising edge.
struct StepEvent {
  unsigned axis = 0;
  unsigned move = 0;   // index of the move within its axis
  uint32_t step = 0;   // 1-based index within the move
  uint64_t cycle = 0;  // clock cycle of the rising edge, the first start strobe's edge is 0
  bool dir = true;     // true: positive motion
  bool operator==(const StepEvent& o) const {
    return axis == o.axis && move == o.move && step == o.step && cycle == o.cycle && dir == o.dir;
  }
};

struct RunOptions {
  bool event_mode = false;        // skip quiet stretches (only where the CoreSim supports it)
  uint64_t max_cycles = 1ull << 44;
};

struct RunResult {
  uint64_t cycles = 0;  // cycles simulated until every axis finished its last move
  bool timed_out = false;
  std::array<int64_t, kNumAxes> position{};
  std::array<uint32_t, kNumAxes> refused{};  // moves refused by the core (err pulse)
  std::array<uint64_t, kNumAxes> steps{};
};

// Plays the job: at cycle 0 every axis with moves gets its first start strobe; each later move
// of an axis starts on the cycle after the previous one's done pulse.
RunResult run_job(CoreSim& core, const Job& job, const std::function<void(const StepEvent&)>& on_step,
                  const RunOptions& opt = RunOptions{});

}  // namespace hexstep
