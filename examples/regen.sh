#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Writes the example jobs from their planning requests (requests/*.json), so that their register
# values are the planner's for the core's units (2^-64 step per tick of 32 clock cycles, ...)
# and can be made again whenever the units or the encoder change:
#   examples/regen.sh [HEXSTEP]      (default: build/cli/hexstep)
# six_axis.json is one request for all six axes plus a second move of axis 1 back in the other
# direction (requests/six_axis_axis1_back.json): a job file runs several moves per axis, a
# planning request plans one.
set -euo pipefail
cd "$(dirname "$0")"
HEXSTEP=${1:-../build/cli/hexstep}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$HEXSTEP" plan --job requests/single_move.json --format job --out "$tmp/single_move.json"
"$HEXSTEP" plan --job requests/six_axis.json --format job --out "$tmp/six.json"
"$HEXSTEP" plan --job requests/six_axis_axis1_back.json --format job --out "$tmp/back.json"
# Python's json keeps integers exact and, with indent=2, prints the canonical layout of
# write_job (docs/FORMATS.md, "Canonical form").
python3 - "$tmp/six.json" "$tmp/back.json" "$tmp/six_axis.json" <<'PY'
import json, sys
job = json.load(open(sys.argv[1]))
back = json.load(open(sys.argv[2]))
axis1 = next(a for a in job["axes"] if a["axis"] == 1)
axis1["moves"] += back["axes"][0]["moves"]
with open(sys.argv[3], "w") as f:
    f.write(json.dumps(job, indent=2) + "\n")
PY
"$HEXSTEP" simulate "$tmp/six_axis.json" --event-mode --summary >/dev/null  # reads back
mv "$tmp/single_move.json" single_move.json
mv "$tmp/six_axis.json" six_axis.json
echo "wrote examples/single_move.json and examples/six_axis.json"
