#!/usr/bin/env python3
"""Draws one scene for `eccd plot` (app/plot.cpp): scene_figure.py DATA.json OUT.png

DATA.json is the "eccd-plot-data/1" file that `eccd plot` writes (keep it with
--data): the `eccd solve` report of the scene ("solve"), object outlines at a
few instants ("snapshots"), the centres' paths ("paths"), contact points
("contacts") and the sampled curve ("curve"): Δ(t)/max|Δ| in 2D, F(u, t) on a
grid of the (u, t) square in 3D. All the mathematics is done by eccd; this
script only draws.

Left panel: the objects at the drawn instants (3D: outlines of their
projections onto the xy-plane), A in blues and B in oranges, darker = later;
labels in red are instants inside a collision interval; crosses are contact
points. A label that would overlap another (or the legend) is moved next to
its object, with a thin leader line. Right panel, 2D (paper 003): Δ(t) on a symmetric log scale; 3D (papers
001/002): the zero set of F(u, t) = det((u-1)A(t) - uB(t)) with F > 0 filled.
Both show the critical instants (dashed, coloured by status), the collision
intervals (shaded) and the contacts (circles) of the report.

Needs numpy and matplotlib only (Agg backend: no display).
"""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

STATUS_COLOUR = {
    "touching": "#d62728",
    "overlapping": "#9467bd",
    "separate": "#555555",
    "uncertain": "#ff7f0e",
}
COLLISION = "#e41a1c"


def approx(instant):
    return float(instant["approx"])


def short(x):
    return f"{x:.6g}"


def answer_text(rep):
    if rep["collides"] is None:
        return "unknown: no collision proved, a stretch is undecided"
    if not rep["collides"]:
        return "collision-free on [0, 1]"
    parts = []
    for a, b in rep.get("intervals") or []:
        ta, tb = approx(a), approx(b)
        parts.append(f"touch at t = {short(ta)}" if a == b else f"[{short(ta)}, {short(tb)}]")
    text = "collides: " + " ∪ ".join(parts) if parts else "collides"
    if rep.get("first_contact") is not None:
        text += f"; first contact t = {short(approx(rep['first_contact']))}"
    n = len(rep.get("contacts") or [])
    text += f"; {n} external contact{'s' if n != 1 else ''}"
    return text


def arith_text(data):
    rep = data["solve"]
    s = f"arithmetic {rep['arith']}, " + ("certified" if rep.get("certified") else "not certified")
    if rep.get("method") and rep["method"] != "cd-disc":
        s += f", method {rep['method']}"
    if rep.get("basis") and rep["basis"] != "exact":
        s += f", basis {rep['basis']}"
    s += f"; {len(rep.get('critical_instants') or [])} critical instant(s)"
    if rep.get("undecided"):
        s += f"; {len(rep['undecided'])} undecided"
    if data.get("arith_note"):
        s += f" ({data['arith_note']})"
    return s


def in_collision(t, rep):
    for a, b in rep.get("intervals") or []:
        if approx(a) - 1e-12 <= t <= approx(b) + 1e-12:
            return True
    return False


def draw_objects(ax, data):
    rep = data["solve"]
    paths = data["paths"]
    for key, cmap in (("a", plt.cm.Blues), ("b", plt.cm.Oranges)):
        ax.plot(paths[key]["x"], paths[key]["y"], ":", color=cmap(0.75), lw=1.2)
        ax.plot(paths[key]["x"][0], paths[key]["y"][0], "o", color=cmap(0.75), ms=4)
    xs = [x for s in data["snapshots"] for k in ("a", "b") for x in s[k]["x"]]
    ys = [y for s in data["snapshots"] for k in ("a", "b") for y in s[k]["y"]]
    tol = 0.03 * max(max(xs) - min(xs), max(ys) - min(ys), 1e-300) if xs else 0
    for key, cmap, name in (("a", plt.cm.Blues, "A"), ("b", plt.cm.Oranges, "B")):
        clusters = []  # snapshots whose centres (nearly) coincide share one label
        for snap in data["snapshots"]:
            t, o = snap["t"], snap[key]
            col = cmap(0.35 + 0.6 * t)
            ax.fill(o["x"], o["y"], color=col, alpha=0.10, lw=0)
            ax.plot(o["x"], o["y"], color=col, lw=2.4 if snap["contact"] else 1.3)
            for cl in clusters:
                if math.dist(cl["centre"], o["centre"]) <= tol:
                    cl["ts"].append(t)
                    break
            else:
                clusters.append({"centre": o["centre"], "ts": [t]})
        for cl in clusters:
            ts = cl["ts"]
            hits = [in_collision(t, rep) for t in ts]
            label = ", ".join(f"{t:.3g}" for t in ts) if len(ts) <= 2 else f"{ts[0]:.3g}…{ts[-1]:.3g} ({len(ts)} instants)"
            data.setdefault("_labels", []).append((f"{name} {label}", cl["centre"],
                                                   COLLISION if all(hits) else "black"))
    for c in data.get("contacts") or []:
        if "point" in c:
            ax.plot(c["point"][0], c["point"][1], "x", color=COLLISION, ms=10, mew=2.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.grid(alpha=0.25)
    where = "outlines of the projections onto the xy-plane" if data["dim"] == 3 else "the ellipses"
    ax.set_title(f"objects at the drawn instants ({where})", fontsize=11)
    handles = [
        Line2D([], [], color=plt.cm.Blues(0.8), lw=2, label="A at t (label), darker = later"),
        Line2D([], [], color=plt.cm.Oranges(0.8), lw=2, label="B at t (label), darker = later"),
        Line2D([], [], color="grey", ls=":", label="centre paths (dot: t = 0)"),
    ]
    if data.get("contacts"):
        handles.append(Line2D([], [], color=COLLISION, marker="x", ls="", mew=2.5,
                              label="contact point (thick outlines: contact instants)"))
    if rep["collides"]:
        handles.append(Line2D([], [], color=COLLISION, marker="$t$", ls="", label="red label: in collision"))
    if data["dim"] == 3:
        handles.append(Patch(color="none", label="projections may overlap while apart"))
    ax.legend(handles=handles, fontsize=8, loc="best", framealpha=0.85)


# Offsets (points) tried in turn for a snapshot label that would overlap one already placed: first on the centre,
# then around it at growing distance; a moved label gets a thin leader line to its centre.
LABEL_OFFSETS = [(0, 0)] + [(round(r * math.cos(a)), round(r * math.sin(a)))
                            for r in (13, 24, 36, 50) for a in [k * math.pi / 4 for k in (2, 6, 0, 4, 1, 3, 5, 7)]]


def place_labels(fig, ax, labels):
    """Draws the snapshot labels so that no two overlap (nor the legend), after the layout is final."""
    fig.canvas.draw()  # runs the constrained layout: data-to-pixel positions are final from here
    renderer = fig.canvas.get_renderer()
    taken = []
    leg = ax.get_legend()
    if leg is not None:
        taken.append(leg.get_window_extent(renderer))
    for text, centre, colour in labels:
        placed = None
        for dx, dy in LABEL_OFFSETS:
            ann = ax.annotate(text, centre, xytext=(dx, dy), textcoords="offset points", fontsize=8, ha="center",
                              va="center", color=colour,
                              bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.7})
            box = ann.get_window_extent(renderer).expanded(1.05, 1.1)
            if not any(box.overlaps(b) for b in taken):
                placed = (ann, box, (dx, dy))
                break
            ann.remove()
        if placed is None:  # crowded everywhere: on the centre
            ann = ax.annotate(text, centre, fontsize=8, ha="center", va="center", color=colour)
            placed = (ann, ann.get_window_extent(renderer), (0, 0))
        ann, box, off = placed
        if off != (0, 0):
            ann.remove()
            ann = ax.annotate(text, centre, xytext=off, textcoords="offset points", fontsize=8, ha="center",
                              va="center", color=colour,
                              bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.7},
                              arrowprops={"arrowstyle": "-", "color": colour, "lw": 0.6, "shrinkA": 0, "shrinkB": 0})
        taken.append(box)


def marks_title(rep):
    return f"instants, intervals, contacts: {rep['arith']}"


def mark_answer(ax, rep, horizontal):
    """Collision intervals shaded, critical instants dashed; horizontal = t on the y axis."""
    span = ax.axhspan if horizontal else ax.axvspan
    line = ax.axhline if horizontal else ax.axvline
    for a, b in rep.get("intervals") or []:
        ta, tb = approx(a), approx(b)
        if tb > ta:
            span(ta, tb, color=COLLISION, alpha=0.13, lw=0)
        else:
            line(ta, color=COLLISION, alpha=0.35, lw=4)
    seen = set()
    for c in rep.get("critical_instants") or []:
        st = c["status"]
        seen.add(st)
        line(approx(c["t"]), color=STATUS_COLOUR.get(st, "black"), ls="--", lw=1.1)
    handles = [Patch(color=COLLISION, alpha=0.25, label="collision interval")] if rep.get("intervals") else []
    for st in ("touching", "overlapping", "separate", "uncertain"):
        if st in seen:
            handles.append(Line2D([], [], color=STATUS_COLOUR[st], ls="--", label=f"critical instant: {st}"))
    return handles


def draw_discriminant(ax, data):
    rep, cur = data["solve"], data["curve"]
    t = np.asarray(cur["t"], dtype=float)
    v = np.asarray(cur["value"], dtype=float)
    handles = mark_answer(ax, rep, horizontal=False)
    if cur["identically_zero"]:
        ax.plot(t, v, color="black", lw=1.5)
        ax.text(0.5, 0.6, "Δ ≡ 0: f has a multiple root at every t", transform=ax.transAxes, ha="center")
        ax.set_ylabel("Δ(t)")
    else:
        nz = np.abs(v[v != 0])
        lin = 10.0 ** math.floor(math.log10(nz.min())) if nz.size else 1e-12
        lin = min(max(lin, 1e-300), 1e-3)
        # the linear part around 0 gets about a tenth of the height, so that 0 and ±lin do not collide
        decades = round(-math.log10(lin))
        ax.set_yscale("symlog", linthresh=lin, linscale=max(1.0, 0.2 * decades))
        # ticks at 0 and ±10^e for e = 0, -step, ... down to lin (none inside the linear part)
        step = max(1, math.ceil(decades / 7))
        pos = [10.0 ** -e for e in range(0, decades + 1, step)]
        ax.set_yticks(sorted([-p for p in pos] + [0.0] + pos))
        ax.yaxis.set_minor_locator(matplotlib.ticker.NullLocator())
        ax.plot(t, v, color="black", lw=1.4)
        ax.set_ylabel(f"Δ(t) / max|Δ|   (symmetric log scale, linear within ±{lin:.0e})")
    ax.axhline(0, color="black", lw=0.6)
    contacts = data.get("contacts") or []
    if contacts:
        ax.plot([c["t"] for c in contacts], [0] * len(contacts), "o", mfc="none", mec=COLLISION, mew=2, ms=9)
        handles.append(Line2D([], [], color=COLLISION, marker="o", mfc="none", ls="", mew=2, label="external contact"))
    cyclo = cur["degree"] == -1 and not cur["identically_zero"]  # a cycloidal Δ: not a polynomial, enclosed in MPFI
    handles.insert(0, Line2D([], [], color="black", lw=1.4,
                             label="Δ(t), MPFI enclosures (mid-points)" if cyclo else "Δ(t), exact (sampled exactly)"))
    ax.set_xlim(0, 1)
    ax.set_xlabel("t")
    ax.grid(alpha=0.25)
    degree = "Δ ≡ 0" if cur["identically_zero"] else ("cycloidal: not a polynomial" if cyclo else f"degree {cur['degree']}")
    ax.set_title(f"Δ(t): discriminant in λ of f(λ;t) = det(λA − B), {degree}\n"
                 "(Δ > 0: three real roots in λ, Δ < 0: one; Δ = 0: a multiple root)", fontsize=10)
    ax.legend(handles=handles, fontsize=8, loc="best", framealpha=0.85, title=marks_title(rep), title_fontsize=8)


def draw_zero_set(ax, data):
    rep, cur = data["solve"], data["curve"]
    u = np.asarray(cur["u"], dtype=float)
    t = np.asarray(cur["t"], dtype=float)
    F = np.asarray(cur["value"], dtype=float)
    fmax = float(F.max())
    if fmax > 0:
        ax.contourf(u, t, F, levels=[0.0, fmax], colors=["#b8e3b0"])
    if F.min() < 0 < fmax:
        ax.contour(u, t, F, levels=[0.0], colors="black", linewidths=1.3)
    handles = mark_answer(ax, rep, horizontal=True)
    contacts = [c for c in data.get("contacts") or [] if "u" in c]
    if contacts:
        ax.plot([c["u"] for c in contacts], [c["t"] for c in contacts], "o", mfc="none", mec=COLLISION, mew=2, ms=9)
        handles.append(Line2D([], [], color=COLLISION, marker="o", mfc="none", ls="", mew=2,
                              label="external contact (u₀ = argmax F)"))
    handles[:0] = [
        Patch(color="#b8e3b0", label="F(u,t) > 0: separate at t"),
        Line2D([], [], color="black", lw=1.3, label="F(u,t) = 0"),
    ]
    w0, w1 = cur.get("u_window", [0.0, 1.0])
    ax.set_xlim(w0, w1)
    ax.set_ylim(0, 1)
    zoom = "" if (w0, w1) == (0.0, 1.0) else f";  zoomed to u ∈ [{w0:.3g}, {w1:.3g}]: F ≤ 0 elsewhere"
    ax.set_xlabel(f"u   (λ = (u − 1)/u sweeps the negative axis){zoom}")
    ax.set_ylabel("t")
    ax.set_title("zero set of F(u,t) = det((u−1)A(t) − uB(t)): separate at t iff F(u,t) > 0 for some u\n"
                 "(F(0,t) = det A < 0, F(1,t) = det B < 0; F built and sampled exactly, grid "
                 f"{len(u)}×{len(t)})", fontsize=10)
    ax.legend(handles=handles, fontsize=8, loc="best", framealpha=0.85, title=marks_title(rep), title_fontsize=8)


def draw_st(ax, data):
    """Independent motions (001 section 4): where A(s) meets B(t) in the (s, t) square (the zero set of F(u, s, t)
    projected on (s, t) is its boundary), with the answer's s-intervals along the s-axis and t-intervals along the
    t-axis."""
    import numpy as np
    from matplotlib.colors import ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    g, rep = data["st_grid"], data["solve"]
    z = np.array(g["meets"], dtype=float).T  # rows: t, columns: s
    cmap = ListedColormap(["#bbbbbb", "#b8e3b0", "#f4a6a6"])  # -1 uncertain, 0 separate, 1 meets
    ax.imshow(z, origin="lower", extent=(0, 1, 0, 1), cmap=cmap, vmin=-1.5, vmax=1.5, interpolation="nearest", aspect="auto")
    def bars(key, along_s):
        for a, b in rep.get(key, []):
            lo, hi = float(a["approx"]), float(b["approx"])
            w = max(hi - lo, 0.004)
            if along_s:
                ax.add_patch(matplotlib.patches.Rectangle((lo - (w - (hi - lo)) / 2, -0.045), w, 0.03, color="#c0392b", clip_on=False))
                ax.annotate(f"[{short(lo)}, {short(hi)}]", ((lo + hi) / 2, -0.07), ha="center", va="top", fontsize=8,
                            color="#c0392b", annotation_clip=False)
            else:
                ax.add_patch(matplotlib.patches.Rectangle((-0.045, lo - (w - (hi - lo)) / 2), 0.03, w, color="#1f4e9c", clip_on=False))
                ax.annotate(f"[{short(lo)}, {short(hi)}]", (-0.07, (lo + hi) / 2), ha="right", va="center", fontsize=8,
                            color="#1f4e9c", annotation_clip=False, rotation=90)
    bars("s_intervals", True)
    bars("t_intervals", False)
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.set_xlabel("s (A's path parameter)", labelpad=28)
    ax.set_ylabel("t (B's path parameter)", labelpad=28)
    ax.set_title(f"where A(s) meets B(t), {g['n']}×{g['n']} grid: its boundary is the zero set of\n"
                 f"F(u, s, t) = det((u−1)A(s) − uB(t)) projected on (s, t)\n{g['how']}", fontsize=9)
    handles = [Patch(color="#f4a6a6", label="A(s) and B(t) meet"), Patch(color="#b8e3b0", label="separate"),
               Line2D([], [], color="#c0392b", lw=6, label="s_intervals of the answer"),
               Line2D([], [], color="#1f4e9c", lw=6, label="t_intervals of the answer")]
    ax.legend(handles=handles, fontsize=8, loc="upper right", framealpha=0.85)


def independent_text(rep):
    if rep.get("collides") is None:
        return "unknown: no collision proved, a piece is undecided"
    if not rep.get("collides"):
        return "free: the swept volumes do not meet"
    return f"collides: {len(rep.get('s_intervals', []))} s-interval(s), {len(rep.get('t_intervals', []))} t-interval(s)"


def main(argv):
    if len(argv) != 3:
        print("usage: scene_figure.py DATA.json OUT.png", file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        data = json.load(f)
    if data.get("format") != "eccd-plot-data/1":
        print(f"scene_figure.py: {argv[1]}: not an eccd-plot-data/1 file", file=sys.stderr)
        return 2
    rep = data["solve"]
    if data.get("kind") == "independent":
        fig = plt.figure(figsize=(9, 8), dpi=100, layout="constrained")
        draw_st(fig.subplots(1, 1), data)
        fig.suptitle(f"{data['scene']} ({data['dim']}D, independent motions A(s), B(t)): {independent_text(rep)}\n"
                     f"answer in {data['arith']}" + (f" ({data['arith_note']})" if data.get("arith_note") else ""), fontsize=11)
        fig.savefig(argv[2], format="png")
        return 0
    fig = plt.figure(figsize=(14, 6), dpi=100, layout="constrained")
    left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.0, 1.15]})
    draw_objects(left, data)
    if data["dim"] == 2:
        draw_discriminant(right, data)
    else:
        draw_zero_set(right, data)
    fig.suptitle(f"{data['scene']} ({data['dim']}D): {answer_text(rep)}\n{arith_text(data)}", fontsize=12)
    place_labels(fig, left, data.get("_labels", []))
    fig.savefig(argv[2], format="png")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
