// SPDX-License-Identifier: Apache-2.0
// hexstep: the Verilated hexstep_top behind TopSim, and the lock-step comparer.
#include "rtl_top.hpp"

#include <sstream>

#include "Vhexstep_top.h"
#include "Vhexstep_top___024root.h"
#include "verilated.h"
#include "verilated_fst_c.h"

#include "trace.hpp"

namespace hexstep {

struct RtlTop::Impl {
  VerilatedContext ctx;
  std::unique_ptr<Vhexstep_top> top;
  std::unique_ptr<VerilatedFstC> trace;
  uint64_t cycles = 0;
};

RtlTop::RtlTop(const std::string& trace_path) : impl_(new Impl) {
  impl_->top.reset(new Vhexstep_top(&impl_->ctx, "hexstep_top"));
  impl_->trace = open_trace(impl_->ctx, *impl_->top, trace_path, "hexstep");
  reset();
}

RtlTop::~RtlTop() {
  if (impl_->trace) impl_->trace->close();
  impl_->top->final();
}

void RtlTop::reset() {
  auto& t = *impl_->top;
  t.clk_i = 0;
  t.rst_i = 1;
  t.estop_i = 0;
  t.wb_cyc_i = t.wb_stb_i = t.wb_we_i = 0;
  t.wb_adr_i = t.wb_dat_i = t.wb_sel_i = 0;
  t.eval();
  for (int i = 0; i < 2; ++i) {
    t.clk_i = 1;
    t.eval();
    t.clk_i = 0;
    t.eval();
  }
  t.rst_i = 0;
  t.eval();
  impl_->cycles = 0;
}

void RtlTop::tick(const WbPins& in) {
  auto& t = *impl_->top;
  t.wb_cyc_i = in.cyc;
  t.wb_stb_i = in.stb;
  t.wb_we_i = in.we;
  t.wb_adr_i = in.adr & 0xFFFu;
  t.wb_dat_i = in.dat;
  t.wb_sel_i = in.sel & 0xFu;
  t.estop_i = in.estop;
  t.eval();
  if (impl_->trace) impl_->trace->dump(impl_->cycles * 10);
  t.clk_i = 1;
  t.eval();
  if (impl_->trace) impl_->trace->dump(impl_->cycles * 10 + 5);
  t.clk_i = 0;
  t.eval();
  ++impl_->cycles;
}

bool RtlTop::ack() const { return impl_->top->wb_ack_o; }
uint32_t RtlTop::dat() const { return impl_->top->wb_dat_o; }
bool RtlTop::irq() const { return impl_->top->irq_o; }
bool RtlTop::step(unsigned k) const { return (impl_->top->step_o >> k) & 1u; }
bool RtlTop::dir(unsigned k) const { return (impl_->top->dir_o >> k) & 1u; }
unsigned RtlTop::naxes() const { return rtl_naxes(); }
uint64_t RtlTop::cycles() const { return impl_->cycles; }

unsigned RtlTop::rtl_naxes() { return HEXSTEP_RTL_NAXES; }
Widths RtlTop::rtl_widths() {
  Widths w;
  w.acc = HEXSTEP_RTL_ACC_W;
  w.steps = HEXSTEP_RTL_STEP_W;
  w.dec_frac = HEXSTEP_RTL_DFRAC_W;
  w.pulse = HEXSTEP_RTL_PULSE_W;
  w.pos = HEXSTEP_RTL_POS_W;
  return w;
}

void Lockstep::reset() {
  a_.reset();
  b_.reset();
  edges_ = 0;
}

void Lockstep::tick(const WbPins& in) {
  a_.tick(in);
  b_.tick(in);
  ++edges_;
  std::ostringstream o;
  bool bad = false;
  auto cmp = [&](const char* what, uint64_t x, uint64_t y) {
    if (x != y) {
      bad = true;
      o << " " << what << " " << a_.name() << "=" << x << " " << b_.name() << "=" << y;
    }
  };
  cmp("ack", a_.ack(), b_.ack());
  cmp("irq", a_.irq(), b_.irq());
  if (a_.ack() || b_.ack()) cmp("dat", a_.dat(), b_.dat());
  for (unsigned k = 0; k < a_.naxes(); ++k) {
    if (a_.step(k) != b_.step(k)) cmp(("step" + std::to_string(k)).c_str(), a_.step(k), b_.step(k));
    if (a_.dir(k) != b_.dir(k)) cmp(("dir" + std::to_string(k)).c_str(), a_.dir(k), b_.dir(k));
  }
  if (bad) {
    ++mismatches_;
    if (mismatches_ <= 10)
      report_ += "edge " + std::to_string(edges_ - 1) + (context.empty() ? "" : " (" + context + ")") + ":" +
                 o.str() + "\n";
  }
}

}  // namespace hexstep
