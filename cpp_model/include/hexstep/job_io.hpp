// SPDX-License-Identifier: Apache-2.0
// hexstep: the job file (JSON, docs/FORMATS.md) to and from hexstep::Job.
#pragma once

#include <stdexcept>
#include <string>

#include "hexstep/job.hpp"

namespace hexstep {

// A job file that cannot be used. what() is one line that names the offending field by its
// JSON path (e.g. "axes[1].moves[0].v_max") and says what it accepts.
class JobError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses and checks a job file: format and version, required and unknown fields, types, the
// core widths (the file's "widths" object; w for a file without one), every value against its
// register width, unique axis indices 0..5, and every move with validate_move() so that the
// core would accept it. Throws JobError.
Job parse_job(const std::string& text, const Widths& w = Widths{});

// The names of the widths as RTL parameters and job-file keys, in this order: SPEED_W, ACC_W,
// STEP_W, DFRAC_W, PULSE_W, POS_W.
constexpr unsigned kNumWidths = 6;
extern const char* const kWidthNames[kNumWidths];
unsigned& width_ref(Widths& w, unsigned i);
unsigned width_of(const Widths& w, unsigned i);
// The accepted range of width i (the RTL's parameter ranges, rtl/hexstep_top.v).
void width_range(const Widths& w, unsigned i, unsigned& lo, unsigned& hi);
// Empty if every width is within its range (the RTL's parameter ranges, rtl/hexstep_top.v),
// else "NAME: must be an integer in [lo, hi], got v" for the first that is not.
std::string widths_error(const Widths& w);
// "SPEED_W 64, ACC_W 48, ..." (all six).
std::string widths_text(const Widths& w);
bool same_widths(const Widths& a, const Widths& b);

// The canonical JSON of a job (two-space indent, fields in the documented order, a trailing
// newline). Axes with no moves and the default pulse configuration are left out, and so are
// default widths.
// parse_job(write_job(j)) equals j for every job that parse_job accepts.
std::string write_job(const Job& job);

// One line describing the MoveError bits of the move at JSON path `path`
// (e.g. "axes[0].moves[1]"), naming the fields and their accepted ranges.
std::string describe_move_error(uint32_t err, const AxisMove& m, const std::string& path,
                                const Widths& w = Widths{});

// Field-by-field equality (the structs in axis.hpp and job.hpp have no operator==).
bool same_move(const AxisMove& a, const AxisMove& b);
bool same_pulse(const PulseConfig& a, const PulseConfig& b);
bool same_job(const Job& a, const Job& b);

}  // namespace hexstep
