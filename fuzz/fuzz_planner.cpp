// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the planner's numeric core (planner/): plan_min_time / plan_timed, then encode.
// Input: text, whitespace-separated fields (a field that is not a number is "not given"):
//   mode steps max_speed accel decel ratio start_speed end_speed time clock_hz
// mode 0 plans minimum time, 1 a time budget; a negative step count is the negative direction.
// Oracles: a refusal is a PlanError whose one-line message starts with the offending flag
// ("--..."); any other exception is a crash. An accepted plan has exactly the requested steps
// (phase counts sum to N, phase distances to N), finite non-negative times and distances,
// speeds within the limits and, timed, the requested duration. Its registers (when encode
// accepts them) pass the core's start checks, and for N <= 2000 the golden model runs them to
// exactly N steps in the requested direction within twice the planned duration.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_check.hpp"
#include "hexstep/job.hpp"
#include "hexstep/planner.hpp"

using namespace hexstep;
using hexstep::fuzz::check;
using hexstep::fuzz::fail;
namespace P = hexstep::plan;

namespace {

std::optional<real> number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const long double v = std::strtold(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return std::nullopt;
  return v;
}

void check_plan_error(const P::PlanError& e, const char* where) {
  const std::string m = e.what();
  fuzz::check_one_line(m, where);
  // "--flag: ..." or, from the six-axis functions, "axis k: --flag: ...".
  check(m.rfind("--", 0) == 0, std::string(where) + ": message does not start with a flag: " + m);
}

bool finite_nonneg(real x) { return std::isfinite(x) && x >= -1e-9L; }

std::string show(const P::PhasePlan& p) {
  std::ostringstream s;
  s << P::profile_name(p.profile) << " N=" << p.steps << " v=" << static_cast<double>(p.v_start) << "/"
    << static_cast<double>(p.v_peak) << "/" << static_cast<double>(p.v_end) << " a=" << static_cast<double>(p.a)
    << " d=" << static_cast<double>(p.d) << " t=" << static_cast<double>(p.t_acc) << "/"
    << static_cast<double>(p.t_cruise) << "/" << static_cast<double>(p.t_dec) << " s="
    << static_cast<double>(p.s_acc) << "/" << static_cast<double>(p.s_cruise) << "/" << static_cast<double>(p.s_dec)
    << " counts=" << p.accel_steps << "/" << p.cruise_steps << "/" << p.decel_steps;
  return s.str();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 512) return 0;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<std::optional<real>> f;
  for (std::string tok; f.size() < 10 && in >> tok;) f.push_back(number(tok));
  f.resize(10);
  const bool timed = f[0] && *f[0] == 1;
  if (!f[1] || !std::isfinite(*f[1]) || std::fabs(*f[1]) >= 1.8e19L) return 0;  // not a step count
  const bool dir = *f[1] >= 0;
  const uint64_t steps = static_cast<uint64_t>(std::fabs(*f[1]));
  P::Limits lim;
  lim.max_speed = f[2].value_or(0);
  lim.accel = f[3].value_or(0);
  lim.decel = f[4];
  lim.ratio = f[5];
  lim.start_speed = f[6].value_or(0);
  lim.end_speed = f[7];
  const real clock = f[9].value_or(1e8L);

  // Ramp rates more than 1e12 apart are refused by the planner (--decel); the input
  // fuzz/corpus/planner/regress_tiny_ramp_ratio once gave a degenerate plan here.
  P::PhasePlan p;
  try {
    p = timed ? P::plan_timed(steps, f[8].value_or(0), lim, dir) : P::plan_min_time(steps, lim, dir);
  } catch (const P::InfeasibleTime& e) {
    check_plan_error(e, "plan_timed");
    check(std::isfinite(e.min_time()) && e.min_time() >= e.requested_time() * (1 - 1e-9L),
          "InfeasibleTime with a minimum time below the request");
    return 0;
  } catch (const P::PlanError& e) {
    check_plan_error(e, timed ? "plan_timed" : "plan_min_time");
    return 0;
  }

  // The plan, against the request.
  const std::string s = show(p);
  const P::RampLimits rl = P::resolve(lim);  // the planner accepted the limits: so must resolve
  check(p.steps == steps && p.dir == dir, "plan for other steps/direction: " + s);
  check(uint64_t(p.accel_steps) + p.cruise_steps + p.decel_steps == steps, "phase step counts do not sum to N: " + s);
  for (real x : {p.t_acc, p.t_cruise, p.t_dec, p.duration, p.s_acc, p.s_cruise, p.s_dec, p.v_start, p.v_peak,
                 p.v_end, p.a, p.d})
    check(finite_nonneg(x), "negative or non-finite plan value: " + s);
  const real n = static_cast<real>(steps);
  check(std::fabs(p.s_acc + p.s_cruise + p.s_dec - n) <= 1e-9L * (1 + n), "phase distances do not sum to N: " + s);
  check(std::fabs(p.t_acc + p.t_cruise + p.t_dec - p.duration) <= 1e-9L * (1 + p.duration),
        "phase times do not sum to the duration: " + s);
  const real vtol = 1 + 1e-12L;
  check(p.v_peak <= rl.v_max * vtol, "peak above --max-speed: " + s);
  check(p.a <= rl.accel * vtol && p.d <= (timed ? rl.accel : rl.decel) * vtol, "ramp above the limits: " + s);
  if (steps != 0) {
    check(p.v_peak * vtol >= p.v_start && p.v_peak * vtol >= p.v_end, "peak below the end speeds: " + s);
    // A timed constant-speed move may start slower than --start-speed (docs/PLANNER.md: the
    // start speed is a maximum jump, and N/T below it is the only way to take that long).
    if (!(timed && p.profile == P::Profile::Constant && p.v_start <= rl.v_start))
      check(std::fabs(p.v_start - rl.v_start) <= 1e-12L * (1 + rl.v_start), "start speed not the requested: " + s);
    check(p.duration > 0, "a move of N > 0 steps in no time: " + s);
  }
  if (timed && steps != 0) {  // an empty move takes no time, whatever the budget
    const real t = *f[8];
    check(std::fabs(p.duration - t) <= 1e-9L * t, "timed plan's duration differs from --time: " + s);
  }

  // Its registers.
  EncodedMove e;
  try {
    e = P::encode(p, clock);
  } catch (const P::PlanError& err) {
    check_plan_error(err, "encode");
    return 0;
  }
  check(e.regs.steps == steps && e.regs.dir == dir, "encoded registers for other steps/direction: " + s);
  check(validate_move(e.regs) == 0,
        "encoded registers refused by the core (MoveError " + std::to_string(validate_move(e.regs)) + "): " + s);

  // Run by the golden model (the pulse stage at 1+1 cycles must keep up, as `hexstep plan`
  // demands; event mode skips the quiet cycles of slow moves).
  try {
    P::check_pulse_rate(p.v_peak, clock, 1, 1);
  } catch (const P::PlanError& err) {
    check_plan_error(err, "check_pulse_rate");
    return 0;
  }
  const real cycles = p.duration * clock;
  if (steps > 2000 || !(cycles < 1e13L)) return 0;
  ModelSim model;
  Job job;
  job.axes[0].moves.push_back(e.regs);
  RunOptions ro;
  ro.event_mode = true;
  ro.max_cycles = static_cast<uint64_t>(2 * cycles) + 100000;
  uint64_t rises = 0;
  const RunResult r = run_job(model, job, [&](const StepEvent& ev) {
    ++rises;
    if (ev.dir != dir) fail("step in the wrong direction: " + s);
  }, ro);
  check(!r.timed_out, "the model did not finish within twice the planned duration: " + s);
  check(r.refused[0] == 0, "the model refused the encoded move: " + s);
  check(r.steps[0] == steps && rises == steps, "the model made " + std::to_string(rises) + " steps: " + s);
  check(r.position[0] == (dir ? 1 : -1) * static_cast<int64_t>(steps), "wrong final position: " + s);
  return 0;
}
