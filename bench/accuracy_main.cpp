// SPDX-License-Identifier: Apache-2.0
// hexstep bench: the accuracy suite. Runs every move on hexstep's golden model (event mode) and
// on each comparison algorithm, and writes per-move metrics (accuracy.json) and the pulse
// instants of the three plotted moves (traces.json). bench/report.py turns them into tables.
//
//   bench_accuracy --out DIR [--threads N] [--seed S] [--scale K]
//
// --scale K divides the number of random moves and lines by K (a quick look; `make bench`
// uses the full suite).
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "harness.hpp"

using namespace hexstep;
using namespace hexstep::bench;
using json = nlohmann::json;

namespace {

[[noreturn]] void usage(const std::string& msg) {
  std::fprintf(stderr, "bench_accuracy: %s\nusage: bench_accuracy --out DIR [--threads 1..64] [--seed N] [--scale 1..1000]\n",
               msg.c_str());
  std::exit(2);
}

unsigned long parse_num(const std::string& flag, const char* v, unsigned long lo, unsigned long hi) {
  char* end = nullptr;
  const unsigned long x = std::strtoul(v, &end, 10);
  if (!*v || *end || x < lo || x > hi)
    usage(flag + ": must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got '" + v + "')");
  return x;
}

json metrics_json(const Metrics& m) {
  json j;
  j["included"] = m.included;
  if (!m.included) {
    j["reason"] = m.reason;
    return j;
  }
  j["pulses"] = m.pulses;
  j["finished"] = m.finished;
  j["n"] = m.n;
  j["max_err_s"] = static_cast<double>(m.max_err);
  j["sum_sq_s2"] = static_cast<double>(m.sum_sq);
  j["worst_step"] = m.worst_step;
  j["max_pos_err"] = static_cast<double>(m.max_pos_err);
  j["max_excess"] = static_cast<double>(m.max_excess);
  j["max_ratio"] = static_cast<double>(m.max_ratio);
  j["duration_err_s"] = static_cast<double>(m.duration_err);
  j["max_rel_speed"] = std::isfinite(static_cast<double>(m.max_rel_speed)) ? json(static_cast<double>(m.max_rel_speed))
                                                                            : json("inf");
  j["final_err"] = m.final_err();
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out;
  unsigned threads = 2, scale = 1;
  SuiteOptions so;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) usage(a + ": needs a value");
    if (a == "--out") out = argv[++i];
    else if (a == "--threads") threads = static_cast<unsigned>(parse_num(a, argv[++i], 1, 64));
    else if (a == "--seed") so.seed = parse_num(a, argv[++i], 0, ~0ul);
    else if (a == "--scale") scale = static_cast<unsigned>(parse_num(a, argv[++i], 1, 1000));
    else usage("unknown option " + a);
  }
  if (out.empty()) usage("--out: required");
  so.random_100 /= scale;
  so.random_48 /= scale;
  so.random_12 /= scale;
  so.lines_100 = std::max(1u, so.lines_100 / scale);
  so.lines_48 = std::max(1u, so.lines_48 / scale);
  so.lines_12 = std::max(1u, so.lines_12 / scale);

  const auto t0 = std::chrono::steady_clock::now();
  const Suite suite = make_suite(so);
  // Work units: a single move, or all axes of one line.
  std::vector<std::vector<const SuiteMove*>> units;
  std::map<int, size_t> line_unit;
  for (const SuiteMove& m : suite.moves) {
    if (m.kind == "line") {
      auto it = line_unit.find(m.line);
      if (it == line_unit.end()) {
        line_unit[m.line] = units.size();
        units.push_back({&m});
      } else {
        units[it->second].push_back(&m);
      }
    } else {
      units.push_back({&m});
    }
  }
  // The three plotted moves: the last three directed moves at 100 MHz.
  std::vector<int> plot_ids;
  for (const SuiteMove& m : suite.moves)
    if (m.kind == "directed" && m.clock_hz == 1e8) plot_ids.push_back(m.id);
  if (plot_ids.size() > 3) plot_ids.erase(plot_ids.begin(), plot_ids.end() - 3);

  std::vector<MoveResult> results(suite.moves.size());
  std::map<int, std::vector<Trace>> traces;
  std::mutex mu;
  std::atomic<size_t> next{0};
  // Ideal instants against the exact (__float128 bisection) evaluation on a sample of steps.
  long double ideal_check_max = 0, ideal_check_moving = 0, ideal_ratio_max = 0;
  uint64_t ideal_check_n = 0;
  auto worker = [&] {
    std::mt19937_64 rng(so.seed ^ 0x5eed);
    long double local_max = 0, local_moving = 0, local_ratio = 0;
    uint64_t local_n = 0;
    for (;;) {
      const size_t u = next.fetch_add(1);
      if (u >= units.size()) break;
      const auto& unit = units[u];
      std::vector<MoveResult> r;
      std::vector<Trace> tr;
      const bool plot = unit.size() == 1 && unit[0]->kind != "line" &&
                        std::find(plot_ids.begin(), plot_ids.end(), unit[0]->id) != plot_ids.end();
      if (unit[0]->kind == "line") r = run_line(unit);
      else r.push_back(run_single(*unit[0], plot ? &tr : nullptr));
      for (const SuiteMove* m : unit) {
        const plan::PhasePlan& p = m->plan;
        std::vector<uint64_t> sample = {1, 2, p.steps / 2, p.steps - 1, p.steps};
        sample.push_back(static_cast<uint64_t>(std::floor(p.s_acc)) + 1);
        sample.push_back(static_cast<uint64_t>(std::floor(p.s_acc + p.s_cruise)) + 1);
        for (int k = 0; k < 5; ++k) sample.push_back(1 + rng() % p.steps);
        for (uint64_t i : sample) {
          if (i < 1 || i > p.steps) continue;
          const __float128 e = exact_time(p, i);
          const long double d =
              std::fabs(static_cast<long double>((static_cast<__float128>(ideal_time(p, i)) - e) * m->clock_hz));
          local_max = std::max(local_max, d);
          if (p.speed(ideal_time(p, i)) > 1e-3L * p.v_peak) local_moving = std::max(local_moving, d);
          local_ratio = std::max(local_ratio, ideal_check_ratio(p, i, m->clock_hz));
          ++local_n;
        }
      }
      std::lock_guard<std::mutex> g(mu);
      for (size_t k = 0; k < unit.size(); ++k) results[static_cast<size_t>(unit[k]->id)] = r[k];
      if (plot) traces[unit[0]->id] = tr;
    }
    std::lock_guard<std::mutex> g(mu);
    ideal_check_max = std::max(ideal_check_max, local_max);
    ideal_check_moving = std::max(ideal_check_moving, local_moving);
    ideal_ratio_max = std::max(ideal_ratio_max, local_ratio);
    ideal_check_n += local_n;
  };
  std::vector<std::thread> pool;
  for (unsigned k = 0; k < threads; ++k) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  json j;
  j["seed"] = so.seed;
  j["scale"] = scale;
  j["threads"] = threads;
  j["seconds"] = secs;
  j["algorithms"] = algorithm_names();
  j["options"] = {{"random_100", so.random_100}, {"random_48", so.random_48}, {"random_12", so.random_12},
                  {"lines_100", so.lines_100},   {"lines_48", so.lines_48},   {"lines_12", so.lines_12},
                  {"max_duration_s", static_cast<double>(so.max_duration_s)}};
  j["redrawn_duration"] = suite.redrawn_duration;
  j["redrawn_range"] = suite.redrawn_range;
  j["ideal_check"] = {{"samples", ideal_check_n},
                      {"max_abs_diff_cycles", static_cast<double>(ideal_check_max)},
                      {"max_abs_diff_cycles_above_0.1pct_peak", static_cast<double>(ideal_check_moving)},
                      {"max_diff_over_allowance", static_cast<double>(ideal_ratio_max)}};
  json moves = json::array();
  for (const SuiteMove& m : suite.moves) {
    const plan::PhasePlan& p = m.plan;
    json jm;
    jm["id"] = m.id;
    jm["kind"] = m.kind;
    jm["range"] = m.range;
    jm["line"] = m.line;
    jm["clock_hz"] = static_cast<double>(m.clock_hz);
    jm["steps"] = p.steps;
    jm["profile"] = plan::profile_name(p.profile);
    jm["v_start"] = static_cast<double>(p.v_start);
    jm["v_peak"] = static_cast<double>(p.v_peak);
    jm["v_end"] = static_cast<double>(p.v_end);
    jm["accel"] = static_cast<double>(p.a);
    jm["decel"] = static_cast<double>(p.d);
    jm["duration_s"] = static_cast<double>(p.duration);
    json ja;
    const MoveResult& r = results[static_cast<size_t>(m.id)];
    for (size_t k = 0; k < algorithm_names().size(); ++k) ja[algorithm_names()[k]] = metrics_json(r.algo[k]);
    jm["algo"] = ja;
    moves.push_back(jm);
  }
  j["moves"] = moves;
  {
    std::ofstream f(out + "/accuracy.json");
    f << j.dump() << "\n";
    if (!f) usage("--out: cannot write " + out + "/accuracy.json");
  }
  json jt = json::array();
  for (int id : plot_ids) {
    const SuiteMove& m = suite.moves[static_cast<size_t>(id)];
    const plan::PhasePlan& p = m.plan;
    json e;
    e["id"] = id;
    e["steps"] = p.steps;
    e["v_start"] = static_cast<double>(p.v_start);
    e["v_peak"] = static_cast<double>(p.v_peak);
    e["accel"] = static_cast<double>(p.a);
    e["decel"] = static_cast<double>(p.d);
    e["duration_s"] = static_cast<double>(p.duration);
    std::vector<double> ti, tv, vv;
    for (uint32_t i = 1; i <= p.steps; ++i) ti.push_back(static_cast<double>(ideal_time(p, i)));
    for (int k = 0; k <= 400; ++k) {
      const real t = p.duration * k / 400;
      tv.push_back(static_cast<double>(t));
      vv.push_back(static_cast<double>(p.speed(t)));
    }
    e["ideal_t"] = ti;
    e["ideal_curve_t"] = tv;
    e["ideal_curve_v"] = vv;
    for (const Trace& tr : traces[id]) {
      std::vector<double> t;
      for (real x : tr.t) t.push_back(static_cast<double>(x));
      e["algo"][tr.algo] = t;
    }
    jt.push_back(e);
  }
  {
    std::ofstream f(out + "/traces.json");
    f << jt.dump() << "\n";
  }
  std::printf("bench_accuracy: %zu moves in %.1f s (%u threads); ideal check: %llu samples, max |long double - exact| = %.3g cycles\n",
              suite.moves.size(), secs, threads, static_cast<unsigned long long>(ideal_check_n),
              static_cast<double>(ideal_check_max));
  return 0;
}
