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
     "fall = step_q && cso_q;", "fall = step_q && (cso_q || cs_q == 2);", "pulse", "prove"),
    ("pulse ends one cycle early (default widths)", "hexstep_pulse.v",
     "fall = step_q && cso_q;", "fall = step_q && (cso_q || cs_q == 2);", "pulse", "prove_wide"),
    ("DIR change ignores the hold time", "hexstep_pulse.v",
     "dir_change = (dir_q != tgt_q) && (cdo_q || !md_q);", "dir_change = (dir_q != tgt_q);",
     "pulse", "prove"),
    ("rise at an abort edge", "hexstep_pulse.v",
     "rise = !abort_i && rz_q;", "rise = rz_q;", "pulse", "prove"),
    ("rise ignores the DIR setup time", "hexstep_pulse.v",
     "&& (dir_change ? over_i[2] : (cdo_q || cd_q == T_TWO || md_q));", "&& 1'b1;", "pulse",
     "prove"),
    ("accepts a fourth waiting step", "hexstep_pulse.v",
     "assign accepts_n_o = rst_i | (wait_d != 2'd3);", "assign accepts_n_o = 1'b1;", "pulse",
     "prove"),
    ("held request acked twice", "hexstep_wb.v",
     "wire        take  = wb_cyc_i & wb_stb_i & ~ack_q & idle & ~cap_q;",
     "wire        take  = wb_cyc_i & wb_stb_i & idle & ~cap_q;", "wb", "prove"),
    ("byte enable 1 ignored by a staging write", "hexstep_wb.v",
     "{8{osel_q[1]}}, {8{osel_q[0]}}};", "{8{1'b1}}, {8{osel_q[0]}}};", "wb", "prove"),
    ("byte enable 1 ignored (default widths)", "hexstep_wb.v",
     "{8{osel_q[1]}}, {8{osel_q[0]}}};", "{8{1'b1}}, {8{osel_q[0]}}};", "wb", "prove_wide"),
    ("write keeps reserved bits", "hexstep_wb.v",
     "wire [31:0] mg = ((rdq & ~osel_mask) | (odat_q & osel_mask)) & mw_mask;",
     "wire [31:0] mg = ((rdq & ~osel_mask) | (odat_q & osel_mask));", "wb", "prove"),
    ("e-stop cleared by writing 0", "hexstep_wb.v",
     "rq_gw_q[G_GSTATUS[2:0]] & wdat[0]));", "rq_gw_q[G_GSTATUS[2:0]]));", "wb", "prove"),
    ("e-stop does not abort the engine", "hexstep_wb.v",
     "abort_q <= abort_cmd_d | {NAXES{estop_d}};",
     "abort_q <= abort_cmd_d;", "wb", "prove"),
    ("CMD.push acked one loader step late", "hexstep_wb.v",
     "if (ocnt_q == LOADER_STEPS) begin", "if (ocnt_q == LOADER_STEPS + 6'd1) begin", "wb", "prove"),
    ("SPI bridge issues a read while a request waits", "hexstep_spi_wb.v",
     "if (r_valid && !cyc_q) begin", "if (r_valid) begin", "spi_wb", "prove"),
    ("speed not clamped at v_max", "hexstep_engine.v",
     "PH_ACCEL: begin c_sell1 = ct1_q; c_sell0 = 1'b1; end",
     "PH_ACCEL: begin c_sell1 = 1'b0; c_sell0 = 1'b0; end", "engine", "bmc"),
    ("move never ends at its N-th step", "hexstep_engine.v",
     "c_cnt_end = ~p2_fl[F_JOG] & zre_q;", "c_cnt_end = 1'b0;", "engine", "bmc_tri"),
    ("chained reversal while steps are pending", "hexstep_engine.v",
     "wire       n_dir_ok = hf[F_BAD] | hf[F_EMPTY] | (hf[F_DIR] == tgt[ga]) | ~pending_n[ga];",
     "wire       n_dir_ok = 1'b1;", "engine", "bmc_chain"),
    ("busy falls while steps are pending", "hexstep_engine.v",
     "assign busy8[gk] = run_q[gk] | chain_q[gk] | starting_q[gk] | pending[gk];",
     "assign busy8[gk] = run_q[gk] | chain_q[gk] | starting_q[gk];", "engine", "bmc_tri"),
    ("abort keeps the owed steps", "hexstep_pulse.v",
     "      owed_d = 2'd0;", "      owed_d = owed_q;", "engine", "bmc_abort"),
    ("stopping floors the speed instead of taking dec off", "hexstep_engine.v",
     "PH_DECEL: begin c_sell1 = ~p2_stop; c_sell0 = ~p2_stop &",
     "PH_DECEL: begin c_sell1 = 1'b1; c_sell0 = p2_stop |", "engine",
     "bmc_stop"),
    ("STOP leaves the queue and the chain", "hexstep_engine.v",
     "if (sfs_q[k]) begin", "if (sfs_q[k] && 1'b0) begin", "engine", "bmc_cnt"),
    ("refused move started", "hexstep_engine.v",
     "wire       c_consume = p2_start & (p2_fl[F_BAD] | p2_fl[F_EMPTY]);",
     "wire       c_consume = p2_start & p2_fl[F_EMPTY];", "engine", "bmc_cons"),
    ("jog ends at its step count", "hexstep_engine.v",
     "c_cnt_end = ~p2_fl[F_JOG] & zre_q;", "c_cnt_end = zre_q;", "engine", "bmc_cnt"),
    ("loader step decode one step off", "hexstep_wb.v",
     "lz1_q <= (lnx == 6'd0);", "lz1_q <= (lnx == 6'd1);", "wb", "prove"),
    ("entry's registered due compare one cycle late", "hexstep_pulse.v",
     "m1_d = (t1_q == gn_i);", "m1_d = (t1_q == gn_i + 7'd1);", "pulse", "prove"),
    ("chained start does not pop the queue", "hexstep_engine.v",
     "sst_q[ga] <= n_ss & (n_sn | n_sc);", "sst_q[ga] <= n_ss & n_sn;", "engine", "bmc_chain"),
    ("zero flag enabled in idle", "hexstep_wb.v",
     "else if (ldc_ld) lzs_q <= ld_zf(lnx);", "else if (ldc_ld) lzs_q <= ld_zf(lnx) | {{(LZ_W-1){1'b0}}, idle};",
     "wb", "prove"),
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
        # A mutant is killed by a counterexample or a failed induction (FAIL/UNKNOWN), not by a
        # tool error (ERROR: the mutated RTL did not even elaborate).
        out = r.stdout.strip()
        killed = r.returncode != 0 and (" FAIL " in out + " " or " UNKNOWN " in out + " ")
        verdict = "killed" if killed else ("ERROR" if r.returncode != 0 else "SURVIVED")
        if not killed:
            bad = 1
        print("mutant %02d %-45s %s:%s %s (%s)" % (i, name, mod, task, verdict, out))
        sys.stdout.flush()
    sys.exit(bad)


if __name__ == "__main__":
    main()
