// SPDX-License-Identifier: Apache-2.0
// Units and limits: conversions (Stoychitch section 4, the lead-screw post), rounding of the
// distance, and the errors (flag named, range given, one line).
#include <limits>
#include <string>

#include "common.hpp"

using namespace hexstep::plan;
using namespace hexstep::plan::test;
using hexstep::real;

namespace {
const real kNaN = std::numeric_limits<real>::quiet_NaN();
const real kInf = std::numeric_limits<real>::infinity();
}  // namespace

TEST(Units, NamesRoundTrip) {
  for (Unit u : {Unit::Steps, Unit::Rev, Unit::Deg, Unit::Rad, Unit::Mm}) EXPECT_EQ(parse_unit(unit_name(u)), u);
  expect_error([] { parse_unit("inch"); }, "--unit", "steps, rev, deg, rad, mm");
}

TEST(Units, FactorsPerUnit) {
  Scale s;
  s.steps_per_rev = 4096;
  EXPECT_EQ(steps_per_unit(Unit::Steps, s), 1);
  EXPECT_EQ(steps_per_unit(Unit::Rev, s), 4096);
  EXPECT_REL(steps_per_unit(Unit::Deg, s), 4096.0L / 360, 1e-18);
  EXPECT_REL(steps_per_unit(Unit::Rad, s), 4096 / (2 * kPi), 1e-18);
  // Stoychitch section 4: position [deg] * K / 360 = position [steps].
  EXPECT_REL(to_steps(90, Unit::Deg, s), 1024, 1e-18);
  // Lead screw post: step length p / n_r = 8 mm / 400 = 0.02 mm, so 50 steps per mm.
  Scale screw;
  screw.steps_per_rev = 400;
  screw.pitch_mm = 8;
  EXPECT_REL(steps_per_unit(Unit::Mm, screw), 50, 1e-18);
  Scale lin;
  lin.steps_per_mm = 80;
  EXPECT_EQ(steps_per_unit(Unit::Mm, lin), 80);
  screw.steps_per_mm = 50;  // consistent: accepted
  EXPECT_REL(steps_per_unit(Unit::Mm, screw), 50, 1e-18);
  screw.steps_per_mm = 80;  // contradicts K / pitch
  expect_error([&] { steps_per_unit(Unit::Mm, screw); }, "--steps-per-mm", "disagrees");
}

TEST(Units, MissingOrInvalidFactorsAreNamed) {
  Scale none;
  for (Unit u : {Unit::Rev, Unit::Deg, Unit::Rad}) expect_error([&] { steps_per_unit(u, none); }, "--steps-per-rev");
  expect_error([&] { steps_per_unit(Unit::Mm, none); }, "--steps-per-mm");
  Scale k;
  k.steps_per_rev = 200;
  expect_error([&] { steps_per_unit(Unit::Mm, k); }, "--pitch-mm");
  Scale p;
  p.pitch_mm = 5;
  expect_error([&] { steps_per_unit(Unit::Mm, p); }, "--steps-per-rev");
  for (real bad : {real(0), real(-4096), kNaN, kInf}) {
    Scale s;
    s.steps_per_rev = bad;
    expect_error([&] { steps_per_unit(Unit::Rev, s); }, "--steps-per-rev", "> 0");
    Scale m;
    m.steps_per_mm = bad;
    expect_error([&] { steps_per_unit(Unit::Mm, m); }, "--steps-per-mm", "> 0");
    Scale q;
    q.steps_per_rev = 400;
    q.pitch_mm = bad;
    expect_error([&] { steps_per_unit(Unit::Mm, q); }, "--pitch-mm", "> 0");
    // An invalid factor is refused even when the unit does not use it.
    expect_error([&] { steps_per_unit(Unit::Steps, q); }, "--pitch-mm", "> 0");
  }
}

TEST(Units, DistanceRoundsToTheNearestStep) {
  Scale s;
  s.steps_per_rev = 4096;
  StepCount c = distance_to_steps(90, Unit::Deg, s);
  EXPECT_EQ(c.steps, 1024u);
  EXPECT_TRUE(c.dir);
  c = distance_to_steps(-1.5L, Unit::Rev, s);
  EXPECT_EQ(c.steps, 6144u);
  EXPECT_FALSE(c.dir);
  c = distance_to_steps(2 * kPi, Unit::Rad, s);  // the Arduino program's default move
  EXPECT_EQ(c.steps, 4096u);
  // 0.1 deg = 1.1378 steps -> 1; 0.2 deg = 2.2756 -> 2; 0.15 deg = 1.7067 -> 2
  EXPECT_EQ(distance_to_steps(0.1L, Unit::Deg, s).steps, 1u);
  EXPECT_EQ(distance_to_steps(0.15L, Unit::Deg, s).steps, 2u);
  Scale screw;
  screw.steps_per_rev = 400;
  screw.pitch_mm = 8;
  c = distance_to_steps(10.013L, Unit::Mm, screw);  // 500.65 steps
  EXPECT_EQ(c.steps, 501u);
  EXPECT_REL(c.exact, 500.65L, 1e-15);
  EXPECT_EQ(distance_to_steps(-10.009L, Unit::Mm, screw).steps, 500u);  // 500.45
  EXPECT_EQ(distance_to_steps(2.5L, Unit::Steps, Scale{}).steps, 3u);    // halves away from zero
  EXPECT_EQ(distance_to_steps(-2.5L, Unit::Steps, Scale{}).steps, 3u);
  c = distance_to_steps(-0.2L, Unit::Steps, Scale{});
  EXPECT_EQ(c.steps, 0u);
  EXPECT_TRUE(c.dir);  // no motion: direction is positive
  EXPECT_EQ(distance_to_steps(4294967295.0L, Unit::Steps, Scale{}).steps, 4294967295u);
  expect_error([] { distance_to_steps(4294967296.0L, Unit::Steps, Scale{}); }, "--distance", "4294967295");
  expect_error([&] { distance_to_steps(2e6L, Unit::Rev, s); }, "--distance", "at most");
  expect_error([] { distance_to_steps(kNaN, Unit::Steps, Scale{}); }, "--distance", "finite");
  expect_error([] { distance_to_steps(-kInf, Unit::Steps, Scale{}); }, "--distance", "finite");
}

TEST(Units, LimitsConvertWithTheSameFactor) {
  Scale s;
  s.steps_per_rev = 4096;
  Limits l;
  l.max_speed = 2;
  l.accel = 2;
  l.ratio = 2;
  l.start_speed = 0.5L;
  const Limits r = limits_to_steps(l, Unit::Rad, s);
  const real k = 4096 / (2 * kPi);
  EXPECT_REL(r.max_speed, 2 * k, 1e-18);
  EXPECT_REL(r.accel, 2 * k, 1e-18);
  EXPECT_REL(r.start_speed, 0.5L * k, 1e-18);
  EXPECT_EQ(*r.ratio, 2);
  EXPECT_FALSE(r.decel);
  EXPECT_FALSE(r.end_speed);
  const RampLimits rl = resolve(r);
  EXPECT_REL(rl.decel, k, 1e-18);  // d = a / m
  EXPECT_EQ(rl.v_end, rl.v_start);  // end speed defaults to the start speed
}

TEST(Units, InvalidLimitsAreNamedWithTheirRange) {
  auto base = [] {
    Limits l;
    l.max_speed = 1000;
    l.accel = 5000;
    return l;
  };
  EXPECT_NO_THROW(resolve(base()));
  for (real bad : {real(0), real(-1), kNaN, kInf}) {
    Limits l = base();
    l.max_speed = bad;
    expect_error([&] { resolve(l); }, "--max-speed", "> 0");
    l = base();
    l.accel = bad;
    expect_error([&] { resolve(l); }, "--accel", "> 0");
    l = base();
    l.decel = bad;
    expect_error([&] { resolve(l); }, "--decel", "> 0");
    l = base();
    l.ratio = bad;
    expect_error([&] { resolve(l); }, "--ratio", "> 0");
  }
  for (real bad : {real(-1), kNaN, kInf}) {
    Limits l = base();
    l.start_speed = bad;
    expect_error([&] { resolve(l); }, "--start-speed", ">= 0");
    l = base();
    l.end_speed = bad;
    expect_error([&] { resolve(l); }, "--end-speed", ">= 0");
  }
  Limits l = base();
  l.start_speed = 1000.5L;
  expect_error([&] { resolve(l); }, "--start-speed", "[0, --max-speed = 1000]");
  expect_error([&] { plan_min_time(10, l); }, "--start-speed", "[0, --max-speed = 1000]");
  l = base();
  l.end_speed = 2000;
  expect_error([&] { resolve(l); }, "--end-speed", "[0, --max-speed = 1000]");
  l = base();
  l.decel = 100;
  l.ratio = 2;
  expect_error([&] { resolve(l); }, "--ratio", "not both");
  // Physical units are validated before conversion, with the caller's numbers.
  Scale s;
  s.steps_per_rev = 200;
  l = base();
  l.accel = -3;
  expect_error([&] { limits_to_steps(l, Unit::Rev, s); }, "--accel", "got -3");
  expect_error([&] { plan_min_time(kMaxSteps + 1, base()); }, "--steps", "4294967295");
}
