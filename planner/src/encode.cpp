// SPDX-License-Identifier: Apache-2.0
// hexstep planner: a decided plan -> core registers, with range checks named by flag.
#include <algorithm>
#include <cmath>

#include "detail.hpp"

namespace hexstep::plan {

using detail::fail;
using detail::num;

namespace {

void check_clock(real f) {
  if (!std::isfinite(f) || !(f > 0)) fail("--clock-hz", "must be a finite frequency > 0 Hz (got " + num(f) + ")");
}

// A speed register holds [0, f) steps/s (below one step per cycle), rounded down.
void check_speed(const char* flag, real v, real f, const Widths& w, bool nonzero) {
  uint64_t reg = 0;
  const real lsb = reg_to_speed(1, f, w);
  // One step per tick (a frame of kFrameCycles clock cycles) is the register's limit.
  const real ft = tick_rate(f);
  const std::string range = nonzero ? "[" + num(lsb) + ", " + num(ft) + ") steps/s (at least one register LSB,"
                                    : "[0, " + num(ft) + ") steps/s (";
  if (!speed_to_reg(v, f, reg, w) || (nonzero && reg == 0))
    fail(flag, num(v) + " steps/s cannot be represented at --clock-hz " + num(f) + ": must be in " + range +
                   " below one step per tick of " + std::to_string(kFrameCycles) + " clock cycles)");
}

void check_accel(const char* flag, real a, real f, const Widths& w) {
  uint64_t reg = 0;
  if (!accel_to_reg(a, f, reg, w) || reg == 0)
    fail(flag, num(a) + " steps/s^2 cannot be represented at --clock-hz " + num(f) + ": must be in [" +
                   num(reg_to_accel(1, f, w)) + ", " + num(max_accel(f, w)) + "] steps/s^2");
}

// encode_ramp names RampProfile fields; the user knows the flags.
std::string flag_of(const std::string& field) {
  if (field == "v_start") return "--start-speed";
  if (field == "v_peak") return "--max-speed";
  if (field == "v_end") return "--end-speed";
  if (field == "accel") return "--accel";
  if (field == "decel") return "--decel";
  if (field == "steps") return "--steps";
  if (field == "clock_hz") return "--clock-hz";
  return field;
}

}  // namespace

EncodedMove encode(const PhasePlan& p, real clock_hz, const Widths& w) {
  check_clock(clock_hz);
  if (static_cast<uint64_t>(p.steps) > w.steps_mask())
    fail("--steps", "must be in [0, " + std::to_string(w.steps_mask()) + "] (got " + std::to_string(p.steps) + ")");
  RampProfile r;
  r.steps = p.steps;
  r.dir = p.dir;
  if (p.steps != 0) {
    check_speed("--start-speed", p.v_start, clock_hz, w, false);
    check_speed("--max-speed", p.v_peak, clock_hz, w, true);
    check_speed("--end-speed", p.v_end, clock_hz, w, false);
    if (p.v_peak > p.v_start) check_accel("--accel", p.a, clock_hz, w);
    if (p.v_peak > p.v_end) check_accel("--decel", p.d, clock_hz, w);
    r.v_start = p.v_start;
    r.v_peak = p.v_peak;
    r.v_end = p.v_end;
    r.accel = p.a;
    r.decel = p.d;
  }
  try {
    return encode_ramp(r, clock_hz, w);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    const size_t colon = what.find(':');
    if (colon == std::string::npos) throw PlanError(what);
    throw PlanError(flag_of(what.substr(0, colon)) + what.substr(colon));
  }
}

void check_pulse_rate(real v_peak, real clock_hz, uint32_t step_high, uint32_t step_low) {
  check_clock(clock_hz);
  const real cycles = static_cast<real>(std::max<uint32_t>(step_high, 1)) + std::max<uint32_t>(step_low, 1);
  const real limit = clock_hz / cycles;
  if (!std::isfinite(v_peak) || v_peak < 0 || v_peak > limit)
    fail("--max-speed", num(v_peak) + " steps/s is faster than the pulse stage allows: must be in [0, " +
                            num(limit) + "] steps/s = --clock-hz " + num(clock_hz) + " / (step_high " +
                            std::to_string(std::max<uint32_t>(step_high, 1)) + " + step_low " +
                            std::to_string(std::max<uint32_t>(step_low, 1)) + " cycles)");
}

}  // namespace hexstep::plan
