#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# hexstep: regenerates every file derived from the register map rdl/hexstep.rdl.
# Usage: scripts/gen_regs.sh [OUTDIR]   (default: the repository, as `make regs` does)
# Writes OUTDIR/firmware/hexstep_regs.h (PeakRDL-cheader), OUTDIR/docs/REGISTERS.md
# (PeakRDL-markdown) and OUTDIR/sim/hexstep_regs.hpp (scripts/gen_regs_hpp.py).
# The regs_up_to_date test runs it into a temp dir and diffs against the committed files.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-.}"
py=.venv/bin/python
peakrdl=.venv/bin/peakrdl
mkdir -p "$out/firmware" "$out/docs" "$out/sim"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$peakrdl" c-header rdl/hexstep.rdl -o "$tmp/hexstep_regs.h"
{ echo "// Generated from rdl/hexstep.rdl by \`make regs\` (scripts/gen_regs.sh). Do not edit."
  cat "$tmp/hexstep_regs.h"; } > "$out/firmware/hexstep_regs.h"

"$peakrdl" markdown rdl/hexstep.rdl -o "$tmp/REGISTERS.md"
{ echo "<!-- Generated from rdl/hexstep.rdl by \`make regs\` (scripts/gen_regs.sh). Do not edit. -->"
  echo
  echo "# hexstep registers"
  echo
  echo "Wishbone B4 classic slave, 32-bit data, byte addresses; every request is acked once, one"
  echo "cycle after it is presented (registered ack); there is no err and no stall signal."
  echo "Unmapped addresses read 0. See rtl/hexstep_wb.v for the bus and queue behaviour."
  echo
  cat "$tmp/REGISTERS.md"; } > "$out/docs/REGISTERS.md"

"$py" scripts/gen_regs_hpp.py rdl/hexstep.rdl "$out/sim/hexstep_regs.hpp"
