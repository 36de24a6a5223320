#!/usr/bin/env python3
"""Writes the two forgeries of incomplete cycloidal certificates for 003
Example 1 (cases/paper003/example1.json, which collides on about
[0.2261, 0.7306]); each claims "collides": false although a stretch is left
undecided, and the checker must reject it (docs/checking.md). Format 2
(eccd-cycloidal-certificate/2, checked by eccd-check's own enclosures):

  cycloidal-incomplete-collides-false-epsilon-1e300.cert.json
      one undecided stretch from 0 to 0.99, "touch or near miss within
      epsilon" with epsilon = 1e300, the rest separate;
  cycloidal-collision-hidden-in-undecided-stretch.cert.json
      made from the genuine certificate: intervals and contacts emptied, one
      undecided stretch over exactly the collision.

Usage: python3 tests/data/cert/make_cycloidal_forgeries.py build/eccd
"""
import json
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", "..", ".."))
scene_path = os.path.join(root, "cases", "paper003", "example1.json")
scene = json.load(open(scene_path))

stretch = {"approx": "0.495", "lo": "0", "hi": "99/100"}
first = {"format": "eccd-cycloidal-certificate/2",
         "scene": {"path": "cases/paper003/example1.json", "name": scene["name"], "dim": scene["dim"], "a": scene["a"], "b": scene["b"]},
         "delta": {"convention": "forged", "precision_bits": 128},
         "timeline": [{"instant": stretch, "kind": "undecided", "status": "uncertain", "epsilon": "1e300",
                       "claim": "touch or near miss within epsilon: |Delta(t)| <= epsilon on [lo, hi]; nothing else is claimed there"},
                      {"cell_sample": "199/200", "status": "separate"},
                      {"instant": {"approx": "1", "lo": "1", "hi": "1"}, "kind": "end", "status": "separate"}],
         "gap_points": [], "gap_proofs": ["natural"], "complete": False,
         "answer": {"collides": False, "intervals": [], "first_contact": None, "contacts": [], "undecided": [stretch]},
         "seconds": 0}
json.dump(first, open(os.path.join(here, "cycloidal-incomplete-collides-false-epsilon-1e300.cert.json"), "w"), indent=1)

with tempfile.TemporaryDirectory() as d:
    out = os.path.join(d, "ex1.cert.json")
    subprocess.run([sys.argv[1], "certify", scene_path, "--no-floating", "--out", out], check=True, stdout=subprocess.DEVNULL)
    cert = json.load(open(out))
iv = cert["answer"]["intervals"][0]
lo, hi = iv[0]["lo"], iv[1]["hi"]
tl = cert["timeline"]
i = next(k for k, e in enumerate(tl) if "instant" in e and e["instant"]["lo"] == lo)
j = next(k for k, e in enumerate(tl) if "instant" in e and e["instant"]["hi"] == hi)
hidden = {"approx": iv[0]["approx"], "lo": lo, "hi": hi}
tl[i:j + 1] = [{"instant": hidden, "kind": "undecided", "status": "uncertain", "epsilon": "1e300",
                "claim": "touch or near miss within epsilon: |Delta(t)| <= epsilon on [lo, hi]; nothing else is claimed there"}]
from fractions import Fraction
cert["gap_points"] = [g for g in cert["gap_points"] if not Fraction(lo) <= Fraction(g) <= Fraction(hi)]
# (gap_proofs is left as written: the checker rejects the answer and the stretch before it reaches the gaps)
cert["complete"] = False
cert["answer"] = {"collides": False, "intervals": [], "first_contact": None, "contacts": [], "undecided": [hidden]}
cert.pop("floating_verdicts", None)
json.dump(cert, open(os.path.join(here, "cycloidal-collision-hidden-in-undecided-stretch.cert.json"), "w"), indent=1)
print("wrote the two cycloidal forgeries into", here)
