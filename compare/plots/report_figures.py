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

The work is done by the package robustness_report/ beside this script (its __init__.py lists the modules).

Everything is written to a temporary folder inside DIR and moved into place at the end
(figures first, report.md last), so a failure leaves no half-written report. Exit status:
0 success, 2 missing or malformed input (the message names the file, line and column),
1 anything else. Needs Python 3, numpy and matplotlib (Debian: python3-matplotlib).
"""


import os
import shutil
import sys
import tempfile

from robustness_report.common import (FAILURE_COLUMNS, INPUTS, InputError, NO_TRUTH, OPTIONAL_RESULT_COLUMNS, PROG,
                                      RESULT_COLUMNS, _die)
from robustness_report.inputs import check_failure_map, check_results, read_csv, read_meta
from robustness_report.fmt import Data, base_label
from robustness_report.figures import (FIGURE_MANIFEST, fig_coef_hist, fig_coef_vs_degree, fig_failure_map,
                                       fig_min_bits, fig_misclass_vs_d, fig_time)
from robustness_report.vocab import OTHER_ENGINES, compute_minbits
from robustness_report.build import FIGURES, MANIFEST, build_report, check_figures_main, manifest_json


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
    # Rows of scenes without ground truth, and the certified row that IS a cycloidal scene's ground truth
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
