#!/usr/bin/env python3
"""Measures eccd animate at scale, per-pose and continuous modes.

    measure-scale.py [--eccd build/eccd] [--bodies 1000] [--frames 100] [--seed 36]
                     [--modes poses,continuous] [--arith double] [--jobs 1,2] [--keep DIR]

Generates the crowd animation (scripts/generate-crowd.py, deterministic by
seed), runs `eccd animate --json` on it for each mode and --jobs value, and
prints per run: the wall time of the process, animate's own seconds (the
answer's "seconds": without reading the file), time per frame (per pose in
--poses mode), the pairs the broad phase let through, peak memory (the
child's ru_maxrss from getrusage, KiB), and the speed-up of each --jobs value
over --jobs 1. Measures, never asserts; quote the figures with this command.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--eccd", default="build/eccd")
    ap.add_argument("--bodies", type=int, default=1000)
    ap.add_argument("--frames", type=int, default=100)
    ap.add_argument("--seed", type=int, default=36)
    ap.add_argument("--modes", default="poses,continuous")
    ap.add_argument("--arith", default="double")
    ap.add_argument("--jobs", default="1,2")
    ap.add_argument("--keep", default=None, help="directory for the animation and the answers (default: a temporary one)")
    a = ap.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))
    work = a.keep or tempfile.mkdtemp(prefix="eccd-scale-")
    os.makedirs(work, exist_ok=True)
    anim = os.path.join(work, "crowd-%d-%d-%d.anim.json" % (a.bodies, a.frames, a.seed))
    if not os.path.exists(anim):
        subprocess.run([sys.executable, os.path.join(here, "generate-crowd.py"), "--bodies", str(a.bodies), "--frames",
                        str(a.frames), "--seed", str(a.seed), anim], check=True)
    size = os.path.getsize(anim)
    print("animation %s: %d bodies, %d frames, %d pairs per frame, %.1f MB" %
          (anim, a.bodies, a.frames, a.bodies * (a.bodies - 1) // 2, size / 1e6))
    print("%-10s %4s %9s %9s %12s %10s %10s %9s" % ("mode", "jobs", "wall s", "animate s", "ms/frame", "narrow", "maxrss KiB", "speed-up"))
    for mode in a.modes.split(","):
        base = None
        for jobs in [int(j) for j in a.jobs.split(",")]:
            out = os.path.join(work, "answer-%s-%s-j%d.json" % (mode, a.arith, jobs))
            cmd = [a.eccd, "--max-file-bytes", str(size + 1), "animate", anim, "--arith", a.arith, "--json", "--quiet",
                   "--jobs", str(jobs), "--out", out, "--force"]
            if mode == "poses":
                cmd.insert(4, "--poses")
            t0 = time.monotonic()
            pid = os.fork()
            if pid == 0:
                os.execv(cmd[0], cmd)
            _, status, usage = os.wait4(pid, 0)
            wall = time.monotonic() - t0
            if status != 0:
                print("%-10s %4d failed (status %d): %s" % (mode, jobs, status, " ".join(cmd)))
                continue
            r = json.load(open(out))
            secs = r["seconds"]
            units = r["poses"] if mode == "poses" else r["frames"]
            st = r["stages"]
            narrow = st.get("static_test", 0) + st.get("continuous_test", 0) + st["separating_plane"]
            base = base or secs
            print("%-10s %4d %9.2f %9.2f %12.2f %10d %10d %9.2f" %
                  (mode, jobs, wall, secs, secs * 1e3 / units, narrow, usage.ru_maxrss, base / secs))
    print("(narrow: pair-frames / pair-poses past the bounding spheres; animate s: the answer's \"seconds\")")


if __name__ == "__main__":
    main()
