#!/usr/bin/env python3
"""Writes a generated animation of many ellipsoids (to measure `eccd animate` at scale).

    generate-crowd.py --bodies N --frames F --seed S [--box L] OUT

N ellipsoids (semi-axes uniform in [0.3, 1.0]) start at random places in the
cube [0, L]^3 (default L = 6 N^(1/3): a mean spacing of 6, a sparse scene),
each moving at a constant random velocity (|v| <= 0.3 per key) that reflects
off the cube's walls, and turning about its own random axis by a random rate
(at most 0.1 rad per key) from a random orientation. Keys 0..F (times 0..F),
so F frames; pairs "all" (N(N-1)/2 per frame). Deterministic: random.Random(S)
only, and every number is written as an exact decimal string (positions 4
decimals, quaternion components 6), so the animation IS those decimals
(docs/animation-format.md). The scale measurement is scripts/measure-scale.py.
"""
import argparse
import json
import math
import random


def quat_mul(p, q):
    return (p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
            p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
            p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
            p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0])


def unit(rng, n):
    while True:
        v = [rng.gauss(0, 1) for _ in range(n)]
        s = math.sqrt(sum(x * x for x in v))
        if s > 1e-3:
            return [x / s for x in v]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bodies", type=int, default=1000)
    ap.add_argument("--frames", type=int, default=100)
    ap.add_argument("--seed", type=int, default=36)
    ap.add_argument("--box", type=float, default=None)
    ap.add_argument("out")
    a = ap.parse_args()
    if a.bodies < 2 or a.frames < 1:
        ap.error("--bodies must be at least 2 and --frames at least 1")
    rng = random.Random(a.seed)
    box = a.box if a.box else 6.0 * a.bodies ** (1.0 / 3.0)
    bodies = []
    for b in range(a.bodies):
        axes = ["%.2f" % rng.uniform(0.3, 1.0) for _ in range(3)]
        pos = [rng.uniform(0, box) for _ in range(3)]
        speed = rng.uniform(0, 0.3)
        vel = [speed * x for x in unit(rng, 3)]
        axis = unit(rng, 3)
        rate = rng.uniform(0, 0.1)
        q0 = unit(rng, 4)
        poses = []
        for k in range(a.frames + 1):
            h = k * rate / 2
            q = quat_mul(q0, (math.cos(h), math.sin(h) * axis[0], math.sin(h) * axis[1], math.sin(h) * axis[2]))
            poses.append({"position": ["%.4f" % x for x in pos], "orientation": ["%.6f" % x for x in q]})
            for i in range(3):  # the next key: reflect off the walls
                pos[i] += vel[i]
                if pos[i] < 0 or pos[i] > box:
                    vel[i] = -vel[i]
                    pos[i] += 2 * vel[i]
        bodies.append({"name": "e%d" % b, "shape": {"semi_axes": axes}, "poses": poses})
    doc = {"format": "ellipse-ccd-animation/1", "name": "crowd-%d-%d-seed%d" % (a.bodies, a.frames, a.seed), "dim": 3,
           "times": [str(k) for k in range(a.frames + 1)], "bodies": bodies, "pairs": "all",
           "note": "scripts/generate-crowd.py --bodies %d --frames %d --seed %d%s" %
                   (a.bodies, a.frames, a.seed, " --box %s" % a.box if a.box else "")}
    with open(a.out, "w") as f:
        json.dump(doc, f, separators=(",", ":"))
        f.write("\n")


if __name__ == "__main__":
    main()
