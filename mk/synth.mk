# SPDX-License-Identifier: Apache-2.0
# Synthesis (synth/, docs/SYNTH.md): Yosys + nextpnr + packers from the project's .venv.
#   make synth                  every target of synth/targets.json (out-of-context rows and board
#                               bitstreams), then the table: synth/results/summary.md (printed)
#                               and docs/SYNTH.md; one JSON per target in synth/results/
#   make synth-<target>         one target (e.g. make synth-ulx3s), results as above
#   make synth-modules          iCE40 cells of hexstep_top per module (synth_ice40 -noflatten)
#                               at six axes, and the cost of one axis (one and six axes)
# Builds go to $(BUILD)/synth-out/<target>/ (bitstreams: <target>.bin / .bit there). An
# out-of-context row that does not fit is reported as such; a board that does not fit or misses
# its core clock, or any Yosys warning not in synth/yosys_waivers.txt on a board, fails the job
# after the remaining targets have run. `make test` runs the bounded slice: ctest label `tool`
# (synth/CMakeLists.txt).
# SoC board builds (soc/boards/, targets soc_*): PicoRV32 + firmware + hexstep_top; the firmware
# image is $(BUILD)/soc/hexstep_fw.hex from the firmware build (built first). They need the C++
# build for the firmware, so they are not part of `make synth` (about four minutes each):
# make synth-soc_icebreaker, make synth-soc_ulx3s, or make synth-soc for both and the table.
SYNTH_FLOW    := $(VENV)/bin/python3 synth/flow.py
SYNTH_TARGETS := ooc_hx8k ooc_up5k ooc_ecp5_25f ooc_ecp5_85f icebreaker ulx3s colorlight_i5
SYNTH_SOC_TARGETS := soc_icebreaker soc_ulx3s
SYNTH_OUT     := $(BUILD)/synth-out
SOC_FW_HEX    := $(BUILD)/soc/hexstep_fw.hex

.PHONY: synth synth-soc synth-modules soc-fw $(addprefix synth-,$(SYNTH_TARGETS) $(SYNTH_SOC_TARGETS))

synth: deps
	@r=0; for t in $(SYNTH_TARGETS); do \
	  $(SYNTH_FLOW) build $$t --out $(SYNTH_OUT) || r=1; \
	done; \
	$(SYNTH_FLOW) summary --doc docs/SYNTH.md || r=1; \
	exit $$r

$(addprefix synth-,$(SYNTH_TARGETS)): synth-%: deps
	$(SYNTH_FLOW) build $* --out $(SYNTH_OUT)

soc-fw: deps $(BUILD)/build.ninja
	cmake --build $(BUILD) --target hexstep_fw

$(addprefix synth-,$(SYNTH_SOC_TARGETS)): synth-%: soc-fw
	$(SYNTH_FLOW) build $* --out $(SYNTH_OUT) --firmware $(SOC_FW_HEX)

synth-soc: soc-fw
	@r=0; for t in $(SYNTH_SOC_TARGETS); do \
	  $(SYNTH_FLOW) build $$t --out $(SYNTH_OUT) --firmware $(SOC_FW_HEX) || r=1; \
	done; \
	$(SYNTH_FLOW) summary --doc docs/SYNTH.md || r=1; \
	exit $$r

synth-modules: deps
	$(SYNTH_FLOW) modules --naxes 1,6 --out $(SYNTH_OUT)
