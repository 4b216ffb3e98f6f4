// SPDX-License-Identifier: Apache-2.0
// hexstep planner: helpers shared by the planner's sources (not installed).
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "hexstep/planner.hpp"

namespace hexstep::plan::detail {

// A number for a message: up to 9 significant digits, no trailing zeros.
inline std::string num(real x) {
  std::ostringstream o;
  o.precision(9);
  o << static_cast<double>(x);
  return o.str();
}

[[noreturn]] inline void fail(const std::string& flag, const std::string& why) {
  throw PlanError(flag + ": " + why);
}

inline bool finite(real x) { return std::isfinite(x); }

// Requires a finite value > 0.
inline void require_positive(const std::string& flag, real x, const std::string& unit = "") {
  if (!finite(x) || !(x > 0))
    fail(flag, "must be a finite number > 0" + (unit.empty() ? "" : " " + unit) + " (got " + num(x) + ")");
}

// Requires a finite value >= 0.
inline void require_nonnegative(const std::string& flag, real x, const std::string& unit = "") {
  if (!finite(x) || x < 0)
    fail(flag, "must be a finite number >= 0" + (unit.empty() ? "" : " " + unit) + " (got " + num(x) + ")");
}

inline void require_steps(uint64_t steps) {
  if (steps > kMaxSteps)
    fail("--steps", "must be in [0, " + std::to_string(kMaxSteps) + "] (got " + std::to_string(steps) + ")");
}

// Fills the integer step counts of a plan from s_acc, s_cruise, s_dec (PLANNER.md "Step counts").
void fill_counts(PhasePlan& p);

}  // namespace hexstep::plan::detail
