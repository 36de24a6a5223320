#!/usr/bin/env python3
"""Writes short-overlap scenes: 3D degree-2 Euler pairs that overlap for a very short time (issue 18's killer).

`eccd generate --families near-miss` builds B's motion as G * T(sigma) * P_B with the gap along the common normal
sigma(t) = d + (t - t0)^2 h(t) (compare/scene_generator.cpp build_touch): every entry of B's matrix is affine in d, and
only the constant terms of the translation column depend on it. From the generator's scenes for the same seed at two
separations d1 and d2 (compare/scene_generator.hpp generate_scene with the spec of the note, d_exponent e1 and e2),
this script extrapolates those entries exactly (rationals) to d = -depth: B is then pushed `depth` into A at t0, and
the two overlap on an interval of length about 2 sqrt(depth / h(t0)) around t0 (about 1e-5 for depth 1e-9).

Usage: make_short_overlap.py NEAR_MISS_D1.json NEAR_MISS_D2.json DEPTH_EXPONENT OUT.json
(the two inputs: the same seed, separations 10^-e1 and 10^-e2, as written by generate_scene).
"""
import json
import re
import sys
from fractions import Fraction


def sep(doc):
    return Fraction(1, 10 ** int(re.search(r" d=1e-(\d+) ", doc["note"]).group(1)))


def main():
    a, b, e, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
    s1, s2 = json.load(open(a)), json.load(open(b))
    d1, d2, d = sep(s1), sep(s2), -Fraction(1, 10 ** e)
    w = (d - d1) / (d2 - d1)

    def walk(x, y):
        if isinstance(x, dict):
            return {k: walk(x[k], y[k]) for k in x}
        if isinstance(x, list):
            return [walk(p, q) for p, q in zip(x, y)]
        if isinstance(x, str) and re.fullmatch(r"-?\d+(/\d+)?", x):
            v = Fraction(x) + w * (Fraction(y) - Fraction(x))
            return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
        return x

    s = walk(s1, s2)
    seed = re.search(r"seed=(\d+)", s1["note"]).group(1)
    s["name"] = f"3d-deg{s1['name'].split('-')[1][3:]}-short-overlap-1e-{e}-euler-{seed}"
    s["note"] = (f"short overlap of depth 1e-{e} at t0 (issue 18): the generator's near-miss scene (seed {seed}, "
                 f"{s1['note'].split(': ')[1].split('. ')[0]}) with the gap d extrapolated to -1e-{e} "
                 f"(cases/short-overlap/make_short_overlap.py)")
    with open(out, "w") as f:
        json.dump(s, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
