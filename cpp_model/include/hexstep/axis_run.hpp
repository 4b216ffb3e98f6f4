// SPDX-License-Identifier: Apache-2.0
// hexstep: one move on one axis, frame by frame, from the model's parts: AxisGen for the
// ticks and PulseStage for the STEP/DIR output, scheduled as docs/ARCHITECTURE.md describes
// ("Frames, slots and ticks", "Timing of the outputs"): axis i's slot is sampled at the edge
// that ends frame cycle 4i - 1 (the output stage's `accepts` decides whether the tick runs),
// the tick commits kCommitDelay edges later, and its step becomes due on F + kDueOffset - q.
// Quiet stretches (no step, no phase change, no output activity) are jumped over with
// AxisGen::quiet_ticks/skip and PulseStage::quiet_cycles/skip, so moves of seconds at 100 MHz
// take milliseconds. tests/model/test_event_mode.cpp and bench_check check that this runner gives
// exactly the STEP edges of the cycle-exact TopModel (run_job on ModelSim) for the same move.
// Used by the accuracy and planner tests and by the benchmarks (bench/harness.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "hexstep/axis.hpp"

namespace hexstep {

struct AxisRise {
  uint32_t step = 0;    // 1-based
  uint64_t cycle = 0;   // first cycle with STEP high, relative to the move's time zero F0
  bool dir = true;      // DIR level (before polarity) at the rise
};

struct AxisRun {
  std::vector<AxisRise> rises;
  uint64_t ticks = 0;          // ticks the generator ran (the first included)
  uint64_t stalled = 0;        // frames in which the generator ran but the output stage did not
                               // accept a step (the tick was skipped)
  uint64_t end_cycle = 0;      // cycle (from F0) after which the axis was at rest
  bool timed_out = false;
  bool refused = false;        // make_slot() marked the move bad or empty: nothing ran
};

struct AxisRunOptions {
  unsigned axis = 0;              // slot (0..7): the sample edge is F + 4 axis - 1
  PulseConfig pulse{};
  Widths widths{};
  bool event_mode = true;         // jump over quiet stretches
  uint64_t max_cycles = 1ull << 40;
  bool keep_rises = true;
  // Called at every rise (step 1-based, cycle relative to F0) whether or not rises are kept.
  std::function<void(uint32_t step, uint64_t cycle)> on_rise;
};

AxisRun run_axis(const AxisMove& m, const AxisRunOptions& opt = AxisRunOptions{});

}  // namespace hexstep
