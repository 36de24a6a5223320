"""The report's sections on the guarded face: trust, Bernstein vs power, coefficient error, MPFR,
other engines, findings, tables, near-miss and the failure map."""

import math

from .common import ANSWERS
from .fmt import (base_label, few, fmt_bits, fmt_err, fmt_pct, fmt_ratio, fmt_sig, fmt_ulps, group_name,
    is_clean, md_table, median, smallest_correct_d, summarize, vmax)
from .figures import coef_pipelines, coef_rows, has_common, held_basis
from .vocab import (FAMILY_GROUPS, ISOLATED_CONTACT, MINBITS_NOTE, MPFR_FAMILY_GROUPS, NOT_PRECISION, T_BERN,
    T_COEF, T_ENGINES, T_MPFR, T_MPFR_FAM, T_TRUST, WRONG, arith_level, count, engine_rows, failing_level,
    fcl_status, fmt_causes, group_of, level_key, minbits_of, reason_class, reason_legend, scenes_of, share,
    touch_detection)


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


def finding_near_miss(data, dim):
    """The near-miss finding of one dimension: the smallest d each double pipeline still classifies correctly."""
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
            return (f"- {dim}D near-miss ({scenes_of(nm)} scenes, {span}): smallest d that each double "
                    f"pipeline still classifies correctly (with every larger d): " + "; ".join(parts)
                    + f"{caveat}.")
    return None


def finding_mpfr(data, dim, minbits):
    """The MPFR finding of one dimension: the smallest precision with no wrong, undecided or error answer."""
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
        return (f"- {dim}D smallest MPFR precision with no misclassification, undecided or error (tested "
                f"{', '.join(map(str, tested))} bits; touch and graze scenes counted apart, see {T_MPFR_FAM}): " + "; ".join(parts) + ".")
    return None


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
        for line in (finding_near_miss(data, dim), finding_mpfr(data, dim, minbits)):
            if line is not None:
                out.append(line)
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
