# SPDX-License-Identifier: Apache-2.0
# `make bench`: accuracy suite (bench_accuracy), throughput (bench_throughput, Google Benchmark,
# medians of BENCH_REPS repetitions), then bench/report.py writes bench/results/summary.md,
# summary.json, the PNG plots and the README's performance section (docs/BENCH.md).
# The bounded slice is the ctest `bench_check` (bench/CMakeLists.txt), run by `make test`.
BENCH_OUT     ?= bench/results
BENCH_THREADS ?= 2
BENCH_REPS    ?= 5

.PHONY: bench
bench: deps $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS) --target bench_accuracy bench_throughput
	@mkdir -p $(BENCH_OUT)
	$(BUILD)/bench/bench_accuracy --out $(BENCH_OUT) --threads $(BENCH_THREADS)
	$(BUILD)/bench/bench_throughput --benchmark_repetitions=$(BENCH_REPS) \
	  --benchmark_report_aggregates_only=true --benchmark_out_format=json \
	  --benchmark_out=$(BENCH_OUT)/throughput.json
	$(VENV)/bin/python bench/report.py --results $(BENCH_OUT) --readme README.md
