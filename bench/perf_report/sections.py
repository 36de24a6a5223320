"""The animation and FCL sections, and the set and ratio targets: verdicts and tables."""

from .targets import RATIO_TARGETS, SET_TARGETS
from .tools import answer_text, fmt_ratio, fmt_time, md_escape


# The animation benchmarks, each a ratio to its group's baseline in
# the same process: (a) the boxers per frame (group animate-boxers, one
# iteration = "frames" frames in the row's result), (b) the plane check per
# pair-frame (plane-check), (c) the static test from two poses
# (static-certified-2d/3d). No limits: figures next to the papers'.
ANIMATION_GROUPS = [
    dict(group="animate-boxers", what="(a) per frame of the boxers (001 section 5 in spirit), 576 pairs per frame",
         per="frames", anchor="001 section 5: 3.4 ms per frame in double (3 GHz Pentium IV, 1000 frames)"),
    dict(group="plane-check", what="(b) the kept plane's check over one frame, per pair-frame (000 section 4)",
         per=None, anchor="000 Table 1: planes save the continuous test in most separate frames (µs per frame with and without)"),
    dict(group="static-certified-2d", what="(c) the static test from two poses, 2D, per pair", per=None,
         anchor="001: under 1 µs for the whole static procedure (3 GHz Pentium IV); the certified static test's cost target: at most 1.5x double"),
    dict(group="static-certified-3d", what="(c) the static test from two poses, 3D, per pair", per=None,
         anchor="001: under 1 µs for the whole static procedure (3 GHz Pentium IV); the certified static test's cost target: at most 1.5x double"),
]


def write_animation_section(w, summ):
    groups = {g["id"]: g for g in summ["groups"]}
    w("## Animations")
    w("")
    w("Each figure is a row's median CPU time and its ratio to the baseline row of its group, measured in the same "
      "process (the groups' full tables are under *Tables*). For the boxers one iteration animates all the frames of "
      "`bench/data/boxers-10.anim.json` (frames 0 to 9 of the report's animation, `make_repro.py boxers --frames 10`) "
      "with one thread (CPU time of the whole process: the pair-frames run on a worker thread); the per-frame time is the "
      "median divided by the frame count. The reproduction itself (1000 frames) is `scripts/run-animation-report.sh`.")
    w("")
    w("| benchmark | row | median (CPU) | per frame | ratio to baseline | result | paper |")
    w("| --- | --- | --- | --- | --- | --- | --- |")
    for a in ANIMATION_GROUPS:
        g = groups.get(a["group"])
        if not g:
            w(f"| {a['what']} | group `{a['group']}` not run | | | | | {a['anchor']} |")
            continue
        for i, r in enumerate(g["rows"]):
            what, anchor = (a["what"], a["anchor"]) if i == 0 else ("", "")
            label = md_escape(r["label"])
            if r["baseline"] and "(baseline)" not in r["label"]:
                label += " **(baseline)**"
            if "median_cpu_ns" not in r:
                w(f"| {what} | {label} | error: {md_escape(r.get('error', 'not measured'))} | | | | {anchor} |")
                continue
            res = r.get("result") if isinstance(r.get("result"), dict) else {}
            per = "–"
            if a["per"] and res.get(a["per"]):
                per = fmt_time(r["median_cpu_ns"] / res[a["per"]])
            if "pairs_per_frame" in res:  # an animation: the stages
                text = (f"{res['frames']} frames × {res['pairs_per_frame']} pairs: bounding spheres {res['bounding_volumes']}, "
                        f"kept plane {res['separating_plane']}, continuous test {res['continuous_test']}; "
                        f"{res['events']} events, {res['undecided']} undecided")
            elif res and all(isinstance(v, str) for v in res.values()):
                text = ", ".join(f"{k} {v}" for k, v in res.items())
            else:
                text = answer_text(r.get("result"))
            w(f"| {what} | {label} | {fmt_time(r['median_cpu_ns'])} | {per} | {fmt_ratio(r.get('ratio'))} | "
              f"{md_escape(text)} | {anchor} |")
    w("")


def per_unit(t):
    """What a target's "per" counts: the result field's name, or per_what (default "frames") for a fixed number."""
    return t["per"] if isinstance(t.get("per"), str) else t.get("per_what", "frames")


def per_divisor(t, r):
    """What a target's row median is divided by (TARGETS' optional "per"): 1, a number, or a result field."""
    per = t.get("per")
    if per is None:
        return 1.0
    if isinstance(per, (int, float)):
        return float(per)
    res = r.get("result") if isinstance(r.get("result"), dict) else {}
    n = res.get(per)
    return float(n) if isinstance(n, (int, float)) and n > 0 else None


FCL_STATIC_GROUP = "fcl-static3d"
FCL_FRAME_GROUPS = [
    ("fcl-table2-main", "orbit radius 5.49 (the report's main orbit)"),
    ("fcl-table2-graze", "orbit radius 5.4999999 (grazing: 1e-7 deep, below FCL's default tolerance 1e-6)"),
]


def write_fcl_section(w, summ):
    """eccd and FCL side by side, from the groups fcl-static3d and fcl-table2-*."""
    groups = {g["id"]: g for g in summ["groups"]}
    w("## Side by side with FCL")
    w("")
    w("Anchor (the figures that set the FCL comparison's targets, measured side by side): eccd's double static test from two poses 144 ns against "
      "549 ns for FCL's fastest ellipsoid test; one continuous query of two linearly translating ellipsoids 0.39 ms in "
      "FCL (its naive continuous collision samples the motion 1000 times). FCL 0.7 (Debian libfcl-dev) runs in the "
      "same process as eccd, on the same inputs; every figure is a median (CPU) and every ratio is of two rows of "
      "the same group.")
    w("")
    g = groups.get(FCL_STATIC_GROUP)
    w("### Static test per pair")
    w("")
    if not g:
        w(f"Group `{FCL_STATIC_GROUP}` not run.")
        w("")
    else:
        w(g["description"])
        w("")
        w("| row | median (CPU) per pair | FCL / eccd double | spread (min – max) | pairs that collide | differ from eccd certified |")
        w("| --- | --- | --- | --- | --- | --- |")
        fcl_best = None
        base = next((r for r in g["rows"] if r["baseline"] and "median_cpu_ns" in r), None)
        for r in g["rows"]:
            label = md_escape(r["label"]) + (" **(baseline)**" if r["baseline"] else "")
            if "median_cpu_ns" not in r:
                w(f"| {label} | error: {md_escape(r.get('error', 'not measured'))} | | | | |")
                continue
            res = r.get("result") if isinstance(r.get("result"), dict) else {}
            extra = f" ({res['uncertain']} uncertain in double)" if res.get("uncertain") else ""
            w(f"| {label} | {fmt_time(r['median_cpu_ns'])} | {fmt_ratio(r.get('ratio'))} | "
              f"{fmt_time(r.get('min_cpu_ns'))} – {fmt_time(r.get('max_cpu_ns'))} | {res.get('collide', '?')} of "
              f"{res.get('pairs', '?')} | {res.get('differ_from_certified', '?')}{extra} |")
            if r["label"].startswith("FCL") and (fcl_best is None or r["median_cpu_ns"] < fcl_best["median_cpu_ns"]):
                fcl_best = r
        w("")
        if fcl_best and base:
            w(f"FCL's fastest here: `{fcl_best['label']}`, {fmt_time(fcl_best['median_cpu_ns'])} per pair against "
              f"{fmt_time(base['median_cpu_ns'])} for eccd's double static test: FCL / eccd = "
              f"×{fcl_best['median_cpu_ns'] / base['median_cpu_ns']:.2f} (the anchor: 549 / 144 = ×3.81).")
            w("")
    g = groups.get("ccd3d-deg1-translation")
    fr = next((r for r in g["rows"] if r["label"].startswith("FCL") and "median_cpu_ns" in r), None) if g else None
    base = next((r for r in g["rows"] if r["baseline"] and "median_cpu_ns" in r), None) if g else None
    cert = next((r for r in g["rows"] if r["label"] == "certified solve (API)" and "median_cpu_ns" in r), None) if g else None
    if fr and base:
        w("### One continuous query of a translating pair")
        w("")
        w(f"The pair of the `ccd3d-deg1-translation` group (both translating linearly, colliding): FCL's naive continuous "
          f"collision with 1000 samples (`fcl_ccd`, first contact only) {fmt_time(fr['median_cpu_ns'])}, eccd's double query "
          f"(`eccd::solve`, all intervals and contact points) {fmt_time(base['median_cpu_ns'])} (FCL / eccd ×{fmt_ratio(fr['median_cpu_ns'] / base['median_cpu_ns'])[1:]})"
          + (f", certified {fmt_time(cert['median_cpu_ns'])} (FCL / eccd certified ×{fmt_ratio(fr['median_cpu_ns'] / cert['median_cpu_ns'])[1:]})" if cert else "")
          + ". FCL stops at its first colliding sample"
          + (f" (here t = {fr['result']['first_contact']})" if isinstance(fr.get("result"), dict) and fr["result"].get("first_contact") else "")
          + ", so its cost depends on where the contact lies. The anchor: FCL 0.39 ms.")
        w("")
    w("### Per frame of paper 000's Table 2 set-up")
    w("")
    w("A unit sphere orbiting a static ellipsoid 4.5, 4, 2 (0.01 rad per frame), frames 0 to 39 of "
      "`scripts/run-animation-report.sh`'s orbits (`bench/data/table2-*-40.anim.json`). A frame is the motion over "
      "[t_k, t_(k+1)]; it counts as colliding for eccd when the animation has an event in it, for FCL when some sample "
      "collides (or, for its continuous test, when it reports a time of contact). *Misclassified*: frames whose "
      "answer differs from eccd's certified animation (counted once, after the timing). The FCL sample rows time "
      "only `fcl::collide` (the poses are computed beforehand); the eccd rows include everything "
      "(`eccd::animate`: bounding spheres, the kept plane, the continuous test). Paper 000 Table 2: EECD 2.12 µs per "
      "frame, enhanced GJK on polyhedra 15.2 to 54.3 µs per frame (Pentium 4), missing 46 to 1 157 of 1 157 colliding frames.")
    w("")
    for gid, what in FCL_FRAME_GROUPS:
        g = groups.get(gid)
        w(f"#### {what}")
        w("")
        if not g:
            w(f"Group `{gid}` not run.")
            w("")
            continue
        w("| row | median (CPU) per frame | ratio to eccd double | frames in collision | misclassified against certified | missed | false collisions | undecided frames (not counted as misclassified) |")
        w("| --- | --- | --- | --- | --- | --- | --- | --- |")
        for r in g["rows"]:
            label = md_escape(r["label"]) + (" **(baseline)**" if r["baseline"] and "(baseline)" not in r["label"] else "")
            if "median_cpu_ns" not in r:
                w(f"| {label} | error: {md_escape(r.get('error', 'not measured'))} | | | | | | |")
                continue
            res = r.get("result") if isinstance(r.get("result"), dict) else {}
            frames = res.get("frames")
            per = fmt_time(r["median_cpu_ns"] / frames) if frames else "–"
            w(f"| {label} | {per} | {fmt_ratio(r.get('ratio'))} | {res.get('frames_in_collision', '?')} of {frames} | "
              f"{res.get('misclassified', '?')} | {res.get('missed', '?')} | {res.get('false_collisions', '?')} | "
              f"{res.get('undecided_frames', '–')} |")
        w("")


def ratio_verdicts(summ, alone=None):
    """The ratio targets' verdicts from the main run; alone_ratio and alone_met from the re-run of the target rows
    (alone: key -> row of that second process), where both rows were re-run."""
    rows = {r["key"]: r for g in summ["groups"] for r in g["rows"] if "median_cpu_ns" in r}
    alone = alone or {}
    out = []
    for t in RATIO_TARGETS:
        v = dict(t)
        r, b = rows.get(t["key"]), rows.get(t["base"])
        if not r or not b:
            v["status"] = "not measured"
        else:
            v["ns"], v["base_ns"] = r["median_cpu_ns"], b["median_cpu_ns"]
            v["ratio"] = v["ns"] / v["base_ns"]
            ratio_of = lambda row: (row or {}).get("counters", {}).get("ratio")  # noqa: E731
            if t.get("interleaved") and ratio_of(rows.get(t["interleaved"])):
                v["separate_ratio"], v["ratio"] = v["ratio"], ratio_of(rows[t["interleaved"]])
            v["status"] = "met" if v["ratio"] <= t["limit_ratio"] else "missed"
            v["result"] = r.get("result")
            ra, ba = alone.get(t["key"], {}), alone.get(t["base"], {})
            if t.get("interleaved") and ratio_of(alone.get(t["interleaved"])):
                v["alone_ratio"] = ratio_of(alone[t["interleaved"]])
                v["alone_met"] = v["alone_ratio"] <= t["limit_ratio"]
            elif ra.get("median_cpu_ns") and ba.get("median_cpu_ns"):
                v["alone_ratio"] = ra["median_cpu_ns"] / ba["median_cpu_ns"]
                v["alone_met"] = v["alone_ratio"] <= t["limit_ratio"]
        out.append(v)
    return out


def write_ratio_targets(w, ratios):
    w("## Ratio targets")
    w("")
    w("One row against another of the same group, medians (CPU) in the same process. *Re-measured alone*: the same "
      "ratio from both rows run again in the second process that re-runs the target rows (a ratio of two medians is "
      "as noisy as both; the verdict is the main run's). The guard's cost is measured *interleaved*: one row runs "
      "both faces in turn in every iteration, each solve timed by its thread's CPU clock, and its ratio (the median "
      "over repetitions of guarded / published) is the target's; the two rows' medians, timed minutes apart on a "
      "machine whose speed drifts, are shown beside it with their own ratio.")
    w("")
    w("| target | anchor | row | base row | row median | base median | ratio | limit | verdict | re-measured alone |")
    w("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for v in ratios:
        if v["status"] == "not measured":
            w(f"| {v['name']} | {v['anchor']} | `{v['key']}` | `{v['base']}` | | | | ×{v['limit_ratio']} | not measured | – |")
            continue
        verdict = f"**{v['status']}**" + (f" by ×{v['ratio'] / v['limit_ratio']:.2f}" if v["status"] == "missed" else "")
        alone = "–"
        if v.get("alone_ratio") is not None:
            alone = f"×{v['alone_ratio']:.2f} ({'met' if v['alone_met'] else 'missed'})"
            if v["alone_met"] != (v["status"] == "met"):
                alone += ": **the verdict differs**"
        ratio = f"×{v['ratio']:.2f}"
        if v.get("separate_ratio") is not None:
            ratio += f" interleaved (`{v['interleaved']}`); the two rows' medians: ×{v['separate_ratio']:.2f}"
        w(f"| {v['name']} | {v['anchor']} | `{v['key']}` | `{v['base']}` | {fmt_time(v['ns'])} | {fmt_time(v['base_ns'])} | "
          f"{ratio} | ×{v['limit_ratio']} | {verdict} | {alone} |")
    w("")
    for v in ratios:
        if isinstance(v.get("result"), dict):
            w(f"- `{v['key']}`: " + md_escape(answer_text(v["result"]) or
                                            ", ".join(f"{k} {n}" for k, n in v["result"].items())) + ".")
    w("")
    for v in ratios:
        if v["status"] != "missed":
            continue
        w(f"### {v['name']}: ×{v['ratio']:.2f} against ×{v['limit_ratio']} (missed)")
        w("")
        if v.get("note"):
            w(v["note"])
            w("")
        if v.get("perf"):
            w(f"Sampling profile of the row `{v['key']}` alone (`perf record -F 2999`; setup of the inputs included, flat, "
              "symbols above 1 %):")
            w("")
            w("| self % | symbol |")
            w("| --- | --- |")
            for pct, name in v["perf"].get("symbol", []):
                w(f"| {pct:.1f} | `{md_escape(name)}` |")
            w("")
            dsos = v["perf"].get("dso", [])
            if dsos:
                w("By shared object: " + ", ".join(f"{md_escape(n)} {p:.0f} %" for p, n in dsos) + ".")
                w("")
        elif v.get("perf_error"):
            w(f"No sampling profile: {v['perf_error']}.")
            w("")


def set_verdicts(summ):
    out = []
    for t in SET_TARGETS:
        g = next((g for g in summ["groups"] if g["id"] == t["group"]), None)
        v = dict(t)
        v["scenes"] = []
        if g is None:
            v["status"] = "not measured"
            out.append(v)
            continue
        by = {}
        for r in g["rows"]:
            if "median_cpu_ns" not in r:
                continue
            name, _, arith = r["label"].rpartition(" ")
            by.setdefault(name, {})[arith] = r
        for name in sorted(by):
            d, c = by[name].get(t.get("base", "double")), by[name].get("certified")
            if not d or not c:
                continue
            res = c.get("result") if isinstance(c.get("result"), dict) else {}
            x = dict(name=name, double_ns=d["median_cpu_ns"], certified_ns=c["median_cpu_ns"],
                     ratio=c["median_cpu_ns"] / d["median_cpu_ns"], decided_in=res.get("decided_in", "?"),
                     reason=res.get("escalation_reason", ""))
            if "interval_ms" in res:  # the guarantee's bound: base + 2 x the interval rung
                x["bound_ratio"] = c["median_cpu_ns"] / (d["median_cpu_ns"] + 2e6 * res["interval_ms"])
            v["scenes"].append(x)
        if not v["scenes"]:
            v["status"] = "not measured"
        else:
            ratios = sorted(x["ratio"] for x in v["scenes"])
            n = len(ratios)
            v["median_ratio"] = ratios[n // 2] if n % 2 else 0.5 * (ratios[n // 2 - 1] + ratios[n // 2])
            v["met"] = v["median_ratio"] <= t["limit_ratio"]
            v["status"] = "met" if v["met"] else "missed"
            # The profile (when missed) is of the certified row of the scene at the median.
            v["median_scene"] = min(v["scenes"], key=lambda x: abs(x["ratio"] - v["median_ratio"]))["name"]
        out.append(v)
    return out


def write_set_targets(w, sets):
    w("## The certified mode against double and exact (set targets)")
    w("")
    w("Per scene of the set: `eccd::solve_scene` with `--arith double` (or `exact`, where the set says so) and with "
      "`--arith certified`, each the median over its repetitions; the ratio is certified / double (or exact). *Decided in*: `interval` (intervals of doubles), "
      "`mpfi:256` (the MPFI rung) or `exact` (the last rung).")
    w("")
    for v in sets:
        w(f"### {v['name']}")
        w("")
        w(f"Anchor: {v['anchor']}. Limit: median ratio ×{v['limit_ratio']:.0f}.")
        w("")
        if v["status"] == "not measured":
            w("Not measured in this run.")
            w("")
            continue
        verdict = (f"**met** (median ×{v['median_ratio']:.2f})" if v["met"] else
                   f"**missed** by ×{v['median_ratio'] / v['limit_ratio']:.1f} (median ×{v['median_ratio']:.1f})")
        w(f"Verdict: {verdict}.")
        w("")
        base = v.get("base", "double")
        bound = any("bound_ratio" in x for x in v["scenes"])
        if bound:
            w(f"Column *bound*: certified / ({base} + 2 × the interval rung's time), the cost guarantee's bound "
              "(certified/ladder.hpp); at most 1 up to the constant c.")
            w("")
        w(f"| scene | {base} | certified | ratio |" + (" bound |" if bound else "") + " decided in | why it escalated |")
        w("| --- | --- | --- | --- |" + (" --- |" if bound else "") + " --- | --- |")
        for x in v["scenes"]:
            b = (f" ×{x['bound_ratio']:.2f} |" if "bound_ratio" in x else " - |") if bound else ""
            w(f"| {x['name']} | {fmt_time(x['double_ns'])} | {fmt_time(x['certified_ns'])} | ×{x['ratio']:.2f} |{b} "
              f"{x['decided_in']} | {md_escape(x['reason'][:140])} |")
        w("")
        counts = {}
        for x in v["scenes"]:
            counts[x["decided_in"]] = counts.get(x["decided_in"], 0) + 1
        w("Decided in: " + ", ".join(f"{k} {n}" for k, n in sorted(counts.items())) + ".")
        w("")
        if v.get("perf"):
            w(f"Profile of the certified row of the scene at the median ({v['median_scene']}), self time:")
            w("")
            w("| % | symbol |")
            w("| --- | --- |")
            for pct, name in v["perf"].get("symbol", []):
                w(f"| {pct:.1f} | `{md_escape(name)}` |")
            w("")
        elif v.get("perf_error"):
            w(f"No sampling profile: {v['perf_error']}.")
            w("")
