#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# hexstep: regenerates every file derived from the register map rdl/hexstep.rdl.
# Usage: scripts/gen_regs.sh [OUTDIR]   (default: the repository, as `make regs` does)
# Writes OUTDIR/firmware/hexstep_regs.h (PeakRDL-cheader), OUTDIR/docs/REGISTERS.md
# (PeakRDL-markdown) and OUTDIR/cpp_model/include/hexstep/regs.hpp (scripts/gen_regs_hpp.py).
# The regs_up_to_date test runs it into a temp dir and diffs against the committed files.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-.}"
py=.venv/bin/python
peakrdl=.venv/bin/peakrdl
mkdir -p "$out/firmware" "$out/docs" "$out/cpp_model/include/hexstep"
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
  # The bus paragraph of the rdl's header comment (from "// Bus:" to the end of the comment),
  # so that the ack times are written in one place.
  sed -n '/^\/\/ Bus:/,/^[^/]/p' rdl/hexstep.rdl | sed -n 's|^// \{0,1\}||p'
  echo "See docs/ARCHITECTURE.md (\"Bus interface\", \"Moves, queue and chaining\") for the bus"
  echo "and queue behaviour."
  echo
  cat "$tmp/REGISTERS.md"; } > "$out/docs/REGISTERS.md"

"$py" scripts/gen_regs_hpp.py rdl/hexstep.rdl "$out/cpp_model/include/hexstep/regs.hpp"
