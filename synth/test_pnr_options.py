#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ctest synth_pnr_options: the nextpnr options of synth/targets.json as flow.py passes them.
Every target's options are accepted; the ECP5 targets run with --tmg-ripup and the iCE40
ones without it (docs/SYNTH.md: it raised the 25F's ten-seed median and changed no iCE40
result); a value outside the accepted set stops the build with an error that names the
target, the field and the accepted values, before any tool runs."""
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

check(flow.pnr_options("x", {"tmg_ripup": False}) == ([], {"tmg_ripup": False}),
      "tmg_ripup false adds no argument")
check(flow.pnr_options("x", {"router": "router2", "tmg_ripup": True})[0] ==
      ["--router", "router2", "--tmg-ripup"], "router and ripup arguments in order")

for bad, field, accepted in [({"tmg_ripup": "yes"}, "tmg_ripup", "true or false"),
                             ({"tmg_ripup": 1}, "tmg_ripup", "true or false"),
                             ({"router": "router3"}, "router", "router1 or router2")]:
    err = io.StringIO()
    code = None
    with contextlib.redirect_stderr(err):
        try:
            flow.pnr_options("bad_target", bad)
        except SystemExit as e:
            code = e.code
    msg = err.getvalue()
    check(code not in (None, 0), f"{bad}: exit code {code}, expected non-zero")
    check("bad_target" in msg and field in msg and accepted in msg,
          f"{bad}: message {msg!r} does not name the target, {field} and '{accepted}'")

for f in fails:
    print("FAIL:", f)
print(f"synth_pnr_options: {'FAILED' if fails else 'ok'} ({len(fails)} failures)")
sys.exit(1 if fails else 0)
