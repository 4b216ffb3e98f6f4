#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the results table of docs/FORMAL.md from a `make formal` run.

    formal/results_table.py SUMMARY DOC

SUMMARY: the lines `formal: MODULE TASK STATUS SECONDSs` that formal/run_sby.sh printed.
DOC: the markdown file whose block between `<!-- formal:begin -->` and `<!-- formal:end -->`
is replaced. Method and depth come from the .sby files beside this script; the property list
below says which task proves or covers each property.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# (property, module, tasks) - every property is checked in each listed task.
PROPERTIES = [
    ("STEP pulse exactly max(step_high,1) cycles high, then at least max(step_low,1) low", "hexstep_pulse, hexstep_axis", "pulse:prove pulse:prove_wide axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("DIR changes >= dir_setup edges before and >= dir_hold edges after a STEP rise, never at one", "hexstep_pulse, hexstep_axis", "pulse:prove pulse:prove_wide axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("STEP/DIR timing at the pins of hexstep_top (reset configuration)", "hexstep_top", "top:bmc"),
    ("no rise without an owed step or at an abort edge; rise_o exact", "hexstep_pulse", "pulse:prove pulse:prove_wide"),
    ("pulses in the move's direction; position +-1 per rise", "hexstep_pulse, hexstep_axis", "pulse:prove pulse:prove_wide axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("no STEP pulse while idle (nor at the abort edge)", "hexstep_axis", "axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("never more than N steps per move", "hexstep_axis", "axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("busy falls only after the N-th step (no ABORT/STOP)", "hexstep_axis", "axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("ABORT: busy low and idle at the abort edge, done pulses, no later rise", "hexstep_axis", "axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("done exactly at busy fall or refused/empty start; busy start refused with err", "hexstep_axis", "axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("child assumption asserted: DIR target loads only with nothing owed", "hexstep_axis", "axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("speed <= v_max (when floor <= v_max), >= min(v_start, floor), >= v_start in ACCEL/CRUISE, in [floor, max(v_dec, floor)] in DECEL", "hexstep_axis", "axis:prove axis:prove_stop axis:prove_wide axis:prove_full"),
    ("STOP: speed never grows from the first stopping tick", "hexstep_axis", "axis:prove_stop axis:prove_wide axis:prove_full"),
    ("jog: a jog move ends only by STOP or ABORT", "hexstep_axis", "axis:prove_stop axis:prove_wide axis:prove_full"),
    ("B4: no ack without cyc & stb; ack in the cycle after a request; never two acks in a row", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("read-back under byte enables of every read/write word (staging, pulse config, IRQ_ENABLE); ID", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("abort_o = ABORT mask of the last edge or e-stop latch; stop_o = STOP mask", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("E-STOP: pin high at t -> core abort from t+3 (abort edge = 4th); latched until cleared; GSTATUS", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("start only for START/done, never with abort, stop or e-stop", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("parent context: hexstep_wb never starts a busy axis", "hexstep_top", "top:bmc"),
    ("pins: no STEP rise at the core abort edge, 4 edges after the e-stop pin / 2 after an ABORT request", "hexstep_top", "top:bmc"),
    ("parent context: the SPI bridge holds its request until ack (the master rule hexstep_wb_fv assumes)", "hexstep_spi_wb + hexstep_wb", "spi_wb:prove"),
    ("cover: DIR reversal between pulses at programmed timing", "hexstep_pulse", "pulse:cover"),
    ("cover: complete triangular move, trapezoidal move, chained pair (axis level)", "hexstep_axis", "axis:cover axis:cover_stop"),
    ("cover: STOP before the N-th step; jog move ended by STOP", "hexstep_axis", "axis:cover_stop"),
    ("cover: partial byte-enable write read back; e-stop cleared; STOP strobe", "hexstep_wb", "wb:cover"),
    ("cover: chained pair from the queue; STOP ending a jog move via the bus", "hexstep_top", "top:cover"),
]

# Widths of the harness parameter defaults (the tasks without chparam).
DEFAULT_WIDTHS = {
    "pulse": "PULSE_W 3 POS_W 4",
    "axis": "SPEED_W 8 ACC_W 6 STEP_W 4 DFRAC_W 4 PULSE_W 2 POS_W 4 OWE_W 2",
    "wb": "NAXES 1 SPEED_W 16 ACC_W 12 STEP_W 6 DFRAC_W 8 PULSE_W 4 POS_W 8 ADDR_W 10",
    "top": "NAXES 1 SPEED_W 4 ACC_W 2 STEP_W 2 DFRAC_W 2 PULSE_W 2 POS_W 4",
    "spi_wb": "wb: NAXES 1 SPEED_W 16 ACC_W 12 STEP_W 6 DFRAC_W 8 PULSE_W 4 POS_W 8 ADDR_W 10",
}


def sby_options(mod):
    """{task: (mode, depth, expect, widths)} from formal/hexstep_<mod>.sby."""
    opts = {}
    widths = {}
    with open(os.path.join(HERE, "hexstep_%s.sby" % mod)) as f:
        for line in f:
            m = re.match(r"(\w+): (mode|depth|expect) (\S+)", line.strip())
            if m:
                opts.setdefault(m.group(1), {})[m.group(2)] = m.group(3)
            m = re.match(r"(\w+): chparam (.*) hexstep_\w+_fv", line.strip())
            if m:
                widths[m.group(1)] = " ".join(m.group(2).replace("-set ", "").split())
    return opts, widths


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: results_table.py SUMMARY DOC")
    runs = {}
    with open(sys.argv[1]) as f:
        for line in f:
            p = line.split()
            if len(p) == 5 and p[0] == "formal:":
                runs["%s:%s" % (p[1], p[2])] = (p[3], p[4])
    info = {}
    for mod in ("pulse", "axis", "wb", "top", "spi_wb"):
        opts, widths = sby_options(mod)
        for task, o in opts.items():
            info["%s:%s" % (mod, task)] = (o, widths.get(task, DEFAULT_WIDTHS[mod]))

    def describe(run):
        o, w = info.get(run, ({}, "?"))
        mode = o.get("mode", "?")
        method = {"prove": "k-induction", "bmc": "bounded (BMC)", "cover": "cover"}.get(mode, mode)
        status, secs = runs.get(run, ("not run", "-"))
        if o.get("expect") == "fail" and status == "FAIL":
            status = "FAIL (expected: finding)"
        return method, o.get("depth", "?"), status, secs, w

    out = ["| property | module | task | method | depth | result | runtime |",
           "|---|---|---|---|---|---|---|"]
    for prop, mod, tasks in PROPERTIES:
        for run in tasks.split():
            method, depth, status, secs, _ = describe(run)
            out.append("| %s | %s | `%s` | %s | %s | %s | %s |" % (prop, mod, run, method, depth, status, secs))
    out += ["", "| task | method | depth | widths | result | runtime |", "|---|---|---|---|---|---|"]
    for run in sorted(info):
        method, depth, status, secs, w = describe(run)
        out.append("| `%s` | %s | %s | %s | %s | %s |" % (run, method, depth, w, status, secs))

    with open(sys.argv[2]) as f:
        doc = f.read()
    begin, end = "<!-- formal:begin", "<!-- formal:end -->"
    if begin not in doc or end not in doc:
        sys.exit("results_table.py: %s has no %s ... %s block" % (sys.argv[2], begin, end))
    head = doc[:doc.index(begin)]
    tail = doc[doc.index(end):]
    block = ("<!-- formal:begin (generated by `make formal`; do not edit by hand) -->\n"
             + "\n".join(out) + "\n")
    with open(sys.argv[2], "w") as f:
        f.write(head + block + tail)


if __name__ == "__main__":
    main()
