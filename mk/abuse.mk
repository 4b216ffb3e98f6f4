# SPDX-License-Identifier: Apache-2.0
# Abuse jobs (docs/TESTING.md): the C++ under ASan+UBSan, libFuzzer targets, the long soak.
#   make test-sanitize          build $(BUILD)-fuzz (clang, ASan+UBSan, libFuzzer coverage
#                               instrumentation, without the Verilated RTL: model, planner, CLI,
#                               job files, bench harness, fuzz corpus replay) and run ctest
#                               there; part of `make test`. One build serves the sanitizer tests
#                               and the fuzz targets (two separate builds did not fit the budget)
#   make test-sanitize-rtl      the same with the Verilated RTL and the co-simulation harness
#                               ($(BUILD)-san-rtl; too slow to build for `make test` on 2 cores)
#   make fuzz FUZZ_SECONDS=N    build the fuzz targets in $(BUILD)-fuzz, run each N seconds
#   make soak SOAK_MOVES=N      N random moves through RTL and model, two processes (log below)
# `make test` runs test-sanitize and fuzz-short (each target FUZZ_SHORT_SECONDS); the soak's
# slice in `make test` is ctest Cosim.RandomJobs2000Moves (and soak.slice).
SAN_RTL_BUILD := $(BUILD)-san-rtl
FUZZ_BUILD    := $(BUILD)-fuzz
FUZZ_DIR      := $(abspath $(FUZZ_BUILD))
FUZZ_TARGETS  := job json cli planner
FUZZ_SECONDS  ?= 60
FUZZ_SHORT_SECONDS ?= 12
# Long co-simulation tests under the sanitizers: fewer moves/cycles (tests/rtl/test_cosim.cpp).
SAN_COSIM_ENV := COSIM_MOVES=336 COSIM_CYCLES=300000 SOAK_SLICE_MOVES=42
SAN_ENV       := ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
SOAK_MOVES    ?= 100000
ifeq ($(origin SOAK_SEED),undefined)
SOAK_SEED     := $(shell date +%s)
endif
SOAK_LOG      := $(BUILD)/soak.log
FUZZ_CC       ?= clang-14
FUZZ_CXX      ?= clang++-14

.PHONY: test-sanitize test-sanitize-rtl fuzz fuzz-build fuzz-short soak

test: test-sanitize fuzz-short

$(SAN_RTL_BUILD)/build.ninja:
	cmake -S . -B $(SAN_RTL_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHEXSTEP_SANITIZE=ON

# ctest label `tool`: synthesis/formal scripts, not C++ under test.
test-sanitize: deps $(FUZZ_BUILD)/build.ninja
	cmake --build $(FUZZ_BUILD) -j $(JOBS)
	cd $(FUZZ_BUILD) && $(SAN_ENV) ctest --output-on-failure -j $(JOBS) -LE tool

test-sanitize-rtl: deps $(SAN_RTL_BUILD)/build.ninja
	cmake --build $(SAN_RTL_BUILD) -j $(JOBS)
	cd $(SAN_RTL_BUILD) && $(SAN_COSIM_ENV) $(SAN_ENV) ctest --output-on-failure -j $(JOBS) -LE tool

$(FUZZ_BUILD)/build.ninja:
	CC=$(FUZZ_CC) CXX=$(FUZZ_CXX) cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DHEXSTEP_RTL=OFF -DHEXSTEP_FUZZ=ON -DHEXSTEP_SANITIZE=ON -DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link

fuzz-build: deps $(FUZZ_BUILD)/build.ninja
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_TARGETS))

# Each target runs $(1) seconds from its seed corpus (fuzz/corpus/<t>, read only); new inputs
# go to $(FUZZ_BUILD)/corpus/<t>, crashes to $(FUZZ_BUILD)/crash-<t>-*. Any crash, timeout (10 s
# per input), sanitizer report or failed oracle stops the job with a non-zero status. Absolute
# paths: fuzz_cli works in a temporary directory of its own.
define run_fuzz
	@set -e; for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$t; \
	  echo "fuzz: $$t for $(1) s"; \
	  $(SAN_ENV) $(FUZZ_DIR)/fuzz/fuzz_$$t -max_total_time=$(1) -timeout=10 -max_len=8192 $(2) \
	    -print_final_stats=1 -artifact_prefix=$(FUZZ_DIR)/crash-$$t- $(FUZZ_DIR)/corpus/$$t $(CURDIR)/fuzz/corpus/$$t \
	    > $(FUZZ_BUILD)/fuzz_$$t.log 2>&1 || { tail -n 60 $(FUZZ_BUILD)/fuzz_$$t.log; exit 1; }; \
	  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" $(FUZZ_BUILD)/fuzz_$$t.log | tr '\n' ' '; echo; \
	done
endef

fuzz: fuzz-build
	$(call run_fuzz,$(FUZZ_SECONDS))

# The slice in `make test` uses a fixed seed: a slower machine runs a prefix of the same inputs,
# so a passing slice does not turn red by chance (`make fuzz` explores with fresh seeds).
fuzz-short: fuzz-build
	$(call run_fuzz,$(FUZZ_SHORT_SECONDS),-seed=1)

# Two processes (one per core) with seeds S and S+1; every job's seed is in $(SOAK_LOG) with
# the one command that replays it.
soak: build
	@echo "soak: $(SOAK_MOVES) moves, seeds $(SOAK_SEED) and $$(($(SOAK_SEED)+1)), log $(SOAK_LOG)"
	@: > $(SOAK_LOG)
	@$(BUILD)/tests/soak/hexstep_soak --moves $$(($(SOAK_MOVES)/2)) --seed $(SOAK_SEED) --log $(SOAK_LOG).0 & p0=$$!; \
	 $(BUILD)/tests/soak/hexstep_soak --moves $$(($(SOAK_MOVES)-$(SOAK_MOVES)/2)) --seed $$(($(SOAK_SEED)+1)) --log $(SOAK_LOG).1 & p1=$$!; \
	 r=0; wait $$p0 || r=1; wait $$p1 || r=1; cat $(SOAK_LOG).0 $(SOAK_LOG).1 > $(SOAK_LOG); rm -f $(SOAK_LOG).0 $(SOAK_LOG).1; \
	 tail -n 2 $(SOAK_LOG); exit $$r
