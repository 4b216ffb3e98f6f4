#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""hexstep bench report: accuracy.json + throughput.json (+ synth/results/summary.md) ->
bench/results/summary.md, summary.json, PNG plots, and the README section between
<!-- bench:begin ...--> and <!-- bench:end -->. Every number comes from those files."""
import argparse
import datetime
import json
import math
import os
import re
import subprocess
import sys

ALGO_TITLES = {
    "hexstep": "hexstep (frame engine; golden model = RTL)",
    "hexstep_regs": "hexstep vs its register profile",
    "avr446": "AVR446 / Austin (integer timer)",
    "stoychitch": "Stoychitch time-per-step (eq. 11-14)",
    "spt_10khz": "steps-per-time, float, 10 kHz ISR",
    "dda_1khz": "hostmot2-style DDA, 1 kHz servo",
}
COMPARED = ["avr446", "stoychitch", "spt_10khz", "dda_1khz"]


def fail(msg):
    print("bench/report.py: " + msg, file=sys.stderr)
    sys.exit(1)


def load(path, what):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(f"cannot read {what} {path}: {e}")


def fmt(x, digits=3):
    if x is None:
        return "-"
    if isinstance(x, str):
        return x
    if x == 0:
        return "0"
    if math.isinf(x):
        return "inf"
    if abs(x) >= 1e5 or abs(x) < 1e-3:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}"


def rel_speed(v):
    return math.inf if v == "inf" else v


def aggregate(moves, algo):
    """Metrics of one algorithm over a set of moves, and hexstep's over the same moves."""
    inc = [m for m in moves if m["algo"][algo]["included"]]
    out = {"moves": len(inc), "excluded": len(moves) - len(inc)}
    if not inc:
        return out
    a = [m["algo"][algo] for m in inc]
    h = [m["algo"]["hexstep"] for m in inc]
    clocks = {m["clock_hz"] for m in inc}
    n = sum(x["n"] for x in a)
    worst = max(inc, key=lambda m: m["algo"][algo]["max_err_s"])
    out.update({
        "steps": n,
        "clock_hz": clocks.pop() if len(clocks) == 1 else None,
        "max_err_us": max(x["max_err_s"] for x in a) * 1e6,
        "max_err_cycles": max(m["algo"][algo]["max_err_s"] * m["clock_hz"] for m in inc),
        "rms_err_us": math.sqrt(sum(x["sum_sq_s2"] for x in a) / n) * 1e6 if n else 0.0,
        "max_pos_err_steps": max(x["max_pos_err"] for x in a),
        "max_excess_steps": max(x["max_excess"] for x in a),
        "max_ratio": max(x["max_ratio"] for x in a),
        "max_abs_final_err": max(abs(x["final_err"]) for x in a),
        "unfinished": sum(1 for x in a if not x["finished"]),
        "max_abs_duration_err_us": max((abs(x["duration_err_s"]) for x in a if x["pulses"] == m_n(x)), default=0.0) * 1e6,
        "max_rel_speed_err": max(rel_speed(x["max_rel_speed"]) for x in a),
        "worst_move": worst["id"],
        "hexstep_max_err_us": max(x["max_err_s"] for x in h) * 1e6,
        "hexstep_max_excess_steps": max(x["max_excess"] for x in h),
    })
    if out["clock_hz"]:
        out["rms_err_cycles"] = out["rms_err_us"] * 1e-6 * out["clock_hz"]
    out["ratio_err_to_hexstep"] = out["max_err_us"] / out["hexstep_max_err_us"] if out["hexstep_max_err_us"] else None
    out["ratio_excess_to_hexstep"] = (out["max_excess_steps"] / out["hexstep_max_excess_steps"]
                                      if out["hexstep_max_excess_steps"] else None)
    return out


def m_n(x):
    return x["pulses"] if x["finished"] and x["final_err"] == 0 else -1


def accuracy_tables(acc):
    moves = acc["moves"]
    ranges = []
    for m in moves:
        if m["range"] not in ranges:
            ranges.append(m["range"])
    overall = {a: aggregate(moves, a) for a in acc["algorithms"]}
    per_range = {r: {a: aggregate([m for m in moves if m["range"] == r], a) for a in acc["algorithms"]} for r in ranges}
    exclusions = {}
    for a in acc["algorithms"]:
        reasons = {}
        for m in moves:
            x = m["algo"][a]
            if not x["included"]:
                reasons[x["reason"]] = reasons.get(x["reason"], 0) + 1
        exclusions[a] = reasons
    return overall, per_range, ranges, exclusions


def throughput_medians(tp):
    med = {}
    for b in tp.get("benchmarks", []):
        if b.get("aggregate_name") != "median":
            continue
        name = b["run_name"].split("/")[0]
        med[name] = b
    def c(name, key):
        b = med.get(name)
        return b.get(key) if b else None
    r = {
        "model_cycle_axis_cycles_per_s": c("BM_ModelCycleMode", "axis_cycles_per_s"),
        "model_cycle_steps_per_s": c("BM_ModelCycleMode", "steps_per_s"),
        "model_event_steps_per_s": c("BM_ModelEventMode", "steps_per_s"),
        "model_event_long_slow_steps_per_s": c("BM_ModelEventModeLongSlow", "steps_per_s"),
        "cosim_cycles_per_s": c("BM_CosimRtl", "cycles_per_s"),
        "cosim_with_model_cycles_per_s": c("BM_CosimRtlWithModel", "cycles_per_s"),
        "plan_single_per_s": c("BM_PlanSingle", "plans_per_s"),
        "plan_six_axis_line_per_s": c("BM_PlanSixAxisLine", "plans_per_s"),
        "repetitions": next((b.get("repetitions") for b in tp.get("benchmarks", []) if "repetitions" in b), None),
    }
    if r["model_event_steps_per_s"] and r["model_cycle_steps_per_s"]:
        r["event_over_cycle"] = r["model_event_steps_per_s"] / r["model_cycle_steps_per_s"]
    if r["cosim_cycles_per_s"] and r["cosim_with_model_cycles_per_s"]:
        r["cosim_model_slowdown"] = r["cosim_cycles_per_s"] / r["cosim_with_model_cycles_per_s"]
    r["context"] = {k: tp.get("context", {}).get(k) for k in ("date", "host_name", "num_cpus", "mhz_per_cpu", "library_build_type")}
    return r


def targets(overall, tp):
    h, hr = overall["hexstep"], overall["hexstep_regs"]
    others = {a: overall[a].get("max_excess_steps") for a in COMPARED if overall[a]["moves"]}
    below_all = all(h["max_excess_steps"] < v for v in others.values())
    t = [
        {"target": "every step within 2/f_clk + 0.001/v_ideal of the planner's real-valued profile (worst error/allowance <= 1)",
         "value": h["max_ratio"], "met": h["max_ratio"] <= 1.0},
        {"target": "same, against the profile the registers describe (the core's own guarantee)",
         "value": hr["max_ratio"], "met": hr["max_ratio"] <= 1.0},
        {"target": "hexstep worst excess error < 0.001 step (planner profile)",
         "value": h["max_excess_steps"], "met": h["max_excess_steps"] < 0.001},
        {"target": "hexstep worst excess error below every other algorithm's worst (measured: the smallest of their worst)",
         "value": min(others.values()) if others else None, "met": below_all},
        {"target": "final position error zero for hexstep on every move",
         "value": h["max_abs_final_err"], "met": h["max_abs_final_err"] == 0 and h["unfinished"] == 0},
        {"target": "event mode >= 100x cycle mode on moves slower than 1,000 steps/s at 100 MHz",
         "value": tp.get("event_over_cycle"), "met": (tp.get("event_over_cycle") or 0) >= 100},
        {"target": "co-simulation >= 10 million cycles/s with six axes moving (no model comparison)",
         "value": tp.get("cosim_cycles_per_s"), "met": (tp.get("cosim_cycles_per_s") or 0) >= 1e7},
    ]
    return t


def findings(acc, overall):
    """Where hexstep's worst excess against the planner's profile comes from (from the data)."""
    moves = acc["moves"]
    w = max(moves, key=lambda m: m["algo"]["hexstep"]["max_excess"])
    h, r = w["algo"]["hexstep"], w["algo"]["hexstep_regs"]
    f = w["clock_hz"]
    ft = f / 32.0  # the registers count ticks of 32 clock cycles (one frame)
    lsb = ft * ft / 2.0 ** 64  # one acceleration register LSB in steps/s^2
    rel = max(lsb / w["accel"] if w["accel"] else 0, lsb / w["decel"] if w["decel"] else 0)
    text = (f"hexstep's worst excess against the planner's profile is on move {w['id']} ({w['kind']}, "
            f"{w['steps']} steps, {w['profile']}, a = {fmt(w['accel'])}, d = {fmt(w['decel'])} steps/s^2, "
            f"peak {fmt(w['v_peak'])} steps/s, {f / 1e6:g} MHz): {fmt(h['max_excess'])} step "
            f"(error/allowance {fmt(h['max_ratio'])}); the same pulses against the profile its registers describe: "
            f"{fmt(r['max_excess'])} step (error/allowance {fmt(r['max_ratio'])}). ")
    if r["max_ratio"] > 1:
        # Outside the core's own allowance: not a matter of the register values.
        return text + ("The pulses are late against the registers' own profile too, so this is the core's "
                       "output timing, not the rounding of the registers.\n")
    return text + (f"One acceleration LSB at this clock is (f/32)^2/2^64 = {fmt(lsb)} steps/s^2, up to {fmt(rel)} "
                   f"of this move's ramp rates; the registers round down, and over {w['steps']} steps that relative "
                   f"difference becomes the position difference above.\n")


def md_table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for r in rows:
        out.append("| " + " | ".join(r) + " |")
    return "\n".join(out)


def vs_hexstep(a, o):
    if a == "hexstep":
        return "1"
    if a == "hexstep_regs":
        return "-"
    return fmt(o["ratio_err_to_hexstep"]) + " / " + fmt(o["ratio_excess_to_hexstep"])


def overall_rows(overall, algos):
    rows = []
    for a in algos:
        o = overall[a]
        if not o["moves"]:
            rows.append([ALGO_TITLES[a], "0", str(o["excluded"])] + ["-"] * 9)
            continue
        rows.append([
            ALGO_TITLES[a], str(o["moves"]), str(o["excluded"]), fmt(o["max_err_us"]), fmt(o["rms_err_us"]),
            fmt(o["max_pos_err_steps"]), fmt(o["max_excess_steps"]), fmt(o["max_ratio"]),
            str(o["max_abs_final_err"]) + (f" ({o['unfinished']} stalled)" if o["unfinished"] else ""),
            fmt(o["max_abs_duration_err_us"]), fmt(o["max_rel_speed_err"]),
            vs_hexstep(a, o),
        ])
    return rows


OVERALL_HEADER = ["algorithm", "moves", "excluded", "max err (us)", "RMS err (us)", "max pos.-equiv. err (steps)",
                  "max excess (steps)", "worst err/allowance", "max final pos. err (steps)",
                  "max duration err (us)", "worst rel. speed err", "max err / excess vs hexstep (same moves)"]


def throughput_rows(tp):
    def row(name, key, unit):
        return [name, fmt(tp.get(key), 4) + " " + unit]
    return [
        row("golden model, cycle mode (six axes, slow moves)", "model_cycle_axis_cycles_per_s", "axis-cycles/s"),
        row("golden model, cycle mode, same job", "model_cycle_steps_per_s", "steps/s"),
        row("golden model, event mode, same job", "model_event_steps_per_s", "steps/s"),
        ["event / cycle mode (same job, moves below 1,000 steps/s)", fmt(tp.get("event_over_cycle"), 4) + " x"],
        row("golden model, event mode, one long slow move (20,000 steps, <= 900 steps/s)",
            "model_event_long_slow_steps_per_s", "steps/s"),
        row("Verilated core, six axes moving", "cosim_cycles_per_s", "cycles/s"),
        row("Verilated core + golden model in lock step, outputs compared every cycle",
            "cosim_with_model_cycles_per_s", "cycles/s"),
        row("planner: single-axis plan + registers", "plan_single_per_s", "plans/s"),
        row("planner: six-axis coordinated line + registers", "plan_six_axis_line_per_s", "plans/s"),
    ]


def plots(traces, outdir):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail(f"matplotlib is needed for the plots ({e}); run `make deps`")
    files = []
    styles = {"hexstep": ("tab:blue", "-"), "avr446": ("tab:red", "--"), "spt_10khz": ("tab:green", ":"),
              "stoychitch": ("tab:purple", "-."), "dda_1khz": ("tab:orange", "-")}
    for k, tr in enumerate(traces, 1):
        fig, ax = plt.subplots(figsize=(8, 4.5))
        ax.plot(tr["ideal_curve_t"], tr["ideal_curve_v"], color="black", lw=2.5, alpha=0.35, label="ideal (planner)")
        for algo in ("hexstep", "avr446", "spt_10khz"):
            t = tr["algo"].get(algo)
            if not t or len(t) < 2:
                continue
            mids = [(t[i] + t[i - 1]) / 2 for i in range(1, len(t))]
            vel = [1.0 / (t[i] - t[i - 1]) if t[i] > t[i - 1] else float("nan") for i in range(1, len(t))]
            c, ls = styles[algo]
            ax.plot(mids, vel, color=c, ls=ls, lw=1, label=ALGO_TITLES[algo])
        ax.set_xlabel("time (s)")
        ax.set_ylabel("speed (steps/s, 1 / pulse interval)")
        ax.set_title(f"move {k}: {tr['steps']} steps from rest, a = {tr['accel']:g}, d = {tr['decel']:g} steps/s^2, 100 MHz")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        fn = f"velocity_move{k}.png"
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, fn), dpi=110)
        plt.close(fig)
        files.append(fn)
    fig, axes = plt.subplots(len(traces), 1, figsize=(8, 3.2 * max(1, len(traces))), squeeze=False)
    for k, tr in enumerate(traces):
        ax = axes[k][0]
        ideal = tr["ideal_t"]
        for algo, t in tr["algo"].items():
            if algo not in styles:
                continue
            n = min(len(t), len(ideal))
            err = [(t[i] - ideal[i]) * 1e6 for i in range(n)]
            c, ls = styles[algo]
            ax.plot(range(1, n + 1), err, color=c, ls=ls, lw=1, label=ALGO_TITLES[algo])
        ax.set_yscale("symlog", linthresh=0.01)
        ax.set_ylabel("t - t_ideal (us)")
        ax.set_title(f"move {k + 1}: {tr['steps']} steps", fontsize=9)
        ax.grid(alpha=0.3)
        if k == 0:
            ax.legend(fontsize=7, ncol=2)
    axes[-1][0].set_xlabel("step index")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "step_error.png"), dpi=110)
    plt.close(fig)
    files.append("step_error.png")
    return files


def git_rev(root):
    try:
        rev = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", root, "status", "--porcelain"], capture_output=True, text=True).stdout.strip()
        return rev + ("+uncommitted changes" if dirty else "")
    except OSError:
        return "unknown"


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--results", required=True, help="directory with accuracy.json, throughput.json, traces.json")
    ap.add_argument("--readme", help="README.md whose bench section is rewritten")
    ap.add_argument("--synth", default="synth/results/summary.md", help="synthesis summary to include if present")
    ap.add_argument("--no-plots", action="store_true")
    args = ap.parse_args()
    rd = args.results
    acc = load(os.path.join(rd, "accuracy.json"), "accuracy results")
    tp_raw = load(os.path.join(rd, "throughput.json"), "throughput results")
    traces = load(os.path.join(rd, "traces.json"), "plot traces")
    overall, per_range, ranges, exclusions = accuracy_tables(acc)
    tp = throughput_medians(tp_raw)
    tg = targets(overall, tp)
    root = os.path.dirname(os.path.abspath(args.readme)) if args.readme else os.getcwd()
    # The measurement's time: Google Benchmark's run date (the last step of `make bench`).
    stamp = tp_raw.get("context", {}).get("date") or datetime.datetime.now(datetime.timezone.utc).strftime(
        "%Y-%m-%d %H:%M UTC")
    rev = git_rev(root)
    files = [] if args.no_plots else plots(traces, rd)
    n_moves = len(acc["moves"])
    kinds = {}
    for m in acc["moves"]:
        kinds[m["kind"]] = kinds.get(m["kind"], 0) + 1
    lines = len({(m["clock_hz"], m["line"]) for m in acc["moves"] if m["kind"] == "line"})
    synth = None
    if os.path.exists(args.synth):
        with open(args.synth) as f:
            synth = f.read().strip()

    md = []
    md.append("# hexstep bench results\n")
    md.append(f"Generated by `make bench` ({stamp}, tree {rev}); do not edit by hand. "
              "Method and distributions: `docs/BENCH.md`.\n")
    md.append("## Targets\n")
    md.append(md_table(["target", "measured", "met"],
                       [[t["target"], fmt(t["value"], 4), "met" if t["met"] else "**not met**"] for t in tg]))
    md.append("")
    md.append(findings(acc, overall))
    md.append("## Suite\n")
    md.append(f"{n_moves} single-axis moves: {kinds.get('random', 0)} random, {kinds.get('directed', 0)} directed "
              f"(range ends and the plotted moves), {kinds.get('line', 0)} axes of {lines} six-axis coordinated lines; "
              f"seed {acc['seed']}, {acc['threads']} threads, {acc['seconds']:.0f} s. Draws redrawn: "
              f"{acc['redrawn_duration']} (longer than {acc['options']['max_duration_s']:g} s), "
              f"{acc['redrawn_range']} (a value outside the issue's ranges or the registers).\n")
    ic = acc["ideal_check"]
    md.append(f"Ideal instants (planner's real-valued profile, long double) against an exact __float128 "
              f"bisection on {ic['samples']} sampled steps: max difference {fmt(ic['max_abs_diff_cycles'])} cycles; "
              f"{fmt(ic.get('max_abs_diff_cycles_above_0.1pct_peak'))} cycles where the ideal speed is above 0.1% of the "
              f"peak (near zero speed the instant is ill-conditioned: dt = sqrt(2 dx/d)); at most "
              f"{fmt(ic.get('max_diff_over_allowance'))} of the step's allowance.\n")
    md.append("## Accuracy, all moves\n")
    md.append("Errors against the planner's real-valued profile (except the second row). Step-time error "
              "|t_i - t_ideal,i|; position-equivalent error = error x ideal speed; excess = "
              "max(0, error - 2/f_clk) x ideal speed; allowance = 2/f_clk + 0.001/v_ideal; relative speed "
              "error per step = |ideal interval / real interval - 1|. Ratios vs hexstep use hexstep's worst on the "
              "same moves.\n")
    md.append(md_table(OVERALL_HEADER, overall_rows(overall, acc["algorithms"])))
    md.append("")
    md.append("## Excluded moves\n")
    rows = []
    for a in acc["algorithms"]:
        for reason, cnt in exclusions[a].items():
            rows.append([ALGO_TITLES[a], str(cnt), reason])
    md.append(md_table(["algorithm", "moves", "reason"], rows) if rows else "None.")
    md.append("")
    md.append("## Accuracy per range\n")
    hdr = ["range", "algorithm", "moves", "max err (cycles)", "max err (us)", "RMS err (cycles)", "RMS err (us)",
           "max pos.-equiv. err (steps)",
           "max excess (steps)", "worst err/allowance", "max final pos. err", "max duration err (us)",
           "worst rel. speed err", "max err / excess vs hexstep"]
    rows = []
    for r in ranges:
        for a in acc["algorithms"]:
            o = per_range[r][a]
            if not o["moves"]:
                continue
            rows.append([r, ALGO_TITLES[a], str(o["moves"]), fmt(o["max_err_cycles"]), fmt(o["max_err_us"]),
                         fmt(o.get("rms_err_cycles")), fmt(o["rms_err_us"]), fmt(o["max_pos_err_steps"]),
                         fmt(o["max_excess_steps"]),
                         fmt(o["max_ratio"]),
                         str(o["max_abs_final_err"]) + (f" ({o['unfinished']} stalled)" if o["unfinished"] else ""),
                         fmt(o["max_abs_duration_err_us"]), fmt(o["max_rel_speed_err"]),
                         vs_hexstep(a, o)])
    md.append(md_table(hdr, rows))
    md.append("")
    md.append("## Throughput\n")
    md.append(f"Google Benchmark, medians of {tp.get('repetitions')} repetitions in one run "
              f"({tp['context'].get('num_cpus')} CPUs, shared machine).\n")
    md.append(md_table(["measurement", "median"], throughput_rows(tp)))
    md.append("")
    md.append("## Synthesis\n")
    md.append(synth if synth else "`synth/results/summary.md` does not exist yet (`make synth` writes it).")
    md.append("")
    if files:
        md.append("## Plots\n")
        md.append("Written to `bench/results/` by `make bench` (not committed): " + ", ".join(f"`{f}`" for f in files) + ".\n")
    summary_md = "\n".join(md) + "\n"

    summary = {"generated": stamp, "tree": rev, "targets": tg, "suite": {
        "moves": n_moves, "kinds": kinds, "lines": lines, "seed": acc["seed"], "seconds": acc["seconds"],
        "redrawn_duration": acc["redrawn_duration"], "redrawn_range": acc["redrawn_range"], "ideal_check": ic},
        "overall": overall, "per_range": per_range, "exclusions": exclusions, "throughput": tp,
        "synth_included": bool(synth), "plots": files}
    with open(os.path.join(rd, "summary.md"), "w") as f:
        f.write(summary_md)
    with open(os.path.join(rd, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1, sort_keys=True, default=lambda x: None)
        f.write("\n")

    if args.readme:
        sec = ["<!-- bench:begin (generated by `make bench` from bench/results/summary.md; do not edit by hand) -->",
               f"Measured by `make bench` ({stamp}); full tables, ranges and exclusions in "
               "`bench/results/summary.md`, method in `docs/BENCH.md`.", "",
               md_table(["target", "measured", "met"],
                        [[t["target"], fmt(t["value"], 4), "met" if t["met"] else "**not met**"] for t in tg]),
               "",
               f"Accuracy over {n_moves} moves at 100, 48 and 12 MHz (errors against the planner's real-valued profile):",
               "",
               md_table(["algorithm", "moves", "max err (us)", "max excess (steps)", "worst err/allowance",
                         "max final pos. err (steps)", "max err / excess vs hexstep"],
                        [[r[0], r[1], r[3], r[6], r[7], r[8], r[11]] for r in overall_rows(overall, acc["algorithms"])]),
               "",
               md_table(["throughput (median)", "value"], throughput_rows(tp)),
               "<!-- bench:end -->"]
        with open(args.readme) as f:
            text = f.read()
        pat = re.compile(r"<!-- bench:begin.*?-->.*?<!-- bench:end -->", re.S)
        if not pat.search(text):
            fail(f"{args.readme}: markers <!-- bench:begin ...--> and <!-- bench:end --> not found")
        text = pat.sub(lambda _: "\n".join(sec), text, count=1)
        with open(args.readme, "w") as f:
            f.write(text)
    print(f"bench/report.py: wrote {rd}/summary.md, summary.json" + (", " + ", ".join(files) if files else "") +
          (f"; updated {args.readme}" if args.readme else ""))


if __name__ == "__main__":
    main()
