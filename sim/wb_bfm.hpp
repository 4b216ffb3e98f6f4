// SPDX-License-Identifier: Apache-2.0
// hexstep: Wishbone B4 classic master bus-functional model driving the Verilated hexstep_top.
// Inputs are applied while the clock is low, then one rising edge is evaluated. The master
// holds a request until it samples ack at a rising edge (so the request is still driven in the
// ack cycle) and inserts random idle cycles (cyc low) and wait cycles (cyc high, stb low)
// before requests. Every edge is checked: ack only while cyc & stb, never two ack cycles in a row.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>

#include "hexstep/wb_model.hpp"

namespace hexstep {

class WbTop {
 public:
  // trace_path: FST trace file (empty: none; TRACE=1 in the environment writes wb_<n>.fst).
  explicit WbTop(uint32_t seed = 1, const std::string& trace_path = "");
  ~WbTop();
  void reset();

  // One rising clock edge with the currently driven inputs; then on_edge() is called.
  void tick();
  // Raw drive of the bus inputs (for protocol tests); read()/write() drive them themselves.
  void drive(bool cyc, bool stb, bool we, uint32_t adr, uint32_t dat, unsigned sel);

  uint32_t read(uint32_t adr);
  void write(uint32_t adr, uint32_t dat, unsigned sel = 0xF);
  // Random bus timing before each request: up to max_idle cycles with cyc low, then up to
  // max_wait cycles with cyc high and stb low. 0, 0: back-to-back requests.
  void set_timing(unsigned max_idle, unsigned max_wait) { max_idle_ = max_idle; max_wait_ = max_wait; }

  void set_estop(bool on);
  bool ack() const;
  uint32_t dat_o() const;
  bool irq() const;
  bool step(unsigned axis) const;
  bool dir(unsigned axis) const;
  uint64_t cycles() const { return cycles_; }
  // Acks seen while cyc & stb were not both driven, or in two consecutive cycles.
  uint64_t protocol_errors() const { return protocol_errors_; }
  uint64_t acks() const { return acks_; }

  // Called after every rising edge (outputs of that edge visible).
  std::function<void()> on_edge;
  // Called right before every rising edge with the inputs the edge samples (to feed a model).
  std::function<void(const WbPins&)> pre_edge;
  // The inputs currently driven.
  WbPins pins() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::mt19937 rng_;
  unsigned max_idle_ = 0, max_wait_ = 0;
  uint64_t cycles_ = 0, protocol_errors_ = 0, acks_ = 0;
  bool prev_ack_ = false;
  void pre_request();
  uint32_t transfer(bool we, uint32_t adr, uint32_t dat, unsigned sel);
};

}  // namespace hexstep
