#!/usr/bin/env python3
"""Writes 3D ellipsoid scenes built so that the collision set is known by construction.

touch-and-separate.json -- a single external touch at exactly t = 1/2.
  A: semi-axes (3, 2, 1), static (axis-aligned, centred at the origin).
  B: semi-axes (1, 2, 3), motion `euler` with e = [1, t - 1/2, 0, 0] and
     translation (4, 2t - 1, t - 1/2) (translation_denominator 1).
  Why it touches only at t = 1/2: e = (e0, e1, 0, 0) is a rotation about the
  x-axis; its first row is ((e0^2 + e1^2)/E, 0, 0) = (1, 0, 0), so world x =
  object x + 4 and B(t) lies in {x >= 3} for every t; its only point with x = 3
  is the image of the object point (-1, 0, 0), which the rotation fixes, i.e.
  (3, 2t - 1, t - 1/2). A lies in {x <= 3} and A n {x = 3} = {(3, 0, 0)}
  (x^2/9 = 1 forces y = z = 0). So A(t) n B(t) is empty unless
  (3, 2t - 1, t - 1/2) = (3, 0, 0), i.e. t = 1/2, where they meet at (3, 0, 0)
  only, with interiors on opposite sides of the plane x = 3: an external
  contact. At t = 1/2, e = (1, 0, 0, 0): B is axis-aligned, centred at (4, 0, 0).
  E = t^2 - t + 5/4 >= 1 never vanishes. Expected answer: collides, intervals
  [[1/2, 1/2]], first contact 1/2, contacts [1/2] at (3, 0, 0).

touch-and-separate-rotated.json -- the same scene moved by one fixed rigid motion
  G: x -> R_G x + g, R_G the rotation of the (non-unit) quaternion (1, 2, 2, 4)
  (E_G = 25, R_G = (1/25)[[-15, 0, 20], [16, -15, 12], [12, 20, 9]]) and
  g = (2, -3, 8)/4 = (0.5, -0.75, 2). A common rigid motion does not change
  whether, or where relative to each other, the two meet, and
  det(lambda G^-T A G^-1 - G^-T B G^-1) = det(G)^-2 det(lambda A - B): f has
  the same roots at every t. So the answer is the same -- a single external touch
  at t = 1/2 -- at the point G(3, 0, 0) = (-1.3, 1.17, 3.44).
  A: `euler`, constant e = [1, 2, 2, 4], translation [2, -3, 8],
     translation_denominator 4.
  B: `matrix`, M(t) = G_h M_B(t) where M_B(t) = [[R_num(t), E(t) V(t)],
     [0, E(t)]] (R_num = E R, the spec's euler matrix before dividing by E) is
     B's homogeneous polynomial matrix above and G_h = [[4 R_num_G, 25 (2, -3, 8)],
     [0, 100]] is G's (= 100 [[R_G, g], [0, 1]]); the product, whose last row is
     (0, 0, 0, 100 E(t)), is scaled to coprime integer coefficients (a constant
     factor of a homogeneous matrix changes nothing). The script checks, with
     exact fractions, that M(t) maps object points exactly as R_G (R_B(t) p +
     V_B(t)) + g at several t.

touch-then-overlap.json -- separate, overlapping on one sub-interval, separate.
  A: semi-axes (3, 2, 1), static. B: semi-axes (1, 2.5, 3), tilted by the
  constant quaternion e = [2, 0, 1, 0] (rotation about the y-axis with cos = 3/5,
  sin = 4/5), moving straight along y: translation (3.5, 12t - 6, 0.5). B's y
  semi-axis stays along y, so at t = 0 (t = 1) B lies in y <= -3.5 (y >= 3.5)
  and A in |y| <= 2: separate at both ends; at t = 1/2 the point
  (2.6, 0, 0.2) lies in both (A: 0.7511 + 0.04 < 1; it is 0.9487 < 1 from B's
  centre, and B contains the unit ball about its centre): overlapping. B
  sweeps past A's +x side. Expected shape: one collision interval [t0, t1] with
  external contacts at t0 and t1 and 0 < t0 < 1/2 < t1 < 1. Symmetry: the
  reflection S: y -> -y maps A to itself and B(t) to B(1 - t) (S commutes with
  rotations about y, and S c(t) = c(1 - t)), so t1 = 1 - t0 exactly. t0 is an
  algebraic number without a closed form here; exact classification with
  bisection gives t0 = 0.21397195728811957414..., t1 = 1 - t0 =
  0.78602804271188042586... (--check reproduces them to 15 digits).

overlap-on-axis.json -- an ellipsoid pair with an exactly known irrational interval.
  A: semi-axes (3, 2, 1), static. B: semi-axes (1, 2.5, 1.5), rotating about the
  x-axis with e = [1, t, 0, 0] (0 to 90 degrees), centre (d(t), 0, 0) with
  d(t) = 8t^2 - 8t + 5 (5 at the ends, 3 at t = 1/2). Both A and every B(t) are
  mapped to themselves by the half-turn H: (x, y, z) -> (x, -y, -z) about the
  x-axis (it commutes with rotations about x). If p lies in A n B(t), so does
  H p, and by convexity (p + H p)/2 = (p_x, 0, 0): the intersection is non-empty
  iff it meets the x-axis, i.e. iff [-3, 3] and [d - 1, d + 1] overlap, iff
  d(t) <= 4 (d >= 3 > -4 always), iff 8t^2 - 8t + 1 <= 0. Expected answer: one
  interval [1/2 - sqrt(2)/4, 1/2 + sqrt(2)/4] = [0.14644660940672623780,
  0.85355339059327376220], external contacts at both ends (at (3, 0, 0): the
  tangent planes of A and B there are both x = 3, interiors on either side).

Numbers are exact decimal strings or p/q (scene-format.md). Run from anywhere;
the files are written next to this script. `python3 make_touch3d.py --check`
also runs an exact classification (Sturm count of the negative roots of
f(lambda; t) = det(lambda A(t) - B(t)) at the instants k/400, rational
bisection on the status changes; pure Python, a few seconds).
`eccd solve FILE --arith exact --write-answer` stores the exact answers.
"""
import json
import math
import os
import sys
from decimal import Decimal, getcontext
from fractions import Fraction as F
import os as _os
import sys as _sys
_sys.path.insert(0, _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), ".."))
from scenelib import charpoly, det, negative_roots, num, pev, prem, write as write_in  # noqa: E402


def write(s):
    write_in(s, _os.path.dirname(_os.path.abspath(__file__)))


HERE = os.path.dirname(os.path.abspath(__file__))


# ------------------------------------------------------------- polynomials in t
def P(p):
    """Scene polynomial (string, or list of strings low degree first) -> list of Fractions."""
    return [F(x) for x in p] if isinstance(p, list) else [F(p)]


def padd(a, b):
    n = max(len(a), len(b))
    return [(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)]


def pmul(a, b):
    r = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return r


def pscale(a, k):
    return [k * x for x in a]


def poly(c):
    c = list(c)
    while len(c) > 1 and c[-1] == 0:
        c.pop()
    return num(c[0]) if len(c) == 1 else [num(v) for v in c]


# ------------------------------------------------------- motions, spec formulas
def euler_hom(e, v, v3="1"):
    """The homogeneous polynomial matrix of the spec's euler motion:
    [[R_num v3, E v], [0, E v3]] with R_num = E R (quaternion rotation before dividing by E)."""
    e0, e1, e2, e3 = [P(x) for x in e]
    v, v3 = [P(x) for x in v], P(v3)
    m = pmul
    def s(*terms):                       # signed sum of products of two polynomials
        r = [F(0)]
        for k, a, b in terms:
            r = padd(r, pscale(m(a, b), k))
        return r
    E = s((1, e0, e0), (1, e1, e1), (1, e2, e2), (1, e3, e3))
    R = [[s((1, e0, e0), (1, e1, e1), (-1, e2, e2), (-1, e3, e3)), s((2, e1, e2), (-2, e0, e3)), s((2, e1, e3), (2, e0, e2))],
         [s((2, e1, e2), (2, e0, e3)), s((1, e0, e0), (-1, e1, e1), (1, e2, e2), (-1, e3, e3)), s((2, e2, e3), (-2, e0, e1))],
         [s((2, e1, e3), (-2, e0, e2)), s((2, e2, e3), (2, e0, e1)), s((1, e0, e0), (-1, e1, e1), (-1, e2, e2), (1, e3, e3))]]
    z = [F(0)]
    return [[pmul(R[i][j], v3) for j in range(3)] + [pmul(E, v[i])] for i in range(3)] + [[z, z, z, pmul(E, v3)]]


def hmul(a, b):
    """Product of two 4x4 polynomial matrices."""
    return [[_sum([pmul(a[i][k], b[k][j]) for k in range(4)]) for j in range(4)] for i in range(4)]


def _sum(ps):
    r = [F(0)]
    for p in ps:
        r = padd(r, p)
    return r


def integer_scaled(m):
    """Scale a polynomial matrix by a positive constant to coprime integer coefficients."""
    coefs = [c for row in m for p in row for c in p]
    den = math.lcm(*[c.denominator for c in coefs])
    g = math.gcd(*[int(c * den) for c in coefs])
    k = F(den, g)
    return [[[c * k for c in p] for p in row] for row in m]


def apply_hom(m, t, p):
    """Dehomogenized image of the object point p under the homogeneous polynomial matrix m at t."""
    x = [sum(pev(m[i][j], t) * p[j] for j in range(3)) + pev(m[i][3], t) for i in range(4)]
    return [x[i] / x[3] for i in range(3)]


# --------------------------------------------------------------------- scenes
def euler(e, v, v3="1"):
    return {"type": "euler", "e": e, "translation": v, "translation_denominator": v3}


def scene(name, a, b, note):
    return {"format": "ellipse-ccd-scene/1", "name": name, "dim": 3, "a": a, "b": b, "note": note}


def obj(axes, motion):
    return {"shape": {"semi_axes": axes}, "motion": motion}


src = "Written by cases/touch3d/make_touch3d.py (the construction is proved in its docstring). "

# 1. touch-and-separate
eB = ["1", ["-0.5", "1"], "0", "0"]
vB = ["4", ["-1", "2"], ["-0.5", "1"]]
A1 = obj(["3", "2", "1"], {"type": "static"})
B1 = obj(["1", "2", "3"], euler(eB, vB))
s1 = scene("touch-and-separate", A1, B1, src + (
    "A: semi-axes (3, 2, 1), static. B: semi-axes (1, 2, 3), rotating about the x-axis (e = [1, t - 1/2, 0, 0]), "
    "centre (4, 2t - 1, t - 1/2). B(t) lies in x >= 3 and touches the plane x = 3 only at (3, 2t - 1, t - 1/2); A "
    "meets x = 3 only at (3, 0, 0). Collision set {1/2} exactly: intervals [[1/2, 1/2]], first contact 1/2, one "
    "external contact at t = 1/2 at the point (3, 0, 0); separate at every other instant."))

# 2. the same, moved by a common rigid motion G
eG, vG, v3G = ["1", "2", "2", "4"], ["2", "-3", "8"], "4"
G_h = euler_hom(eG, vG, v3G)                         # = 100 [[R_G, g], [0, 1]]
MB_h = euler_hom(eB, vB)
M2 = integer_scaled(hmul(G_h, MB_h))
assert all(not any(M2[3][j]) for j in range(3))   # last row (0, 0, 0, w(t))


def R_of(e, t):
    e0, e1, e2, e3 = [pev(P(x), t) for x in e]
    E = e0 * e0 + e1 * e1 + e2 * e2 + e3 * e3
    return [[(e0*e0 + e1*e1 - e2*e2 - e3*e3) / E, 2*(e1*e2 - e0*e3) / E, 2*(e1*e3 + e0*e2) / E],
            [2*(e1*e2 + e0*e3) / E, (e0*e0 - e1*e1 + e2*e2 - e3*e3) / E, 2*(e2*e3 - e0*e1) / E],
            [2*(e1*e3 - e0*e2) / E, 2*(e2*e3 + e0*e1) / E, (e0*e0 - e1*e1 - e2*e2 + e3*e3) / E]]


def rigid(R, c, p):
    return [sum(R[i][j] * p[j] for j in range(3)) + c[i] for i in range(3)]


RG = R_of(eG, 0)
g = [F(x) / F(v3G) for x in vG]
assert [[x * 25 for x in r] for r in RG] == [[-15, 0, 20], [16, -15, 12], [12, 20, 9]]
for t in (F(0), F(1, 5), F(1, 2), F(2, 3), F(1)):
    w = pev(M2[3][3], t)
    assert w > 0
    for p in ([1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [1, 2, 3], [F(-7, 3), F(1, 2), 5]):
        p = [F(x) for x in p]
        composed = rigid(RG, g, rigid(R_of(eB, t), [pev(P(x), t) for x in vB], p))
        assert apply_hom(M2, t, p) == composed, (t, p)
# w(t) = c E_B(t) with E_B = t^2 - t + 5/4 > 0 on [0, 1]
assert M2[3][3][1] == -M2[3][3][2] and M2[3][3][0] * 4 == M2[3][3][2] * 5 and M2[3][3][2] > 0
contact2 = rigid(RG, g, [F(3), F(0), F(0)])
assert contact2 == [F("-1.3"), F("1.17"), F("3.44")]
A2 = obj(["3", "2", "1"], euler(eG, vG, v3G))
B2 = obj(["1", "2", "3"], {"type": "matrix", "m": [[poly(p) for p in row] for row in M2]})
s2 = scene("touch-and-separate-rotated", A2, B2, src + (
    "touch-and-separate.json moved by one fixed rigid motion G: x -> R_G x + g, R_G the rotation of the quaternion "
    "(1, 2, 2, 4) (R_G = (1/25)[[-15, 0, 20], [16, -15, 12], [12, 20, 9]]), g = (2, -3, 8)/4. A: euler with "
    "constant e = [1, 2, 2, 4], translation (2, -3, 8)/4. B: matrix G_h M_B(t), B's euler motion (e = [1, t - 1/2, 0, "
    "0], centre (4, 2t - 1, t - 1/2)) composed with G, scaled to integer coefficients; w(t) is a multiple of "
    "t^2 - t + 5/4. Same f roots at every t as touch-and-separate.json. Collision set {1/2} exactly: intervals "
    "[[1/2, 1/2]], first contact 1/2, one external contact at t = 1/2 at the point G(3, 0, 0) = (-1.3, 1.17, 3.44)."))

# 3. touch-then-overlap
A3 = obj(["3", "2", "1"], {"type": "static"})
B3 = obj(["1", "2.5", "3"], euler(["2", "0", "1", "0"], ["3.5", ["-6", "12"], "0.5"]))
T0, T1 = "0.21397195728811957414", "0.78602804271188042586"   # exact statuses, 75 bisections; T1 = 1 - T0
s3 = scene("touch-then-overlap", A3, B3, src + (
    "A: semi-axes (3, 2, 1), static. B: semi-axes (1, 2.5, 3), tilted about the y-axis by the constant quaternion "
    "(2, 0, 1, 0) (cos 3/5, sin 4/5), moving straight along y past A's +x side: centre (3.5, 12t - 6, 0.5). Separate "
    "at t = 0 and t = 1 (B in y <= -3.5, resp. y >= 3.5; A in |y| <= 2), overlapping at t = 1/2 (both contain "
    "(2.6, 0, 0.2)). Expected: one collision interval [t0, t1], 0 < t0 < 1/2 < t1 < 1, external contacts at t0 and "
    "t1, first contact t0. The reflection y -> -y maps A to A and B(t) to B(1 - t), so t1 = 1 - t0 exactly. "
    f"No closed form; exact classification with bisection when this file was written gives t0 = {T0}..., "
    f"t1 = {T1}... (make_touch3d.py --check)."))

# 4. overlap-on-axis
A4 = obj(["3", "2", "1"], {"type": "static"})
B4 = obj(["1", "2.5", "1.5"], euler(["1", ["0", "1"], "0", "0"], [["5", "-8", "8"], "0", "0"]))
getcontext().prec = 60
r = Decimal(2).sqrt() / 4
lo4, hi4 = [str((Decimal("0.5") + s * r).quantize(Decimal(10) ** -20)) for s in (-1, 1)]
assert 8 * (Decimal(lo4)) ** 2 - 8 * Decimal(lo4) + 1 < Decimal("1e-18")
s4 = scene("overlap-on-axis", A4, B4, src + (
    "A: semi-axes (3, 2, 1), static. B: semi-axes (1, 2.5, 1.5), rotating about the x-axis (e = [1, t, 0, 0], 0 to "
    "90 degrees), centre (8t^2 - 8t + 5, 0, 0). The half-turn about the x-axis maps A and every B(t) to themselves, "
    "so A(t) and B(t) meet iff they meet on the x-axis, iff 8t^2 - 8t + 5 - 1 <= 3, iff 8t^2 - 8t + 1 <= 0. "
    f"Collision set: one interval [1/2 - sqrt(2)/4, 1/2 + sqrt(2)/4] = [{lo4}, {hi4}]; first contact "
    f"1/2 - sqrt(2)/4; external contacts at both ends, each at the point (3, 0, 0)."))


# ---------------------------------------------------------------- exact checks
def inverse(m):
    n = len(m)
    a = [list(r) + [F(int(i == j)) for j in range(n)] for i, r in enumerate(m)]
    for i in range(n):
        p = next(r for r in range(i, n) if a[r][i] != 0)
        a[i], a[p] = a[p], a[i]
        a[i] = [x / a[i][i] for x in a[i]]
        for r in range(n):
            if r != i and a[r][i] != 0:
                f = a[r][i]
                a[r] = [x - f * y for x, y in zip(a[r], a[i])]
    return [r[n:] for r in a]


def hom_of(o):
    """t -> numeric homogeneous matrix of an object's motion (static, euler or matrix)."""
    mo = o["motion"]
    if mo["type"] == "static":
        m = [[[F(int(i == j))] for j in range(4)] for i in range(4)]
    elif mo["type"] == "euler":
        m = euler_hom(mo["e"], mo["translation"], mo.get("translation_denominator", "1"))
    else:
        m = [[P(p) for p in row] for row in mo["m"]]
    return lambda t: [[pev(p, t) for p in row] for row in m]


def world(o, t):
    Q = [[F(0)] * 4 for _ in range(4)]
    for i, a in enumerate(o["shape"]["semi_axes"]):
        Q[i][i] = 1 / F(a) ** 2
    Q[3][3] = F(-1)
    M = hom_of(o)(t)
    N = inverse([[x / M[3][3] for x in row] for row in M])   # w = 1: the affine map itself
    QN = [[sum(Q[i][k] * N[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
    return [[sum(N[k][i] * QN[k][j] for k in range(4)) for j in range(4)] for i in range(4)]




def status(s, t):
    """Root pattern of f(lambda; t): 2 distinct negative roots = separate, a negative double root = touching,
    none = overlapping (Wang-Wang-Kim, as used in 002 section III)."""
    f = charpoly(world(s["a"], t), world(s["b"], t))
    return {2: "separate", 1: "touching", 0: "overlap"}[negative_roots(f)]


def boundaries(s, n=400, halvings=40):
    st = [status(s, F(k, n)) for k in range(n + 1)]
    out = []
    for k in range(n):
        if (st[k] == "separate") != (st[k + 1] == "separate"):
            lo, hi, left = F(k, n), F(k + 1, n), st[k] == "separate"
            for _ in range(halvings):
                mid = (lo + hi) / 2
                if (status(s, mid) == "separate") == left:
                    lo = mid
                else:
                    hi = mid
            out.append((st[k], st[k + 1], lo, hi))
    return st, out


def check():
    sts = {}
    for s in (s1, s2, s3, s4):
        st, out = boundaries(s)
        sts[s["name"]] = st
        seen = {x: [k for k, y in enumerate(st) if y == x] for x in set(st)}
        print(f"{s['name']}: t = 0 {st[0]}, t = 1/2 {st[200]}, t = 1 {st[-1]}; "
              + ", ".join(f"{x} at {len(v)} of the instants k/400" for x, v in sorted(seen.items())))
        for a, b, lo, hi in out:
            print(f"  {a} -> {b} in [{float(lo):.15f}, {float(hi):.15f}]")
    assert sts["touch-and-separate"] == sts["touch-and-separate-rotated"]
    assert [k for k, x in enumerate(sts["touch-and-separate"]) if x != "separate"] == [200]
    assert sts["touch-and-separate"][200] == "touching"
    # f of the rotated scene is a constant multiple of f of the original (same roots)
    for t in (F(0), F(1, 3), F(1, 2), F(1)):
        f1 = charpoly(world(s1["a"], t), world(s1["b"], t))
        f2 = charpoly(world(s2["a"], t), world(s2["b"], t))
        assert all(f1[i] * f2[4] == f2[i] * f1[4] for i in range(5))
    print("touch-and-separate-rotated: same status as touch-and-separate at all k/400, f proportional at 0, 1/3, 1/2, 1")


for s in (s1, s2, s3, s4):
    write(s)
print("wrote", ", ".join(s["name"] + ".json" for s in (s1, s2, s3, s4)), "to", HERE)
if "--check" in sys.argv[1:]:
    check()
