"""The run's steps after the main benchmark: target verdicts, the target rows re-run alone, profiles."""

import json
import os
import subprocess
import sys
import time

from .targets import RATIO_TARGETS, TARGETS, independent_targets
from .tools import ere_escape, loadavg, perf_profile, perf_works, run
from .sections import per_divisor, ratio_verdicts, set_verdicts


def run_benchmark(args, info):
    """One run of eccd_bench with the JSON and summary outputs; returns the summary and the run's seconds."""
    raw = os.path.join(args.work, "benchmark.json")
    summary_path = os.path.join(args.work, "summary.json")
    log_path = os.path.join(args.work, "benchmark.log")

    cmd = [args.bench, "--benchmark_out=" + raw, "--benchmark_out_format=json", "--eccd_summary=" + summary_path,
   ]
    if args.quick:
        cmd.append("--eccd_quick")
    if args.filter:
        cmd.append("--benchmark_filter=" + args.filter)
    print("running: " + " ".join(cmd), file=sys.stderr)
    t0 = time.time()
    with open(log_path, "w") as log:
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        for line in p.stdout:
            log.write(line)
            if "_median" in line:
                print("  " + line.split()[0].replace("_median", ""), file=sys.stderr)
        rc = p.wait()
    bench_seconds = time.time() - t0
    if rc != 0:
        sys.exit(f"eccd_bench failed (exit {rc}); see {log_path}")
    info["load_after"] = loadavg()
    with open(summary_path) as f:
        summ = json.load(f)
    return summ, bench_seconds


def target_verdicts(summ, rows):
    """Each target (TARGETS and the independent scenes' limits) against its row: met, missed or not measured."""
    # Targets.
    indep_times, indep_ratios = independent_targets(summ)
    targets = TARGETS + indep_times
    RATIO_TARGETS.extend(indep_ratios)
    verdicts = []
    for t in targets:
        g, r = rows.get(t["key"], (None, None))
        v = dict(t)
        if r is None or "median_cpu_ns" not in r:
            v["status"] = "not measured"
            verdicts.append(v)
            continue
        div = per_divisor(t, r)
        if div is None:
            v["status"] = "not measured"
            verdicts.append(v)
            continue
        v["div"] = div
        ns = r["median_cpu_ns"] / div
        v["ns"] = ns
        v["real_ns"] = r["median_real_ns"] / div if r.get("median_real_ns") is not None else None
        v["spread"] = tuple(r[k] / div if r.get(k) is not None else None for k in ("min_cpu_ns", "max_cpu_ns"))
        v["reps"] = r.get("repetitions")
        v["met"] = ns <= t["limit_ns"]
        v["factor"] = ns / t["limit_ns"]
        v["status"] = "met" if v["met"] else "missed"
        verdicts.append(v)
    return verdicts


def rerun_alone(args, verdicts, info):
    """The target rows re-measured alone: alone_ns and alone_met on each verdict."""
    # The target rows once more, alone, in a second process right after the
    # main run (the verdict is the main run's; this shows how much a verdict
    # depends on what else ran, and on the load at the time).
    alone_path = os.path.join(args.work, "targets-alone.json")
    # (the per-scene independent rows are seconds each: not re-run)
    # The ratio targets' two rows too (a ratio of two noisy medians is as noisy as both; the per-scene
    # independent-motion rows, seconds each, are left out).
    keys = [t["key"] for t in TARGETS] + [k for t in RATIO_TARGETS if not t["key"].startswith("independent-")
                                          for k in (t["key"], t["base"], t.get("interleaved")) if k]
    regex = "^(" + "|".join(ere_escape(k) for k in dict.fromkeys(keys)) + ")(/|$)"
    cmd2 = [args.bench, "--benchmark_filter=" + regex, "--eccd_summary=" + alone_path] + (["--eccd_quick"] if args.quick else [])
    print("re-running the target rows alone", file=sys.stderr)
    r2 = run(cmd2)
    alone = {}
    if r2.returncode == 0:
        with open(alone_path) as f:
            for g in json.load(f)["groups"]:
                for r in g["rows"]:
                    alone[r["key"]] = r
    for v in verdicts:
        a = alone.get(v["key"])
        if a and "median_cpu_ns" in a and v.get("div") and per_divisor(v, a):
            v["alone_ns"] = a["median_cpu_ns"] / per_divisor(v, a)
            v["alone_met"] = v["alone_ns"] <= v["limit_ns"]
    info["alone_rows"] = alone
    info["load_after_rerun"] = loadavg()


def profile_targets(args, summ, verdicts, info):
    """perf profiles of the missed targets (and the narrowly met ones), the set targets and the ratio targets."""
    # Profiles of the missed targets, and of those met only narrowly (the
    # limit within the spread of the repetitions, or missed when re-measured).
    ok, why_not = (False, "--no-perf") if args.no_perf else perf_works()
    for v in verdicts:
        if v["status"] == "met":
            lo, hi = v["spread"]
            v["borderline"] = (lo is not None and hi is not None and lo <= v["limit_ns"] <= hi) or v.get("alone_met") is False
        if v["status"] != "missed" and not v.get("borderline"):
            continue
        if ok:
            print(f"profiling {v['key']} under perf", file=sys.stderr)
            prof, err = perf_profile(args.bench, v["key"], args.work, args.profile_seconds)
            v["perf"] = prof
            v["perf_error"] = err
        else:
            v["perf_error"] = why_not

    sets = set_verdicts(summ)
    for v in sets:
        if v["status"] != "missed":
            continue
        if ok:
            key = v["group"] + "/" + v["median_scene"] + " certified"
            print(f"profiling {key} under perf", file=sys.stderr)
            v["perf"], v["perf_error"] = perf_profile(args.bench, key, args.work, args.profile_seconds)
        else:
            v["perf_error"] = why_not
    info["set_targets"] = sets
    ratios = ratio_verdicts(summ, info.get("alone_rows", {}))
    for v in ratios:
        if v["status"] != "missed" and v.get("alone_met") is not False:
            continue
        if ok:
            print(f"profiling {v['key']} under perf", file=sys.stderr)
            v["perf"], v["perf_error"] = perf_profile(args.bench, v["key"], args.work, args.profile_seconds)
        else:
            v["perf_error"] = why_not
    info["ratio_targets"] = ratios
