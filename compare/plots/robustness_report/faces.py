"""The two faces: the published algorithms as published, the guard's record, the papers' claims and
the verdict's opening."""

from .common import FAMILIES, INPUTS
from .fmt import base_label, few, fmt_pct, fmt_ratio, md_table, median
from .vocab import T_DETAIL, is_baseline, see, share


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


def time_ratio(p, g):
    """The guarded run's time over its as-published twin's, None where either failed or has no time."""
    if p["outcome"] == "error" or g["outcome"] == "error" or not p["time_us"] or not g["time_us"]:
        return None
    return g["time_us"] / p["time_us"]


def cost_stats(pairs):
    """The guard's cost on `pairs`: median time ratios over all pairs, over those whose guarded run the bound decided
    alone (second_look 0) and over those that took a second look (1 or 2, of which `looks_decided` decided), and the
    counts; a guarded run that hit its budget has no second_look and counts in the first median only. The split is
    None when results.csv has no second_look column (older files)."""
    timed = [(g.get("second_look"), time_ratio(p, g)) for p, g in pairs]
    timed = [(k, r) for k, r in timed if r is not None]
    out = {"all": median([r for _, r in timed]), "runs": len(timed), "split": None}
    if any(k is not None for k, _ in timed):
        alone = [r for k, r in timed if k == 0]
        looked = [r for k, r in timed if k is not None and k > 0]
        out["split"] = {"alone": len(alone), "alone_med": median(alone), "looks": len(looked),
                        "looks_med": median(looked), "looks_decided": sum(1 for k, _ in timed if k == 2)}
    return out


def cost_text(c):
    """'Time ×5.2 (median); ×1.4 where the bound decided alone (9 runs), ×24 with a second look (10 runs).'"""
    if c["all"] is None:
        return ""
    t = f" Time ×{fmt_ratio(c['all'])} (median)"
    sp = c["split"]
    if sp and sp["looks"]:
        alone = f"×{fmt_ratio(sp['alone_med'])} where the bound decided alone ({sp['alone']} runs), " if sp["alone"] else ""
        t += f"; {alone}×{fmt_ratio(sp['looks_med'])} with a second look ({sp['looks']} runs)"
    return t + "."


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
            "run was right; the last column is their share of the guarded undecided runs. *No touch in the truth*: "
            "the scenes whose exact answer never touches without overlapping (no collision interval of one instant, "
            "no continuous touching; column `exact_touch`): a touch is a double root, which no rounded run can prove, "
            "so a guarded run is undecided there by design and a right as-published answer there is the rounding's "
            "luck. The touch family, grazes and the touching cases (two spheres meeting, a circle rolling on a "
            "circle) are left out of that row.", ""]
    head = ["", "runs", "errors", "caught", "right anyway", "missed", "flagged", "false alarms", "of undecided"]
    body = []
    for dim in sorted({p["dim"] for p, _ in pairs}):
        dp = [(p, g) for p, g in pairs if p["dim"] == dim]
        body.append(guard_row(f"**{dim}D, all**", guard_stats(dp)))
        if all(p.get("exact_touch") is not None for p, _ in dp):  # older results.csv: no exact_touch column
            body.append(guard_row(f"**{dim}D, no touch in the truth**",
                                  guard_stats([(p, g) for p, g in dp if p["exact_touch"] == 0])))
        for f in FAMILIES:
            fp = [(p, g) for p, g in dp if p["family"] == f]
            if fp:
                body.append(guard_row(f"{dim}D {f}", guard_stats(fp)))
        for deg in sorted({p["degree"] for p, _ in dp}):
            body.append(guard_row(f"{dim}D degree {deg}", guard_stats([(p, g) for p, g in dp if p["degree"] == deg])))
    out += [md_table(head, body), ""]
    out += section_guard_cost(pairs)
    missed = [(p, g) for p, g in pairs if pub_error(p) and pub_error(g)]
    if missed:
        out += [f"**Missed by the guard** ({len(missed)}): " + "; ".join(
            f"{p['scene']} {guarded_label(p['pipeline'])} ({g['outcome']})" for p, g in missed[:10])
            + (" …" if len(missed) > 10 else "") + ".", ""]
    return out


def section_guard_cost(pairs):
    """The guard's cost per dimension, face pipeline and degree: the guarded run's time over its as-published twin's,
    split by whether the bound decided alone or a second look in 128-bit MPFR ran (column second_look)."""
    if not any(g.get("second_look") is not None for _, g in pairs):
        return []
    out = ["**The guard's cost**: the guarded run's time over its as-published twin's (wall time of each run as the "
           "harness measured it, medians over the pairs). *Bound alone*: the guarded double or MPFR run decided with "
           "its error bound, or stayed undecided without a second look. *Second look*: a guarded double run left "
           "undecided only by signs its bound could not read runs once more in 128-bit MPFR from the scene's numbers "
           "(docs/answer-format.md, `guard`); *decided* counts those whose second look decided everything. A guarded run "
           "that hit its time budget counts in *pairs* only. The "
           "target for the guard's cost is ×1.5 (median) on the 2D degree-6 set (reports/performance.md).", ""]
    head = ["", "pairs", "time ×", "bound alone", "its time ×", "second look", "decided", "its time ×"]
    body = []
    r = lambda x: f"×{fmt_ratio(x)}" if x is not None else "—"
    for dim in sorted({p["dim"] for p, _ in pairs}):
        for arith in ("double", "mpfr"):
            dp = [(p, g) for p, g in pairs if p["dim"] == dim and p["arith"] == arith]
            if not dp:
                continue
            rows = [(f"**{dim}D {arith}, all**", dp)] + [
                (f"{dim}D {arith} degree {deg}", [(p, g) for p, g in dp if p["degree"] == deg])
                for deg in sorted({p["degree"] for p, _ in dp})]
            for label, sel in rows:
                c = cost_stats(sel)
                sp = c["split"]
                if not c["runs"] or sp is None:
                    continue
                body.append([label, c["runs"], r(c["all"]), sp["alone"], r(sp["alone_med"]), sp["looks"],
                             sp["looks_decided"], r(sp["looks_med"])])
    return [*out, md_table(head, body), ""] if body else []


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
            cost = cost_text(cost_stats(dp))
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
