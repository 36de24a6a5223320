#!/usr/bin/env python3
"""Turn the raw output of `eccd report` into the human robustness report.

Usage:  python3 compare/plots/report_figures.py DIR
        python3 compare/plots/report_figures.py --check-figures DIR   (checks DIR/figures.json: exit 0 ok, 1 not)

Reads   DIR/results.csv     one row per (scene, pipeline), the harness's contract
        DIR/meta.json       what was run, where, when
        DIR/failure_map.csv optional: answers on an n x n grid of ulp perturbations
Writes  DIR/report.md       tables and a plain-language summary, every number from the data
        DIR/*.png           coef_error_vs_degree, coef_error_hist, misclassification_vs_d,
                            min_mpfr_bits_vs_degree, time_vs_degree, failure_map
                            (a figure whose data are absent is skipped, and report.md says so)
        DIR/figures.json    per figure and panel the series drawn (label, colour, marker): at most 8 per
                            panel, no two with the same colour and marker (--check-figures checks it)

report.md opens with the verdict (at most 150 words): per dimension how often the published algorithms
as published are wrong in double, and the guard's record and cost; then the verdict in detail on the
guarded pipelines, per aspect (families, separations, degrees, input modes, Bernstein vs power,
coefficient error, MPFR bits, other engines) one computed sentence that names its table; then the
as-published misclassification tables, the guard's record and the papers' claims.

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
                           undecided or error; "none of the tested" otherwise. Touch and graze scenes
                           (an isolated contact: a double root no finite precision splits) are not
                           counted there but shown in rows of their own (MPFR bits per family, all
                           bases pooled); what keeps a precision up is classified by `reason`
                           (REASON_CLASSES: wrong, error bound, no status, Bézier unresolved, work bound,
                           overflow, time-out).
  time                     medians of time_us over rows whose outcome is not `error` (an error row
                           has no measured time; the harness writes 0 there).
  trustworthy              per dimension, family group and input mode, an arithmetic (double: the
                           error-bounded double pipelines pooled; mpfr:B) or another engine (certified,
                           each grid baseline, each FCL pipeline, each ext:NAME: a column of its own)
                           with no false positive, false negative or error; undecided
                           answers (the pipelines' own, from an error bound or a time budget) are
                           honest and counted apart. "Trustworthy from mpfr:B on": B and every larger
                           tested precision are.
  faces                    results.csv's `guard` column (absent in older files: the guarded face only):
                           `none` rows are the algorithms as published (plain double or MPFR, labels
                           ending in /published), `bound` rows guarded by the running error bound.
                           Every section but the verdict's first lines, the as-published tables, the
                           guard's record and the claims reads the guarded rows (and those without a face).
  input modes              results.csv's `input` column: `rounded` (the scene's numbers rounded to the
                           arithmetic) or `prepared` (coefficients prepared exactly, then rounded). The
                           main sections read the rounded rows where there are any; the section on
                           input modes reads both (certified, FCL and external rows, one mode each, are
                           in every section). Columns `input`, `digits`, `reason` and `coef_err_common`
                           may be absent (older files: input `prepared`).
  coefficient error        `coef_err` in each pipeline's own basis (power form for power, Bernstein
                           otherwise: not comparable across bases); `coef_err_common` the same
                           coefficients changed exactly to the Bernstein basis (comparable). Both exist
                           for the prepared input mode only.

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

OUTCOMES = ("correct", "false_positive", "false_negative", "undecided", "error", "no_ground_truth")
NO_TRUTH = "no_ground_truth"  # issue 20: the scene has no ground truth (compare/harness_families.hpp); kept out of every table
ARITHS = ("double", "mpfr", "exact", "certified", "fcl", "external")  # fcl: FCL as a peer; external: report --external
BASES = ("power", "bernstein", "scaled-bernstein", "exact", "none", "pointwise")  # none: certified, fcl and external rows; pointwise: cycloidal
FAMILIES = ("colliding", "free", "touch", "near-miss", "overlap", "graze", "decimal", "keyframe", "case", "cycloidal",
            "independent")
SOURCES = ("generated", "cases")
MOTIONS = ("kinematic", "euler", "affine", "translation", "case", "cycloidal")
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
    ("guard", "str", True, ("none", "bound"), None),  # issue 30: the face of a floating row; older files: guarded only
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
                if (empty_ok is True or (empty_ok == "error" and raw["outcome"] == "error") or raw["outcome"] == NO_TRUTH
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
        others = [p for p in self.order if p in have and self.pinfo[p][0] in ("certified", "fcl", "external")]
        if len(mp) <= 4:
            return cols + mp + others
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
        return cols + [p for p in mp if p in chosen] + others


def group_name(basis, method):
    return basis if method == "cd-disc" else f"{basis} ({method})"


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


def base_label(p):
    """A pipeline's label without the input-mode suffix (@prepared)."""
    return p.split("@")[0]


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


# --------------------------------------------------------------------------- report


MINBITS_NOTE = ("Touch and graze scenes (an isolated contact at one instant) are not counted in this table's minimum; "
                "they have their own rows in *MPFR bits per family*: a tangency is a double root, which rounding "
                "splits into a short overlap or removes at any finite precision, unless the method accepts a tolerance "
                "(the 3D Bézier method reports an instant where its two shots meet within its touch tolerance "
                "2^-(bits/2) as uncertain, floating/bezier_ccd.hpp). For them the right answer is *collision*.")


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
                # touch and graze scenes are counted apart (MPFR bits per family): see MINBITS_NOTE
                rb = {b: [r for r in data.sel(dim=dim, degree=deg, pipeline=p) if r["family"] not in ISOLATED_CONTACT]
                      for b, p in by_bits.items()}
                rb = {b: rs for b, rs in rb.items() if rs}
                if rb:
                    out[dim][grp][deg] = smallest_clean_bits(rb)
    return out


def scenes_of(rows):
    return len({r["scene"] for r in rows})


def row_counts(data):
    """The one account of the rows, for the verdict and *What was run*: all rows of results.csv, those judged
    against a ground truth (the rest: ground-truth rows themselves and rows of scenes without one), and those of
    the input mode the sections show."""
    total = getattr(data, "csv_rows", len(data.all_rows))
    published = len(getattr(data, "published", []))
    judged = len(data.all_rows) + published
    parts = [f"{judged} judged against a ground truth"
             + (f" ({published} of them as published, {len(data.all_rows)} guarded or faceless)" if published else "")]
    if getattr(data, "truth_rows", 0):
        parts.append(f"{data.truth_rows} the ground truth itself (a cycloidal scene's certified answer)")
    nt = total - judged - getattr(data, "truth_rows", 0)
    if nt > 0:
        parts.append(f"{nt} of scenes without a ground truth")
    text = f"{total} rows: " + ", ".join(parts)
    if len(data.rows) != judged:
        text += f"; {len(data.rows)} of them in input mode *{getattr(data, 'primary_input', 'prepared')}*, the mode of the sections below"
    return text


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
    rev = m.get("revision")
    out.append(f"- Version: {m['version']}" + (f" (git {rev})" if rev and rev != m["version"] else ""))
    out.append(f"- Started: {m['started']}")
    out.append(f"- Wall time: {fmt_seconds(m['wall_seconds'])} in {m['shards']} shard{'s' if m['shards'] != 1 else ''}")
    sc = f"- Scenes: {scenes_of(data.all_rows)} in results.csv, {row_counts(data)}"
    if m["scene_count"] != nscenes + len(getattr(data, "no_truth", {})):
        sc += f" (meta.json says {m['scene_count']} scenes)"
    out.append(sc)
    failed = m.get("failed")
    if isinstance(failed, list) and failed:
        shown = "; ".join(str(f) for f in failed[:3]) + ("; …" if len(failed) > 3 else "")
        out.append(f"- Failed tasks (meta.json): {len(failed)}: {shown}")
    no_truth = getattr(data, "no_truth", {})
    if no_truth:
        shown = "; ".join(f"{k} ({v[:160]})" for k, v in list(no_truth.items())[:3]) + ("; …" if len(no_truth) > 3 else "")
        out.append(f"- Scenes without ground truth (never guessed, left out of every table): {len(no_truth)}: {shown}")
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
            "from the exact ones. The exact pipeline is the ground truth (for a cycloidal scene the certified one: "
            "exact arithmetic cannot represent its motion; a scene without ground truth is counted above and left out).", ""]
    return out


FAMILY_GROUPS = (
    ("generic colliding", ("colliding",)),
    ("generic free", ("free",)),
    ("near-miss", ("near-miss",)),
    ("touch", ("touch",)),
    ("just overlapping and graze", ("overlap", "graze")),
    ("realistic decimals", ("decimal", "keyframe")),
    ("paper cases", ("case",)),
    ("cycloidal (003 V; certified truth)", ("cycloidal",)),
    ("independent motions (001 4; s-, t-intervals)", ("independent",)),
)
# The MPFR tables put the two isolated-contact families on rows of their own (a double root: see MINBITS_NOTE).
MPFR_FAMILY_GROUPS = tuple(g for g in FAMILY_GROUPS if g[0] != "just overlapping and graze")[:4] + (
    ("just overlapping", ("overlap",)), ("graze (isolated contact)", ("graze",))) + \
    tuple(g for g in FAMILY_GROUPS if g[0] != "just overlapping and graze")[4:]
WRONG = ("false_positive", "false_negative")
ISOLATED_CONTACT = ("touch", "graze")  # the exact collision set is one instant: a double root of the contact function
OTHER_ENGINES = ("certified", "fcl", "external")

# Titles of the tables the verdict points to (each is a heading below; test_report_figures.cpp checks both ends).
T_TRUST = "Where each arithmetic stays trustworthy, per family and input mode"
T_NEARMISS = "Near-miss scenes"
T_DEGREE = "Results per dimension and degree"
T_BERN = "Bernstein versus power"
T_COEF = "Coefficient error"
T_MPFR_FAM = "MPFR bits per family"
T_MPFR = "Smallest MPFR precision with no misclassification"
T_ENGINES = "Other engines: certified, FCL, external"
T_DETAIL = "Verdict in detail: the guarded pipelines"


def slug(title):
    """GitHub's anchor of a heading."""
    keep = "".join(c for c in title.lower() if c.isalnum() or c in " -_")
    return keep.replace(" ", "-")


def see(title):
    return f"→ [{title}](#{slug(title)})"


def is_baseline(r):
    return r["arith"] == "double" and r["method"].startswith(("sampling", "marching"))


def is_decision(r):
    """A double pipeline with an error-bounded decision: 2D cd-disc (any basis), 3D Bézier (either setup)."""
    return r["arith"] == "double" and r["method"] in ("cd-disc", "bezier")


def arith_level(r):
    """Column of the trust table: double (the error-bounded pipelines pooled), mpfr:B, certified, each grid baseline,
    each FCL pipeline and each external engine on its own."""
    a = r["arith"]
    if a == "double":
        return base_label(r["pipeline"]) if is_baseline(r) else "double"
    if a == "mpfr":
        return f"mpfr:{r['bits']}"
    if a == "certified":
        return "certified"
    return base_label(r["pipeline"])


def level_key(level):
    if level == "double":
        return (0, 0, "")
    if level.startswith("mpfr:"):
        return (1, int(level.split(":")[1]), "")
    if level == "certified":
        return (2, 0, "")
    if level.startswith("double/"):
        return (3, 0, level)
    if level.startswith("fcl/"):
        kind, _, n = level[4:].partition(":")
        return (4, int(n) if n.isdigit() else 0, kind)
    return (5, 0, level)


def level_kind(level):
    if level.startswith("double/"):
        return "grid baseline"
    if level.startswith("fcl/"):
        return "FCL"
    if level.startswith("ext:"):
        return "external engine"
    return None


def count(rows, *outcomes):
    return sum(1 for r in rows if r["outcome"] in outcomes)


def share(k, n):
    return f"{k}/{n} ({100.0 * k / n:.0f}%)" if n else "—"


def group_of(family):
    for g, fams in FAMILY_GROUPS:
        if family in fams:
            return g
    return family


def d_span(rows):
    ds = sorted({(r["d"], r["d_text"]) for r in rows if r.get("d") is not None}, reverse=True)
    if not ds:
        return ""
    return f"d = {ds[0][1]}" if len(ds) == 1 else f"d {ds[0][1]}…{ds[-1][1]}"


# Why a run is not clean, from its outcome and the words of its `reason` (compare/harness.cpp: the time budget, or the
# pipeline's own reasons: kernel/cd_disc.hpp, floating/bezier_ccd.hpp). The classes that more precision does not cure
# are NOT_PRECISION.
REASON_CLASSES = (
    ("wrong", "a false positive or negative: the precision was too low and the pipeline did not notice"),
    ("error bound", "a sign too close to zero to decide in this arithmetic (CD-DISC's error bound): more bits help"),
    ("no status", "as published (no error bound): the rounded values gave no status at an instant (f's signs in a "
                  "pattern impossible for two ellipses, a NaN, or a root of Δ between separate cells that did not read "
                  "as a touch): more bits help"),
    ("Bézier unresolved", "a status or contact the Bézier method could not resolve in this arithmetic: its error "
                          "bound, or two shots meeting within its touch tolerance 2^-(bits/2) at a tangency, which "
                          "more bits do not split"),
    ("work bound", "root isolation stopped at its work bound (pieces), not a precision limit"),
    ("overflow", "a non-finite coefficient: the exponent range of double, not its precision"),
    ("time-out", "the time budget, not the precision"),
    ("undecided", "undecided with a reason none of the above (older runs name only the instants)"),
    ("error", "the pipeline threw"),
)
NOT_PRECISION = ("work bound", "time-out")


def reason_class(r):
    """Why a row is not clean: one of REASON_CLASSES (or 'clean')."""
    if r["outcome"] in WRONG:
        return "wrong"
    if r["outcome"] == "error":
        return "error"
    if r["outcome"] != "undecided":
        return "clean"
    why = r.get("reason") or ""
    if why.startswith("time budget"):
        return "time-out"
    if "work bound" in why:
        return "work bound"
    if why.startswith("overflow"):
        return "overflow"
    if "Bezier method could not resolve" in why or "Bézier method could not resolve" in why:
        return "Bézier unresolved"
    if "too close to zero" in why:
        return "error bound"
    if "no status there" in why:  # kernel/cd_disc.hpp collect_reasons, plain T (issue 30 point 4)
        return "no status"
    return "undecided"


def reason_legend():
    return "; ".join(f"*{k}*: {v}" for k, v in REASON_CLASSES)


def fmt_causes(rows):
    bad = [r for r in rows if r["outcome"] != "correct"]
    cnt = {}
    for r in bad:
        c = reason_class(r)
        cnt[c] = cnt.get(c, 0) + 1
    return ", ".join(f"{v} {k}" for k, v in sorted(cnt.items(), key=lambda kv: -kv[1]))


def engine_rows(data):
    return [r for r in data.all_rows if r["arith"] in OTHER_ENGINES]


def fcl_status(data):
    """(available, sentence) from meta.json's "fcl" key and the rows."""
    fcl = data.meta.get("fcl")
    rows = [r for r in data.all_rows if r["arith"] == "fcl"]
    how = ("install Debian's libfcl-dev (apt-get install libfcl-dev), rebuild (CMake finds it) and rerun "
           "`eccd report`")
    if rows:
        return True, None
    if isinstance(fcl, dict) and fcl.get("available") is False:
        return False, f"FCL was not available in this run (meta.json: \"fcl\": available false): {how}."
    if isinstance(fcl, dict) and fcl.get("available"):
        return False, (f"FCL {fcl.get('version', '')} was available but results.csv has no FCL rows "
                       f"(every scene skipped?).")
    return False, f"FCL was not available in this run (no FCL rows in results.csv, no \"fcl\" key in meta.json): {how}."


def minbits_of(rows):
    """Smallest clean MPFR precision over `rows` (MPFR rows, bases pooled): bits | 'none of the tested' | None."""
    by_bits = {}
    for r in rows:
        if r["arith"] == "mpfr":
            by_bits.setdefault(r["bits"], []).append(r)
    if not by_bits:
        return None, {}
    return smallest_clean_bits(by_bits), by_bits


def failing_level(res, by_bits):
    """The precision whose failures decide `res`: the largest tested precision that is not clean."""
    bad = [b for b in by_bits if not all(is_clean(r) for r in by_bits[b])]
    return max(bad) if bad else None


def section_verdict_detail(data, minbits):
    rows = data.rows  # primary input mode (+ exact and the single-mode engines)
    allr = [r for r in data.all_rows if r["arith"] != "exact"]
    nscenes = scenes_of(data.all_rows)
    mode = data.primary_input
    out = [f"## {T_DETAIL}", "",
           f"Computed from results.csv: {nscenes} scenes, {row_counts(data)}; the as-published rows are in "
           f"{see(T_PUB)}, the sections below read the guarded face. A pipeline is *trusted* where "
           f"it is never confidently wrong (no false positive or false negative against the exact answer); an "
           f"*undecided* answer is honest and counted as the share it does not decide. *Double* means the "
           f"error-bounded double pipelines: 2D power / Bernstein / scaled-Bernstein (CD-DISC), 3D Bézier (both "
           f"setups); input mode *{mode}* unless said. Each point names the table below that backs it.", ""]
    out += headline(data) + [""]
    # 1. where some pipeline is confidently wrong
    wrong = [r for r in allr if r["outcome"] in WRONG]
    if wrong:
        per = {}
        for r in wrong:
            per.setdefault(base_label(r["pipeline"]), []).append(r)
        parts = []
        for p, rs in sorted(per.items(), key=lambda kv: -len(kv[1])):
            kind = level_kind(arith_level(rs[0])) or rs[0]["arith"]
            fams = {}
            for r in rs:
                fams.setdefault(group_of(r["family"]), []).append(r)
            where = ", ".join(f"{g} {len(x)}" + (f" ({d_span(x)})" if g == "near-miss" else "")
                              for g, x in sorted(fams.items(), key=lambda kv: -len(kv[1])))
            fp, fn = count(rs, "false_positive"), count(rs, "false_negative")
            dims = "/".join(f"{d}D" for d in sorted({r["dim"] for r in rs}))
            parts.append(f"{p} ({dims}, {kind}): {fp} false positive{'s' if fp != 1 else ''}, {fn} false "
                         f"negative{'s' if fn != 1 else ''} — {where}")
        clean_ps = sorted({base_label(r["pipeline"]) for r in allr} - set(per))
        out.append(f"- **Confidently wrong** ({'both input modes, ' if len(data.input_modes) > 1 else ''}"
                   f"{len(allr)} runs): " + "; ".join(parts)
                   + f". Never confidently wrong: {len(clean_ps)} other pipeline{'s' if len(clean_ps) != 1 else ''}. "
                   + see(T_TRUST))
    else:
        out.append(f"- **Confidently wrong**: no pipeline, anywhere in the data ({len(allr)} runs"
                   f"{', both input modes' if len(data.input_modes) > 1 else ''}). " + see(T_TRUST))
    # 2. families
    parts = []
    for dim in data.dims:
        dr = [r for r in rows if r["dim"] == dim and is_decision(r)]
        if not dr:
            continue
        w = [r for r in dr if r["outcome"] in WRONG]
        fam_parts = []
        for g, fams in FAMILY_GROUPS:
            gr = [r for r in dr if r["family"] in fams]
            if gr:
                fam_parts.append(f"{g} {share(count(gr, 'undecided', 'error'), len(gr))}")
        if w:
            wg = {}
            for r in w:
                wg[group_of(r["family"])] = wg.get(group_of(r["family"]), 0) + 1
            trust = ("NOT trusted in " + ", ".join(f"{g} ({k} wrong)" for g, k in wg.items())
                     + "; trusted in the other families")
        else:
            trust = f"trusted in every family ({len(dr)} runs, 0 wrong)"
        parts.append(f"{dim}D {trust}; undecided: " + ", ".join(fam_parts))
    if parts:
        out.append("- **Families** (double): " + ". ".join(parts) + ". " + see(T_TRUST))
    # 3. touch
    tparts = []
    for dim in data.dims:
        for label, pred in (("double", is_decision), ("MPFR", lambda r: r["arith"] == "mpfr")):
            tr = [r for r in rows if r["dim"] == dim and r["family"] in ISOLATED_CONTACT and pred(r)]
            if tr:
                tparts.append(f"{dim}D {label} says collision on {count(tr, 'correct')}, is undecided on "
                              f"{count(tr, 'undecided', 'error')} and wrong on {count(tr, *WRONG)} of {len(tr)} runs")
    out.append("- **Touch** (and graze): for a touch scene *collision* is the right answer — touching counts as a "
               "collision, the collision set is closed. A tangency is a double root: rounding splits it into a short "
               "overlap or removes it, so a floating pipeline decides it only by luck or a tolerance, and an honest one "
               "is often undecided there"
               + (": " + "; ".join(tparts) if tparts else "") + ". " + see(T_MPFR_FAM))
    # 4. separations
    parts = []
    for dim in data.dims:
        nm = [r for r in rows if r["dim"] == dim and r["family"] == "near-miss" and is_decision(r)]
        if not nm:
            continue
        ds = sorted({r["d"] for r in nm}, reverse=True)
        cells = []
        for d in ds:
            rd = [r for r in nm if r["d"] == d]
            cells.append(f"{rd[0]['d_text']} {100.0 * count(rd, 'undecided', 'error') / len(rd):.0f}%")
        w = [r for r in nm if r["outcome"] in WRONG]
        wtxt = f"wrong from {d_span(w)} ({len(w)} runs)" if w else "wrong at no d"
        parts.append(f"{dim}D double {wtxt}; undecided by d: " + ", ".join(cells))
    if parts:
        out.append("- **Separations** (near-miss, all degrees): " + ". ".join(parts) + ". " + see(T_NEARMISS))
    # 5. degrees
    parts = []
    for dim in data.dims:
        dr = [r for r in rows if r["dim"] == dim and is_decision(r)]
        if not dr:
            continue
        cells = []
        for deg in data.degrees[dim]:
            rd = [r for r in dr if r["degree"] == deg]
            if rd:
                cells.append(f"{deg}: {100.0 * count(rd, 'undecided', 'error') / len(rd):.0f}%"
                             + (f" ({count(rd, *WRONG)} wrong)" if count(rd, *WRONG) else ""))
        w = count(dr, *WRONG)
        parts.append(f"{dim}D double {'wrong at no degree' if not w else f'{w} wrong'}; undecided by degree "
                     + ", ".join(cells))
    if parts:
        out.append("- **Degrees**: " + ". ".join(parts) + ". " + see(T_DEGREE))
    # 6. input modes
    if len(data.input_modes) > 1:
        parts = []
        for dim in data.dims:
            cells = []
            for m in data.input_modes:
                mr = [r for r in data.all_rows if r["dim"] == dim and is_decision(r) and r["input"] == m]
                if mr:
                    cells.append(f"{m} {share(count(mr, 'undecided', 'error'), len(mr))} undecided, "
                                 f"{count(mr, *WRONG)} wrong")
            if cells:
                parts.append(f"{dim}D double " + " vs ".join(cells))
        out.append("- **Input modes** (rounded: the scene's numbers rounded, as a user's program holds them; "
                   "prepared: coefficients prepared exactly, then rounded): " + ". ".join(parts) + ". " + see(T_TRUST))
    else:
        out.append(f"- **Input modes**: only *{data.primary_input}* in results.csv. " + see(T_TRUST))
    # 7. Bernstein vs power
    parts = []
    for dim in data.dims:
        cmp = bernstein_comparison(data, dim)
        if not cmp:
            continue
        ref = cmp["ref"]
        items = []
        for p, st in cmp["pipes"].items():
            if p == ref:
                continue
            t = f", time ×{fmt_ratio(st['ratio'])}" if st["ratio"] is not None else ""
            items.append(f"{p} undecided {share(st['und'], st['n'])}, wrong {st['wrong']}{t}")
        rs = cmp["pipes"][ref]
        parts.append(f"{dim}D against {ref} (undecided {share(rs['und'], rs['n'])}, wrong {rs['wrong']}): "
                     + "; ".join(items))
    if parts:
        out.append("- **Bernstein vs power** (double; time: median of the per-scene ratios to power form): "
                   + ". ".join(parts) + ". " + see(T_BERN))
    # 8. coefficient error
    ce = coef_summary(data)
    if ce:
        out.append("- **Coefficient error** (prepared input only): " + ce + " " + see(T_COEF))
    # 9. MPFR bits
    parts = []
    for dim in data.dims:
        items = []
        for g, fams in MPFR_FAMILY_GROUPS:
            res, by_bits = minbits_of([r for r in rows if r["dim"] == dim and r["family"] in fams])
            if res is None:
                continue
            per_deg = {}
            for deg in data.degrees[dim]:
                rd, _ = minbits_of([r for r in rows if r["dim"] == dim and r["family"] in fams and r["degree"] == deg])
                if rd is not None:
                    per_deg[deg] = rd
            vals = set(map(str, per_deg.values()))
            if len(vals) == 1:
                txt = f"{fmt_bits(next(iter(per_deg.values())))}" + (" at every degree" if len(per_deg) > 1 else "")
            else:
                runs = []  # consecutive degrees with the same answer: "deg 2–3: 128"
                for d, b in per_deg.items():
                    if runs and runs[-1][2] == b and runs[-1][1] == d - 1:
                        runs[-1][1] = d
                    else:
                        runs.append([d, d, b])
                txt = ", ".join(f"deg {a}{'' if a == z else f'–{z}'}: {b if isinstance(b, int) else 'none'}"
                                for a, z, b in runs)
            if not isinstance(res, int):
                txt += f" (what fails at {max(by_bits)} bits: {fmt_causes(by_bits[max(by_bits)])})"
            items.append(f"{g} {txt}")
        if items:
            parts.append(f"{dim}D: " + "; ".join(items))
    if parts:
        out.append("- **MPFR bits** needed to decide every scene (no wrong, undecided or error at that and every "
                   "larger tested precision; bases pooled; 'none' = none of the tested): " + ". ".join(parts) + ". "
                   + see(T_MPFR_FAM))
    # 10. other engines
    out.append("- **Other engines**: " + engines_summary(data) + " " + see(T_ENGINES))
    out.append("")
    return out


def headline(data):
    """The verdict in one line per dimension (computed; the bullets below give the detail): is double ever confidently
    wrong, how much it leaves undecided, the best double form against power form, and which engines were wrong."""
    out = []
    for dim in data.dims:
        dr = [r for r in data.rows if r["dim"] == dim and is_decision(r)]
        if not dr:
            continue
        w = count(dr, *WRONG)
        tr = [r for r in dr if r["family"] in ISOLATED_CONTACT]
        touch = f"; {count(tr, 'undecided', 'error')} of them on the {len(tr)} touch and graze runs" if tr else ""
        text = (f"**{dim}D:** double {'was never confidently wrong' if not w else f'was confidently wrong {w} times'} "
                f"({len(dr)} runs, input *{data.primary_input}*) and left {share(count(dr, 'undecided', 'error'), len(dr))} "
                f"undecided, which it says itself{touch}")
        cmp = bernstein_comparison(data, dim)
        if cmp:
            best = min((p for p in cmp["pipes"] if p != cmp["ref"]), key=lambda p: cmp["pipes"][p]["und"], default=None)
            if best is not None:
                b, r0 = cmp["pipes"][best], cmp["pipes"][cmp["ref"]]
                t = f" at ×{fmt_ratio(b['ratio'])} its time" if b["ratio"] is not None else ""
                text += (f"; {best} leaves {share(b['und'], b['n'])} undecided against {share(r0['und'], r0['n'])} "
                         f"for {cmp['ref']}{t}")
        bad = sorted({base_label(r["pipeline"]) for r in data.all_rows
                      if r["dim"] == dim and r["outcome"] in WRONG and not is_decision(r) and r["arith"] != "exact"})
        if bad:
            text += f"; confidently wrong here: {', '.join(bad)}"
        out.append(f"- {text}. " + see(T_TRUST))
    return (["**In short.**", ""] + out) if out else []


def bernstein_comparison(data, dim):
    """Double form pipelines of `dim` against the power-form one (primary input mode): per pipeline runs, wrong,
    undecided and the median of per-scene time ratios to power form."""
    forms = [p for p in data.form_pipelines(dim)]
    ref = next((p for p in forms if data.pinfo[p][2] == "power"), None)
    if ref is None or len(forms) < 2:
        return None
    t_ref = {r["scene"]: r["time_us"] for r in data.sel(dim=dim, pipeline=ref)
             if r["outcome"] != "error" and r["time_us"]}
    pipes = {}
    for p in forms:
        rs = data.sel(dim=dim, pipeline=p)
        ratios = [r["time_us"] / t_ref[r["scene"]] for r in rs
                  if r["outcome"] != "error" and r["time_us"] and r["scene"] in t_ref]
        pipes[p] = {"n": len(rs), "wrong": count(rs, *WRONG), "und": count(rs, "undecided", "error"),
                    "ratio": median(ratios) if p != ref else 1.0}
    return {"ref": ref, "pipes": pipes}


def prepared_rows(data, dim, p):
    """The prepared-mode rows of the pipeline whose label (without suffix) is base_label(p)."""
    b = base_label(p)
    return [r for r in data.all_rows if r["dim"] == dim and base_label(r["pipeline"]) == b and r["input"] == "prepared"]


def coef_medians(data, dim, p, deg=None):
    rs = [r for r in prepared_rows(data, dim, p) if deg is None or r["degree"] == deg]
    return (median(r["coef_err"] for r in rs), median(r.get("coef_err_common") for r in rs),
            median(r["delta_err"] for r in rs))


def power_bernstein_pair(data, dim):
    """(the power-form double pipeline, its Bernstein-form counterpart) of a dimension, or None."""
    cmp = bernstein_comparison(data, dim)
    if not cmp:
        return None
    ref = cmp["ref"]
    bern = next((p for p in cmp["pipes"] if p != ref and data.pinfo[p][2] == "bernstein"), None)
    return None if bern is None else (ref, bern)


def coef_pairs(data):
    """Per dimension with a power/Bernstein double pair and measured coefficient errors: (dim, ref, bern,
    (own, common, Δ/F medians of ref), (the same of bern)); the common loop of coef_summary and coef_explanation."""
    for dim in data.dims:
        pair = power_bernstein_pair(data, dim)
        if pair is None:
            continue
        ref, bern = pair
        pm, bm = coef_medians(data, dim, ref), coef_medians(data, dim, bern)
        if pm[0] is None or bm[0] is None:
            continue
        yield dim, ref, bern, pm, bm


def coef_summary(data):
    """One computed paragraph: own-basis vs common-basis medians of the power and Bernstein double pipelines."""
    parts = []
    for dim, ref, bern, (po, pc, pd), (bo, bc, bd) in coef_pairs(data):
        dname = "Δ" if dim == 2 else "F(u,t)"
        same = held_basis(data.pinfo[ref]) == held_basis(data.pinfo[bern])
        txt = (f"{dim}D median in each pipeline's own basis {fmt_err(po)} ({ref}, {held_basis(data.pinfo[ref])}) vs "
               f"{fmt_err(bo)} ({bern}, {held_basis(data.pinfo[bern])}"
               + ("; one basis, so these compare)" if same else "; two bases, so these do not compare)"))
        if pc is not None and bc is not None:
            txt += f", in the common Bernstein basis {fmt_err(pc)} vs {fmt_err(bc)}"
        else:
            txt += ", common basis not measured (no coef_err_common in results.csv: an older run)"
        if pd is not None and bd is not None:
            txt += f"; {dname} error {fmt_err(pd)} vs {fmt_err(bd)}"
        parts.append(txt)
    if not parts:
        return None
    return ". ".join(parts) + "."


def engines_summary(data):
    er = engine_rows(data)
    parts = []
    for lv in sorted({arith_level(r) for r in er}, key=level_key):
        rs = [r for r in er if arith_level(r) == lv]
        w = count(rs, *WRONG)
        parts.append(f"{lv} {'never' if not w else f'{w} times'} confidently wrong in {len(rs)} runs, undecided "
                     f"{share(count(rs, 'undecided', 'error'), len(rs))}")
    avail, sentence = fcl_status(data)
    if sentence:
        parts.append(sentence.rstrip("."))
    if not any(r["arith"] == "certified" for r in er):
        parts.append("no certified rows")
    if not any(r["arith"] == "external" for r in er) and not data.meta.get("externals"):
        parts.append("no external engine (`eccd report --external NAME=DIR`)")
    return "; ".join(parts) + "."


def section_trust(data):
    """Per dimension, family group and input mode: where each arithmetic and each other engine stays trustworthy."""
    rows = [r for r in data.all_rows if r["arith"] != "exact"]
    out = [f"## {T_TRUST}", ""]
    if not rows:
        return out + ["No floating pipeline in results.csv.", ""]
    modes = data.input_modes or [data.primary_input]
    out += ["A floating answer is *trustworthy* here when it is never confidently wrong: no false positive or false "
            "negative against the exact answer (an *undecided* answer, which the pipeline gives itself from its error "
            "bound or its time budget, is honest and not wrong). Each cell: confidently wrong / runs, then undecided "
            "runs. *double*: the error-bounded double pipelines pooled (2D power, Bernstein, scaled-Bernstein; 3D "
            "Bézier, both setups); *mpfr:B*: every MPFR pipeline of B bits; *certified*, each grid baseline "
            "(3D sampling:N, marching:N: they look at a grid of instants and claim nothing between them), each FCL "
            "pipeline and each external engine: a column of its own. Input *rounded*: the scene's numbers rounded to "
            "the arithmetic, as a user's program holds them; *prepared*: the coefficients prepared exactly, then "
            "rounded. For touch and graze scenes the right answer is *collision* (touching counts).", ""]
    if len(modes) == 1:
        out += [f"Only the input mode *{modes[0]}* is in results.csv"
                + (" (this solver has no rounded input mode; every floating run started from the prepared scene)."
                   if modes[0] == "prepared" else "."), ""]
    avail, sentence = fcl_status(data)
    if sentence:
        out += [sentence, ""]
    levels = sorted({arith_level(r) for r in rows}, key=level_key)
    body, notes = [], []
    for dim in data.dims:
        for gname, fams in FAMILY_GROUPS:
            grows = [r for r in rows if r["family"] in fams and r["dim"] == dim]
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
                    wrong, und, err = count(lr, *WRONG), count(lr, "undecided"), count(lr, "error")
                    clean[lv] = wrong == 0 and err == 0
                    undec[lv] = (und, len(lr))
                    cell = f"{wrong}/{len(lr)}"
                    if und:
                        cell += f", {und} und."
                    if err:
                        cell += f", {err} err."
                    cells.append(cell)
                body.append([f"{dim}D", gname, mode, scenes_of(mrows)] + cells)
                ladder = [lv for lv in levels if lv in clean and (lv == "double" or lv.startswith("mpfr:"))]
                ok_from = None
                for lv in reversed(ladder):
                    if clean[lv]:
                        ok_from = lv
                    else:
                        break
                dbl = clean.get("double")
                if not ladder:
                    verdict = "no double or MPFR runs"
                elif ok_from is None:
                    verdict = "neither double nor any tested MPFR precision is free of confident errors"
                elif ok_from == ladder[0] and ok_from == "double":
                    verdict = "double and every tested MPFR precision trustworthy"
                else:
                    verdict = (f"double {'trustworthy' if dbl else 'not trustworthy' if dbl is not None else 'not run'}; "
                               f"MPFR trustworthy from {ok_from} on")
                bad_others = [lv for lv in clean if lv not in ladder and not clean[lv]]
                if bad_others:
                    verdict += "; confidently wrong: " + ", ".join(bad_others)
                und_levels = [f"{lv} {u} of {n}" for lv, (u, n) in undec.items() if u]
                if und_levels:
                    verdict += "; undecided: " + ", ".join(und_levels)
                notes.append(f"- {dim}D {gname}, input {mode} ({scenes_of(mrows)} scenes{few(scenes_of(mrows))}): "
                             f"{verdict}.")
    out.append(md_table(["dim", "family", "input", "scenes"] + levels, body,
                        ["---", "---", "---", "---:"] + ["---:"] * len(levels)))
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


def section_bernstein(data):
    out = [f"## {T_BERN}", ""]
    dims = [dim for dim in data.dims if bernstein_comparison(data, dim)]
    if not dims:
        return out + ["No power-form and Bernstein-form double pipelines side by side in results.csv.", ""]
    common = has_common(data)
    out += [f"The double pipelines that differ only by the basis f(λ; t) is set up in: 2D power, Bernstein and scaled "
            f"Bernstein form (003 VI-C); 3D the Bézier method with f set up in Bernstein form (double/bezier) or in "
            f"power form (double/bezier-power). Runs, wrong, undecided and time: input mode *{data.primary_input}*; "
            f"time ratio: median over scenes of this pipeline's time / the power-form pipeline's time. Coefficient "
            f"columns: **prepared input mode only** (the only mode in which the harness measures them). *coef err "
            f"own*: the normwise relative error of g_0..g_n in the basis the pipeline holds them (power form for "
            f"power, Bernstein form otherwise: compare/metrics.hpp); *coef err common*: the same floating "
            f"coefficients converted exactly to the Bernstein basis on [0, 1] and compared with the exact Bernstein "
            f"coefficients"
            + ("" if common else " (not in this results.csv: an older run; rerun `eccd report`)")
            + "; *Δ / F err*: the error of what is handed to the root finder (2D Δ in Bernstein form; 3D the "
            "control points of F(u, t)), already one basis for all.", ""]
    body = []
    for dim in dims:
        cmp = bernstein_comparison(data, dim)
        for deg in data.degrees[dim] + ["all"]:
            for p in cmp["pipes"]:
                rs = data.sel(dim=dim, pipeline=p) if deg == "all" else data.sel(dim=dim, degree=deg, pipeline=p)
                if not rs:
                    continue
                ref_t = {r["scene"]: r["time_us"] for r in data.sel(dim=dim, pipeline=cmp["ref"])
                         if r["outcome"] != "error" and r["time_us"]}
                ratios = [r["time_us"] / ref_t[r["scene"]] for r in rs
                          if r["outcome"] != "error" and r["time_us"] and r["scene"] in ref_t]
                co, cc, cd = coef_medians(data, dim, p, None if deg == "all" else deg)
                body.append([f"{dim}D", deg, p, len(rs), count(rs, *WRONG), count(rs, "undecided", "error"),
                             fmt_sig(median(r["time_us"] for r in rs if r["outcome"] != "error")),
                             fmt_ratio(median(ratios)) if ratios else "—", fmt_err(co), fmt_err(cc), fmt_err(cd)])
    out += [md_table(["dim", "degree", "pipeline", "runs", "wrong", "undecided", "time µs med", "time vs power",
                      "coef err own med", "coef err common med", "Δ / F err med"], body,
                     ["---", "---:", "---"] + ["---:"] * 8), ""]
    out += coef_explanation(data)
    return out


def coef_explanation(data):
    """Computed sentences on the apparent contradiction between coefficient and Δ errors (power vs Bernstein)."""
    out = []
    for dim, ref, bern, (po, pc, pd), (bo, bc, bd) in coef_pairs(data):
        same = held_basis(data.pinfo[ref]) == held_basis(data.pinfo[bern])
        if same and (pc is None or bc is None):
            pc, bc = po, bo  # one basis already: the own-basis error is the common-basis error
        dname = "Δ" if dim == 2 else "F(u, t)"
        txt = (f"{dim}D, all degrees (prepared input): the median coefficient error is {fmt_err(po)} for {ref} and "
               f"{fmt_err(bo)} for {bern}")
        if po > 0 and bo > po:
            txt += f" ({fmt_ratio(bo / po)}× larger for Bernstein)"
        elif bo > 0 and po > bo:
            txt += f" ({fmt_ratio(po / bo)}× larger for power)"
        if not same:
            txt += (", but these are errors of different numbers: power-form coefficients relative to the largest "
                    "power coefficient, Bernstein coefficients relative to the largest Bernstein coefficient.")
        else:
            txt += (f", both measured on Bernstein coefficients ({ref} sets f up in power form and converts it in "
                    f"floating point), so they compare as they stand.")
        g_ratio = None
        if pc is not None and bc is not None:
            if not same:
                txt += (f" Measured on the same numbers — each pipeline's floating coefficients changed exactly to "
                        f"the Bernstein basis — the medians are {fmt_err(pc)} ({ref}) and {fmt_err(bc)} ({bern}).")
            g_ratio = pc / bc if bc > 0 else (1.0 if pc == 0 else math.inf)
        else:
            txt += " The common-basis error is not in this results.csv (an older run: rerun `eccd report`)."
        d_ratio = pd / bd if (pd is not None and bd) else None
        if pd is not None and bd is not None:
            txt += (f" The {dname} error, measured on Bernstein coefficients for both, is {fmt_err(pd)} ({ref}) vs "
                    f"{fmt_err(bd)} ({bern})")
            txt += (f": {fmt_ratio(d_ratio)}× smaller for Bernstein." if d_ratio and d_ratio >= 1
                    else f": {fmt_ratio(1 / d_ratio)}× smaller for power form." if d_ratio else ".")
        if g_ratio is not None and d_ratio is not None and d_ratio >= 10:
            if g_ratio < 10:
                txt += (f" So g itself is about as accurate in either basis (common-basis ratio power / Bernstein "
                        f"{fmt_ratio(g_ratio)}); Bernstein form gains where {dname} is built from g.")
            elif d_ratio < 10 * g_ratio:
                txt += (f" The gain is already in g (common-basis ratio power / Bernstein {fmt_ratio(g_ratio)}) and carries over to "
                        f"{dname}.")
            else:
                txt += (f" g is {fmt_ratio(g_ratio)}× less accurate in power form already, and building {dname} "
                        f"from it loses more.")
        elif g_ratio is None and d_ratio is not None and d_ratio >= 10:
            txt += (f" Without the common-basis column this report cannot say whether the gain is in g or in building "
                    f"{dname}.")
        out += [txt, ""]
    return out


def section_coef(data, figs):
    out = [f"## {T_COEF}", "",
           "Coefficient errors exist only for the **prepared** input mode: the harness recomputes the coefficients "
           "from the exactly prepared scene, so rounded rows leave them empty. `coef_err` is measured in the basis "
           "each pipeline holds its coefficients — power form for `power` (and the 3D projection), Bernstein form "
           "otherwise (3D bezier-power included: its f is set up in power form but held in Bernstein form) — so the "
           "raw column of a power pipeline and of a Bernstein pipeline measure different numbers and do not compare. "
           "`coef_err_common` converts every pipeline's floating coefficients exactly to the Bernstein basis on "
           "[0, 1] and compares them with the exact Bernstein coefficients; for a Bernstein pipeline it equals "
           f"`coef_err`. The numbers per degree are in *{T_BERN}* above.", ""]
    body = []
    for dim in data.dims:
        for p in coef_pipelines(data, dim) + [q for q in data.all_order if data.all_pinfo[q][0] == "mpfr"
                                              and coef_rows(data, dim, q)]:
            rs = coef_rows(data, dim, p)
            body.append([f"{dim}D", base_label(p), held_basis(data.all_pinfo[p]), len(rs),
                         fmt_err(median(r["coef_err"] for r in rs)), fmt_err(median(r.get("coef_err_common") for r in rs)),
                         fmt_err(vmax(r.get("coef_err_common") for r in rs)), fmt_err(median(r["delta_err"] for r in rs))])
    if body:
        out += [md_table(["dim", "pipeline (prepared)", "basis held", "rows", "coef err own med", "coef err common med",
                          "coef err common max", "Δ / F err med"], body, ["---", "---", "---"] + ["---:"] * 5), ""]
    out += figure_block(figs, "coef_error_vs_degree.png")
    out += figure_block(figs, "coef_error_hist.png")
    return out


def section_mpfr_family(data):
    out = [f"## {T_MPFR_FAM}", ""]
    rows = [r for r in data.rows if r["arith"] == "mpfr"]
    if not rows:
        return out + ["No MPFR pipelines in results.csv.", ""]
    tested = sorted({r["bits"] for r in rows})
    out += [f"Smallest tested MPFR precision (tested {', '.join(map(str, tested))} bits; all bases and methods pooled; "
            f"input mode *{data.primary_input}*) at which this and every larger tested precision gives no wrong, "
            "undecided or error answer on the family's scenes of that degree — every family, touch included. When "
            "it is not the lowest tested precision, the parenthesis says what failed at the largest precision that "
            "is not clean, classified by the `reason` column: " + reason_legend() + ". The reason column does not "
            "say which of the Bézier method's unresolved instants are tangencies within its touch tolerance; in touch "
            "and graze scenes they are.", ""]
    body = []
    for dim in data.dims:
        for g, fams in MPFR_FAMILY_GROUPS:
            gr = [r for r in rows if r["dim"] == dim and r["family"] in fams]
            if not gr:
                continue
            cells = []
            for deg in data.degrees[dim] + ["all"]:
                dr = gr if deg == "all" else [r for r in gr if r["degree"] == deg]
                res, by_bits = minbits_of(dr)
                if res is None:
                    cells.append("—")
                    continue
                fl = failing_level(res, by_bits)
                cell = str(res) if isinstance(res, int) else "none"
                if fl is not None:
                    cell += f" ({fl}: {fmt_causes(by_bits[fl])})"
                cells.append(cell)
            body.append([f"{dim}D", g, scenes_of(gr)] + cells)
    # one table per dimension (degrees differ between dimensions)
    for dim in data.dims:
        dbody = [b for b in body if b[0] == f"{dim}D"]
        if not dbody:
            continue
        dd = data.degrees[dim]
        out += [f"{dim}D (cells: bits; none: none of the tested):", "",
                md_table(["dim", "family", "scenes"] + [f"degree {d}" for d in dd] + ["all degrees"], dbody,
                         ["---", "---", "---:"] + ["---:"] * (len(dd) + 1)), ""]
    out += ["Touch (and graze) rows: a finite precision cannot split a double root, so no precision is expected to "
            "decide them unless a method accepts a tolerance; the right answer there is *collision* (touching "
            "counts). Their undecided answers are honest, not wrong.", ""]
    return out


def section_engines(data):
    out = [f"## {T_ENGINES}", ""]
    er = engine_rows(data)
    out += ["Engines judged against the exact answer next to double and MPFR: `certified` (the certified ladder), "
            "FCL (`fcl/sample:N`: fcl::collide at t = k/N; `fcl/ccd:N`: fcl::continuousCollide, naive, N "
            "iterations) and external engines (`ext:NAME`, `eccd report --external NAME=DIR`). Their rows are also "
            f"columns of *{T_TRUST}* and of the near-miss tables.", ""]
    avail, sentence = fcl_status(data)
    if sentence:
        out += [sentence, ""]
    fcl = data.meta.get("fcl")
    if isinstance(fcl, dict) and fcl.get("available"):
        if fcl.get("version"):
            out.append(f"- FCL version: {fcl['version']}")
        if fcl.get("tolerances"):
            out.append(f"- FCL tolerances: {fcl['tolerances']}")
        sk = fcl.get("skipped")
        if isinstance(sk, dict) and sk:
            out.append("- Scenes FCL cannot express (no row for that pipeline): "
                       + ", ".join(f"{k} {v}" for k, v in sk.items()))
        out.append("")
    ext = data.meta.get("externals")
    if isinstance(ext, list) and ext:
        for e in ext:
            if isinstance(e, dict):
                out.append(f"- External engine {e.get('name')}: answers from {e.get('dir')}, {e.get('answers')} "
                           f"answers, {e.get('missing')} scenes without an answer")
        out.append("")
    if not er:
        return out + ["No certified, FCL or external rows in results.csv.", ""]
    levels = sorted({arith_level(r) for r in er}, key=level_key)
    body = []
    for lv in levels:
        for dim in data.dims:
            rs = [r for r in er if arith_level(r) == lv and r["dim"] == dim]
            if not rs:
                continue
            fams = {}
            for r in rs:
                if r["outcome"] in WRONG:
                    g = group_of(r["family"])
                    fams[g] = fams.get(g, 0) + 1
            body.append([lv, f"{dim}D", rs[0]["input"], len(rs), count(rs, "false_positive"),
                         count(rs, "false_negative"), count(rs, "undecided"), count(rs, "error"),
                         fmt_pct(count(rs, *WRONG), len(rs)),
                         ", ".join(f"{g} {k}" for g, k in fams.items()) or "none",
                         fmt_sig(median(r["time_us"] for r in rs if r["outcome"] != "error"))])
    out += [md_table(["engine", "dim", "input", "runs", "FP", "FN", "undecided", "errors", "misclass.",
                      "wrong by family", "time µs med"], body, ["---", "---", "---"] + ["---:"] * 5 + ["---", "---:"]),
            ""]
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
                        bad = [r for r in data.sel(dim=dim, degree=deg, pipeline=by_bits[top])
                               if not is_clean(r) and r["family"] not in ISOLATED_CONTACT]
                        fams = {}
                        for r in bad:
                            fams[r["family"]] = fams.get(r["family"], 0) + 1
                        notes.append(f"at {top} bits " + ", ".join(f"{c} {f}" for f, c in fams.items())
                                     + f" scene{'s' if len(bad) != 1 else ''} still fail{'s' if len(bad) == 1 else ''}")
                    items.append(f"degree {deg}: {fmt_bits(b)}" + (f" ({'; '.join(notes)})" if notes else ""))
                parts.append(f"{group_name(*grp)} — " + ", ".join(items))
            tested = sorted({b for g in data.mpfr_groups(dim).values() for b in g})
            out.append(f"- {dim}D smallest MPFR precision with no misclassification, undecided or error (tested "
                       f"{', '.join(map(str, tested))} bits; touch and graze scenes counted apart, see {T_MPFR_FAM}): " + "; ".join(parts) + ".")
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
            "(instants in t ∈ [0, 1]); time: median over rows without error; — : not applicable or no data. The coefficient "
            "columns exist for the prepared input mode only (the rows of the other mode show —); coef err is in each "
            f"pipeline's own basis: see *{T_BERN}* and *{T_COEF}* for the common basis.", ""]
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
    out = [f"## {T_MPFR}", ""]
    if not minbits:
        out += ["No MPFR pipelines in results.csv: table and min_mpfr_bits_vs_degree.png skipped.", ""]
        return out
    out += ["Per dimension, degree and basis: the smallest tested precision p such that at p and every larger "
            "tested precision no scene is a false positive, false negative, undecided or error. " + MINBITS_NOTE, ""]
    cols = list(dict.fromkeys(g for dim in minbits for g in minbits[dim]))
    body, why = [], []
    for dim in data.dims:
        for deg in data.degrees[dim]:
            rs = data.sel(dim=dim, degree=deg)
            counted = [r for r in rs if r["family"] not in ISOLATED_CONTACT]
            row = [f"{dim}D", deg, scenes_of(rs), scenes_of(counted), scenes_of(rs) - scenes_of(counted)]
            for g in cols:
                b = minbits.get(dim, {}).get(g, {}).get(deg)
                row.append("—" if b is None else fmt_bits(b))
                by_bits = data.mpfr_groups(dim).get(g, {})
                rb = {bb: [r for r in data.sel(dim=dim, degree=deg, pipeline=p) if r["family"] not in ISOLATED_CONTACT]
                      for bb, p in by_bits.items()}
                rb = {bb: x for bb, x in rb.items() if x}
                fl = failing_level(b, rb) if b is not None and rb else None
                if fl is not None:
                    bad = [r for r in rb[fl] if not is_clean(r)]
                    fams = {}
                    for r in bad:
                        fams[r["family"]] = fams.get(r["family"], 0) + 1
                    causes = fmt_causes(bad)
                    only_not_precision = all(reason_class(r) in NOT_PRECISION for r in bad)
                    why.append(f"- {dim}D degree {deg}, {group_name(*g)}: {fmt_bits(b)} because at {fl} bits "
                               f"{len(bad)} run{'s' if len(bad) != 1 else ''} {'are' if len(bad) != 1 else 'is'} not "
                               f"clean: {causes} (families: " + ", ".join(f"{f} {k}" for f, k in fams.items()) + ")"
                               + ("; none of them is a precision limit (time budget or work bound)" if only_not_precision
                                  else "") + ".")
            body.append(row)
    out += [md_table(["dim", "degree", "scenes", "counted", "touch + graze (apart)"] + [group_name(*g) for g in cols],
                     body, ["---", "---:", "---:", "---:", "---:"] + ["---:"] * len(cols)), ""]
    if why:
        out += ["Why a cell is above the lowest tested precision, by the `reason` column (" + reason_legend() + "):",
                ""] + why + [""]
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

# --------------------------------------------------------------------------- the two faces
#
# Rows with guard "none" are the published algorithms as published (plain double or MPFR, nothing added); their label
# ends in "/published" before any "@prepared" (compare/harness.hpp). Every other section reads the guarded rows (guard
# "bound") and the rows without a face; these sections read the as-published rows and pair each with its guarded twin.

PUBLISHED = "/published"
T_PUB = "The published algorithms as published: misclassification"
T_GUARD = "The guard's record"
T_CLAIMS = "The papers' claims"


def guarded_label(p):
    """The guarded twin of an as-published label ("double/power/published@prepared" -> "double/power@prepared")."""
    return p.replace(PUBLISHED, "", 1)


def pub_error(r):
    """How an as-published (or any) run is wrong against the exact answer: 'FP', 'FN', 'structure' (collides right,
    intervals, contacts or ends not), or None (right, undecided or error). A run that claims a collision where none
    happens is a false positive even beside undecided instants (its outcome is then `undecided`): the collision it
    reports is decided, and wrong."""
    if r["outcome"] == "false_positive" or (r["outcome"] == "undecided" and r["collides"] == 1 and r["exact_collides"] == 0):
        return "FP"
    if r["outcome"] == "false_negative":
        return "FN"
    if r["outcome"] == "correct" and r["structure_ok"] != 1:
        return "structure"
    return None


def is_right(r):
    return r["outcome"] == "correct" and r["structure_ok"] == 1


def face_pairs(data):
    """(as-published row, guarded row) for every as-published row whose guarded twin is in results.csv, the sampled
    baselines (sampling:N, marching:N) left out: they claim nothing between their samples, so the guard, which bounds
    rounding errors, has nothing to flag in their sampling errors (the as-published tables show them)."""
    twin = {(r["scene"], r["pipeline"]): r for r in data.all_rows}
    return [(p, twin[(p["scene"], guarded_label(p["pipeline"]))]) for p in data.published
            if (p["scene"], guarded_label(p["pipeline"])) in twin and not p["method"].startswith(("sampling", "marching"))]


def err_cell(rs):
    """'wrong/runs' with the kinds: '3/40 (2 FP, 1 FN)'; '0/40'; '' without runs."""
    if not rs:
        return ""
    kinds = [pub_error(r) for r in rs]
    w = sum(1 for k in kinds if k)
    parts = [f"{kinds.count(k)} {name}" for k, name in (("FP", "FP"), ("FN", "FN"), ("structure", "struct"))
             if kinds.count(k)]
    return f"{w}/{len(rs)}" + (f" ({', '.join(parts)})" if parts else "")


def pub_pivot(rows, col_of, cols, title, names=None):
    """One table: a row per (dim, pipeline without '/published'), a column per value of col_of (headed by
    names[c] when given)."""
    keys = []
    for r in rows:
        k = (r["dim"], r["pipeline"].replace(PUBLISHED, ""))
        if k not in keys:
            keys.append(k)
    body = []
    for dim, p in keys:
        rs = [r for r in rows if r["dim"] == dim and r["pipeline"].replace(PUBLISHED, "") == p]
        body.append([f"{dim}D", p] + [err_cell([r for r in rs if col_of(r) == c]) for c in cols] + [err_cell(rs)])
    head = ["dim", "pipeline (as published)"] + [str((names or {}).get(c, c)) for c in cols] + ["all"]
    return [f"**{title}**", "", md_table(head, body, ["---", "---"] + ["---:"] * (len(cols) + 1)), ""]


def section_published(data):
    out = [f"## {T_PUB}", ""]
    rows = data.published
    if not rows:
        return out + ["No as-published rows in results.csv (run `eccd report --guard none,bound`; older runs measured "
                      "the guarded face only).", ""]
    out += ["Each cell: runs whose answer is wrong / runs, with the kinds: FP (false positive: collision claimed, none "
            "happens; also beside undecided instants), FN (false negative), struct (collides right, but an interval, an end, the first contact or a "
            "contact wrong). The pipelines run in plain double or MPFR with nothing added (label without its "
            "`/published` suffix; `@prepared`: the exactly prepared input, else the scene's numbers rounded). "
            "Undecided here means the algorithm itself gave up (a work bound, a value that is not finite, the time "
            "budget).", ""]
    degs = sorted({r["degree"] for r in rows})
    out += pub_pivot(rows, lambda r: r["degree"], degs, "Per motion degree")
    fams = [f for f in FAMILIES if any(r["family"] == f for r in rows)]
    out += pub_pivot(rows, lambda r: r["family"], fams, "Per family")
    nm = [r for r in rows if r["family"] == "near-miss"]
    if nm:
        ds = sorted({r["d"] for r in nm}, reverse=True)
        text = {r["d"]: r["d_text"] for r in nm}
        out += pub_pivot(nm, lambda r: r["d"], ds, "Near-miss scenes per separation d", text)
    modes = [m for m in INPUTS if any(r["input"] == m for r in rows)]
    if len(modes) > 1:
        byp = [dict(r, pipeline=base_label(r["pipeline"])) for r in rows]
        out += pub_pivot(byp, lambda r: r["input"], modes, "Per input mode (both modes pooled under one label)")
    return out


def guard_stats(pairs):
    """errors (as published wrong), caught (guarded undecided or error there), right (guarded right anyway), missed
    (guarded wrong too), alarms (as published right, guarded undecided), undecided (guarded undecided or error)."""
    s = {"runs": len(pairs), "errors": 0, "caught": 0, "right": 0, "missed": 0, "alarms": 0, "undecided": 0}
    for p, g in pairs:
        g_und = g["outcome"] in ("undecided", "error") and not pub_error(g)
        s["undecided"] += g_und
        if pub_error(p):
            s["errors"] += 1
            if pub_error(g):
                s["missed"] += 1
            elif g_und:
                s["caught"] += 1
            else:
                s["right"] += 1
        elif is_right(p) and g_und:
            s["alarms"] += 1
    return s


def guard_row(label, s):
    flagged = s["errors"] - s["missed"]
    return [label, s["runs"], s["errors"], s["caught"], s["right"], s["missed"],
            fmt_pct(flagged, s["errors"]) if s["errors"] else "—", s["alarms"],
            share(s["alarms"], s["undecided"]) if s["undecided"] else "—"]


def section_guard(data):
    out = [f"## {T_GUARD}", ""]
    pairs = face_pairs(data)
    if not pairs:
        return out + ["No pairs of as-published and guarded runs in results.csv: the guard's record needs both faces "
                      "(`eccd report --guard none,bound`, the default).", ""]
    out += ["Each as-published run beside its guarded twin (same scene, pipeline and input). *Errors*: the as-published "
            "answer is wrong (FP, FN or structure). *Caught*: the guarded run is undecided there. *Right anyway*: the "
            "guarded answer is right. *Missed*: the guarded answer is wrong too — a bug of the guard, and a test "
            "failure (tests/compare/test_guard_record.cpp). *False alarms*: guarded undecided where the as-published "
            "run was right; the last column is their share of the guarded undecided runs.", ""]
    head = ["", "runs", "errors", "caught", "right anyway", "missed", "flagged", "false alarms", "of undecided"]
    body = []
    for dim in sorted({p["dim"] for p, _ in pairs}):
        dp = [(p, g) for p, g in pairs if p["dim"] == dim]
        body.append(guard_row(f"**{dim}D, all**", guard_stats(dp)))
        for f in FAMILIES:
            fp = [(p, g) for p, g in dp if p["family"] == f]
            if fp:
                body.append(guard_row(f"{dim}D {f}", guard_stats(fp)))
        for deg in sorted({p["degree"] for p, _ in dp}):
            body.append(guard_row(f"{dim}D degree {deg}", guard_stats([(p, g) for p, g in dp if p["degree"] == deg])))
    out += [md_table(head, body), ""]
    missed = [(p, g) for p, g in pairs if pub_error(p) and pub_error(g)]
    if missed:
        out += [f"**Missed by the guard** ({len(missed)}): " + "; ".join(
            f"{p['scene']} {guarded_label(p['pipeline'])} ({g['outcome']})" for p, g in missed[:10])
            + (" …" if len(missed) > 10 else "") + ".", ""]
    return out


def claim_near_miss(data, dim, basis, d_max):
    """As-published double near-miss runs of `basis` (2D cd-disc) per input mode: the d at which they are wrong."""
    res = {}
    for m in INPUTS:
        rs = [r for r in data.published if r["dim"] == dim and r["family"] == "near-miss" and r["arith"] == "double"
              and r["basis"] == basis and r["method"] == "cd-disc" and r["input"] == m]
        if rs:
            w = [r for r in rs if pub_error(r)]
            res[m] = (len(rs), len(w), sorted({r["d"] for r in w}, reverse=True), {r["d"]: r["d_text"] for r in rs})
    return res


def section_claims(data):
    out = [f"## {T_CLAIMS}", "",
           "Each claim of the papers (docs/references.md), how this workbench reproduces it and the verdict: *confirmed*, "
           "*refuted*, or *holds only for prepared input* (true when the scene's coefficients are prepared exactly, "
           "false for the scene's numbers held as doubles, as a user's program holds them). Verdicts marked (run) are "
           "computed from this run's results.csv; the others cite where they are measured.", ""]
    body = []

    def mode_text(res, m):
        n, w, ds, text = res[m]
        return f"{m}: wrong {w}/{n}" + (f" (largest d wrong {text[ds[0]]})" if ds else "") + few(n)

    pw = claim_near_miss(data, 2, "power", 1e-6)
    if pw:
        # fails below ~1e-6: wrong at some d <= 1e-6, never above 1e-5
        def fails_as_claimed(m):
            n, w, ds, _ = pw[m]
            return bool(ds) and max(ds) <= 1e-5
        v = ("confirmed" if all(fails_as_claimed(m) for m in pw) else
             "holds only for prepared input" if "prepared" in pw and fails_as_claimed("prepared") else
             "refuted" if not any(pw[m][1] for m in pw) else "refuted (fails at larger d)")
        body.append(["003 VI-C: power form fails below d ≈ 1e-6", "2D near-miss, double/power as published; "
                     + "; ".join(mode_text(pw, m) for m in pw), v + " (run)"])
    bz = claim_near_miss(data, 2, "bernstein", 1e-12)
    if bz:
        def robust(m):
            n, w, ds, _ = bz[m]
            return not any(d >= 1e-12 for d in ds)
        v = ("confirmed" if all(robust(m) for m in bz) else
             "holds only for prepared input" if "prepared" in bz and robust("prepared") else "refuted")
        body.append(["003 VI-C: Bernstein form robust to d = 1e-12", "2D near-miss, double/bernstein as published; "
                     + "; ".join(mode_text(bz, m) for m in bz), v + " (run)"])
    ex2 = [r for r in data.published if "example2" in r["scene"] and r["arith"] == "double" and r["basis"] == "bernstein"]
    if ex2:
        w = [r for r in ex2 if pub_error(r)]
        body.append(["003 Example 2: the Bernstein form decides the perturbed scenes in double",
                     f"cases/paper003/example2*.json, double/bernstein as published: wrong on {len(w)} of {len(ex2)} runs"
                     + (" (" + ", ".join(sorted({r['scene'] + ' ' + r['pipeline'] for r in w})[:4]) + ")" if w else ""),
                     ("confirmed" if not w else "holds only for prepared input"
                      if all(r["input"] == "rounded" for r in w) else "refuted") + " (run)"])
    body.append(["003 Example 2: Δ of degree 96, touching at t = 1/2",
                 "cases/paper003/example2.json (stored exact answer; `eccd solve --arith exact --json`: "
                 "projection_degree, the contact at 1/2)", "confirmed (cases/, eccd regress)"])
    body.append(["003 VI-C, Fig. 8: variant timings (degree 6: under 1 ms for Variant 1, 5 ms for Variant 2, 7 ms "
                 "for all contacts)", "reports/performance.md, the 2D CCD rows per degree and Variant",
                 "not measured by this run: reports/performance.md"])
    bez = [r for r in data.published if r["dim"] == 3 and r["arith"] == "double" and r["method"] == "bezier"
           and r["basis"] == "bernstein"]
    if bez:
        w = [r for r in bez if pub_error(r)]
        modes = {r["input"] for r in w}
        v = ("confirmed" if not w else
             "holds only for prepared input" if modes == {"rounded"} else "refuted")
        body.append(["001 section 4: the Bézier method is robust in double",
                     f"3D, double/bezier as published: wrong on {len(w)} of {len(bez)} runs"
                     + (f" ({', '.join(sorted(modes))} input)" if w else ""), v + " (run)"])
    body.append(["001: the static test under 1 µs", "reports/performance.md, the static3d target row (eccd::static_status "
                 "in double, per pair)", "not measured by this run: reports/performance.md"])
    body.append(["002 III: its example collides on [0.1699, 0.3465] and [0.7055, 0.8544]",
                 "cases/paper002/example.json: the exact answer, stored and checked by `eccd regress` "
                 "([0.16988, 0.34650] and [0.70471, 0.85621])", "first interval confirmed, second refuted (cases/)"])
    body.append(["000 Table 1: a kept separating plane spares the continuous test in most frames",
                 "reports/performance.md, Animations (b): the plane check against the continuous test per pair-frame",
                 "not measured by this run: reports/performance.md"])
    body.append(["000 Table 2: GJK on polyhedra misses colliding frames",
                 "reports/performance.md, per frame of 000's Table 2 set-up (FCL's GJK against eccd's certified animation)",
                 "not measured by this run: reports/performance.md"])
    out += [md_table(["claim", "reproduction", "verdict"], body, ["---", "---", "---"]), ""]
    return out


def faces_verdict(data):
    """The verdict's first lines: per dimension how often the published algorithms are wrong in double (from which
    degree and d), then what the guard costs. Short sentences; the whole verdict stays under 150 words."""
    out = []
    pairs = face_pairs(data)
    for dim in data.dims:
        pd = [r for r in data.published if r["dim"] == dim and r["arith"] == "double" and not is_baseline(r)]
        if not pd:
            continue
        w = [r for r in pd if pub_error(r)]
        if not w:
            out.append(f"- **{dim}D, as published:** double was never wrong ({len(pd)} runs).")
            continue
        degs = sorted({r["degree"] for r in w})
        nm = sorted({(r["d"], r["d_text"]) for r in w if r["family"] == "near-miss"}, reverse=True)
        where = f" Wrong at degree {degs[0]}" + (f"–{degs[-1]}" if len(degs) > 1 else "") + \
            (f"; near misses from d = {nm[0][1]} down" if nm else "") + "."
        out.append(f"- **{dim}D, as published:** double was wrong on {share(len(w), len(pd))} runs." + where)
        dp = [(p, g) for p, g in pairs if p["dim"] == dim and p["arith"] == "double" and not is_baseline(p)]
        if dp:
            s = guard_stats(dp)
            flagged = s["errors"] - s["missed"]
            caught = (f"it flagged all {s['errors']} errors." if not s["missed"] else
                      f"it missed {s['missed']} of {s['errors']} errors (a bug of the guard).")
            ratios = [g["time_us"] / p["time_us"] for p, g in dp
                      if p["time_us"] and g["time_us"] and p["outcome"] != "error" and g["outcome"] != "error"]
            cost = f" Time ×{fmt_ratio(median(ratios))} (median)." if ratios else ""
            out.append(f"  Guarded: {caught} Undecided {share(s['undecided'], s['runs'])}, of which {s['alarms']} "
                       f"false alarms.{cost}")
    if not out:
        return ["- No as-published rows: this run measured the guarded face only."]
    return out


def words(lines):
    return sum(len(l.replace("*", "").split()) for l in lines)


def section_verdict(data, minbits):
    """The verdict (at most 150 words, short sentences): the two faces per dimension, then where the detail is."""
    out = ["## Verdict", "",
           "*As published*: the papers' algorithms in plain double. *Guarded*: the same with an error bound.", ""]
    out += faces_verdict(data)
    out += ["", "Detail: " + ", ".join(see(t) for t in (T_PUB, T_GUARD, T_CLAIMS, T_DETAIL)) + ".", ""]
    return out


def build_report(data, figs, minbits):
    out = [f"# Robustness report: {data.meta['name']}", ""]
    out += section_verdict(data, minbits)
    out += section_verdict_detail(data, minbits)
    out += section_published(data)
    out += section_guard(data)
    out += section_claims(data)
    out += section_what_was_run(data)
    out += section_trust(data)
    out += section_findings(data, minbits)
    out += section_tables(data)
    out += section_bernstein(data)
    out += section_coef(data, figs)
    out += section_nearmiss(data, figs)
    out += section_mpfr(data, minbits, figs)
    out += section_mpfr_family(data)
    out += section_engines(data)
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
    out.append(f"- [{MANIFEST}]({MANIFEST}): the series of every figure panel (label, colour, marker)")
    out += ["", f"Written by compare/plots/{PROG} from the files above.", ""]
    return "\n".join(out)


FIGURES = ("coef_error_vs_degree.png", "coef_error_hist.png", "misclassification_vs_d.png",
           "min_mpfr_bits_vs_degree.png", "time_vs_degree.png", "failure_map.png")
MANIFEST = "figures.json"


def manifest_json():
    """figures.json: per figure, its panels and their series (label, colour, marker, line style, merged count)."""
    return json.dumps({"format": "eccd-report-figures/1", "version": 1, "max_series_per_panel": MAX_SERIES,
                       "figures": FIGURE_MANIFEST}, indent=2, ensure_ascii=False) + "\n"


def check_figures_main(out_dir):
    """--check-figures DIR: checks DIR/figures.json against the plot rules; prints each problem; 0 if none, 1 else."""
    path = os.path.join(out_dir, MANIFEST)
    if not os.path.isfile(path):
        raise InputError(f"{path}: not found")
    try:
        with open(path, encoding="utf-8") as fh:
            manifest = json.load(fh)
    except json.JSONDecodeError as e:
        raise InputError(f"{MANIFEST} line {e.lineno}, column {e.colno}: {e.msg}") from None
    problems = check_manifest(manifest)
    for p in problems:
        print(p)
    panels = sum(len(v) for v in manifest["figures"].values())
    print(f"{PROG}: {len(manifest['figures'])} figures, {panels} panels, {len(problems)} problems")
    return 1 if problems else 0


def check_manifest(manifest):
    """The plot rules on a figures.json object: a list of problems (empty: all kept). Used by the tests."""
    problems = []
    for fig, panels in manifest["figures"].items():
        for pn in panels:
            ser = pn["series"]
            if len(ser) > manifest.get("max_series_per_panel", MAX_SERIES):
                problems.append(f"{fig} / {pn['panel']}: {len(ser)} series")
            seen = {}
            for s in ser:
                key = (s["color"], s["marker"])
                if key in seen:
                    problems.append(f"{fig} / {pn['panel']}: '{s['label']}' and '{seen[key]}' share colour and marker")
                seen[key] = s["label"]
            labels = [s["label"] for s in ser]
            if len(set(labels)) != len(labels):
                problems.append(f"{fig} / {pn['panel']}: a label twice")
    return problems


def main(argv):
    if len(argv) == 3 and argv[1] == "--check-figures":
        return check_figures_main(argv[2])
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print("\n".join(__doc__.strip().splitlines()[2:4]), file=sys.stderr)
        return 2 if len(argv) != 2 else 0
    out_dir = argv[1]
    if not os.path.isdir(out_dir):
        raise InputError(f"{out_dir}: not a directory")
    all_rows = read_csv(os.path.join(out_dir, "results.csv"), RESULT_COLUMNS, OPTIONAL_RESULT_COLUMNS)
    check_results(all_rows)
    # Issue 20: rows of scenes without ground truth, and the certified row that IS a cycloidal scene's ground truth
    # (compared with itself), are kept out of every table; the scenes without ground truth are counted apart.
    no_truth = {}
    csv_rows = len(all_rows)
    truth_rows = sum(1 for r in all_rows if r["outcome"] != NO_TRUTH and (r["reason"] or "").startswith("ground truth:"))
    for r in all_rows:
        if r["outcome"] == NO_TRUTH:
            no_truth.setdefault(r["scene"], r["reason"] or "")
    all_rows = [r for r in all_rows if r["outcome"] != NO_TRUTH and not (r["reason"] or "").startswith("ground truth:")]
    if not all_rows:
        raise InputError("results.csv: every scene lacks a ground truth (outcome no_ground_truth): nothing to report")
    # The as-published rows (guard none) have sections of their own; every other section reads the guarded face.
    published = [r for r in all_rows if r.get("guard") == "none"]
    all_rows = [r for r in all_rows if r.get("guard") != "none"]
    if not all_rows:
        raise InputError("results.csv: only as-published rows (guard none): the report needs the exact rows")
    all_pinfo = check_results(all_rows)
    # The main sections read one input mode (rounded where present: what users run); the section on input modes
    # and families reads every row.
    # input modes of the double and MPFR pipelines (certified, FCL and external run in one mode each)
    modes = [m for m in INPUTS if any(r["input"] == m and r["arith"] in ("double", "mpfr") for r in all_rows)]
    primary = modes[0] if modes else "prepared"
    # exact and the engines that run in one input mode only (certified, FCL, external) are in every section
    # (a pipeline that runs in one input mode only, e.g. double/independent or double/cycloidal, is in every section)
    in_primary = {base_label(r["pipeline"]) for r in all_rows if r["input"] == primary}
    rows = [r for r in all_rows if r["arith"] in ("exact",) + OTHER_ENGINES or r["input"] == primary
            or base_label(r["pipeline"]) not in in_primary]
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
    data.no_truth = no_truth
    data.csv_rows, data.truth_rows = csv_rows, truth_rows
    data.published = published
    data.all_pinfo = all_pinfo
    data.all_order = [p for p in data.order if p in all_pinfo] + [p for p in dict.fromkeys(r["pipeline"] for r in all_rows)
                                                                  if p not in data.order]
    FIGURE_MANIFEST.clear()
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
        with open(os.path.join(tmp, MANIFEST), "w", encoding="utf-8") as fh:
            fh.write(manifest_json())
        for name in FIGURES:  # figures first, report.md last
            dst = os.path.join(out_dir, name)
            if figs[name] is not None:
                os.replace(os.path.join(tmp, name), dst)
            elif os.path.exists(dst):
                os.remove(dst)  # a stale figure from an earlier run that this report does not show
        os.replace(os.path.join(tmp, MANIFEST), os.path.join(out_dir, MANIFEST))
        os.replace(os.path.join(tmp, "report.md"), os.path.join(out_dir, "report.md"))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    written = ["report.md", MANIFEST] + [n for n in FIGURES if figs[n] is not None]
    print(f"{PROG}: wrote {', '.join(written)} in {out_dir}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except InputError as e:
        _die(str(e), 2)
