#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Black-box tests of the `hexstep` command line.
# Usage: cli_test.sh HEXSTEP EXAMPLES_DIR HAVE_RTL(0|1) [CASE...]
# CASE is one of: csv stdin event summary errors timeout rtl help plan_csv plan_c plan_pipe
# plan_line plan_help (default: all). `hexstep plan`'s values and errors: test_plan.cpp.
set -u

HEXSTEP=$1
EXAMPLES=$2
HAVE_RTL=$3
shift 3
CASES=${*:-csv stdin event summary errors timeout rtl help plan_csv plan_c plan_pipe plan_line plan_help}

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
PASS=0
FAIL=0

ok() { PASS=$((PASS + 1)); echo "ok   $*"; }
bad() { FAIL=$((FAIL + 1)); echo "FAIL $*"; }
check() {  # check DESCRIPTION COMMAND...: passes if the command succeeds
  local d=$1
  shift
  if "$@"; then ok "$d"; else bad "$d"; fi
}

# run OUT ARGS...: runs hexstep with stdout in $TMP/OUT.out, stderr in $TMP/OUT.err; sets RC.
run() {
  local o=$1
  shift
  "$HEXSTEP" "$@" >"$TMP/$o.out" 2>"$TMP/$o.err"
  RC=$?
}

# Sum of all "steps" of a job file written with one field per line or inline (not acc_steps).
sum_steps() { grep -o '"steps": *[0-9]*' "$1" | awk -F: '{s += $2} END {print s + 0}'; }

# Checks a CSV: exact header, ordering by (cycle, axis), time_s = cycle / clock_hz exactly,
# dir 0/1, steps counting from 1 within a move, and EXPECTED data lines.
check_csv() {
  local file=$1 expected=$2 clock=$3 what=$4
  check "$what: header" test "$(head -n 1 "$file")" = "axis,step,cycle,time_s,dir"
  check "$what: $expected step lines" test "$(($(wc -l <"$file") - 1))" -eq "$expected"
  check "$what: sorted, well-formed, time_s exact" awk -F, -v hz="$clock" '
    NR == 1 { next }
    NF != 5 || $1 !~ /^[0-5]$/ || $2 !~ /^[1-9][0-9]*$/ || $3 !~ /^[0-9]+$/ || $5 !~ /^[01]$/ { exit 1 }
    NR > 2 && ($3 < pc || ($3 == pc && $1 <= pa)) { exit 1 }
    { t = sprintf("%.8f", $3 / hz); if (hz == 100000000 && t != $4) exit 1 }
    { pc = $3; pa = $1 }
    ' "$file"
}

# A job with one move on each listed axis; writes $TMP/NAME.json, prints nothing.
# make_job NAME MOVE_JSON [AXES...]
make_job() {
  local name=$1 move=$2
  shift 2
  local axes=${*:-0}
  {
    echo '{"format": "hexstep-job", "version": 1, "clock_hz": 100000000, "axes": ['
    local first=1
    for a in $axes; do
      [ $first = 1 ] || echo ','
      first=0
      echo "{\"axis\": $a, \"pulse\": {\"step_high\": 2, \"step_low\": 2}, \"moves\": [$move]}"
    done
    echo ']}'
  } >"$TMP/$name.json"
}
GOOD_MOVE='{"steps": 300, "dir": 0, "v_start": 1152921504606846976, "v_max": 1152921504606846976,
            "v_end": 1152921504606846976, "acc": 0, "dec": 0, "v_dec": 1152921504606846976, "acc_steps": 0, "dec_step": 300, "dec_frac": 0}'

PLAN_CSV_HEADER=axis,profile,dir,total_steps,accel_steps,cruise_steps,decel_steps,start_speed_steps_per_s,peak_speed_steps_per_s,end_speed_steps_per_s,accel_steps_per_s2,decel_steps_per_s2,t_accel_s,t_cruise_s,t_decel_s,duration_s,executed_peak_speed_steps_per_s,executed_duration_s,warning
# A six-axis line request (docs/FORMATS.md, "Planning request"): several units, a zero move.
cat >"$TMP/line6.json" <<'EOF'
{"format": "hexstep-plan-request", "version": 1, "clock_hz": 100000000, "mode": "line",
 "axes": [
  {"axis": 0, "steps": 400, "max_speed": 200000, "accel": 100000000},
  {"axis": 1, "steps": -300, "max_speed": 200000, "accel": 100000000,
   "pulse": {"step_high": 3, "step_low": 3, "dir_setup": 2, "dir_hold": 2}},
  {"axis": 2, "distance": 0.5, "unit": "rev", "steps_per_rev": 400, "max_speed": 500, "accel": 500000},
  {"axis": 3, "distance": -45, "unit": "deg", "steps_per_rev": 800, "max_speed": 90000, "accel": 45000000, "ratio": 2},
  {"axis": 4, "distance": 0.25, "unit": "mm", "steps_per_rev": 400, "pitch_mm": 2, "max_speed": 1000, "accel": 1000000},
  {"axis": 5, "steps": 0, "max_speed": 1000, "accel": 1000}
 ]}
EOF

for c in $CASES; do
  case $c in
  csv)
    for ex in six_axis single_move; do
      run csv_$ex simulate "$EXAMPLES/$ex.json"
      check "csv $ex: exit 0" test "$RC" -eq 0
      check "csv $ex: stderr empty" test ! -s "$TMP/csv_$ex.err"
      check_csv "$TMP/csv_$ex.out" "$(sum_steps "$EXAMPLES/$ex.json")" 100000000 "csv $ex"
    done
    # Generated job: 3 axes x 300 steps, all negative, step index runs 1..300 per axis.
    make_job gen "$GOOD_MOVE" 1 3 5
    run gen simulate "$TMP/gen.json"
    check "csv generated: exit 0" test "$RC" -eq 0
    check_csv "$TMP/gen.out" 900 100000000 "csv generated"
    check "csv generated: per-axis steps 1..300, dir 0" awk -F, '
      NR > 1 { n[$1]++; if ($2 != n[$1] || $5 != 0) exit 1 }
      END { if (n[1] != 300 || n[3] != 300 || n[5] != 300 || length(n) != 3) exit 1 }' "$TMP/gen.out"
    # v = 2^60 is 1/16 step per tick, and a tick is 32 clock cycles: the core crosses a whole
    # step exactly every 16 ticks (no sub-tick offset), so the edges are 512 cycles apart, and
    # the three axes started by one START rise on the same cycles.
    check "csv generated: steps 16 ticks = 512 cycles apart, axes in step" awk -F, '
      NR > 1 { if ($1 in last && $3 - last[$1] != 512) exit 1; last[$1] = $3; c[$2] = c[$2] "," $3 }
      END { for (k in c) { split(substr(c[k], 2), v, ","); if (v[1] != v[2] || v[2] != v[3]) exit 1 } }' "$TMP/gen.out"
    # A clock that does not divide a power of ten: time_s still identifies the cycle.
    sed 's/"clock_hz": 100000000/"clock_hz": 3000000/' "$TMP/gen.json" >"$TMP/clk.json"
    run clk simulate "$TMP/clk.json"
    check "csv 3 MHz: exit 0" test "$RC" -eq 0
    check "csv 3 MHz: round(time_s * clock_hz) == cycle, 7 decimals" awk -F, '
      NR > 1 { split($4, t, "."); if (int($4 * 3000000 + 0.5) != $3 || length(t[2]) != 7) exit 1 }' "$TMP/clk.out"
    ;;
  stdin)
    run s_file simulate "$EXAMPLES/six_axis.json"
    "$HEXSTEP" simulate - <"$EXAMPLES/six_axis.json" >"$TMP/s_in.out" 2>"$TMP/s_in.err"
    check "stdin: exit 0" test $? -eq 0
    check "stdin: '-' gives the same output as the file" cmp -s "$TMP/s_file.out" "$TMP/s_in.out"
    ;;
  event)
    for ex in six_axis single_move; do
      run ev_cyc simulate "$EXAMPLES/$ex.json" --engine model
      run ev_evt simulate "$EXAMPLES/$ex.json" --engine model --event-mode
      check "event $ex: exit 0" test "$RC" -eq 0
      check "event $ex: --event-mode output identical" cmp -s "$TMP/ev_cyc.out" "$TMP/ev_evt.out"
      run ev_sc simulate "$EXAMPLES/$ex.json" --summary
      run ev_se simulate "$EXAMPLES/$ex.json" --summary --event-mode
      check "event $ex: --event-mode summary identical" cmp -s "$TMP/ev_sc.out" "$TMP/ev_se.out"
    done
    ;;
  summary)
    run sum simulate "$EXAMPLES/six_axis.json" --summary
    check "summary: exit 0" test "$RC" -eq 0
    check "summary: table header" grep -q 'axis.*moves.*steps.*position.*last step cycle.*duration s' "$TMP/sum.out"
    check "summary: six axis rows" test "$(grep -cE '^ +[0-5] +[0-9]+ +[0-9]+ +-?[0-9]+ +[0-9]+ +[0-9.]+$' "$TMP/sum.out")" -eq 6
    check "summary: total steps" test "$(awk '$1 ~ /^[0-5]$/ {s += $3} END {print s}' "$TMP/sum.out")" -eq "$(sum_steps "$EXAMPLES/six_axis.json")"
    check "summary: no CSV" test "$(grep -c 'axis,step' "$TMP/sum.out")" -eq 0
    ;;
  errors)
    # expect_error NAME FIELD_TEXT JOB_FILE [ARGS...]: exit 2, empty stdout, one stderr line
    # starting "hexstep: error:" that contains FIELD_TEXT.
    expect_error() {
      local name=$1 text=$2 job=$3 f0=$FAIL
      shift 3
      run "e_$name" simulate "$job" "$@"
      check "error $name: exit 2" test "$RC" -eq 2
      check "error $name: stdout empty" test ! -s "$TMP/e_$name.out"
      check "error $name: one stderr line" test "$(wc -l <"$TMP/e_$name.err")" -eq 1
      check "error $name: 'hexstep: error:' prefix" grep -q '^hexstep: error: ' "$TMP/e_$name.err"
      check "error $name: names '$text'" grep -qF -- "$text" "$TMP/e_$name.err"
      [ "$FAIL" -eq "$f0" ] || sed 's/^/    stderr: /' "$TMP/e_$name.err"
    }
    printf '{"format": "hexstep-job", "version": 1,\n "axes": [ }' >"$TMP/badjson.json"
    expect_error badjson "malformed JSON at byte" "$TMP/badjson.json"
    make_job missing '{"steps": 300, "dir": 0, "v_start": 1, "v_max": 1, "v_end": 1, "acc": 0, "dec": 0, "v_dec": 1, "acc_steps": 0, "dec_frac": 0}' 2
    expect_error missing "axes[0].moves[0].dec_step: required field is missing; it must be an integer in [0, 4294967295]" "$TMP/missing.json"
    # ACC_W = 48: acc holds [0, 2^48 - 1].
    make_job range "$(echo "$GOOD_MOVE" | sed 's/"acc": 0/"acc": 281474976710656/')" 0 4
    expect_error range "axes[0].moves[0].acc: must be an integer in [0, 281474976710655] (ACC_W = 48 bits)" "$TMP/range.json"
    # SPEED_W is 64 in every build.
    sed 's/"clock_hz": 100000000,/"clock_hz": 100000000, "widths": {"SPEED_W": 48},/' "$TMP/range.json" >"$TMP/speedw.json"
    expect_error speedw "widths.SPEED_W: must be an integer in [64, 64] bits, got 48" "$TMP/speedw.json"
    sed 's/"clock_hz": 100000000,/"clock_hz": 100000000, "widths": {"OWE_W": 2},/' "$TMP/range.json" >"$TMP/owew.json"
    expect_error owew "widths.OWE_W: unknown field" "$TMP/owew.json"
    make_job refused "$(echo "$GOOD_MOVE" | sed 's/"v_start": 1152921504606846976/"v_start": 1152921504606846977/')" 1 2
    expect_error refused "axes[0].moves[0].v_start: must be <= v_max" "$TMP/refused.json"
    make_job unknown "$(echo "$GOOD_MOVE" | sed 's/"dec_frac"/"decfrac"/')" 3
    expect_error unknown "axes[0].moves[0].decfrac: unknown field" "$TMP/unknown.json"
    make_job dupaxis "$GOOD_MOVE" 2 2
    expect_error dupaxis "axes[1].axis: must be an integer in [0, 5] and unique" "$TMP/dupaxis.json"
    expect_error nofile "cannot open" "$TMP/does_not_exist.json"
    expect_error badflag "--max-cycles" "$EXAMPLES/six_axis.json" --max-cycles -5
    expect_error badengine "--engine" "$EXAMPLES/six_axis.json" --engine vhdl
    run e_stdin_empty simulate - </dev/null
    check "error empty stdin: exit 2 and no stdout" test "$RC" -eq 2 -a ! -s "$TMP/e_stdin_empty.out"
    ;;
  timeout)
    for mode in "" --event-mode; do
      run to simulate "$EXAMPLES/six_axis.json" --max-cycles 1000 $mode
      check "timeout $mode: exit 4" test "$RC" -eq 4
      check "timeout $mode: stdout empty" test ! -s "$TMP/to.out"
      check "timeout $mode: message" grep -q '^hexstep: error: .*--max-cycles' "$TMP/to.err"
    done
    # Exactly enough cycles passes; one fewer times out.
    run full simulate "$EXAMPLES/single_move.json" --summary
    n=$(sed -n 's/^run: \([0-9]*\) cycles.*/\1/p' "$TMP/full.out")
    run exact simulate "$EXAMPLES/single_move.json" --max-cycles "$n"
    check "timeout: --max-cycles = run length ($n) succeeds" test "$RC" -eq 0
    run short simulate "$EXAMPLES/single_move.json" --max-cycles "$((n - 1))"
    check "timeout: --max-cycles = run length - 1 fails" test "$RC" -eq 4
    ;;
  rtl)
    if [ "$HAVE_RTL" = 1 ]; then
      make_job gen "$GOOD_MOVE" 0 1 2 3 4 5
      for job in "$EXAMPLES/six_axis.json" "$EXAMPLES/single_move.json" "$TMP/gen.json"; do
        run r_model simulate "$job" --engine model
        run r_model_s simulate "$job" --engine model --summary
        # A diverging RTL must fail fast rather than run for the default 10^10 cycles.
        limit=$(($(sed -n 's/^run: \([0-9]*\) cycles.*/\1/p' "$TMP/r_model_s.out") * 2 + 1000))
        run r_rtl simulate "$job" --engine rtl --max-cycles "$limit"
        check "rtl $(basename "$job"): exit 0" test "$RC" -eq 0
        check "rtl $(basename "$job"): output identical to model" cmp -s "$TMP/r_model.out" "$TMP/r_rtl.out"
        run r_rtl_s simulate "$job" --engine rtl --summary --max-cycles "$limit"
        check "rtl $(basename "$job"): summary identical apart from the engine name" \
          cmp -s <(sed 1d "$TMP/r_model_s.out") <(sed 1d "$TMP/r_rtl_s.out")
      done
    else
      run r_none simulate "$EXAMPLES/six_axis.json" --engine rtl
      check "rtl not built: exit 2" test "$RC" -eq 2
      check "rtl not built: stdout empty" test ! -s "$TMP/r_none.out"
      check "rtl not built: message" grep -q '^hexstep: error: --engine rtl' "$TMP/r_none.err"
    fi
    ;;
  help)
    run h --help
    check "help: exit 0" test "$RC" -eq 0
    check "help: lists simulate" grep -q simulate "$TMP/h.out"
    check "help: exit statuses" grep -q 'Exit status' "$TMP/h.out"
    check "help: exit status 3 = infeasible time budget" grep -q '3 (plan) the --time budget' "$TMP/h.out"
    check "help: exit status 5 = move refused by the core" grep -q '5 (simulate) the core refused' "$TMP/h.out"
    run hs simulate --help
    check "simulate --help: exit 0" test "$RC" -eq 0
    for flag in --engine --event-mode --max-cycles --summary --trace JOB.json; do
      check "simulate --help: explains $flag" grep -q -- "$flag" "$TMP/hs.out"
    done
    check "simulate --help: CSV header" grep -q 'axis,step,cycle,time_s,dir' "$TMP/hs.out"
    run hn
    check "no subcommand: exit 2" test "$RC" -eq 2
    ;;
  plan_csv)
    # One line per axis under the documented header; total_steps signed.
    run pc plan --steps -700 --max-speed 5000 --accel 100000 --axis 2 --format csv
    check "plan csv: exit 0" test "$RC" -eq 0
    check "plan csv: header" test "$(head -n 1 "$TMP/pc.out")" = "$PLAN_CSV_HEADER"
    check "plan csv: one data line" test "$(wc -l <"$TMP/pc.out")" -eq 2
    check "plan csv: 19 columns, axis 2, dir 0, total -700, counts sum to 700" awk -F, '
      NR == 2 { if (NF != 19 || $1 != 2 || $3 != 0 || $4 != -700 || $5 + $6 + $7 != 700) exit 1 }' "$TMP/pc.out"
    run pcl plan --job "$TMP/line6.json" --format csv
    check "plan csv line: exit 0" test "$RC" -eq 0
    check "plan csv line: six data lines, axes 0..5" test "$(awk -F, 'NR > 1 {printf "%s", $1}' "$TMP/pcl.out")" = "012345"
    ;;
  plan_c)
    # The header compiles as C99 with every warning an error, alone and used, one axis and six.
    CC_BIN=${CC:-cc}
    if ! command -v "$CC_BIN" >/dev/null; then
      bad "plan c: no C compiler ($CC_BIN)"
      continue
    fi
    run ph plan --steps -700 --max-speed 5000 --accel 100000 --axis 3 --step-high 4 --format c --out "$TMP/plan1.h"
    check "plan c: exit 0, nothing on stdout" test "$RC" -eq 0 -a ! -s "$TMP/ph.out"
    run ph6 plan --job "$TMP/line6.json" --format c --out "$TMP/plan6.h"
    check "plan c line: exit 0" test "$RC" -eq 0
    for h in plan1 plan6; do
      check "plan c $h: include guard" grep -q '^#ifndef HEXSTEP_PLAN_H' "$TMP/$h.h"
      check "plan c $h: stdint.h" grep -q '^#include <stdint.h>' "$TMP/$h.h"
      check "plan c $h: clock macro" grep -q '^#define HEXSTEP_PLAN_CLOCK_HZ UINT64_C(100000000)' "$TMP/$h.h"
      printf '#include "%s.h"\n' "$h" >"$TMP/${h}_only.c"
      check "plan c $h: compiles alone (cc -std=c99 -Wall -Werror)" \
        "$CC_BIN" -std=c99 -Wall -Werror -c "$TMP/${h}_only.c" -o "$TMP/${h}_only.o"
      cat >"$TMP/${h}_use.c" <<EOF
#include "$h.h"
#include "$h.h"
uint64_t total_steps(void);
uint64_t total_steps(void) {
  uint64_t n = 0;
  unsigned i;
  for (i = 0; i < HEXSTEP_PLAN_NUM_AXES; ++i)
    n += hexstep_plan_moves[i].steps + hexstep_plan_moves[i].v_max * 0u + hexstep_plan_pulse[i].step_high * 0u;
  return n + HEXSTEP_PLAN_CLOCK_HZ * 0u + HEXSTEP_PLAN_AXIS_MASK * 0u;
}
EOF
      check "plan c $h: compiles when used (cc -std=c99 -Wall -Wextra -pedantic -Werror)" \
        "$CC_BIN" -std=c99 -Wall -Wextra -pedantic -Werror -c "$TMP/${h}_use.c" -o "$TMP/${h}_use.o"
    done
    check "plan c: axis 3 row is 700 steps, dir 0" grep -q '^  {700u, 0u, UINT64_C(' "$TMP/plan1.h"
    check "plan c: axis mask 0x08" grep -q '^#define HEXSTEP_PLAN_AXIS_MASK 0x08u' "$TMP/plan1.h"
    check "plan c: pulse row of axis 3" grep -q '^  {4u, 1u, 0u, 0u, 0u, 0u}, /\* axis 3 \*/' "$TMP/plan1.h"
    check "plan c line: axis mask 0x3F" grep -q '^#define HEXSTEP_PLAN_AXIS_MASK 0x3Fu' "$TMP/plan6.h"
    ;;
  plan_pipe)
    # hexstep plan ... --format job | hexstep simulate -: exactly |total| steps, all in the
    # planned direction on the planned axis, ending at the planned signed position; on the model
    # and (if built) the RTL, with identical output.
    engines=model
    [ "$HAVE_RTL" = 1 ] && engines="model rtl"
    for move in "--steps -300 --max-speed 200000 --accel 1e8" \
                "--distance 0.75 --unit rev --steps-per-rev 400 --max-speed 400 --accel 200000 --step-high 3 --step-low 2 --dir-setup 2 --dir-hold 1 --axis 4" \
                "--distance -2.5 --unit mm --steps-per-mm 80 --max-speed 1000 --accel 1e6 --start-speed 50 --axis 1" \
                "--steps 250 --max-speed 100000 --accel 1e9 --time 0.004 --axis 5"; do
      # shellcheck disable=SC2086
      run pj plan $move
      total=$(grep -o '"total": *-\{0,1\}[0-9]*' "$TMP/pj.out" | sed 's/.*: *//')
      axis=$(grep -o '"axis": *[0-9]' "$TMP/pj.out" | head -n 1 | sed 's/.*: *//')
      abs=${total#-}
      dir=1
      [ "$total" -lt 0 ] && dir=0
      for eng in $engines; do
        # shellcheck disable=SC2086
        "$HEXSTEP" plan $move --format job 2>"$TMP/pp.err" | "$HEXSTEP" simulate - --engine "$eng" >"$TMP/pp_$eng.out" 2>>"$TMP/pp.err"
        check "plan pipe $eng [$move]: exit 0" test $? -eq 0 -a ! -s "$TMP/pp.err"
        check_csv "$TMP/pp_$eng.out" "$abs" 100000000 "plan pipe $eng [$move]"
        check "plan pipe $eng [$move]: axis $axis, dir $dir" awk -F, -v a="$axis" -v d="$dir" \
          'NR > 1 && ($1 != a || $5 != d) { exit 1 }' "$TMP/pp_$eng.out"
        # shellcheck disable=SC2086
        "$HEXSTEP" plan $move --format job | "$HEXSTEP" simulate - --engine "$eng" --summary >"$TMP/ps_$eng.out"
        pos=$(awk -v a="$axis" '$1 == a {print $4}' "$TMP/ps_$eng.out")
        check "plan pipe $eng [$move]: final position $pos == planned total $total" test "$pos" = "$total"
      done
      [ "$HAVE_RTL" = 1 ] && check "plan pipe [$move]: rtl output identical to model" cmp -s "$TMP/pp_model.out" "$TMP/pp_rtl.out"
    done
    ;;
  plan_line)
    # A six-axis line from a request file: every axis ends at its planned position, and all
    # moving axes finish together (last STEP edges within 1 % of the run).
    run pl plan --job "$TMP/line6.json" --format csv
    check "plan line: exit 0" test "$RC" -eq 0
    engines=model
    [ "$HAVE_RTL" = 1 ] && engines="model rtl"
    for eng in $engines; do
      "$HEXSTEP" plan --job "$TMP/line6.json" --format job | "$HEXSTEP" simulate - --engine "$eng" --summary >"$TMP/pls.out"
      check "plan line $eng: exit 0" test $? -eq 0
      check "plan line $eng: positions equal the planned totals" awk -F, '
        FNR == NR { if (FNR > 1) want[$1] = $4; next }
        $1 ~ /^[0-5]$/ { seen++; if ($4 != want[$1]) exit 1 }
        END { if (seen != 6) exit 1 }' "$TMP/pl.out" <(sed 's/^ *//; s/  */,/g' "$TMP/pls.out")
      check "plan line $eng: axes finish together" awk '
        $1 ~ /^[0-4]$/ { c = $5; if (n == 0 || c < lo) lo = c; if (n == 0 || c > hi) hi = c; n++ }
        END { if (n != 5 || hi - lo > hi / 100) exit 1 }' "$TMP/pls.out"
    done
    ;;
  plan_help)
    run ph plan --help
    check "plan --help: exit 0" test "$RC" -eq 0
    for flag in --steps --distance --unit --steps-per-rev --steps-per-mm --pitch-mm --start-speed \
                --end-speed --max-speed --accel --decel --ratio --time --clock-hz --axis --job \
                --format --out --step-high --step-low --dir-setup --dir-hold 'UNIT/s^2' 'clock cycles'; do
      check "plan --help: explains $flag" grep -qF -- "$flag" "$TMP/ph.out"
    done
    check "plan --help: CSV header" grep -qF "$PLAN_CSV_HEADER" "$TMP/ph.out"
    # Exit statuses and the empty output of the two plan error classes (details: test_plan.cpp).
    run pe plan --steps 100 --max-speed -1 --accel 1000
    check "plan error: exit 2, stdout empty, names --max-speed" \
      test "$RC" -eq 2 -a ! -s "$TMP/pe.out" -a "$(grep -c '^hexstep: error: --max-speed: ' "$TMP/pe.err")" -eq 1
    run pi plan --steps 3000 --max-speed 1000 --accel 1000 --time 3.9 --out "$TMP/pi.json"
    check "plan infeasible: exit 3, nothing written, names --time and the minimum" \
      test "$RC" -eq 3 -a ! -s "$TMP/pi.out" -a ! -e "$TMP/pi.json" -a "$(grep -c '^hexstep: error: --time: .*minimum achievable time 4 s' "$TMP/pi.err")" -eq 1
    ;;
  *)
    bad "unknown case $c"
    ;;
  esac
done

echo "$PASS passed, $FAIL failed"
[ "$FAIL" -eq 0 ]
