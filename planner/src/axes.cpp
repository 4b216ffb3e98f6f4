// SPDX-License-Identifier: Apache-2.0
// hexstep planner: six axes, each alone or along one straight line (docs/PLANNER.md, "Lines").
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "detail.hpp"

namespace hexstep::plan {

using detail::fail;
using detail::num;

namespace {

uint64_t magnitude(int64_t s) {
  return s < 0 ? static_cast<uint64_t>(-(s + 1)) + 1 : static_cast<uint64_t>(s);
}

[[noreturn]] void rethrow_for_axis(unsigned axis, const PlanError& e) {
  throw PlanError("axis " + std::to_string(axis) + ": " + e.what());
}

// Checks the axis indices and every request's steps and limits; returns the resolved limits.
std::vector<RampLimits> check(const std::vector<AxisRequest>& req) {
  if (req.size() > kNumAxes)
    fail("--axis", "at most " + std::to_string(kNumAxes) + " axes (got " + std::to_string(req.size()) + ")");
  std::vector<RampLimits> out;
  uint32_t seen = 0;
  for (const AxisRequest& r : req) {
    if (r.axis >= kNumAxes)
      fail("--axis", "must be in [0, " + std::to_string(kNumAxes - 1) + "] (got " + std::to_string(r.axis) + ")");
    if ((seen >> r.axis) & 1u) fail("--axis", "axis " + std::to_string(r.axis) + " is given twice");
    seen |= 1u << r.axis;
    try {
      detail::require_steps(magnitude(r.steps));
      out.push_back(resolve(r.limits));
    } catch (const InfeasibleTime&) {
      throw;
    } catch (const PlanError& e) {
      rethrow_for_axis(r.axis, e);
    }
  }
  return out;
}

PhasePlan empty_plan() {
  PhasePlan p;
  p.profile = Profile::Empty;
  return p;
}

}  // namespace

std::vector<AxisPlan> independent(const std::vector<AxisRequest>& req) {
  const std::vector<RampLimits> lim = check(req);
  std::vector<AxisPlan> out;
  for (size_t i = 0; i < req.size(); ++i) {
    try {
      out.push_back(AxisPlan{req[i].axis, plan_min_time(magnitude(req[i].steps), lim[i], req[i].steps >= 0)});
    } catch (const PlanError& e) {
      rethrow_for_axis(req[i].axis, e);
    }
  }
  return out;
}

LinePlan coordinated_line(const std::vector<AxisRequest>& req) {
  const std::vector<RampLimits> lim = check(req);
  LinePlan line;
  uint64_t L = 0;
  for (const AxisRequest& r : req) L = std::max(L, magnitude(r.steps));
  if (L == 0) {
    line.path = empty_plan();
    for (const AxisRequest& r : req) line.axes.push_back(AxisPlan{r.axis, empty_plan()});
    return line;
  }
  // Path limits: axis i moves r_i = |N_i|/L of the path, so its speed is r_i times the path
  // speed: the path may go at most limit_i / r_i for every axis i.
  RampLimits path;
  bool first = true;
  for (size_t i = 0; i < req.size(); ++i) {
    const uint64_t n = magnitude(req[i].steps);
    if (n == 0) continue;
    const real k = static_cast<real>(L) / static_cast<real>(n);  // 1 / r_i
    const RampLimits& l = lim[i];
    const RampLimits s{l.v_start * k, l.v_end * k, l.v_max * k, l.accel * k, l.decel * k};
    if (first) {
      path = s;
      first = false;
    } else {
      path.v_start = std::min(path.v_start, s.v_start);
      path.v_end = std::min(path.v_end, s.v_end);
      path.v_max = std::min(path.v_max, s.v_max);
      path.accel = std::min(path.accel, s.accel);
      path.decel = std::min(path.decel, s.decel);
    }
  }
  line.path = plan_min_time(L, path, true);
  const PhasePlan& P = line.path;
  for (size_t i = 0; i < req.size(); ++i) {
    const uint64_t n = magnitude(req[i].steps);
    if (n == 0) {
      line.axes.push_back(AxisPlan{req[i].axis, empty_plan()});
      continue;
    }
    const real r = static_cast<real>(n) / static_cast<real>(L);
    const RampLimits& l = lim[i];
    PhasePlan q = P;
    q.steps = static_cast<uint32_t>(n);
    q.dir = req[i].steps >= 0;
    // Scaled by r; clamped to the axis's own limits, which the scaled values can exceed only by
    // rounding (the path limits are min over axes of limit_i / r_i).
    real vs = std::min(P.v_start * r, l.v_start);
    real vp = std::min(P.v_peak * r, l.v_max);
    real ve = std::min(P.v_end * r, P.warning.empty() ? l.v_end : l.v_max);
    // Speeds equal on the path stay equal (no ramp appears from a clamp).
    if (P.v_start == P.v_peak) vp = vs = std::min(vs, vp);
    if (P.v_end == P.v_peak) vp = ve = std::min(ve, vp);
    if (P.v_start == P.v_peak) vs = vp;
    q.v_peak = vp;
    q.v_start = std::min(vs, vp);
    q.v_end = std::min(ve, vp);
    q.a = std::min(P.a * r, l.accel);
    q.d = std::min(P.d * r, l.decel);
    q.end_speed_requested = l.v_end;
    q.end_speed_reached = q.v_end;
    q.s_acc = P.s_acc * r;
    q.s_cruise = P.s_cruise * r;
    q.s_dec = std::max<real>(static_cast<real>(n) - q.s_acc - q.s_cruise, 0);
    if (P.profile == Profile::AccelOnly) {
      q.s_acc = static_cast<real>(n);
      q.s_cruise = q.s_dec = 0;
    }
    q.warning.clear();
    if (!P.warning.empty())
      q.warning = "axis " + std::to_string(req[i].axis) +
                  ": the line is too short to reach its end speed; this axis ends at " + num(q.v_end) +
                  " steps/s (path: " + P.warning + ")";
    detail::fill_counts(q);
    line.axes.push_back(AxisPlan{req[i].axis, q});
  }
  return line;
}

}  // namespace hexstep::plan
