"""The report's figures, each drawn through plot_series() and recorded in FIGURE_MANIFEST."""

import math
import os
import statistics
import textwrap

from .common import ListedColormap, Patch, np, plt
from .fmt import base_label, fmt_err, fmt_ulps, group_name, is_clean, summarize
from .vocab import ISOLATED_CONTACT, NOT_PRECISION, failing_level, reason_class


# --------------------------------------------------------------------------- figures
#
# Every figure draws its series through plot_series(), which (1) merges series whose points are identical into one
# legend entry "A = B (identical)", (2) gives each series of a panel a colour AND a marker no other series of that
# panel has (a pipeline keeps its preferred style across panels where it can: colour by variant, marker by
# precision), and (3) records every panel in FIGURE_MANIFEST, written as figures.json next to the figures, so that a
# test can check the rules: at most MAX_SERIES series per panel, no two series sharing colour and marker.

DPI = 120
MAX_SERIES = 8
PALETTE = ("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#7f7f7f",
           "#bcbd22", "#000000", "#6b8e23")
MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*", "<", ">", "h", "p")
VARIANT_COLOUR = {"power": 0, "bezier-power": 0, "bernstein": 1, "bezier": 1, "scaled-bernstein": 2, "fcl/sample": 3,
                  "certified": 4, "sampling": 5, "fcl/ccd": 6, "ext": 7, "marching": 8, "exact": 10}
FIGURE_MANIFEST = {}


def pipeline_variant(data, p):
    PI = getattr(data, "all_pinfo", data.pinfo)
    arith = PI[p][0]
    b = base_label(p)
    if arith == "exact":
        return "exact"
    if arith == "certified":
        return "certified"
    if arith == "fcl":
        return b.split(":")[0]
    if arith == "external":
        return "ext"
    v = b.split("/", 1)[1] if "/" in b else b
    return v.split(":")[0]


def preferred_style(data, p):
    """(colour index, marker index) a pipeline asks for: colour by variant (basis or method), marker by precision."""
    PI = getattr(data, "all_pinfo", data.pinfo)
    arith, bits = PI[p][0], PI[p][1]
    colour = VARIANT_COLOUR.get(pipeline_variant(data, p), 9)
    if arith == "double":
        marker = 0
    elif arith == "mpfr":
        levels = sorted({PI[q][1] for q in PI if PI[q][0] == "mpfr"})
        marker = 1 + levels.index(bits) % (len(MARKERS) - 1)
    elif arith == "fcl":
        ns = sorted({PI[q][3] for q in PI if PI[q][0] == "fcl"})
        marker = (5 + ns.index(PI[p][3])) % len(MARKERS)
    elif arith == "external":
        exts = sorted({base_label(q) for q in PI if PI[q][0] == "external"})
        colour = (7 + exts.index(base_label(p))) % len(PALETTE)
        marker = 4
    elif arith == "certified":
        marker = 5
    else:
        marker = 7
    return colour, marker


def panel_styles(prefs):
    """prefs: list of (colour index, marker index). Returns one (colour, marker) per entry such that no two entries of
    the panel share a colour nor a marker (while there are enough of both): the preferred colour and marker where
    still free, else the first free one."""
    used_c, used_m, out = set(), set(), []
    for c, m in prefs:
        if c in used_c:
            c = next((k for k in range(len(PALETTE)) if k not in used_c), c)
        if m in used_m:
            m = next((k for k in range(len(MARKERS)) if k not in used_m), m)
        used_c.add(c)
        used_m.add(m)
        out.append((c, m))
    return out


def merge_identical(series):
    """series: list of dicts with label, xs, ys, pipelines. Series with the same points become one entry whose
    label names all of them and says they are identical."""
    merged = []
    for s in series:
        key = (tuple(s["xs"]), tuple(s["ys"]), tuple(s.get("lo") or ()), tuple(s.get("hi") or ()))
        for m in merged:
            if m["_key"] == key:
                m["labels"].append(s["label"])
                break
        else:
            merged.append(dict(s, labels=[s["label"]], _key=key))
    for m in merged:
        ls = m["labels"]
        m["label"] = (ls[0] if len(ls) == 1 else " = ".join(ls) + " (identical)" if len(ls) <= 3
                      else f"{len(ls)} identical: " + ", ".join(ls))
    return merged


def plot_series(ax, fig_name, panel_title, data, series, linestyle="-", band=False, xoffset=0.0):
    """Draws series (label, pipeline, xs, ys[, lo, hi]) on ax with panel-unique colour+marker; records the panel."""
    series = merge_identical([s for s in series if s["xs"]])
    if len(series) > MAX_SERIES:
        raise ValueError(f"{fig_name}: {len(series)} series in one panel (at most {MAX_SERIES})")
    styles = panel_styles([preferred_style(data, s["pipeline"]) for s in series])
    rec = []
    n = len(series)
    for k, (s, (ci, mi)) in enumerate(zip(series, styles)):
        colour, marker = PALETTE[ci], MARKERS[mi]
        off = (k - (n - 1) / 2) * xoffset
        xs = [x + off for x in s["xs"]]
        ax.plot(xs, s["ys"], linestyle=linestyle, marker=marker, color=colour, markersize=6,
                markevery=s.get("markevery"),
                label=textwrap.fill(s["label"], 44, subsequent_indent="  "))
        if band and s.get("lo") is not None:
            ax.fill_between(xs, s["lo"], s["hi"], color=colour, alpha=0.12, linewidth=0)
        rec.append({"label": s["label"], "color": colour, "marker": marker, "linestyle": linestyle,
                    "merged": len(s["labels"])})
    FIGURE_MANIFEST.setdefault(fig_name, []).append({"panel": panel_title, "series": rec})
    return rec


def chunks(items, size=MAX_SERIES):
    return [items[i:i + size] for i in range(0, len(items), size)] or [[]]


def _floor_for(values, lowest=1e-20):
    """Where zeros (and errors below `lowest`) are drawn on a log axis."""
    pos = [v for v in values if v is not None and v > 0 and math.isfinite(v)]
    return max(10.0 ** (math.floor(math.log10(min(pos))) - 1), lowest) if pos else 1e-17


def held_basis(info):
    """The basis a pipeline's coef_err is measured in (compare/harness.hpp): power form for 2D power and the 3D
    projection, Bernstein form otherwise (the 3D bezier-power setup holds f in Bernstein form too)."""
    return "power form" if info[2] == "power" and info[3] in ("cd-disc", "projection") else "Bernstein form"


def _grid(nrow, ncol, width=6.0, height=4.2):
    fig, axes = plt.subplots(nrow, ncol, figsize=(width * ncol, height * nrow), squeeze=False)
    return fig, axes


def _legend(ax, outside=False):
    if not ax.get_legend_handles_labels()[0]:
        return
    if outside == "below":
        ax.legend(fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.24))
    elif outside:
        ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    else:
        ax.legend(fontsize="small", loc="best")


def _save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=DPI, bbox_inches="tight", format="png")
    plt.close(fig)


def coef_rows(data, dim, pipeline=None):
    """Rows that carry coefficient errors: the prepared input mode (rounded rows have none)."""
    return [r for r in data.all_rows if r["dim"] == dim and r["coef_err"] is not None
            and (pipeline is None or r["pipeline"] == pipeline)]


def coef_pipelines(data, dim):
    """The double form pipelines' labels in the prepared mode (those with coefficient errors)."""
    out = []
    for p in data.all_order:
        info = data.all_pinfo[p]
        if info[0] == "double" and info[3] in ("cd-disc", "bezier") and coef_rows(data, dim, p):
            out.append(p)
    return out


def has_common(data):
    return any(r.get("coef_err_common") is not None for r in data.all_rows)


def fig_coef_vs_degree(data, path):
    """Per dim: median coefficient error of the double form pipelines vs degree (prepared input), in the basis
    each pipeline holds its coefficients (left) and in the common Bernstein basis (right, when measured)."""
    name = os.path.basename(path)
    dims = [dim for dim in data.dims if coef_pipelines(data, dim)]
    if not dims:
        return None
    cols = [("coef_err", "own basis")]
    if has_common(data):
        cols.append(("coef_err_common", "common basis (Bernstein on [0, 1])"))
    allvals = [r[c] for dim in dims for r in coef_rows(data, dim) for c, _ in cols if r.get(c) is not None]
    floor = _floor_for(allvals)
    fig, axes = _grid(len(dims), len(cols), width=6.2, height=4.4)
    for i, dim in enumerate(dims):
        one_basis = len({held_basis(data.all_pinfo[p]) for p in coef_pipelines(data, dim)}) == 1
        for j, (col, what) in enumerate(cols):
            ax = axes[i][j]
            if one_basis and len(cols) > 1 and col == "coef_err":
                ax.axis("off")  # every pipeline holds Bernstein coefficients: the own basis is the common one
                ax.text(0.5, 0.5, textwrap.fill(f"{dim}D: every pipeline holds its coefficients in Bernstein form, "
                                                f"so its own basis is the common basis (right).", 40),
                        ha="center", va="center", transform=ax.transAxes, fontsize="medium", color="0.3")
                continue
            if one_basis and col == "coef_err_common":
                what += ": every pipeline's own basis here"
            series = []
            for p in coef_pipelines(data, dim):
                pts = {}
                for r in coef_rows(data, dim, p):
                    if r.get(col) is not None and math.isfinite(r[col]):
                        pts.setdefault(r["degree"], []).append(max(r[col], floor))
                degs = sorted(pts)
                series.append({"label": base_label(p), "pipeline": p, "xs": degs,
                               "ys": [float(np.median(pts[g])) for g in degs],
                               "lo": [float(np.percentile(pts[g], 10)) for g in degs],
                               "hi": [float(np.percentile(pts[g], 90)) for g in degs]})
            title = f"{dim}D, {what}"
            if col == "coef_err":
                title += " (" + ", ".join(f"{base_label(p)}: {held_basis(data.all_pinfo[p])}"
                                          for p in coef_pipelines(data, dim)) + ")"
            plot_series(ax, name, title, data, series, band=True, xoffset=0.05)
            ax.axhline(floor, color="0.5", linewidth=0.8, linestyle=":")
            ax.set_yscale("log")
            ax.set_xticks(data.degrees[dim])
            ax.set_xlabel("motion degree")
            ax.set_ylabel("coefficient error of g (median; band 10–90%)")
            ax.set_title(textwrap.fill(title, 48), fontsize="medium")
            ax.grid(True, which="major", alpha=0.3)
            _legend(ax)
        used = [ax for ax in axes[i] if ax.axison]
        if not used:
            continue
        lo, hi = min(ax.get_ylim()[0] for ax in used), max(ax.get_ylim()[1] for ax in used)
        for ax in used:
            ax.set_ylim(lo, hi)  # one scale per dimension: own and common basis compare by eye
    _save(fig, path)
    common = ("; right: the same coefficients converted exactly to the Bernstein basis, the only column that "
              "compares pipelines" if len(cols) > 1 else "; results.csv has no coef_err_common column (an older "
              "run), so only the own-basis error is drawn and the pipelines cannot be compared")
    return (f"Median coefficient error of g_0..g_n in double precision per motion degree, prepared input mode only "
            f"(rounded rows carry no coefficient error); band: 10th to 90th percentile. Left: in the basis each "
            f"pipeline holds them{common}. Errors below {fmt_err(floor)} (zeros included) are drawn at it (dotted); "
            f"identical series are one legend entry.")


def fig_coef_hist(data, path):
    name = os.path.basename(path)
    col = "coef_err_common" if has_common(data) else "coef_err"
    dims = [dim for dim in data.dims if coef_pipelines(data, dim)]
    if not dims:
        return None
    allvals = [r[col] for dim in dims for r in coef_rows(data, dim) if r.get(col) is not None
               and math.isfinite(r[col])]
    if not allvals:
        return None
    floor = _floor_for(allvals)
    logs = [math.log10(max(v, floor)) for v in allvals]
    lo, hi = math.floor(min(logs)), math.ceil(max(logs))
    if hi <= lo:
        hi = lo + 1
    edges = np.arange(lo - 0.25, hi + 0.5, 0.5)
    centres = [float(c) for c in (edges[:-1] + edges[1:]) / 2]
    fig, axes = _grid(1, len(dims), width=6.2, height=4.4)
    for ax, dim in zip(axes[0], dims):
        series = []
        for p in coef_pipelines(data, dim):
            vals = [r[col] for r in coef_rows(data, dim, p) if r.get(col) is not None and math.isfinite(r[col])]
            counts, _ = np.histogram(np.log10(np.maximum(np.array(vals), floor)), bins=edges)
            series.append({"label": f"{base_label(p)} ({len(vals)} scenes)", "pipeline": p, "xs": centres,
                           "ys": [int(c) for c in counts],
                           "markevery": [i for i, c in enumerate(counts) if c > 0]})  # markers on counts > 0
        what = "common basis" if col == "coef_err_common" else "own basis"
        title = f"{dim}D: coefficient error of g, double, {what}"
        plot_series(ax, name, title, data, series)
        ax.set_xlabel(f"log10 coefficient error (below {math.log10(floor):.0f}, zero too: at {math.log10(floor):.0f})")
        ax.set_ylabel("scenes per half decade")
        ax.set_title(title, fontsize="medium")
        ax.yaxis.get_major_locator().set_params(integer=True)
        ax.grid(True, alpha=0.3)
        _legend(ax)
    _save(fig, path)
    basis = ("in the common (Bernstein) basis" if col == "coef_err_common" else
             "in each pipeline's own basis (no coef_err_common in results.csv)")
    return (f"Distribution of log10 of the coefficient error {basis}, per double pipeline, prepared input mode only; "
            f"points are the counts per half decade. Errors below 1e{math.log10(floor):.0f} (zeros included) are "
            f"counted at log10 = {math.log10(floor):.0f}.")


def fig_misclass_vs_d(data, path):
    name = os.path.basename(path)
    dims = [dim for dim in data.dims if data.nearmiss_pipelines(dim)]
    if not dims:
        return None
    # A pipeline never misclassified and never undecided at any d draws two flat lines at 0: it is named in
    # the caption instead of taking panels (FCL at near-miss separations: it always says separate).
    rows_spec, flat = [], []  # (dim, pipelines of this row of panels); (dim, pipeline) left out as flat
    for dim in dims:
        nm = data.nearmiss_rows(dim)
        shown = []
        for p in data.nearmiss_pipelines(dim):
            rs = [r for r in nm if r["pipeline"] == p]
            s_ = summarize(rs) if rs else None
            if s_ and s_["mis"] == 0 and s_["und"] == 0:
                flat.append((dim, p))
            else:
                shown.append(p)
        for part in chunks(shown):
            rows_spec.append((dim, part))
    fig, axes = _grid(len(rows_spec), 2, width=6.0, height=5.6)
    for i, (dim, pl) in enumerate(rows_spec):
        nm = data.nearmiss_rows(dim)
        ds = sorted({r["d"] for r in nm}, reverse=True)
        for j, (what, key) in enumerate((("misclassified", "mis"), ("undecided", "und"))):
            ax = axes[i][j]
            series = []
            for p in pl:
                xs, ys = [], []
                for d in ds:
                    rs = [r for r in nm if r["pipeline"] == p and r["d"] == d]
                    if rs:
                        s = summarize(rs)
                        xs.append(d)
                        ys.append(100.0 * s[key] / s["n"])
                series.append({"label": p, "pipeline": p, "xs": xs, "ys": ys})
            title = f"{dim}D near-miss: {what} (%)"
            plot_series(ax, name, title, data, series)
            ax.set_xscale("log")
            if len(ds) > 1:
                ax.set_xlim(max(ds) * 3, min(ds) / 3)  # decreasing separation to the right
            ax.set_ylim(-5, 105)
            ax.set_xlabel("separation d (decreasing →)")
            ax.set_ylabel(f"scenes {what} (%)")
            ax.set_title(title, fontsize="medium")
            ax.grid(True, alpha=0.3)
            _legend(ax, outside="below")
    _save(fig, path)
    flat_note = ""
    if flat:
        by_dim = {}
        for dim, p in flat:
            by_dim.setdefault(dim, []).append(p)
        flat_note = (" Never misclassified and never undecided at any d, so not drawn: "
                     + "; ".join(f"{dim}D {', '.join(ps)}" for dim, ps in by_dim.items()) + ".")
    return ("Near-miss family, all degrees pooled: share of scenes misclassified (false positive or false negative, "
            "left) and undecided (right) against the separation d; one row of panels per dimension (more rows when "
            "a dimension has more than 8 pipelines drawn); identical series are one legend entry." + flat_note)


def fig_min_bits(data, path, minbits):
    name = os.path.basename(path)
    dims = [dim for dim in data.dims if minbits.get(dim)]
    if not dims:
        return None
    fig, axes = _grid(1, len(dims), width=6.0, height=4.4)
    hollow_seen = False
    for ax, dim in zip(axes[0], dims):
        table = minbits[dim]  # (basis, method) -> degree -> bits | "none of the tested"
        levels = sorted({b for grp in data.mpfr_groups(dim).values() for b in grp})
        ypos = {b: i for i, b in enumerate(levels)}
        none_y = len(levels)
        series = []
        for grp, by_deg in table.items():
            degs = sorted(by_deg)
            p = next(iter(data.mpfr_groups(dim)[grp].values()))
            series.append({"label": group_name(*grp), "pipeline": p, "xs": degs,
                           "ys": [ypos[by_deg[g]] if isinstance(by_deg[g], int) else none_y for g in degs]})
        title = f"{dim}D: smallest clean MPFR precision (touch, graze apart)"
        rec = plot_series(ax, name, title, data, series, xoffset=0.08)
        # hollow: every run that keeps the precision up is a time-out (the time budget, not the precision)
        nser = len(rec)
        for k, (s_, st) in enumerate(zip(merge_identical([x for x in series if x["xs"]]), rec)):
            grp = next(g for g in table if group_name(*g) == s_["labels"][0])
            hx, hy = [], []
            for x, y in zip(s_["xs"], s_["ys"]):
                causes = minbits_causes(data, dim, grp, x, table[grp][x])
                if causes and set(causes) <= set(NOT_PRECISION):
                    hx.append(x + (k - (nser - 1) / 2) * 0.08)
                    hy.append(y)
            if hx:
                ax.plot(hx, hy, linestyle="none", marker=st["marker"], markersize=9, markerfacecolor="white",
                        markeredgecolor=st["color"], markeredgewidth=1.8)
                hollow_seen = True
                if not any(line.get_label().startswith("hollow") for line in ax.lines):
                    ax.plot([], [], linestyle="none", marker="o", markerfacecolor="white", markeredgecolor="0.3",
                            label="hollow: only time-outs or work bounds keep it up (not precision)")
        ax.axhline(none_y - 0.5, color="0.5", linewidth=0.8, linestyle=":")
        ax.set_yticks(list(range(len(levels) + 1)))
        ax.set_yticklabels([str(b) for b in levels] + ["none of\nthe tested"])
        ax.set_ylim(-0.5, none_y + 0.5)
        ax.set_xticks(data.degrees[dim])
        ax.set_xlabel("motion degree")
        ax.set_ylabel("MPFR precision (bits)")
        ax.set_title(title, fontsize="medium")
        ax.grid(True, alpha=0.3)
        _legend(ax, outside="below")
    _save(fig, path)
    return ("Smallest tested MPFR precision at which this and every larger tested precision has no false positive, "
            "false negative, undecided or error on the scenes of that dimension and degree, touch and graze scenes "
            "counted apart (table *MPFR bits per family*); above the dotted line: none of the tested precisions."
            + (" Hollow marker: every run that keeps the precision up there hit the time budget or a work bound, "
               "not a precision limit." if hollow_seen else ""))


def minbits_causes(data, dim, grp, deg, bits):
    """Reason classes of the runs (touch and graze apart) that are not clean at the largest tested precision that
    is not clean, for one dim x degree x (basis, method): what keeps the smallest clean precision at `bits`."""
    by_bits = data.mpfr_groups(dim).get(grp, {})
    rb = {b: [r for r in data.sel(dim=dim, degree=deg, pipeline=p) if r["family"] not in ISOLATED_CONTACT]
          for b, p in by_bits.items()}
    rb = {b: x for b, x in rb.items() if x}
    fl = failing_level(bits, rb) if rb else None
    if fl is None:
        return []
    return [reason_class(r) for r in rb[fl] if not is_clean(r)]


def fig_time(data, path):
    name = os.path.basename(path)
    dims = [dim for dim in data.dims if any(r["time_us"] is not None for r in data.sel(dim=dim))]
    if not dims:
        return None
    # Two panels per dimension, at most 8 series each: eccd's arithmetics, each pooled over its bases and
    # methods (the time of each basis is in the tables: *Bernstein versus power*), and the baselines and other
    # engines with exact for reference.
    layout = []  # per dim: list of (title, series specs); a spec: (label, style pipeline, pipelines pooled)
    for dim in dims:
        pl = data.pipelines(dim)
        grid = [p for p in pl if data.pinfo[p][0] == "double" and data.pinfo[p][3] in ("sampling", "marching")]
        ref = [p for p in pl if data.pinfo[p][0] == "exact"]
        own = [("exact", ref[0], ref)] if ref else []
        own += [(p, p, [p]) for p in pl if data.pinfo[p][0] == "certified"]
        dbl = [p for p in pl if data.pinfo[p][0] == "double" and p not in grid]
        if dbl:
            own.append((f"double ({len(dbl)} pooled)" if len(dbl) > 1 else dbl[0], dbl[0], dbl))
        levels = sorted({data.pinfo[p][1] for p in pl if data.pinfo[p][0] == "mpfr"})
        for b in levels:
            ps = [p for p in pl if data.pinfo[p][0] == "mpfr" and data.pinfo[p][1] == b]
            own.append((f"mpfr:{b} ({len(ps)} pooled)" if len(ps) > 1 else ps[0], ps[0], ps))
        peers = [(p, p, [p]) for p in grid] + [(p, p, [p]) for p in pl if data.pinfo[p][0] in ("fcl", "external")]
        panels = []
        for k, part in enumerate(chunks(own)):
            panels.append((f"{dim}D: eccd's arithmetics" + (f" ({k + 1})" if len(own) > MAX_SERIES else ""), part))
        if peers:
            ex = own[:1] if ref else []
            for k, part in enumerate(chunks(peers, MAX_SERIES - len(ex))):
                panels.append((f"{dim}D: baselines and other engines (exact for reference)"
                               + (f" ({k + 1})" if len(peers) > MAX_SERIES - len(ex) else ""), ex + part))
        layout.append((dim, [pn for pn in panels if pn[1]]))
    ncol = max(len(p) for _, p in layout)
    fig, axes = _grid(len(layout), ncol, width=5.4, height=4.0)
    for i, (dim, panels) in enumerate(layout):
        for j in range(ncol):
            ax = axes[i][j]
            if j >= len(panels):
                ax.axis("off")
                continue
            title, specs = panels[j]
            series = []
            for label, style, pooled in specs:
                pts = {}
                for p in pooled:
                    for r in data.sel(dim=dim, pipeline=p):
                        if r["outcome"] != "error" and r["time_us"] is not None and r["time_us"] > 0:
                            pts.setdefault(r["degree"], []).append(r["time_us"])
                degs = sorted(pts)
                series.append({"label": label, "pipeline": style, "xs": degs,
                               "ys": [float(statistics.median(pts[g])) for g in degs]})
            plot_series(ax, name, title, data, series)
            ax.set_yscale("log")
            ax.set_xticks(data.degrees[dim])
            ax.set_xlabel("motion degree")
            ax.set_ylabel("median time per query (µs)")
            ax.set_title(title, fontsize="medium")
            ax.grid(True, which="major", alpha=0.3)
            _legend(ax)
    # one y range per row, so that the panels of a dimension compare by eye
    for i in range(len(layout)):
        used = [ax for ax in axes[i] if ax.get_visible() and ax.lines]
        if used:
            # from the data, with room on the log scale so that no marker is cut at the top or bottom
            ys = [y for ax in used for line in ax.lines for y in line.get_ydata() if y > 0]
            lo, hi = (min(ys) / 2.5, max(ys) * 2.5) if ys else (min(ax.get_ylim()[0] for ax in used), max(ax.get_ylim()[1] for ax in used))
            for ax in used:
                ax.set_ylim(lo, hi)
    _save(fig, path)
    return ("Median wall time of one query per motion degree (log scale, one y range per dimension), rows that ended "
            "in an error left out; left: eccd's arithmetics, each pooled over its bases and methods (per basis: "
            "*Bernstein versus power*); right: the grid baselines, FCL and external engines next to exact.")


FM_COLORS = {"separate": "#9ecae1", "touching": "#fdd835", "colliding": "#e53935", "undecided": "#9e9e9e",
             "error": "#212121", "missing": "#ffffff"}
FM_ORDER = ("separate", "touching", "colliding", "undecided", "error", "missing")


def fig_failure_map(data, path):
    rows = data.fmap["rows"]
    exact_at, ux, uy = data.fmap["exact"], data.fmap["ux"], data.fmap["uy"]
    nx, ny = max(ux) + 1, max(uy) + 1
    panels = list(dict.fromkeys(r["pipeline"] for r in rows))
    grids = {}
    for p in panels:
        g = np.full((ny, nx), FM_ORDER.index("missing"))
        for r in rows:
            if r["pipeline"] == p:
                g[r["iy"], r["ix"]] = FM_ORDER.index(r["answer"])
        grids[p] = g
    g = np.full((ny, nx), FM_ORDER.index("missing"))
    for (ix, iy), a in exact_at.items():
        g[iy, ix] = FM_ORDER.index(a)
    grids["exact"] = g
    # pipelines with identical answers on every cell share one panel, titled with all their names
    merged = []
    for p in panels:
        for m in merged:
            if np.array_equal(grids[m[0]], grids[p]):
                m.append(p)
                break
        else:
            merged.append([p])
    titles = {m[0]: (m[0] if len(m) == 1 else textwrap.fill(" = ".join(m) + " (identical)", 34)) for m in merged}
    titles["exact"] = "exact"
    names = [m[0] for m in merged] + ["exact"]
    ncol = min(4, len(names))
    nrow = math.ceil(len(names) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.6 * ncol, 3.6 * nrow + 0.6), squeeze=False)
    cmap = ListedColormap([FM_COLORS[a] for a in FM_ORDER])
    fm_meta = data.meta.get("failure_map") or {}
    xlab, ylab = "x input (ulps)", "y input (ulps)"  # the inputs' descriptions go under the figure
    step_x, step_y = max(1, nx // 8), max(1, ny // 8)
    for k, ax in enumerate(axes.flat):
        if k >= len(names):
            ax.axis("off")
            continue
        p = names[k]
        ax.imshow(grids[p], cmap=cmap, vmin=-0.5, vmax=len(FM_ORDER) - 0.5, origin="lower", interpolation="nearest")
        if p != "exact" and max(nx, ny) <= 40:
            wy, wx = np.nonzero((grids[p] != grids["exact"]) & (grids[p] != FM_ORDER.index("missing")))
            ax.plot(wx, wy, "kx", markersize=max(3, 60 // max(nx, ny)))
        ax.set_xticks(range(0, nx, step_x))
        ax.set_xticklabels([fmt_ulps(ux.get(i, float("nan"))) if i in ux else "" for i in range(0, nx, step_x)])
        ax.set_yticks(range(0, ny, step_y))
        ax.set_yticklabels([fmt_ulps(uy.get(i, float("nan"))) if i in uy else "" for i in range(0, ny, step_y)])
        ax.set_xlabel(xlab, fontsize="small")
        if k % ncol == 0:
            ax.set_ylabel(ylab, fontsize="small")
        ax.set_title(titles[p], fontsize="medium")
    present = {FM_ORDER[v] for gr in grids.values() for v in np.unique(gr)}
    handles = [Patch(facecolor=FM_COLORS[a], edgecolor="0.3", label=a) for a in FM_ORDER if a in present]
    FIGURE_MANIFEST.setdefault(os.path.basename(path), []).append(
        {"panel": "legend (every panel)", "series": [{"label": a, "color": FM_COLORS[a], "marker": "square",
                                                      "linestyle": "none", "merged": 1}
                                                     for a in FM_ORDER if a in present]})
    title = f"Failure map around {fm_meta['scene']}" if fm_meta.get("scene") else "Failure map"
    fig.suptitle(title + " (× = answer differs from exact)")
    fig.tight_layout()
    fig.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, 0.0), ncol=len(handles), frameon=False)
    inputs = [f"{a} input: {fm_meta[k2]}" for a, k2 in (("x", "x_input"), ("y", "y_input")) if fm_meta.get(k2)]
    if inputs:
        width = int(30 * ncol)
        fig.text(0.5, -0.07, "\n".join(textwrap.fill(t, width) for t in inputs), ha="center", va="top",
                 fontsize="small")
    _save(fig, path)
    return ("Answer of each pipeline on the scene perturbed by the given number of ulps in two inputs; "
            "the last panel is the exact answer; × marks a cell whose answer differs from it.")
