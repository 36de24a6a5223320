#!/usr/bin/env python3
"""Writes the animations of the three paper reproductions (issue 17 point 5;
reports/animation/, scripts/run-animation-report.sh). Deterministic: seeded,
and every number is an exact decimal string (rounded once from the float
construction, then exact: the animation IS those decimals).

  table1 --rate R --frames N --seed S OUT
      Paper 000 Table 1: two ellipsoids with semi-axes 3, 3, 5 (the long axis
      along the body's z), centres (0,0,0) and (8,0,0), each rotating about its
      own random axis (uniform on the sphere, random.Random(S)) by R radians per
      frame, starting from a random orientation. Key k: quaternion
      q0 * (cos(kR/2), sin(kR/2) u) with 6 decimals (not unit length: the spec
      allows it). times 0, 1, ..., N.
  table2 --frames N --radius R OUT [--scenes DIR]
      Paper 000 Table 2: a sphere of radius 1 whose centre is at
      (R cos 0.01k, R sin 0.01k, 0) at key k (6 decimals), around a static
      ellipsoid with semi-axes 4.5, 4, 2 at the origin (the orbit lies in the
      plane of its two longer axes). Between keys the centre moves on the chord
      (the spec's linear interpolation). --scenes DIR also writes each frame
      as a scene (frame-K.json: the sphere translating linearly in t, the
      ellipsoid static) for `eccd fcl`.
  boxers --frames N [--subdivide S] OUT
      Paper 001 section 5 in spirit: two articulated figures of 24 ellipsoids
      each (groups "boxer-1", "boxer-2"), pairs "between-groups" (576). Each
      figure is a planar skeleton in its x-z plane (x towards the opponent):
      every limb segment hangs from its parent joint at the angle
      base + A sin(2 pi f k + phase) (k the key index; see LIMBS), positions
      by forward kinematics, orientation the rotation about y by the segment
      angle; the torso, neck and head sway in x by 0.08 sin(2 pi k/40). The
      second figure is the first, phase-shifted by 0.37 of a period, turned
      a half turn about z and set 1.0 along x. Keys 6 decimals (positions 4).
      --subdivide S (default 1): key k is the pose of the motion above at
      k/S, i.e. the same motion sampled S times as finely (S frames for each
      frame of the default; the report uses S = 4 to show how the share of
      the kept plane depends on the motion per frame).
"""
import argparse
import sys
import json
import math
import os
import random
from fractions import Fraction as F


def dec(x, d):
    """x rounded to d decimals, as an exact decimal string."""
    n = round(x * 10**d)
    f = F(n, 10**d)
    if f.denominator == 1:
        return str(f.numerator)
    s = str(abs(n)).rjust(d + 1, "0")
    s = s[:-d] + "." + s[-d:]
    s = s.rstrip("0").rstrip(".")
    return ("-" if n < 0 else "") + s


def qmul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return (w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2)


def qaxis(u, ang):
    s = math.sin(ang / 2)
    return (math.cos(ang / 2), u[0] * s, u[1] * s, u[2] * s)


def rand_axis(rng):
    z = rng.uniform(-1, 1)
    p = rng.uniform(0, 2 * math.pi)
    r = math.sqrt(1 - z * z)
    return (r * math.cos(p), r * math.sin(p), z)


def write(path, doc):
    with open(path + ".tmp", "w") as f:
        json.dump(doc, f, separators=(",", ":"))
        f.write("\n")
    os.replace(path + ".tmp", path)


def table1(a):
    rng = random.Random(a.seed)
    bodies = []
    for i, centre in enumerate([(0, 0, 0), (8, 0, 0)]):
        axis = rand_axis(rng)
        q0 = qaxis(rand_axis(rng), rng.uniform(0, 2 * math.pi))
        poses = []
        for k in range(a.frames + 1):
            q = qmul(q0, qaxis(axis, k * a.rate))
            poses.append({"position": [str(c) for c in centre], "orientation": [dec(x, 6) for x in q]})
        bodies.append({"name": f"e{i}", "shape": {"semi_axes": ["3", "3", "5"]}, "poses": poses})
    write(a.out, {"format": "ellipse-ccd-animation/1", "name": f"table1-rate-{a.rate}", "dim": 3,
                  "times": [str(k) for k in range(a.frames + 1)], "bodies": bodies, "pairs": "all",
                  "note": f"paper 000 Table 1 set-up: semi-axes 3,3,5, centres 8 apart, random axes (seed {a.seed}), {a.rate} rad per frame"})


def table2(a):
    keys = [(dec(a.radius * math.cos(0.01 * k), 6), dec(a.radius * math.sin(0.01 * k), 6)) for k in range(a.frames + 1)]
    ident = ["1", "0", "0", "0"]
    sphere = {"name": "sphere", "shape": {"semi_axes": ["1", "1", "1"]},
              "poses": [{"position": [x, y, "0"], "orientation": ident} for x, y in keys]}
    ell = {"name": "ellipsoid", "shape": {"semi_axes": ["4.5", "4", "2"]},
           "poses": [{"position": ["0", "0", "0"], "orientation": ident}] * (a.frames + 1)}
    write(a.out, {"format": "ellipse-ccd-animation/1", "name": "table2-orbit", "dim": 3,
                  "times": [str(k) for k in range(a.frames + 1)], "bodies": [sphere, ell], "pairs": "all",
                  "note": f"paper 000 Table 2 set-up: sphere r=1 orbiting at radius {a.radius}, 0.01 rad per frame"})
    if a.scenes:
        os.makedirs(a.scenes, exist_ok=True)
        for k in range(a.frames):
            (x0, y0), (x1, y1) = keys[k], keys[k + 1]
            lin = lambda p, q: [p, str(F(q) - F(p))]
            scene = {"format": "ellipse-ccd-scene/1", "name": f"table2-frame-{k}", "dim": 3,
                     "a": {"shape": {"semi_axes": ["1", "1", "1"]},
                           "motion": {"type": "matrix", "m": [["1", "0", "0", lin(x0, x1)], ["0", "1", "0", lin(y0, y1)],
                                                              ["0", "0", "1", "0"], ["0", "0", "0", "1"]]}},
                     "b": {"shape": {"semi_axes": ["4.5", "4", "2"]}, "motion": {"type": "static"}}}
            write(os.path.join(a.scenes, f"frame-{k}.json"), scene)


# A figure: (name, parent joint name or None, semi-axes, length along the segment, base angle, amplitude, freq, phase)
# Angles: from straight down (0), positive towards +x (the opponent), about y.
# Joints: "hip" (0, 0, 1.0) and "shoulder-l/r" on the torso; each segment's end is its child's joint.
LIMBS = [
    # arms (l: y = +0.22, r: y = -0.22): upper arm, forearm, glove, thumb
    ("upper-arm-{s}", "shoulder-{s}", (0.05, 0.05, 0.15), 0.30, 0.9, 0.5, 1 / 20, 0.0),
    ("forearm-{s}", "elbow-{s}", (0.045, 0.045, 0.13), 0.26, 1.5, 0.6, 1 / 20, 0.3),
    ("glove-{s}", "wrist-{s}", (0.07, 0.06, 0.06), 0.0, 1.5, 0.6, 1 / 20, 0.3),
    ("thumb-{s}", "wrist-{s}", (0.02, 0.02, 0.04), 0.05, 1.2, 0.6, 1 / 20, 0.3),
    # legs: thigh, shin, foot
    ("thigh-{s}", "hip-{s}", (0.08, 0.08, 0.22), 0.44, 0.1, 0.25, 1 / 40, 0.0),
    ("shin-{s}", "knee-{s}", (0.06, 0.06, 0.21), 0.42, -0.1, 0.2, 1 / 40, 0.5),
    ("foot-{s}", "ankle-{s}", (0.05, 0.05, 0.12), 0.0, 1.5708, 0.0, 1 / 40, 0.0),
]
CHILD = {"upper-arm": "elbow", "forearm": "wrist", "thigh": "knee", "shin": "ankle"}
# Torso parts: name, semi-axes, centre relative to the pelvis centre (0, 0, 1.0)
TORSO = [("pelvis", (0.16, 0.12, 0.1), (0, 0, 0)), ("abdomen", (0.14, 0.12, 0.12), (0, 0, 0.2)),
         ("chest", (0.17, 0.12, 0.15), (0, 0, 0.45)), ("neck", (0.05, 0.05, 0.06), (0, 0, 0.66)),
         ("head", (0.1, 0.09, 0.12), (0, 0, 0.82)), ("jaw", (0.06, 0.05, 0.04), (0.03, 0, 0.72)),
         ("shoulder-l", (0.07, 0.07, 0.07), (0, 0.22, 0.55)), ("shoulder-r", (0.07, 0.07, 0.07), (0, -0.22, 0.55)),
         ("hip-l", (0.07, 0.07, 0.07), (0, 0.1, -0.05)), ("hip-r", (0.07, 0.07, 0.07), (0, -0.1, -0.05))]


def figure_pose(k, phase):
    """[(name, semi_axes, centre, quaternion)] of one figure at key k (facing +x)."""
    sway = 0.08 * math.sin(2 * math.pi * (k / 40 + phase))
    out, joints = [], {}
    base = (0.0, 0.0, 1.0)
    for name, axes, off in TORSO:
        c = (base[0] + off[0] + (sway if name not in ("pelvis", "hip-l", "hip-r") else 0), base[1] + off[1], base[2] + off[2])
        out.append((name, axes, c, (1.0, 0.0, 0.0, 0.0)))
        if name.startswith("shoulder") or name.startswith("hip"):
            joints[name] = c
    for side in ("l", "r"):
        sgn = 1 if side == "l" else -1
        for name, parent, axes, length, ang0, amp, freq, ph in LIMBS:
            n, p = name.format(s=side), parent.format(s=side)
            ang = ang0 + amp * math.sin(2 * math.pi * (freq * k + phase) + ph + (math.pi if sgn < 0 else 0))
            j = joints[p]
            d = (math.sin(ang), 0.0, -math.cos(ang))  # the segment's direction (down at angle 0)
            half = max(length, 2 * axes[2]) / 2
            c = (j[0] + d[0] * half, j[1], j[2] + d[2] * half)
            out.append((n, axes, c, qaxis((0, 1, 0), -ang + math.pi)))  # the body's z along -d... any consistent choice
            key = name.split("-{s}")[0]
            if key in CHILD:
                joints[f"{CHILD[key]}-{side}"] = (j[0] + d[0] * length, j[1], j[2] + d[2] * length)
    return out


def boxers(a):
    if a.subdivide < 1:
        sys.exit("make_repro.py boxers: --subdivide must be at least 1")
    times = [str(k) for k in range(a.frames + 1)]
    bodies = []
    for g, (phase, turn, shift) in enumerate([(0.0, False, 0.0), (0.37, True, 1.0)]):
        per_key = [figure_pose(k / a.subdivide, phase) for k in range(a.frames + 1)]
        for b in range(len(per_key[0])):
            name, axes = per_key[0][b][0], per_key[0][b][1]
            poses = []
            for k in range(a.frames + 1):
                _, _, c, q = per_key[k][b]
                if turn:  # a half turn about z, then shift along x
                    c = (shift - c[0], -c[1], c[2])
                    q = qmul((0.0, 0.0, 0.0, 1.0), q)
                poses.append({"position": [dec(x, 4) for x in c], "orientation": [dec(x, 6) for x in q]})
            bodies.append({"name": f"b{g + 1}-{name}", "group": f"boxer-{g + 1}",
                           "shape": {"semi_axes": [dec(x, 3) for x in axes]}, "poses": poses})
    assert len(bodies) == 48, len(bodies)
    write(a.out, {"format": "ellipse-ccd-animation/1", "name": "boxers", "dim": 3, "times": times, "bodies": bodies,
                  "pairs": "between-groups", "note": "paper 001 section 5 in spirit: two figures of 24 ellipsoids (make_repro.py)"})


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("table1")
    p.add_argument("--rate", type=float, required=True)
    p.add_argument("--frames", type=int, default=10000)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("out")
    p = sub.add_parser("table2")
    p.add_argument("--frames", type=int, default=629)
    p.add_argument("--radius", type=float, default=5.3)
    p.add_argument("--scenes")
    p.add_argument("out")
    p = sub.add_parser("boxers")
    p.add_argument("--frames", type=int, default=1000)
    p.add_argument("--subdivide", type=int, default=1)
    p.add_argument("out")
    a = ap.parse_args()
    {"table1": table1, "table2": table2, "boxers": boxers}[a.cmd](a)


if __name__ == "__main__":
    main()
