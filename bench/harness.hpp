// SPDX-License-Identifier: Apache-2.0
// hexstep bench: the accuracy suite (seeded moves, six-axis lines), the ideal step instants of
// the planner's real-valued profile, and the per-move error metrics of every algorithm.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "algorithms.hpp"
#include "hexstep/encoding.hpp"
#include "hexstep/planner.hpp"

namespace hexstep::bench {

// One single-axis move of the suite (a six-axis line contributes six, one per moving axis).
struct SuiteMove {
  int id = 0;
  std::string kind;   // "random", "directed", "line"
  std::string range;  // report row, e.g. "100 MHz, v < 1e3"
  int line = -1;      // index of the line (kind "line")
  unsigned axis = 0;  // axis within its line
  real clock_hz = 1e8;
  plan::PhasePlan plan;  // the planner's real-valued profile: the ideal
  EncodedMove enc;       // hexstep's registers and the profile they describe
  // The limits the move was planned with (steps/s^2): the comparison algorithms' ramp rates
  // where the plan has none (a constant-speed plan).
  real accel_limit = 0, decel_limit = 0;
};

struct SuiteOptions {
  uint64_t seed = 20261123;
  unsigned random_100 = 600, random_48 = 300, random_12 = 300;  // random single-axis moves
  unsigned lines_100 = 12, lines_48 = 6, lines_12 = 6;            // six-axis coordinated lines
  bool directed = true;                                           // range-end moves per clock
  real max_duration_s = 600;                                      // longer draws are redrawn
};

struct Suite {
  std::vector<SuiteMove> moves;
  unsigned redrawn_duration = 0;  // draws redrawn because the move would last too long
  unsigned redrawn_range = 0;     // draws redrawn because a value was outside the ranges
};

Suite make_suite(const SuiteOptions& o);

// Ideal instant (s) of step i (1-based) of the planner's profile, long double closed form.
real ideal_time(const plan::PhasePlan& p, uint64_t i);
// The same instant by bisection on the profile's position in __float128 (slow, exact to ~1e-30 s).
__float128 exact_time(const plan::PhasePlan& p, uint64_t i);

// |ideal_time - exact_time| divided by the allowance at that step (2/f + 0.001/v): how much of
// the allowance the long double evaluation could misplace. (At a rest-to-rest end the instant
// is ill-conditioned in absolute terms: dt = sqrt(2 dx/d) for a position rounding dx.)
real ideal_check_ratio(const plan::PhasePlan& p, uint64_t i, real clock_hz);

// Error metrics of one algorithm on one move. Times in seconds, positions in steps.
struct Metrics {
  bool included = true;
  std::string reason;     // why the move was excluded from this algorithm's row
  uint64_t expected = 0;  // N
  uint64_t pulses = 0;
  bool finished = true;
  uint64_t n = 0;             // steps compared (pulses up to N)
  real max_err = 0;           // max |t_i - t_ideal,i|
  real sum_sq = 0;            // sum of squared errors
  uint64_t worst_step = 0;    // step of max_err
  real max_pos_err = 0;       // max |error| * v_ideal
  real max_excess = 0;        // max max(0, |error| - 2/f) * v_ideal
  real max_ratio = 0;         // max |error| / (2/f + 0.001/v_ideal)
  real duration_err = 0;      // t_N - duration (finished moves)
  real max_rel_speed = 0;     // max |ideal interval / real interval - 1|
  int64_t final_err() const { return static_cast<int64_t>(pulses) - static_cast<int64_t>(expected); }
};

// Accumulates Metrics from a stream of pulses against a profile P with time_at(x) and speed(t).
template <typename P>
class MetricAcc {
 public:
  MetricAcc(const P& prof, uint64_t steps, real duration, real clock_hz)
      : p_(prof), dur_(duration), f_(clock_hz) {
    m_.expected = steps;
  }
  void pulse(uint64_t i, real t) {
    ++m_.pulses;
    if (i > m_.expected || i == 0) return;
    const real ti = p_.time_at(static_cast<real>(i));
    const real v = p_.speed(ti);
    const real e = std::fabs(t - ti);
    ++m_.n;
    m_.sum_sq += e * e;
    if (e > m_.max_err) {
      m_.max_err = e;
      m_.worst_step = i;
    }
    if (v > 0) {
      m_.max_pos_err = std::max(m_.max_pos_err, e * v);
      m_.max_excess = std::max(m_.max_excess, std::max<real>(0, e - 2 / f_) * v);
      m_.max_ratio = std::max(m_.max_ratio, e / (2 / f_ + 0.001L / v));
    }
    const real d = t - t_prev_, di = ti - ti_prev_;
    const real rel = d > 0 ? std::fabs(di / d - 1) : std::numeric_limits<real>::infinity();
    m_.max_rel_speed = std::max(m_.max_rel_speed, rel);
    t_prev_ = t;
    ti_prev_ = ti;
    if (i == m_.expected) m_.duration_err = t - dur_;
  }
  Metrics finish(bool finished = true) {
    m_.finished = finished;
    return m_;
  }

 private:
  const P& p_;
  real dur_, f_;
  real t_prev_ = 0, ti_prev_ = 0;
  Metrics m_;
};

// ---- hexstep's step instants ----------------------------------------------------------------
// One axis of the frame engine running one move: the model library's frame runner
// (hexstep/axis_run.hpp: AxisGen once per frame in the axis's slot, its own PulseStage, quiet
// stretches jumped over in closed form), which is TopModel's schedule for one axis without the
// bus and the other axes; bench_check checks it equal to run_job on TopModel.
// on_rise(step, cycle): step i (1-based) has its first STEP-high cycle `cycle` cycles after the
// move's time zero F0 (the first cycle of the frame of its first tick). Returns the number of
// rising edges; stops after max_cycles.
using RiseFn = std::function<void(uint64_t step, uint64_t cycle)>;
uint64_t tick_sim(const AxisMove& m, unsigned axis, const PulseConfig& pc, const Widths& w, const RiseFn& on_rise,
                  uint64_t max_cycles = 1ull << 50);

// Algorithms in report order. "hexstep_regs" is hexstep measured against the profile its
// registers describe (the core issue's reference) rather than the planner's.
const std::vector<std::string>& algorithm_names();

struct MoveResult {
  int id = 0;
  std::vector<Metrics> algo;  // indexed like algorithm_names()
};

// Pulse instants of one algorithm on one move, for the plots.
struct Trace {
  std::string algo;
  std::vector<real> t;  // t[i-1] = instant of step i
};

// Runs every algorithm on a single-axis move (kind random/directed). traces: if non-null,
// receives each algorithm's pulse instants.
MoveResult run_single(const SuiteMove& m, std::vector<Trace>* traces = nullptr);
// Runs a six-axis line (the moves of one line, any order) on hexstep as one job, and every
// comparison algorithm per axis.
std::vector<MoveResult> run_line(const std::vector<const SuiteMove*>& axes);

// Comparison algorithm `name` on the move's profile; returns false (with reason) if excluded.
bool comparison_applies(const std::string& name, const plan::PhasePlan& p, std::string& reason);

}  // namespace hexstep::bench
