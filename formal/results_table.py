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
    ("STEP pulse exactly max(step_high,1) cycles high, then at least max(step_low,1) low", "hexstep_pulse (engine: at the pins)", "pulse:prove pulse:prove_wide engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("DIR changes >= dir_setup edges before and >= dir_hold edges after a STEP rise, never at one", "hexstep_pulse (engine: at the pins)", "pulse:prove pulse:prove_wide engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("STEP rises exactly when a step is owed, no abort, low time and DIR setup over, DIR at target; DIR moves exactly when the hold is over", "hexstep_pulse", "pulse:prove pulse:prove_wide"),
    ("position +-1 by DIR per rise; accepts_o/pending_o = waiting steps; DIR target", "hexstep_pulse", "pulse:prove pulse:prove_wide"),
    ("B4: no ack without cyc & stb; never two acks in a row; no ack before the initialization", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("ack latency <= 106 cycles (CMD.push; + 32*NAXES+5 for a request during the initialization)", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("read-back under byte enables and implemented bits: staging and pulse configuration words, IRQ_ENABLE; ID, VERSION", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("live pulse configuration = written value from the edge of its mirror write", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("START/STOP strobes = written masks; abort_o = ABORT mask of the last edge or e-stop latch; push only at a CMD.push ack", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("E-STOP: pin high at edge E -> abort_o (all axes) after E+2; latched until 1 written to GSTATUS.estop; GSTATUS", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("IRQ_PENDING set by done/freed/error events, cleared only by write-1, set wins; irq_o = registered pending & enable", "hexstep_wb", "wb:prove wb:prove_wide"),
    ("parent context: the SPI bridge holds its request until ack (the master rule hexstep_wb_fv assumes)", "hexstep_spi_wb + hexstep_wb", "spi_wb:prove"),
    ("no STEP rise while the engine is not busy (nor before the first step can be due)", "hexstep_engine + hexstep_pulse", "engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("at most N step requests per move (none for a refused or empty one); STEP rises <= sum of N of the moves taken", "hexstep_engine + hexstep_pulse", "engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("busy falls only after the N-th step and with every queued move taken (without STOP/abort); a jog ends only by STOP or abort", "hexstep_engine + hexstep_pulse", "engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("refused and empty moves consumed without motion, moves and jogs started; refused_o exactly for a refused move", "hexstep_engine + hexstep_pulse", "engine:bmc_cnt engine:bmc_cons"),
    ("STOP: no move leaves the queue from 42 cycles after the strobe", "hexstep_engine + hexstep_pulse", "engine:bmc engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("STOP: every stopping tick after the first takes exactly dec off the speed; no tick of the move after the one whose old speed is below dec", "hexstep_engine", "engine:bmc engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("abort: no STEP rise at or after the abort edge; STEP low within max(step_high,1) cycles; busy low after it", "hexstep_engine + hexstep_pulse", "engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("child contract asserted: request only with accepts_o, due 1..127 ahead and in order; DIR target changes only with nothing pending", "hexstep_engine", "engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("child assumptions of hexstep_wb_fv asserted: act, qn in 0..2; engine writes only per-axis state words", "hexstep_engine", "engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("speed read by every tick <= v_max and, unless stopping, >= min(v_start, floor)", "hexstep_engine", "engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop engine:bmc_cnt engine:bmc_cons"),
    ("cover: DIR reversal between pulses at programmed timing", "hexstep_pulse", "pulse:cover"),
    ("cover: partial byte-enable write read back; configuration word read back; e-stop cleared; IRQ cleared", "hexstep_wb", "wb:cover"),
    ("cover: complete triangular move", "hexstep_engine + hexstep_pulse", "engine:cover_tri"),
    ("cover: complete trapezoidal move", "hexstep_engine + hexstep_pulse", "engine:cover_trap"),
    ("cover: chained pair (reversing direction), both complete", "hexstep_engine + hexstep_pulse", "engine:cover_chain"),
    ("cover: STOP brings a move to rest before its N-th step", "hexstep_engine + hexstep_pulse", "engine:cover_stop"),
]

# Widths of the harness parameter defaults (the tasks without chparam).
DEFAULT_WIDTHS = {
    "pulse": "PULSE_W 3 POS_W 4",
    "wb": "NAXES 1 ACC_W 12 STEP_W 6 DFRAC_W 8 PULSE_W 4 POS_W 8 ADDR_W 12",
    "spi_wb": "bridge ADDR_W 12; wb: NAXES 1 ACC_W 12 STEP_W 6 DFRAC_W 8 PULSE_W 4 POS_W 8",
    "engine": "NAXES 1 (engine: 64-bit speed, 32-bit words); pulse PULSE_W 2 POS_W 6",
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
    for mod in ("pulse", "wb", "spi_wb", "engine"):
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
