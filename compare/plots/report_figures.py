#!/usr/bin/env python3
"""Turn the raw output of `eccd report` into the human robustness report.

Usage:  python3 compare/plots/report_figures.py DIR

Reads   DIR/results.csv     one row per (scene, pipeline), the harness's contract
        DIR/meta.json       what was run, where, when
        DIR/failure_map.csv optional: answers on an n x n grid of ulp perturbations
Writes  DIR/report.md       tables and a plain-language summary, every number from the data
        DIR/*.png           coef_error_vs_degree, coef_error_hist, misclassification_vs_d,
                            min_mpfr_bits_vs_degree, time_vs_degree, failure_map
                            (a figure whose data are absent is skipped, and report.md says so)

Definitions used throughout (they are repeated in report.md):
  misclassification rate   (false positives + false negatives) / scenes; undecided and
                           error rows count in `scenes` but are reported apart, never as
                           right or wrong.
  smallest correct d       for a pipeline, the smallest near-miss separation d in the data
                           such that for this d and every larger d all its near-miss scenes
                           are `correct` (undecided and error are not correct); "none" if
                           the largest d already fails.
  smallest clean precision for dim x degree x (basis, method), the smallest MPFR precision p
                           in the data such that for p and every larger tested precision no
                           scene of that dim x degree is a false positive, false negative,
                           undecided or error; "none of the tested" otherwise.
  time                     medians of time_us over rows whose outcome is not `error` (an error row
                           has no measured time; the harness writes 0 there).
  trustworthy              per family group and input mode, an arithmetic (double, mpfr:B; all its
                           pipelines pooled) with no false positive, false negative or error; undecided
                           answers (the pipelines' own, from an error bound or a time budget) are
                           honest and counted apart. "Trustworthy from mpfr:B on": B and every larger
                           tested precision are.
  input modes              results.csv's `input` column: `rounded` (the scene's numbers rounded to the
                           arithmetic) or `prepared` (coefficients prepared exactly, then rounded). The
                           main sections read the rounded rows where there are any; the section on
                           input modes reads both. Columns `input`, `digits` and `reason` may be absent
                           (older files: input `prepared`).

Everything is written to a temporary folder inside DIR and moved into place at the end
(figures first, report.md last), so a failure leaves no half-written report. Exit status:
0 success, 2 missing or malformed input (the message names the file, line and column),
1 anything else. Needs Python 3, numpy and matplotlib (Debian: python3-matplotlib).
"""

import csv
import json
import math
import os
import shutil
import statistics
import sys
import tempfile
import textwrap

PROG = "report_figures.py"


def _die(msg, status=2):
    print(f"{PROG}: {msg}", file=sys.stderr)
    sys.exit(status)


try:
    import numpy as np
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch
except ImportError as _e:  # e.g. a pyenv/venv python3 first on PATH without the Debian packages
    _alt = "/usr/bin/python3"
    if (os.path.exists(_alt) and os.path.realpath(sys.executable) != os.path.realpath(_alt)
            and not os.environ.get("ECCD_REPORT_FIGURES_REEXEC")):
        os.environ["ECCD_REPORT_FIGURES_REEXEC"] = "1"
        os.execv(_alt, [_alt] + sys.argv)
    _die(f"needs numpy and matplotlib ({_e}); on Debian: apt-get install python3-matplotlib", 1)


class InputError(Exception):
    """Missing or malformed input; the message names file, line and column."""


# --------------------------------------------------------------------------- input

OUTCOMES = ("correct", "false_positive", "false_negative", "undecided", "error")
ARITHS = ("double", "mpfr", "exact", "certified", "fcl", "external")  # fcl: FCL as a peer; external: report --external
BASES = ("power", "bernstein", "scaled-bernstein", "exact", "none")  # none: certified, fcl and external rows
FAMILIES = ("colliding", "free", "touch", "near-miss", "overlap", "graze", "decimal", "keyframe", "case")
SOURCES = ("generated", "cases")
MOTIONS = ("kinematic", "euler", "affine", "translation", "case")
INPUTS = ("rounded", "prepared")
ANSWERS = ("separate", "touching", "colliding", "undecided", "error")

# column -> (kind, empty allowed, choices); empty allowed: True, False, "error" (only on rows whose outcome is
# error) or "nodecision" (only on error or undecided rows: a pipeline that decided nothing may leave them empty)
RESULT_COLUMNS = [
    ("scene", "str", False, None),
    ("source", "str", False, SOURCES),
    ("dim", "int", False, (2, 3)),
    ("degree", "int", False, None),
    ("family", "str", False, FAMILIES),
    ("motion", "str", False, MOTIONS),
    ("d", "float", True, None),
    ("seed", "int", True, None),
    ("pipeline", "str", False, None),
    ("arith", "str", False, ARITHS),
    ("bits", "int", False, None),
    ("basis", "str", False, BASES),
    ("method", "str", False, None),
    ("coef_err", "float", True, None),
    ("delta_err", "float", True, None),
    ("outcome", "str", False, OUTCOMES),
    ("collides", "int", "nodecision", (0, 1)),
    ("exact_collides", "int", False, (0, 1)),
    ("intervals", "int", "nodecision", None),
    ("exact_intervals", "int", False, None),
    ("missed_contacts", "int", "nodecision", None),
    ("false_contacts", "int", "nodecision", None),
    ("first_contact_err", "float", True, None),
    ("endpoint_err", "float", True, None),
    ("time_us", "float", "error", None),
    ("structure_ok", "int", "error", (0, 1)),
]

# Columns added later (issue 14): a results.csv without them reads with these defaults (before input modes
# existed every floating pipeline started from the prepared scene).
OPTIONAL_RESULT_COLUMNS = [
    ("input", "str", False, INPUTS, "prepared"),
    ("digits", "int", True, None, None),
    ("reason", "str", True, None, None),
    ("coef_err_common", "float", True, None, None),
]

FAILURE_COLUMNS = [
    ("pipeline", "str", False, None),
    ("ix", "int", False, None),
    ("iy", "int", False, None),
    ("dx_ulps", "float", False, None),
    ("dy_ulps", "float", False, None),
    ("answer", "str", False, ANSWERS),
    ("exact", "str", False, ANSWERS),
]

META_KEYS = ("name", "command", "seed", "mpfr_bits", "degrees", "families", "pipelines", "machine",
             "version", "started", "wall_seconds", "shards", "scene_count", "failure_map")


def _convert(text, kind, where):
    if kind == "str":
        return text
    if kind == "int":
        try:
            return int(text)
        except ValueError:
            raise InputError(f"{where}: '{text}' is not an integer") from None
    try:
        v = float(text)
    except ValueError:
        raise InputError(f"{where}: '{text}' is not a number") from None
    return v


def read_csv(path, columns, optional=()):
    """Rows of a CSV file (RFC 4180 quoting, as compare/csv.hpp writes it; read with the `csv` module), converted
    per `columns`.

    `optional`: (column, kind, empty allowed, choices, default) of columns that may be absent from the header (every
    row then gets the default). Each row is a dict (plus '_line', its line number in the file)."""
    name = os.path.basename(path)
    if not os.path.isfile(path):
        raise InputError(f"{path}: not found")
    records = []  # (line the record starts on, fields)
    start = 1
    try:
        with open(path, encoding="utf-8", newline="") as fh:
            reader = csv.reader(fh, strict=True)
            for rec in reader:
                records.append((start, rec))
                start = reader.line_num + 1
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: cannot be read ({e})") from None
    except csv.Error as e:
        raise InputError(f"{name} line {start}: malformed CSV, a quoted field that is not closed or a stray quote "
                         f"({e})") from None
    if not records or not "".join(records[0][1]).strip():
        raise InputError(f"{name} line 1: empty, expected the header row")
    header = [h.strip() for h in records[0][1]]
    index = {}
    for i, h in enumerate(header):
        if h in index:
            raise InputError(f"{name} line 1, column {i + 1}: column '{h}' appears twice in the header")
        index[h] = i
    for col, *_ in columns:
        if col not in index:
            raise InputError(f"{name} line 1: the header lacks column '{col}'")
    present_optional = [o[:4] for o in optional if o[0] in index]
    absent_optional = [(o[0], o[4]) for o in optional if o[0] not in index]
    columns = list(columns) + present_optional
    rows = []
    for ln, fields in records[1:]:
        if not "".join(fields).strip():
            continue
        if len(fields) != len(header):
            raise InputError(f"{name} line {ln}: {len(fields)} fields, the header has {len(header)}")
        raw = {h: fields[i].strip() for h, i in index.items()}
        row = {"_line": ln}
        for col, kind, empty_ok, choices in columns:
            text = raw[col]
            where = f"{name} line {ln}, column '{col}' (column {index[col] + 1})"
            if text == "":
                if (empty_ok is True or (empty_ok == "error" and raw["outcome"] == "error")
                        or (empty_ok == "nodecision" and raw["outcome"] in ("error", "undecided"))):
                    row[col] = None
                    continue
                raise InputError(f"{where}: empty, a value is required")
            v = _convert(text, kind, where)
            if kind == "float" and math.isnan(v):
                v = None  # "nan": not measured
            if choices is not None and v not in choices:
                raise InputError(f"{where}: '{text}' is not one of {', '.join(map(str, choices))}")
            row[col] = v
            if col == "d" and v is not None:
                row["d_text"] = text
        for col, default in absent_optional:
            row[col] = default
        rows.append(row)
    return rows


def check_results(rows):
    """Contract checks that the aggregates rely on. Returns pipeline -> (arith, bits, basis, method)."""
    if not rows:
        raise InputError("results.csv: no data rows after the header")
    seen = {}
    scene_attr = {}
    pinfo = {}
    for r in rows:
        ln = r["_line"]
        key = (r["scene"], r["pipeline"])
        if key in seen:
            raise InputError(f"results.csv line {ln}, column 'pipeline': a second row for scene '{r['scene']}' and "
                             f"pipeline '{r['pipeline']}' (the first is on line {seen[key]})")
        seen[key] = ln
        attrs = (r["dim"], r["degree"], r["family"], r["d"])
        if r["scene"] in scene_attr and scene_attr[r["scene"]][0] != attrs:
            first_attrs, first_ln = scene_attr[r["scene"]]
            for col, a, b in zip(("dim", "degree", "family", "d"), attrs, first_attrs):
                if a != b:
                    raise InputError(f"results.csv line {ln}, column '{col}': scene '{r['scene']}' has {col} {a} here "
                                     f"but {b} on line {first_ln}")
        scene_attr.setdefault(r["scene"], (attrs, ln))
        if r["family"] == "near-miss" and r["d"] is None:
            raise InputError(f"results.csv line {ln}, column 'd': empty, a near-miss scene needs its separation d")
        # exact's method is cd-disc in 2D and the projection in 3D
        info = (r["arith"], r["bits"], r["basis"], r["method"] if r["pipeline"] != "exact" else "exact")
        if r["pipeline"] in pinfo and pinfo[r["pipeline"]][0] != info:
            raise InputError(f"results.csv line {ln}, column 'pipeline': '{r['pipeline']}' has arith/bits/basis/method "
                             f"{'/'.join(map(str, info))} here but {'/'.join(map(str, pinfo[r['pipeline']][0]))} "
                             f"on line {pinfo[r['pipeline']][1]}")
        pinfo.setdefault(r["pipeline"], (info, ln))
        o, c, e = r["outcome"], r["collides"], r["exact_collides"]
        expect = {"correct": (c == e), "false_positive": (c == 1 and e == 0), "false_negative": (c == 0 and e == 1)}
        if o in expect and not expect[o]:
            raise InputError(f"results.csv line {ln}, column 'outcome': '{o}' contradicts collides={c}, "
                             f"exact_collides={e}")
    return {p: v[0] for p, v in pinfo.items()}


def read_meta(path):
    if not os.path.isfile(path):
        raise InputError(f"{path}: not found")
    try:
        with open(path, encoding="utf-8") as fh:
            meta = json.load(fh)
    except json.JSONDecodeError as e:
        raise InputError(f"meta.json line {e.lineno}, column {e.colno}: {e.msg}") from None
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: cannot be read ({e})") from None
    if not isinstance(meta, dict):
        raise InputError("meta.json line 1: the top level must be a JSON object")
    for k in META_KEYS:
        if k not in meta:
            raise InputError(f"meta.json: missing key '{k}'")
    for k in ("mpfr_bits", "degrees", "families", "pipelines"):
        if not isinstance(meta[k], list):
            raise InputError(f"meta.json: key '{k}' must be a list")
    if not all(isinstance(b, int) and not isinstance(b, bool) for b in meta["mpfr_bits"]):
        raise InputError("meta.json: key 'mpfr_bits' must be a list of integers")
    if not isinstance(meta["machine"], dict):
        raise InputError("meta.json: key 'machine' must be an object with cpu, cores, os")
    if meta["failure_map"] is not None and not isinstance(meta["failure_map"], dict):
        raise InputError("meta.json: key 'failure_map' must be an object or null")
    return meta


def check_failure_map(rows):
    if not rows:
        raise InputError("failure_map.csv: no data rows after the header")
    seen = {}
    exact_at = {}
    ulps_x, ulps_y = {}, {}
    for r in rows:
        ln = r["_line"]
        for col in ("ix", "iy"):
            if r[col] < 0:
                raise InputError(f"failure_map.csv line {ln}, column '{col}': {r[col]} is negative")
        key = (r["pipeline"], r["ix"], r["iy"])
        if key in seen:
            raise InputError(f"failure_map.csv line {ln}, column 'iy': a second row for pipeline '{r['pipeline']}' "
                             f"cell ({r['ix']}, {r['iy']}) (the first is on line {seen[key]})")
        seen[key] = ln
        cell = (r["ix"], r["iy"])
        if cell in exact_at and exact_at[cell][0] != r["exact"]:
            raise InputError(f"failure_map.csv line {ln}, column 'exact': cell ({r['ix']}, {r['iy']}) is "
                             f"'{r['exact']}' here but '{exact_at[cell][0]}' on line {exact_at[cell][1]}")
        exact_at.setdefault(cell, (r["exact"], ln))
        for idx, col, table in (("ix", "dx_ulps", ulps_x), ("iy", "dy_ulps", ulps_y)):
            i = r[idx]
            if i in table and table[i][0] != r[col]:
                raise InputError(f"failure_map.csv line {ln}, column '{col}': {idx}={i} has {col} {r[col]:g} here "
                                 f"but {table[i][0]:g} on line {table[i][1]}")
            table.setdefault(i, (r[col], ln))
    return {k: v[0] for k, v in exact_at.items()}, {k: v[0] for k, v in ulps_x.items()}, \
        {k: v[0] for k, v in ulps_y.items()}


# --------------------------------------------------------------------------- formatting


def fmt_sig(x, sig=3):
    """Compact number: 0, 31, 5500, 0.0123, 3.1e-12, inf."""
    if x is None:
        return "—"
    if isinstance(x, float) and math.isinf(x):
        return "inf" if x > 0 else "-inf"
    if x == 0:
        return "0"
    ax = abs(x)
    if 1e-3 <= ax < 1e5:
        digits = sig - 1 - math.floor(math.log10(ax))
        r = round(x, digits)
        if digits <= 0:
            return str(int(r))
        return f"{r:.{digits}f}".rstrip("0").rstrip(".")
    return f"{x:.{sig}g}"


def fmt_ratio(x):
    """A factor such as 1000, 180 or 1.5e9 (no '+' nor leading zeros in the exponent)."""
    t = fmt_sig(x, 2)
    return t.replace("e+0", "e").replace("e+", "e")


def fmt_err(x):
    return fmt_sig(x, 2)


def fmt_pct(num, den):
    if den == 0:
        return "—"
    return f"{100.0 * num / den:.1f}%"


def fmt_bits(b):
    return f"{b} bits" if isinstance(b, int) else b


def fmt_seconds(s):
    if not isinstance(s, (int, float)) or isinstance(s, bool):
        return str(s)
    if s < 120:
        return f"{fmt_sig(float(s))} s"
    m, sec = divmod(int(round(s)), 60)
    h, m = divmod(m, 60)
    return (f"{h} h {m} min" if h else f"{m} min {sec} s") + f" ({fmt_sig(float(s))} s)"


def fmt_ulps(v):
    return str(int(v)) if float(v).is_integer() else fmt_sig(v)


def md_cell(s):
    return str(s).replace("|", "\\|")


def md_table(header, rows, align=None):
    out = ["| " + " | ".join(md_cell(h) for h in header) + " |"]
    align = align or (["---"] + ["---:"] * (len(header) - 1))
    out.append("| " + " | ".join(align) + " |")
    for r in rows:
        out.append("| " + " | ".join(md_cell(c) for c in r) + " |")
    return "\n".join(out)


def few(n):
    return ", too few for a firm claim" if n < 5 else ""


# --------------------------------------------------------------------------- aggregates


def median(vals):
    vals = [v for v in vals if v is not None]
    return statistics.median(vals) if vals else None


def vmax(vals):
    vals = [v for v in vals if v is not None]
    return max(vals) if vals else None


def summarize(rows):
    n = len(rows)
    cnt = {o: sum(1 for r in rows if r["outcome"] == o) for o in OUTCOMES}
    non_err = [r for r in rows if r["outcome"] != "error"]
    return {
        "n": n, "fp": cnt["false_positive"], "fn": cnt["false_negative"], "und": cnt["undecided"],
        "err": cnt["error"], "mis": cnt["false_positive"] + cnt["false_negative"],
        "non_err": len(non_err), "struct_wrong": sum(1 for r in non_err if r["structure_ok"] != 1),
        "coef_med": median(r["coef_err"] for r in rows), "coef_max": vmax(r["coef_err"] for r in rows),
        "delta_med": median(r["delta_err"] for r in rows),
        "fc_med": median(r["first_contact_err"] for r in rows),
        "ep_max": vmax(r["endpoint_err"] for r in rows),
        "time_med": median(r["time_us"] for r in non_err),
    }


def is_clean(r):
    return r["outcome"] == "correct"


def smallest_correct_d(rows):
    """(d, d_text) per the module definition, ("none", None) if the largest d fails, None without near-miss rows."""
    by_d = {}
    for r in rows:
        if r["family"] == "near-miss":
            by_d.setdefault(r["d"], []).append(r)
    if not by_d:
        return None
    best = ("none", None)
    for d in sorted(by_d, reverse=True):
        if all(is_clean(r) for r in by_d[d]):
            best = (d, by_d[d][0]["d_text"])
        else:
            break
    return best


def smallest_clean_bits(rows_by_bits):
    """rows_by_bits: bits -> rows of one dim x degree x (basis, method). Smallest clean precision or 'none'."""
    best = "none of the tested"
    for b in sorted(rows_by_bits, reverse=True):
        if all(is_clean(r) for r in rows_by_bits[b]):
            best = b
        else:
            break
    return best


class Data:
    def __init__(self, rows, pinfo, meta, fmap):
        self.rows, self.pinfo, self.meta, self.fmap = rows, pinfo, meta, fmap
        order = [p for p in meta["pipelines"] if isinstance(p, str) and p in pinfo]
        order += [p for p in dict.fromkeys(r["pipeline"] for r in rows) if p not in order]
        self.order = order
        self.dims = sorted({r["dim"] for r in rows})
        self.degrees = {dim: sorted({r["degree"] for r in rows if r["dim"] == dim}) for dim in self.dims}
        self.notes = []

    def sel(self, **kw):
        return [r for r in self.rows if all(r[k] == v for k, v in kw.items())]

    def pipelines(self, dim, arith=None):
        present = {r["pipeline"] for r in self.rows if r["dim"] == dim}
        return [p for p in self.order if p in present and (arith is None or self.pinfo[p][0] == arith)]

    def form_pipelines(self, dim):
        """Double pipelines that differ only by the basis of f (cd-disc in 2D, bezier in 3D)."""
        return [p for p in self.pipelines(dim, "double") if self.pinfo[p][3] in ("cd-disc", "bezier")]

    def mpfr_groups(self, dim):
        """(basis, method) -> {bits: pipeline} for the MPFR pipelines of `dim`."""
        groups = {}
        for p in self.pipelines(dim, "mpfr"):
            _, bits, basis, method = self.pinfo[p]
            groups.setdefault((basis, method), {})[bits] = p
        return groups

    def nearmiss_rows(self, dim):
        return [r for r in self.rows if r["dim"] == dim and r["family"] == "near-miss"]

    def nearmiss_pipelines(self, dim):
        """All double pipelines, plus a few MPFR ones: all if at most 4, else per (basis, method) the lowest
        precision and the lowest precision that classifies every near-miss scene correctly."""
        nm = self.nearmiss_rows(dim)
        have = {r["pipeline"] for r in nm}
        cols = [p for p in self.pipelines(dim, "double") if p in have]
        mp = [p for p in self.pipelines(dim, "mpfr") if p in have]
        if len(mp) <= 4:
            return cols + mp
        chosen = set()
        for (_basis, _method), by_bits in self.mpfr_groups(dim).items():
            bits = sorted(b for b in by_bits if by_bits[b] in have)
            if not bits:
                continue
            chosen.add(by_bits[bits[0]])
            for b in bits:
                if all(is_clean(r) for r in nm if r["pipeline"] == by_bits[b]):
                    chosen.add(by_bits[b])
                    break
        return cols + [p for p in mp if p in chosen]


def group_name(basis, method):
    return basis if method == "cd-disc" else f"{basis} ({method})"


# --------------------------------------------------------------------------- figures

DPI = 120


def _floor_for(values):
    pos = [v for v in values if v is not None and v > 0 and math.isfinite(v)]
    return 10.0 ** (math.floor(math.log10(min(pos))) - 1) if pos else 1e-17


def _series_style(data, p):
    arith = data.pinfo[p][0]
    return {"double": "-", "mpfr": "--", "exact": ":"}[arith]


def _colors(n):
    cmap = plt.get_cmap("tab10" if n <= 10 else "tab20")
    return [cmap(i % cmap.N) for i in range(n)]


def _subplots(ndims, width=6.0, height=4.4, stacked=False):
    """One panel per dimension, side by side (or one above the other when legends sit to the right)."""
    if stacked:
        fig, axes = plt.subplots(ndims, 1, figsize=(width, height * ndims), squeeze=False)
        return fig, list(axes[:, 0])
    fig, axes = plt.subplots(1, ndims, figsize=(width * ndims, height), squeeze=False)
    return fig, list(axes[0])


def _save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=DPI, bbox_inches="tight", format="png")
    plt.close(fig)


def fig_coef_vs_degree(data, path):
    """Per dim: median coefficient error of the double form pipelines vs degree with a 10-90% band."""
    per_dim = {}
    allvals = []
    for dim in data.dims:
        pl = data.form_pipelines(dim) or data.pipelines(dim, "double")
        series = {}
        for p in pl:
            pts = {}
            for r in data.sel(dim=dim, pipeline=p):
                if r["coef_err"] is not None and math.isfinite(r["coef_err"]):
                    pts.setdefault(r["degree"], []).append(r["coef_err"])
            if pts:
                series[p] = pts
                allvals += [v for vs in pts.values() for v in vs]
        if series:
            per_dim[dim] = series
    if not per_dim:
        return None
    floor = _floor_for(allvals)
    nzero = sum(1 for v in allvals if v == 0)
    fig, axes = _subplots(len(per_dim))
    for ax, (dim, series) in zip(axes, per_dim.items()):
        colors = _colors(len(series))
        for k, (p, pts) in enumerate(series.items()):
            degs = sorted(pts)
            xs = [g + (k - (len(series) - 1) / 2) * 0.05 for g in degs]  # offset: equal series stay visible
            arr = [np.maximum(np.array(pts[g]), floor) for g in degs]
            med = [float(np.median(a)) for a in arr]
            lo = [float(np.percentile(a, 10)) for a in arr]
            hi = [float(np.percentile(a, 90)) for a in arr]
            ax.plot(xs, med, "o-", color=colors[k], label=f"{p} (median)")
            ax.fill_between(xs, lo, hi, color=colors[k], alpha=0.15, linewidth=0)
        ax.axhline(floor, color="0.5", linewidth=0.8, linestyle=":")
        ax.set_yscale("log")
        ax.set_xticks(data.degrees[dim])
        ax.set_xlabel("motion degree")
        ax.set_ylabel("coefficient error of f (normwise relative)")
        ax.set_title(f"{dim}D: double coefficient error vs degree\n(band: 10–90%; zero drawn at {fmt_err(floor)})")
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize="small")
    _save(fig, path)
    return (f"Median coefficient error of f(λ;t) in double precision per motion degree, one line per basis; "
            f"the band spans the 10th to 90th percentile. Zero errors ({nzero} of {len(allvals)}) are drawn "
            f"at the floor {fmt_err(floor)} (dotted line).")


def fig_coef_hist(data, path):
    per_dim = {}
    allvals = []
    for dim in data.dims:
        series = {}
        for p in data.pipelines(dim, "double"):
            vals = [r["coef_err"] for r in data.sel(dim=dim, pipeline=p)
                    if r["coef_err"] is not None and math.isfinite(r["coef_err"])]
            if vals:
                series[p] = vals
                allvals += vals
        if series:
            per_dim[dim] = series
    if not per_dim:
        return None
    floor = _floor_for(allvals)
    logs = [math.log10(max(v, floor)) for v in allvals]
    lo, hi = math.floor(min(logs)), math.ceil(max(logs))
    if hi <= lo:
        hi = lo + 1
    bins = np.arange(lo - 0.25, hi + 0.5, 0.5)
    fig, axes = _subplots(len(per_dim))
    for ax, (dim, series) in zip(axes, per_dim.items()):
        colors = _colors(len(series))
        for k, (p, vals) in enumerate(series.items()):
            x = np.log10(np.maximum(np.array(vals), floor))
            ax.hist(x, bins=bins, histtype="step", linewidth=1.8, color=colors[k], label=f"{p} ({len(vals)})")
        ax.set_xlabel(f"log10 coefficient error (zero drawn at {math.log10(floor):.0f})")
        ax.set_ylabel("scenes")
        ax.set_title(f"{dim}D: coefficient error of f, double pipelines")
        ax.yaxis.get_major_locator().set_params(integer=True)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", loc="best")
    _save(fig, path)
    return (f"Histogram of log10 of the coefficient error per double pipeline (bins of half a decade). "
            f"Zero errors are counted at log10 = {math.log10(floor):.0f}.")


def fig_misclass_vs_d(data, path):
    dims = [dim for dim in data.dims if data.nearmiss_pipelines(dim)]
    if not dims:
        return None
    fig, axes = _subplots(len(dims), stacked=True)
    for ax, dim in zip(axes, dims):
        nm = data.nearmiss_rows(dim)
        pl = data.nearmiss_pipelines(dim)
        colors = _colors(len(pl))
        ds = sorted({r["d"] for r in nm}, reverse=True)
        for k, p in enumerate(pl):
            xs, mis, und = [], [], []
            for d in ds:
                rs = [r for r in nm if r["pipeline"] == p and r["d"] == d]
                if not rs:
                    continue
                s = summarize(rs)
                xs.append(d)
                mis.append(100.0 * s["mis"] / s["n"])
                und.append(100.0 * s["und"] / s["n"])
            ax.plot(xs, mis, "o-", color=colors[k], label=f"{p} misclassified")
            if any(u > 0 for u in und):
                ax.plot(xs, und, "s--", color=colors[k], alpha=0.7, markersize=4, label=f"{p} undecided")
        ax.set_xscale("log")
        if len(ds) > 1:
            ax.set_xlim(max(ds) * 3, min(ds) / 3)  # decreasing separation to the right
        ax.set_ylim(-5, 105)
        ax.set_xlabel("near-miss separation d (decreasing →)")
        ax.set_ylabel("scenes (%)")
        ax.set_title(f"{dim}D near-miss scenes: misclassified (solid), undecided (dashed)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    _save(fig, path)
    return ("Near-miss family: share of scenes misclassified (false positive or false negative, solid) and "
            "undecided (dashed, drawn only where non-zero) against the separation d, all degrees pooled.")


def fig_min_bits(data, path, minbits):
    dims = [dim for dim in data.dims if minbits.get(dim)]
    if not dims:
        return None
    fig, axes = _subplots(len(dims))
    for ax, dim in zip(axes, dims):
        table = minbits[dim]  # (basis, method) -> degree -> bits | "none of the tested"
        levels = sorted({b for grp in data.mpfr_groups(dim).values() for b in grp})
        ypos = {b: i for i, b in enumerate(levels)}
        none_y = len(levels)
        colors = _colors(len(table))
        n = len(table)
        for k, (grp, by_deg) in enumerate(table.items()):
            degs = sorted(by_deg)
            off = (k - (n - 1) / 2) * 0.08
            xs = [g + off for g in degs]
            ys = [ypos[by_deg[g]] if isinstance(by_deg[g], int) else none_y for g in degs]
            ax.plot(xs, ys, "-", color=colors[k], alpha=0.6)
            for x, y in zip(xs, ys):
                ax.plot([x], [y], "x" if y == none_y else "o", color=colors[k], markersize=8 if y == none_y else 6)
            ax.plot([], [], "o-", color=colors[k], label=group_name(*grp))
        ax.axhline(none_y - 0.5, color="0.5", linewidth=0.8, linestyle=":")
        ax.set_yticks(list(range(len(levels) + 1)))
        ax.set_yticklabels([str(b) for b in levels] + ["none of\nthe tested"])
        ax.set_ylim(-0.5, none_y + 0.5)
        ax.set_xticks(data.degrees[dim])
        ax.set_xlabel("motion degree")
        ax.set_ylabel("MPFR precision (bits)")
        ax.set_title(f"{dim}D: smallest MPFR precision with no misclassification")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", title="basis")
    _save(fig, path)
    return ("Smallest tested MPFR precision at which this and every larger tested precision has no false positive, "
            "false negative, undecided or error on any scene of that dimension and degree; × above the dotted line: "
            "none of the tested precisions.")


def fig_time(data, path):
    dims = [dim for dim in data.dims if any(r["time_us"] is not None for r in data.sel(dim=dim))]
    if not dims:
        return None
    fig, axes = _subplots(len(dims), width=7.0, stacked=True)
    for ax, dim in zip(axes, dims):
        pl = data.pipelines(dim)
        colors = _colors(len(pl))
        for k, p in enumerate(pl):
            pts = {}
            for r in data.sel(dim=dim, pipeline=p):
                if r["outcome"] != "error" and r["time_us"] is not None and r["time_us"] > 0:
                    pts.setdefault(r["degree"], []).append(r["time_us"])
            if not pts:
                continue
            degs = sorted(pts)
            style = _series_style(data, p)
            color = "black" if data.pinfo[p][0] == "exact" else colors[k]
            ax.plot(degs, [statistics.median(pts[g]) for g in degs], "o" + style, color=color, label=p)
        ax.set_yscale("log")
        ax.set_xticks(data.degrees[dim])
        ax.set_xlabel("motion degree")
        ax.set_ylabel("median time per query (µs)")
        ax.set_title(f"{dim}D: median time per query")
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    _save(fig, path)
    return ("Median wall time of one query per motion degree (log scale), rows that ended in an error left out; "
            "solid: double, dashed: MPFR, dotted: exact.")


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
    names = panels + ["exact"]
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
        ax.set_title(p)
    present = {FM_ORDER[v] for gr in grids.values() for v in np.unique(gr)}
    handles = [Patch(facecolor=FM_COLORS[a], edgecolor="0.3", label=a) for a in FM_ORDER if a in present]
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


# --------------------------------------------------------------------------- report


MINBITS_NOTE = ("Touch scenes (an isolated tangency at one instant) are left out of this count and their detection "
                "rate is reported on its own: a tangency is a double root, which rounding splits into a short overlap "
                "or removes at any finite precision, unless the method accepts a tolerance (the 3D Bézier method calls "
                "a peak of F within its touch tolerance a touch).")


def touch_detection(data, dim):
    """pipeline -> (detected, total) over touch scenes: `collides` true (the touch was seen)."""
    out = {}
    for p in data.pipelines(dim):
        rs = [r for r in data.sel(dim=dim, pipeline=p) if r["family"] == "touch" and r["outcome"] != "error"]
        if rs and p != "exact":
            out[p] = (sum(1 for r in rs if r["outcome"] == "correct"), len(rs))
    return out


def compute_minbits(data):
    """dim -> (basis, method) -> degree -> bits | 'none of the tested'."""
    out = {}
    for dim in data.dims:
        groups = data.mpfr_groups(dim)
        if not groups:
            continue
        out[dim] = {}
        for grp, by_bits in groups.items():
            out[dim][grp] = {}
            for deg in data.degrees[dim]:
                # touch scenes are left out: see MINBITS_NOTE
                rb = {b: [r for r in data.sel(dim=dim, degree=deg, pipeline=p) if r["family"] not in ("touch", "graze")]
                      for b, p in by_bits.items()}
                rb = {b: rs for b, rs in rb.items() if rs}
                if rb:
                    out[dim][grp][deg] = smallest_clean_bits(rb)
    return out


def scenes_of(rows):
    return len({r["scene"] for r in rows})


def section_what_was_run(data):
    m = data.meta
    mach = m["machine"]
    machine = ", ".join(str(x) for x in (mach.get("cpu"), f"{mach.get('cores')} cores" if mach.get("cores") else None,
                                           mach.get("os")) if x)
    nscenes = scenes_of(data.rows)
    out = ["## What was run", ""]
    out.append(f"- Command: `{m['command']}`")
    out.append(f"- Seed: {m['seed']}")
    out.append(f"- MPFR precisions (bits): {', '.join(str(b) for b in m['mpfr_bits']) or 'none'}")
    out.append(f"- Pipelines: {', '.join(data.order)}")
    modes = getattr(data, "input_modes", None) or [getattr(data, "primary_input", "prepared")]
    line = f"- Input modes of the floating pipelines: {', '.join(modes)}"
    if len(modes) > 1:
        line += (f" (rows of the mode *{modes[1]}* carry the suffix @{modes[1]}; the sections below the next one "
                 f"show the mode *{modes[0]}*)")
    if m.get("budget_seconds") is not None:
        line += (f"; every floating run under a time budget of {fmt_seconds(m['budget_seconds'])}, the exact run "
                 f"under {fmt_seconds(m.get('exact_budget_seconds', 0))} (kernel/budget.hpp; a time-out is undecided)")
    out.append(line)
    out.append(f"- Machine: {machine or 'not recorded'}")
    out.append(f"- Version: {m['version']}")
    out.append(f"- Started: {m['started']}")
    out.append(f"- Wall time: {fmt_seconds(m['wall_seconds'])} in {m['shards']} shard{'s' if m['shards'] != 1 else ''}")
    sc = f"- Scenes: {nscenes} in results.csv, {len(data.rows)} rows"
    if m["scene_count"] != nscenes:
        sc += f" (meta.json says {m['scene_count']} scenes)"
    out.append(sc)
    failed = m.get("failed")
    if isinstance(failed, list) and failed:
        shown = "; ".join(str(f) for f in failed[:3]) + ("; …" if len(failed) > 3 else "")
        out.append(f"- Failed tasks (meta.json): {len(failed)}: {shown}")
    bits_data = sorted({data.pinfo[p][1] for p in data.order if data.pinfo[p][0] == "mpfr"})
    if set(bits_data) != set(m["mpfr_bits"]):
        out.append(f"- Note: results.csv has MPFR precisions {', '.join(map(str, bits_data)) or 'none'}, "
                   f"meta.json lists {', '.join(map(str, m['mpfr_bits'])) or 'none'}; the tables use those in "
                   f"results.csv.")
    fams = [f for f in m["families"] if isinstance(f, str)]
    fams += [f for f in FAMILIES if f not in fams and any(r["family"] == f for r in data.rows)]
    out += ["", "Scenes per dimension, motion degree and family:", ""]
    body = []
    for dim in data.dims:
        for deg in data.degrees[dim]:
            rs = data.sel(dim=dim, degree=deg)
            body.append([f"{dim}D", deg] + [scenes_of([r for r in rs if r["family"] == f]) for f in fams]
                        + [scenes_of(rs)])
    body.append(["all", ""] + [scenes_of([r for r in data.rows if r["family"] == f]) for f in fams] + [nscenes])
    out.append(md_table(["dim", "degree"] + fams + ["total"], body, ["---", "---:"] + ["---:"] * (len(fams) + 1)))
    out += ["", "Definitions. *Misclassification rate*: (false positives + false negatives) / scenes, where a false "
            "positive says *collides* and the exact answer does not; *undecided* (the floating pipeline said it "
            "could not decide) and *errors* are counted apart, never as right or wrong. *Structure wrong*: among "
            "rows without error, the share whose collision intervals (ends within 1e-6), contacts or answer differ "
            "from the exact ones. The exact pipeline is the ground truth.", ""]
    return out


FAMILY_GROUPS = (
    ("generic colliding", ("colliding",)),
    ("generic free", ("free",)),
    ("near-miss", ("near-miss",)),
    ("touch (isolated contact)", ("touch", "graze")),
    ("just overlapping (linear)", ("overlap",)),
    ("realistic decimals", ("decimal", "keyframe")),
    ("shipped cases", ("case",)),
)


def arith_level(r):
    return "double" if r["arith"] == "double" else f"mpfr:{r['bits']}"


def level_key(level):
    return (0, 0) if level == "double" else (1, int(level.split(":")[1]))


def section_trust(data):
    """Per family group and input mode: where double and each MPFR precision stay trustworthy."""
    # The 3D sampling and marching baselines look at a grid of instants and claim nothing between them (their
    # answers say "sampled"): they are no error-bounded decision, so they are left out of the pooled verdict here.
    rows = [r for r in data.all_rows if r["arith"] != "exact"
            and not r.get("method", "").startswith(("sampling", "marching"))]
    out = ["## Where each arithmetic stays trustworthy, per family and input mode", ""]
    if not rows:
        return out + ["No floating pipeline in results.csv.", ""]
    modes = data.input_modes or [data.primary_input]
    out += ["A floating answer is *trustworthy* here when it is never confidently wrong: no false positive or false "
            "negative against the exact answer (an *undecided* answer, which the pipeline gives itself from its error "
            "bound or its time budget, is honest and not wrong). Each cell: confidently wrong / runs, then undecided "
            "runs; all pipelines (bases, methods) of that arithmetic pooled. Input *rounded*: the scene's numbers "
            "rounded to the arithmetic, as a user's program holds them; *prepared*: the coefficients prepared exactly, "
            "then rounded. The difference between the two rows of a family is the error of rounding the input. "
            "The 3D sampling:N and marching:N baselines are left out of this table: they look at a grid of instants "
            "and claim nothing between them (their misses are in the tables further down).", ""]
    if len(modes) == 1:
        out += [f"Only the input mode *{modes[0]}* is in results.csv"
                + (" (this solver has no rounded input mode; every floating run started from the prepared scene)."
                   if modes[0] == "prepared" else "."), ""]
    levels = sorted({arith_level(r) for r in rows}, key=level_key)
    body, notes = [], []
    for gname, fams in FAMILY_GROUPS:
        grows = [r for r in rows if r["family"] in fams]
        if not grows:
            continue
        for mode in modes:
            mrows = [r for r in grows if r["input"] == mode]
            if not mrows:
                continue
            cells, clean, undec = [], {}, {}
            for lv in levels:
                lr = [r for r in mrows if arith_level(r) == lv]
                if not lr:
                    cells.append("—")
                    continue
                wrong = sum(1 for r in lr if r["outcome"] in ("false_positive", "false_negative"))
                und = sum(1 for r in lr if r["outcome"] == "undecided")
                err = sum(1 for r in lr if r["outcome"] == "error")
                clean[lv] = wrong == 0 and err == 0
                undec[lv] = (und, len(lr))
                cell = f"{wrong}/{len(lr)}"
                if und:
                    cell += f", {und} und."
                if err:
                    cell += f", {err} err."
                cells.append(cell)
            body.append([gname, mode, scenes_of(mrows)] + cells)
            tested = [lv for lv in levels if lv in clean]
            ok_from = None
            for lv in reversed(tested):
                if clean[lv]:
                    ok_from = lv
                else:
                    break
            dbl = clean.get("double")
            mp = [lv for lv in tested if lv != "double"]
            if ok_from is None:
                verdict = "no tested arithmetic is free of confident errors"
            elif ok_from == "double":
                verdict = "trustworthy from double on (every tested arithmetic)"
            else:
                verdict = (f"double {'trustworthy' if dbl else 'not trustworthy' if dbl is not None else 'not run'}; "
                           f"MPFR trustworthy from {ok_from} on")
                if mp and ok_from == mp[0]:
                    verdict += " (the lowest tested precision)"
            und_levels = [f"{lv} {u} of {n}" for lv, (u, n) in undec.items() if u]
            if und_levels:
                verdict += "; undecided (honest, but no answer): " + ", ".join(und_levels)
            notes.append(f"- {gname}, input {mode} ({scenes_of(mrows)} scenes{few(scenes_of(mrows))}): {verdict}.")
    out.append(md_table(["family", "input", "scenes"] + levels, body, ["---", "---", "---:"] + ["---:"] * len(levels)))
    out += [""] + notes + [""]
    reasons = {}
    for r in rows:
        if r["outcome"] == "undecided" and r.get("reason"):
            key = "time budget" if r["reason"].startswith("time budget") else r["reason"].split(";")[0][:60]
            reasons[key] = reasons.get(key, 0) + 1
    if reasons:
        top = sorted(reasons.items(), key=lambda kv: -kv[1])[:6]
        out += ["Undecided runs by reason (the pipelines' own words, first reason per run): "
                + "; ".join(f"{k}: {v}" for k, v in top) + ".", ""]
    return out



def section_findings(data, minbits):
    out = ["## Findings", ""]
    for dim in data.dims:
        forms = data.form_pipelines(dim)
        for deg in data.degrees[dim]:
            n = scenes_of(data.sel(dim=dim, degree=deg))
            if not forms:
                continue
            parts = []
            for p in forms:
                s = summarize(data.sel(dim=dim, degree=deg, pipeline=p))
                if s["n"] == 0:
                    continue
                extra = [f"{s['und']} undecided"]
                if s["err"]:
                    extra.append(f"{s['err']} error{'s' if s['err'] != 1 else ''}")
                parts.append(f"{p} {fmt_pct(s['mis'], s['n'])} ({s['mis']} of {s['n']}; {', '.join(extra)})")
            if parts:
                out.append(f"- {dim}D, degree {deg} ({n} scene{'s' if n != 1 else ''}{few(n)}): misclassification rate "
                           + "; ".join(parts) + ".")
        # coefficient error at the highest degree with data
        if len(forms) >= 2:
            for deg in reversed(data.degrees[dim]):
                meds = [(p, median(r["coef_err"] for r in data.sel(dim=dim, degree=deg, pipeline=p))) for p in forms]
                meds = [(p, v) for p, v in meds if v is not None]
                if len(meds) >= 2:
                    lo = min(meds, key=lambda t: t[1])
                    hi = max(meds, key=lambda t: t[1])
                    ratio = (f", {fmt_ratio(hi[1] / lo[1])}× the smallest" if lo[1] > 0 and hi[1] > lo[1] else "")
                    out.append(f"- {dim}D, degree {deg}: median coefficient error of f in double is "
                               + ", ".join(f"{fmt_err(v)} for {p}" for p, v in meds)
                               + f" (largest {hi[0]}{ratio}).")
                    break
        # near-miss
        nm = data.nearmiss_rows(dim)
        if nm:
            ds = sorted({r["d"] for r in nm}, reverse=True)
            per_d = [scenes_of([r for r in nm if r["d"] == d]) for d in ds]
            parts = []
            for p in data.pipelines(dim, "double"):
                res = smallest_correct_d([r for r in nm if r["pipeline"] == p])
                if res is not None:
                    parts.append(f"{p} {res[1] if res[1] else 'none'}")
            texts = {d: next(r["d_text"] for r in nm if r["d"] == d) for d in ds}
            span = f"d from {texts[ds[0]]} down to {texts[ds[-1]]}" if len(ds) > 1 else f"d = {texts[ds[0]]}"
            span_n = f"{min(per_d)}" if min(per_d) == max(per_d) else f"{min(per_d)}–{max(per_d)}"
            caveat = f" ({span_n} scenes per d: too few for a firm claim)" if min(per_d) < 5 else ""
            if parts:
                out.append(f"- {dim}D near-miss ({scenes_of(nm)} scenes, {span}): smallest d that each double "
                           f"pipeline still classifies correctly (with every larger d): " + "; ".join(parts)
                           + f"{caveat}.")
        # MPFR
        if dim in minbits:
            parts = []
            for grp, by_deg in minbits[dim].items():
                items = []
                by_bits = data.mpfr_groups(dim)[grp]
                for deg, b in sorted(by_deg.items()):
                    n = scenes_of(data.sel(dim=dim, degree=deg))
                    notes = [f"{n} scenes, too few"] if n < 5 else []
                    if not isinstance(b, int):  # say which scenes still fail at the top precision
                        top = max(bb for bb in by_bits if data.sel(dim=dim, degree=deg, pipeline=by_bits[bb]))
                        bad = [r for r in data.sel(dim=dim, degree=deg, pipeline=by_bits[top]) if not is_clean(r)]
                        fams = {}
                        for r in bad:
                            fams[r["family"]] = fams.get(r["family"], 0) + 1
                        notes.append(f"at {top} bits " + ", ".join(f"{c} {f}" for f, c in fams.items())
                                     + f" scene{'s' if len(bad) != 1 else ''} still fail{'s' if len(bad) == 1 else ''}")
                    items.append(f"degree {deg}: {fmt_bits(b)}" + (f" ({'; '.join(notes)})" if notes else ""))
                parts.append(f"{group_name(*grp)} — " + ", ".join(items))
            tested = sorted({b for g in data.mpfr_groups(dim).values() for b in g})
            out.append(f"- {dim}D smallest MPFR precision with no misclassification, undecided or error (tested "
                       f"{', '.join(map(str, tested))} bits; touch scenes left out, see below): " + "; ".join(parts) + ".")
        td = touch_detection(data, dim)
        if td:
            items = [f"{p} {d}/{n}" for p, (d, n) in td.items()]
            out.append(f"- {dim}D touch scenes (the exact answer is one isolated contact): seen as a collision by "
                       + ", ".join(items) + ". " + MINBITS_NOTE.split(": ", 1)[1][0].upper() + MINBITS_NOTE.split(": ", 1)[1][1:])
        # time
        meds = []
        for p in data.pipelines(dim):
            t = median(r["time_us"] for r in data.sel(dim=dim, pipeline=p) if r["outcome"] != "error")
            if t is not None:
                meds.append((p, t))
        if len(meds) >= 2:
            fast = min(meds, key=lambda t: t[1])
            slow = max(meds, key=lambda t: t[1])
            ratio = f", {fmt_ratio(slow[1] / fast[1])}× slower" if fast[1] > 0 else ""
            out.append(f"- {dim}D time: fastest {fast[0]} (median {fmt_sig(fast[1])} µs per query), slowest "
                       f"{slow[0]} (median {fmt_sig(slow[1])} µs{ratio}).")
    errs = [r for r in data.rows if r["outcome"] == "error"]
    if errs:
        names = ", ".join(f"{r['pipeline']} on {r['scene']}" for r in errs[:3]) + (", …" if len(errs) > 3 else "")
        out.append(f"- {len(errs)} run{'s' if len(errs) != 1 else ''} ended in an error: {names}.")
    if len(out) == 2:
        out.append("- No floating pipeline in the data to compare.")
    out.append("")
    return out


def section_tables(data):
    out = ["## Results per dimension and degree", ""]
    for dim in data.dims:
        derr = "Δ err med" if dim == 2 else "F(u,t) err med"
        header = ["pipeline", "scenes", "FP", "FN", "undecided", "errors", "misclass.", "structure wrong",
                  "coef err med", "coef err max", derr, "1st contact err med", "endpoint err max", "time µs med"]
        for deg in data.degrees[dim]:
            body = []
            for p in data.pipelines(dim):
                rs = data.sel(dim=dim, degree=deg, pipeline=p)
                if not rs:
                    continue
                s = summarize(rs)
                body.append([p, s["n"], s["fp"], s["fn"], s["und"], s["err"], fmt_pct(s["mis"], s["n"]),
                             fmt_pct(s["struct_wrong"], s["non_err"]), fmt_err(s["coef_med"]), fmt_err(s["coef_max"]),
                             fmt_err(s["delta_med"]), fmt_err(s["fc_med"]), fmt_err(s["ep_max"]),
                             fmt_sig(s["time_med"])])
            n = scenes_of(data.sel(dim=dim, degree=deg))
            out += [f"### {dim}D, degree {deg} ({n} scenes)", "", md_table(header, body), ""]
    out += ["FP: false positives, FN: false negatives; errors are relative (coefficients, normwise) or absolute "
            "(instants in t ∈ [0, 1]); time: median over rows without error; — : not applicable or no data.", ""]
    return out


def section_nearmiss(data, figs):
    out = ["## Near-miss scenes", ""]
    dims = [dim for dim in data.dims if data.nearmiss_pipelines(dim)]
    if not dims:
        out += ["No near-miss scenes solved by a floating pipeline in results.csv: tables and "
                "misclassification_vs_d.png skipped.", ""]
        return out
    out += ["Cells: misclassified / scenes at that separation d (all degrees pooled), with undecided and errors "
            "added when there are any.", ""]
    for dim in dims:
        nm = data.nearmiss_rows(dim)
        pl = data.nearmiss_pipelines(dim)
        ds = sorted({r["d"] for r in nm}, reverse=True)
        body = []
        for d in ds:
            rd = [r for r in nm if r["d"] == d]
            row = [rd[0]["d_text"]]
            for p in pl:
                rs = [r for r in rd if r["pipeline"] == p]
                if not rs:
                    row.append("—")
                    continue
                s = summarize(rs)
                cell = f"{s['mis']}/{s['n']}"
                if s["und"]:
                    cell += f" ({s['und']} undecided)"
                if s["err"]:
                    cell += f" ({s['err']} error{'s' if s['err'] != 1 else ''})"
                row.append(cell)
            body.append(row)
        out += [f"### {dim}D", "", md_table(["d"] + pl, body), ""]
        body = []
        for deg in data.degrees[dim]:
            rdeg = [r for r in nm if r["degree"] == deg]
            if not rdeg:
                continue
            row = [deg]
            for p in pl:
                res = smallest_correct_d([r for r in rdeg if r["pipeline"] == p])
                row.append("—" if res is None else (res[1] if res[1] else "none"))
            body.append(row)
        out += [f"Smallest d still classified correctly, with every larger d ({dim}D, per degree):", "",
                md_table(["degree"] + pl, body), ""]
    out += figure_block(figs, "misclassification_vs_d.png")
    return out


def section_mpfr(data, minbits, figs):
    out = ["## Smallest MPFR precision with no misclassification", ""]
    if not minbits:
        out += ["No MPFR pipelines in results.csv: table and min_mpfr_bits_vs_degree.png skipped.", ""]
        return out
    out += ["Per dimension, degree and basis: the smallest tested precision p such that at p and every larger "
            "tested precision no scene is a false positive, false negative, undecided or error. " + MINBITS_NOTE, ""]
    cols = list(dict.fromkeys(g for dim in minbits for g in minbits[dim]))
    body = []
    for dim in data.dims:
        for deg in data.degrees[dim]:
            row = [f"{dim}D", deg, scenes_of(data.sel(dim=dim, degree=deg))]
            for g in cols:
                b = minbits.get(dim, {}).get(g, {}).get(deg)
                row.append("—" if b is None else fmt_bits(b))
            body.append(row)
    out += [md_table(["dim", "degree", "scenes"] + [group_name(*g) for g in cols], body,
                     ["---", "---:", "---:"] + ["---:"] * len(cols)), ""]
    out += figure_block(figs, "min_mpfr_bits_vs_degree.png")
    return out


def section_failure_map(data, figs):
    out = ["## Failure map", ""]
    if data.fmap is None:
        out += ["No failure_map.csv in this directory: section and failure_map.png skipped.", ""]
        return out
    fm = data.meta.get("failure_map") or {}
    exact_at = data.fmap["exact"]
    nx, ny = max(data.fmap["ux"]) + 1, max(data.fmap["uy"]) + 1
    desc = f"Scene {fm['scene']}: " if fm.get("scene") else ""
    desc += (f"{fm.get('x_input', 'x input')} and {fm.get('y_input', 'y input')} perturbed by "
             f"{fmt_ulps(min(data.fmap['ux'].values()))}…{fmt_ulps(max(data.fmap['ux'].values()))} and "
             f"{fmt_ulps(min(data.fmap['uy'].values()))}…{fmt_ulps(max(data.fmap['uy'].values()))} ulps "
             f"on a {nx} × {ny} grid (after Kettner et al. 2004).")
    out.append(desc)
    if fm.get("note"):
        out += ["", f"Note: {fm['note']}"]
    if not data.meta.get("failure_map"):
        out += ["", "meta.json has no failure_map entry; the grid is described from failure_map.csv alone."]
    counts = {a: sum(1 for v in exact_at.values() if v == a) for a in ANSWERS}
    out += ["", "Exact answers on the grid: " + ", ".join(f"{v} {a}" for a, v in counts.items() if v) + ".", ""]
    body = []
    for p in dict.fromkeys(r["pipeline"] for r in data.fmap["rows"]):
        rs = [r for r in data.fmap["rows"] if r["pipeline"] == p]
        wrong = [r for r in rs if r["answer"] != r["exact"]]
        und = sum(1 for r in wrong if r["answer"] == "undecided")
        err = sum(1 for r in wrong if r["answer"] == "error")
        at_touch = sum(1 for r in wrong if r["exact"] == "touching")
        body.append([p, len(rs), len(wrong), fmt_pct(len(wrong), len(rs)), und, err, at_touch])
    out += [md_table(["pipeline", "cells", "differ from exact", "share", "of which undecided", "of which error",
                      "where exact is touching"], body), ""]
    out += figure_block(figs, "failure_map.png")
    return out


def figure_block(figs, name):
    cap = figs.get(name)
    if cap is None:
        return [f"Figure {name} skipped: no data for it.", ""]
    return [f"![{name}]({name})", "", f"*{cap}*", ""]


def build_report(data, figs, minbits):
    out = [f"# Robustness report: {data.meta['name']}", ""]
    out += section_what_was_run(data)
    out += section_trust(data)
    out += section_findings(data, minbits)
    out += section_tables(data)
    out += ["## Coefficient error", ""]
    out += figure_block(figs, "coef_error_vs_degree.png")
    out += figure_block(figs, "coef_error_hist.png")
    out += section_nearmiss(data, figs)
    out += section_mpfr(data, minbits, figs)
    out += ["## Time", ""]
    out += figure_block(figs, "time_vs_degree.png")
    out += section_failure_map(data, figs)
    out += ["## Files", "", "- [results.csv](results.csv): one row per scene and pipeline",
            "- [meta.json](meta.json): what was run"]
    if data.fmap is not None:
        out.append("- [failure_map.csv](failure_map.csv): the failure-map grid")
    for name in FIGURES:
        if figs.get(name) is not None:
            out.append(f"- [{name}]({name})")
    out += ["", f"Written by compare/plots/{PROG} from the files above.", ""]
    return "\n".join(out)


FIGURES = ("coef_error_vs_degree.png", "coef_error_hist.png", "misclassification_vs_d.png",
           "min_mpfr_bits_vs_degree.png", "time_vs_degree.png", "failure_map.png")


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2 if len(argv) != 2 else 0
    out_dir = argv[1]
    if not os.path.isdir(out_dir):
        raise InputError(f"{out_dir}: not a directory")
    all_rows = read_csv(os.path.join(out_dir, "results.csv"), RESULT_COLUMNS, OPTIONAL_RESULT_COLUMNS)
    check_results(all_rows)
    # The main sections read one input mode (rounded where present: what users run); the section on input modes
    # and families reads every row.
    modes = [m for m in INPUTS if any(r["input"] == m and r["arith"] != "exact" for r in all_rows)]
    primary = modes[0] if modes else "prepared"
    rows = [r for r in all_rows if r["arith"] == "exact" or r["input"] == primary]
    pinfo = check_results(rows)
    meta = read_meta(os.path.join(out_dir, "meta.json"))
    fmap = None
    fm_path = os.path.join(out_dir, "failure_map.csv")
    if os.path.exists(fm_path):
        fm_rows = read_csv(fm_path, FAILURE_COLUMNS)
        exact_at, ux, uy = check_failure_map(fm_rows)
        fmap = {"rows": fm_rows, "exact": exact_at, "ux": ux, "uy": uy}
    data = Data(rows, pinfo, meta, fmap)
    data.all_rows, data.primary_input, data.input_modes = all_rows, primary, modes
    minbits = compute_minbits(data)

    tmp = tempfile.mkdtemp(prefix=".report_figures-", dir=out_dir)
    try:
        figs = {}
        makers = {
            "coef_error_vs_degree.png": lambda p: fig_coef_vs_degree(data, p),
            "coef_error_hist.png": lambda p: fig_coef_hist(data, p),
            "misclassification_vs_d.png": lambda p: fig_misclass_vs_d(data, p),
            "min_mpfr_bits_vs_degree.png": lambda p: fig_min_bits(data, p, minbits),
            "time_vs_degree.png": lambda p: fig_time(data, p),
            "failure_map.png": lambda p: fig_failure_map(data, p) if fmap is not None else None,
        }
        for name in FIGURES:
            figs[name] = makers[name](os.path.join(tmp, name))
        with open(os.path.join(tmp, "report.md"), "w", encoding="utf-8") as fh:
            fh.write(build_report(data, figs, minbits))
        for name in FIGURES:  # figures first, report.md last
            dst = os.path.join(out_dir, name)
            if figs[name] is not None:
                os.replace(os.path.join(tmp, name), dst)
            elif os.path.exists(dst):
                os.remove(dst)  # a stale figure from an earlier run that this report does not show
        os.replace(os.path.join(tmp, "report.md"), os.path.join(out_dir, "report.md"))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    written = ["report.md"] + [n for n in FIGURES if figs[n] is not None]
    print(f"{PROG}: wrote {', '.join(written)} in {out_dir}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except InputError as e:
        _die(str(e), 2)
