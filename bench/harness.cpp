// SPDX-License-Identifier: Apache-2.0
// hexstep bench: suite, ideal instants and the runs of every algorithm (see harness.hpp).
#include "harness.hpp"

#include <random>
#include <stdexcept>

#include "hexstep/axis.hpp"
#include "hexstep/axis_run.hpp"

namespace hexstep::bench {

namespace {

real log_uniform(std::mt19937_64& rng, real lo, real hi) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return std::exp(std::log(lo) + static_cast<real>(u(rng)) * (std::log(hi) - std::log(lo)));
}

std::string clock_name(real f) { return std::to_string(static_cast<long>(std::llround(f / 1e6))) + " MHz"; }

std::string speed_band(real v) {
  if (v < 1e3) return "v_peak < 1e3";
  if (v < 1e5) return "1e3 <= v_peak < 1e5";
  return "v_peak >= 1e5";
}

// Plans and encodes one single-axis move; false if the registers cannot hold it at f.
bool make_single(real f, uint64_t N, real vmax, real a, real d, real vs, SuiteMove& out) {
  plan::Limits lim;
  lim.max_speed = vmax;
  lim.accel = a;
  lim.decel = d;
  lim.start_speed = vs;
  lim.end_speed = vs;
  try {
    out.plan = plan::plan_min_time(N, lim, true);
    out.enc = plan::encode(out.plan, f);
  } catch (const plan::PlanError&) {
    return false;
  }
  out.clock_hz = f;
  out.accel_limit = a;
  out.decel_limit = d;
  out.range = clock_name(f) + ", " + speed_band(out.plan.v_peak);
  return true;
}

}  // namespace

Suite make_suite(const SuiteOptions& o) {
  Suite s;
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int id = 0;
  int line_id = 0;
  const struct {
    real f;
    unsigned n, lines;
  } clocks[] = {{1e8, o.random_100, o.lines_100}, {4.8e7, o.random_48, o.lines_48}, {1.2e7, o.random_12, o.lines_12}};
  for (const auto& c : clocks) {
    if (o.directed) {
      // Range ends of the issue (and the three moves of the plots at 100 MHz), within what the
      // registers hold at this clock: speeds below one step per tick (f / 32; 3.125e6 steps/s
      // at 100 MHz) and accelerations up to 2^-16 step/tick^2 (ACC_W 48; 1.49e8 steps/s^2 at
      // 100 MHz, 2.1e6 at 12 MHz).
      const real vtop = std::min<real>(5e6, 0.99L * max_speed(c.f));
      const real atop = std::min<real>(1e8, 0.99L * max_accel(c.f));
      struct D {
        uint64_t N;
        real vmax, a, d, vs;
      };
      std::vector<D> dir = {
          {1, vtop, atop, atop, 0},              {10000000, vtop, atop, atop, 0},
          {10000000, vtop, atop, atop / 4, 5e4}, {3, 1, 10, 10, 1},
          {2000, 100, 10, 10, 0},                {400, vtop, 10, 40, 1},
          {100000, vtop, atop / 4, atop, 5e4},   {2, vtop, atop, atop, 0},
      };
      if (c.f == 1e8) {
        dir.push_back({400, 2000, 20000, 20000, 0});   // plot 1: trapezoid from rest
        dir.push_back({300, 5000, 8000, 4000, 0});     // plot 2: triangular, decel = accel/2
        dir.push_back({1000, 4000, 10000, 20000, 0});   // plot 3: triangular, decel = 2 x accel
      }
      for (const D& d : dir) {
        SuiteMove m;
        if (!make_single(c.f, d.N, d.vmax, d.a, d.d, d.vs, m))
          throw std::logic_error("bench: a directed move cannot be encoded");
        m.id = id++;
        m.kind = "directed";
        s.moves.push_back(m);
      }
    }
    for (unsigned k = 0; k < c.n;) {
      const real ratio = log_uniform(rng, 0.25, 4);
      const real a = log_uniform(rng, 10, 1e8);
      const real d = a / ratio;
      const real vmax = log_uniform(rng, 1, 5e6);
      const real vs = u01(rng) < 0.5 ? 0 : log_uniform(rng, 1, std::min<real>(5e4, vmax));
      const real nr = u01(rng) < 0.01 ? log_uniform(rng, 1e6, 1e7) : log_uniform(rng, 1, 1e6);
      const uint64_t N = std::max<uint64_t>(1, static_cast<uint64_t>(std::llround(nr)));
      if (d < 10 || d > 1e8) {
        ++s.redrawn_range;
        continue;
      }
      SuiteMove m;
      if (!make_single(c.f, N, vmax, a, d, vs, m)) {
        ++s.redrawn_range;
        continue;
      }
      if (m.plan.duration > o.max_duration_s) {
        ++s.redrawn_duration;
        continue;
      }
      m.id = id++;
      m.kind = "random";
      s.moves.push_back(m);
      ++k;
    }
    for (unsigned k = 0; k < c.lines;) {
      std::vector<plan::AxisRequest> req;
      const bool moving_start = u01(rng) < 0.5;
      const real vs_all = moving_start ? log_uniform(rng, 1, 5e3) : 0;
      for (unsigned ax = 0; ax < kNumAxes; ++ax) {
        plan::AxisRequest r;
        r.axis = ax;
        const int64_t n = u01(rng) < 0.15 ? 0 : std::llround(log_uniform(rng, 1, 1e5));
        r.steps = u01(rng) < 0.5 ? -n : n;
        r.limits.max_speed = log_uniform(rng, 100, 5e5);
        r.limits.accel = log_uniform(rng, 1e3, 1e7);
        r.limits.decel = r.limits.accel / log_uniform(rng, 0.25, 4);
        r.limits.start_speed = std::min(vs_all, r.limits.max_speed);
        r.limits.end_speed = r.limits.start_speed;
        req.push_back(r);
      }
      std::vector<SuiteMove> axes;
      bool ok = true;
      try {
        const plan::LinePlan lp = plan::coordinated_line(req);
        if (lp.path.duration > o.max_duration_s) {
          ++s.redrawn_duration;
          continue;
        }
        for (size_t i = 0; i < lp.axes.size(); ++i) {
          if (lp.axes[i].plan.steps == 0) continue;
          SuiteMove m;
          m.plan = lp.axes[i].plan;
          m.enc = plan::encode(m.plan, c.f);
          m.clock_hz = c.f;
          m.axis = lp.axes[i].axis;
          m.accel_limit = req[i].limits.accel;
          m.decel_limit = *req[i].limits.decel;
          axes.push_back(m);
        }
      } catch (const plan::PlanError&) {
        ok = false;
      }
      if (!ok || axes.empty()) {
        ++s.redrawn_range;
        continue;
      }
      for (SuiteMove& m : axes) {
        m.id = id++;
        m.kind = "line";
        m.line = line_id;
        m.range = "six-axis lines, " + clock_name(c.f);
        s.moves.push_back(m);
      }
      ++line_id;
      ++k;
    }
  }
  return s;
}

real ideal_time(const plan::PhasePlan& p, uint64_t i) { return p.time_at(static_cast<real>(i)); }

__float128 exact_time(const plan::PhasePlan& p, uint64_t i) {
  using q = __float128;
  const q ta = p.t_acc, tc = p.t_cruise, td = p.t_dec;
  const q v0 = p.v_start, vp = p.v_peak, a = p.a, d = p.d, sa = p.s_acc, sc = p.s_cruise;
  auto pos = [&](q t) -> q {
    if (t <= 0) return 0;
    if (t <= ta) return v0 * t + a * t * t / 2;
    t -= ta;
    if (t <= tc) return sa + vp * t;
    t -= tc;
    if (t <= td) return sa + sc + vp * t - d * t * t / 2;
    return static_cast<q>(p.steps);
  };
  const q x = static_cast<q>(i);
  q lo = 0, hi = ta + tc + td;
  if (pos(hi) < x) return hi;
  for (int k = 0; k < 240; ++k) {
    const q mid = (lo + hi) / 2;
    if (mid <= lo || mid >= hi) break;
    if (pos(mid) < x) lo = mid;
    else hi = mid;
  }
  return hi;
}

real ideal_check_ratio(const plan::PhasePlan& p, uint64_t i, real f) {
  const real t = ideal_time(p, i);
  const real diff = std::fabs(static_cast<real>(static_cast<__float128>(t) - exact_time(p, i)));
  const real v = p.speed(t);
  const real allow = 2 / f + (v > 0 ? 0.001L / v : std::numeric_limits<real>::infinity());
  return diff / allow;
}

uint64_t tick_sim(const AxisMove& m, unsigned axis, const PulseConfig& pc, const Widths& w, const RiseFn& on_rise,
                  uint64_t max_cycles) {
  AxisRunOptions o;
  o.axis = axis;
  o.pulse = pc;
  o.widths = w;
  o.max_cycles = max_cycles;
  o.keep_rises = false;
  uint64_t rises = 0;
  o.on_rise = [&](uint32_t, uint64_t cycle) { on_rise(++rises, cycle); };
  run_axis(m, o);
  return rises;
}

const std::vector<std::string>& algorithm_names() {
  static const std::vector<std::string> n = {"hexstep", "hexstep_regs", "avr446", "stoychitch", "spt_10khz", "dda_1khz"};
  return n;
}

bool comparison_applies(const std::string& name, const plan::PhasePlan& p, std::string& reason) {
  const bool same_ends = std::fabs(p.v_end - p.v_start) <= 1e-9L * std::max<real>(1, p.v_start);
  if (name == "avr446" && !(p.v_start == 0 && p.v_end == 0)) {
    reason = "start or end speed above 0: AVR446 ramps start and end at rest";
    return false;
  }
  if (name == "stoychitch" && !(p.v_start > 0 && same_ends)) {
    reason = p.v_start > 0 ? "end speed differs from the start speed (section 2 uses one vs)"
                           : "start speed 0: eq. 13 needs c0 = f/vs with vs > 0";
    return false;
  }
  if (name == "spt_10khz") {
    if (p.v_peak > 10000) {
      reason = "peak speed above 10,000 steps/s: one step per 10 kHz interrupt at most";
      return false;
    }
    if (!same_ends) {
      reason = "end speed differs from the start speed (the program has one vs)";
      return false;
    }
  }
  return true;
}

namespace {

// The comparison algorithms on one profile; m[k] filled for k >= 2 (k: algorithm_names index).
void run_comparisons(const SuiteMove& sm, std::vector<Metrics>& out, std::vector<Trace>* traces) {
  const plan::PhasePlan& p = sm.plan;
  const real f = sm.clock_hz;
  const real a = p.a > 0 ? p.a : sm.accel_limit;
  const real d = p.d > 0 ? p.d : sm.decel_limit;
  const auto& names = algorithm_names();
  for (size_t k = 2; k < names.size(); ++k) {
    Metrics m;
    m.expected = p.steps;
    std::string reason;
    if (!comparison_applies(names[k], p, reason)) {
      m.included = false;
      m.reason = reason;
      out[k] = m;
      continue;
    }
    MetricAcc<plan::PhasePlan> acc(p, p.steps, p.duration, f);
    Trace* tr = nullptr;
    if (traces) {
      traces->push_back(Trace{names[k], {}});
      tr = &traces->back();
    }
    const PulseFn fn = [&](uint64_t i, real t) {
      acc.pulse(i, t);
      if (tr) tr->t.push_back(t);
    };
    AlgoResult r;
    if (names[k] == "avr446") r = avr446_run(p.steps, a, d, p.v_peak, f, fn);
    else if (names[k] == "stoychitch") r = stoychitch_run(p.steps, p.v_start, p.v_peak, a, a / d, f, fn);
    else if (names[k] == "spt_10khz")
      r = arduino_run(static_cast<long>(p.steps), static_cast<float>(p.v_start), static_cast<float>(p.v_peak),
                      static_cast<float>(a), static_cast<float>(a / d), 10000.0f,
                      std::min<real>(2e4L, 2 * p.duration + 1 + (p.v_start > 0 ? 2 * p.steps / p.v_start : 0)), fn);
    else if (names[k] == "dda_1khz")
      r = dda_run(p.steps, p.duration, [&p](real t) { return p.position(t); }, f, 1000, fn);
    out[k] = acc.finish(r.finished);
  }
}

}  // namespace

MoveResult run_single(const SuiteMove& sm, std::vector<Trace>* traces) {
  MoveResult res;
  res.id = sm.id;
  res.algo.resize(algorithm_names().size());
  const real f = sm.clock_hz;
  MetricAcc<plan::PhasePlan> acc_plan(sm.plan, sm.plan.steps, sm.plan.duration, f);
  MetricAcc<IdealProfile> acc_regs(sm.enc.ideal, sm.plan.steps, sm.enc.ideal.duration(), f);
  Trace* tr = nullptr;
  if (traces) {
    traces->push_back(Trace{"hexstep", {}});
    tr = &traces->back();
  }
  // The rising edge lies kStepLatency cycles after the step's instant (ARCHITECTURE.md).
  const uint64_t rises = tick_sim(sm.enc.regs, 0, PulseConfig{}, Widths{}, [&](uint64_t i, uint64_t cycle) {
    const real t = (static_cast<real>(cycle) - kStepLatency) / f;
    acc_plan.pulse(i, t);
    acc_regs.pulse(i, t);
    if (tr) tr->t.push_back(t);
  });
  res.algo[0] = acc_plan.finish(rises == sm.plan.steps);
  res.algo[1] = acc_regs.finish(rises == sm.plan.steps);
  run_comparisons(sm, res.algo, traces);
  return res;
}

std::vector<MoveResult> run_line(const std::vector<const SuiteMove*>& axes) {
  // All axes of a line start on one START and share its time zero, and no axis affects another's
  // motion: each runs on its own axis of the same frame schedule.
  std::vector<MoveResult> res(axes.size());
  for (size_t i = 0; i < axes.size(); ++i) {
    const SuiteMove& m = *axes[i];
    const real f = m.clock_hz;
    MetricAcc<plan::PhasePlan> ap(m.plan, m.plan.steps, m.plan.duration, f);
    MetricAcc<IdealProfile> ar(m.enc.ideal, m.plan.steps, m.enc.ideal.duration(), f);
    const uint64_t rises = tick_sim(m.enc.regs, m.axis, PulseConfig{}, Widths{}, [&](uint64_t k, uint64_t cycle) {
      const real t = (static_cast<real>(cycle) - kStepLatency) / f;
      ap.pulse(k, t);
      ar.pulse(k, t);
    });
    res[i].id = m.id;
    res[i].algo.resize(algorithm_names().size());
    res[i].algo[0] = ap.finish(rises == m.plan.steps);
    res[i].algo[1] = ar.finish(rises == m.plan.steps);
    run_comparisons(m, res[i].algo, nullptr);
  }
  return res;
}

}  // namespace hexstep::bench
