#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End to end on the simulated SoC: hexstep plan -> hexstep send -> pseudo-terminal -> UART ->
# firmware -> Wishbone -> hexstep core; the STEP/DIR edges recorded by hexstep-soc-sim must equal
# `hexstep simulate --engine model` on the same job, byte for byte.
# usage: soc_e2e.sh HEXSTEP SOC_SIM SOC_FRAMES CASE   (CASE: six | chain | estop | frames | reduced;
#   reduced takes the SoC in the iCEBreaker configuration, hexstep-soc-sim-reduced)
set -euo pipefail
H=$1 SIM=$2 FRAMES=$3 CASE=$4
here=$(cd "$(dirname "$0")" && pwd)
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Expected final positions from the model's CSV (count of dir=1 edges minus dir=0 edges).
positions_of() { awk -F, 'NR > 1 { p[$1] += ($5 == 1) ? 1 : -1; seen[$1] = 1 }
  END { print "axis,position"; for (k = 0; k < 6; ++k) if (k in seen) print k "," p[k] }' "$1"; }

run_job() {  # JOB: send it through the SoC and compare with the model
  local job=$1
  "$H" simulate "$job" --engine model > "$w/model.csv"
  "$SIM" --job "$job" --csv "$w/soc.csv" --max-cycles 40000000 -- \
    "$H" send "$job" --port '{port}' > "$w/send.out" || fail "send exited with status $?"
  cmp "$w/model.csv" "$w/soc.csv" || { diff "$w/model.csv" "$w/soc.csv" | head -5; fail "STEP/DIR edges differ from the model"; }
  positions_of "$w/model.csv" | cmp - "$w/send.out" || { cat "$w/send.out"; fail "final positions printed by send differ"; }
  echo "ok: $(($(wc -l < "$w/soc.csv") - 1)) STEP edges identical to the model; positions: $(tail -n +2 "$w/send.out" | tr '\n' ' ')"
}

case $CASE in
  six)
    "$H" plan --job "$here/six_axis_request.json" --format job --out "$w/job.json"
    run_job "$w/job.json"
    ;;
  chain)
    # Axis 0: 12 chained moves (more than the firmware's 8-move FIFO plus the 2-deep hardware
    # queue: they stream while the axis runs); axis 2: 3 moves with a start/end speed; axis 5: 2.
    i=0
    for s in 300 -250 400 -300 350 -200 300 -400 250 -300 300 -350; do
      i=$((i + 1)); "$H" plan --axis 0 --steps $s --max-speed 20000 --accel 400000 --clock-hz 1000000 \
        --format job --out "$w/a0_$(printf %02d $i).json"
    done
    for s in 500 -200 300; do
      i=$((i + 1)); "$H" plan --axis 2 --steps $s --max-speed 15000 --accel 200000 --start-speed 2000 \
        --clock-hz 1000000 --format job --out "$w/a2_$(printf %02d $i).json"
    done
    for s in -600 600; do
      i=$((i + 1)); "$H" plan --axis 5 --steps $s --max-speed 25000 --accel 300000 --step-high 2 --step-low 3 \
        --clock-hz 1000000 --format job --out "$w/a5_$(printf %02d $i).json"
    done
    python3 "$here/merge_jobs.py" "$w"/a*_*.json > "$w/job.json"
    run_job "$w/job.json"
    ;;
  estop)
    # The e-stop pin rises right after the 300th STEP edge: every edge up to there equals the
    # model, none follows that the model does not have within the documented 4-cycle abort
    # latency, and send reports the e-stop with exit status 7.
    n=300
    "$H" plan --job "$here/six_axis_request.json" --format job --out "$w/job.json"
    "$H" simulate "$w/job.json" --engine model > "$w/model.csv"
    set +e
    "$SIM" --job "$w/job.json" --csv "$w/soc.csv" --estop-after-steps $n --max-cycles 40000000 -- \
      "$H" send "$w/job.json" --port '{port}' > "$w/send.out" 2> "$w/send.err"
    rc=$?
    set -e
    cat "$w/send.err"
    [ $rc -eq 7 ] || fail "send exit status $rc, expected 7"
    grep -q "E-STOP latched" "$w/send.err" || fail "send did not report the e-stop"
    [ ! -s "$w/send.out" ] || fail "send printed positions on stdout after an e-stop"
    got=$(($(wc -l < "$w/soc.csv") - 1))
    head -n $((got + 1)) "$w/model.csv" | cmp - "$w/soc.csv" || fail "edges before the e-stop differ from the model"
    cn=$(awk -F, -v n=$n 'NR == n + 1 { print $3 }' "$w/model.csv")
    allowed=$(awk -F, -v c="$cn" 'NR > 1 && $3 <= c + 4' "$w/model.csv" | wc -l)
    [ "$got" -ge $n ] && [ "$got" -le "$allowed" ] || fail "$got edges; expected $n..$allowed"
    total=$(($(wc -l < "$w/model.csv") - 1))
    echo "ok: e-stop after edge $n (cycle $cn): $got of $total edges, exit 7"
    ;;
  frames)
    "$H" plan --job "$here/six_axis_request.json" --format job --out "$w/job.json"
    # The bad frames make no STEP edge; the only motion is soc_frames' STOP test on axis 4,
    # whose STEP intervals (64 cycles at its constant speed) must grow at the end: the STOP
    # decelerated (2^-21 step/cycle^2 from 1/64 step/cycle: 2^15 cycles, about 256 steps)
    # instead of cutting.
    "$SIM" --job "$w/job.json" --csv "$w/soc.csv" --max-cycles 40000000 -- "$FRAMES" '{port}'
    awk -F, 'NR > 1 && $1 != 4 { bad = 1 } END { exit bad }' "$w/soc.csv" || fail "bad frames caused STEP edges"
    n=$(($(wc -l < "$w/soc.csv") - 1))
    [ "$n" -gt 50 ] || fail "axis 4 made only $n steps before STOP"
    last=$(awk -F, 'NR > 1 { if (prev != "") d = $3 - prev; prev = $3 } END { print d }' "$w/soc.csv")
    [ "$last" -gt 128 ] || fail "last STEP interval $last cycles: STOP did not decelerate"
    echo "ok: no STEP edge from bad frames; STOP: $n steps, last interval $last cycles (cruise 64)"
    ;;
  reduced)
    # The SoC in the iCEBreaker build's configuration (hexstep-soc-sim-reduced: one axis,
    # SPEED_W 24, ACC_W 12, STEP_W 16, DFRAC_W 8, PULSE_W 8, POS_W 16) at its 12 MHz clock:
    # 1. a job planned for those widths runs and its STEP/DIR edges equal the model's at the
    #    same widths (and the positions send prints);
    # 2. the six-axis job is refused before anything is loaded: axis 1 is not on the board;
    # 3. a one-axis job planned for the default widths is refused, naming the widths.
    # Each refusal: exit 7, nothing on stdout, no STEP edge.
    wid=SPEED_W=24,ACC_W=12,STEP_W=16,DFRAC_W=8,PULSE_W=8,POS_W=16
    "$H" plan --axis 0 --steps 1500 --max-speed 1000000 --accel 1e9 --decel 5e8 --start-speed 20000 \
      --step-high 2 --step-low 2 --clock-hz 12000000 --widths $wid --format job --out "$w/a0.json"
    "$H" plan --axis 0 --steps -700 --max-speed 600000 --accel 2e9 --clock-hz 12000000 --widths $wid \
      --step-high 2 --step-low 2 --format job --out "$w/a1.json"
    python3 "$here/merge_jobs.py" "$w/a0.json" "$w/a1.json" > "$w/job.json"
    grep -q '"SPEED_W": 24' "$w/job.json" || fail "the planned job does not record its widths"
    run_job "$w/job.json"
    refused() {  # JOB MESSAGE
      set +e
      "$SIM" --job "$1" --csv "$w/soc.csv" --max-cycles 40000000 -- \
        "$H" send "$1" --port '{port}' > "$w/send.out" 2> "$w/send.err"
      local rc=$?
      set -e
      cat "$w/send.err"
      [ $rc -eq 7 ] || fail "send exit status $rc, expected 7"
      grep -qF "$2" "$w/send.err" || fail "send did not say: $2"
      [ ! -s "$w/send.out" ] || fail "send printed positions for a refused job"
      [ "$(wc -l < "$w/soc.csv")" -eq 1 ] || fail "STEP edges from a refused job"
    }
    "$H" plan --job "$here/six_axis_request.json" --format job --out "$w/six.json"
    refused "$w/six.json" "the job moves axis 1, the board has 1 axis (0)"
    "$H" plan --axis 0 --steps 300 --max-speed 20000 --accel 400000 --clock-hz 12000000 --format job \
      --out "$w/default.json"
    refused "$w/default.json" "the board's core has SPEED_W 24, ACC_W 12, STEP_W 16, DFRAC_W 8, PULSE_W 8"
    echo "ok: reduced-width job equal to the model; six-axis and default-width jobs refused before loading"
    ;;
  *) fail "unknown case $CASE" ;;
esac
