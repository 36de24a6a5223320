"""The certificate's timeline over [0, 1] and the claims on its shape:
  timeline  instant, cell, ..., instant from [0, 0] to [1, 1], in order;
  brackets  Descartes' rule: each bracketed instant holds one root of its
            factor and none of the other factors;
  gaps      every piece between brackets and gap points: Descartes 0, so the
            projection has no root outside the brackets.
A node is a dict: lo, hi, cell, name, status, and for an instant its place,
factor (index into the square-free factors, or None) and evidence."""
from .errors import reject
from .inputs import at, check_approx, rational, whole
from .polynomials import descartes, ev

STATUSES = ("separate", "touching", "overlapping")


def read_instant_node(fx, e, k2, place):
    inst = at(e, "instant", place)
    lo = rational(at(inst, "lo", place + ".instant"), place + ".instant.lo", fx.max_bits)
    hi = rational(at(inst, "hi", place + ".instant"), place + ".instant.hi", fx.max_bits)
    node = dict(lo=lo, hi=hi, cell=False, name=f"instant {k2 // 2}", place=place)
    if lo > hi:
        reject(node["name"], "lo > hi")
    check_approx(at(inst, "approx", place + ".instant"), lo, hi, node["name"], place + ".instant.approx", fx.approx_chars)
    fct = at(e, "root_of_factor", place)
    node["factor"] = None if fct is None else whole(fct, place + ".root_of_factor", 0, len(fx.F) - 1)
    node["evidence"] = e.get("evidence", [])
    if not isinstance(node["evidence"], list) or len(node["evidence"]) > 16 or not all(isinstance(x, dict) for x in node["evidence"]):
        reject("certificate format", place + ".evidence: expected an array of objects")
    return node


def check_timeline_claim(fx, cert):
    """Returns the timeline's nodes, read and proved to run in order from 0 to 1."""
    tl = at(cert, "timeline", "certificate")
    if not isinstance(tl, list) or len(tl) < 3 or len(tl) % 2 == 0 or len(tl) > 2 * fx.n + 3:
        reject("timeline", "expected instant, cell, ..., instant")
    nodes = []
    for k2, e in enumerate(tl):
        place = f"timeline[{k2}]"
        if k2 % 2:
            s = rational(at(e, "cell_sample", place), place + ".cell_sample", fx.max_bits)
            node = dict(lo=s, hi=s, cell=True, name=f"cell {k2 // 2}")
        else:
            node = read_instant_node(fx, e, k2, place)
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
    return nodes


def check_brackets_claim(fx, nodes):
    P, F = fx.P, fx.F
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


def check_gaps_claim(fx, cert, nodes):
    P, F, n = fx.P, fx.F, fx.n
    gp = at(cert, "gap_points", "certificate")
    if not isinstance(gp, list) or len(gp) > 8 * n + 64:
        reject("certificate format", "gap_points: too many")
    pts, used = [rational(x, f"gap_points[{i}]", fx.max_bits) for i, x in enumerate(gp)], 0
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
