// SPDX-License-Identifier: Apache-2.0
// hexstep tests: the refusal rules of docs/ARCHITECTURE.md ("Refusal rules") as test cases,
// each rule broken alone on a valid move, next to the boundary value the same rule still
// accepts. Used by the model tests (validate_move, make_slot) and, through the bus, by the fault
// tests (refused moves consumed with ERR.move, accepted ones run).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "vectors.hpp"

namespace hexstep::test {

struct RuleCase {
  std::string what;
  AxisMove m;
  uint32_t bits;   // the MoveError bits validate_move() must report (0: accepted)
  bool runs_long;  // accepted, but a jog or far too slow to run to its end in a test
};

// The cases on `ok`, a valid plain move (trapezoid(n) for any n).
inline std::vector<RuleCase> rule_cases(const AxisMove& ok) {
  std::vector<RuleCase> v;
  auto add = [&](const std::string& what, uint32_t bits, bool long_run, const std::function<void(AxisMove&)>& f) {
    AxisMove m = ok;
    f(m);
    v.push_back({what, m, bits, long_run});
  };
  add("v_max == 0", kErrVmaxZero | kErrStartAboveMax | kErrEndAboveMax | kErrDecAboveMax, false,
      [](AxisMove& m) { m.v_max = 0; });
  add("v_max == 0, all speeds 0 (the floor dec is above it)", kErrVmaxZero | kErrEndAboveMax, false,
      [](AxisMove& m) { m.v_max = m.v_start = m.v_end = m.v_dec = 0; });
  add("v_start > v_max", kErrStartAboveMax, false, [](AxisMove& m) { m.v_start = m.v_max + 1; });
  add("v_start == v_max", 0, false, [](AxisMove& m) { m.v_start = m.v_max; });
  add("v_end > v_max", kErrEndAboveMax, false, [](AxisMove& m) { m.v_end = m.v_max + 1; });
  add("v_end == v_max", 0, false, [](AxisMove& m) { m.v_end = m.v_max; });
  add("v_dec > v_max", kErrDecAboveMax, false, [](AxisMove& m) { m.v_dec = m.v_max + 1; });
  add("v_dec == v_max", 0, false, [](AxisMove& m) { m.v_dec = m.v_max; });
  add("all speeds all ones", 0, false, [](AxisMove& m) { m.v_start = m.v_max = m.v_end = m.v_dec = ~0ull; });
  add("v_end == 0, dec > v_max", kErrEndAboveMax, false, [](AxisMove& m) {
    m.v_end = 0;
    m.v_max = m.v_start = m.v_dec = 1ull << 40;
    m.dec = (1ull << 40) + 1;
  });
  add("v_end == 0, dec == v_max", 0, true, [](AxisMove& m) {  // floor 2^-24 step/tick: hours
    m.v_end = 0;
    m.v_max = m.v_start = m.v_dec = 1ull << 40;
    m.dec = 1ull << 40;
  });
  add("acc_steps > steps", kErrCountPastN, false, [](AxisMove& m) { m.acc_steps = m.steps + 1; });
  add("acc_steps == steps", 0, false, [](AxisMove& m) { m.acc_steps = m.steps; });
  add("acc_steps all ones", kErrCountPastN, false, [](AxisMove& m) { m.acc_steps = ~0u; });
  add("dec_step > steps", kErrCountPastN, false, [](AxisMove& m) { m.dec_step = m.steps + 1; });
  add("dec_step == steps", 0, false, [](AxisMove& m) { m.dec_step = m.steps; });
  add("dec_step all ones", kErrCountPastN, false, [](AxisMove& m) { m.dec_step = ~0u; });
  add("v_end == 0 && dec == 0", kErrNoFloor, false, [](AxisMove& m) {
    m.v_end = 0;
    m.dec = 0;
  });
  add("v_end != 0, dec == 0", 0, false, [](AxisMove& m) { m.dec = 0; });
  add("v_start == 0 && acc == 0", kErrNoStart, false, [](AxisMove& m) {
    m.v_start = 0;
    m.acc = 0;
  });
  add("v_start == 0 && acc_steps == 0", kErrNoStart, false, [](AxisMove& m) {
    m.v_start = 0;
    m.acc_steps = 0;
  });
  add("v_start == 0, accelerating", 0, false, [](AxisMove& m) { m.v_start = 0; });
  add("v_start == 0, acc == 0, decelerating from the first tick", 0, false, [](AxisMove& m) {
    m.v_start = 0;
    m.acc = 0;
    m.dec_step = 0;
    m.dec_frac = 0;
  });
  add("v_start == 0, acc == 0, dec_frac != 0", kErrNoStart, false, [](AxisMove& m) {
    m.v_start = 0;
    m.acc = 0;
    m.dec_step = 0;
    m.dec_frac = 1;
  });
  add("several rules at once", kErrVmaxZero | kErrStartAboveMax | kErrDecAboveMax | kErrCountPastN | kErrNoFloor,
      false, [](AxisMove& m) {
        m.v_max = 0;
        m.acc_steps = ~0u;
        m.dec = 0;
        m.v_end = 0;
      });
  add("jog, dec == 0", kErrJogNoDec, false, [](AxisMove& m) {
    m.jog = true;
    m.dec = 0;
  });
  add("jog, v_start == 0 && acc == 0", kErrNoStart, false, [](AxisMove& m) {
    m.jog = true;
    m.v_start = 0;
    m.acc = 0;
  });
  add("jog, v_start == 0, acc != 0", 0, true, [](AxisMove& m) {
    m.jog = true;
    m.v_start = 0;
  });
  add("jog, v_start > v_max", kErrStartAboveMax, false, [](AxisMove& m) {
    m.jog = true;
    m.v_start = m.v_max + 1;
  });
  add("jog, v_max == 0", kErrVmaxZero | kErrStartAboveMax, false, [](AxisMove& m) {
    m.jog = true;
    m.v_max = 0;
  });
  // A jog ignores the counts and v_end/v_dec: values the plain move would refuse.
  add("jog, counts past N and v_end above v_max", 0, true, [](AxisMove& m) {
    m.jog = true;
    m.steps = 0;
    m.acc_steps = m.dec_step = ~0u;
    m.v_end = m.v_dec = ~0ull;
  });
  return v;
}

}  // namespace hexstep::test
