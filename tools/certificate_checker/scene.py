"""The scene file (ellipse-ccd-scene/1) read into exact matrices: for each
object its quadric Q (from semi-axes, squared semi-axes or a matrix) and its
motion matrix M(t) with polynomial entries (static, matrix, 2D kinematic with
the rational rotation of d, 3D euler with the Euler-Rodrigues rotation).
Returns H = dim + 1 and the two (Q, M)."""
from fractions import Fraction as Q
from math import comb

from .errors import Unreadable
from .inputs import scene_number
from .polynomials import add, mul, scale, trim


def poly_of(x, place):
    if isinstance(x, dict):
        b = [scene_number(c, f"{place}/bernstein/{i}") for i, c in enumerate(x.get("bernstein") or [])]
        if not b:
            raise Unreadable(f"scene: {place}: expected a polynomial")
        n, p = len(b) - 1, []
        for i in range(n + 1):
            term = [Q(0)] * (n + 1)
            for k in range(n - i + 1):
                term[i + k] = (-1) ** k * comb(n - i, k) * comb(n, i) * b[i]
            p = add(p, term)
        return p
    if isinstance(x, list):
        return trim([scene_number(c, f"{place}/{i}") for i, c in enumerate(x)])
    return trim([scene_number(x, place)])


def read_scene(doc, label):
    if not isinstance(doc, dict) or doc.get("format") != "ellipse-ccd-scene/1":
        raise Unreadable(f"{label}: not a scene (format ellipse-ccd-scene/1)")
    dim = scene_number(doc.get("dim"), "/dim")
    if dim not in (2, 3):
        raise Unreadable(f"{label}: /dim: expected 2 or 3")
    H, objs = int(dim) + 1, []
    for name in ("a", "b"):
        o = doc.get(name)
        if not isinstance(o, dict):
            raise Unreadable(f"{label}: /{name}: expected an object")
        shape, motion, pl = o.get("shape") or {}, o.get("motion") or {}, f"/{name}"
        Qm = [[Q(0)] * H for _ in range(H)]
        if "semi_axes" in shape or "semi_axes_squared" in shape:
            sq = "semi_axes_squared" in shape
            for i, x in enumerate(shape["semi_axes_squared" if sq else "semi_axes"]):
                v = scene_number(x, f"{pl}/shape/{i}")
                Qm[i][i] = 1 / v if sq else 1 / (v * v)
            Qm[H - 1][H - 1] = Q(-1)
        elif "matrix" in shape:
            Qm = [[scene_number(x, f"{pl}/shape/matrix") for x in row] for row in shape["matrix"]]
        else:
            raise Unreadable(f"{label}: {pl}/shape: expected semi_axes, semi_axes_squared or matrix")
        ty = motion.get("type")
        one = lambda: [[[Q(1)] if i == j else [] for j in range(H)] for i in range(H)]
        if ty == "static":
            M = one()
        elif ty == "matrix":
            M = [[poly_of(e, f"{pl}/motion/m") for e in row] for row in motion["m"]]
        elif ty == "kinematic" and H == 3:
            d0, d1, d2, d3 = (poly_of(e, f"{pl}/motion/d") for e in motion["d"])
            c, s = add(mul(d2, d2), scale(Q(-1), mul(d3, d3))), scale(Q(2), mul(d2, d3))
            M = [[c, s, scale(Q(2), add(mul(d0, d3), scale(Q(-1), mul(d1, d2))))],
                 [scale(Q(-1), s), c, scale(Q(2), add(mul(d0, d2), mul(d1, d3)))],
                 [[], [], add(mul(d2, d2), mul(d3, d3))]]
        elif ty == "euler" and H == 4:
            e = [poly_of(x, f"{pl}/motion/e") for x in motion["e"]]
            v = [poly_of(x, f"{pl}/motion/translation") for x in motion["translation"]]
            v3 = poly_of(motion.get("translation_denominator", "1"), f"{pl}/motion/translation_denominator")
            sq = [mul(x, x) for x in e]
            m2 = lambda x, y: scale(Q(2), mul(x, y))
            neg = lambda x: scale(Q(-1), x)
            R = [[add(add(sq[0], sq[1]), neg(add(sq[2], sq[3]))), add(m2(e[1], e[2]), neg(m2(e[0], e[3]))), add(m2(e[1], e[3]), m2(e[0], e[2]))],
                 [add(m2(e[1], e[2]), m2(e[0], e[3])), add(add(sq[0], sq[2]), neg(add(sq[1], sq[3]))), add(m2(e[2], e[3]), neg(m2(e[0], e[1])))],
                 [add(m2(e[1], e[3]), neg(m2(e[0], e[2]))), add(m2(e[2], e[3]), m2(e[0], e[1])), add(add(sq[0], sq[3]), neg(add(sq[1], sq[2])))]]
            E = add(add(sq[0], sq[1]), add(sq[2], sq[3]))
            M = [[mul(v3, R[r][c]) for c in range(3)] + [mul(E, v[r])] for r in range(3)] + [[[], [], [], mul(E, v3)]]
        else:
            raise Unreadable(f"{label}: {pl}/motion: a {ty} motion has no exact certificate (this checker covers rational motions)")
        objs.append((Qm, M))
    if doc.get("parameters", "shared") != "shared":
        raise Unreadable(f"{label}: independent motions have no eccd-certificate/2 (not covered here)")
    return H, objs
