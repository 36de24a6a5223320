"""What the sections share: the MPFR minimum table, *What was run*, family groups, table titles,
arithmetic levels and the classes of a run's reason."""

from .common import FAMILIES
from .fmt import base_label, fmt_seconds, is_clean, md_table, smallest_clean_bits


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
    if "no status there" in why:  # kernel/cd_disc.hpp collect_reasons, plain T (as published)
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
