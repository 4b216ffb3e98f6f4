// SPDX-License-Identifier: Apache-2.0
// hexstep tests: the one-axis frame runner of the model library (hexstep/axis_run.hpp) under
// the names the tests use.
#pragma once

#include "hexstep/axis_run.hpp"

namespace hexstep::test {
using hexstep::AxisRise;
using hexstep::AxisRun;
using hexstep::AxisRunOptions;
using hexstep::run_axis;
}  // namespace hexstep::test
