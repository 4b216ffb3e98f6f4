#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# End to end on the simulated SoC: hexstep plan -> hexstep send -> pseudo-terminal -> UART ->
# firmware -> Wishbone -> hexstep core; the STEP/DIR edges recorded by hexstep-soc-sim must equal
# `hexstep simulate --engine model` on the same job: the same edges (axis, step, direction) in
# the same order, every one shifted by the same number of cycles. Both count cycles from their
# own START write, and the core starts every axis at the next frame boundary (32 cycles), so
# the two runs may differ by a constant below 32 cycles and by nothing else: the firmware must
# keep every queue filled so that the chained moves run without a gap.
# usage: soc_e2e.sh HEXSTEP SOC_SIM SOC_FRAMES CASE   (CASE: six | chain | estop | frames | reduced;
#   reduced takes the one-axis SoC of narrower widths, hexstep-soc-sim-reduced)
# The jobs run at 12 MHz: a tick is 32 cycles, and the accelerations of ordinary motors need
# ACC_W 48 bits per tick^2 at that clock (the planner refuses them at 1 MHz).
set -euo pipefail
H=$1 SIM=$2 FRAMES=$3 CASE=$4
here=$(cd "$(dirname "$0")" && pwd)
w=$(mktemp -d)
trap 'rm -rf "$w"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Expected final positions from the model's CSV (count of dir=1 edges minus dir=0 edges).
positions_of() { awk -F, 'NR > 1 { p[$1] += ($5 == 1) ? 1 : -1; seen[$1] = 1 }
  END { print "axis,position"; for (k = 0; k < 6; ++k) if (k in seen) print k "," p[k] }' "$1"; }

# same_edges MODEL SOC [N]: the first N edges (default: all, and both files have the same
# number) agree in axis, step and direction, and the SoC's cycle minus the model's is one
# constant in (-32, 32) for all of them. Prints that offset.
same_edges() {
  local n=${3:-}
  if [ -z "$n" ]; then
    [ "$(wc -l < "$1")" -eq "$(wc -l < "$2")" ] ||
      fail "$(($(wc -l < "$2") - 1)) STEP edges on the SoC, $(($(wc -l < "$1") - 1)) on the model"
    n=$(($(wc -l < "$1") - 1))
  fi
  paste -d, <(tail -n +2 "$1" | head -n "$n") <(tail -n +2 "$2" | head -n "$n") | awk -F, -v n="$n" '
    function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
    NF != 10 { bad("edge " NR ": missing on one side") }
    $1 != $6 || $2 != $7 || $5 != $10 { bad("edge " NR ": model " $1 "," $2 ",dir " $5 ", SoC " $6 "," $7 ",dir " $10) }
    NR == 1 { d = $8 - $3; if (d <= -32 || d >= 32) bad("offset " d " cycles, not within a frame") }
    $8 - $3 != d { bad("edge " NR " (axis " $1 " step " $2 "): model cycle " $3 ", SoC " $8 ": offset " ($8 - $3) ", edge 1 had " d) }
    END { if (failed) exit 1; if (NR != n) { print NR " edges compared, expected " n > "/dev/stderr"; exit 1 } print d }' ||
    fail "STEP/DIR edges differ from the model"
}

run_job() {  # JOB: send it through the SoC and compare with the model
  local job=$1 d
  "$H" simulate "$job" --engine model > "$w/model.csv"
  "$SIM" --job "$job" --csv "$w/soc.csv" --max-cycles 40000000 -- \
    "$H" send "$job" --port '{port}' > "$w/send.out" || fail "send exited with status $?"
  d=$(same_edges "$w/model.csv" "$w/soc.csv")
  positions_of "$w/model.csv" | cmp - "$w/send.out" || { cat "$w/send.out"; fail "final positions printed by send differ"; }
  echo "ok: $(($(wc -l < "$w/soc.csv") - 1)) STEP edges equal to the model's, all $d cycles later; positions: $(tail -n +2 "$w/send.out" | tr '\n' ' ')"
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
      i=$((i + 1)); "$H" plan --axis 0 --steps $s --max-speed 100000 --accel 2000000 --clock-hz 12000000 \
        --format job --out "$w/a0_$(printf %02d $i).json"
    done
    for s in 500 -200 300; do
      i=$((i + 1)); "$H" plan --axis 2 --steps $s --max-speed 75000 --accel 1000000 --start-speed 10000 \
        --clock-hz 12000000 --format job --out "$w/a2_$(printf %02d $i).json"
    done
    for s in -600 600; do
      i=$((i + 1)); "$H" plan --axis 5 --steps $s --max-speed 120000 --accel 1500000 --step-high 2 --step-low 3 \
        --clock-hz 12000000 --format job --out "$w/a5_$(printf %02d $i).json"
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
    [ "$got" -ge $n ] || fail "$got edges before the e-stop, expected at least $n"
    d=$(same_edges "$w/model.csv" "$w/soc.csv" "$got")
    # The abort latency in the model's time: edges up to 4 cycles after its n-th may still come.
    cn=$(awk -F, -v n=$n 'NR == n + 1 { print $3 }' "$w/model.csv")
    allowed=$(awk -F, -v c="$cn" 'NR > 1 && $3 <= c + 4' "$w/model.csv" | wc -l)
    [ "$got" -le "$allowed" ] || fail "$got edges; expected $n..$allowed"
    total=$(($(wc -l < "$w/model.csv") - 1))
    echo "ok: e-stop after edge $n (model cycle $cn, SoC $d cycles later): $got of $total edges, exit 7"
    ;;
  frames)
    "$H" plan --job "$here/six_axis_request.json" --format job --out "$w/job.json"
    # The bad frames make no STEP edge; the only motion is soc_frames' STOP test on axis 4,
    # whose STEP intervals (512 cycles at its constant speed of 1/16 step per tick) must grow
    # at the end: the STOP decelerated (2^-17 step/tick^2: 2^13 ticks, about 256 steps)
    # instead of cutting.
    "$SIM" --job "$w/job.json" --csv "$w/soc.csv" --max-cycles 40000000 -- "$FRAMES" '{port}'
    awk -F, 'NR > 1 && $1 != 4 { bad = 1 } END { exit bad }' "$w/soc.csv" || fail "bad frames caused STEP edges"
    n=$(($(wc -l < "$w/soc.csv") - 1))
    [ "$n" -gt 50 ] || fail "axis 4 made only $n steps before STOP"
    last=$(awk -F, 'NR > 1 { if (prev != "") d = $3 - prev; prev = $3 } END { print d }' "$w/soc.csv")
    [ "$last" -gt 1024 ] || fail "last STEP interval $last cycles: STOP did not decelerate"
    echo "ok: no STEP edge from bad frames; STOP: $n steps, last interval $last cycles (cruise 512)"
    ;;
  reduced)
    # The one-axis SoC of narrower widths (hexstep-soc-sim-reduced: ACC_W 44, STEP_W 16,
    # DFRAC_W 16, PULSE_W 8, POS_W 16; soc/CMakeLists.txt) at 12 MHz:
    # 1. a job planned for those widths runs and its STEP/DIR edges equal the model's at the
    #    same widths (and the positions send prints);
    # 2. the six-axis job is refused before anything is loaded: axis 1 is not on the board;
    # 3. the firmware refuses values one bit wider than these registers (soc_frames);
    # 4. a one-axis job planned for the default widths is refused, naming the widths.
    # Each refusal: exit 7, nothing on stdout, no STEP edge.
    wid=ACC_W=44,STEP_W=16,DFRAC_W=16,PULSE_W=8,POS_W=16
    "$H" plan --axis 0 --steps 150 --max-speed 20000 --accel 120000 --decel 60000 --start-speed 2000 \
      --step-high 2 --step-low 2 --clock-hz 12000000 --widths $wid --format job --out "$w/a0.json"
    "$H" plan --axis 0 --steps -100 --max-speed 15000 --accel 130000 --clock-hz 12000000 --widths $wid \
      --step-high 2 --step-low 2 --format job --out "$w/a1.json"
    python3 "$here/merge_jobs.py" "$w/a0.json" "$w/a1.json" > "$w/job.json"
    grep -q '"ACC_W": 44' "$w/job.json" || fail "the planned job does not record its widths"
    run_job "$w/job.json"
    # The firmware's range checks follow this build's widths (INFO0/INFO1), not the default's.
    "$SIM" --job "$w/job.json" --csv "$w/soc.csv" --max-cycles 40000000 -- "$FRAMES" '{port}' 44 16 16 8
    [ "$(wc -l < "$w/soc.csv")" -eq 1 ] || fail "STEP edges from the range checks"
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
    "$H" plan --axis 0 --steps 300 --max-speed 20000 --accel 100000 --clock-hz 12000000 --format job \
      --out "$w/default.json"
    refused "$w/default.json" "the board's core has SPEED_W 64, ACC_W 44, STEP_W 16, DFRAC_W 16, PULSE_W 8"
    echo "ok: reduced-width job equal to the model; its range checks; six-axis and default-width jobs refused before loading"
    ;;
  *) fail "unknown case $CASE" ;;
esac
