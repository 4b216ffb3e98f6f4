#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# ctest soak.slice: a short soak, a fresh seed each run unless $SEED is set, $SOAK_SLICE_MOVES
# moves (default 168: one job of 28 moves per axis; fewer moves make a smaller job).
# Usage: slice.sh PATH/TO/hexstep_soak
set -eu
seed=${SEED:-$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')}
moves=${SOAK_SLICE_MOVES:-168}
per=28
if [ "$moves" -lt 168 ]; then per=$(( (moves + 5) / 6 )); fi
echo "soak slice: seed $seed, $moves moves (rerun: SEED=$seed SOAK_SLICE_MOVES=$moves ctest -R soak.slice)"
exec "$1" --moves "$moves" --seed "$seed" --moves-per-axis "$per"
