#!/usr/bin/env python3
"""Writes fcl-sampled-*.json: answers for shipped cases as a sampling engine
(FCL's naive continuous collision, issue 19) gives them: the static test at
t = k/N, k = 0..N, colliding samples merged into intervals [k/N, m/N], decimals
only (no brackets), no contacts (a sampler reports none). The static test here
is eccd's exact one (eccd.status_at, arith='exact'), so every difference judge
finds comes from the sampling alone; FCL's own static test adds its tolerance
on top. Run from the repository root with PYTHONPATH=build/python."""
import json
import os
import sys
from fractions import Fraction

import eccd


def sampled_answer(scene, n):
    hits = [eccd.status_at(scene, Fraction(k, n), "exact") != "separate" for k in range(n + 1)]
    intervals, k = [], 0
    while k <= n:
        if hits[k]:
            m = k
            while m + 1 <= n and hits[m + 1]:
                m += 1
            intervals.append([{"approx": repr(k / n)}, {"approx": repr(m / n)}])
            k = m + 1
        else:
            k += 1
    return {"collides": bool(intervals), "intervals": intervals,
            "first_contact": intervals[0][0] if intervals else None, "contacts": []}


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for case, n, out in [("cases/spheres/spheres-crossing.json", 10, "fcl-sampled-spheres-crossing-10.json"),
                         ("cases/spheres/spheres-crossing.json", 1000, "fcl-sampled-spheres-crossing-1000.json"),
                         ("cases/touch3d/touch-and-separate.json", 7, "fcl-sampled-touch-and-separate-7.json")]:
        a = sampled_answer(eccd.read_scene(case), n)
        with open(os.path.join(here, out), "w") as f:
            json.dump(a, f, indent=1)
            f.write("\n")
        print(out, a["collides"], [(i[0]["approx"], i[1]["approx"]) for i in a["intervals"]], file=sys.stderr)


if __name__ == "__main__":
    main()
