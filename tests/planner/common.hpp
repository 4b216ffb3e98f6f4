// SPDX-License-Identifier: Apache-2.0
// hexstep planner tests: seed handling, random inputs and an independent minimum-time
// computation (bisection on the acceleration distance, no closed-form peak).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "hexstep/planner.hpp"

namespace hexstep::plan::test {

constexpr real kPi = 3.14159265358979323846264338327950288L;

// Seed of a random test: $SEED if set, else a fresh one; printed so a failure can be replayed.
inline uint64_t seed_for(const char* name) {
  uint64_t s;
  if (const char* e = std::getenv("SEED")) s = std::strtoull(e, nullptr, 0);
  else s = std::random_device{}() ^ (uint64_t(std::random_device{}()) << 32);
  std::printf("%s: SEED=%llu\n", name, static_cast<unsigned long long>(s));
  return s;
}

inline real log_uniform(std::mt19937_64& rng, real lo, real hi) {
  std::uniform_real_distribution<double> u(std::log(static_cast<double>(lo)), std::log(static_cast<double>(hi)));
  return std::exp(static_cast<real>(u(rng)));
}

inline real uniform(std::mt19937_64& rng, real lo, real hi) {
  std::uniform_real_distribution<double> u(static_cast<double>(lo), static_cast<double>(hi));
  return u(rng);
}

// |x - y| <= tol * max(|x|, |y|, floor)
inline bool rel_near(real x, real y, real tol, real floor = 0) {
  const real m = std::max({std::fabs(x), std::fabs(y), floor});
  return std::fabs(x - y) <= tol * m;
}

#define EXPECT_REL(x, y, tol)                                                                     \
  EXPECT_PRED4(::hexstep::plan::test::rel_near, static_cast<::hexstep::real>(x),                 \
               static_cast<::hexstep::real>(y), static_cast<::hexstep::real>(tol), ::hexstep::real(0))

#define ASSERT_REL(x, y, tol)                                                                     \
  ASSERT_PRED4(::hexstep::plan::test::rel_near, static_cast<::hexstep::real>(x),                 \
               static_cast<::hexstep::real>(y), static_cast<::hexstep::real>(tol), ::hexstep::real(0))

// The end speed a move of N steps can actually reach (the fastest possible change).
inline real reachable_end(real N, real v0, real ve, real a, real d) {
  if (ve > v0 && ve * ve > v0 * v0 + 2 * a * N) return std::sqrt(v0 * v0 + 2 * a * N);
  if (ve < v0 && ve * ve < v0 * v0 - 2 * d * N) return std::sqrt(std::max<real>(v0 * v0 - 2 * d * N, 0));
  return ve;
}

// Independent minimum time: the acceleration distance s (steps) is found by bisection so that
// s + (distance to slow from the speed at s to ve) is at most N and the speed at s at most vM;
// time = 2s/(v0+p) + 2 s_d/(p+ve) + cruise/p with p = sqrt(v0^2 + 2 a s).
inline real min_time_bisect(real N, real v0, real ve, real vM, real a, real d) {
  const real vr = reachable_end(N, v0, ve, a, d);
  if (vr != ve) return 2 * N / (v0 + vr);  // one ramp all the way: distance / mean speed
  ve = vr;
  auto peak = [&](real s) { return std::sqrt(v0 * v0 + 2 * a * s); };
  auto dec_dist = [&](real s) { return ((v0 - ve) * (v0 + ve) + 2 * a * s) / (2 * d); };
  real lo = std::max<real>(0, (ve - v0) * (ve + v0) / (2 * a));
  real hi = std::min<real>(N, (vM - v0) * (vM + v0) / (2 * a));
  if (hi < lo) hi = lo;
  real s;
  if (hi + dec_dist(hi) <= N) {
    s = hi;
  } else {
    for (int i = 0; i < 200; ++i) {
      const real mid = (lo + hi) / 2;
      if (mid + dec_dist(mid) <= N) lo = mid;
      else hi = mid;
    }
    s = lo;
  }
  const real p = peak(s);
  const real sd = std::max<real>(dec_dist(s), 0);
  const real cruise = std::max<real>(N - s - sd, 0);
  real t = 0;
  if (s > 0) t += 2 * s / (v0 + p);
  if (sd > 0) t += 2 * sd / (p + ve);
  if (cruise > 0) t += cruise / p;
  return t;
}

// The fastest speed any motion within the limits can have at position x (0 <= x <= N): it must
// be reachable from v0 by x, able to slow to the reachable end speed by N, and at most vM.
inline real envelope(real x, real N, real v0, real ve, real vM, real a, real d) {
  ve = reachable_end(N, v0, ve, a, d);
  return std::min({vM, std::sqrt(v0 * v0 + 2 * a * x), std::sqrt(ve * ve + 2 * d * std::max<real>(N - x, 0))});
}

// Runs f, expects a PlanError whose one-line message starts with `flag:` and contains `part`.
template <class F>
inline void expect_error(F f, const std::string& flag, const std::string& part = "") {
  try {
    f();
    ADD_FAILURE() << "no PlanError, expected one naming " << flag;
  } catch (const PlanError& e) {
    const std::string w = e.what();
    EXPECT_EQ(w.rfind(flag + ":", 0), 0u) << w;
    EXPECT_NE(w.find(part), std::string::npos) << w;
    EXPECT_EQ(w.find('\n'), std::string::npos) << w;
  }
}

}  // namespace hexstep::plan::test
