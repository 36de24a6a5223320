"""The report's name, its exit on bad input, the plotting packages and the schema of results.csv,
meta.json and failure_map.csv."""

import os
import sys


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
NO_TRUTH = "no_ground_truth"  # the scene has no ground truth (compare/harness_families.hpp); kept out of every table
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

# Columns that older results.csv files lack: a results.csv without them reads with these defaults (before input modes
# existed every floating pipeline started from the prepared scene).
OPTIONAL_RESULT_COLUMNS = [
    ("input", "str", False, INPUTS, "prepared"),
    ("digits", "int", True, None, None),
    ("reason", "str", True, None, None),
    ("coef_err_common", "float", True, None, None),
    ("guard", "str", True, ("none", "bound"), None),  # the face of a floating row; older files: guarded only
    ("exact_touch", "int", True, (0, 1), None),  # the truth touches without overlap (compare/metrics.hpp)
    ("second_look", "int", True, (0, 1, 2), None),  # guarded rows: 0 the bound alone, 1 a second look ran, 2 it decided
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
