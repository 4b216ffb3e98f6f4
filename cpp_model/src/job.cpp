// SPDX-License-Identifier: Apache-2.0
// hexstep: job runner shared by the model, the Verilated RTL, the CLI and the tests.
#include "hexstep/job.hpp"

#include <algorithm>

namespace hexstep {

RunResult run_job(CoreSim& core, const Job& job, const std::function<void(const StepEvent&)>& on_step,
                  const RunOptions& opt) {
  RunResult r;
  core.reset();
  CoreInputs in;
  std::array<size_t, kNumAxes> next{};      // next move to start
  std::array<uint32_t, kNumAxes> count{};   // steps of the running move so far
  std::array<bool, kNumAxes> level{};       // STEP level before polarity, last cycle
  std::array<bool, kNumAxes> active{};      // a move of this axis has been started and not ended
  for (unsigned i = 0; i < kNumAxes; ++i) {
    in.pulse[i] = job.axes[i].pulse;
    if (!job.axes[i].moves.empty()) {
      in.start_mask |= 1u << i;
      in.move[i] = job.axes[i].moves[0];
    }
    level[i] = false;
  }
  uint64_t cycle = 0;
  for (;;) {
    core.tick(in);
    for (unsigned i = 0; i < kNumAxes; ++i) {
      if ((in.start_mask >> i) & 1u) {
        active[i] = true;
        count[i] = 0;
        ++next[i];
      }
    }
    in.start_mask = 0;
    bool all_done = true;
    for (unsigned i = 0; i < kNumAxes; ++i) {
      const AxisOutputs o = core.out(i);
      const bool lv = o.step != in.pulse[i].step_invert;
      if (lv && !level[i]) {
        ++count[i];
        ++r.steps[i];
        on_step(StepEvent{i, static_cast<unsigned>(next[i] - 1), count[i], cycle,
                          o.dir != in.pulse[i].dir_invert});
      }
      level[i] = lv;
      if (o.err) ++r.refused[i];
      if (o.done && active[i]) {
        active[i] = false;
        if (next[i] < job.axes[i].moves.size()) {
          in.start_mask |= 1u << i;
          in.move[i] = job.axes[i].moves[next[i]];
        }
      }
      r.position[i] = o.pos;
      if (active[i] || ((in.start_mask >> i) & 1u) || lv) all_done = false;
    }
    ++cycle;
    if (all_done) break;
    if (cycle >= opt.max_cycles) {
      r.timed_out = true;
      break;
    }
    if (opt.event_mode && in.start_mask == 0) {
      uint64_t k = core.quiet_ticks(in);
      k = std::min(k, opt.max_cycles - cycle);
      if (k > 0) {
        core.skip(k);
        cycle += k;
      }
    }
  }
  r.cycles = cycle;
  return r;
}

}  // namespace hexstep
