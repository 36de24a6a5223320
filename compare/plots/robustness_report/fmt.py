"""Number and table formatting, the per-pipeline summaries and the Data the sections read."""

import math
import statistics

from .common import OUTCOMES


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


def base_label(p):
    """A pipeline's label without the input-mode suffix (@prepared)."""
    return p.split("@")[0]
