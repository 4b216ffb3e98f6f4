// SPDX-License-Identifier: Apache-2.0
// Six axes: independent plans, and coordinated straight lines (same duration, positions
// proportional at every instant, each axis within its own limits, the slowest sets the pace).
#include <string>

#include "common.hpp"

using namespace hexstep::plan;
using namespace hexstep::plan::test;
using hexstep::real;

namespace {
Limits lim(real vmax, real a, real d = 0, real v0 = 0, real ve = -1) {
  Limits l;
  l.max_speed = vmax;
  l.accel = a;
  if (d > 0) l.decel = d;
  l.start_speed = v0;
  if (ve >= 0) l.end_speed = ve;
  return l;
}

template <class F>
void expect_error_prefix(F f, const std::string& prefix) {
  try {
    f();
    ADD_FAILURE() << "no PlanError, expected " << prefix;
  } catch (const PlanError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
  }
}

// Checks a line: same phase times, proportional positions, per-axis limits.
void check_line(const std::vector<AxisRequest>& req, const LinePlan& line) {
  ASSERT_EQ(line.axes.size(), req.size());
  uint64_t L = 0;
  for (const AxisRequest& r : req) L = std::max<uint64_t>(L, std::llabs(r.steps));
  EXPECT_EQ(line.path.steps, L);
  for (size_t i = 0; i < req.size(); ++i) {
    const AxisPlan& ap = line.axes[i];
    const PhasePlan& q = ap.plan;
    SCOPED_TRACE("axis " + std::to_string(req[i].axis));
    EXPECT_EQ(ap.axis, req[i].axis);
    const uint64_t n = std::llabs(req[i].steps);
    EXPECT_EQ(q.steps, n);
    if (n == 0) {
      EXPECT_EQ(q.profile, Profile::Empty);
      EXPECT_EQ(q.duration, 0);
      continue;
    }
    EXPECT_EQ(q.dir, req[i].steps > 0);
    // All start together and arrive together: the same phase times.
    EXPECT_REL(q.t_acc, line.path.t_acc, 1e-15);
    EXPECT_REL(q.t_cruise, line.path.t_cruise, 1e-15);
    EXPECT_REL(q.t_dec, line.path.t_dec, 1e-15);
    EXPECT_REL(q.duration, line.path.duration, 1e-15);
    EXPECT_EQ(uint64_t(q.accel_steps) + q.cruise_steps + q.decel_steps, n);
    EXPECT_REL(q.s_acc + q.s_cruise + q.s_dec, n, 1e-12);
    // Proportional positions: x_i(t)/N_i == x_path(t)/L at sampled instants.
    for (int k = 0; k <= 16; ++k) {
      const real t = line.path.duration * k / 16;
      EXPECT_NEAR(static_cast<double>(q.position(t) / n), static_cast<double>(line.path.position(t) / L), 1e-9)
          << "t=" << static_cast<double>(t);
    }
    // Within this axis's own limits.
    const RampLimits rl = resolve(req[i].limits);
    EXPECT_LE(q.v_peak, rl.v_max);
    EXPECT_LE(q.a, rl.accel);
    EXPECT_LE(q.d, rl.decel);
    EXPECT_LE(q.v_start, rl.v_start);
    if (q.warning.empty()) {
      EXPECT_LE(q.v_end, rl.v_end);
    }
    EXPECT_PRED4(rel_near, q.v_start + q.a * q.t_acc, q.v_peak, real(1e-9), rl.v_max);
    EXPECT_PRED4(rel_near, q.v_peak - q.d * q.t_dec, q.v_end, real(1e-9), rl.v_max);
  }
}
}  // namespace

TEST(Axes, IndependentPlansEachAxisAlone) {
  const std::vector<AxisRequest> req = {
      {0, 1000, lim(1000, 5000)}, {3, -20000, lim(4000, 1e4, 2e4, 100)}, {5, 0, lim(10, 10)}};
  const std::vector<AxisPlan> out = independent(req);
  ASSERT_EQ(out.size(), 3u);
  for (size_t i = 0; i < req.size(); ++i) {
    const PhasePlan alone = plan_min_time(std::llabs(req[i].steps), req[i].limits, req[i].steps >= 0);
    EXPECT_EQ(out[i].axis, req[i].axis);
    EXPECT_EQ(out[i].plan.duration, alone.duration);
    EXPECT_EQ(out[i].plan.v_peak, alone.v_peak);
    EXPECT_EQ(out[i].plan.dir, alone.dir);
  }
  EXPECT_FALSE(out[1].plan.dir);
  EXPECT_EQ(out[2].plan.profile, Profile::Empty);
}

TEST(Axes, BadRequestsAreNamed) {
  expect_error_prefix([] { independent({{6, 10, lim(1, 1)}}); }, "--axis:");
  expect_error_prefix([] { coordinated_line({{1, 10, lim(1, 1)}, {1, 5, lim(1, 1)}}); }, "--axis:");
  expect_error_prefix([] { independent({{0, 10, lim(1, 1)}, {2, 10, lim(1, -1)}}); }, "axis 2: --accel:");
  expect_error_prefix([] { coordinated_line({{4, 10, lim(100, 1, 0, 200)}}); }, "axis 4: --start-speed:");
  expect_error_prefix([] { coordinated_line({{0, int64_t(1) << 33, lim(1, 1)}}); }, "axis 0: --steps:");
}

TEST(Axes, LineScalesThePathOfTheLongestAxis) {
  const std::vector<AxisRequest> req = {{0, 1000, lim(1000, 1000)}, {1, -500, lim(1000, 1000)}, {2, 0, lim(1000, 1000)}};
  const LinePlan line = coordinated_line(req);
  check_line(req, line);
  // The longest axis's own limits bind: its plan is its minimum-time plan.
  const PhasePlan alone = plan_min_time(1000, lim(1000, 1000));
  EXPECT_REL(line.path.duration, alone.duration, 1e-15);
  EXPECT_REL(line.axes[0].plan.v_peak, alone.v_peak, 1e-15);
  EXPECT_REL(line.axes[1].plan.v_peak, alone.v_peak / 2, 1e-15);
  EXPECT_REL(line.axes[1].plan.a, 500, 1e-15);
  EXPECT_FALSE(line.axes[1].plan.dir);
  EXPECT_EQ(line.axes[2].plan.profile, Profile::Empty);
}

TEST(Axes, SlowestAxisSetsThePace) {
  // Axis 1 moves half as far but may go only 100 steps/s: the path may go 200.
  const std::vector<AxisRequest> req = {{0, 4000, lim(1000, 1000)}, {1, 2000, lim(100, 1000)}};
  const LinePlan line = coordinated_line(req);
  check_line(req, line);
  EXPECT_REL(line.path.v_peak, 200, 1e-15);
  EXPECT_REL(line.axes[1].plan.v_peak, 100, 1e-15);
  EXPECT_REL(line.axes[0].plan.v_peak, 200, 1e-15);
  EXPECT_REL(line.path.duration, plan_min_time(4000, lim(200, 1000)).duration, 1e-15);
  EXPECT_GE(line.path.duration, plan_min_time(2000, lim(100, 1000)).duration);
}

TEST(Axes, EmptyLine) {
  const LinePlan line = coordinated_line({{0, 0, lim(1, 1)}, {5, 0, lim(1, 1)}});
  EXPECT_EQ(line.path.profile, Profile::Empty);
  ASSERT_EQ(line.axes.size(), 2u);
  EXPECT_EQ(line.axes[1].axis, 5u);
  EXPECT_EQ(line.axes[1].plan.profile, Profile::Empty);
}

TEST(Axes, RandomLinesStayProportionalAndWithinLimits) {
  std::mt19937_64 rng(seed_for("Axes.RandomLinesStayProportionalAndWithinLimits"));
  for (int i = 0; i < 3000; ++i) {
    std::vector<unsigned> axes = {0, 1, 2, 3, 4, 5};
    std::shuffle(axes.begin(), axes.end(), rng);
    const unsigned count = 1 + rng() % 6;
    std::vector<AxisRequest> req;
    for (unsigned k = 0; k < count; ++k) {
      AxisRequest r;
      r.axis = axes[k];
      r.steps = rng() % 7 == 0 ? 0 : static_cast<int64_t>(log_uniform(rng, 1, 1e7)) * (rng() & 1 ? 1 : -1);
      const real vmax = log_uniform(rng, 1, 5e6);
      const real v0 = rng() % 3 == 0 ? 0 : uniform(rng, 0, vmax);
      const real ve = rng() % 3 == 0 ? 0 : uniform(rng, 0, vmax);
      r.limits = lim(vmax, log_uniform(rng, 10, 1e8), log_uniform(rng, 10, 1e8), v0, ve);
      req.push_back(r);
    }
    const LinePlan line = coordinated_line(req);
    SCOPED_TRACE("line " + std::to_string(i));
    check_line(req, line);
    // Minimum time for the line: the path's duration is the minimum for the path limits,
    // computed here independently, and no axis could finish sooner even alone.
    uint64_t L = 0;
    for (const AxisRequest& r : req) L = std::max<uint64_t>(L, std::llabs(r.steps));
    if (L == 0) continue;
    real v0 = 1e300, ve = 1e300, vm = 1e300, a = 1e300, d = 1e300;
    real slowest_alone = 0;
    for (const AxisRequest& r : req) {
      if (r.steps == 0) continue;
      const real k = static_cast<real>(L) / std::llabs(r.steps);
      const RampLimits rl = resolve(r.limits);
      v0 = std::min(v0, rl.v_start * k);
      ve = std::min(ve, rl.v_end * k);
      vm = std::min(vm, rl.v_max * k);
      a = std::min(a, rl.accel * k);
      d = std::min(d, rl.decel * k);
      const PhasePlan alone = plan_min_time(std::llabs(r.steps), r.limits);
      if (alone.warning.empty()) slowest_alone = std::max(slowest_alone, alone.duration);
    }
    EXPECT_REL(line.path.duration, min_time_bisect(static_cast<real>(L), v0, ve, vm, a, d), 1e-9);
    if (line.path.warning.empty()) {
      EXPECT_GE(line.path.duration, slowest_alone * (1 - 1e-9));
    }
    if (::testing::Test::HasFailure()) break;
  }
}
