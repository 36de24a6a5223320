"""report.md assembled from the sections, and figures.json written and checked."""

import json
import os

from .common import InputError, PROG
from .figures import FIGURE_MANIFEST, MAX_SERIES
from .vocab import section_what_was_run
from .sections import (figure_block, section_bernstein, section_coef, section_engines, section_failure_map,
    section_findings, section_mpfr, section_mpfr_family, section_nearmiss, section_tables, section_trust)
from .verdict import section_verdict_detail
from .faces import section_claims, section_guard, section_published, section_verdict


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
