// SPDX-License-Identifier: Apache-2.0
// hexstep test vectors: written once, linked into the model tests (which check them against
// the seeds' formulas) and the RTL co-simulation (which checks RTL == model on them).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "hexstep/encoding.hpp"
#include "hexstep/job.hpp"

namespace hexstep::test {

struct Ramp {  // physical request for a test move; v_peak is derived (triangular or trapezoid)
  uint32_t steps;
  bool dir;
  real v_start, v_max, v_end, accel, decel;
};

// Peak speed of the fastest linear-ramp move within the limits (Stoychitch eq. 1-8 generalised
// to an end speed): the smaller of v_max and the triangular peak.
real ramp_peak(const Ramp& r);
EncodedMove encode(const Ramp& r, real clock_hz = kDefaultClockHz);

struct NamedJob {
  std::string name;
  Job job;
  // For moves built from a ramp: the ideal profile per axis and move (steps == 0 if raw).
  std::vector<std::vector<IdealProfile>> ideal;
};

std::vector<NamedJob> directed_jobs();

// Seed for the random regressions: $SEED if set, else a fresh one. Printed by the caller.
uint64_t test_seed();

// A random valid ramp within ranges that keep a move under ~10^6 cycles at 100 MHz.
Ramp random_ramp(std::mt19937_64& rng);
// Random raw register values, valid or not (the core must refuse the invalid ones cleanly).
AxisMove random_raw_move(std::mt19937_64& rng);
PulseConfig random_pulse(std::mt19937_64& rng);
// A constant-speed move: `steps` steps at `speed` (2^-64 step per tick) in every phase
// register (v_start = v_max = v_end = v_dec), decelerating from the last step.
AxisMove cruise(uint32_t steps, uint64_t speed, bool dir = true);
// A short trapezoid for the bus tests: from 1/64 to 1/8 step per tick at 2^-21 step/tick^2
// (2^43, the largest power of two in the 44-bit ACC/DEC registers), cruise, back to 1/64.
AxisMove bus_trapezoid(uint32_t steps, bool dir = true);
// A job with `moves_per_axis` moves on each of the six axes, mostly planned ramps.
NamedJob random_job(std::mt19937_64& rng, unsigned moves_per_axis, bool raw_too);

}  // namespace hexstep::test
