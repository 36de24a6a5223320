#!/usr/bin/env python3
"""Writes scenes of independent motions ("parameters": "independent",
scene-format.md, last section; paper 001 section 4): A moves as A(s), B as
B(t), s and t unrelated, and the question is which part of each path enters
the other's swept volume.

Sphere cases (analytic answers). Two balls of radii r_A, r_B with centres on
segments c_A(s) = p + s d, c_B(t) = q + t e meet iff |c_A(s) - c_B(t)| <=
R = r_A + r_B. So the s-intervals are { s : dist(c_A(s), B's segment) <= R }
and the t-intervals { t : dist(c_B(t), A's segment) <= R }. The data below
make the nearest point an interior point or an end of the other segment, so
each end solves a quadratic; the script checks every claim with exact
fractions before writing.

  spheres-cross   r_A = 1, r_B = 1/2 (R = 3/2); c_A(s) = (2, -3 + 6s, 1),
                  c_B(t) = (4t, 0, 0). Nearest points interior:
                  dist^2(c_A(s), B's path) = (6s - 3)^2 + 1, so
                  s in [1/2 - sqrt(5)/12, 1/2 + sqrt(5)/12]
                  (roots of 144 s^2 - 144 s + 31); dist^2(c_B(t), A's path) =
                  (4t - 2)^2 + 1, t in [1/2 - sqrt(5)/8, 1/2 + sqrt(5)/8]
                  (roots of 64 t^2 - 64 t + 11).
  spheres-end     r_A = 1, r_B = 1/2; c_A(s) = (-1/2, -3 + 6s, 1), c_B(t) =
                  (4t, 0, 0). For A's centre the nearest point of B's path is
                  its end (0, 0, 0): dist^2 = 1/4 + (6s - 3)^2 + 1 <= 9/4 iff
                  s in [1/3, 2/3] (rational ends); for B's centre the nearest
                  point of A's path is (-1/2, 0, 1): (4t + 1/2)^2 + 1 <= 9/4 iff
                  t in [0, (sqrt(5) - 1)/8] (16 t^2 + 4 t - 1 = 0).

The sphere cases' answers are stored by `eccd solve FILE --arith exact
--write-answer` (exact/independent_balls.hpp), so `eccd regress` checks them;
running this script again drops them (store them again).

Ellipsoid cases (answered by the proved route of the exact pipeline,
certified/independent_proof.hpp; their answers are stored the same way as the
sphere cases', and running this script drops them too):
  ellipsoids-cross     semi-axes (2, 1, 1/2) and (1, 1, 3/2); A translates
                       along y (from -4 to 5) through B's path, B translates along x and
                       rotates (a rational motion: the rotation by the
                       Cayley-like matrix of (1 - t^2, 2t)/(1 + t^2) about z).
  ellipsoids-apart     the same shapes on parallel paths 4 apart: never meet.
  ellipsoids-turning   as ellipsoids-cross with A's path at z = 1/3 and B's
                       semi-axes (3/2, 7/10, 1): B's turning now matters and
                       the ends are irrational (no closed form; the proved
                       answer agrees with double's ends to 3e-11).
"""
import json
import os
from fractions import Fraction as Fr

HERE = os.path.dirname(os.path.abspath(__file__))


def s(x):
    x = Fr(x)
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def translation(c0, c1):
    """matrix motion M(t) = [[I, c0 + t c1], [0, 1]]"""
    m = [[s(1 if i == j else 0) for j in range(3)] for i in range(3)]
    for i in range(3):
        m[i].append([s(c0[i]), s(c1[i])] if c1[i] != 0 else s(c0[i]))
    m.append(["0", "0", "0", "1"])
    return {"type": "matrix", "m": m}


def write(name, a, b, note):
    doc = {"format": "ellipse-ccd-scene/1", "name": name, "dim": 3, "parameters": "independent",
           "a": a, "b": b, "note": note}
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def ball(r, c0, c1):
    return {"shape": {"semi_axes": [s(r)] * 3}, "motion": translation(c0, c1)}


# --- checks of the analytic claims (exact)
R2 = Fr(9, 4)
# spheres-cross: (6s-3)^2 + 1 - 9/4 = 36 s^2 - 36 s + 31/4 = (144 s^2 - 144 s + 31)/4
for x in [Fr(k, 100) for k in range(101)]:
    assert ((6 * x - 3) ** 2 + 1 - R2) * 4 == 144 * x * x - 144 * x + 31
    assert ((4 * x - 2) ** 2 + 1 - R2) * 4 == 64 * x * x - 64 * x + 11
    assert ((4 * x + Fr(1, 2)) ** 2 + 1 - R2) * 4 == 4 * (16 * x * x + 4 * x - 1)
    assert Fr(1, 4) + (6 * x - 3) ** 2 + 1 - R2 == 36 * x * x - 36 * x + 8  # roots 1/3, 2/3
assert 36 * Fr(1, 3) ** 2 - 36 * Fr(1, 3) + 8 == 0 and 36 * Fr(2, 3) ** 2 - 36 * Fr(2, 3) + 8 == 0

write("spheres-cross", ball(1, (2, -3, 1), (0, 6, 0)), ball(Fr(1, 2), (0, 0, 0), (4, 0, 0)),
      "Independent motions, two balls on segments (cases/independent/make_independent.py). r_A = 1, r_B = 1/2; "
      "c_A(s) = (2, -3 + 6s, 1), c_B(t) = (4t, 0, 0). s-intervals: [1/2 - sqrt(5)/12, 1/2 + sqrt(5)/12] = "
      "[0.31366100187501755, 0.68633899812498245] (roots of 144 s^2 - 144 s + 31); t-intervals: "
      "[1/2 - sqrt(5)/8, 1/2 + sqrt(5)/8] = [0.22048849718747371, 0.77951150281252629] (roots of 64 t^2 - 64 t + 11).")
write("spheres-end", ball(1, (Fr(-1, 2), -3, 1), (0, 6, 0)), ball(Fr(1, 2), (0, 0, 0), (4, 0, 0)),
      "Independent motions, two balls on segments (cases/independent/make_independent.py). r_A = 1, r_B = 1/2; "
      "c_A(s) = (-1/2, -3 + 6s, 1), c_B(t) = (4t, 0, 0). The nearest point of B's path to A's centre is its end "
      "(0, 0, 0): s-intervals [1/3, 2/3]; t-intervals [0, (sqrt(5) - 1)/8] = [0, 0.15450849718747371] "
      "(16 t^2 + 4 t - 1 = 0).")


def rotating(c0, c1):
    """B: translation c0 + t c1 and the rational rotation about z by
    [[1 - t^2, -2t], [2t, 1 - t^2]] / (1 + t^2), written homogeneously
    (w = 1 + t^2)."""
    w = ["1", "0", "1"]
    m = [[["1", "0", "-1"], ["0", "-2"], "0"], [["0", "2"], ["1", "0", "-1"], "0"], ["0", "0", w]]
    for i in range(3):
        # (c0 + t c1) w
        p = [Fr(0)] * 4
        for k, wk in enumerate([1, 0, 1]):
            p[k] += Fr(c0[i]) * wk
            p[k + 1] += Fr(c1[i]) * wk
        while len(p) > 1 and p[-1] == 0:
            p.pop()
        m[i].append([s(x) for x in p])
    m.append(["0", "0", "0", w])
    return {"type": "matrix", "m": m}


write("ellipsoids-cross",
      {"shape": {"semi_axes": ["2", "1", "1/2"]}, "motion": translation((1, -4, 0), (0, 9, 0))},
      {"shape": {"semi_axes": ["1", "1", "3/2"]}, "motion": rotating((-3, 0, 0), (6, 0, 0))},
      "Independent motions of two ellipsoids (cases/independent/make_independent.py): A (semi-axes 2, 1, 1/2) "
      "translates from (1, -4, 0) to (1, 5, 0); B (semi-axes 1, 1, 3/2) translates from (-3, 0, 0) to (3, 0, 0) "
      "while turning about z by the rational rotation (1 - t^2, 2t)/(1 + t^2). The paths cross: both projections "
      "are non-empty. B's semi-axes in x and y are equal (1, 1), so its turning about z leaves it unchanged: A(s) "
      "(y-extent 1 about y = -4 + 9s) meets B(t) (y-extent 1 about y = 0) iff |-4 + 9s| <= 2 at the best t (B centred "
      "at x = 1, t = 2/3): s in [2/9, 2/3]; B(t) (x in [-4 + 6t, -2 + 6t]) meets A's swept volume (x in [-1, 3] at y = 0) "
      "iff -2 + 6t >= -1: t in [1/6, 1]. The stored answer is the proved one (eccd solve --arith exact --write-answer, "
      "certified/independent_proof.hpp); its brackets hold 2/9, 2/3 and 1/6.")
write("ellipsoids-apart",
      {"shape": {"semi_axes": ["2", "1", "1/2"]}, "motion": translation((-3, 4, 0), (6, 0, 0))},
      {"shape": {"semi_axes": ["1", "1", "3/2"]}, "motion": rotating((-3, -1, 0), (6, 0, 0))},
      "Independent motions of two ellipsoids (cases/independent/make_independent.py) on parallel paths: A's centre "
      "stays at y = 4, B's at y = -1; A reaches at most y = 4 - 1 = 3 and B at most y = -1 + 1 = 0 (B's z-rotation "
      "keeps its x-y section a unit disc): they never meet, collides = false.")
write("ellipsoids-turning",
      {"shape": {"semi_axes": ["2", "1", "1/2"]}, "motion": translation((1, -4, Fr(1, 3)), (0, 9, 0))},
      {"shape": {"semi_axes": ["3/2", "7/10", "1"]}, "motion": rotating((-3, 0, 0), (6, 0, 0))},
      "Independent motions of two ellipsoids (cases/independent/make_independent.py): A (semi-axes 2, 1, 1/2) "
      "translates from (1, -4, 1/3) to (1, 5, 1/3); B (semi-axes 3/2, 7/10, 1) translates from (-3, 0, 0) to "
      "(3, 0, 0) while turning about z by the rational rotation (1 - t^2, 2t)/(1 + t^2), which now changes it. "
      "No closed form: the stored answer is the proved one (eccd solve --arith exact --write-answer, "
      "certified/independent_proof.hpp); double's ends (floating/independent_ccd.hpp) lie within 3e-11 of its brackets.")


# --- 2D (ellipses: F is built with H = 3, kernel/trivariate_bernstein.hpp) and bodies that do not move
def write2(name, a, b, note, dim=2):
    doc = {"format": "ellipse-ccd-scene/1", "name": name, "dim": dim, "parameters": "independent",
           "a": a, "b": b, "note": note}
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def translation2(c0, c1):
    """2D matrix motion M(t) = [[I, c0 + t c1], [0, 1]]"""
    m = [[s(1 if i == j else 0) for j in range(2)] for i in range(2)]
    for i in range(2):
        m[i].append([s(c0[i]), s(c1[i])] if c1[i] != 0 else s(c0[i]))
    m.append(["0", "0", "1"])
    return {"type": "matrix", "m": m}


def turning2():
    """2D: the rational rotation [[1 - t^2, -2t], [2t, 1 - t^2]] / (1 + t^2) about the origin (0 to 90 degrees)."""
    w = ["1", "0", "1"]
    return {"type": "matrix", "m": [[["1", "0", "-1"], ["0", "-2"], "0"], [["0", "2"], ["1", "0", "-1"], "0"], ["0", "0", w]]}


# discs-end: c_A(s) = (3s, 0), c_B(t) = (7/2, 3t), R = 1: 7/2 - 3s <= 1 iff s >= 5/6;
# (1/2)^2 + (3t)^2 <= 1 iff 12 t^2 <= 1, t <= sqrt(3)/6
for x in [Fr(k, 100) for k in range(101)]:
    assert ((Fr(1, 2)) ** 2 + (3 * x) ** 2 - 1) * 4 == 3 * (12 * x * x - 1)
write2("discs-end", {"shape": {"semi_axes": ["1/2", "1/2"]}, "motion": translation2((0, 0), (3, 0))},
       {"shape": {"semi_axes": ["1/2", "1/2"]}, "motion": translation2((Fr(7, 2), 0), (0, 3))},
       "Independent motions in 2D, two discs on segments (cases/independent/make_independent.py). r_A = r_B = 1/2; "
       "c_A(s) = (3s, 0), c_B(t) = (7/2, 3t): they meet only near the end of A's path and the start of B's. "
       "s-intervals [5/6, 1]; t-intervals [0, sqrt(3)/6] = [0, 0.28867513459481289] (12 t^2 - 1 = 0).")
# ellipse-static: a disc (r = 1/2) along the minor axis of a static ellipse (2, 1): |9s - 5| <= 3/2
assert 9 * Fr(7, 18) - 5 == Fr(-3, 2) and 9 * Fr(13, 18) - 5 == Fr(3, 2)
write2("ellipse-static", {"shape": {"semi_axes": ["1/2", "1/2"]}, "motion": translation2((0, -5), (0, 9))},
       {"shape": {"semi_axes": ["2", "1"]}, "motion": {"type": "static"}},
       "Independent motions in 2D: a disc (r = 1/2) with centre (0, -5 + 9s) crosses a static ellipse (semi-axes 2, 1) "
       "along its minor axis; the vertex (0, +-1) is the nearest point of the ellipse to the centre (the centre of "
       "curvature there is on the other side). B does not move: t-intervals [0, 1]; s-intervals [7/18, 13/18] "
       "(|9s - 5| <= 3/2). Proved on the lower-dimensional problem F = F_u = 0 in (u, s) "
       "(certified/independent_proof.hpp, system free).")
write2("ellipses-turning", {"shape": {"semi_axes": ["2", "1/2"]}, "motion": turning2()},
       {"shape": {"semi_axes": ["1/4", "1/4"]}, "motion": translation2((1, -1), (0, 2))},
       "Independent motions in 2D: A (semi-axes 2, 1/2) turns about its centre, the origin, by the rational rotation "
       "(1 - s^2, 2s)/(1 + s^2) (0 to 90 degrees); a disc B (r = 1/4) moves from (1, -1) to (1, 1). No closed form: "
       "the stored answer is the proved one (eccd solve --arith exact --write-answer).")
# ellipsoid-static: A (1, 1/2, 1/2) with centre (0, -5 + 9s, 0) crosses a static ellipsoid B (2, 1, 1) along y;
# the planes y = +-1 touch B at its vertices and A's lowest (highest) point is its vertex: they meet iff |9s - 5| <= 3/2
write2("ellipsoid-static", {"shape": {"semi_axes": ["1", "1/2", "1/2"]}, "motion": translation((0, -5, 0), (0, 9, 0))},
       {"shape": {"semi_axes": ["2", "1", "1"]}, "motion": {"type": "static"}},
       "Independent motions: A (semi-axes 1, 1/2, 1/2) with centre (0, -5 + 9s, 0) crosses a static ellipsoid B "
       "(semi-axes 2, 1, 1) along its y-axis; the plane y = 1 (y = -1) is tangent to B at its vertex and to A at A's "
       "when they touch, so they meet iff |9s - 5| <= 3/2: s-intervals [7/18, 13/18]; B does not move: t-intervals "
       "[0, 1]. Proved on the lower-dimensional problem F = F_u = 0 in (u, s) (system free).", dim=3)


# --- a body turning in place (it does not move as a set: A(s) = c(s) A(0), kernel/trivariate_bernstein.hpp
# hold_still): the answer is the lower-dimensional problem of the static body, P_s all of [0, 1] or nothing.
# ball-turning: A a ball (r = 1) turning about x through its centre (1/2, 0, 0) by the quaternion (1, s, 0, 0)
# (0 to 90 degrees); B a ball (r = 1/2) with centre (-3 + 6t, 1, 0): (6t - 7/2)^2 + 1 <= 9/4 iff
# 36 t^2 - 42 t + 11 <= 0, t in [(7 - sqrt(5))/12, (7 + sqrt(5))/12].
for x in [Fr(k, 100) for k in range(101)]:
    assert ((6 * x - Fr(7, 2)) ** 2 + 1 - R2) == 36 * x * x - 42 * x + 11
    assert ((6 * x - 3) ** 2 + 1 - R2) * 4 == 144 * x * x - 144 * x + 31


def turning_scenes():
    write2("ball-turning",
           {"shape": {"semi_axes": ["1", "1", "1"]},
            "motion": {"type": "euler", "e": ["1", ["0", "1"], "0", "0"], "translation": ["1/2", "0", "0"]}},
           ball(Fr(1, 2), (-3, 1, 0), (6, 0, 0)),
           "Independent motions, a body turning in place (cases/independent/make_independent.py): A, a ball (r = 1), "
           "turns about the x-axis through its fixed centre (1/2, 0, 0) by the quaternion (1, s, 0, 0) (0 to 90 degrees); "
           "B, a ball (r = 1/2), moves from (-3, 1, 0) to (3, 1, 0). A does not move as a set, so s-intervals [0, 1]; "
           "(6t - 7/2)^2 + 1 <= 9/4: t-intervals [(7 - sqrt(5))/12, (7 + sqrt(5))/12] = [0.39699, 0.76967] "
           "(36 t^2 - 42 t + 11 = 0). Proved on the lower-dimensional problem (A held at s = 0, system free).", dim=3)
    write2("disc-turning", {"shape": {"semi_axes": ["1", "1"]}, "motion": turning2()},
           {"shape": {"semi_axes": ["1/2", "1/2"]}, "motion": translation2((-3, 1), (6, 0))},
           "Independent motions in 2D, a body turning in place (cases/independent/make_independent.py): A, a disc "
           "(r = 1), turns about its centre, the origin, by the rational rotation (1 - s^2, 2s)/(1 + s^2) (0 to 90 "
           "degrees); B, a disc (r = 1/2), moves from (-3, 1) to (3, 1). A does not move as a set, so s-intervals "
           "[0, 1]; (6t - 3)^2 + 1 <= 9/4: t-intervals [1/2 - sqrt(5)/12, 1/2 + sqrt(5)/12] = [0.31366, 0.68634] "
           "(144 t^2 - 144 t + 31 = 0). Proved on the lower-dimensional problem (A held at s = 0, system free).")


turning_scenes()
