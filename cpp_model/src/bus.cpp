// SPDX-License-Identifier: Apache-2.0
// hexstep: Wishbone master for a TopSim (see bus.hpp).
#include "hexstep/bus.hpp"

namespace hexstep {

void Bus::reset() {
  sim_.reset();
  pins_ = WbPins{};
  cycles_ = 0;
  prev_ack_ = false;
}

void Bus::drive(bool cyc, bool stb, bool we, uint32_t adr, uint32_t dat, unsigned sel) {
  pins_.cyc = cyc;
  pins_.stb = stb;
  pins_.we = we;
  pins_.adr = adr & 0xFFFu;
  pins_.dat = dat;
  pins_.sel = sel & 0xFu;
}

void Bus::tick() {
  sim_.tick(pins_);
  ++cycles_;
  // The master's outputs do not change at this edge: a compliant slave acks only while they
  // show a request, and acks one request once.
  const bool a = sim_.ack();
  if (a) {
    ++acks_;
    if (!(pins_.cyc && pins_.stb) || prev_ack_) ++protocol_errors_;
  }
  prev_ack_ = a;
  if (on_edge) on_edge();
}

void Bus::idle(uint64_t n) {
  drive(false, false, false, 0, 0, 0);
  for (uint64_t i = 0; i < n; ++i) tick();
}

void Bus::pre_request() {
  if (max_idle_) {
    const unsigned n = std::uniform_int_distribution<unsigned>(0, max_idle_)(rng_);
    idle(n);
  }
  if (max_wait_) {
    const unsigned n = std::uniform_int_distribution<unsigned>(0, max_wait_)(rng_);
    pins_.cyc = true;
    pins_.stb = false;
    for (unsigned i = 0; i < n; ++i) tick();
  }
}

uint32_t Bus::transfer(bool we, uint32_t adr, uint32_t dat, unsigned sel) {
  pre_request();
  drive(true, true, we, adr, dat, we ? sel : 0xF);
  last_req_ = cycles_;
  for (unsigned i = 0;; ++i) {
    if (i == kAckTimeout) throw BusError("wishbone: no ack within " + std::to_string(kAckTimeout) + " cycles");
    tick();
    if (sim_.ack()) break;
  }
  const uint32_t r = sim_.dat();
  // The master samples ack at the edge that ends the ack cycle; the request is held until then.
  tick();
  drive(false, false, false, 0, 0, 0);
  return r;
}

uint32_t Bus::read(uint32_t adr) { return transfer(false, adr, 0, 0xF); }
void Bus::write(uint32_t adr, uint32_t dat, unsigned sel) { transfer(true, adr, dat, sel); }

}  // namespace hexstep
