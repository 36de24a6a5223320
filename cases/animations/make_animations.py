#!/usr/bin/env python3
"""Writes the shipped example animations (docs/animation-format.md).

  two-rows-3d.json  12 ellipsoids in two groups ("left", "right") of six,
                    51 key times (50 frames), pairs "between-groups" (36 pairs
                    per frame). The rows stand 5 apart (x = -2.5 and 2.5, y =
                    0, 2.5, ..., 12.5); four bodies punch across, by translation
                    only: left-0 diagonally into right-1 (frames 2-14, peak at
                    key 8), left-2 into right-2 (10-30, peak 20), left-5 under
                    right-5, 0.05 short of it (18-34, peak 26: a near miss),
                    right-4 into left-4 (28-48, peak 38). right-2 turns slowly
                    about z with a fixed centre; left-4 breathes (an affine
                    deformation diag(1 + s/4, 1 - s/5, 1), fixed centre);
                    right-5 stands still; the others turn slowly in place. Each
                    body either translates or turns in a frame, never both, so
                    every motion has degree <= 2 and exact mode stays cheap; the
                    bounding spheres drop every pair that is not a punching pair
                    near another body.
  swarm-2d.json     5 ellipses in the plane, 21 key times (20 frames), pairs
                    "all": three turn in place, two cross the field; some pairs
                    collide in some frames.

Every number is an exact decimal or fraction written as a string (no floating
point is used: fractions.Fraction throughout). Run from this folder:
    python3 make_animations.py
"""
import json
import re
from fractions import Fraction as F


def num(x):
    x = F(x)
    if x.denominator == 1:
        return str(x.numerator)
    d = x.denominator
    # a terminating decimal when the denominator is 2^a 5^b
    k = d
    for p in (2, 5):
        while k % p == 0:
            k //= p
    if k == 1:
        digits = 0
        while (x * 10**digits).denominator != 1:
            digits += 1
        n = x * 10**digits
        s = str(abs(n.numerator)).rjust(digits + 1, "0")
        out = s[:-digits] + "." + s[-digits:]
        return ("-" if x < 0 else "") + out
    return f"{x.numerator}/{x.denominator}"


def bump(k, lo, peak, hi):
    """Piecewise linear 0 -> 1 -> 0 over key times lo..peak..hi (key index k)."""
    if k <= lo or k >= hi:
        return F(0)
    if k <= peak:
        return F(k - lo, peak - lo)
    return F(hi - k, hi - peak)


def turn_z(k, rate):
    """A quaternion [w, 0, 0, z] turning about z: z/w = rate*k (not unit; exact)."""
    return [F(1), F(0), F(0), F(rate) * k]


def write(path, doc):
    """Indented JSON with each array of numbers (and of number arrays) on one line."""
    text = json.dumps(doc, indent=1)
    flat = lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]"
    for _ in range(2):  # rows of a deformation, then the matrix
        text = re.sub(r"\[\s+([^\[\]{}]*?)\s+\]", flat, text)
    with open(path, "w") as f:
        f.write(text + "\n")


def rows_3d():
    K = 50
    times = [num(F(k, 25)) for k in range(K + 1)]
    bodies = []
    semi = [["0.9", "0.6", "0.5"], ["0.7", "0.7", "0.5"], ["0.9", "0.5", "0.6"],
            ["0.6", "0.8", "0.5"], ["0.8", "0.6", "0.6"], ["0.7", "0.5", "0.7"]]
    for side, x0 in (("left", F(-5, 2)), ("right", F(5, 2))):
        for i in range(6):
            name = f"{side}-{i}"
            y = F(5, 2) * i
            poses = []
            for k in range(K + 1):
                pos = [x0, y, F(0)]
                q = [F(1), F(0), F(0), F(0)]
                deform = None
                if name == "left-0":  # punches right-1 diagonally: translation only
                    b = bump(k, 2, 8, 14)
                    pos[0] = x0 + F(37, 10) * b
                    pos[1] = y + F(5, 2) * b
                elif name == "left-2":  # punches right-2: translation only
                    pos[0] = x0 + F(36, 10) * bump(k, 10, 20, 30)
                elif name == "left-5":  # under right-5, 0.05 short at the peak (semi-axes 0.5 in y both)
                    b = bump(k, 18, 26, 34)
                    pos[0] = x0 + 5 * b
                    pos[1] = y - F(105, 100) * b
                    q = [F(1), F(0), F(0), F(0)]
                elif name == "right-5":  # stands still
                    pass
                elif name == "right-4":  # punches left-4: translation only
                    pos[0] = x0 - F(36, 10) * bump(k, 28, 38, 48)
                    pos[1] = y + F(1, 10) * bump(k, 28, 38, 48)
                elif name == "right-2":  # turns about z in place
                    q = turn_z(k, F(1, 40))
                elif name == "left-4":  # breathes in place (affine deformation)
                    s = bump(k, 30, 38, 46)
                    deform = [[1 + s / 4, 0, 0], [0, 1 - s / 5, 0], [0, 0, 1]]
                    q = [F(1), F(0), F(1, 10), F(0)]
                else:  # turns slowly in place about an axis of its own
                    axis = [F(0), F(1 + i % 2), F(i % 3), F(1)]
                    q = [F(1)] + [a * F(k, 100) for a in axis[1:]]
                pose = {"position": [num(v) for v in pos], "orientation": [num(v) for v in q]}
                if deform is not None:
                    pose["deformation"] = [[num(v) for v in row] for row in deform]
                poses.append(pose)
            bodies.append({"name": name, "group": side, "shape": {"semi_axes": semi[i]}, "poses": poses})
    return {
        "format": "ellipse-ccd-animation/1",
        "name": "two-rows-3d",
        "dim": 3,
        "times": times,
        "bodies": bodies,
        "pairs": "between-groups",
        "note": "cases/animations/make_animations.py: two rows of six ellipsoids 5 apart; left-0 punches right-1 "
                "(frames 2-14), left-2 right-2 (10-30), left-5 passes under right-5, 0.05 apart (18-34), right-4 punches "
                "left-4 (28-48); 50 frames",
    }


def swarm_2d():
    K = 20
    times = [num(F(k, 20)) for k in range(K + 1)]
    spec = [  # name, semi-axes, centre at key k, orientation [w, z] at key k
        ("a", ["1.5", "0.5"], lambda k: [F(0), F(0)], lambda k: [F(1), F(k, 10)]),
        ("b", ["1", "0.6"], lambda k: [F(4), F(0)], lambda k: [F(1), F(-k, 15)]),
        ("c", ["0.8", "0.8"], lambda k: [F(2), F(3)], lambda k: [F(1), F(0)]),
        ("d", ["0.7", "0.4"], lambda k: [F(-4) + F(2, 5) * k, F(-1, 2)], lambda k: [F(1), F(0)]),
        ("e", ["0.5", "0.3"], lambda k: [F(2), F(6) - F(3, 10) * k], lambda k: [F(1), F(1, 2)]),
    ]
    bodies = []
    for name, semi, c, q in spec:
        poses = [{"position": [num(v) for v in c(k)], "orientation": [num(v) for v in q(k)]} for k in range(K + 1)]
        bodies.append({"name": name, "shape": {"semi_axes": semi}, "poses": poses})
    return {
        "format": "ellipse-ccd-animation/1",
        "name": "swarm-2d",
        "dim": 2,
        "times": times,
        "bodies": bodies,
        "pairs": "all",
        "note": "cases/animations/make_animations.py: a and b turn in place, c stands still, d crosses along y = -1/2, "
                "e falls along x = 2; 20 frames",
    }


if __name__ == "__main__":
    write("two-rows-3d.json", rows_3d())
    write("swarm-2d.json", swarm_2d())
