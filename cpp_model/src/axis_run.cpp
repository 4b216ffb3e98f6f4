// SPDX-License-Identifier: Apache-2.0
// hexstep: one move on one axis from AxisGen and PulseStage (hexstep/axis_run.hpp).
#include "hexstep/axis_run.hpp"

#include <algorithm>
#include <limits>

namespace hexstep {

AxisRun run_axis(const AxisMove& m, const AxisRunOptions& opt) {
  AxisRun r;
  const SlotMove s = make_slot(m, opt.widths);
  if (s.bad || s.empty) {
    r.refused = true;
    return r;
  }
  constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();
  const PulseConfig& pc = opt.pulse;
  PulseStage ps(opt.widths);
  AxisGen gen;
  // Cycle numbers of this run put F0 two frames in, so that every sample edge (the end of
  // frame cycle 4 axis - 1, for axis 0 the last cycle of the frame before) has a number.
  const uint64_t f0 = 2 * kFrameCycles;
  const uint64_t limit = opt.max_cycles > kNever / 2 ? kNever / 2 : f0 + opt.max_cycles;
  uint64_t c = 0;  // the next edge ends cycle c
  uint32_t n = 0;
  auto edge = [&](uint64_t due, int tgt) {
    const bool was = ps.step_level();
    ps.edge(c, false, pc, due, tgt);
    ++c;
    if (!was && ps.step_level()) {
      ++n;
      if (opt.keep_rises) r.rises.push_back(AxisRise{n, c - f0, ps.dir_level()});
      if (opt.on_rise) opt.on_rise(n, c - f0);
    }
  };
  // Edges up to (not including) the one that ends cycle `to`.
  auto run_to = [&](uint64_t to) {
    while (c < to) {
      const uint64_t q = opt.event_mode ? ps.quiet_cycles(c, pc) : 0;
      if (q > 0) {
        const uint64_t k = std::min(q, to - c);
        ps.skip(k);
        c += k;
      } else {
        edge(0, -1);
      }
    }
  };

  bool first = true;
  for (uint64_t F = f0;; F += kFrameCycles) {
    if (F > limit) {
      r.timed_out = true;
      break;
    }
    const uint64_t sample = F + kSlotCycles * opt.axis - 1;
    run_to(sample);
    if (!first && !gen.run()) break;
    if (opt.event_mode && !first && ps.accepts()) {
      // Whole frames in which the generator only adds (no step, no phase change) and the output
      // stage only counts down: jumped over together.
      uint64_t k = std::min(gen.quiet_ticks(), ps.quiet_cycles(c, pc) / kFrameCycles);
      k = std::min(k, (limit - F) / kFrameCycles + 1);
      if (k > 0) {
        gen.skip(k);
        ps.skip(k * kFrameCycles);
        c += k * kFrameCycles;
        r.ticks += k;
        F += (k - 1) * kFrameCycles;
        continue;
      }
    }
    const bool accepts = ps.accepts();  // the state before the sample edge decides
    edge(0, -1);
    run_to(sample + kCommitDelay);
    TickOut out;
    bool ticked = false;
    int tgt = -1;
    if (first) {  // the start: the move's first tick runs in the same slot
      gen.begin(s);
      tgt = s.m.dir ? 1 : 0;
      out = gen.tick();
      ticked = true;
      first = false;
    } else if (accepts) {
      out = gen.tick();
      ticked = true;
    } else {
      ++r.stalled;
    }
    if (ticked) ++r.ticks;
    edge(ticked && out.step ? F + kDueOffset - out.q : 0, tgt);
  }
  // The steps still owed are pulsed; then the axis is at rest.
  while (!r.timed_out && (ps.pending() || ps.step_level() || ps.dir_level() != ps.dir_target())) {
    const uint64_t q = opt.event_mode ? ps.quiet_cycles(c, pc) : 0;
    if (q > 0 && q != kNever) {
      ps.skip(q);
      c += q;
    } else {
      edge(0, -1);
    }
  }
  r.end_cycle = c - f0;
  return r;
}

}  // namespace hexstep
