// SPDX-License-Identifier: Apache-2.0
// hexstep: job runner shared by the model, the Verilated RTL, the CLI and the tests: a bus
// master that programs the block the way firmware does (see job.hpp).
#include "hexstep/job.hpp"

#include <algorithm>
#include <stdexcept>

#include "hexstep/bus.hpp"

namespace hexstep {

namespace {
namespace A = regs::axis;

// Moves that produce steps, in order: the runner assigns rising edges to them by count.
std::vector<uint32_t> expected_steps(const AxisJob& aj, const Widths& w) {
  std::vector<uint32_t> v;
  for (const AxisMove& m : aj.moves) {
    const SlotMove s = make_slot(m, w);
    v.push_back(s.bad || s.empty ? 0u : s.m.steps);
  }
  return v;
}
}  // namespace

RunResult run_job(TopSim& sim, const Job& job, const std::function<void(const StepEvent&)>& on_step,
                  const RunOptions& opt) {
  RunResult r;
  const unsigned nax = sim.naxes();
  const Widths w = sim.widths();
  uint32_t mask = 0;
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (job.axes[k].moves.empty()) continue;
    if (k >= nax)
      throw std::invalid_argument("axis " + std::to_string(k) + " has moves, the core has " + std::to_string(nax) +
                                  " axes");
    for (const AxisMove& m : job.axes[k].moves)
      if (m.jog) throw std::invalid_argument("axis " + std::to_string(k) + ": a jog move never ends by itself");
    mask |= 1u << k;
  }

  Bus bus(sim, opt.bus_seed);
  bus.set_timing(opt.bus_idle, opt.bus_wait);
  bus.reset();

  std::array<std::vector<uint32_t>, kNumAxes> want{};
  std::array<size_t, kNumAxes> next{};      // next move to push
  std::array<size_t, kNumAxes> cur{};       // move the next rising edge belongs to
  std::array<uint32_t, kNumAxes> count{};   // its steps so far
  std::array<bool, kNumAxes> level{};       // STEP level before polarity, last cycle
  for (unsigned k = 0; k < kNumAxes; ++k) want[k] = expected_steps(job.axes[k], w);
  bool started = false;
  uint64_t t0 = 0;

  bus.on_edge = [&] {
    for (unsigned k = 0; k < nax && k < kNumAxes; ++k) {
      const bool lv = sim.step(k) != job.axes[k].pulse.step_invert;
      if (lv && !level[k] && started) {
        while (cur[k] < want[k].size() && count[k] >= want[k][cur[k]]) {
          ++cur[k];
          count[k] = 0;
        }
        ++count[k];
        ++r.steps[k];
        on_step(StepEvent{k, static_cast<unsigned>(cur[k]), count[k], bus.cycles() - t0,
                          sim.dir(k) != job.axes[k].pulse.dir_invert});
      }
      level[k] = lv;
    }
  };

  // Pulse configuration and interrupts.
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (!(mask & (1u << k))) continue;
    const PulseConfig& p = job.axes[k].pulse;
    bus.write(ax_reg(k, A::STEP_HIGH), p.step_high);
    bus.write(ax_reg(k, A::STEP_LOW), p.step_low);
    bus.write(ax_reg(k, A::DIR_SETUP), p.dir_setup);
    bus.write(ax_reg(k, A::DIR_HOLD), p.dir_hold);
    bus.write(ax_reg(k, A::POLARITY), (p.step_invert ? 1u : 0u) | (p.dir_invert ? 2u : 0u));
  }
  bus.write(regs::IRQ_ENABLE, (mask << regs::IRQ_ENABLE_DONE_SHIFT) | (mask << regs::IRQ_ENABLE_SLOT_SHIFT));

  auto refill = [&](unsigned k, unsigned free) {
    while (free > 0 && next[k] < job.axes[k].moves.size()) {
      push_move(bus, k, job.axes[k].moves[next[k]++]);
      --free;
    }
  };
  for (unsigned k = 0; k < kNumAxes; ++k)
    if (mask & (1u << k)) refill(k, 2);
  bus.write(regs::START, mask);
  t0 = bus.last_request_cycle();
  started = true;
  r.setup_cycles = t0;

  uint32_t active = mask;  // axes not yet finished
  while (active) {
    if (bus.cycles() - t0 >= opt.max_cycles) {
      r.timed_out = true;
      break;
    }
    if (!sim.irq()) {
      uint64_t k = opt.event_mode ? sim.quiet_cycles(bus.pins()) : 0;
      k = std::min<uint64_t>(k, opt.max_cycles - (bus.cycles() - t0));
      if (k > 1) {
        bus.skip(k);
      } else {
        bus.idle(1);
      }
      continue;
    }
    const uint32_t pend = bus.read(regs::IRQ_PENDING);
    bus.write(regs::IRQ_PENDING, pend);
    for (unsigned k = 0; k < kNumAxes; ++k) {
      const uint32_t b = 1u << k;
      if (!(active & b)) continue;
      const bool done_ev = (pend >> regs::IRQ_PENDING_DONE_SHIFT) & b;
      const bool slot_ev = (pend >> regs::IRQ_PENDING_SLOT_SHIFT) & b;
      if (!done_ev && !slot_ev) continue;
      if (done_ev) {
        const uint32_t e = bus.read(ax_reg(k, A::ERR));
        if (e & A::ERR_MOVE_MASK) {
          ++r.refused[k];
          bus.write(ax_reg(k, A::ERR), A::ERR_MOVE_MASK);
        }
      }
      const uint32_t st = bus.read(ax_reg(k, A::STATUS));
      const unsigned free = (st & A::STATUS_FREE_MASK) >> A::STATUS_FREE_SHIFT;
      const bool busy = st & A::STATUS_BUSY_MASK, run = st & A::STATUS_RUN_MASK;
      refill(k, free);
      if (!busy && !run) {
        const uint32_t st2 = bus.read(ax_reg(k, A::STATUS));
        const unsigned free2 = (st2 & A::STATUS_FREE_MASK) >> A::STATUS_FREE_SHIFT;
        if (free2 < 2) {
          // The queue ran dry while the axis was running: the pushed moves wait for START.
          bus.write(regs::START, b);
          ++r.restarts[k];
        } else if (next[k] >= job.axes[k].moves.size()) {
          // Finished. A refused last move consumed after this event's ERR read set ERR.move
          // and a done that this loop no longer serves: read ERR once more.
          if (bus.read(ax_reg(k, A::ERR)) & A::ERR_MOVE_MASK) {
            ++r.refused[k];
            bus.write(ax_reg(k, A::ERR), A::ERR_MOVE_MASK);
          }
          active &= ~b;
        }
      }
    }
  }
  r.cycles = bus.cycles() - t0;
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (!(mask & (1u << k))) continue;
    const uint32_t lo = bus.read(ax_reg(k, A::POS_LO));
    const uint32_t hi = bus.read(ax_reg(k, A::POS_HI));
    r.position[k] = static_cast<int64_t>((uint64_t(hi) << 32) | lo);
  }
  r.protocol_errors = bus.protocol_errors();
  return r;
}

}  // namespace hexstep
