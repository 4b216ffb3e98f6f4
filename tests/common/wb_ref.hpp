// SPDX-License-Identifier: Apache-2.0
// hexstep tests: the golden register-block model hexstep::WbModel beside a Verilated
// hexstep_top (tests/rtl through sim/wb_bfm, tests/spi behind the SPI bridge). The model is fed
// the pins the RTL samples before every edge; after the edge ack, read data (where the harness
// shows it), IRQ and every STEP/DIR pin are compared. WbModel itself equals the RTL at every
// edge under random bus traffic (tests/rtl/test_wb_model.cpp), so the queue, START, ABORT,
// E-STOP and polarity semantics are written once, in cpp_model/src/wb_model.cpp.
// Mismatches are collected as text (like tests/soak/lockstep.hpp): every test asserts
// `mismatches == 0` and prints report_text().
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "hexstep/wb_model.hpp"
#include "hexstep_regs.hpp"  // sim/, generated from rdl/hexstep.rdl

namespace hexstep::test {

// Outputs of hexstep_top after an edge; step/dir bit k is axis k.
struct TopPins {
  bool ack = false;
  bool irq = false;
  std::optional<uint32_t> dat;  // wb_dat_o, where the harness brings it out
  uint32_t step = 0, dir = 0;
};

class WbRef {
 public:
  WbRef() = default;
  WbRef(const WbRef&) = delete;
  WbRef& operator=(const WbRef&) = delete;
  // Hooks itself into a harness with pre_edge(const WbPins&), on_edge(), ack(), irq(),
  // step(k), dir(k) and optionally dat_o() (WbTop, the SPI test's SpiTop).
  template <class Top>
  explicit WbRef(Top& top) {
    top.pre_edge = [this](const WbPins& p) { before_edge(p); };
    top.on_edge = [this, &top] {
      TopPins o;
      o.ack = top.ack();
      o.irq = top.irq();
      if constexpr (HasDat<Top>::value) o.dat = top.dat_o();
      for (unsigned k = 0; k < kNumAxes; ++k) {
        o.step |= uint32_t(top.step(k)) << k;
        o.dir |= uint32_t(top.dir(k)) << k;
      }
      after_edge(o);
    };
  }

  void before_edge(const WbPins& p) { model.tick(p); }
  void after_edge(const TopPins& o);

  // Every axis idle in the core and not running a queue (moves may still be queued).
  bool idle() const;
  AxisOutputs out(unsigned k) const { return model.core().out(k); }
  std::string report_text() const;

  WbModel model;
  uint64_t mismatches = 0;
  uint64_t edges = 0;                                   // edges seen since construction
  std::array<uint64_t, kNumAxes> rises{};               // STEP rising edges (before polarity)
  std::array<std::vector<uint64_t>, kNumAxes> starts;   // edge index of every core start
  std::array<std::vector<uint64_t>, kNumAxes> dones;    // edge index after which done was high
  std::vector<uint64_t> acks;                           // edge index of every ack
  std::string context;                                  // what the test is doing (in reports)
  std::vector<std::string> report;                      // the first 10 mismatches

 private:
  template <class T, class = void>
  struct HasDat : std::false_type {};
  template <class T>
  struct HasDat<T, std::void_t<decltype(std::declval<const T&>().dat_o())>> : std::true_type {};
  std::array<bool, kNumAxes> prev_step_{};
};

// Register address of axis k's register at offset reg (rdl/hexstep.rdl).
constexpr uint32_t ax(unsigned k, uint32_t reg) {
  return regs::AXIS_BASE + k * regs::AXIS_STRIDE + reg;
}
constexpr uint32_t kAllAxes = (1u << kNumAxes) - 1u;

// Writes move m into the staging registers of axis k, word by word (any bus with
// write(adr, dat): WbTop, SpiMaster). DIR carries the jog bit.
template <class Bus>
void write_move(Bus& bus, unsigned k, const AxisMove& m) {
  namespace A = regs::axis;
  auto w64 = [&](uint32_t lo, uint64_t v) {
    bus.write(ax(k, lo), static_cast<uint32_t>(v));
    bus.write(ax(k, lo + 4), static_cast<uint32_t>(v >> 32));
  };
  bus.write(ax(k, A::STEPS), m.steps);
  bus.write(ax(k, A::DIR), (m.dir ? 1u : 0u) | (m.jog ? 2u : 0u));
  w64(A::V_START_LO, m.v_start);
  w64(A::V_MAX_LO, m.v_max);
  w64(A::V_END_LO, m.v_end);
  w64(A::V_DEC_LO, m.v_dec);
  w64(A::ACC_LO, m.acc);
  w64(A::DEC_LO, m.dec);
  bus.write(ax(k, A::ACC_STEPS), m.acc_steps);
  bus.write(ax(k, A::DEC_STEP), m.dec_step);
  bus.write(ax(k, A::DEC_FRAC), m.dec_frac);
}

// Stages move m on axis k and pushes it (CMD.push).
template <class Bus>
void push(Bus& bus, unsigned k, const AxisMove& m) {
  write_move(bus, k, m);
  bus.write(ax(k, regs::axis::CMD), regs::axis::CMD_PUSH_MASK);
}

}  // namespace hexstep::test
