#!/usr/bin/env python3
"""Runs the benchmark program and writes reports/performance.md.

Called by scripts/run-benchmarks.sh after it has built eccd_bench; standard
library only. Steps:
  1. the machine (CPU, cores, memory, OS, compiler, build type, libraries),
     the date and the git revision;
  2. one run of eccd_bench: Google Benchmark's JSON (--benchmark_out) and the
     program's summary (--eccd_summary: groups, rows, medians over the
     repetitions, ratios to each group's baseline, what each row answered);
  3. the targets (the speed limits per row; the certified mode's set and
     ratio targets; the guard's cost), each against its
     anchor (a paper's figure, FCL, or the flop count): met, or missed by how much;
  4. for each missed target, what dominates the time: the target's phase group
     (the pipeline's public steps timed one by one in the same run) and, when
     `perf` works here, a sampling profile of the target's row alone
     (eccd_bench --benchmark_filter=ROW --eccd_profile_seconds=S under
     `perf record`; flat profile by symbol and by shared object);
  5. reports/performance.md: the machine, the targets, the animations, FCL side
     by side (static test per pair, per frame of 000 Table 2 with the
     misclassified frames), the profiles, one table per group, the scenes, and
     what was left out.
Raw outputs stay in the work directory (--work, default build-bench/bench-results).
The work is done by the package perf_report/ beside this script (its __init__.py lists the modules).
"""

import argparse
import os
import sys
import time

from perf_report.tools import loadavg, machine_info
from perf_report.steps import profile_targets, rerun_alone, run_benchmark, target_verdicts
from perf_report.certificates import certificate_cost
from perf_report.write import write_report


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bench", required=True, help="the eccd_bench executable")
    ap.add_argument("--out", default="reports/performance.md")
    ap.add_argument("--work", default="build-bench/bench-results")
    ap.add_argument("--quick", action="store_true", help="3 repetitions, short minimum times (development only)")
    ap.add_argument("--filter", default=None, help="only the rows matching this regular expression (development only: "
                                                  "the report then lacks the other rows)")
    ap.add_argument("--profile-seconds", type=float, default=2.0)
    ap.add_argument("--no-perf", action="store_true")
    ap.add_argument("--started", type=float, default=None, help="time.time() when the whole script started")
    ap.add_argument("--eccd", default=None,
                    help="the eccd program, for the certificates' cost (`eccd regress cases/ --arith certified --certify`); "
                         "default: eccd beside the benchmark's build folder; 'none' leaves the section out")
    args = ap.parse_args()
    return args


def main():
    args = parse_args()

    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    os.makedirs(args.work, exist_ok=True)
    started = args.started or time.time()
    info = machine_info(root, os.path.dirname(os.path.dirname(os.path.abspath(args.bench))))
    info["load_before"] = loadavg()
    summ, bench_seconds = run_benchmark(args, info)

    rows = {}
    for g in summ["groups"]:
        for r in g["rows"]:
            rows[r["key"]] = (g, r)

    verdicts = target_verdicts(summ, rows)
    rerun_alone(args, verdicts, info)
    profile_targets(args, summ, verdicts, info)

    info["certificate_cost"] = certificate_cost(args, root)

    total_seconds = time.time() - started
    write_report(args.out, summ, info, verdicts, rows, bench_seconds, total_seconds, args)
    print(f"wrote {args.out} (benchmark {bench_seconds:.0f} s, whole run {total_seconds:.0f} s)", file=sys.stderr)


if __name__ == "__main__":
    main()
