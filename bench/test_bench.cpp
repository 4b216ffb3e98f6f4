// SPDX-License-Identifier: Apache-2.0
// The bounded slice of `make bench` that runs in `make test`: the harness's ideal instants
// against an exact evaluation and a closed form, each comparison algorithm on a case worked by
// hand from its seed document, the error metrics on known streams, and a small seeded slice of
// the suite on which hexstep must end on exactly N steps.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "harness.hpp"
#include "hexstep/job.hpp"
#include "hexstep/top_sim.hpp"

using namespace hexstep;
using namespace hexstep::bench;

namespace {

plan::PhasePlan make_plan(uint64_t N, real vmax, real a, real d, real vs) {
  plan::Limits lim;
  lim.max_speed = vmax;
  lim.accel = a;
  lim.decel = d;
  lim.start_speed = vs;
  lim.end_speed = vs;
  return plan::plan_min_time(N, lim, true);
}

struct Pulse {
  uint64_t i;
  real t;
};

}  // namespace

// The long double closed form against __float128 bisection, every step of small moves.
TEST(BenchIdeal, LongDoubleMatchesExactBisection) {
  const plan::PhasePlan plans[] = {
      make_plan(400, 2000, 20000, 20000, 0),      // trapezoid from rest
      make_plan(300, 5000, 8000, 4000, 0),        // triangular
      make_plan(1000, 4000, 10000, 20000, 200),   // start speed
      make_plan(3, 1, 10, 10, 1),                 // constant speed
      make_plan(5000, 5e6, 1e8, 2.5e7, 5e4),      // fast
  };
  for (const auto& p : plans) {
    for (uint64_t i = 1; i <= p.steps; ++i) {
      const __float128 e = exact_time(p, i);
      const long double diff = std::fabs(static_cast<long double>(static_cast<__float128>(ideal_time(p, i)) - e));
      // Where the speed is not near zero: 1e-6 cycle at 100 MHz. At a rest-to-rest end the
      // instant is ill-conditioned (dt = sqrt(2 dx / d)); judged against the allowance there.
      const real v = p.speed(ideal_time(p, i));
      if (v > 1e-3L * p.v_peak) {
        ASSERT_LT(diff * 1e8L, 1e-6L) << "step " << i << " of " << p.steps;
      }
      ASSERT_LT(ideal_check_ratio(p, i, 1e8), 1e-3L) << "step " << i << " of " << p.steps;
    }
  }
}

// From rest at acceleration a, step i is reached at sqrt(2 i / a) (AVR446 appendix 5.1).
TEST(BenchIdeal, AccelerationFromRestIsSqrt2iOverA) {
  const plan::PhasePlan p = make_plan(10000, 1000, 500, 500, 0);  // s_acc = 1000 steps
  for (uint64_t i : {1ull, 2ull, 10ull, 999ull})
    EXPECT_NEAR(static_cast<double>(ideal_time(p, i)), std::sqrt(2.0 * i / 500.0), 1e-12) << i;
  // Cruise at 1000 steps/s: 2 s of ramp up, then 1 ms per step.
  EXPECT_NEAR(static_cast<double>(ideal_time(p, 1500)), 2.0 + 0.5, 1e-12);
}

TEST(BenchMetrics, PerfectAndShiftedStreams) {
  const plan::PhasePlan p = make_plan(50, 1000, 5000, 5000, 0);
  MetricAcc<plan::PhasePlan> perfect(p, p.steps, p.duration, 1e8), late(p, p.steps, p.duration, 1e8);
  for (uint64_t i = 1; i <= p.steps; ++i) {
    perfect.pulse(i, ideal_time(p, i));
    late.pulse(i, ideal_time(p, i) + 3e-8L);  // 3 cycles late at 100 MHz
  }
  const Metrics a = perfect.finish(), b = late.finish();
  EXPECT_EQ(a.final_err(), 0);
  EXPECT_EQ(a.max_err, 0);
  EXPECT_EQ(a.max_excess, 0);
  EXPECT_NEAR(static_cast<double>(b.max_err), 3e-8, 1e-15);
  EXPECT_NEAR(static_cast<double>(b.duration_err), 3e-8, 1e-15);
  // Excess over 2 cycles: 1 cycle times the ideal speed, largest at step 25, the peak of this
  // triangle: sqrt(2 * 5000 * 25) = 500 steps/s.
  EXPECT_NEAR(static_cast<double>(b.max_excess), 1e-8 * 500, 1e-12);
}

// AVR446 worked by hand at f = 1 MHz, a = 2 steps/s^2: c0 = trunc(0.676 * 1e6 * sqrt(2/2)) =
// 676000; c1 = 676000 - 1352000/5 = 405600 (rest 0); c2 = 405600 - 811200/9 = 315467 (rest 3);
// c3 = 315467 - 630937/13 = 266934 (rest 8).
TEST(BenchAvr446, RecurrenceByHand) {
  std::vector<Pulse> got;
  avr446_run(1000, 2, 2, 1e6, 1e6, [&](uint64_t i, real t) { got.push_back({i, t}); });
  ASSERT_EQ(got.size(), 1000u);
  const long expect[] = {676000, 676000 + 405600, 676000 + 405600 + 315467, 676000 + 405600 + 315467 + 266934};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(got[k].i, static_cast<uint64_t>(k + 1));
    EXPECT_EQ(std::llround(got[k].t * 1e6L), expect[k]) << "pulse " << k + 1;
  }
  // Without the 0.676 factor the first ratio 0.6 would be 44% above sqrt(2) - 1 (section 2.3.1).
  EXPECT_NEAR(0.6 / (std::sqrt(2.0) - 1) - 1, 0.44, 0.01);
}

// Section 3.2.1: 1000 steps, accel 100, decel 300, speed 200: max_s_lim = 200^2/200 = 200 <
// accel_lim = 1000*300/400 = 750, decel_val = -trunc(200*100/300) = -66, decel_start = 934.
// 100 steps, accel = decel = 100, speed 1000: max_s_lim 5000 >= accel_lim 50, decel_val = -50.
TEST(BenchAvr446, StepCountsByHand) {
  Avr446Setup s = avr446_setup(1000, 100, 300, 200, 1e6);
  EXPECT_EQ(s.max_s_lim, 200);
  EXPECT_EQ(s.accel_lim, 750);
  EXPECT_EQ(s.decel_val, -66);
  EXPECT_EQ(s.decel_start, 934);
  s = avr446_setup(100, 100, 100, 1000, 1e6);
  EXPECT_EQ(s.max_s_lim, 5000);
  EXPECT_EQ(s.accel_lim, 50);
  EXPECT_EQ(s.decel_val, -50);
  EXPECT_EQ(s.decel_start, 50);
  for (uint64_t n : {1ull, 2ull, 3ull, 100ull, 1000ull}) {
    uint64_t last = 0;
    const AlgoResult r = avr446_run(n, 100, 300, 200, 1e6, [&](uint64_t i, real) { last = i; });
    EXPECT_EQ(r.pulses, n);
    EXPECT_EQ(last, n);
  }
}

// Section 2, eq. 4-8: N = 1000, vs = 100, vM = 1000, aM = 1000, m = 2: T = -0.3 + sqrt(6.09),
// v = 100 + 1000 T/3 = 822.6 <= vM: triangular, Na = floor(1000/3) = 333, Nd = 667.
// N = 10000: trapezoid, ta = 0.9, Tad = 2.7, s_ad = 270 + 1000*2.7^2/6 = 1485, Na = 495,
// Nd = 990, Nv = 8515.
TEST(BenchStoychitch, PlanningByHand) {
  StoychitchPlan p = stoychitch_plan(1000, 100, 1000, 1000, 2);
  EXPECT_TRUE(p.triangular);
  EXPECT_EQ(p.Na, 333u);
  EXPECT_EQ(p.Nd, 667u);
  EXPECT_EQ(p.Nv, 0u);
  p = stoychitch_plan(10000, 100, 1000, 1000, 2);
  EXPECT_FALSE(p.triangular);
  EXPECT_EQ(p.Na, 495u);
  EXPECT_EQ(p.Nd, 990u);
  EXPECT_EQ(p.Nv, 8515u);
}

// Eq. 11-14 at f = 1 MHz, vs = 100: c0 = 10000 (eq. 13); Ra = 1000/1e12, c1 = 10000/1.1 =
// 9090.909, corrected by (1 + 0.08/1) (eq. 14) = 9818.18 -> 9818 counts.
TEST(BenchStoychitch, DelaysByHand) {
  EXPECT_NEAR(stoychitch_next(10000, 1e-9), 10000 / 1.1, 1e-9);
  std::vector<Pulse> got;
  const AlgoResult r = stoychitch_run(1000, 100, 1000, 1000, 2, 1e6, [&](uint64_t i, real t) { got.push_back({i, t}); });
  EXPECT_EQ(r.pulses, 1000u);
  ASSERT_EQ(got.size(), 1000u);
  EXPECT_EQ(std::llround(got[0].t * 1e6L), 10000);
  EXPECT_EQ(std::llround(got[1].t * 1e6L), 10000 + 9818);
}

// The paper's own parameters (appendix): K = 4096, vs = 0.5, vM = 2, aM = 2 rad/s(^2), m = 2,
// one revolution. In steps (alfa = 2 pi/4096 rad): trapezoid with ta = 0.75 s, T_ad = 2.25 s,
// ss = 2.8125 rad = 1833.46 steps: np = 1833, Na = int(1833/3) = 611, Nd = 1222, Nv = 2263.
// First step: position after k interrupts is k*Vsf + Af*k(k+1)/2 (speed is added first):
// k = 30 gives 0.984, k = 31 gives 1.017, so the first step is at 3.1 ms.
TEST(BenchArduino, PapersExampleByHand) {
  const float spr = 4096.0f / (2.0f * 3.14159265f);  // steps per rad
  const float vs = 0.5f * spr, vM = 2.0f * spr, aM = 2.0f * spr;
  const ArduinoPlan p = arduino_plan(4096, vs, vM, aM, 2.0f, 10000.0f);
  EXPECT_EQ(p.Na, 611);
  EXPECT_EQ(p.Nd, 1222);
  EXPECT_EQ(p.Nv, 2263);
  std::vector<Pulse> got;
  const AlgoResult r = arduino_run(4096, vs, vM, aM, 2.0f, 10000.0f, 100, [&](uint64_t i, real t) { got.push_back({i, t}); });
  EXPECT_TRUE(r.finished);
  EXPECT_EQ(r.pulses, 4096u);
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(std::llround(got[0].t * 10000), 31);
}

// Constant 1000 steps/s at f = 1 MHz, 1 kHz servo (1000 cycles per period): the rate is
// ceil(2^32/1000) = 4294968, the accumulator crosses each whole step on the 1000th cycle of
// the period, so step i is at exactly i ms.
TEST(BenchDda, ConstantSpeedByHand) {
  std::vector<Pulse> got;
  const AlgoResult r = dda_run(20, 0.02L, [](real t) { return 1000 * t; }, 1e6, 1000,
                               [&](uint64_t i, real t) { got.push_back({i, t}); });
  EXPECT_TRUE(r.finished);
  ASSERT_EQ(got.size(), 20u);
  for (size_t k = 0; k < got.size(); ++k) EXPECT_EQ(std::llround(got[k].t * 1e6L), 1000 * static_cast<long>(k + 1));
}

// ---- the tick-level simulation of hexstep against the cycle-exact model ----

using Rises = std::vector<std::pair<uint64_t, uint64_t>>;  // (step, first high cycle after F0)

// run_job on TopModel through the bus, as `hexstep simulate` does: every rising edge of every
// axis, its cycle counted from the time zero of the axis's move (TopModel::move_t0).
std::map<unsigned, Rises> model_rises(const Job& job, bool event_mode) {
  ModelSim sim;
  std::map<unsigned, Rises> out;
  RunOptions o;
  o.event_mode = event_mode;
  const RunResult r = run_job(sim, job, [&](const StepEvent& ev) {
    out[ev.axis].push_back({ev.step, sim.model().cycle() - sim.model().move_t0(ev.axis)});
  }, o);
  EXPECT_FALSE(r.timed_out);
  return out;
}

Rises fast_rises(const AxisMove& m, unsigned axis, const PulseConfig& pc) {
  Rises v;
  tick_sim(m, axis, pc, Widths{}, [&](uint64_t i, uint64_t c) { v.push_back({i, c}); });
  return v;
}

// One job of single moves (one per axis), compared axis by axis, edge by edge.
void expect_same_rises(const Job& job, bool event_mode, const std::string& what) {
  const std::map<unsigned, Rises> ref = model_rises(job, event_mode);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (job.axes[k].moves.empty()) continue;
    ASSERT_EQ(job.axes[k].moves.size(), 1u);
    const Rises fast = fast_rises(job.axes[k].moves[0], k, job.axes[k].pulse);
    const auto it = ref.find(k);
    const Rises model = it == ref.end() ? Rises{} : it->second;
    ASSERT_EQ(fast.size(), model.size()) << what << ", axis " << k;
    EXPECT_EQ(fast.size(), job.axes[k].moves[0].steps) << what << ", axis " << k;
    for (size_t i = 0; i < fast.size(); ++i)
      ASSERT_EQ(fast[i], model[i]) << what << ", axis " << k << ", rise " << i;
  }
}

EncodedMove planned(uint64_t N, real vmax, real a, real d, real vs, real f = 1e8) {
  return plan::encode(make_plan(N, vmax, a, d, vs), f);
}

// Moves the accuracy suite relies on: slow ones (quiet ticks skipped), ones near one step per
// tick on every axis (where the output stage can hold the generator back), a pulse timing
// slower than the steps (it does hold it back), and both directions with DIR timing.
TEST(BenchTickSim, EqualsTopModelOnDirectedMoves) {
  const real vtop = 0.99L * max_speed(1e8);  // just below one step per tick
  {
    Job j;  // six axes at the top speed, one START
    for (unsigned k = 0; k < kNumAxes; ++k)
      j.axes[k].moves.push_back(planned(1500 + 37 * k, vtop, 1.4e8, 1.4e8, vtop / (k + 2)).regs);
    expect_same_rises(j, true, "six axes near one step per tick");
  }
  {
    Job j;
    j.axes[0].moves.push_back(planned(2000, vtop, 1e8, 1e8, vtop).regs);  // constant
    j.axes[3].moves.push_back(planned(300, 2e6, 1e8, 2.5e7, 0).regs);
    j.axes[5].moves.push_back(planned(40, 150, 300, 600, 0).regs);  // slow: mostly quiet ticks
    expect_same_rises(j, true, "constant, fast ramp, slow");
    j.axes[5].moves.clear();  // 0.5 s of motion: too long for cycle mode here
    expect_same_rises(j, false, "constant and fast ramp in cycle mode");
  }
  {
    Job j;  // pulses of 20 + 20 cycles: at most 2.5e6 steps/s, slower than the move's 3e6
    for (unsigned k : {0u, 2u, 4u}) {
      EncodedMove e = planned(700, 3e6, 1e8, 1e8, 2e6);
      e.regs.dir = k != 2;
      j.axes[k].moves.push_back(e.regs);
      j.axes[k].pulse = PulseConfig{20, 20, 7, 5, k == 4, k == 2};
    }
    expect_same_rises(j, true, "output stage slower than the steps, DIR timing, polarity");
  }
}

// The suite's own moves (single and lines), as far as the cycle-exact model runs them quickly.
TEST(BenchTickSim, EqualsTopModelOnSuiteMoves) {
  SuiteOptions o;
  o.seed = 20261124;
  o.random_100 = 60;
  o.random_48 = 30;
  o.random_12 = 30;
  o.lines_100 = 2;
  o.lines_48 = 1;
  o.lines_12 = 1;
  o.directed = false;
  o.max_duration_s = 2;
  const Suite s = make_suite(o);
  unsigned compared = 0;
  std::map<int, Job> lines;
  for (const SuiteMove& m : s.moves) {
    if (m.plan.steps > 4000) continue;
    if (m.kind == "line") {
      lines[m.line].axes[m.axis].moves.push_back(m.enc.regs);
      continue;
    }
    Job j;
    j.axes[0].moves.push_back(m.enc.regs);
    expect_same_rises(j, true, "suite move " + std::to_string(m.id));
    ++compared;
  }
  for (const auto& [id, j] : lines) {
    expect_same_rises(j, true, "suite line " + std::to_string(id));
    ++compared;
  }
  EXPECT_GE(compared, 40u);
}

// The range end of the speeds at 100 MHz: a trapezoid to 0.99 step per tick and back to rest on
// every axis, against the core's own guarantee (the profile its registers describe; docs/
// ARCHITECTURE.md, "Accuracy": every step within 2 cycles + 0.001 step / v_ideal).
TEST(BenchSlice, TopSpeedWithinTheRegisterAllowanceOnEveryAxis) {
  const plan::PhasePlan p = make_plan(200000, 0.99L * max_speed(1e8), 0.99e8, 0.99e8, 0);  // 48,000 steps up
  const EncodedMove e = plan::encode(p, 1e8);
  for (unsigned k = 0; k < kNumAxes; ++k) {
    MetricAcc<IdealProfile> acc(e.ideal, p.steps, e.ideal.duration(), 1e8);
    const uint64_t rises = tick_sim(e.regs, k, PulseConfig{}, Widths{}, [&](uint64_t i, uint64_t c) {
      acc.pulse(i, (static_cast<real>(c) - kStepLatency) / 1e8L);
    });
    const Metrics m = acc.finish();
    EXPECT_EQ(rises, p.steps) << "axis " << k;
    EXPECT_LE(m.max_ratio, 1.0L) << "axis " << k << ": step " << m.worst_step << " is "
                                 << static_cast<double>(m.max_err * 1e8L) << " cycles from its ideal instant";
  }
}

// A seeded slice of the suite (the same generator as `make bench`, fewer moves): hexstep ends on
// exactly N steps on every move and stays within the core's allowance of its register profile;
// every comparison algorithm that applies emits pulses; the ideal instants match the exact
// evaluation on a sample.
TEST(BenchSlice, HexstepExactFinalPosition) {
  SuiteOptions o;
  o.random_100 = 24;
  o.random_48 = 8;
  o.random_12 = 8;
  o.lines_100 = 1;
  o.lines_48 = 1;
  o.lines_12 = 1;
  o.directed = false;
  o.max_duration_s = 60;
  const Suite s = make_suite(o);
  ASSERT_GE(s.moves.size(), 40u);
  std::vector<const SuiteMove*> line;
  int line_id = -1;
  std::vector<MoveResult> res;
  auto flush = [&] {
    if (!line.empty()) {
      for (auto& r : run_line(line)) res.push_back(r);
    }
    line.clear();
  };
  for (const SuiteMove& m : s.moves) {
    if (m.kind == "line") {
      if (m.line != line_id) flush();
      line_id = m.line;
      line.push_back(&m);
    } else {
      flush();
      res.push_back(run_single(m));
    }
    for (uint64_t i : {uint64_t(1), uint64_t(m.plan.steps), uint64_t(m.plan.steps / 2 + 1)})
      EXPECT_LT(ideal_check_ratio(m.plan, i, m.clock_hz), 1e-3L) << "move " << m.id << " step " << i;
  }
  flush();
  ASSERT_EQ(res.size(), s.moves.size());
  for (const MoveResult& r : res) {
    const Metrics& h = r.algo[0];
    EXPECT_TRUE(h.finished) << "move " << r.id;
    EXPECT_EQ(h.final_err(), 0) << "move " << r.id;
    EXPECT_EQ(h.n, h.expected) << "move " << r.id;
    EXPECT_LE(r.algo[1].max_ratio, 1.0L) << "move " << r.id << ": hexstep outside the allowance of its registers";
    // The time-per-step algorithms and the DDA count their steps: exactly N. The Arduino
    // program may stall short of N (its speed crosses zero), never overshoot.
    for (size_t k = 2; k < r.algo.size(); ++k) {
      const Metrics& m = r.algo[k];
      if (!m.included) continue;
      if (algorithm_names()[k] == "spt_10khz") {
        EXPECT_LE(m.pulses, m.expected) << "move " << r.id;
        if (m.pulses < m.expected) {
          EXPECT_FALSE(m.finished) << "move " << r.id;
        }
      } else {
        EXPECT_TRUE(m.finished) << algorithm_names()[k] << " move " << r.id;
        EXPECT_EQ(m.final_err(), 0) << algorithm_names()[k] << " move " << r.id;
      }
    }
  }
}
