#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Concatenates the moves of several `hexstep plan --format job` outputs into one job (axis by
# axis, in the order given): a chained multi-move job. Pulse settings and clock must agree.
import json
import sys

out = None
for path in sys.argv[1:]:
    with open(path) as f:
        job = json.load(f)
    if out is None:
        out = {k: v for k, v in job.items() if k != "axes"}
        out["axes"] = []
    if job["clock_hz"] != out["clock_hz"]:
        sys.exit(f"merge_jobs: {path}: clock_hz differs")
    for ax in job["axes"]:
        mine = next((a for a in out["axes"] if a["axis"] == ax["axis"]), None)
        if mine is None:
            out["axes"].append(ax)
        else:
            if mine.get("pulse") != ax.get("pulse"):
                sys.exit(f"merge_jobs: {path}: axis {ax['axis']}: pulse differs")
            mine["moves"].extend(ax["moves"])
out["axes"].sort(key=lambda a: a["axis"])
json.dump(out, sys.stdout, indent=2)
sys.stdout.write("\n")
