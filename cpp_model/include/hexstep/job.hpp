// SPDX-License-Identifier: Apache-2.0
// hexstep: a register-level job (per axis, a list of moves) and the runner that plays it on
// any TopSim through the Wishbone bus, the way firmware on a soft CPU does: pulse
// configuration, the first two moves of every axis pushed, one START for all axes, then the
// queues refilled from the slot-free interrupt. The same runner drives the model and the RTL,
// so their STEP/DIR output can be compared event by event.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "hexstep/top_sim.hpp"

namespace hexstep {

struct AxisJob {
  PulseConfig pulse{};
  std::vector<AxisMove> moves;
};

struct Job {
  uint64_t clock_hz = kDefaultClockHz;
  // The core build the registers are meant for (units: 2^-SPEED_W step per tick, ...).
  Widths widths{};
  std::array<AxisJob, kNumAxes> axes{};
};

// One STEP rising edge.
struct StepEvent {
  unsigned axis = 0;
  unsigned move = 0;   // index of the move within its axis
  uint32_t step = 0;   // 1-based index within the move
  uint64_t cycle = 0;  // first cycle with STEP high, counted from the cycle START was written in
  bool dir = true;     // true: positive motion
  bool operator==(const StepEvent& o) const {
    return axis == o.axis && move == o.move && step == o.step && cycle == o.cycle && dir == o.dir;
  }
};

struct RunOptions {
  bool event_mode = false;        // skip quiet stretches (only where the TopSim supports it)
  uint64_t max_cycles = 1ull << 44;
  uint32_t bus_seed = 1;          // random bus timing (with bus_idle/bus_wait)
  unsigned bus_idle = 0, bus_wait = 0;
};

struct RunResult {
  uint64_t cycles = 0;        // cycles from the START write until every axis came to rest
  uint64_t setup_cycles = 0;  // cycles from reset to the START write
  bool timed_out = false;
  std::array<int64_t, kNumAxes> position{};
  std::array<uint32_t, kNumAxes> refused{};  // refusals seen (ERR.move after a done interrupt)
  std::array<uint64_t, kNumAxes> steps{};
  std::array<uint32_t, kNumAxes> restarts{};  // START again after a queue ran dry
  uint64_t protocol_errors = 0;               // Wishbone protocol violations seen by the master
};

// Plays the job. Throws std::invalid_argument if it moves an axis the simulator lacks or has a
// jog move (which only a STOP ends), BusError if the block stops acknowledging.
RunResult run_job(TopSim& sim, const Job& job, const std::function<void(const StepEvent&)>& on_step,
                  const RunOptions& opt = RunOptions{});

// Writes move m into the staging registers of axis k and pushes it (CMD.push), word by word,
// on any bus with write(adr, dat).
template <class B>
void push_move(B& bus, unsigned k, const AxisMove& m);

}  // namespace hexstep

#include "hexstep/regs.hpp"

namespace hexstep {

// Register address of axis k's register at offset reg (rdl/hexstep.rdl).
constexpr uint32_t ax_reg(unsigned k, uint32_t reg) { return regs::AXIS_BASE + k * regs::AXIS_STRIDE + reg; }

template <class B>
void write_move(B& bus, unsigned k, const AxisMove& m) {
  namespace A = regs::axis;
  auto w64 = [&](uint32_t lo, uint64_t v) {
    bus.write(ax_reg(k, lo), static_cast<uint32_t>(v));
    bus.write(ax_reg(k, lo + 4), static_cast<uint32_t>(v >> 32));
  };
  bus.write(ax_reg(k, A::STEPS), m.steps);
  bus.write(ax_reg(k, A::DIR), (m.dir ? 1u : 0u) | (m.jog ? 2u : 0u));
  w64(A::V_START_LO, m.v_start);
  w64(A::V_MAX_LO, m.v_max);
  w64(A::V_END_LO, m.v_end);
  w64(A::V_DEC_LO, m.v_dec);
  w64(A::ACC_LO, m.acc);
  w64(A::DEC_LO, m.dec);
  bus.write(ax_reg(k, A::ACC_STEPS), m.acc_steps);
  bus.write(ax_reg(k, A::DEC_STEP), m.dec_step);
  bus.write(ax_reg(k, A::DEC_FRAC), m.dec_frac);
}

template <class B>
void push_move(B& bus, unsigned k, const AxisMove& m) {
  write_move(bus, k, m);
  bus.write(ax_reg(k, regs::axis::CMD), regs::axis::CMD_PUSH_MASK);
}

}  // namespace hexstep
