#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# make demo: a six-axis job on the golden model and on the Verilated RTL, side by side.
set -euo pipefail
cd "$(dirname "$0")/.."
HEXSTEP=${1:-build/cli/hexstep}
JOB=examples/six_axis.json
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "== hexstep demo: $JOB (six axes, one start strobe) =="
echo
echo "-- golden C++ model (event mode) --"
"$HEXSTEP" simulate "$JOB" --engine model --event-mode --summary
echo
echo "-- Verilated RTL (cycle by cycle) --"
"$HEXSTEP" simulate "$JOB" --engine rtl --summary
echo
"$HEXSTEP" simulate "$JOB" --engine model > "$out/model.csv"
"$HEXSTEP" simulate "$JOB" --engine rtl > "$out/rtl.csv"
steps=$(($(wc -l < "$out/model.csv") - 1))
if cmp -s "$out/model.csv" "$out/rtl.csv"; then
  echo "RTL == model: all $steps STEP edges at identical cycles (CSV files identical)."
  echo "First lines of the CSV (hexstep simulate $JOB --engine rtl):"
  head -n 6 "$out/rtl.csv"
else
  echo "MISMATCH between RTL and model:" >&2
  diff "$out/model.csv" "$out/rtl.csv" | head -20 >&2
  exit 1
fi
