// SPDX-License-Identifier: Apache-2.0
// Time-constrained plans (Ranade 2009): the expected values come from Ranade's formulas
// (required_max_speed, required_acceleration) and from the area of the speed profile.
#include <string>

#include "common.hpp"

using namespace hexstep::plan;
using namespace hexstep::plan::test;
using hexstep::real;

namespace {
// Ranade's example motor: start speed 1000 steps/s, speed limit 5000 steps/s, acceleration
// limit 25000 steps/s^2.
Limits ranade_limits(real start = 1000) {
  Limits l;
  l.start_speed = start;
  l.max_speed = 5000;
  l.accel = 25000;
  return l;
}

void expect_timed(const PhasePlan& p, real T, real N) {
  EXPECT_REL(p.duration, T, 1e-9);
  EXPECT_REL(p.position(T), N, 1e-9);
  EXPECT_REL(p.s_acc + p.s_cruise + p.s_dec, N, 1e-12);
  EXPECT_EQ(uint64_t(p.accel_steps) + p.cruise_steps + p.decel_steps, static_cast<uint64_t>(N));
  EXPECT_EQ(p.v_end, p.v_start);
}
}  // namespace

TEST(Ranade, TriangularCaseUsesHisFormulas) {
  struct Case {
    real N, T, start;
  } cases[] = {{3000, 2, 1000}, {1000, 1, 0}, {12345, 4.5L, 777}};
  for (const Case& c : cases) {
    const Limits l = ranade_limits(c.start);
    // distance_covered = available_time * (speed_limit + start_speed)/2 >= desired_position
    ASSERT_GE(c.T * (l.max_speed + c.start) / 2, c.N);
    const real required_average_speed = c.N / c.T;
    const real required_max_speed = (required_average_speed * 2) - c.start;
    const real required_acceleration = (required_max_speed - c.start) * 2 / c.T;
    ASSERT_LE(required_max_speed, l.max_speed);
    ASSERT_LE(required_acceleration, l.accel);
    const PhasePlan p = plan_timed(static_cast<uint64_t>(c.N), c.T, l);
    expect_timed(p, c.T, c.N);
    EXPECT_EQ(p.profile, Profile::Triangular);
    EXPECT_REL(p.v_peak, required_max_speed, 1e-12);
    EXPECT_REL(p.a, required_acceleration, 1e-12);
    EXPECT_REL(p.d, required_acceleration, 1e-12);  // deceleration = -required_acceleration
    EXPECT_REL(p.t_acc, c.T / 2, 1e-12);            // top speed in exactly half the time
    EXPECT_EQ(p.v_start, c.start);
  }
  // The first case by hand: 3000 steps in 2 s from 1000 steps/s: peak 2000, acceleration 1000.
  const PhasePlan p = plan_timed(3000, 2, ranade_limits());
  EXPECT_REL(p.v_peak, 2000, 1e-15);
  EXPECT_REL(p.a, 1000, 1e-15);
}

TEST(Ranade, TrapezoidWhereTheTriangleCannotCover) {
  // 8000 steps in 2 s: a triangle covers at most 2 * (5000 + 1000)/2 = 6000 steps.
  const Limits l = ranade_limits();
  const real N = 8000, T = 2, v0 = 1000, vl = 5000;
  ASSERT_LT(T * (vl + v0) / 2, N);
  // Area: v0*T + (vl - v0)*(T - t_r) = N.
  const real t_r = T - (N - v0 * T) / (vl - v0);
  const real acc = (vl - v0) / t_r;
  EXPECT_REL(t_r, 0.5L, 1e-15);
  const PhasePlan p = plan_timed(8000, T, l);
  expect_timed(p, T, N);
  EXPECT_EQ(p.profile, Profile::Trapezoidal);
  EXPECT_EQ(p.v_peak, vl);
  EXPECT_REL(p.a, acc, 1e-12);
  EXPECT_REL(p.t_acc, t_r, 1e-12);
  EXPECT_REL(p.t_cruise, T - 2 * t_r, 1e-12);
  EXPECT_REL(p.s_acc, (v0 + vl) / 2 * t_r, 1e-12);
}

TEST(Ranade, SlowMoveRunsAtConstantSpeed) {
  const PhasePlan p = plan_timed(100, 1, ranade_limits());  // 100 steps/s < start speed
  expect_timed(p, 1, 100);
  EXPECT_EQ(p.profile, Profile::Constant);
  EXPECT_REL(p.v_peak, 100, 1e-15);
  EXPECT_EQ(p.cruise_steps, 100u);
  const PhasePlan q = plan_timed(1000, 1, ranade_limits());  // N/T == start speed
  EXPECT_EQ(q.profile, Profile::Constant);
  EXPECT_REL(q.v_peak, 1000, 1e-15);
}

TEST(Ranade, TooShortATimeReportsTheMinimum) {
  const Limits l = ranade_limits();
  // Fastest 3000 steps: triangle peak sqrt(v0^2 + a N) = 8717 > 5000, so trapezoid: ramps of
  // (5000 - 1000)/25000 s covering (5000^2 - 1000^2)/(2*25000) = 480 steps each.
  const real ramp_t = 4000.0L / 25000, ramp_s = (25e6L - 1e6L) / 50000;
  const real t_min = 2 * ramp_t + (3000 - 2 * ramp_s) / 5000;
  EXPECT_REL(t_min, 0.728L, 1e-15);
  try {
    plan_timed(3000, 0.1L, l);
    ADD_FAILURE() << "no InfeasibleTime";
  } catch (const InfeasibleTime& e) {
    EXPECT_REL(e.min_time(), t_min, 1e-12);
    EXPECT_EQ(e.requested_time(), 0.1L);
    const std::string w = e.what();
    EXPECT_EQ(w.rfind("--time:", 0), 0u) << w;
    EXPECT_NE(w.find("0.728"), std::string::npos) << w;
    EXPECT_EQ(w.find('\n'), std::string::npos);
  }
  EXPECT_THROW(plan_timed(3000, t_min * (1 - 1e-9L), l), InfeasibleTime);
  const PhasePlan p = plan_timed(3000, t_min, l);  // exactly the minimum: the min-time plan
  expect_timed(p, t_min, 3000);
  EXPECT_LE(p.a, l.accel);
  EXPECT_REL(p.a, l.accel, 1e-9);
  // It is a PlanError too (a std::invalid_argument).
  EXPECT_THROW(plan_timed(3000, 0.1L, l), PlanError);
  EXPECT_THROW(plan_timed(3000, 0.1L, l), std::invalid_argument);
}

TEST(Ranade, InvalidRequestsAreNamed) {
  auto expect_flag = [](auto f, const std::string& flag) {
    try {
      f();
      ADD_FAILURE() << "no PlanError for " << flag;
    } catch (const PlanError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(flag + ":", 0), 0u) << e.what();
    }
  };
  const Limits l = ranade_limits();
  for (real T : {real(0), real(-1), std::numeric_limits<real>::quiet_NaN(), std::numeric_limits<real>::infinity()})
    expect_flag([&] { plan_timed(10, T, l); }, "--time");
  Limits d = l;
  d.decel = 1000;
  expect_flag([&] { plan_timed(10, 1, d); }, "--decel");
  d = l;
  d.decel = l.accel;  // equal: accepted
  EXPECT_NO_THROW(plan_timed(10, 1, d));
  d = l;
  d.ratio = 2;
  expect_flag([&] { plan_timed(10, 1, d); }, "--ratio");
  d = l;
  d.end_speed = 0;
  expect_flag([&] { plan_timed(10, 1, d); }, "--end-speed");
  d = l;
  d.start_speed = 6000;
  expect_flag([&] { plan_timed(10, 1, d); }, "--start-speed");
}

TEST(Ranade, RandomBudgetsAreMetExactly) {
  std::mt19937_64 rng(seed_for("Ranade.RandomBudgetsAreMetExactly"));
  int infeasible = 0, kinds[6] = {};
  for (int i = 0; i < 20000; ++i) {
    const uint64_t N = rng() % 5 == 0 ? 1 + rng() % 10 : static_cast<uint64_t>(log_uniform(rng, 1, 1e8));
    const real vl = log_uniform(rng, 1, 5e6);
    const real al = log_uniform(rng, 10, 1e8);
    const real v0 = rng() % 3 == 0 ? 0 : uniform(rng, 0, vl);
    Limits l;
    l.max_speed = vl;
    l.accel = al;
    l.start_speed = v0;
    const real n = static_cast<real>(N);
    const real t_min = min_time_bisect(n, v0, v0, vl, al, al);
    real factor;
    switch (rng() % 6) {
      case 0: factor = 1; break;
      case 1: factor = uniform(rng, 0.3L, 0.999999L); break;
      default: factor = log_uniform(rng, 1, 1000); break;
    }
    const real T = t_min * factor;
    SCOPED_TRACE("case " + std::to_string(i) + ": N=" + std::to_string(N) + " T=" + std::to_string(double(T)) +
                 " vl=" + std::to_string(double(vl)) + " al=" + std::to_string(double(al)) +
                 " v0=" + std::to_string(double(v0)));
    if (factor < 1) {
      try {
        plan_timed(N, T, l);
        ADD_FAILURE() << "no InfeasibleTime";
      } catch (const InfeasibleTime& e) {
        ++infeasible;
        EXPECT_REL(e.min_time(), t_min, 1e-9);
      }
      continue;
    }
    const PhasePlan p = plan_timed(N, T, l);
    ++kinds[static_cast<int>(p.profile)];
    expect_timed(p, T, n);
    EXPECT_LE(p.v_peak, vl);
    EXPECT_LE(p.a, al);
    EXPECT_EQ(p.a, p.d);
    EXPECT_LE(p.v_start, v0);
    if (p.profile != Profile::Constant) {
      EXPECT_EQ(p.v_start, v0);
    }
    EXPECT_PRED4(rel_near, p.v_start + p.a * p.t_acc, p.v_peak, real(1e-9), vl);
    if (::testing::Test::HasFailure()) break;
  }
  std::printf("infeasible %d, constant %d, triangular %d, trapezoidal %d\n", infeasible, kinds[1], kinds[2], kinds[3]);
  EXPECT_GT(infeasible, 0);
  EXPECT_GT(kinds[1], 0);
  EXPECT_GT(kinds[2], 0);
  EXPECT_GT(kinds[3], 0);
}
