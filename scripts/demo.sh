#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# make demo: a six-axis job on the golden model and on the Verilated RTL, side by side.
set -euo pipefail
cd "$(dirname "$0")/.."
HEXSTEP=${1:-build/cli/hexstep}
JOB=examples/six_axis.json
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "== hexstep demo: $JOB (six axes, one START write) =="
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

echo
echo "== From physical limits: hexstep plan | hexstep simulate =="
echo "8 mm on an 8 mm lead screw, 400 steps/rev, 50 mm/s, 500 mm/s^2, 12 MHz core clock"
echo "(by hand: 400 steps, 125 up at 25,000 steps/s^2 in 0.1 s, 150 at 2,500 steps/s, 125 down: 0.26 s):"
"$HEXSTEP" plan --distance 8 --unit mm --pitch-mm 8 --steps-per-rev 400 --max-speed 50 \
  --accel 500 --clock-hz 12000000 --format job > "$out/plan.json"
"$HEXSTEP" simulate "$out/plan.json" --engine model --summary
"$HEXSTEP" simulate "$out/plan.json" --engine model > "$out/pm.csv"
"$HEXSTEP" simulate "$out/plan.json" --engine rtl > "$out/pr.csv"
if cmp -s "$out/pm.csv" "$out/pr.csv"; then
  echo "RTL == model on the planned move ($(($(wc -l < "$out/pr.csv") - 1)) STEP edges)."
else
  echo "MISMATCH between RTL and model on the planned move" >&2
  exit 1
fi

SOCSIM=$(dirname "$HEXSTEP")/../soc/hexstep-soc-sim
if [ -x "$SOCSIM" ]; then
  echo
  echo "== The whole chain on the simulated SoC (soc/, firmware/soc_main.c, docs/PROTOCOL.md) =="
  echo "hexstep plan -> hexstep send --port <pseudo-terminal> -> UART -> PicoRV32 firmware -> Wishbone -> core"
  "$HEXSTEP" plan --job tests/soc/six_axis_request.json --format job --out "$out/soc_job.json"
  "$SOCSIM" --job "$out/soc_job.json" --csv "$out/soc.csv" -- "$HEXSTEP" send "$out/soc_job.json" --port '{port}'
  "$HEXSTEP" simulate "$out/soc_job.json" --engine model > "$out/soc_model.csv"
  # Both count cycles from their own START write and START acts at the next frame boundary,
  # so the SoC's edges must be the model's shifted by one constant below one frame (32 cycles).
  if [ "$(wc -l < "$out/soc_model.csv")" -eq "$(wc -l < "$out/soc.csv")" ] &&
     d=$(paste -d, <(tail -n +2 "$out/soc_model.csv") <(tail -n +2 "$out/soc.csv") | awk -F, '
       $1 != $6 || $2 != $7 || $5 != $10 { exit 1 }
       NR == 1 { d = $8 - $3; if (d <= -32 || d >= 32) exit 1 }
       $8 - $3 != d { exit 1 }
       END { print d }'); then
    echo "SoC == model: all $(($(wc -l < "$out/soc.csv") - 1)) STEP edges sent through the firmware, the same edges in the same order, every one shifted by the same $d cycles (START acts at a frame boundary)."
  else
    echo "MISMATCH between the SoC run and the model" >&2
    exit 1
  fi
fi
