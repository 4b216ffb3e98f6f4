// SPDX-License-Identifier: Apache-2.0
// hexstep bench: throughput with Google Benchmark. Golden model in cycle and event mode, the
// Verilated core (six axes moving) with and without the lock-step model comparison, and the
// planner. `make bench` runs it with repetitions and takes the medians (bench/report.py).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "hexstep/bus.hpp"
#include "hexstep/job.hpp"
#include "hexstep/planner.hpp"
#include "hexstep/top_sim.hpp"
#include "rtl_top.hpp"

using namespace hexstep;

namespace {

EncodedMove plan_move(uint64_t n, real vmax, real a, real vs = 0) {
  plan::Limits lim;
  lim.max_speed = vmax;
  lim.accel = a;
  lim.start_speed = vs;
  return plan::encode(plan::plan_min_time(n, lim, true), 1e8);
}

// Six axes, slow moves (peaks 300..800 steps/s, below 1,000 steps/s) at 100 MHz.
Job slow_six_axis_job(uint64_t steps) {
  Job j;
  for (unsigned i = 0; i < kNumAxes; ++i)
    j.axes[i].moves.push_back(plan_move(steps + 7 * i, 300 + 100 * i, 2000 + 500 * i).regs);
  return j;
}

// Six axes moving fast (1e5..6e5 steps/s) for the co-simulation: many steps per cycle budget.
std::vector<AxisMove> fast_six_axis_moves() {
  std::vector<AxisMove> v;
  for (unsigned i = 0; i < kNumAxes; ++i) v.push_back(plan_move(4000000, 1e5 * (i + 1), 1e9 / 16).regs);
  return v;
}

// Reset, one move per axis pushed through the bus, one START: the block is then running.
void start_fast_six_axis(Bus& bus, const std::vector<AxisMove>& moves) {
  bus.reset();
  for (unsigned i = 0; i < kNumAxes; ++i) push_move(bus, i, moves[i]);
  bus.write(regs::START, (1u << kNumAxes) - 1);
}

bool all_busy(Bus& bus) {
  for (unsigned i = 0; i < kNumAxes; ++i)
    if (!(bus.read(ax_reg(i, regs::axis::STATUS)) & regs::axis::STATUS_BUSY_MASK)) return false;
  return true;
}

void BM_ModelCycleMode(benchmark::State& st) {
  const Job j = slow_six_axis_job(30);
  uint64_t cycles = 0, steps = 0;
  for (auto _ : st) {
    ModelSim m;
    RunOptions o;
    o.event_mode = false;
    uint64_t n = 0;
    const RunResult r = run_job(m, j, [&](const StepEvent&) { ++n; }, o);
    cycles += r.cycles;
    steps += n;
  }
  st.counters["axis_cycles_per_s"] = benchmark::Counter(static_cast<double>(cycles * kNumAxes), benchmark::Counter::kIsRate);
  st.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

void BM_ModelEventMode(benchmark::State& st) {
  const Job j = slow_six_axis_job(30);  // the same job as BM_ModelCycleMode
  uint64_t steps = 0;
  for (auto _ : st) {
    ModelSim m;
    RunOptions o;
    o.event_mode = true;
    uint64_t n = 0;
    run_job(m, j, [&](const StepEvent&) { ++n; }, o);
    steps += n;
  }
  st.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

// One long slow move (20,000 steps at up to 900 steps/s), event mode.
void BM_ModelEventModeLongSlow(benchmark::State& st) {
  Job j;
  j.axes[0].moves.push_back(plan_move(20000, 900, 3000).regs);
  uint64_t steps = 0;
  for (auto _ : st) {
    ModelSim m;
    RunOptions o;
    o.event_mode = true;
    uint64_t n = 0;
    run_job(m, j, [&](const StepEvent&) { ++n; }, o);
    steps += n;
  }
  st.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

constexpr uint64_t kCosimCycles = 1000000;

// The cycles counted are those with the six axes moving (after the setup through the bus).
void BM_CosimRtl(benchmark::State& st) {
  RtlTop rtl;
  const std::vector<AxisMove> moves = fast_six_axis_moves();
  uint64_t cycles = 0;
  for (auto _ : st) {
    st.PauseTiming();
    Bus bus(rtl);
    start_fast_six_axis(bus, moves);
    st.ResumeTiming();
    bus.idle(kCosimCycles);
    st.PauseTiming();
    if (!all_busy(bus)) st.SkipWithError("an axis stopped moving before the end of the run");
    st.ResumeTiming();
    cycles += kCosimCycles;
  }
  st.counters["cycles_per_s"] = benchmark::Counter(static_cast<double>(cycles), benchmark::Counter::kIsRate);
}

void BM_CosimRtlWithModel(benchmark::State& st) {
  RtlTop rtl;
  ModelSim model;
  Lockstep pair(model, rtl);
  const std::vector<AxisMove> moves = fast_six_axis_moves();
  uint64_t cycles = 0;
  for (auto _ : st) {
    st.PauseTiming();
    Bus bus(pair);
    start_fast_six_axis(bus, moves);
    st.ResumeTiming();
    bus.idle(kCosimCycles);
    st.PauseTiming();
    if (pair.mismatches() != 0) st.SkipWithError(("RTL and model differ: " + pair.report()).c_str());
    else if (!all_busy(bus)) st.SkipWithError("an axis stopped moving before the end of the run");
    st.ResumeTiming();
    cycles += kCosimCycles;
  }
  st.counters["cycles_per_s"] = benchmark::Counter(static_cast<double>(cycles), benchmark::Counter::kIsRate);
}

struct PlanCase {
  uint64_t n;
  plan::Limits lim;
};

std::vector<PlanCase> plan_cases() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  auto logu = [&](double lo, double hi) { return std::exp(std::log(lo) + u(rng) * (std::log(hi) - std::log(lo))); };
  std::vector<PlanCase> v;
  for (int k = 0; k < 256; ++k) {
    PlanCase c;
    c.n = static_cast<uint64_t>(logu(1, 1e6));
    c.lim.max_speed = logu(10, 3e6);  // below one step per tick at 100 MHz (3.125e6 steps/s)
    c.lim.accel = logu(100, 3.7e7);  // decel up to 4x: within ACC_W 48 at 100 MHz (1.49e8)
    c.lim.decel = c.lim.accel / logu(0.25, 4);
    v.push_back(c);
  }
  return v;
}

// plan_min_time + encode (registers) of one single-axis move.
void BM_PlanSingle(benchmark::State& st) {
  const auto cases = plan_cases();
  size_t k = 0;
  for (auto _ : st) {
    const PlanCase& c = cases[k++ % cases.size()];
    const plan::PhasePlan p = plan::plan_min_time(c.n, c.lim, true);
    EncodedMove e = plan::encode(p, 1e8);
    benchmark::DoNotOptimize(e);
  }
  st.counters["plans_per_s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}

// coordinated_line over six axes + encode of every axis.
void BM_PlanSixAxisLine(benchmark::State& st) {
  const auto cases = plan_cases();
  std::vector<std::vector<plan::AxisRequest>> lines;
  for (size_t l = 0; l + kNumAxes <= cases.size(); l += kNumAxes) {
    std::vector<plan::AxisRequest> r;
    for (unsigned i = 0; i < kNumAxes; ++i) {
      plan::AxisRequest a;
      a.axis = i;
      a.steps = static_cast<int64_t>(cases[l + i].n) * ((i & 1) ? -1 : 1);
      a.limits = cases[l + i].lim;
      r.push_back(a);
    }
    lines.push_back(r);
  }
  size_t k = 0;
  for (auto _ : st) {
    const plan::LinePlan lp = plan::coordinated_line(lines[k++ % lines.size()]);
    for (const plan::AxisPlan& a : lp.axes) {
      if (a.plan.steps == 0) continue;
      EncodedMove e = plan::encode(a.plan, 1e8);
      benchmark::DoNotOptimize(e);
    }
  }
  st.counters["plans_per_s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_ModelCycleMode)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ModelEventMode)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ModelEventModeLongSlow)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CosimRtl)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CosimRtlWithModel)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_PlanSingle);
BENCHMARK(BM_PlanSixAxisLine);

BENCHMARK_MAIN();
