"""The statuses along the timeline:
  cells     the static test at each cell's sample: f(lambda; t) has >= 2
            distinct negative roots (separate), else a negative multiple
            root (touching), else overlapping (Sturm sequences);
  instants  rational: the static test; irrational: the evidence signs
            proved on the bracket (Descartes 0 and the sign at lo, or a
            common factor with its one root there), then 003 Theorem 6
            (2D) or the subresultant touch rule (3D).
The evidence polynomials (2D: P and D of the cubic; 3D: the subresultant
coefficients s(j, i) and disc(S_2)) are computed here from g, never read."""
from fractions import Fraction as Q

from .errors import reject
from .inputs import at, rational
from .matrices import subresultant
from .polynomials import add, deriv, descartes, divmod_poly, ev, gcd, interpolate, mul, negative_roots, scale, trim


def static_status(fx, t):
    """The static test at a rational t."""
    f = trim(fx.g_at(t))
    if len(f) != fx.H + 1 or f[0] == 0:
        reject("scene", f"f(lambda; {t}) is degenerate")
    if negative_roots(f) >= 2:
        return "separate"
    h = gcd(f, deriv(f))
    return "touching" if len(h) > 1 and negative_roots(h) >= 1 else "overlapping"


class Evidence:
    """The evidence polynomials by name, computed once each, and the signs
    an instant's evidence proves for them at its root."""

    def __init__(self, fx):
        self.fx, self.cache = fx, {}

    def poly(self, nm):
        if nm in self.cache:
            return self.cache[nm]
        fx, g, H = self.fx, self.fx.g, self.fx.H
        if H == 3 and nm in ("P", "D"):
            q = add(scale(Q(9), mul(g[3], g[0])), scale(Q(-1), mul(g[2], g[1]))) if nm == "P" else add(mul(g[2], g[2]), scale(Q(-3), mul(g[3], g[1])))
        elif H == 4:
            s = lambda j, i: interpolate([subresultant(fx.g_at(Q(k3)), j, i) for k3 in range((2 * H - 1 - 2 * j) * fx.gdeg + 1)])
            if nm == "disc(S_2)":
                q = add(mul(s(2, 1), s(2, 1)), scale(Q(-4), mul(s(2, 2), s(2, 0))))
            elif nm in {f"s({j},{i})" for j in range(4) for i in range(j + 1)}:
                q = s(int(nm[2]), int(nm[4]))
            else:
                reject("certificate format", f"unknown evidence polynomial {nm}")
        else:
            reject("certificate format", f"unknown evidence polynomial {nm}")
        self.cache[nm] = q
        return q

    def sign(self, nd, nm):
        """The sign of evidence polynomial nm at the instant nd's root, as the instant's evidence proves it."""
        for i, e in enumerate(nd["evidence"]):
            if e.get("poly") != nm:
                continue
            q, claimed = self.poly(nm), {"negative": -1, "zero": 0, "positive": 1}.get(e.get("sign"))
            if claimed is None:
                reject("certificate format", f"{nd['place']}.evidence[{i}].sign")
            if claimed:
                v = ev(q, nd["lo"])
                if v == 0 or descartes(q, nd["lo"], nd["hi"]) != 0 or (v > 0) != (claimed > 0):
                    reject(nd["name"], f"the sign of {nm} at the root is not proved")
                return claimed
            self.check_common_factor(nd, nm, q, e, i)
            return 0
        reject(nd["name"], f"the evidence for the sign of {nm} is missing")

    def check_common_factor(self, nd, nm, q, e, i):
        """nm = 0 at the root: a factor of both nm and the instant's factor with its one root in the bracket."""
        fx = self.fx
        co = at(e, "common_factor", f"{nd['place']}.evidence[{i}]")
        if not isinstance(co, list) or len(co) > fx.n + 1:
            reject("certificate format", f"{nd['place']}.evidence[{i}].common_factor")
        h = trim([rational(c, f"{nd['place']}.evidence[{i}].common_factor", fx.factor_bits) for c in co])
        if (len(h) < 2 or divmod_poly(q, h)[1] or divmod_poly(fx.F[nd["factor"]][0], h)[1] or ev(h, nd["lo"]) == 0 or ev(h, nd["hi"]) == 0
                or descartes(h, nd["lo"], nd["hi"]) != 1):
            reject(nd["name"], f"the common factor offered for {nm} = 0 is not proved")


def check_cells_claim(fx, nodes):
    for k2 in range(1, len(nodes), 2):
        if static_status(fx, nodes[k2]["lo"]) != nodes[k2]["status"]:
            reject(nodes[k2]["name"], "the static test gives another status")


def touch_3d(fx, evidence, nd):
    """3D: whether f has a negative multiple root at the instant's root, by
    the first s(j,j) after the projection that does not vanish there; None
    when every one vanishes."""
    for j in range(fx.k + 1, 4):
        lead = evidence.sign(nd, f"s({j},{j})")
        if lead == 0:
            continue
        if j in (1, 3):
            return evidence.sign(nd, f"s({j},{j - 1})") * lead > 0
        b, c, d = evidence.sign(nd, "s(2,1)"), evidence.sign(nd, "s(2,0)"), evidence.sign(nd, "disc(S_2)")
        return d >= 0 and (lead * c < 0 or (lead * c > 0 and lead * b > 0) or (c == 0 and lead * b > 0))
    return None


def instant_status(fx, evidence, nodes, k2):
    """The status the evidence proves at instant k2."""
    nd = nodes[k2]
    if nd["lo"] == nd["hi"]:
        return static_status(fx, nd["lo"])
    if nd["factor"] is None:
        reject(nd["name"], "an end that is not a root must be a point")
    if fx.H == 3:
        sp, sd = evidence.sign(nd, "P"), evidence.sign(nd, "D")
        return "overlapping" if sd == 0 else "touching" if sp * sd < 0 else "overlapping"
    touch = touch_3d(fx, evidence, nd)
    if touch is None:
        reject(nd["name"], "every s(j,j) vanishes at the root")
    st = "touching" if touch else nodes[k2 - 1]["status"]
    if not touch and nodes[k2 + 1]["status"] != st:
        reject(nd["name"], "no negative multiple root, yet the neighbouring cells differ")
    return st


def check_instants_claim(fx, nodes):
    evidence = Evidence(fx)
    for k2 in range(0, len(nodes), 2):
        st = instant_status(fx, evidence, nodes, k2)
        if st != nodes[k2]["status"]:
            reject(nodes[k2]["name"], f"the evidence gives {st}, not {nodes[k2]['status']}")


def check_theorem6(fx, nodes):
    """2D: no overlapping instant between two separate cells (003 Theorem 6)."""
    if fx.H == 3:
        for k2 in range(2, len(nodes) - 2, 2):
            if nodes[k2]["status"] == "overlapping" and nodes[k2 - 1]["status"] == nodes[k2 + 1]["status"] == "separate":
                reject("timeline", "an overlapping instant between two separate cells (003 Theorem 6)")
