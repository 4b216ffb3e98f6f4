// SPDX-License-Identifier: Apache-2.0
// hexstep: register widths and fixed-point formats, the C++ side of the parameters of
// rtl/hexstep_core.v.
// tests/model/test_widths.cpp checks these against the parameter defaults declared in
// rtl/hexstep_core.v and rtl/hexstep_axis.v, so the two can never drift apart.
#pragma once

#include <cstdint>

namespace hexstep {

// Default widths. docs/ARCHITECTURE.md, "Fixed-point formats", derives each one.
struct Widths {
  unsigned speed_frac = 64;  // SPEED_W: speed and position-fraction bits (unit 2^-64 step/tick)
  unsigned acc = 44;         // ACC_W: acceleration/deceleration register bits (same unit per tick)
  unsigned steps = 32;       // STEP_W: step counts
  unsigned dec_frac = 32;    // DFRAC_W: fraction bits of the deceleration start position
  unsigned pulse = 12;       // PULSE_W: pulse timing registers, in clock cycles
  unsigned pos = 32;         // POS_W: signed absolute position counter
  unsigned owe = 2;          // OWE_W: steps generated but not yet pulsed

  uint64_t speed_mask() const { return mask(speed_frac); }
  uint64_t acc_mask() const { return mask(acc); }
  uint64_t steps_mask() const { return mask(steps); }
  uint64_t dec_frac_mask() const { return mask(dec_frac); }
  uint64_t pulse_mask() const { return mask(pulse); }
  uint64_t pos_mask() const { return mask(pos); }
  unsigned owe_max() const { return (1u << owe) - 1u; }
  static constexpr uint64_t mask(unsigned w) { return w >= 64 ? ~0ull : ((1ull << w) - 1ull); }
};

// Number of clock cycles from the start strobe's rising clock edge to the instant that the
// generator treats as time zero of the motion, plus the one-cycle register between the
// generator's crossing tick and the STEP pin. A step whose ideal crossing lies in
// (k-1, k] ticks after time zero rises at cycle k + STEP_LATENCY.
constexpr unsigned kStepLatency = 1;

constexpr uint64_t kDefaultClockHz = 100000000ull;
constexpr unsigned kNumAxes = 6;

}  // namespace hexstep
