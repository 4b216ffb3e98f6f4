# SPDX-License-Identifier: Apache-2.0
# The SoC (soc/, firmware/soc_*): lint of its RTL with PicoRV32 from the .venv package
# pythondata-cpu-picorv32 (scripts/deps/soc.pip), located at run time, never copied.
# `make demo` ends with the plan -> send -> firmware -> core chain (scripts/demo.sh).
SOC_RTL := soc/hexstep_soc.v soc/hexstep_soc_ram.v soc/hexstep_soc_uart.v
# Board tops of the SoC (soc/boards/hexstep_soc_<board>.v, built by `make synth-soc_<board>`,
# mk/synth.mk): linted with their default parameters too; the ECP5 board's DP16KD block RAM
# (RAM_STYLE "ECP5") against the project's model of it, tests/ram/dp16kd_sim.v (Makefile).
SOC_BOARDS := icebreaker ulx3s
SOC_PICORV32 = $(shell $(VENV)/bin/python -c "import pythondata_cpu_picorv32 as p; print(p.data_location)")/picorv32.v
.PHONY: soc-lint

soc-lint: deps
	verilator --lint-only -Wall --timescale 1ns/1ps -Irtl soc/hexstep_soc_waiver.vlt rtl/verilator_waiver.vlt \
	  $(SOC_PICORV32) rtl/hexstep_top.v $(SOC_RTL) --top-module hexstep_soc
	for b in $(SOC_BOARDS); do \
	  g=; case $$b in ulx3s) g=$(DP16KD_SIM);; esac; \
	  verilator --lint-only -Wall --timescale 1ns/1ps -Irtl soc/hexstep_soc_waiver.vlt rtl/verilator_waiver.vlt \
	    $(SOC_PICORV32) rtl/hexstep_top.v $(SOC_RTL) rtl/boards/hexstep_board_reset.v soc/boards/hexstep_soc_board.v \
	    soc/boards/hexstep_soc_$$b.v --top-module hexstep_soc_$$b $$g || exit 1; \
	done

test: soc-lint

# Cell counts of the whole SoC (PicoRV32 + default six-axis hexstep_top + RAM + UART) after
# Yosys synth_ecp5, before place and route: $(BUILD)/soc/stat.txt. Not a board build (those are
# `make synth-soc_icebreaker` / `make synth-soc_ulx3s`, docs/SYNTH.md). Slow: about 15 minutes
# on a busy 2-core machine.
.PHONY: soc-stat
soc-stat: build
	@mkdir -p $(BUILD)/soc
	$(YOSYS) -q -l $(BUILD)/soc/stat.log -p "read_verilog $(SOC_PICORV32) $(RTL) $(SOC_RTL); \
	  chparam -set INIT_FILE \"$(CURDIR)/$(BUILD)/soc/hexstep_fw.hex\" hexstep_soc; \
	  synth_ecp5 -top hexstep_soc; tee -q -o $(BUILD)/soc/stat.txt stat"
	@grep -A14 '=== hexstep_soc ===' $(BUILD)/soc/stat.txt | grep -E 'cells|LUT4|TRELLIS_FF|DP16KD|CCU2C|DPR16'
