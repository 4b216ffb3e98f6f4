// SPDX-License-Identifier: Apache-2.0
// hexstep: Verilator driver for rtl/hexstep_core.v. Inputs are applied while the clock is low,
// then one rising edge is evaluated, matching CoreSim::tick().
#include "rtl_core.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>

#include "Vhexstep_core.h"
#include "verilated.h"
#include "verilated_fst_c.h"

#include "trace.hpp"

namespace hexstep {

namespace {
// Widths of the default build (the Verilated model has no run-time parameters).
const Widths kW{};

template <std::size_t N>
void put(VlWide<N>& v, unsigned lsb, unsigned width, uint64_t value) {
  for (unsigned b = 0; b < width; ++b) {
    const unsigned bit = lsb + b;
    const uint32_t m = 1u << (bit % 32);
    if ((value >> b) & 1u) v[bit / 32] |= m; else v[bit / 32] &= ~m;
  }
}
template <typename T>
void put(T& v, unsigned lsb, unsigned width, uint64_t value) {
  for (unsigned b = 0; b < width; ++b) {
    const T m = static_cast<T>(T(1) << (lsb + b));
    if ((value >> b) & 1u) v |= m; else v &= static_cast<T>(~m);
  }
}
template <std::size_t N>
uint64_t get(const VlWide<N>& v, unsigned lsb, unsigned width) {
  // Word by word (at most three 32-bit words for 64 bits): read for every axis every cycle.
  uint64_t r = 0;
  for (unsigned got = 0, bit = lsb; got < width;) {
    const unsigned off = bit % 32;
    const unsigned n = std::min(32u - off, width - got);
    r |= ((static_cast<uint64_t>(v[bit / 32]) >> off) & Widths::mask(n)) << got;
    got += n;
    bit += n;
  }
  return r;
}
template <typename T>
uint64_t get(const T& v, unsigned lsb, unsigned width) {
  return (static_cast<uint64_t>(v) >> lsb) & Widths::mask(width);
}
}  // namespace

bool same_inputs(const AxisMove& a, const AxisMove& b) {
  return a.steps == b.steps && a.dir == b.dir && a.v_start == b.v_start && a.v_max == b.v_max &&
         a.v_end == b.v_end && a.v_dec == b.v_dec && a.acc == b.acc && a.dec == b.dec &&
         a.acc_steps == b.acc_steps && a.dec_step == b.dec_step && a.dec_frac == b.dec_frac &&
         a.jog == b.jog;
}
bool same_inputs(const PulseConfig& a, const PulseConfig& b) {
  return a.step_high == b.step_high && a.step_low == b.step_low && a.dir_setup == b.dir_setup &&
         a.dir_hold == b.dir_hold && a.step_invert == b.step_invert && a.dir_invert == b.dir_invert;
}

struct RtlCore::Impl {
  VerilatedContext ctx;
  // The move and pulse inputs last packed into the model's ports: packing is bit by bit, so
  // only axes whose inputs changed are packed again.
  std::array<AxisMove, kNumAxes> move{};
  std::array<PulseConfig, kNumAxes> pulse{};
  bool packed = false;
  std::unique_ptr<Vhexstep_core> top;
  std::unique_ptr<VerilatedFstC> trace;
  uint64_t cycles = 0;
};

RtlCore::RtlCore(const std::string& trace_path) : impl_(new Impl) {
  impl_->top.reset(new Vhexstep_core(&impl_->ctx, "hexstep_core"));
  impl_->trace = open_trace(impl_->ctx, *impl_->top, trace_path, "hexstep");
  reset();
}

RtlCore::~RtlCore() {
  if (impl_->trace) impl_->trace->close();
  impl_->top->final();
}

Widths RtlCore::rtl_widths() { return kW; }

uint64_t RtlCore::cycles() const { return impl_->cycles; }

void RtlCore::reset() {
  auto& t = *impl_->top;
  t.clk_i = 0;
  t.rst_i = 1;
  t.start_i = 0;
  t.abort_i = 0;
  t.stop_i = 0;
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

void RtlCore::tick(const CoreInputs& in) {
  auto& t = *impl_->top;
  t.start_i = static_cast<uint8_t>(in.start_mask);
  t.abort_i = static_cast<uint8_t>(in.abort_mask);
  t.stop_i = static_cast<uint8_t>(in.stop_mask);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    const AxisMove& m = in.move[k];
    const PulseConfig& p = in.pulse[k];
    if (impl_->packed && same_inputs(m, impl_->move[k]) && same_inputs(p, impl_->pulse[k])) continue;
    impl_->move[k] = m;
    impl_->pulse[k] = p;
    put(t.steps_i, k * kW.steps, kW.steps, m.steps);
    put(t.dir_i, k, 1, m.dir);
    put(t.jog_i, k, 1, m.jog);
    put(t.v_start_i, k * kW.speed_frac, kW.speed_frac, m.v_start);
    put(t.v_max_i, k * kW.speed_frac, kW.speed_frac, m.v_max);
    put(t.v_end_i, k * kW.speed_frac, kW.speed_frac, m.v_end);
    put(t.v_dec_i, k * kW.speed_frac, kW.speed_frac, m.v_dec);
    put(t.acc_i, k * kW.acc, kW.acc, m.acc);
    put(t.dec_i, k * kW.acc, kW.acc, m.dec);
    put(t.acc_steps_i, k * kW.steps, kW.steps, m.acc_steps);
    put(t.dec_step_i, k * kW.steps, kW.steps, m.dec_step);
    put(t.dec_frac_i, k * kW.dec_frac, kW.dec_frac, m.dec_frac);
    put(t.step_high_i, k * kW.pulse, kW.pulse, p.step_high);
    put(t.step_low_i, k * kW.pulse, kW.pulse, p.step_low);
    put(t.dir_setup_i, k * kW.pulse, kW.pulse, p.dir_setup);
    put(t.dir_hold_i, k * kW.pulse, kW.pulse, p.dir_hold);
    put(t.step_inv_i, k, 1, p.step_invert);
    put(t.dir_inv_i, k, 1, p.dir_invert);
  }
  impl_->packed = true;
  // Verilator settles the input-driven logic at the start of every eval(), so the rising edge
  // below sees the new inputs without a separate eval; that one is needed only for the trace.
  if (impl_->trace) {
    t.eval();
    impl_->trace->dump(impl_->cycles * 10);
  }
  t.clk_i = 1;
  t.eval();
  if (impl_->trace) impl_->trace->dump(impl_->cycles * 10 + 5);
  t.clk_i = 0;
  t.eval();
  ++impl_->cycles;
}

AxisOutputs RtlCore::out(unsigned k) const {
  const auto& t = *impl_->top;
  AxisOutputs o;
  o.step = get(t.step_o, k, 1);
  o.dir = get(t.dir_o, k, 1);
  o.busy = get(t.busy_o, k, 1);
  o.done = get(t.done_o, k, 1);
  o.err = get(t.err_o, k, 1);
  o.phase = static_cast<Phase>(get(t.phase_o, 2 * k, 2));
  uint64_t p = get(t.pos_o, k * kW.pos, kW.pos);
  if (kW.pos < 64 && ((p >> (kW.pos - 1)) & 1u)) p |= ~Widths::mask(kW.pos);
  o.pos = static_cast<int64_t>(p);
  return o;
}

}  // namespace hexstep
