// SPDX-License-Identifier: Apache-2.0
// Plans -> registers -> the core's timing (the one-axis frame runner of tests/common/axis_run on
// the model's AxisGen and PulseStage, equal to the cycle-exact TopModel by
// tests/model/test_event_mode.cpp): exactly N steps, every step within allowance_cycles of
// ideal_rise_cycle, and the encoded IdealProfile's duration and peak equal the plan's to 1e-6
// relative. Also the range checks of encode() and check_pulse_rate(). The registers count
// ticks (tick_rate(f) = f / 32): the limits below are one step per tick and ACC_W's range.
#include <array>
#include <string>

#include "axis_run.hpp"
#include "common.hpp"

using namespace hexstep::plan;
using namespace hexstep::plan::test;
using hexstep::real;

namespace {
constexpr real kClock = 100e6;

struct RunStats {
  real worst_ratio = 0;  // worst |error| / allowance
  uint64_t steps = 0;
};

// Runs each encoded move on its axis (all axes of one START share their time zero, so each
// axis alone gives the same instants) and checks every step against its ideal instant. Returns
// the last step's cycle per axis, from the common time zero.
std::array<uint64_t, hexstep::kNumAxes> run_and_check(const std::vector<std::pair<unsigned, hexstep::EncodedMove>>& moves,
                                                      real clock, RunStats& st, const std::string& name) {
  (void)clock;
  std::array<uint64_t, hexstep::kNumAxes> last{};
  for (const auto& m : moves) {
    const hexstep::EncodedMove& e = m.second;
    hexstep::test::AxisRunOptions o;
    o.axis = m.first;
    const hexstep::test::AxisRun r = hexstep::test::run_axis(e.regs, o);
    EXPECT_FALSE(r.timed_out) << name;
    EXPECT_FALSE(r.refused && e.regs.steps != 0) << name;
    EXPECT_EQ(r.rises.size(), e.regs.steps) << name << " axis " << m.first;
    unsigned bad = 0;
    for (const hexstep::test::AxisRise& x : r.rises) {
      const real ideal = hexstep::ideal_rise_cycle(e.ideal, x.step);
      const real err = std::fabs(static_cast<real>(x.cycle) - ideal);
      const real allow = hexstep::allowance_cycles(e.ideal, x.step);
      st.worst_ratio = std::max(st.worst_ratio, err / allow);
      if (err > allow && bad++ < 3)
        ADD_FAILURE() << name << " axis " << m.first << " step " << x.step << " cycle " << x.cycle << " ideal "
                      << static_cast<double>(ideal) << " allowance " << static_cast<double>(allow);
      EXPECT_EQ(x.dir, e.regs.dir) << name;
      last[m.first] = x.cycle;
    }
    if (bad > 3) ADD_FAILURE() << name << " axis " << m.first << ": " << bad << " steps outside the allowance";
    st.steps += r.rises.size();
  }
  return last;
}

// Encodes a plan, compares the encoded ideal with it, runs it alone on axis 0.
void check_plan(const PhasePlan& p, real clock, RunStats& st, const std::string& name) {
  SCOPED_TRACE(name + " (" + profile_name(p.profile) + ", N=" + std::to_string(p.steps) + ")");
  check_pulse_rate(p.v_peak, clock, 1, 1);
  const hexstep::EncodedMove e = encode(p, clock);
  EXPECT_EQ(e.regs.steps, p.steps);
  EXPECT_EQ(e.regs.dir, p.dir);
  EXPECT_EQ(hexstep::validate_move(e.regs), 0u);
  if (p.steps == 0) return;
  EXPECT_REL(e.ideal.duration(), p.duration, 1e-6);
  EXPECT_REL(e.ideal.vp, p.v_peak, 1e-6);
  run_and_check({{0u, e}}, clock, st, name);
}
}  // namespace

TEST(Encode, SeedMovesRunOnTheModel) {
  RunStats st;
  // Stoychitch's defaults (K = 4096; rad units), triangular and trapezoidal.
  Scale k4096;
  k4096.steps_per_rev = 4096;
  Limits stoy;
  stoy.max_speed = 2;
  stoy.accel = 2;
  stoy.ratio = 2;
  stoy.start_speed = 0.5L;
  const Limits stoy_s = limits_to_steps(stoy, Unit::Rad, k4096);
  check_plan(plan_min_time(1024, stoy_s), kClock, st, "stoychitch 90 deg");
  check_plan(plan_min_time(4096, stoy_s, false), kClock, st, "stoychitch 2 pi");
  // Lead screw: 400 steps/rev, 8 mm pitch, 10 mm at 100 mm/s^2.
  Scale screw;
  screw.steps_per_rev = 400;
  screw.pitch_mm = 8;
  Limits ls;
  ls.max_speed = 100;
  ls.accel = 100;
  check_plan(plan_min_time(500, limits_to_steps(ls, Unit::Mm, screw)), kClock, st, "lead screw 10 mm");
  // Ranade: 3000 steps in 2 s from 1000 steps/s; 8000 steps in 2 s (trapezoid).
  Limits rl;
  rl.start_speed = 1000;
  rl.max_speed = 5000;
  rl.accel = 25000;
  check_plan(plan_timed(3000, 2, rl), kClock, st, "ranade triangle");
  check_plan(plan_timed(8000, 2, rl), kClock, st, "ranade trapezoid");
  check_plan(plan_timed(100, 1, rl), kClock, st, "ranade constant");
  // AVR446 demo (spr 400): 20 rad/s, 40 rad/s^2, 400 steps.
  Scale k400;
  k400.steps_per_rev = 400;
  Limits avr;
  avr.max_speed = 20;
  avr.accel = 40;
  avr.decel = 40;
  check_plan(plan_min_time(400, limits_to_steps(avr, Unit::Rad, k400)), kClock, st, "avr446 demo");
  // Short moves that cannot meet the end speed.
  Limits up;
  up.max_speed = 5000;
  up.accel = 1e5;
  up.start_speed = 100;
  up.end_speed = 5000;
  check_plan(plan_min_time(10, up), kClock, st, "accel-only");
  Limits down;
  down.max_speed = 5000;
  down.accel = 1e5;
  down.start_speed = 5000;
  down.end_speed = 0;
  check_plan(plan_min_time(10, down), kClock, st, "decel-only");
  Limits cst;
  cst.max_speed = 3000;
  cst.accel = 1e5;
  cst.start_speed = 3000;
  check_plan(plan_min_time(300, cst), kClock, st, "constant");
  std::printf("seed moves: %llu steps, worst error/allowance %.3f\n", (unsigned long long)st.steps,
              static_cast<double>(st.worst_ratio));
}

// Random plans (minimum-time and timed) at 1, 10 and 100 MHz. Accelerations are at least
// 10^7 register LSBs (ft^2 / 2^64 steps/s^2 each, ft = f / 32 ticks/s), so that rounding them
// changes the profile by less than 1e-7 relative, and at most half of ACC_W's range; speeds stay
// below 0.9 step per tick (the register's limit is one).
TEST(Encode, RandomPlansRunOnTheModel) {
  std::mt19937_64 rng(seed_for("Encode.RandomPlansRunOnTheModel"));
  RunStats st;
  int timed = 0;
  for (int i = 0; i < 300; ++i) {
    const real clock = std::array<real, 3>{1e6L, 1e7L, 1e8L}[rng() % 3];
    const real ft = hexstep::tick_rate(clock);
    const real lsb = ft * ft / 18446744073709551616.0L;
    const real vtop = std::min<real>(5e6L, 0.9L * ft);
    const real amin = std::max<real>(1e7L * lsb, 10);
    const uint64_t N = static_cast<uint64_t>(log_uniform(rng, 1, 20000));
    Limits l;
    l.max_speed = log_uniform(rng, 1, vtop);
    const real amax = std::min<real>(1e8L, hexstep::max_accel(clock) / 2);
    l.accel = log_uniform(rng, amin, amax);
    l.decel = log_uniform(rng, amin, amax);
    auto speed = [&]() -> real {
      switch (rng() % 4) {
        case 0: return 0;
        case 1: return l.max_speed;
        default: return uniform(rng, 0, l.max_speed);
      }
    };
    l.start_speed = speed();
    l.end_speed = speed();
    // Keep each move under ~10 s of motion so the event-mode model stays quick.
    const PhasePlan p0 = plan_min_time(N, l, rng() & 1);
    if (p0.duration > 10) continue;
    check_plan(p0, clock, st, "random min-time #" + std::to_string(i));
    Limits t = l;
    t.decel.reset();
    t.end_speed.reset();
    const PhasePlan fastest = plan_min_time(N, [&] {
      Limits s = t;
      s.end_speed = t.start_speed;
      return s;
    }());
    const real T = fastest.duration * log_uniform(rng, 1, 3);
    if (T > 10) continue;
    const PhasePlan pt = plan_timed(N, T, t, rng() & 1);
    // A time budget lowers the acceleration below the limit, maybe below amin.
    if (pt.a > 0 && pt.a < amin) continue;
    check_plan(pt, clock, st, "random timed #" + std::to_string(i));
    ++timed;
    if (::testing::Test::HasFailure()) break;
  }
  std::printf("random moves: %llu steps (%d timed moves), worst error/allowance %.3f\n",
              (unsigned long long)st.steps, timed, static_cast<double>(st.worst_ratio));
  EXPECT_GT(timed, 30);
}

// A coordinated line on all six axes at 10 MHz: every axis makes its steps on time, and all
// arrive together (their ideal durations equal the path's). Each axis's acceleration is the
// path's times |N_i|/L >= 1/100 of at least 1e4 steps/s^2: >= 1.9e10 LSBs (5.3e-9 steps/s^2
// each at 10 MHz); at most 1e6 of ACC_W's 1.46e6 steps/s^2 there; speeds below 0.9 step per
// tick (281 k steps/s).
TEST(Encode, CoordinatedLineRunsTogether) {
  std::mt19937_64 rng(seed_for("Encode.CoordinatedLineRunsTogether"));
  const real kLineClock = 10e6;
  RunStats st;
  for (int i = 0; i < 40; ++i) {
    std::vector<AxisRequest> req;
    for (unsigned a = 0; a < hexstep::kNumAxes; ++a) {
      AxisRequest r;
      r.axis = a;
      r.steps = static_cast<int64_t>(log_uniform(rng, 80, 8000)) * (rng() & 1 ? 1 : -1);
      r.limits.max_speed = log_uniform(rng, 1e3, 2.8e5);
      r.limits.accel = log_uniform(rng, 1e4, 1e6);
      r.limits.decel = log_uniform(rng, 1e4, 1e6);
      req.push_back(r);
    }
    const LinePlan line = coordinated_line(req);
    if (line.path.duration > 5) continue;
    std::vector<std::pair<unsigned, hexstep::EncodedMove>> moves;
    for (const AxisPlan& ap : line.axes) {
      const hexstep::EncodedMove e = encode(ap.plan, kLineClock);
      EXPECT_REL(e.ideal.duration(), line.path.duration, 1e-6);
      EXPECT_REL(e.ideal.vp, ap.plan.v_peak, 1e-6);
      moves.emplace_back(ap.axis, e);
    }
    const auto last = run_and_check(moves, kLineClock, st, "line #" + std::to_string(i));
    // Arrive together: each last step is within its allowance of the ideal end (checked in
    // run_and_check); the ideal ends agree, so the last steps are within a few cycles plus
    // the allowances of each other.
    uint64_t lo = ~0ull, hi = 0;
    for (unsigned a = 0; a < hexstep::kNumAxes; ++a) {
      lo = std::min(lo, last[a]);
      hi = std::max(hi, last[a]);
    }
    real allow = 0;
    for (const auto& m : moves) allow = std::max(allow, hexstep::allowance_cycles(m.second.ideal, m.second.regs.steps));
    EXPECT_LE(static_cast<real>(hi - lo), 2 * allow + 1e-6L * line.path.duration * kLineClock) << "line #" << i;
    if (::testing::Test::HasFailure()) break;
  }
  std::printf("lines: %llu steps, worst error/allowance %.3f\n", (unsigned long long)st.steps,
              static_cast<double>(st.worst_ratio));
}

TEST(Encode, UnrepresentableValuesAreNamedWithTheRangeAtThisClock) {
  // At 100 MHz a tick is 32 cycles: speeds in [2^-64, 1) step per tick = [1.69e-13, 3125000)
  // steps/s, accelerations up to 2^-16 step per tick^2 = 1.49e8 steps/s^2 (ACC_W = 48).
  const real ft = hexstep::tick_rate(kClock);
  ASSERT_EQ(ft, 3125000.0L);
  Limits l;
  l.max_speed = 4e6;  // faster than one step per tick at 100 MHz
  l.accel = 1e8;
  expect_error([&] { encode(plan_min_time(4000000000u, l), kClock); }, "--max-speed", "[1.69406589e-13, 3125000)");
  l.max_speed = 1000;
  l.accel = 1e-7;  // below one LSB (ft^2 / 2^64 = 5.29e-7 steps/s^2 at 100 MHz)
  expect_error([&] { encode(plan_min_time(10, l), kClock); }, "--accel", "steps/s^2");
  l.accel = 1000;
  l.decel = 1e-7;
  l.start_speed = 1000;
  l.end_speed = 999;
  expect_error([&] { encode(plan_min_time(1000, l), kClock); }, "--decel", "[5.29395592e-07");
  l = Limits{};
  l.max_speed = 1000;
  l.accel = 1e13;  // above the ACC_W range at 100 MHz ((2^48 - 1) / 2^64 * ft^2)
  expect_error([&] { encode(plan_min_time(1000, l), kClock); }, "--accel", "149011612");
  // At 1 MHz the same 1e-7 steps/s^2 is 1,890 LSBs (5.29e-11 steps/s^2 each): representable.
  l.accel = 1e-7;
  l.max_speed = 1e-4;
  EXPECT_NO_THROW(encode(plan_min_time(1, l), 1e6));
  for (real f : {real(0), real(-1), std::numeric_limits<real>::quiet_NaN()})
    expect_error([&] { encode(plan_min_time(1, l), f); }, "--clock-hz", "> 0");
  // Zero steps encode to a no-op move.
  EXPECT_EQ(encode(plan_min_time(0, l), kClock).regs.steps, 0u);
}

TEST(Encode, PulseRateLimit) {
  EXPECT_NO_THROW(check_pulse_rate(5e7L, kClock, 1, 1));  // f / (1 + 1)
  expect_error([] { check_pulse_rate(5e7L + 1, kClock, 1, 1); }, "--max-speed", "50000000");
  EXPECT_NO_THROW(check_pulse_rate(5e7L, kClock, 0, 0));  // 0 acts as 1
  expect_error([] { check_pulse_rate(1e6L, kClock, 190, 190); }, "--max-speed", "263157.8");  // DRV8825 timing
  EXPECT_NO_THROW(check_pulse_rate(263157, kClock, 190, 190));
  expect_error([] { check_pulse_rate(1, 0, 1, 1); }, "--clock-hz");
}
