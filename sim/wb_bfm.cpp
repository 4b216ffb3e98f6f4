// SPDX-License-Identifier: Apache-2.0
// hexstep: Wishbone master BFM for the Verilated rtl/hexstep_top.v (see wb_bfm.hpp).
#include "wb_bfm.hpp"

#include <cstdlib>
#include <stdexcept>

#include "Vhexstep_top.h"
#include "verilated.h"
#include "verilated_fst_c.h"

#include "trace.hpp"

namespace hexstep {

namespace {
constexpr unsigned kAckTimeout = 64;
}  // namespace

struct WbTop::Impl {
  VerilatedContext ctx;
  std::unique_ptr<Vhexstep_top> top;
  std::unique_ptr<VerilatedFstC> trace;
};

WbTop::WbTop(uint32_t seed, const std::string& trace_path) : impl_(new Impl), rng_(seed) {
  impl_->top.reset(new Vhexstep_top(&impl_->ctx, "hexstep_top"));
  impl_->trace = open_trace(impl_->ctx, *impl_->top, trace_path, "wb");
  reset();
}

WbTop::~WbTop() {
  if (impl_->trace) impl_->trace->close();
  impl_->top->final();
}

void WbTop::reset() {
  auto& t = *impl_->top;
  t.clk_i = 0;
  t.rst_i = 1;
  t.estop_i = 0;
  drive(false, false, false, 0, 0, 0);
  t.eval();
  for (int i = 0; i < 2; ++i) {
    t.clk_i = 1;
    t.eval();
    t.clk_i = 0;
    t.eval();
  }
  t.rst_i = 0;
  t.eval();
  cycles_ = 0;
  prev_ack_ = false;
}

void WbTop::drive(bool cyc, bool stb, bool we, uint32_t adr, uint32_t dat, unsigned sel) {
  auto& t = *impl_->top;
  t.wb_cyc_i = cyc;
  t.wb_stb_i = stb;
  t.wb_we_i = we;
  t.wb_adr_i = adr & 0xFFFu;
  t.wb_dat_i = dat;
  t.wb_sel_i = sel & 0xFu;
}

WbPins WbTop::pins() const {
  const auto& t = *impl_->top;
  WbPins p;
  p.cyc = t.wb_cyc_i;
  p.stb = t.wb_stb_i;
  p.we = t.wb_we_i;
  p.adr = t.wb_adr_i;
  p.dat = t.wb_dat_i;
  p.sel = t.wb_sel_i;
  p.estop = t.estop_i;
  return p;
}

void WbTop::tick() {
  auto& t = *impl_->top;
  if (pre_edge) pre_edge(pins());
  t.eval();
  if (impl_->trace) impl_->trace->dump(cycles_ * 10);
  t.clk_i = 1;
  t.eval();
  if (impl_->trace) impl_->trace->dump(cycles_ * 10 + 5);
  t.clk_i = 0;
  t.eval();
  ++cycles_;
  // The master's outputs do not change at this edge: a compliant slave acks only while they
  // show a request, and acks one request once.
  if (t.wb_ack_o) {
    ++acks_;
    if (!(t.wb_cyc_i && t.wb_stb_i) || prev_ack_) ++protocol_errors_;
  }
  prev_ack_ = t.wb_ack_o;
  if (on_edge) on_edge();
}

void WbTop::pre_request() {
  if (max_idle_) {
    const unsigned n = std::uniform_int_distribution<unsigned>(0, max_idle_)(rng_);
    drive(false, false, false, 0, 0, 0);
    for (unsigned i = 0; i < n; ++i) tick();
  }
  if (max_wait_) {
    const unsigned n = std::uniform_int_distribution<unsigned>(0, max_wait_)(rng_);
    auto& t = *impl_->top;
    t.wb_cyc_i = 1;
    t.wb_stb_i = 0;
    for (unsigned i = 0; i < n; ++i) tick();
  }
}

uint32_t WbTop::transfer(bool we, uint32_t adr, uint32_t dat, unsigned sel) {
  pre_request();
  drive(true, true, we, adr, dat, we ? sel : 0xF);
  for (unsigned i = 0;; ++i) {
    if (i == kAckTimeout) throw std::runtime_error("wishbone: no ack");
    tick();
    if (impl_->top->wb_ack_o) break;
  }
  const uint32_t r = impl_->top->wb_dat_o;
  // The master samples ack at the edge that ends the ack cycle; the request is held until then.
  tick();
  drive(false, false, false, 0, 0, 0);
  return r;
}

uint32_t WbTop::read(uint32_t adr) { return transfer(false, adr, 0, 0xF); }
void WbTop::write(uint32_t adr, uint32_t dat, unsigned sel) { transfer(true, adr, dat, sel); }

void WbTop::set_estop(bool on) { impl_->top->estop_i = on; }
bool WbTop::ack() const { return impl_->top->wb_ack_o; }
uint32_t WbTop::dat_o() const { return impl_->top->wb_dat_o; }
bool WbTop::irq() const { return impl_->top->irq_o; }
bool WbTop::step(unsigned k) const { return (impl_->top->step_o >> k) & 1u; }
bool WbTop::dir(unsigned k) const { return (impl_->top->dir_o >> k) & 1u; }

}  // namespace hexstep
