// SPDX-License-Identifier: Apache-2.0
// hexstep: a Wishbone B4 classic master for any TopSim. It holds a request until it samples
// ack at a rising edge (so the request is still driven in the ack cycle), can insert random
// idle cycles (cyc low) and wait cycles (cyc high, stb low) before requests, and checks every
// edge: ack only while cyc & stb, never two ack cycles in a row.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>

#include "hexstep/top_sim.hpp"

namespace hexstep {

class BusError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Bus {
 public:
  // The longest a request may wait for its ack (a CMD.push takes about 105 cycles, the
  // initialization after reset 4 * 8 * NAXES).
  static constexpr unsigned kAckTimeout = 400;

  explicit Bus(TopSim& sim, uint32_t seed = 1) : sim_(sim), rng_(seed) {}
  TopSim& sim() { return sim_; }

  // sim.reset() and the cycle count to 0.
  void reset();
  // One edge with the pins as driven now (then on_edge()).
  void tick();
  uint32_t read(uint32_t adr);
  void write(uint32_t adr, uint32_t dat, unsigned sel = 0xF);
  // n edges with no request.
  void idle(uint64_t n);
  // Event mode: k edges with the pins as driven now, jumped over by sim.skip(k) (k at most
  // sim.quiet_cycles(pins())); on_edge() is not called for them.
  void skip(uint64_t k) {
    sim_.skip(k);
    cycles_ += k;
  }
  // Random bus timing before each request: up to max_idle cycles with cyc low, then up to
  // max_wait cycles with cyc high and stb low. 0, 0: back-to-back requests.
  void set_timing(unsigned max_idle, unsigned max_wait) { max_idle_ = max_idle; max_wait_ = max_wait; }
  void set_estop(bool on) { pins_.estop = on; }
  // Raw drive of the bus inputs (for protocol tests); read()/write() drive them themselves.
  void drive(bool cyc, bool stb, bool we, uint32_t adr, uint32_t dat, unsigned sel);
  const WbPins& pins() const { return pins_; }

  // Edges since reset(); the cycle in progress has this number.
  uint64_t cycles() const { return cycles_; }
  // The cycle in which the last request was first driven (cyc & stb): the slave acts on it at
  // the edge that ends that cycle, or later if it is busy.
  uint64_t last_request_cycle() const { return last_req_; }
  uint64_t protocol_errors() const { return protocol_errors_; }
  uint64_t acks() const { return acks_; }

  // Called after every edge.
  std::function<void()> on_edge;

 private:
  TopSim& sim_;
  std::mt19937 rng_;
  WbPins pins_{};
  unsigned max_idle_ = 0, max_wait_ = 0;
  uint64_t cycles_ = 0, protocol_errors_ = 0, acks_ = 0, last_req_ = 0;
  bool prev_ack_ = false;
  void pre_request();
  uint32_t transfer(bool we, uint32_t adr, uint32_t dat, unsigned sel);
};

}  // namespace hexstep
