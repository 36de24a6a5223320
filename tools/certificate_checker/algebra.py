"""The algebraic claims of a certificate, each re-derived from the scene:
  scene       the certificate's dim, a, b are the scene file's; det M(t) has
              no root in [0, 1] (Sturm) for either object;
  f           g_k = alpha^k beta^(H-k) h_k (alpha, beta > 0), h the
              coefficients of det(lambda A(t) - B(t)), A = N^T Q N with N the
              primitive adjugate of M: the roots lambda are those of the
              scene up to a positive factor; checked at deg + 1 points;
  projection  the candidates listed vanish identically and P is a constant
              multiple of the named one (2D: the cubic's discriminant; 3D:
              P * g_4 against psc_0 = Res(f, f'), or psc_k), at deg + 1 points;
  factors     prod F_i^m_i is a constant multiple of P (at deg + 1 points).
What they establish is kept in a Facts for the timeline's claims."""
import json
import math
from fractions import Fraction as Q

from .errors import reject
from .inputs import at, rational, whole
from .matrices import at_point, cubic_disc, det, mdeg, moving_quadric, pencil, primitive_inverse, subresultant
from .polynomials import ev, interpolate, roots_between, trim


class Facts:
    """What the algebraic claims proved: H = dim + 1; g, the coefficients of
    f(lambda; t) (lowest power of lambda first); the projection P, its
    degree n, its index k among the candidates and its square-free factors F
    as (polynomial, multiplicity); the size bounds derived from P."""

    def __init__(self, H, g):
        self.H, self.g = H, g
        self.gdeg = max(len(x) - 1 for x in g)
        self.k = self.name = self.P = self.n = None
        self.F = []
        self.max_bits = self.factor_bits = self.approx_chars = None

    def g_at(self, t):
        return [ev(x, t) for x in self.g]


def check_scene_claim(scene_doc, cert, motions, H):
    sc = at(cert, "scene", "certificate")
    for key in ("dim", "a", "b"):
        if at(sc, key, "scene") != scene_doc.get(key):
            reject("scene", f"the certificate's \"{key}\" differs from the scene file's: it is a certificate for another scene")
    for M in motions:
        dm = interpolate([det(at_point(M, Q(k))) for k in range(H * mdeg(M) + 1)])
        if not dm or ev(dm, 0) == 0 or ev(dm, 1) == 0 or roots_between(dm, Q(0), Q(1)) != 0:
            reject("scene", "det M(t) vanishes in [0, 1]")


def check_f_claim(cert, H, objs):
    """Returns the g_k of the certificate once they are proved to be the
    scene's pencil coefficients up to positive factors."""
    (Qa, Ma), (Qb, Mb) = objs
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
    return g


def projection_names(H):
    return ["discriminant"] if H == 3 else ["discriminant", "psc_1", "psc_2", "psc_3"]


def candidate(fx, kk, t):
    """The kk-th projection candidate at t: the cubic's discriminant (2D) or psc_kk (3D)."""
    return cubic_disc(fx.g_at(t)) if fx.H == 3 else subresultant(fx.g_at(t), kk, kk)


def isobaric_bound(fx, factors, weight):
    """The largest degree in t of a product of `factors` coefficients g_k
    whose indices add up to `weight`."""
    best = [-1] * (weight + 1)
    best[0] = 0
    for _ in range(factors):
        nxt = [-1] * (weight + 1)
        for w in range(weight + 1):
            if best[w] < 0:
                continue
            for k in range(fx.H + 1):
                if w + k <= weight and fx.g[k]:
                    nxt[w + k] = max(nxt[w + k], best[w] + len(fx.g[k]) - 1)
        best = nxt
    return best[weight]


def candidate_bound(fx, kk):
    """A bound on the degree in t of the kk-th candidate."""
    if fx.H == 3:
        return isobaric_bound(fx, 4, 6)
    return isobaric_bound(fx, 7, 16) if kk == 0 else (2 * fx.H - 1 - 2 * kk) * fx.gdeg


def vanishes_identically(fx, kk):
    b = candidate_bound(fx, kk)
    return all(candidate(fx, kk, Q(j - (b + 1) // 2)) == 0 for j in range(b + 1))


def check_vanishing_candidates(fx, p):
    """Reads the projection's name into fx.name, fx.k and proves that every
    candidate before it vanishes identically."""
    names = projection_names(fx.H)
    name = at(p, "name", "projection")
    if name not in names:
        reject("projection", f"unknown projection {json.dumps(name)[:40]}")
    fx.name, fx.k = name, names.index(name)
    if at(p, "vanishing", "projection") != names[: fx.k]:
        reject("projection", f"projection.vanishing must list {names[:fx.k]}")
    for i in range(fx.k):
        if not vanishes_identically(fx, i):
            reject("projection", f"{names[i]} does not vanish identically")


def check_projection_multiple(fx, p):
    """Reads P into fx.P, fx.n and proves it a constant multiple of the named candidate."""
    H, k, g = fx.H, fx.k, fx.g
    cj = at(p, "coefficients", "projection")
    p_bound = isobaric_bound(fx, 6, 12) if H == 4 and k == 0 else candidate_bound(fx, k)
    if not isinstance(cj, list) or not cj or len(cj) > p_bound + 1:
        reject("projection", f"expected at most {p_bound + 1} coefficients")
    P = trim([rational(c, f"projection.coefficients[{i}]", 1 << 20) for i, c in enumerate(cj)])
    if not P or whole(at(p, "degree", "projection"), "projection.degree", 0, 1 << 30) != len(P) - 1:
        reject("projection", "projection.degree differs from the degree of its coefficients")
    ratio = None
    points = max(candidate_bound(fx, k), len(P) - 1 + (len(g[4]) - 1 if H == 4 and k == 0 else 0)) + 1
    for j in range(points):
        t = Q(j - points // 2)
        want, got = candidate(fx, k, t), ev(P, t) * (ev(g[4], t) if H == 4 and k == 0 else 1)
        if ratio is None and want != 0:
            ratio = got / want
        if (got != ratio * want) if ratio is not None else got != 0:
            reject("projection", f"P is not a constant multiple of the {fx.name} of f (t = {j})")
    if ratio is None:
        reject("projection", f"{fx.name} vanishes identically")
    fx.P, fx.n = P, len(P) - 1


def set_size_bounds(fx):
    """The bit sizes the timeline's rationals may have, from P's integer height."""
    P, n = fx.P, fx.n
    m_ = 1
    for c in P:
        m_ = m_ * c.denominator // math.gcd(m_, c.denominator)
    ints = [int(c * m_) for c in P]
    gg = 0
    for x in ints:
        gg = math.gcd(gg, x)
    tau = max(abs(x // gg).bit_length() for x in ints)
    fx.max_bits = min(4 * tau + 1024, max(256, (1 << 24) // max(n * n, 1)))
    fx.factor_bits, fx.approx_chars = tau + 2 * n + 64, fx.max_bits * 30103 // 100000 + 64


def check_factors_claim(fx, p):
    """Reads the square-free factors into fx.F and proves their product a constant multiple of P."""
    P, n = fx.P, fx.n
    fj = at(p, "square_free_factors", "projection")
    if not isinstance(fj, list) or not fj or len(fj) > n:
        reject("factors", "expected a non-empty list of factors")
    F = []
    for i, f in enumerate(fj):
        co = at(f, "coefficients", f"projection.square_free_factors[{i}]")
        if not isinstance(co, list) or len(co) > n + 1:
            reject("certificate format", f"projection.square_free_factors[{i}].coefficients: too many")
        fi = trim([rational(c, f"projection.square_free_factors[{i}].coefficients[{j}]", fx.factor_bits) for j, c in enumerate(co)])
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
    fx.F = F
