// SPDX-License-Identifier: Apache-2.0
// hexstep: one axis of the frame engine: the refusal rules and slot contents (the loader of rtl/hexstep_wb.v),
// the per-tick generator (one slot of rtl/hexstep_engine.v) and the STEP/DIR output stage
// (rtl/hexstep_pulse.v). docs/ARCHITECTURE.md describes the semantics in prose.
#include "hexstep/axis.hpp"

#include <algorithm>
#include <limits>

namespace hexstep {

namespace {
using u128 = unsigned __int128;
constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();

// Smallest j in [1, limit] with f(j) >= target for a nondecreasing f, or kNever.
template <typename F>
uint64_t first_reach(F f, u128 target, uint64_t limit) {
  if (limit == 0) return kNever;
  uint64_t lo = 0;  // f(lo) < target (lo == 0 stands for "before the first tick")
  uint64_t hi = 1;
  while (f(hi) < target) {
    if (hi >= limit) return kNever;
    lo = hi;
    hi = (hi > limit / 2) ? limit : hi * 2;
  }
  while (hi - lo > 1) {
    uint64_t mid = lo + (hi - lo) / 2;
    if (f(mid) >= target) hi = mid; else lo = mid;
  }
  return hi;
}

// Saturating at 2^127 so that comparisons against 2^64-sized targets stay exact.
constexpr u128 kBig = u128(1) << 127;

u128 pos_accel(uint64_t p, uint64_t s, uint64_t a, uint64_t j) {
  // p + j*s + a*j*(j-1)/2
  if (a != 0 && j > (1ull << 42)) return kBig;
  u128 tri = (u128(j) * (j - 1)) / 2;  // < 2^85 here
  return u128(p) + u128(j) * s + tri * a;
}

u128 pos_decel(uint64_t p, uint64_t s, uint64_t d, uint64_t j) {
  // p + j*s - d*j*(j-1)/2, only used while s - (j-1)*d stays >= 0
  u128 up = u128(p) + u128(j) * s;
  u128 down = (u128(d) * (j - 1)) * j / 2;
  return up - down;
}
}  // namespace

uint32_t validate_move(const AxisMove& m, const Widths& w) {
  (void)w;
  uint32_t e = kErrNone;
  if (m.jog) {
    if (m.v_max == 0) e |= kErrVmaxZero;
    if (m.v_start > m.v_max) e |= kErrStartAboveMax;
    if (m.v_start == 0 && m.acc == 0) e |= kErrNoStart;
    if (m.dec == 0) e |= kErrJogNoDec;
    return e;
  }
  if (m.steps == 0) return kErrNone;
  if (m.v_max == 0) e |= kErrVmaxZero;
  if (m.v_start > m.v_max) e |= kErrStartAboveMax;
  // The deceleration floor (v_end, or dec when v_end is 0) must not exceed v_max.
  if (m.v_end > m.v_max || (m.v_end == 0 && m.dec > m.v_max)) e |= kErrEndAboveMax;
  if (m.v_dec > m.v_max) e |= kErrDecAboveMax;
  if (m.acc_steps > m.steps || m.dec_step > m.steps) e |= kErrCountPastN;
  if (m.v_end == 0 && m.dec == 0) e |= kErrNoFloor;
  bool decel_now = (m.dec_step == 0 && m.dec_frac == 0);
  if (!decel_now && m.v_start == 0 && (m.acc == 0 || m.acc_steps == 0)) e |= kErrNoStart;
  return e;
}

SlotMove make_slot(const AxisMove& staged, const Widths& w) {
  SlotMove s;
  AxisMove& m = s.m;
  m = staged;
  // The staging registers hold only the implemented bits of each word.
  m.steps &= static_cast<uint32_t>(w.steps_mask());
  m.acc_steps &= static_cast<uint32_t>(w.steps_mask());
  m.dec_step &= static_cast<uint32_t>(w.steps_mask());
  m.dec_frac &= static_cast<uint32_t>(w.dec_frac_mask());
  m.acc &= w.acc_mask();
  m.dec &= w.acc_mask();
  s.floor = m.v_end != 0 ? m.v_end : m.dec;
  s.dfa = w.dec_frac >= 32 ? m.dec_frac : (m.dec_frac << (32 - w.dec_frac));
  s.empty = !m.jog && m.steps == 0;
  s.bad = !s.empty && validate_move(m, w) != kErrNone;
  s.dec_zero = m.dec == 0;
  if (m.jog) {
    s.init = m.acc != 0 ? Phase::Accel : Phase::Cruise;
  } else {
    s.init = (m.dec_step == 0 && m.dec_frac == 0) ? Phase::Decel
             : (m.acc_steps != 0)                  ? Phase::Accel
                                                   : Phase::Cruise;
  }
  return s;
}

unsigned subtick(uint64_t e, uint64_t s) {
  const uint32_t et = static_cast<uint32_t>(e >> (64 - kSubtickBits));
  const uint32_t st = static_cast<uint32_t>(s >> (64 - kSubtickBits));
  if (st == 0) return 0;
  uint32_t rem = et;
  unsigned q = 0;
  for (int j = static_cast<int>(kFrameLog2) - 1; j >= 0; --j) {
    const uint32_t r2 = rem << 1;
    if (r2 >= st) {
      q |= 1u << j;
      rem = r2 - st;
    } else {
      rem = r2;
    }
  }
  return q;
}

// ---- AxisGen ----

void AxisGen::begin(const SlotMove& s) {
  cfg_ = s;
  run_ = true;
  phase_ = s.init;
  dec_first_ = true;
  stop_ = false;
  s_ = s.m.v_start;
  p_ = 0;
  re_ = s.m.steps;
  ra_ = s.m.acc_steps;
  rd_ = s.m.dec_step;
}

void AxisGen::enter_stop() {
  if (!run_) return;
  stop_ = true;
  phase_ = Phase::Decel;
  dec_first_ = false;
}

TickOut AxisGen::tick() {
  TickOut out;
  const AxisMove& m = cfg_.m;
  const u128 sum = u128(p_) + s_;
  const unsigned step = static_cast<unsigned>(sum >> 64);
  const uint64_t pn = static_cast<uint64_t>(sum);
  const uint32_t re_n = re_ - step, ra_n = ra_ - step, rd_n = rd_ - step;
  uint64_t sn = s_;
  bool clamp = false;
  switch (phase_) {
    case Phase::Accel: {
      const u128 t = u128(s_) + m.acc;
      clamp = t >= m.v_max;
      sn = clamp ? m.v_max : static_cast<uint64_t>(t);
      break;
    }
    case Phase::Decel:
      if (stop_) {
        sn = s_ - m.dec;  // modulo 2^64: no v_dec, no floor (the move ends on a borrow)
      } else if (dec_first_) {
        sn = m.v_dec < cfg_.floor ? cfg_.floor : m.v_dec;
      } else {
        const bool borrow = m.dec > s_;
        const uint64_t t = s_ - m.dec;
        sn = (borrow || t < cfg_.floor) ? cfg_.floor : t;
      }
      dec_first_ = false;
      break;
    default:
      break;
  }
  const bool dfc = static_cast<uint32_t>(pn >> 32) >= cfg_.dfa;
  const bool dec_trig = !m.jog && phase_ != Phase::Decel && ((rd_n == 0 && dfc) || (rd_ == 0 && step));
  // Stopping: the old speed is below dec (or dec is 0): the motion is at rest.
  const bool stop_end = stop_ && (m.dec > s_ || cfg_.dec_zero);
  const bool cnt_end = !m.jog && re_n == 0;
  out.step = step != 0;
  out.q = step ? subtick(pn, s_) : 0;
  if (cnt_end || stop_end) {
    run_ = false;
    phase_ = Phase::Idle;
    out.ended = true;
  } else if (dec_trig) {
    phase_ = Phase::Decel;
    dec_first_ = true;
  } else if (phase_ == Phase::Accel && (clamp || (!m.jog && ra_n == 0))) {
    phase_ = Phase::Cruise;
  }
  s_ = sn;
  p_ = pn;
  re_ = re_n;
  ra_ = ra_n;
  rd_ = rd_n;
  return out;
}

uint64_t AxisGen::quiet_ticks() const {
  if (!run_) return kNever;
  const u128 wrap = u128(1) << 64;
  const AxisMove& m = cfg_.m;
  const uint64_t thr_dec = (!m.jog && phase_ != Phase::Decel && rd_ == 0) ? (uint64_t(cfg_.dfa) << 32) : kNever;
  uint64_t ev = kNever;  // first tick (>= 1) with an event
  auto consider_pos = [&](auto f, uint64_t limit) {
    ev = std::min(ev, first_reach(f, wrap, limit));
    if (thr_dec != kNever) ev = std::min(ev, first_reach(f, thr_dec, limit));
  };
  switch (phase_) {
    case Phase::Accel: {
      const uint64_t a = m.acc;
      uint64_t jc;
      if (s_ >= m.v_max) jc = 1;
      else if (a == 0) jc = kNever;
      else jc = (m.v_max - s_) / a + ((m.v_max - s_) % a != 0);  // ceil, without overflow
      ev = std::min(ev, jc);
      consider_pos([&](uint64_t j) { return pos_accel(p_, s_, a, j); }, std::min<uint64_t>(jc, kNever - 1));
      break;
    }
    case Phase::Cruise:
      consider_pos([&](uint64_t j) { return u128(p_) + u128(j) * s_; }, kNever - 1);
      break;
    case Phase::Decel: {
      const uint64_t d = m.dec;
      if (stop_) {
        if (d == 0 || s_ < d) {
          ev = 1;
        } else {
          const uint64_t je = s_ / d + 1;  // the tick that ends the stop (old speed < d)
          ev = std::min(ev, je);
          consider_pos([&](uint64_t j) { return pos_decel(p_, s_, d, j); }, je);
        }
      } else if (dec_first_ || s_ < cfg_.floor) {
        ev = 1;
      } else if (s_ == cfg_.floor || d == 0) {
        consider_pos([&](uint64_t j) { return u128(p_) + u128(j) * s_; }, kNever - 1);
      } else {
        const uint64_t jf = (s_ - cfg_.floor) / d + 1;  // first tick whose result is clamped
        ev = std::min(ev, jf);
        consider_pos([&](uint64_t j) { return pos_decel(p_, s_, d, j); }, jf);
      }
      break;
    }
    default:
      return kNever;
  }
  return ev == kNever ? kNever : ev - 1;
}

void AxisGen::skip(uint64_t k) {
  if (k == 0 || !run_) return;
  const AxisMove& m = cfg_.m;
  switch (phase_) {
    case Phase::Accel:
      p_ = static_cast<uint64_t>(pos_accel(p_, s_, m.acc, k));
      s_ += k * m.acc;
      break;
    case Phase::Cruise:
      p_ += k * s_;
      break;
    case Phase::Decel:
      if (!stop_ && (s_ == cfg_.floor || m.dec == 0)) {
        p_ += k * s_;
      } else {
        p_ = static_cast<uint64_t>(pos_decel(p_, s_, m.dec, k));
        s_ -= k * m.dec;
      }
      break;
    default:
      break;
  }
}

// ---- PulseStage ----

void PulseStage::reset() {
  due_.clear();
  owed_ = 0;
  step_ = false;
  dir_ = true;
  tgt_ = true;
  h_ = l_ = u_ = s_ = 0;
  pos_ = 0;
}

int64_t PulseStage::position() const {
  uint64_t v = pos_ & w_.pos_mask();
  if (w_.pos < 64 && (v >> (w_.pos - 1)) & 1) v |= ~w_.pos_mask();
  return static_cast<int64_t>(v);
}

namespace {
bool over(uint32_t t) { return t <= 1; }
uint32_t dec0(uint32_t t) { return t == 0 ? 0 : t - 1; }
}  // namespace

void PulseStage::edge(uint64_t cycle, bool abort, const PulseConfig& pc, uint64_t req_due, int tgt) {
  const uint32_t pm = static_cast<uint32_t>(w_.pulse_mask());
  // Events, all from the old state.
  const bool dir_change = (dir_ != tgt_) && over(u_);
  const bool rise = !abort && owed_ != 0 && !step_ && over(l_) && dir_ == tgt_ && over(s_);
  const bool fall = step_ && over(h_);
  unsigned due_now = 0;
  for (uint64_t d : due_) due_now += d == cycle ? 1u : 0u;

  // Next state.
  if (abort) {
    owed_ = 0;
    due_.clear();
  } else {
    owed_ = owed_ + due_now - (rise ? 1u : 0u);
    due_.erase(std::remove(due_.begin(), due_.end(), cycle), due_.end());
    if (req_due != 0) due_.push_back(req_due);
  }
  uint32_t h = dec0(h_), l = dec0(l_), u = dec0(u_), s = dec0(s_);
  if (rise) {
    h = pc.step_high & pm;
    u = pc.dir_hold & pm;
    pos_ = (pos_ + (dir_ ? 1ull : ~0ull)) & w_.pos_mask();
    step_ = true;
  } else if (fall) {
    l = pc.step_low & pm;
    step_ = false;
  }
  if (dir_change) {
    dir_ = tgt_;
    s = pc.dir_setup & pm;
  }
  if (tgt >= 0) tgt_ = tgt != 0;
  h_ = h;
  l_ = l;
  u_ = u;
  s_ = s;
}

uint64_t PulseStage::quiet_cycles(uint64_t cycle, const PulseConfig& pc) const {
  (void)pc;
  if (owed_ != 0 || step_ || dir_ != tgt_) return 0;
  uint64_t q = std::numeric_limits<uint64_t>::max();
  for (uint64_t d : due_) q = std::min(q, d > cycle ? d - cycle : 0);
  return q;
}

void PulseStage::skip(uint64_t k) {
  auto sub = [k](uint32_t t) { return k >= t ? 0u : static_cast<uint32_t>(t - k); };
  h_ = sub(h_);
  l_ = sub(l_);
  u_ = sub(u_);
  s_ = sub(s_);
}

}  // namespace hexstep
