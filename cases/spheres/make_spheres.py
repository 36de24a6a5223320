#!/usr/bin/env python3
"""Writes sphere-sphere scenes (dim 3) whose collision sets are known exactly.

Two balls of radii r_A, r_B with centres c_A(t), c_B(t) meet iff
    D(t) = |c_A(t) - c_B(t)|^2 - (r_A + r_B)^2 <= 0,
they touch externally iff D(t) = 0, and one lies inside the other iff
|c_A - c_B| <= |r_A - r_B|. With linear centres D is a quadratic in t, so every
instant below is rational or a quadratic irrationality, and the script checks
each claim with exact rational arithmetic (fractions) before writing anything:
the coefficients of D, the sign of D at 0 and 1, that the roots in (0, 1) are
the ones named and, where they are said to be irrational, that the discriminant
of the integer quadratic is not a perfect square. The roots are printed in the
notes to 20 decimals (decimal module, 60 digits of working precision).

Shapes: {"semi_axes": [r, r, r]}.

Motions: type "matrix", M(t) = [[1,0,0,x(t)], [0,1,0,y(t)], [0,0,1,z(t)],
[0,0,0,1]] with x, y, z of degree <= 1 (or "static" for a ball fixed at the
origin). Chosen over "euler" with e = [1, 0, 0, 0]: the matrix form is what
every motion form is turned into (scene-format.md), so these scenes say
literally what the solver sees -- a degree-1 motion with w = 1 and a constant
identity block -- without going through the quaternion formula and its E(t);
the euler path is exercised by cases/paper002 and cases/touch3d.

Scenes (A is the first ball, B the second):
  spheres-crossing        r = 1, 2; A from (-4, 0.5, 0.25) to (4, 0.5, 0.25), B
                          static at the origin. D = (1024t^2 - 1024t + 117)/16,
                          one interval [1/2 - sqrt(139)/32, 1/2 + sqrt(139)/32],
                          both ends external contacts (irrational).
  spheres-touch           r = 1, 2; c_A = (-4 + 8t, 1.2, 0.9), c_B = (4 - 8t, -1.2,
                          -0.9). D = (16t - 8)^2, touch at t = 1/2 only, at the
                          point (0, 0.4, 0.3).
  spheres-free            r = 1, 2; c_A = (-4 + 8t, 1.6, 1.2), c_B = (4 - 8t, -1.6,
                          -1.2). D = (16t - 8)^2 + 7 > 0: minimum centre distance
                          4 > 3, never meet.
  spheres-overlap-start   r = 1, 2; c_A = (1 + 2t, 0.6, 0.8), c_B = (-2t, 0, 0).
                          D = 16t^2 + 8t - 7, overlapping at t = 0, separating at
                          (2 sqrt(2) - 1)/4 (external contact).
  spheres-overlap-end     r = 2, 1; A static at the origin, c_B = (5 - 4t, 0.6, 0.8).
                          D = 16t^2 - 40t + 17, separate at 0, first contact at
                          (5 - 2 sqrt(2))/4, overlapping up to t = 1.
  spheres-touch-at-start  r = 1, 2; c_A = (1.8 + 0.6t, 2.4 + 0.8t, 0), B static.
                          |c_A| = 3 + t: touch at t = 0 only (isolated instant at
                          the end of the domain), at (1.2, 1.6, 0).
  spheres-inside-touch-at-start
                          r = 1, 3; c_A = (1.2 - 0.6t, 1.6 - 0.8t, 0), B static.
                          |c_A| = 2 - t <= 2 = r_B - r_A: A inside B for all t,
                          internally tangent at t = 0 (interiors overlap, so not
                          an external contact). C = [0, 1], no contacts.

Note for the solver: for two balls the upper-left 3x3 block of lambda A(t) - B(t)
is (lambda/r_A^2 - 1/r_B^2) I, so (lambda - r_A^2/r_B^2)^2 divides
f(lambda; t) = det(lambda A(t) - B(t)) for every t: f has a positive double
root at every instant and its discriminant in lambda vanishes identically. These
scenes therefore also exercise the degenerate path (square-free part of f, or
whatever the solver does instead); the negative roots still decide the status.

Numbers are exact decimal strings (scene-format.md). Run from anywhere; the files
are written next to this script. `eccd solve FILE --arith exact --write-answer`
stores the exact answers.
"""
import math
import os
from decimal import Decimal, getcontext
from fractions import Fraction as F
import os as _os
import sys as _sys
_sys.path.insert(0, _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), ".."))
from scenelib import num, write as write_in  # noqa: E402


def write(s):
    write_in(s, _os.path.dirname(_os.path.abspath(__file__)))


getcontext().prec = 60
HERE = os.path.dirname(os.path.abspath(__file__))


def poly(c):
    """Coefficients low degree first; trailing zeros dropped; a constant as a bare string."""
    c = [F(v) for v in c]
    while len(c) > 1 and c[-1] == 0:
        c.pop()
    return num(c[0]) if len(c) == 1 else [num(v) for v in c]


def translating(c):
    """matrix motion x -> x + c(t); c = three (c0, c1) pairs, c(t) = c0 + c1 t."""
    if all(F(v) == 0 for p in c for v in p):
        return {"type": "static"}
    m = [["1" if i == j else "0" for j in range(3)] + [poly(c[i])] for i in range(3)]
    return {"type": "matrix", "m": m + [["0", "0", "0", "1"]]}


def ball(r, c):
    return {"shape": {"semi_axes": [num(r)] * 3}, "motion": translating(c)}


def D(rA, cA, rB, cB):
    """|c_A(t) - c_B(t)|^2 - (r_A + r_B)^2 as exact power coefficients [d0, d1, d2]."""
    d = [0, 0, 0]
    for (a0, a1), (b0, b1) in zip(cA, cB):
        u0, u1 = F(a0) - F(b0), F(a1) - F(b1)
        d[0] += u0 * u0
        d[1] += 2 * u0 * u1
        d[2] += u1 * u1
    d[0] -= (F(rA) + F(rB)) ** 2
    return d


def pv(p, t):
    return sum(F(c) * F(t) ** i for i, c in enumerate(p))


def integer_quadratic(d):
    """d scaled to coprime integers (a, b, c), a > 0: a t^2 + b t + c."""
    den = math.lcm(*[F(v).denominator for v in d])
    a, b, c = [int(F(v) * den) for v in reversed(d)]
    g = math.gcd(a, math.gcd(b, c))
    s = 1 if a > 0 else -1
    return a // g * s, b // g * s, c // g * s


def roots20(a, b, c):
    """The two real roots of a t^2 + b t + c (disc > 0), as Decimals."""
    sq = Decimal(b * b - 4 * a * c).sqrt()
    return sorted([(-Decimal(b) - sq) / (2 * a), (-Decimal(b) + sq) / (2 * a)])


def d20(x):
    return str(x.quantize(Decimal(10) ** -20))


def qstr(a, b, c):
    """a t^2 + b t + c as text, e.g. 16t^2 + 8t - 7."""
    out = "t^2" if a == 1 else f"{a}t^2"
    for k, p in ((b, "t"), (c, "")):
        if k:
            out += (" - " if k < 0 else " + ") + (str(abs(k)) if (abs(k) != 1 or not p) else "") + p
    return out


def check_irrational_crossing(d, n_expected):
    """Checks: 2 distinct real roots, n_expected of them in (0, 1), integer discriminant not a square."""
    a, b, c = integer_quadratic(d)
    disc = b * b - 4 * a * c
    assert disc > 0, "no two distinct real roots"
    assert math.isqrt(disc) ** 2 != disc, "roots are rational"
    rs = roots20(a, b, c)
    inside = [r for r in rs if 0 < r < 1]
    assert len(inside) == n_expected, (rs, n_expected)
    return a, b, c, disc, rs


scenes = []


def add(name, rA, cA, rB, cB, note):
    scenes.append({
        "format": "ellipse-ccd-scene/1",
        "name": name,
        "dim": 3,
        "a": ball(rA, cA),
        "b": ball(rB, cB),
        "note": note,
    })


src = ("Sphere-sphere scene with linear translations, written by cases/spheres/make_spheres.py. "
       "D(t) = |c_A(t) - c_B(t)|^2 - (r_A + r_B)^2; the balls meet iff D(t) <= 0. ")

# --- crossing: two irrational contacts in (0, 1)
rA, cA, rB, cB = 1, [(-4, 8), ("0.5", 0), ("0.25", 0)], 2, [(0, 0)] * 3
d = D(rA, cA, rB, cB)
a, b, c, disc, rs = check_irrational_crossing(d, 2)
assert (a, b, c) == (1024, -1024, 117) and d == [F(117, 16), -64, 64]
assert pv(d, 0) > 0 and pv(d, 1) > 0 and 0 < F(-b, 2 * a) < 1
# roots 1/2 -+ sqrt(139)/32
assert disc == 64**2 * 139
lo, hi = rs
assert abs(lo - (Decimal("0.5") - Decimal(139).sqrt() / 32)) < Decimal("1e-50")
add("spheres-crossing", rA, cA, rB, cB, src +
    "Radii 1 and 2; A moves from (-4, 0.5, 0.25) to (4, 0.5, 0.25), B is static at the origin. "
    f"16 D(t) = {qstr(a, b, c)} (discriminant 1024*556 = 64^2*139, not a square), roots t = 1/2 -+ sqrt(139)/32 = "
    f"{d20(lo)}, {d20(hi)}. Separate at t = 0 and t = 1. Collision set: one interval "
    f"[1/2 - sqrt(139)/32, 1/2 + sqrt(139)/32] = [{d20(lo)}, {d20(hi)}]; first contact {d20(lo)}; "
    "external contacts at both ends (irrational instants).")

# --- touch at exactly 1/2
rA, cA, rB, cB = 1, [(-4, 8), ("1.2", 0), ("0.9", 0)], 2, [(4, -8), ("-1.2", 0), ("-0.9", 0)]
d = D(rA, cA, rB, cB)
assert d == [64, -256, 256]            # (16t - 8)^2 >= 0, zero only at t = 1/2
assert pv(d, F(1, 2)) == 0
add("spheres-touch", rA, cA, rB, cB, src +
    "Radii 1 and 2; c_A = (-4 + 8t, 1.2, 0.9), c_B = (4 - 8t, -1.2, -0.9). D(t) = (16t - 8)^2: the centre distance "
    "is sqrt((16t - 8)^2 + 9) >= 3 = r_A + r_B with equality only at t = 1/2. Collision set {1/2} (exactly): "
    "intervals [[1/2, 1/2]], first contact 1/2, one external contact at t = 1/2 at the point (0, 0.4, 0.3).")

# --- never meet
rA, cA, rB, cB = 1, [(-4, 8), ("1.6", 0), ("1.2", 0)], 2, [(4, -8), ("-1.6", 0), ("-1.2", 0)]
d = D(rA, cA, rB, cB)
assert d == [71, -256, 256] and 71 * 256 * 4 > 256**2   # min D = 7 at t = 1/2
assert pv(d, F(1, 2)) == 7
add("spheres-free", rA, cA, rB, cB, src +
    "Radii 1 and 2; c_A = (-4 + 8t, 1.6, 1.2), c_B = (4 - 8t, -1.6, -1.2). D(t) = (16t - 8)^2 + 7 >= 7: the "
    "centre distance is at least 4 > 3 = r_A + r_B (gap 1 at t = 1/2). Collision set empty: collides false, "
    "no intervals, no first contact, no contacts.")

# --- overlapping at 0, separating at an irrational instant
rA, cA, rB, cB = 1, [(1, 2), ("0.6", 0), ("0.8", 0)], 2, [(0, -2), (0, 0), (0, 0)]
d = D(rA, cA, rB, cB)
a, b, c, disc, rs = check_irrational_crossing(d, 1)
assert (a, b, c) == (16, 8, -7) and pv(d, 0) < 0 and pv(d, 1) > 0
assert disc == 512 and rs[1] > 0 > rs[0]
t1 = rs[1]
assert abs(t1 - (2 * Decimal(2).sqrt() - 1) / 4) < Decimal("1e-50")
add("spheres-overlap-start", rA, cA, rB, cB, src +
    "Radii 1 and 2; c_A = (1 + 2t, 0.6, 0.8), c_B = (-2t, 0, 0), so c_A - c_B = (1 + 4t, 0.6, 0.8). "
    f"D(t) = {qstr(a, b, c)} (discriminant 512, not a square), roots t = (-1 -+ 2 sqrt(2))/4; the one in [0, 1] is "
    f"(2 sqrt(2) - 1)/4 = {d20(t1)} (the other is {d20(rs[0])}). Overlapping at t = 0 (D(0) = -7), separate at t = 1. "
    f"Collision set: [0, (2 sqrt(2) - 1)/4] = [0, {d20(t1)}]; first contact 0 (exactly); one external contact, "
    f"at (2 sqrt(2) - 1)/4 (the instant they separate; t = 0 is not a contact, they overlap there).")

# --- separate at 0, entering at an irrational instant, overlapping at 1
rA, cA, rB, cB = 2, [(0, 0)] * 3, 1, [(5, -4), ("0.6", 0), ("0.8", 0)]
d = D(rA, cA, rB, cB)
a, b, c, disc, rs = check_irrational_crossing(d, 1)
assert (a, b, c) == (16, -40, 17) and pv(d, 0) > 0 and pv(d, 1) < 0
assert disc == 512 and 0 < rs[0] < 1 < rs[1]
t0 = rs[0]
assert abs(t0 - (5 - 2 * Decimal(2).sqrt()) / 4) < Decimal("1e-50")
add("spheres-overlap-end", rA, cA, rB, cB, src +
    "Radii 2 (A, static at the origin) and 1 (B); c_B = (5 - 4t, 0.6, 0.8). "
    f"D(t) = {qstr(a, b, c)} (discriminant 512, not a square), roots t = (5 -+ 2 sqrt(2))/4; the one in [0, 1] is "
    f"(5 - 2 sqrt(2))/4 = {d20(t0)} (the other is {d20(rs[1])}). Separate at t = 0 (D(0) = 17), overlapping at t = 1 "
    f"(D(1) = -7). Collision set: [(5 - 2 sqrt(2))/4, 1] = [{d20(t0)}, 1]; first contact {d20(t0)}; one external "
    "contact, at (5 - 2 sqrt(2))/4 (t = 1 is not a contact, they overlap there).")

# --- external touch at t = 0 only
rA, cA, rB, cB = 1, [("1.8", "0.6"), ("2.4", "0.8"), (0, 0)], 2, [(0, 0)] * 3
d = D(rA, cA, rB, cB)
assert d == [0, 6, 1]                  # (3 + t)^2 - 9 = t (t + 6)
add("spheres-touch-at-start", rA, cA, rB, cB, src +
    "Radii 1 and 2; c_A = (1.8 + 0.6t, 2.4 + 0.8t, 0) = (3 + t)(0.6, 0.8, 0), B static at the origin. "
    "D(t) = t^2 + 6t = t(t + 6): zero at t = 0, positive on (0, 1]. Collision set {0}: intervals [[0, 0]], "
    "first contact 0, one external contact at t = 0 at the point (1.2, 1.6, 0). An isolated touch at the end "
    "of the time domain.")

# --- A inside B, internally tangent at t = 0
rA, cA, rB, cB = 1, [("1.2", "-0.6"), ("1.6", "-0.8"), (0, 0)], 3, [(0, 0)] * 3
for t in (F(0), F(1, 3), F(1)):
    dist2 = (F("1.2") - F("0.6") * t) ** 2 + (F("1.6") - F("0.8") * t) ** 2
    assert dist2 == (2 - t) ** 2 and dist2 <= (rB - rA) ** 2 and dist2 > 0
add("spheres-inside-touch-at-start", rA, cA, rB, cB, src +
    "Radii 1 (A) and 3 (B, static at the origin); c_A = (1.2 - 0.6t, 1.6 - 0.8t, 0) = (2 - t)(0.6, 0.8, 0). "
    "|c_A| = 2 - t <= 2 = r_B - r_A: A lies inside B for all t in [0, 1], internally tangent at t = 0 (at the point "
    "(1.8, 2.4, 0)); never concentric. Collision set: [0, 1]; first contact 0; no external contacts (the "
    "interiors overlap at every instant, the tangency at t = 0 is internal).")


for s in scenes:
    write(s)
print("wrote", len(scenes), "scenes to", HERE)
