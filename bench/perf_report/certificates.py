"""The certificates' cost: checking against proving per kind, from `eccd regress --certify --json`."""

import json
import os
import sys

from .tools import loadavg, run


CHECK_OVER_PROVE_LIMIT = 0.5


def certificate_cost(args, root):
    """Checking against proving, per certificate kind, over cases/: the figures `eccd regress --certify --json` prints
    (prove = writing the certificate, its exact or interval run included; check = eccd-check's library on it)."""
    if args.eccd == "none":
        return {"error": "left out (--eccd none)"}
    eccd = args.eccd or os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(args.bench))), "eccd")
    if not os.path.isfile(eccd):
        return {"error": f"no eccd program at {eccd}"}
    cmd = [eccd, "-q", "regress", "cases/", "--arith", "certified", "--certify", "--json"]
    print("running: " + " ".join(cmd), file=sys.stderr)
    p = run(cmd, cwd=root)
    try:
        j = json.loads(p.stdout)
    except ValueError:
        return {"error": f"`{' '.join(cmd[1:])}` exited {p.returncode} without JSON: {p.stderr.strip()[-300:]}"}
    return {"command": "eccd " + " ".join(cmd[1:]), "agree": j.get("agree"), "differ": j.get("differ"),
            "errors": j.get("errors"), "kinds": j.get("certificate_cost", []), "load": loadavg()}


def write_certificate_cost(w, cost):
    w("## Certificates: checking against proving")
    w("")
    if not cost or cost.get("error"):
        w(f"Not measured: {cost.get('error') if cost else 'not run'}.")
        w("")
        return
    w(f"`{cost['command']}` in the same run (wall time of each step in one process, load {cost['load']}): proving is "
      "writing the certificate (its exact or interval run included), checking is `eccd-check`'s library on it, which "
      "shares no code with the prover. Target: checking at most half of proving, per kind, over the scenes of "
      f"`cases/`. The regression itself: {cost['agree']} agree, {cost['differ']} differ, {cost['errors']} errors.")
    w("")
    w("| kind | certificates | prove | check | check / prove | worst scene | limit | verdict |")
    w("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for k in cost["kinds"]:
        r = k["check_over_prove"]
        verdict = "**met**" if r <= CHECK_OVER_PROVE_LIMIT else f"**missed** by ×{r / CHECK_OVER_PROVE_LIMIT:.2f}"
        w(f"| `{k['kind']}` | {k['certificates']} | {k['prove_seconds']:.2f} s | {k['check_seconds']:.2f} s | {r:.2f} | "
          f"{k['worst_check_over_prove']:.2f} | {CHECK_OVER_PROVE_LIMIT} | {verdict} |")
    w("")
