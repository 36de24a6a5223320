#!/usr/bin/env python3
"""check_certificate.py SCENE CERT: a second, independent checker of eccd's
exact certificates ("eccd-certificate/2", 2D and 3D), in Python with the
standard library only (fractions, json). It shares no code with eccd: an
auditor reads it in an hour (docs/checking.md).

Exit 0 VALID, 1 REJECTED (the claim and why), 2 unreadable input or a format
it does not cover.

What it proves, in order (the claim names of eccd-check):
  scene       the certificate's dim, a, b are the scene file's; det M(t) has
              no root in [0, 1] (Sturm) for either object;
  f           g_k = alpha^k beta^(H-k) h_k (alpha, beta > 0), h the
              coefficients of det(lambda A(t) - B(t)), A = N^T Q N with N the
              adjugate of M (interpolated at integers) over the gcd of its
              entries: the roots lambda are those of the scene up to a
              positive factor; checked at deg + 1 points;
  projection  the candidates listed vanish identically and P is a constant
              multiple of the named one (2D: the cubic's discriminant; 3D:
              P * g_4 against psc_0 = Res(f, f'), or psc_k), at deg + 1 points;
  factors     prod F_i^m_i is a constant multiple of P (at deg + 1 points);
  timeline    instant, cell, ..., instant from [0, 0] to [1, 1], in order;
  brackets    Descartes' rule: one root of its factor, none of the others;
  gaps        every piece between brackets and gap points: Descartes 0;
  cells       the static test: f(lambda; t) has >= 2 distinct negative
              roots (separate), else a negative multiple root (touching),
              else overlapping (Sturm sequences);
  instants    rational: the static test; irrational: the evidence signs
              proved on the bracket (Descartes 0 and the sign at lo, or a
              common factor with its one root there), then 003 Theorem 6
              (2D) or the subresultant touch rule (3D);
  answer      assembled here from the checked timeline, equal to the
              certificate's (brackets exactly, approx inside its bracket).
"""
import json
import sys
from fractions import Fraction as Q


class Rejected(Exception):
    def __init__(self, claim, reason):
        super().__init__(claim + ": " + reason)
        self.claim, self.reason = claim, reason


class Unreadable(Exception):
    pass


def reject(claim, reason):
    raise Rejected(claim, reason)


# ---------------------------------------------------------------- JSON, numbers
def load_strict(path, duplicate):
    """JSON with duplicate keys refused and no float accepted as a number."""
    def pairs(kv):
        d = {}
        for k, v in kv:
            if k in d:
                duplicate(k)
            d[k] = v
        return d
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        raise Unreadable(f"{path}: cannot be read: {e.strerror}")
    try:
        return json.loads(text, object_pairs_hook=pairs, parse_float=lambda s: "json-float:" + s)
    except json.JSONDecodeError as e:
        raise Unreadable(f"{path}: not valid JSON: line {e.lineno}, column {e.colno}: {e.msg}")


def scene_number(x, place):
    if isinstance(x, bool):
        raise Unreadable(f"scene: {place}: expected an exact number")
    if isinstance(x, int):
        return Q(x)
    if isinstance(x, str) and not x.startswith("json-float:"):
        s = x
        try:
            if "/" in s:
                n, d = s.split("/")
                if not n.lstrip("+-").isdigit() or not d.isdigit() or int(d) == 0:
                    raise ValueError
                return Q(int(n), int(d))
            mant, _, exp = s.lower().partition("e")
            if exp and (not exp.lstrip("+-").isdigit() or abs(int(exp)) > 10000):
                raise ValueError
            body = mant.lstrip("+-")
            if body.count(".") > 1 or not body.replace(".", "").isdigit():
                raise ValueError
            return Q(mant) * Q(10) ** int(exp or 0)
        except (ValueError, ZeroDivisionError):
            pass
    raise Unreadable(f"scene: {place}: expected an exact number, got {json.dumps(x)[:40]}")


def rational(x, place, max_bits):
    if not isinstance(x, str) or len(x) > 2 * (max_bits * 30103 // 100000 + 2) + 2:
        reject("certificate format", f"{place}: expected a rational \"p/q\" of at most {max_bits} bits, got {json.dumps(x)[:40]}")
    n, _, d = x.partition("/")
    body = n[1:] if n.startswith("-") else n
    if not body.isdigit() or (d and not d.isdigit()) or (d == "" and "/" in x):
        reject("certificate format", f"{place}: expected a rational \"p/q\", got {json.dumps(x)[:40]}")
    if d and int(d) == 0:
        reject("certificate format", f"{place}: zero denominator")
    q = Q(int(n), int(d) if d else 1)
    if q.numerator.bit_length() > max_bits or q.denominator.bit_length() > max_bits:
        reject("certificate format", f"{place}: a rational of more than {max_bits} bits")
    return q


def whole(x, place, lo, hi):
    if isinstance(x, bool) or not isinstance(x, int) or not lo <= x <= hi:
        reject("certificate format", f"{place}: expected a whole number from {lo} to {hi}, got {json.dumps(x)[:40]}")
    return x


def at(obj, key, place):
    if not isinstance(obj, dict):
        reject("certificate format", f"{place}: expected an object")
    if key not in obj:
        reject("certificate format", f"{place}: missing key \"{key}\"")
    return obj[key]


# ---------------------------------------------------------------- polynomials (lists of Fractions, lowest first)
def trim(p):
    p = list(p)
    while p and p[-1] == 0:
        p.pop()
    return p


def ev(p, x):
    v = Q(0)
    for c in reversed(p):
        v = v * x + c
    return v


def add(a, b):
    r = [Q(0)] * max(len(a), len(b))
    for i, c in enumerate(a):
        r[i] += c
    for i, c in enumerate(b):
        r[i] += c
    return trim(r)


def scale(k, a):
    return trim([k * c for c in a])


def mul(a, b):
    if not a or not b:
        return []
    r = [Q(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return trim(r)


def divmod_poly(a, b):
    r, q = trim(a), [Q(0)] * max(len(a) - len(b) + 1, 1)
    while r and len(r) >= len(b):
        s, k = len(r) - len(b), r[-1] / b[-1]
        q[s] = k
        for i, c in enumerate(b):
            r[i + s] -= k * c
        r = trim(r[:-1])
    return trim(q), r


def deriv(p):
    return trim([i * p[i] for i in range(1, len(p))])


def gcd(a, b):
    a, b = trim(a), trim(b)
    while b:
        a, b = b, divmod_poly(a, b)[1]
    return scale(1 / a[-1], a) if a else a


def interpolate(values):
    """The polynomial through (k, values[k]), k = 0, 1, ... (Newton)."""
    d, n = list(values), len(values)
    for j in range(1, n):
        for i in range(n - 1, j - 1, -1):
            d[i] = (d[i] - d[i - 1]) / j
    p = []
    for i in range(n - 1, -1, -1):
        p = add(mul(p, [Q(-i), Q(1)]), [d[i]])
    return p


def variations(seq):
    v, last = 0, 0
    for x in seq:
        s = (x > 0) - (x < 0)
        if s:
            v += last != 0 and s != last
            last = s
    return v


def taylor_shift(a, s):
    a = list(a)
    for i in range(len(a) - 1):
        for j in range(len(a) - 2, i - 1, -1):
            a[j] += s * a[j + 1]
    return a


def descartes(p, lo, hi):
    """Sign variations of p on (lo, hi) mapped onto (0, inf): 0 = no root, 1 = one simple root."""
    p = trim(p)
    if len(p) <= 1:
        return 0
    n, w = len(p) - 1, hi - lo
    l = 1
    for c in p:
        l = l * c.denominator // __import__("math").gcd(l, c.denominator)
    D, A, B = lo.denominator * w.denominator, lo.numerator * w.denominator, w.numerator * lo.denominator
    a = [int(p[i] * l) * D ** (n - i) for i in range(n + 1)]
    a = taylor_shift(a, A)
    a = [x * B ** i for i, x in enumerate(a)]
    return variations(taylor_shift(list(reversed(a)), 1))


def sturm(p):
    seq = [trim(p), deriv(p)]
    while seq[-1]:
        r = divmod_poly(seq[-2], seq[-1])[1]
        if not r:
            break
        seq.append(scale(Q(-1), r))
    return seq


def negative_roots(p):
    """Distinct real roots in (-inf, 0) (p(0) != 0)."""
    if len(trim(p)) <= 1:
        return 0
    seq = sturm(p)
    return variations([q[-1] * (1 if (len(q) - 1) % 2 == 0 else -1) for q in seq]) - variations([q[0] for q in seq])


def roots_between(p, a, b):
    seq = sturm(p)
    return variations([ev(q, a) for q in seq]) - variations([ev(q, b) for q in seq])


# ---------------------------------------------------------------- matrices
def det(m):
    m = [list(r) for r in m]
    n, d = len(m), Q(1)
    for c in range(n):
        p = next((r for r in range(c, n) if m[r][c] != 0), None)
        if p is None:
            return Q(0)
        if p != c:
            m[p], m[c], d = m[c], m[p], -d
        d *= m[c][c]
        for r in range(c + 1, n):
            if m[r][c]:
                k = m[r][c] / m[c][c]
                for j in range(c, n):
                    m[r][j] -= k * m[c][j]
    return d


def at_point(M, t):
    return [[ev(e, t) for e in row] for row in M]


def mdeg(M):
    return max(len(e) - 1 for row in M for e in row)


def primitive_inverse(M):
    """adj(M) over the gcd of its entries, by values at integers."""
    H = len(M)
    D = (H - 1) * max(mdeg(M), 0)
    vals = [[[] for _ in range(H)] for _ in range(H)]
    for k in range(D + 1):
        m = at_point(M, Q(k))
        for i in range(H):
            for j in range(H):
                minor = [[m[r][c] for c in range(H) if c != i] for r in range(H) if r != j]
                vals[i][j].append((-1) ** (i + j) * det(minor))
    N = [[interpolate(vals[i][j]) for j in range(H)] for i in range(H)]
    g = []
    for row in N:
        for e in row:
            if e:
                g = gcd(g, e) if g else scale(1 / e[-1], e)
    if len(g) > 1:
        N = [[divmod_poly(e, g)[0] for e in row] for row in N]
    return N


def moving_quadric(Q_, N, t):
    n, H = at_point(N, t), len(Q_)
    qn = [[sum(Q_[i][k] * n[k][j] for k in range(H)) for j in range(H)] for i in range(H)]
    return [[sum(n[k][i] * qn[k][j] for k in range(H)) for j in range(H)] for i in range(H)]


def pencil(A, B):
    H = len(A)
    v = [det([[l * A[i][j] - B[i][j] for j in range(H)] for i in range(H)]) for l in range(H + 1)]
    c = interpolate(v)
    return c + [Q(0)] * (H + 1 - len(c))


def subresultant(c, j, i):
    """s(j, i) of S_j(f, f') for f with coefficients c (lowest first), deg f = n."""
    n = len(c) - 1
    m, d = n - 1, [k * c[k] for k in range(1, n + 1)]
    rows, top = n + m - 2 * j, n + m - j - 1
    sq = []
    for r in range(rows):
        is_f = r < m - j
        p = c if is_f else d
        shift = (m - j - 1 - r) if is_f else (n - j - 1 - (r - (m - j)))
        coeff = lambda power: p[power - shift] if 0 <= power - shift < len(p) else Q(0)
        sq.append([coeff(top - col) for col in range(rows - 1)] + [coeff(i)])
    return det(sq)


def cubic_disc(g):
    a, b, c, d = g[3], g[2], g[1], g[0]
    return 18 * a * b * c * d - 4 * b ** 3 * d + b * b * c * c - 4 * a * c ** 3 - 27 * a * a * d * d


# ---------------------------------------------------------------- the scene
def poly_of(x, place):
    if isinstance(x, dict):
        b = [scene_number(c, f"{place}/bernstein/{i}") for i, c in enumerate(x.get("bernstein") or [])]
        if not b:
            raise Unreadable(f"scene: {place}: expected a polynomial")
        n, p = len(b) - 1, []
        from math import comb
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


# ---------------------------------------------------------------- the checker
STATUSES = ("separate", "touching", "overlapping")


def check(scene_doc, cert, label):
    out = []
    if not isinstance(cert, dict) or cert.get("format") != "eccd-certificate/2":
        reject("certificate format", f"format: expected \"eccd-certificate/2\", got {json.dumps(cert.get('format') if isinstance(cert, dict) else cert)[:40]}"
               + (" (format 1 is no longer accepted: run eccd certify again)" if isinstance(cert, dict) and cert.get("format") == "eccd-certificate/1" else ""))
    H, ((Qa, Ma), (Qb, Mb)) = read_scene(scene_doc, label)
    sc = at(cert, "scene", "certificate")
    for k in ("dim", "a", "b"):
        if at(sc, k, "scene") != scene_doc.get(k):
            reject("scene", f"the certificate's \"{k}\" differs from the scene file's: it is a certificate for another scene")
    for M in (Ma, Mb):
        dm = interpolate([det(at_point(M, Q(k))) for k in range(H * mdeg(M) + 1)])
        if not dm or ev(dm, 0) == 0 or ev(dm, 1) == 0 or roots_between(dm, Q(0), Q(1)) != 0:
            reject("scene", "det M(t) vanishes in [0, 1]")
    out.append("scene")
    # f
    Na, Nb = primitive_inverse(Ma), primitive_inverse(Mb)
    D = 2 * H * max(mdeg(Na), mdeg(Nb))
    gj = at(at(cert, "f", "certificate"), "g", "f")
    if not isinstance(gj, list) or len(gj) != H + 1 or any(not isinstance(x, list) or len(x) > D + 1 for x in gj):
        reject("f", f"expected {H + 1} polynomials of at most {D + 1} coefficients")
    g = [trim([rational(c, f"f.g[{k}][{i}]", 1 << 16) for i, c in enumerate(gk)]) for k, gk in enumerate(gj)]
    rho = [None] * (H + 1)
    for j in range(D + 1):
        t = Q(j)
        h = pencil(moving_quadric(Qa, Na, t), moving_quadric(Qb, Nb, t))
        for k in range(H + 1):
            gv = ev(g[k], t)
            if rho[k] is None and h[k] != 0:
                rho[k] = gv / h[k]
            if (gv != rho[k] * h[k]) if rho[k] is not None else gv != 0:
                reject("f", f"g_{k} is not a constant multiple of the coefficient of lambda^{k} of det(lambda A(t) - B(t)) (t = {j})")
    if rho[0] is None or rho[H] is None or rho[0] <= 0 or rho[H] <= 0:
        reject("f", "g_0 or g_H vanishes or has the wrong sign")
    for k in range(1, H):
        if rho[k] is not None and (rho[k] <= 0 or rho[k] ** H != rho[H] ** k * rho[0] ** (H - k)):
            reject("f", f"g_{k} is scaled differently from g_0 and g_{H}: the roots lambda would move")
    out.append("f")
    gdeg = max(len(x) - 1 for x in g)
    g_at = lambda t: [ev(x, t) for x in g]
    # projection
    p = at(cert, "projection", "certificate")
    names = ["discriminant"] if H == 3 else ["discriminant", "psc_1", "psc_2", "psc_3"]
    name = at(p, "name", "projection")
    if name not in names:
        reject("projection", f"unknown projection {json.dumps(name)[:40]}")
    k = names.index(name)
    cand = lambda kk, t: cubic_disc(g_at(t)) if H == 3 else subresultant(g_at(t), kk, kk)

    def isobaric_bound(factors, weight):
        best = [-1] * (weight + 1)
        best[0] = 0
        for _ in range(factors):
            nxt = [-1] * (weight + 1)
            for w in range(weight + 1):
                if best[w] < 0:
                    continue
                for k in range(H + 1):
                    if w + k <= weight and g[k]:
                        nxt[w + k] = max(nxt[w + k], best[w] + len(g[k]) - 1)
            best = nxt
        return best[weight]

    bound = lambda kk: isobaric_bound(4, 6) if H == 3 else isobaric_bound(7, 16) if kk == 0 else (2 * H - 1 - 2 * kk) * gdeg
    if at(p, "vanishing", "projection") != names[:k]:
        reject("projection", f"projection.vanishing must list {names[:k]}")
    for i in range(k):
        if any(cand(i, Q(j - (bound(i) + 1) // 2)) != 0 for j in range(bound(i) + 1)):
            reject("projection", f"{names[i]} does not vanish identically")
    zero = at(p, "identically_zero", "projection")
    if zero is True:
        if H != 3 or any(cand(k, Q(j - (bound(k) + 1) // 2)) != 0 for j in range(bound(k) + 1)):
            reject("projection", "the projection does not vanish identically")
        return out + continuous_touching(cert, g, g_at, H)
    cj = at(p, "coefficients", "projection")
    p_bound = isobaric_bound(6, 12) if H == 4 and k == 0 else bound(k)
    if not isinstance(cj, list) or not cj or len(cj) > p_bound + 1:
        reject("projection", f"expected at most {p_bound + 1} coefficients")
    P = trim([rational(c, f"projection.coefficients[{i}]", 1 << 20) for i, c in enumerate(cj)])
    if not P or whole(at(p, "degree", "projection"), "projection.degree", 0, 1 << 30) != len(P) - 1:
        reject("projection", "projection.degree differs from the degree of its coefficients")
    ratio = None
    points = max(bound(k), len(P) - 1 + (len(g[4]) - 1 if H == 4 and k == 0 else 0)) + 1
    for j in range(points):
        t = Q(j - points // 2)
        want, got = cand(k, t), ev(P, t) * (ev(g[4], t) if H == 4 and k == 0 else 1)
        if ratio is None and want != 0:
            ratio = got / want
        if (got != ratio * want) if ratio is not None else got != 0:
            reject("projection", f"P is not a constant multiple of the {name} of f (t = {j})")
    if ratio is None:
        reject("projection", f"{name} vanishes identically")
    n = len(P) - 1
    m_ = 1
    for c in P:
        m_ = m_ * c.denominator // __import__("math").gcd(m_, c.denominator)
    ints = [int(c * m_) for c in P]
    gg = 0
    for x in ints:
        gg = __import__("math").gcd(gg, x)
    tau = max(abs(x // gg).bit_length() for x in ints)
    max_bits = min(4 * tau + 1024, max(256, (1 << 24) // max(n * n, 1)))
    factor_bits, approx_chars = tau + 2 * n + 64, max_bits * 30103 // 100000 + 64
    out.append("projection")
    fj = at(p, "square_free_factors", "projection")
    if not isinstance(fj, list) or not fj or len(fj) > n:
        reject("factors", "expected a non-empty list of factors")
    F = []
    for i, f in enumerate(fj):
        co = at(f, "coefficients", f"projection.square_free_factors[{i}]")
        if not isinstance(co, list) or len(co) > n + 1:
            reject("certificate format", f"projection.square_free_factors[{i}].coefficients: too many")
        fi = trim([rational(c, f"projection.square_free_factors[{i}].coefficients[{j}]", factor_bits) for j, c in enumerate(co)])
        mult = whole(at(f, "multiplicity", f"projection.square_free_factors[{i}]"), f"projection.square_free_factors[{i}].multiplicity", 1, n)
        if len(fi) < 2:
            reject("factors", f"factor {i} is constant")
        F.append((fi, mult))
    if sum((len(fi) - 1) * m for fi, m in F) != n:
        reject("factors", "the factors' degrees times multiplicities do not add up to the projection's degree")
    r2 = None
    for j in range(n + 1):
        prod, pv = Q(1), ev(P, Q(j))
        for fi, m in F:
            prod *= ev(fi, Q(j)) ** m
        if r2 is None and pv != 0:
            r2 = prod / pv
        if (prod != r2 * pv) if r2 is not None else prod != 0:
            reject("factors", "the product of the factors is not a constant multiple of the projection")
    out.append("factors")
    # timeline
    tl = at(cert, "timeline", "certificate")
    if not isinstance(tl, list) or len(tl) < 3 or len(tl) % 2 == 0 or len(tl) > 2 * n + 3:
        reject("timeline", "expected instant, cell, ..., instant")
    nodes = []
    for k2, e in enumerate(tl):
        place = f"timeline[{k2}]"
        if k2 % 2:
            s = rational(at(e, "cell_sample", place), place + ".cell_sample", max_bits)
            node = dict(lo=s, hi=s, cell=True, name=f"cell {k2 // 2}")
        else:
            inst = at(e, "instant", place)
            lo, hi = rational(at(inst, "lo", place + ".instant"), place + ".instant.lo", max_bits), rational(at(inst, "hi", place + ".instant"), place + ".instant.hi", max_bits)
            node = dict(lo=lo, hi=hi, cell=False, name=f"instant {k2 // 2}", place=place)
            if lo > hi:
                reject(node["name"], "lo > hi")
            check_approx(at(inst, "approx", place + ".instant"), lo, hi, node["name"], place + ".instant.approx", approx_chars)
            fct = at(e, "root_of_factor", place)
            node["factor"] = None if fct is None else whole(fct, place + ".root_of_factor", 0, len(F) - 1)
            node["evidence"] = e.get("evidence", [])
            if not isinstance(node["evidence"], list) or len(node["evidence"]) > 16 or not all(isinstance(x, dict) for x in node["evidence"]):
                reject("certificate format", place + ".evidence: expected an array of objects")
        st = at(e, "status", place)
        if st not in STATUSES:
            reject("certificate format", place + ".status: expected separate, touching or overlapping")
        node["status"] = st
        nodes.append(node)
    if not (nodes[0]["lo"] == nodes[0]["hi"] == 0 and nodes[-1]["lo"] == nodes[-1]["hi"] == 1):
        reject("timeline", "the timeline must run from [0, 0] to [1, 1]")
    for a, b in zip(nodes, nodes[1:]):
        if not a["hi"] < b["lo"]:
            reject("timeline", f"{a['name']} and {b['name']} overlap or are out of order")
    out.append("timeline")
    # brackets
    for k2 in range(0, len(nodes), 2):
        nd, end = nodes[k2], k2 in (0, len(nodes) - 1)
        if nd["factor"] is None:
            if not end or ev(P, nd["lo"]) == 0:
                reject(nd["name"], "an instant must be a root of the projection, or 0 or 1 where it does not vanish")
            continue
        Fi = F[nd["factor"]][0]
        if nd["lo"] == nd["hi"]:
            if ev(Fi, nd["lo"]) != 0:
                reject(nd["name"], "its factor does not vanish there")
            continue
        if ev(P, nd["lo"]) == 0 or ev(P, nd["hi"]) == 0:
            reject(nd["name"], "the projection vanishes at an end of the bracket")
        for j, (fj_, _) in enumerate(F):
            if descartes(fj_, nd["lo"], nd["hi"]) != (1 if j == nd["factor"] else 0):
                reject(nd["name"], f"Descartes does not prove exactly one root of its factor and none of factor {j}")
    out.append("brackets")
    gp = at(cert, "gap_points", "certificate")
    if not isinstance(gp, list) or len(gp) > 8 * n + 64:
        reject("certificate format", "gap_points: too many")
    pts, used = [rational(x, f"gap_points[{i}]", max_bits) for i, x in enumerate(gp)], 0
    for k2 in range(0, len(nodes) - 2, 2):
        a, b = nodes[k2]["hi"], nodes[k2 + 2]["lo"]
        cut = [a]
        while used < len(pts) and pts[used] < b:
            if not cut[-1] < pts[used] or ev(P, pts[used]) == 0:
                reject("gaps", f"gap point {pts[used]} is out of order, outside a gap, or a root")
            cut.append(pts[used])
            used += 1
        cut.append(b)
        for x, y in zip(cut, cut[1:]):
            if any(descartes(fi, x, y) != 0 for fi, _ in F):
                reject("gaps", f"the projection may have a root in ({x}, {y}) outside every bracket")
    if used != len(pts):
        reject("gaps", f"gap point {pts[used]} is not strictly inside a gap")
    out.append("gaps")

    def static(t):
        f = trim(g_at(t))
        if len(f) != H + 1 or f[0] == 0:
            reject("scene", f"f(lambda; {t}) is degenerate")
        if negative_roots(f) >= 2:
            return "separate"
        h = gcd(f, deriv(f))
        return "touching" if len(h) > 1 and negative_roots(h) >= 1 else "overlapping"

    cache = {}

    def evidence(nm):
        if nm in cache:
            return cache[nm]
        if H == 3 and nm in ("P", "D"):
            q = add(scale(Q(9), mul(g[3], g[0])), scale(Q(-1), mul(g[2], g[1]))) if nm == "P" else add(mul(g[2], g[2]), scale(Q(-3), mul(g[3], g[1])))
        elif H == 4:
            s = lambda j, i: interpolate([subresultant(g_at(Q(k3)), j, i) for k3 in range((2 * H - 1 - 2 * j) * gdeg + 1)])
            if nm == "disc(S_2)":
                q = add(mul(s(2, 1), s(2, 1)), scale(Q(-4), mul(s(2, 2), s(2, 0))))
            elif nm in {f"s({j},{i})" for j in range(4) for i in range(j + 1)}:
                q = s(int(nm[2]), int(nm[4]))
            else:
                reject("certificate format", f"unknown evidence polynomial {nm}")
        else:
            reject("certificate format", f"unknown evidence polynomial {nm}")
        cache[nm] = q
        return q

    def sign_of(nd, nm):
        for i, e in enumerate(nd["evidence"]):
            if e.get("poly") != nm:
                continue
            q, claimed = evidence(nm), {"negative": -1, "zero": 0, "positive": 1}.get(e.get("sign"))
            if claimed is None:
                reject("certificate format", f"{nd['place']}.evidence[{i}].sign")
            if claimed:
                v = ev(q, nd["lo"])
                if v == 0 or descartes(q, nd["lo"], nd["hi"]) != 0 or (v > 0) != (claimed > 0):
                    reject(nd["name"], f"the sign of {nm} at the root is not proved")
                return claimed
            co = at(e, "common_factor", f"{nd['place']}.evidence[{i}]")
            if not isinstance(co, list) or len(co) > n + 1:
                reject("certificate format", f"{nd['place']}.evidence[{i}].common_factor")
            h = trim([rational(c, f"{nd['place']}.evidence[{i}].common_factor", factor_bits) for c in co])
            if (len(h) < 2 or divmod_poly(q, h)[1] or divmod_poly(F[nd["factor"]][0], h)[1] or ev(h, nd["lo"]) == 0 or ev(h, nd["hi"]) == 0
                    or descartes(h, nd["lo"], nd["hi"]) != 1):
                reject(nd["name"], f"the common factor offered for {nm} = 0 is not proved")
            return 0
        reject(nd["name"], f"the evidence for the sign of {nm} is missing")

    for k2 in range(1, len(nodes), 2):
        if static(nodes[k2]["lo"]) != nodes[k2]["status"]:
            reject(nodes[k2]["name"], "the static test gives another status")
    out.append("cells")
    for k2 in range(0, len(nodes), 2):
        nd = nodes[k2]
        if nd["lo"] == nd["hi"]:
            st = static(nd["lo"])
        elif nd["factor"] is None:
            reject(nd["name"], "an end that is not a root must be a point")
        elif H == 3:
            sp, sd = sign_of(nd, "P"), sign_of(nd, "D")
            st = "overlapping" if sd == 0 else "touching" if sp * sd < 0 else "overlapping"
        else:
            touch = None
            for j in range(k + 1, 4):
                lead = sign_of(nd, f"s({j},{j})")
                if lead == 0:
                    continue
                if j in (1, 3):
                    touch = sign_of(nd, f"s({j},{j - 1})") * lead > 0
                else:
                    b, c, d = sign_of(nd, "s(2,1)"), sign_of(nd, "s(2,0)"), sign_of(nd, "disc(S_2)")
                    touch = d >= 0 and (lead * c < 0 or (lead * c > 0 and lead * b > 0) or (c == 0 and lead * b > 0))
                break
            if touch is None:
                reject(nd["name"], "every s(j,j) vanishes at the root")
            st = "touching" if touch else nodes[k2 - 1]["status"]
            if not touch and nodes[k2 + 1]["status"] != st:
                reject(nd["name"], "no negative multiple root, yet the neighbouring cells differ")
        if st != nd["status"]:
            reject(nd["name"], f"the evidence gives {st}, not {nd['status']}")
    out.append("instants")
    if H == 3:
        for k2 in range(2, len(nodes) - 2, 2):
            if nodes[k2]["status"] == "overlapping" and nodes[k2 - 1]["status"] == nodes[k2 + 1]["status"] == "separate":
                reject("timeline", "an overlapping instant between two separate cells (003 Theorem 6)")
    # the answer
    inc = lambda i: nodes[i]["status"] != "separate"
    tcell = lambda i: i < len(nodes) and nodes[i]["cell"] and nodes[i]["status"] == "touching"
    br = lambda i: (nodes[i]["lo"], nodes[i]["hi"])
    for i in range(1, len(nodes), 2):
        if inc(i) and not (inc(i - 1) and inc(i + 1)):
            reject("timeline", f"{nodes[i]['name']} is in collision next to a separate instant")
    intervals, contacts, cints, i = [], [], [], 0
    while i < len(nodes):
        if tcell(i):
            e = i
            while tcell(e + 2) and nodes[e + 1]["status"] == "touching":
                e += 2
            cints.append((br(i - 1), br(e + 1)))
            i = e
        i += 1
    for i in range(0, len(nodes), 2):
        if nodes[i]["status"] == "touching" and not tcell(i + 1) and not (i > 0 and tcell(i - 1)):
            contacts.append(br(i))
    i = 0
    while i < len(nodes):
        if inc(i):
            e = i
            while e + 1 < len(nodes) and inc(e + 1):
                e += 1
            intervals.append((br(i), br(e)))
            i = e
        i += 1
    ans = at(cert, "answer", "certificate")
    if not isinstance(ans, dict) or set(ans) - {"collides", "intervals", "first_contact", "contacts", "contact_intervals"}:
        reject("certificate format", "answer: unknown keys")

    def inst(j, place, want):
        if not isinstance(j, dict) or set(j) - {"approx", "lo", "hi"}:
            reject("certificate format", f"{place}: an instant has the keys approx, lo, hi only")
        lo, hi = rational(at(j, "lo", place), place + ".lo", max_bits), rational(at(j, "hi", place), place + ".hi", max_bits)
        if (lo, hi) != want:
            reject("answer", f"{place}: the instant differs from the checked timeline's")
        check_approx(at(j, "approx", place), lo, hi, "answer", place + ".approx", approx_chars)

    if at(ans, "collides", "answer") is not bool(intervals):
        reject("answer", f"answer.collides must be {str(bool(intervals)).lower()}")
    for key, want in (("intervals", intervals), ("contact_intervals", cints)):
        lst = ans.get(key, [] if key == "contact_intervals" else None)
        if not isinstance(lst, list) or len(lst) != len(want) or not all(isinstance(x, list) and len(x) == 2 for x in lst):
            reject("answer", f"answer.{key}: the checked timeline gives {len(want)}")
        for i, (x, w) in enumerate(zip(lst, want)):
            inst(x[0], f"answer.{key}[{i}][0]", w[0])
            inst(x[1], f"answer.{key}[{i}][1]", w[1])
    fc = at(ans, "first_contact", "answer")
    if (fc is None) != (not intervals):
        reject("answer", "first_contact must be the start of the first interval, or null")
    if intervals:
        inst(fc, "answer.first_contact", intervals[0][0])
    cs = at(ans, "contacts", "answer")
    if not isinstance(cs, list) or len(cs) != len(contacts):
        reject("answer", f"answer.contacts: the checked timeline gives {len(contacts)}")
    for i, (x, w) in enumerate(zip(cs, contacts)):
        inst(x, f"answer.contacts[{i}]", w)
    out.append("answer")
    return out


def continuous_touching(cert, g, g_at, H):
    """2D, discriminant identically zero: never separate (003 Corollary 7); P*D has no root in [0, 1], so the status at one sample holds on all of it."""
    ct = at(cert, "continuous_touching", "certificate")
    Pp = add(scale(Q(9), mul(g[3], g[0])), scale(Q(-1), mul(g[2], g[1])))
    Dd = add(mul(g[2], g[2]), scale(Q(-3), mul(g[3], g[1])))
    PD = mul(Pp, Dd)
    zero = not PD
    if at(ct, "identically_zero", "continuous_touching") is not zero:
        reject("continuous touching", "identically_zero differs from P*D computed here")
    sample = rational(at(ct, "sample", "continuous_touching"), "continuous_touching.sample", 4096)
    if not 0 < sample < 1:
        reject("continuous touching", "the sample must lie in (0, 1)")
    f = trim(g_at(sample))
    st = "separate" if negative_roots(f) >= 2 else "touching" if (lambda h: len(h) > 1 and negative_roots(h) >= 1)(gcd(f, deriv(f))) else "overlapping"
    if at(ct, "status", "continuous_touching") != st or st == "separate":
        reject("continuous touching", f"the static test at the sample gives {st}")
    gp = at(ct, "gap_points", "continuous_touching")
    if not isinstance(gp, list) or len(gp) > 8 * max(len(PD) - 1, 0) + 64:
        reject("certificate format", "continuous_touching.gap_points: too many")
    if zero:
        if gp or st != "overlapping":
            reject("continuous touching", "P*D vanishes identically: overlapping, no gap points")
    else:
        cut = [Q(0)] + [rational(x, f"continuous_touching.gap_points[{i}]", 4096) for i, x in enumerate(gp)] + [Q(1)]
        if any(not a < b for a, b in zip(cut, cut[1:])) or any(ev(PD, x) == 0 for x in cut):
            reject("continuous touching", "the gap points are out of order, or P*D vanishes at one (or at 0 or 1)")
        if any(descartes(PD, a, b) != 0 for a, b in zip(cut, cut[1:])):
            reject("continuous touching", "P*D may have a root in [0, 1]: the status may change")
    ans = at(cert, "answer", "certificate")
    z, o = {"approx": "0", "lo": "0", "hi": "0"}, {"approx": "1", "lo": "1", "hi": "1"}
    want = {"collides": True, "intervals": [[z, o]], "first_contact": z, "contacts": []}
    if st == "touching":
        want["contact_intervals"] = [[z, o]]
    got = dict(ans) if isinstance(ans, dict) else {}
    if got.get("contact_intervals") == []:
        del got["contact_intervals"]
    if got != want:
        reject("answer", "the answer must be the collision interval [0, 1]" + (" with the contact interval [0, 1]: it would pass a continuous touch off as an overlap" if st == "touching" else ""))
    return ["continuous touching", "answer"]


def check_approx(a, lo, hi, claim, place, max_chars):
    if not isinstance(a, str) or not 0 < len(a) <= max_chars:
        reject(claim, f"{place}: approx must be a decimal string")
    mant, _, exp = a.lower().partition("e")
    body = mant.lstrip("+-")
    if (body.count(".") > 1 or not body.replace(".", "").isdigit() or len(mant) - len(body) > 1
            or (exp and (not exp.lstrip("+-").isdigit() or abs(int(exp)) > 100000))):
        reject(claim, f"{place}: approx must be a decimal string, got {json.dumps(a)[:40]}")
    places = len(body.partition(".")[2])
    v = Q(mant) * Q(10) ** int(exp or 0)
    unit = Q(10) ** (int(exp or 0) - places)
    if not (abs(v - lo) * 2 <= unit if lo == hi else lo <= v <= hi):
        reject(claim, f"{place}: approx {a} lies outside its bracket")


def check_index(index_path):
    """--index FILE: every eccd-certificate/2 listed in an index.json of `eccd regress --certify --keep-certificates DIR`."""
    import os
    import time
    try:
        with open(index_path, encoding="utf-8") as f:
            entries = json.load(f)["certificates"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"check_certificate.py: {index_path}: not an index of certificates: {e}", file=sys.stderr)
        return 2
    base, bad, done, t0 = os.path.dirname(index_path), 0, 0, time.process_time()
    for e in entries:
        if e.get("format") != "eccd-certificate/2":
            continue
        done += 1
        code = main(["check_certificate.py", e["scene"], os.path.join(base, e["certificate"])], quiet=True)
        if code != 0:
            bad += 1
            print(f"NOT VALID ({code}): {e['certificate']}")
    print(f"check_certificate.py: {done - bad} of {done} eccd-certificate/2 certificate(s) VALID ({time.process_time() - t0:.1f} s CPU)")
    return 0 if bad == 0 and done > 0 else 1


def main(argv, quiet=False):
    if len(argv) == 3 and argv[1] == "--index":
        return check_index(argv[2])
    if len(argv) != 3:
        print("usage: check_certificate.py SCENE CERT  |  check_certificate.py --index DIR/index.json", file=sys.stderr)
        return 2
    dups = []
    try:
        scene = load_strict(argv[1], lambda k: dups.append(("scene", k)))
        if dups:
            raise Unreadable(f"{argv[1]}: duplicate key \"{dups[0][1]}\"")
        cert = load_strict(argv[2], lambda k: dups.append(("cert", k)))
        if isinstance(cert, dict) and cert.get("format") not in ("eccd-certificate/2", "eccd-certificate/1") and not dups:
            raise Unreadable(f"{argv[2]}: format {json.dumps(cert.get('format'))[:40]} is not covered (this checker covers eccd-certificate/2)")
    except Unreadable as e:
        print(f"check_certificate.py: {e}", file=sys.stderr)
        return 2
    try:
        if dups:
            reject("certificate format", f"duplicate key \"{dups[0][1]}\"")
        claims = check(scene, cert, argv[1])
    except Unreadable as e:
        print(f"check_certificate.py: {e}", file=sys.stderr)
        return 2
    except Rejected as r:
        print(f"REJECTED: {r.claim}: {r.reason}" + (f" ({argv[2]})" if quiet else ""))
        return 1
    except (ZeroDivisionError, TypeError, ValueError, KeyError, IndexError, AttributeError) as e:
        print(f"REJECTED: certificate format: the certificate cannot be checked: {type(e).__name__}: {e}")
        return 1
    if not quiet:
        print("ok  " + ", ".join(claims))
        print("VALID")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
