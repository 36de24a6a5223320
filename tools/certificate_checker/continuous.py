"""2D, the discriminant of f identically zero: the two ellipses are never
separate (003 Corollary 7); P*D has no root in [0, 1], so the status at one
sample holds on all of it, and the answer is the collision interval [0, 1]
(with the contact interval [0, 1] when that status is touching)."""
from fractions import Fraction as Q

from .errors import reject
from .inputs import at, rational
from .polynomials import add, deriv, descartes, ev, gcd, mul, negative_roots, scale, trim


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
