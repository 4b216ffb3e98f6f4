// SPDX-License-Identifier: Apache-2.0
// hexstep: cycle-exact model of hexstep_top (rtl/hexstep_wb.v + the core). Each block below
// names the part of rtl/hexstep_wb.v it mirrors.
#include "hexstep/wb_model.hpp"

namespace hexstep {

namespace {
// Word indexes (byte offset / 4) of rdl/hexstep.rdl.
enum : unsigned { G_ID = 0, G_VERSION = 1, G_START = 2, G_ABORT = 3, G_GSTATUS = 4,
                  G_IRQ_EN = 5, G_IRQ_PEND = 6, G_STOP = 7 };
enum : unsigned { W_STEPS = 0, W_DIR = 1, W_V_START = 2, W_V_MAX = 4, W_V_END = 6, W_V_DEC = 8,
                  W_ACC = 10, W_DEC = 12, W_ACC_STEPS = 14, W_DEC_STEP = 15, W_DEC_FRAC = 16,
                  W_CMD = 17, W_STATUS = 18, W_ERR = 19, W_POS_LO = 20, W_POS_HI = 21,
                  W_CFG = 22 };
constexpr unsigned kAddrBits = 12;

uint32_t lo_mask(unsigned w) { return w >= 32 ? 0xFFFFFFFFu : ((1u << w) - 1u); }
uint32_t hi_mask(unsigned w) {
  return w >= 64 ? 0xFFFFFFFFu : (w <= 32 ? 0u : ((1u << (w - 32)) - 1u));
}
uint64_t pair(const std::array<uint32_t, WbModel::kNw>& wd, unsigned i) {
  return uint64_t(wd[i]) | (uint64_t(wd[i + 1]) << 32);
}
}  // namespace

WbModel::WbModel(const Widths& w) : w_(w), core_(w) { reset(); }

void WbModel::reset() {
  core_.reset();
  core_in_ = CoreInputs{};
  ack_q_ = irq_q_ = false;
  dat_q_ = 0;
  es1_ = es2_ = estop_ = false;
  start_cmd_ = abort_cmd_ = stop_cmd_ = 0;
  irq_en_ = pend_ = 0;
  run_.fill(false);
  cnt_.fill(0);
  errf_.fill(0);
  poshi_.fill(0);
  for (auto& s : stg_) s.fill(0);
  for (auto& c : cfg_) c = {1, 1, 0, 0, 0};  // STEP_HIGH = STEP_LOW = 1
  // q0/q1 are not reset in the RTL; the core only samples them at a start, after a push.
  for (auto& s : q0_) s.fill(0);
  for (auto& s : q1_) s.fill(0);
}

// stg_mask()/cfg_mask(): implemented bits of each word.
uint32_t WbModel::stg_mask(unsigned i) const {
  switch (i) {
    case W_STEPS: case W_ACC_STEPS: case W_DEC_STEP: return lo_mask(w_.steps);
    case W_DIR: return 0x3u;
    case W_V_START: case W_V_MAX: case W_V_END: case W_V_DEC: return lo_mask(w_.speed_frac);
    case W_V_START + 1: case W_V_MAX + 1: case W_V_END + 1: case W_V_DEC + 1:
      return hi_mask(w_.speed_frac);
    case W_ACC: case W_DEC: return lo_mask(w_.acc);
    case W_ACC + 1: case W_DEC + 1: return hi_mask(w_.acc);
    case W_DEC_FRAC: return lo_mask(w_.dec_frac);
    default: return 0;
  }
}
uint32_t WbModel::cfg_mask(unsigned i) const { return i == kNc - 1 ? 0x3u : lo_mask(w_.pulse); }

// "Core move inputs": the queue head, fields at their word positions.
AxisMove WbModel::move_of(const Words& wd) const {
  AxisMove m;
  m.steps = wd[W_STEPS];
  m.dir = wd[W_DIR] & 1u;
  m.jog = (wd[W_DIR] >> 1) & 1u;
  m.v_start = pair(wd, W_V_START);
  m.v_max = pair(wd, W_V_MAX);
  m.v_end = pair(wd, W_V_END);
  m.v_dec = pair(wd, W_V_DEC);
  m.acc = pair(wd, W_ACC);
  m.dec = pair(wd, W_DEC);
  m.acc_steps = wd[W_ACC_STEPS];
  m.dec_step = wd[W_DEC_STEP];
  m.dec_frac = wd[W_DEC_FRAC];
  return m;
}
PulseConfig WbModel::pulse_of(unsigned k) const {
  const auto& c = cfg_[k];
  PulseConfig p;
  p.step_high = c[0];
  p.step_low = c[1];
  p.dir_setup = c[2];
  p.dir_hold = c[3];
  p.step_invert = c[4] & 1u;
  p.dir_invert = (c[4] >> 1) & 1u;
  return p;
}

void WbModel::tick(const WbPins& in) {
  // ---- bus request decode ----
  const bool req = in.cyc && in.stb && !ack_q_;
  const bool wr = req && in.we;
  const bool rd = req && !in.we;
  uint32_t bmask = 0;
  for (unsigned b = 0; b < 4; ++b)
    if ((in.sel >> b) & 1u) bmask |= 0xFFu << (8 * b);
  const uint32_t wdat = in.dat & bmask;
  const uint32_t adr = in.adr & ((1u << kAddrBits) - 1u);
  const uint32_t blk = adr >> 7;
  const uint32_t widx = (adr >> 2) & 31u;
  const bool g_hit = blk == 0;
  const uint32_t all = (1u << kNumAxes) - 1u;
  const uint32_t irq_mask = all | (all << 8) | (all << 16);

  // ---- core control from the old state (go, abort_w) ----
  std::array<AxisOutputs, kNumAxes> co;
  for (unsigned k = 0; k < kNumAxes; ++k) co[k] = core_.out(k);
  const uint32_t abort_w = abort_cmd_ | (estop_ ? all : 0u);
  uint32_t go = 0;
  for (unsigned k = 0; k < kNumAxes; ++k) {
    const uint32_t b = 1u << k;
    const bool g = !(abort_w & b) && !(stop_cmd_ & b) && cnt_[k] != 0 &&
                   (((start_cmd_ & b) && !run_[k] && !co[k].busy) || (run_[k] && co[k].done));
    if (g) go |= b;
  }
  CoreInputs ci;
  ci.start_mask = go;
  ci.abort_mask = abort_w;
  ci.stop_mask = stop_cmd_;
  for (unsigned k = 0; k < kNumAxes; ++k) {
    ci.move[k] = move_of(q0_[k]);
    ci.pulse[k] = pulse_of(k);
  }

  // ---- global registers ----
  auto stg_n = stg_;
  auto cfg_n = cfg_;
  auto q0_n = q0_;
  auto q1_n = q1_;
  auto cnt_n = cnt_;
  auto run_n = run_;
  auto errf_n = errf_;
  auto poshi_n = poshi_;
  uint32_t irq_en_n = irq_en_, pend_n = pend_;
  uint32_t start_n = 0, abort_n = 0, stop_n = 0;
  uint32_t rdata = 0;

  const bool estop_rise = es2_ && !estop_;
  const bool estop_n =
      es2_ || (estop_ && !(wr && g_hit && widx == G_GSTATUS && (wdat & 1u)));
  if (g_hit) {
    switch (widx) {
      case G_ID: rdata = kId; break;
      case G_VERSION:
        rdata = (uint32_t(kNumAxes) << 16) | (kVersionMajor << 8) | kVersionMinor;
        break;
      case G_GSTATUS: rdata = (es2_ ? 2u : 0u) | (estop_ ? 1u : 0u); break;
      case G_IRQ_EN: rdata = irq_en_; break;
      case G_IRQ_PEND: rdata = pend_; break;
      default: rdata = 0; break;
    }
    if (wr) {
      if (widx == G_START) start_n = wdat & all;
      if (widx == G_ABORT) abort_n = wdat & all;
      if (widx == G_STOP) stop_n = wdat & all;
      if (widx == G_IRQ_EN) irq_en_n = ((irq_en_ & ~bmask) | wdat) & irq_mask;
      if (widx == G_IRQ_PEND) pend_n = pend_ & ~wdat;
    }
  }

  // ---- per axis ----
  for (unsigned k = 0; k < kNumAxes; ++k) {
    const uint32_t b = 1u << k;
    const bool hit = blk == k + 2;
    const unsigned cnt = cnt_[k];
    bool push = false;
    if (hit) {
      if (widx < kNw) {
        rdata = stg_[k][widx];
        if (wr) stg_n[k][widx] = ((stg_[k][widx] & ~bmask) | wdat) & stg_mask(widx);
      }
      if (widx >= W_CFG && widx < W_CFG + kNc) {
        const unsigned i = widx - W_CFG;
        rdata = cfg_[k][i];
        if (wr) cfg_n[k][i] = ((cfg_[k][i] & ~bmask) | wdat) & cfg_mask(i);
      }
      const uint64_t pos64 = static_cast<uint64_t>(co[k].pos);
      switch (widx) {
        case W_STATUS:
          rdata = ((2u - cnt) << 4) | (run_[k] ? 8u : 0u) |
                  (static_cast<uint32_t>(co[k].phase) << 1) | (co[k].busy ? 1u : 0u);
          break;
        case W_ERR: rdata = errf_[k]; break;
        case W_POS_LO: rdata = static_cast<uint32_t>(pos64); break;
        case W_POS_HI: rdata = poshi_[k]; break;
        default: break;
      }
      if (rd && widx == W_POS_LO) poshi_n[k] = static_cast<uint32_t>(pos64 >> 32);
      if (wr && widx == W_CMD) push = wdat & 1u;
      if (wr && widx == W_ERR) errf_n[k] = errf_[k] & ~(wdat & 7u);
    }

    const bool flush = (abort_w & b) || (stop_cmd_ & b);
    const bool overrun = push && !flush && cnt == 2 && !(go & b);
    const bool ok_push = push && !flush && !overrun;
    if (flush) {
      cnt_n[k] = 0;
      run_n[k] = false;
    } else {
      if (go & b) run_n[k] = true;
      else if (run_[k] && co[k].done) run_n[k] = false;
      if (go & b) {
        q0_n[k] = q1_[k];
        if (ok_push) {
          if (cnt == 1) q0_n[k] = stg_[k];
          else q1_n[k] = stg_[k];
        } else {
          cnt_n[k] = cnt - 1;
        }
      } else if (ok_push) {
        if (cnt == 0) q0_n[k] = stg_[k];
        else q1_n[k] = stg_[k];
        cnt_n[k] = cnt + 1;
      }
    }

    // sticky errors and interrupts
    const uint32_t eset = (estop_rise ? 4u : 0u) | (overrun ? 2u : 0u) | (co[k].err ? 1u : 0u);
    errf_n[k] |= eset;
    if (co[k].done) pend_n |= b;
    if (cnt_n[k] < cnt) pend_n |= b << 8;
    if (eset) pend_n |= b << 16;
  }

  // ---- commit: the core sees the old register state, the block its next state ----
  core_.tick(ci);
  core_in_ = ci;
  ack_q_ = req;
  dat_q_ = rd ? rdata : 0;
  irq_q_ = (pend_n & irq_en_n) != 0;
  es2_ = es1_;
  es1_ = in.estop;
  estop_ = estop_n;
  start_cmd_ = start_n;
  abort_cmd_ = abort_n;
  stop_cmd_ = stop_n;
  run_ = run_n;
  cnt_ = cnt_n;
  errf_ = errf_n;
  poshi_ = poshi_n;
  irq_en_ = irq_en_n;
  pend_ = pend_n;
  stg_ = stg_n;
  cfg_ = cfg_n;
  q0_ = q0_n;
  q1_ = q1_n;
}

}  // namespace hexstep
