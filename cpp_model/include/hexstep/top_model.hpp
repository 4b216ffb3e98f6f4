// SPDX-License-Identifier: Apache-2.0
// hexstep: cycle-exact model of rtl/hexstep_top.v, the block software sees: the Wishbone
// register interface with its memory-backed staging registers and move loader, the frame
// engine that runs every axis's tick in its slot, and the STEP/DIR stages. Every rule here has
// its counterpart in rtl/ (named in the .cpp); docs/ARCHITECTURE.md states them in prose and
// the register map is rdl/hexstep.rdl (docs/REGISTERS.md). The co-simulation tests compare
// this model with the Verilated RTL on every output after every clock edge.
#pragma once

#include <array>
#include <cstdint>

#include "hexstep/axis.hpp"

namespace hexstep {

// The inputs of hexstep_top during one clock cycle (sampled at its rising edge).
struct WbPins {
  bool cyc = false;
  bool stb = false;
  bool we = false;
  uint32_t adr = 0;  // byte address (ADDR_W = 12 bits used)
  uint32_t dat = 0;
  unsigned sel = 0;  // byte enables, 4 bits
  bool estop = false;
};

class TopModel {
 public:
  // The word layout of the map (rdl/hexstep.rdl), shared with the tests.
  static constexpr unsigned kNw = 17;  // staging words per axis (STEPS..DEC_FRAC)
  static constexpr unsigned kNc = 5;   // pulse config words per axis (STEP_HIGH..POLARITY)
  static constexpr uint32_t kId = 0x48585354u;
  static constexpr uint32_t kVersionMajor = 1, kVersionMinor = 0;
  // Bus cycles (frame cycles 4i+3) that one CMD.push takes: the loader reads the staging words
  // one per bus cycle and writes the slot words one bus cycle later (rtl/hexstep_loader.v).
  static constexpr unsigned kLoaderSteps = 25;

  explicit TopModel(unsigned naxes = kNumAxes, const Widths& w = Widths{});
  void reset();
  // One rising clock edge with these inputs applied during the cycle before it.
  void tick(const WbPins& in);

  // Registered outputs after the last edge.
  bool ack() const { return ack_q_; }
  uint32_t dat() const { return dat_q_; }
  bool irq() const { return irq_q_; }
  // STEP/DIR pins: the output stage's levels through the live POLARITY register.
  bool step(unsigned k) const { return ax_[k].pulse.step_level() != bool(ax_[k].cfg[kNc - 1] & 1u); }
  bool dir(unsigned k) const { return ax_[k].pulse.dir_level() != bool(ax_[k].cfg[kNc - 1] & 2u); }

  // The cycle number of the cycle now in progress (edges since reset).
  uint64_t cycle() const { return n_; }
  unsigned naxes() const { return naxes_; }
  const Widths& widths() const { return w_; }

  // Introspection for the tests (none of it is visible on the pins directly).
  const AxisGen& gen(unsigned k) const { return ax_[k].gen; }
  const PulseStage& pulse(unsigned k) const { return ax_[k].pulse; }
  unsigned queued(unsigned k) const { return ax_[k].qn; }
  bool running(unsigned k) const { return ax_[k].running; }
  bool busy(unsigned k) const;      // STATUS.busy
  bool bus_idle() const { return op_.kind == Op::kNone; }
  PulseConfig pulse_config(unsigned k) const;
  uint32_t staging(unsigned k, unsigned word) const { return ax_[k].stg[word]; }
  // Time zero of axis k's running move: the first cycle of the frame in which its first tick
  // was sampled (docs/ARCHITECTURE.md, "Timing of the outputs").
  uint64_t move_t0(unsigned k) const { return ax_[k].t0; }

  // Event mode: edges from now (the first one ending the cycle in progress) during which, with
  // `in` held, nothing changes but what skip() advances in closed form; 0 if the next edge
  // must be simulated.
  uint64_t quiet_cycles(const WbPins& in) const;
  void skip(uint64_t k);

 private:
  struct Flight {            // a slot between its sample edge and its commit edge
    bool valid = false;
    uint64_t commit = 0;     // edge of the commit
    uint64_t frame = 0;      // first cycle of the frame of the sample
    bool start = false;      // a move starts in this slot (new or chained)
    bool start_new = false;  // ... by START (not by chaining)
    bool stop = false;       // STOP applies in this slot
    bool gen_ok = false;     // the output stage accepts a step
    bool abort_seen = false;
  };
  struct Axis {
    AxisGen gen;
    PulseStage pulse;
    std::array<uint32_t, kNw> stg{};
    std::array<uint32_t, kNc> cfg{};
    std::array<SlotMove, 3> slot{};
    unsigned act = 0;        // slot of the running (or last) move; queued moves follow it
    unsigned qn = 0;         // queued moves, 0..2
    bool running = false;    // started by START: queued moves chain
    bool chain = false;      // the next queued move starts in the axis's next slot
    bool starting = false;   // a start is between its sample and its commit
    uint32_t errf = 0;       // {estop, overrun, move}
    uint32_t poshi = 0;
    uint64_t t0 = 0;
    bool busy_prev = false;  // busy during the last cycle
    Flight fl;
  };
  struct Op {                // the bus engine's multi-cycle operation
    enum Kind { kNone, kInit, kStgRead, kStgWrite, kCfgRead, kCfgWrite, kPush } kind = kNone;
    uint64_t done = 0;       // edge at which it completes (and acks, except kInit)
    unsigned axis = 0, word = 0;
    uint32_t wdat = 0, bmask = 0;
    unsigned tail = 0;       // push: the slot being loaded
    bool cancelled = false;  // push: the queue was flushed meanwhile
    SlotMove sm{};
  };

  unsigned naxes_;
  Widths w_;
  uint64_t n_ = 0;
  bool ack_q_ = false, irq_q_ = false;
  bool cap_q_ = false;  // a request was taken at the last edge: act on it at this one
  uint32_t dat_q_ = 0;
  bool es1_ = false, es2_ = false, estop_ = false;
  uint32_t abort_cmd_ = 0, start_pend_ = 0, stop_pend_ = 0, frame_start_ = 0, frame_stop_ = 0;
  uint32_t irq_en_ = 0, pend_ = 0;
  std::array<Axis, kSlots> ax_{};
  Op op_{};

  uint32_t all_mask() const { return (1u << naxes_) - 1u; }
  uint32_t stg_mask(unsigned i) const;
  uint32_t cfg_mask(unsigned i) const;
  AxisMove staged_move(unsigned k) const;
  bool busy_core(const Axis& a) const;
  uint32_t status_word(unsigned k) const;
  static uint64_t next_bus_cycle(uint64_t c) { return c + 1 + ((3u + 4u - (unsigned)((c + 1) & 3u)) & 3u); }
};

}  // namespace hexstep
