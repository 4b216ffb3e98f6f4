// SPDX-License-Identifier: Apache-2.0
// hexstep: cycle-exact model of one axis. Every line here has a counterpart in
// rtl/hexstep_axis.v; docs/ARCHITECTURE.md describes the semantics in prose.
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

void AxisModel::reset() {
  cfg_ = AxisMove{};
  floor_ = 0;
  run_q_ = false;
  phase_q_ = Phase::Idle;
  s_q_ = p_q_ = 0;
  cnt_q_ = 0;
  dec_first_q_ = false;
  stop_q_ = false;
  owed_q_ = 0;
  step_q_ = false;
  dir_q_ = true;
  dir_tgt_q_ = true;
  c_q_ = c_max();
  d_q_ = d_max();
  pos_q_ = 0;
  done_q_ = err_q_ = rose_q_ = false;
}

int64_t AxisModel::position() const {
  uint64_t v = pos_q_ & w_.pos_mask();
  if (w_.pos < 64 && (v >> (w_.pos - 1)) & 1) v |= ~w_.pos_mask();
  return static_cast<int64_t>(v);
}

void AxisModel::tick(bool start, bool abort, bool stop, const AxisMove& mv,
                     const PulseConfig& pc) {
  const uint32_t pm = static_cast<uint32_t>(w_.pulse_mask());
  const uint32_t hi_t = std::max<uint32_t>(pc.step_high & pm, 1);
  const uint32_t lo_t = std::max<uint32_t>(pc.step_low & pm, 1);
  const uint32_t setup = pc.dir_setup & pm;
  const uint32_t hold = pc.dir_hold & pm;
  const bool busy_q = run_q_ || owed_q_ != 0;

  // ---- pulse stage (old state) ----
  const bool dir_change = (dir_q_ != dir_tgt_q_) && c_q_ >= hold;
  const bool rise = !abort && owed_q_ != 0 && !step_q_ && dir_q_ == dir_tgt_q_ &&
                    c_q_ >= hi_t + lo_t && d_q_ >= setup;
  const bool fall = step_q_ && c_q_ >= hi_t;

  // ---- generator (old state) ----
  bool run_n = run_q_;
  Phase phase_n = phase_q_;
  uint64_t s_n = s_q_, p_n = p_q_;
  uint32_t cnt_n = cnt_q_;
  bool dec_first_n = dec_first_q_;
  bool stop_n = stop_q_;
  unsigned carry = 0;
  const bool gen = run_q_ && owed_q_ != w_.owe_max();
  if (gen) {
    const uint64_t sm = w_.speed_mask();
    u128 sum = u128(p_q_) + s_q_;
    carry = static_cast<unsigned>(sum >> w_.speed_frac);
    p_n = static_cast<uint64_t>(sum) & sm;
    cnt_n = static_cast<uint32_t>((uint64_t(cnt_q_) + carry) & w_.steps_mask());
    bool clamp = false;
    switch (phase_q_) {
      case Phase::Accel: {
        u128 t = u128(s_q_) + cfg_.acc;
        clamp = t >= cfg_.v_max;
        s_n = clamp ? cfg_.v_max : static_cast<uint64_t>(t);
        break;
      }
      case Phase::Decel: {
        if (stop_q_) {
          // Controlled stop: subtract dec, no v_dec and no floor (the move ends on borrow).
          s_n = (s_q_ - cfg_.dec) & w_.speed_mask();
        } else {
          // The first decelerating tick loads v_dec (the planner's exact mean speed over that
          // tick); later ticks subtract dec. Neither goes below the floor.
          bool borrow = !dec_first_q_ && cfg_.dec > s_q_;
          uint64_t t = dec_first_q_ ? cfg_.v_dec : s_q_ - cfg_.dec;
          s_n = (borrow || t < floor_) ? floor_ : t;
        }
        dec_first_n = false;
        break;
      }
      default:
        break;
    }
    const uint64_t hi = p_n >> (w_.speed_frac - w_.dec_frac);
    const bool dec_trig = !cfg_.jog && phase_q_ != Phase::Decel &&
                          ((cnt_n == cfg_.dec_step && hi >= cfg_.dec_frac) ||
                           (cnt_q_ == cfg_.dec_step && carry));
    // Stopping: the old speed is below dec (or dec is 0): the motion is at rest.
    const bool stop_end = stop_q_ && (cfg_.dec > s_q_ || cfg_.dec == 0);
    const bool cnt_end = !cfg_.jog && cnt_n == cfg_.steps;
    if (cnt_end || stop_end) {
      run_n = false;
      phase_n = Phase::Idle;
    } else if (dec_trig) {
      phase_n = Phase::Decel;
      dec_first_n = true;
    } else if (phase_q_ == Phase::Accel && (clamp || (!cfg_.jog && cnt_n == cfg_.acc_steps))) {
      phase_n = Phase::Cruise;
    }
  }
  // STOP: from the next tick on, decelerate by dec from the speed reached.
  if (stop && run_n && !abort) {
    stop_n = true;
    phase_n = Phase::Decel;
    dec_first_n = false;
  }
  unsigned owed_n = owed_q_ + carry - (rise ? 1u : 0u);

  // ---- start / abort ----
  bool done_n = false, err_n = false;
  bool dir_tgt_n = dir_tgt_q_;
  if (abort) {
    run_n = false;
    phase_n = Phase::Idle;
    owed_n = 0;
  } else if (start) {
    if (busy_q) {
      err_n = true;  // a start strobe for a busy axis is refused
    } else {
      AxisMove m = mv;
      m.v_start &= w_.speed_mask();
      m.v_max &= w_.speed_mask();
      m.v_end &= w_.speed_mask();
      m.v_dec &= w_.speed_mask();
      m.acc &= w_.acc_mask();
      m.dec &= w_.acc_mask();
      m.steps &= static_cast<uint32_t>(w_.steps_mask());
      m.acc_steps &= static_cast<uint32_t>(w_.steps_mask());
      m.dec_step &= static_cast<uint32_t>(w_.steps_mask());
      m.dec_frac &= static_cast<uint32_t>(w_.dec_frac_mask());
      const uint32_t e = validate_move(m, w_);
      if ((m.steps == 0 && !m.jog) || e != kErrNone) {
        done_n = true;
        err_n = e != kErrNone;
      } else {
        cfg_ = m;
        floor_ = m.v_end != 0 ? m.v_end : m.dec;
        s_n = m.v_start;
        p_n = 0;
        cnt_n = 0;
        run_n = true;
        dec_first_n = true;
        stop_n = false;
        dir_tgt_n = m.dir;
        if (m.jog) {
          phase_n = m.acc != 0 ? Phase::Accel : Phase::Cruise;
        } else {
          phase_n = (m.dec_step == 0 && m.dec_frac == 0) ? Phase::Decel
                    : (m.acc_steps != 0)                  ? Phase::Accel
                                                          : Phase::Cruise;
        }
      }
    }
  }
  const bool busy_n = run_n || owed_n != 0;
  if (busy_q && !busy_n) done_n = true;

  // ---- pulse stage next state ----
  const bool dir_n = dir_change ? dir_tgt_q_ : dir_q_;
  const uint32_t c_n = rise ? 1u : std::min(c_q_ + 1u, c_max());
  const uint32_t d_n = dir_change ? 1u : std::min(d_q_ + 1u, d_max());
  const bool step_n = rise ? true : (fall ? false : step_q_);
  if (rise) pos_q_ = (pos_q_ + (dir_q_ ? 1ull : ~0ull)) & w_.pos_mask();

  run_q_ = run_n;
  phase_q_ = phase_n;
  s_q_ = s_n;
  p_q_ = p_n;
  cnt_q_ = cnt_n;
  dec_first_q_ = dec_first_n;
  stop_q_ = stop_n;
  owed_q_ = owed_n;
  dir_tgt_q_ = dir_tgt_n;
  dir_q_ = dir_n;
  c_q_ = c_n;
  d_q_ = d_n;
  step_q_ = step_n;
  done_q_ = done_n;
  err_q_ = err_n;
  rose_q_ = rise;
}

uint64_t AxisModel::gen_quiet_ticks() const {
  const u128 wrap = u128(1) << w_.speed_frac;
  const uint64_t thr_dec = (!cfg_.jog && phase_q_ != Phase::Decel && cnt_q_ == cfg_.dec_step)
                               ? (uint64_t(cfg_.dec_frac) << (w_.speed_frac - w_.dec_frac))
                               : kNever;
  uint64_t ev = kNever;  // first tick (>= 1) with an event
  auto consider_pos = [&](auto f, uint64_t limit) {
    ev = std::min(ev, first_reach(f, wrap, limit));
    if (thr_dec != kNever) ev = std::min(ev, first_reach(f, thr_dec, limit));
  };
  switch (phase_q_) {
    case Phase::Accel: {
      const uint64_t a = cfg_.acc;
      uint64_t jc;
      if (s_q_ >= cfg_.v_max) jc = 1;
      else if (a == 0) jc = kNever;
      else jc = (cfg_.v_max - s_q_ + a - 1) / a;
      ev = std::min(ev, jc);
      consider_pos([&](uint64_t j) { return pos_accel(p_q_, s_q_, a, j); },
                   std::min<uint64_t>(jc, kNever - 1));
      break;
    }
    case Phase::Cruise:
      consider_pos([&](uint64_t j) { return u128(p_q_) + u128(j) * s_q_; }, kNever - 1);
      break;
    case Phase::Decel: {
      const uint64_t d = cfg_.dec;
      if (stop_q_) {
        if (d == 0 || s_q_ < d) {
          ev = 1;
        } else {
          const uint64_t je = s_q_ / d + 1;  // the tick that ends the stop (old speed < d)
          ev = std::min(ev, je);
          consider_pos([&](uint64_t j) { return pos_decel(p_q_, s_q_, d, j); }, je);
        }
      } else if (dec_first_q_ || s_q_ < floor_) {
        ev = 1;
      } else if (s_q_ == floor_ || d == 0) {
        consider_pos([&](uint64_t j) { return u128(p_q_) + u128(j) * s_q_; }, kNever - 1);
      } else {
        const uint64_t jf = (s_q_ - floor_) / d + 1;  // first tick whose result is clamped
        ev = std::min(ev, jf);
        consider_pos([&](uint64_t j) { return pos_decel(p_q_, s_q_, d, j); }, jf);
      }
      break;
    }
    default:
      return kNever;
  }
  return ev == kNever ? kNever : ev - 1;
}

uint64_t AxisModel::quiet_ticks(const PulseConfig& pc) const {
  (void)pc;
  if (owed_q_ != 0 || step_q_ || dir_q_ != dir_tgt_q_ || done_q_ || err_q_ || rose_q_) return 0;
  if (!run_q_) return kNever;
  return gen_quiet_ticks();
}

void AxisModel::skip(uint64_t k) {
  if (k == 0) return;
  c_q_ = static_cast<uint32_t>(std::min<uint64_t>(uint64_t(c_q_) + k, c_max()));
  d_q_ = static_cast<uint32_t>(std::min<uint64_t>(uint64_t(d_q_) + k, d_max()));
  if (!run_q_) return;
  switch (phase_q_) {
    case Phase::Accel:
      p_q_ = static_cast<uint64_t>(pos_accel(p_q_, s_q_, cfg_.acc, k));
      s_q_ += k * cfg_.acc;
      break;
    case Phase::Cruise:
      p_q_ += k * s_q_;
      break;
    case Phase::Decel:
      if (!stop_q_ && (s_q_ == floor_ || cfg_.dec == 0)) {
        p_q_ += k * s_q_;
      } else {
        p_q_ = static_cast<uint64_t>(pos_decel(p_q_, s_q_, cfg_.dec, k));
        s_q_ -= k * cfg_.dec;
      }
      break;
    default:
      break;
  }
}

}  // namespace hexstep
