#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest synth_pnr_options: the nextpnr and Yosys options of synth/targets.json as flow.py
passes them. Every target's options are accepted; the ECP5 targets run with --tmg-ripup and
synth_ecp5 -nowidelut, the iCE40 ones with neither (docs/SYNTH.md: each raised the 25F's
ten-seed median; --tmg-ripup changed no iCE40 result, and iCE40 has no PFU muxes); a value
outside the accepted set stops the build with an error that names the target, the field and
the accepted values, before any tool runs. Also the Fmax goal's verdict over placement seeds,
and the axis counts `flow.py modules --naxes` accepts."""
import contextlib
import io
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import flow  # noqa: E402

fails = []


def check(cond, what):
    if not cond:
        fails.append(what)


for name, t in flow.load_targets().items():
    args, res = flow.pnr_options(name, t)
    want = t["family"] == "ecp5"
    check(("--tmg-ripup" in args) == want, f"{name}: --tmg-ripup expected {want}, args {args}")
    check(res.get("tmg_ripup", False) == want, f"{name}: result records tmg_ripup {res}")
    check("--router" not in args, f"{name}: no router override expected, args {args}")
    opts, sres = flow.yosys_options(name, t)
    check(opts == (["-nowidelut"] if want else []), f"{name}: Yosys options {opts}")
    check(sres.get("nowidelut", False) == want, f"{name}: result records nowidelut {sres}")

check(flow.pnr_options("x", {"tmg_ripup": False}) == ([], {"tmg_ripup": False}),
      "tmg_ripup false adds no argument")
check(flow.pnr_options("x", {"router": "router2", "tmg_ripup": True})[0] ==
      ["--router", "router2", "--tmg-ripup"], "router and ripup arguments in order")

check(flow.yosys_options("x", {"family": "ecp5", "nowidelut": False}) ==
      ([], {"nowidelut": False}), "nowidelut false adds no option")

def refusal(fn, *args):
    """Calls fn, which must stop the flow: (its exit code, or None if it returned; stderr)."""
    err = io.StringIO()
    code = None
    with contextlib.redirect_stderr(err):
        try:
            fn(*args)
        except SystemExit as e:
            code = e.code
    return code, err.getvalue()


for fn, bad, field, accepted in [
        (flow.pnr_options, {"tmg_ripup": "yes"}, "tmg_ripup", "true or false"),
        (flow.pnr_options, {"tmg_ripup": 1}, "tmg_ripup", "true or false"),
        (flow.pnr_options, {"router": "router3"}, "router", "router1 or router2"),
        (flow.yosys_options, {"family": "ecp5", "nowidelut": "yes"}, "nowidelut",
         "true or false"),
        (flow.yosys_options, {"family": "ice40", "nowidelut": True}, "nowidelut",
         "only to family ecp5")]:
    code, msg = refusal(fn, "bad_target", bad)
    check(code not in (None, 0), f"{bad}: exit code {code}, expected non-zero")
    check("bad_target" in msg and field in msg and accepted in msg,
          f"{bad}: message {msg!r} does not name the target, {field} and '{accepted}'")

# `modules --naxes`: one axis count 1..8 (hexstep_top's range) or two increasing ones.
check(flow.parse_naxes("6") == [6] and flow.parse_naxes("1,6") == [1, 6] and
      flow.parse_naxes("8") == [8], "--naxes accepts 6, 1,6 and 8")
for bad in ("0", "9", "6,1", "3,3", "1,9", "x", "", "1,2,3"):
    code, msg = refusal(flow.parse_naxes, bad)
    check(code not in (None, 0) and "--naxes" in msg and "1..8" in msg,
          f"--naxes {bad!r}: exit {code}, message {msg!r}")

# The Fmax goal's verdict: seed 1 alone, or every seed `seeds` placed.
g = {"goals": {"fmax_mhz_min": 150}, "fits": True, "fmax_mhz": 150.5}
check(flow.goal_status(g)["fmax"] == "met", "one seed at the goal: met")
check(flow.goal_status({**g, "fmax_mhz": 149.9})["fmax"] == "not met", "one seed below: not met")
check(flow.goal_status({**g, "fmax_seeds": {"1": 150.5, "2": 139.7, "3": 150.4}})["fmax"] ==
      "not met (2 of 3 seeds)", "a seed below the goal: not met, with the count")
check(flow.goal_status({**g, "fmax_seeds": {"1": 150.5, "2": 151.0}})["fmax"] ==
      "met (2 of 2 seeds)", "every seed at the goal: met")
check(flow.goal_status({**g, "fits": False})["fmax"] == "not met", "does not fit: not met")

for f in fails:
    print("FAIL:", f)
print(f"synth_pnr_options: {'FAILED' if fails else 'ok'} ({len(fails)} failures)")
sys.exit(1 if fails else 0)
