#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# hexstep.core (FuseSoC CAPI2) parses, names the core, lists every target, and each target sets
# up an EDA project (edalize writes its files and copies every listed source: a missing file or a
# bad tool option fails here); the lint and sim targets run. Usage: check_fusesoc.sh REPO_ROOT WORK_DIR
set -euo pipefail
root=$1 work=$2
fusesoc=$root/.venv/bin/fusesoc
core=hexstep:hexstep:hexstep
rm -rf "$work" && mkdir -p "$work"
info=$("$fusesoc" --cores-root "$root" core-info "$core")
grep -q "^Name: *$core:1.0.0" <<<"$info" || { echo "core-info does not name $core:"; echo "$info"; exit 1; }
for t in default lint sim icebreaker ulx3s colorlight_i5; do
  grep -q "^$t *:" <<<"$info" || { echo "target $t missing from core-info"; exit 1; }
  [ "$t" = default ] && continue   # the file list other cores depend on: no tool to set up
  "$fusesoc" --cores-root "$root" run --setup --build-root "$work/$t" --target "$t" "$core" \
    > "$work/$t.log" 2>&1 || { cat "$work/$t.log"; echo "fusesoc setup of target $t failed"; exit 1; }
  ls "$work/$t"/*/*/*.eda.yml > /dev/null || { echo "no EDA project for target $t"; exit 1; }
done
# The ECP5 board targets pass the options of synth/targets.json's ECP5 targets (nowidelut,
# tmg_ripup): the set-up's Yosys script and Makefile carry them.
for t in ulx3s colorlight_i5; do
  grep -rq -- "-nowidelut" "$work/$t" || { echo "target $t: synth_ecp5 without -nowidelut"; exit 1; }
  grep -rq -- "--tmg-ripup" "$work/$t" || { echo "target $t: nextpnr without --tmg-ripup"; exit 1; }
done
# The lint target runs for real (Verilator -Wall through edalize), and so does the sim target
# (Verilator, then synth/fusesoc_sim_main.cpp reads ID and VERSION through the SPI bridge).
"$fusesoc" --cores-root "$root" run --build-root "$work/lint-run" --target lint "$core" \
  > "$work/lint-run.log" 2>&1 || { cat "$work/lint-run.log"; echo "fusesoc lint failed"; exit 1; }
"$fusesoc" --cores-root "$root" run --build-root "$work/sim-run" --target sim "$core" \
  > "$work/sim-run.log" 2>&1 || { cat "$work/sim-run.log"; echo "fusesoc sim failed"; exit 1; }
grep -q "^PASS: " "$work/sim-run.log" || { cat "$work/sim-run.log"; echo "fusesoc sim: no PASS"; exit 1; }
echo "hexstep.core: core-info, lint and sim runs, setup of 5 tool targets OK"
