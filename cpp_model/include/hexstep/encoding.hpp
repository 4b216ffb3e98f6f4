// SPDX-License-Identifier: Apache-2.0
// hexstep: the fixed-point encoding, defined once. Physical speeds and accelerations to
// register values and back, a continuous linear-ramp profile to the registers of one move,
// and the ideal step instants of that profile (what the core's steps are measured against).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hexstep/axis.hpp"

namespace hexstep {

using real = long double;

// The register units count ticks: one tick of every axis per frame of kFrameCycles clock
// cycles, so a tick lasts kFrameCycles / clock_hz seconds (tick_rate: ticks per second).
real tick_rate(real clock_hz);
// steps/s -> speed register (2^-SPEED_W step per tick), rounded down. Returns false if the
// value does not fit (>= 1 step per tick) or is not finite/negative. clock_hz is the core's
// clock (the registers are in units of its ticks).
bool speed_to_reg(real steps_per_s, real clock_hz, uint64_t& reg, const Widths& w = Widths{});
// steps/s^2 -> acceleration register (2^-SPEED_W step per tick^2), rounded down.
bool accel_to_reg(real steps_per_s2, real clock_hz, uint64_t& reg, const Widths& w = Widths{});
real reg_to_speed(uint64_t reg, real clock_hz, const Widths& w = Widths{});
real reg_to_accel(uint64_t reg, real clock_hz, const Widths& w = Widths{});
// Largest and smallest non-zero values the registers hold at this clock, in physical units.
real max_speed(real clock_hz, const Widths& w = Widths{});
real max_accel(real clock_hz, const Widths& w = Widths{});

// A linear-ramp move in physical units: start at v_start, accelerate at accel up to v_peak,
// cruise, decelerate at decel to v_end, exactly `steps` steps. v_peak is the speed actually
// reached (the planner has already decided triangular or trapezoidal).
struct RampProfile {
  uint32_t steps = 0;
  bool dir = true;
  real v_start = 0, v_peak = 0, v_end = 0;  // steps/s
  real accel = 0, decel = 0;                 // steps/s^2, > 0 where a ramp exists
};

// The continuous motion that a move's registers describe, with every value exactly what the
// registers hold. Step instants of the core are compared with this profile.
struct IdealProfile {
  real clock_hz = 0;
  uint32_t steps = 0;
  real v0 = 0, vp = 0, ve = 0, a = 0, d = 0;  // steps/s, steps/s^2
  real s_acc = 0, s_cruise = 0, s_dec = 0;    // steps
  real t_acc = 0, t_cruise = 0, t_dec = 0;    // s
  real duration() const { return t_acc + t_cruise + t_dec; }
  // Position (steps) at time t (s) after the motion's time zero.
  real position(real t) const;
  // Speed (steps/s) at time t.
  real speed(real t) const;
  // Instant (s) at which the position reaches `x` steps, 0 <= x <= steps.
  real time_at(real x) const;
};

struct EncodedMove {
  AxisMove regs;
  IdealProfile ideal;
};

// Encodes a ramp profile. Throws std::invalid_argument naming the field and the accepted
// range when a value cannot be represented at this clock.
EncodedMove encode_ramp(const RampProfile& p, real clock_hz, const Widths& w = Widths{});

// Clock cycle, counted from the move's time zero (the first cycle of the frame whose slot ran
// its first tick), at which the ideal profile's step i (1-based) would rise if the core had no
// quantization: kStepLatency + time_at(i) * clock_hz. The core's STEP rises on the cycle
// ceil(that) or up to one cycle later (docs/ARCHITECTURE.md, "Timing of the outputs").
real ideal_rise_cycle(const IdealProfile& p, uint32_t i);

// The accuracy allowance of the core issue for step i, in clock cycles:
// 2 + 0.001 step / v_ideal (converted to cycles); infinite where the ideal speed is zero.
real allowance_cycles(const IdealProfile& p, uint32_t i);

}  // namespace hexstep
