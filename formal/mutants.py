#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that the formal properties can fail: each mutant is a one-line bug put into a copy
of rtl/, and the named task must then fail (a counterexample or an induction failure).

    formal/mutants.py WORKDIR [N ...]  (make formal-mutants runs all; N: only mutant N)

Prints one line per mutant and exits non-zero if a mutant survives (its task passes) or its
pattern is no longer in the RTL (update the list then).
"""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# (name, rtl file, original text, mutated text, module, task)
MUTANTS = [
    ("pulse ends one cycle early", "hexstep_pulse.v",
     "fall = step_q && (c_q >= hi_x);", "fall = step_q && (c_q >= hi_x - 1);", "pulse", "prove"),
    ("pulse ends one cycle early (default widths)", "hexstep_pulse.v",
     "fall = step_q && (c_q >= hi_x);", "fall = step_q && (c_q >= hi_x - 1);", "pulse", "prove_wide"),
    ("DIR change ignores the hold time", "hexstep_pulse.v",
     "dir_change = (dir_q != tgt_q) && (c_q >= hold_x);", "dir_change = (dir_q != tgt_q);",
     "pulse", "prove"),
    ("rise at an abort edge", "hexstep_pulse.v",
     "rise = !abort_i && owed_nz_i", "rise = owed_nz_i", "axis", "prove"),
    ("move ends one step late", "hexstep_axis.v",
     "cnt_end = !jog_q && (cnt_inc == steps_q);", "cnt_end = !jog_q && (cnt_inc == steps_q + 1);",
     "axis", "prove"),
    ("move ends one step late (default widths)", "hexstep_axis.v",
     "cnt_end = !jog_q && (cnt_inc == steps_q);", "cnt_end = !jog_q && (cnt_inc == steps_q + 1);",
     "axis", "prove_full"),
    ("no done pulse after an abort", "hexstep_axis.v",
     "if (busy_now && !busy_nxt) begin", "if (busy_now && !busy_nxt && !abort_i) begin",
     "axis", "prove"),
    ("held request acked twice", "hexstep_wb.v",
     "wire        req   = wb_cyc_i & wb_stb_i & ~ack_q;", "wire        req   = wb_cyc_i & wb_stb_i;",
     "wb", "prove"),
    ("byte enable 1 ignored", "hexstep_wb.v",
     "{8{wb_sel_i[1]}}, {8{wb_sel_i[0]}}};", "{8{1'b1}}, {8{wb_sel_i[0]}}};", "wb", "prove"),
    ("byte enable 1 ignored (default widths)", "hexstep_wb.v",
     "{8{wb_sel_i[1]}}, {8{wb_sel_i[0]}}};", "{8{1'b1}}, {8{wb_sel_i[0]}}};", "wb", "prove_wide"),
    ("e-stop cleared by writing 0", "hexstep_wb.v",
     "(widx == G_GSTATUS) & wdat[0]));", "(widx == G_GSTATUS)));", "wb", "prove"),
    ("e-stop does not abort the core", "hexstep_wb.v",
     "wire [NAXES-1:0] abort_w = abort_cmd_q | {NAXES{estop_q}};",
     "wire [NAXES-1:0] abort_w = abort_cmd_q;", "top", "bmc"),
]


def skip_dirs(src, names):
    """copytree filter: leave out directories (sby work directories, caches)."""
    return [n for n in names if os.path.isdir(os.path.join(src, n))]


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: mutants.py WORKDIR [N ...]")
    work = os.path.abspath(sys.argv[1])
    try:
        only = [int(a) for a in sys.argv[2:]]
    except ValueError:
        sys.exit("mutants.py: N must be a mutant number 0..%d" % (len(MUTANTS) - 1))
    if any(n < 0 or n >= len(MUTANTS) for n in only):
        sys.exit("mutants.py: N must be a mutant number 0..%d" % (len(MUTANTS) - 1))
    bad = 0
    for i, (name, fname, old, new, mod, task) in enumerate(MUTANTS):
        if only and i not in only:
            continue
        d = os.path.join(work, "mutant%02d" % i)
        shutil.rmtree(d, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "rtl"), os.path.join(d, "rtl"))
        shutil.copytree(HERE, os.path.join(d, "formal"), ignore=skip_dirs)
        path = os.path.join(d, "rtl", fname)
        with open(path) as f:
            text = f.read()
        if old not in text:
            print("mutant %02d %-45s PATTERN GONE from rtl/%s" % (i, name, fname))
            bad = 1
            continue
        with open(path, "w") as f:
            f.write(text.replace(old, new, 1))
        env = dict(os.environ, VENV=os.environ.get("VENV", os.path.join(ROOT, ".venv")))
        r = subprocess.run([os.path.join(d, "formal", "run_sby.sh"), os.path.join(d, "work"), mod,
                            task], env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                           text=True)
        verdict = "killed" if r.returncode != 0 else "SURVIVED"
        if r.returncode == 0:
            bad = 1
        print("mutant %02d %-45s %s:%s %s (%s)" % (i, name, mod, task, verdict, r.stdout.strip()))
        sys.stdout.flush()
    sys.exit(bad)


if __name__ == "__main__":
    main()
