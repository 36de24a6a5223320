#!/usr/bin/env python3
"""Writes the certificate forgeries of issue 15 (item 6 and 7) next to this
script, each a genuine certificate with one part forged, and forgeries.json,
which names for each file its scene (under cases/), the claim the checker must
name, and a text its reason must contain (the JSON place).

Usage: make_forgeries.py ECCD   (the eccd binary; it writes the genuine
certificates with `eccd certify --no-floating` first, kept as valid-*.cert.json).
tests/certificate/test_certificate_forgeries.cpp checks every entry: the genuine
certificate VALID, each forgery REJECTED with the claim and place named, in
bounded time.
"""
import copy
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "..", "..", "..", "cases")
eccd = sys.argv[1]

BASES = {
    "2d": "paper003/example2-towards-1e-9.json",
    "3d": "paper002/example.json",
    "rolling2d": "rolling/circles-rolling.json",
    "rolling3d": "rolling/spheres-rolling.json",
}
certs = {}
for key, rel in BASES.items():
    out = os.path.join(HERE, f"valid-{key}.cert.json")
    subprocess.run([eccd, "certify", os.path.join(CASES, rel), "--no-floating", "--out", out], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(out) as f:
        c = json.load(f)
    c.pop("floating_verdicts", None)
    c["scene"]["path"] = rel
    with open(out, "w") as f:
        f.write(json.dumps(c, indent=1) + "\n")
    certs[key] = c

manifest = []


def forge(name, base, what, claim, place, edit=None, text=None):
    path = os.path.join(HERE, name + ".cert.json")
    if text is None:
        c = copy.deepcopy(certs[base])
        edit(c)
        text = json.dumps(c, indent=1) + "\n"
    with open(path, "w") as f:
        f.write(text)
    manifest.append({"file": name + ".cert.json", "scene": BASES[base], "what": what, "claim": claim, "place": place})


def first_irrational(c):
    for k in range(0, len(c["timeline"]), 2):
        n = c["timeline"][k]
        if n["root_of_factor"] is not None and n["instant"]["lo"] != n["instant"]["hi"]:
            return k
    raise SystemExit("no irrational root")


k2 = first_irrational(certs["2d"])


def setp(path, value):
    def edit(c):
        o = c
        for p in path[:-1]:
            o = o[p]
        o[path[-1]] = value
    return edit


# (a) approx checked: a number lying in its bracket.
forge("approx-first-contact-0.75", "3d", "first contact approx 0.75 (true ~0.1699)", "answer", "answer.first_contact.approx",
      setp(["answer", "first_contact", "approx"], "0.75"))
forge("approx-not-a-number", "2d", "an interval start approx \"not a number\"", "answer", "answer.intervals[0][0].approx",
      setp(["answer", "intervals", 0, 0, "approx"], "not a number"))
forge("approx-timeline-outside", "2d", "a timeline instant's approx outside its bracket", "instant 1 ",
      f"timeline[{k2}].instant.approx", setp(["timeline", k2, "instant", "approx"], "0.75"))
forge("approx-contact-fraction", "2d", "a contact's approx written as a fraction", "answer", "answer.contacts[0].approx",
      setp(["answer", "contacts", 0, "approx"], "1/2"))
# (c) duplicate keys: a forged answer before the true one.
c = certs["2d"]
forged = {"collides": False, "intervals": [], "first_contact": None, "contacts": []}
body = json.dumps({k: v for k, v in c.items() if k != "answer"}, indent=1)
text = body[:-2] + ',\n "answer": ' + json.dumps(forged) + ',\n "answer": ' + json.dumps(c["answer"]) + "\n}\n"
forge("duplicate-answer", "2d", "a forged \"answer\" followed by the true one", "certificate format", "/answer: duplicate key",
      text=text)
# (d) integers range-checked, projection.degree checked.
forge("root-of-factor-2pow32", "2d", "root_of_factor 4294967296 (reads as 0 when truncated)", "certificate format",
      f"timeline[{k2}].root_of_factor", setp(["timeline", k2, "root_of_factor"], 4294967296))
forge("multiplicity-2pow32-plus-1", "2d", "multiplicity 4294967297 (reads as 1 when truncated)", "certificate format",
      "projection.square_free_factors[0].multiplicity",
      setp(["projection", "square_free_factors", 0, "multiplicity"], 4294967297))
forge("projection-degree-wrong", "2d", "projection.degree 95 instead of 96", "projection", "projection.degree",
      setp(["projection", "degree"], certs["2d"]["projection"]["degree"] - 1))
# (e) malformed parts.
forge("evidence-string", "2d", "evidence a string", "certificate format", f"timeline[{k2}].evidence",
      setp(["timeline", k2, "evidence"], "P negative, D positive"))
forge("evidence-object", "2d", "evidence an object", "certificate format", f"timeline[{k2}].evidence",
      setp(["timeline", k2, "evidence"], {"poly": "P", "sign": "negative"}))
forge("evidence-entry-number", "2d", "an evidence entry a number", "certificate format", f"timeline[{k2}].evidence[0]",
      setp(["timeline", k2, "evidence", 0], 7))
forge("timeline-entry-string", "2d", "a timeline entry a string", "certificate format", "timeline[1]",
      setp(["timeline", 1], "cell"))
# (f) denial of service: rationals and multiplicities beyond any need.
forge("cell-sample-2e6-digit-denominator", "2d", "a cell sample with a 2*10^6-digit denominator", "certificate format",
      "timeline[1].cell_sample", setp(["timeline", 1, "cell_sample"], "1/1" + "0" * 2000000))
forge("gap-point-1e5-digit-denominator", "2d", "a gap point with a 10^5-digit denominator", "certificate format",
      "gap_points[0]", setp(["gap_points"], ["1/1" + "0" * 100000]))
forge("multiplicity-1000", "2d", "multiplicity 1000 on a factor", "certificate format",
      "projection.square_free_factors[0].multiplicity", setp(["projection", "square_free_factors", 0, "multiplicity"], 1000))
forge("bracket-exponent-bomb", "2d", "a bracket end written 1e-10000 style with a huge exponent", "certificate format",
      f"timeline[{k2}].instant.lo", setp(["timeline", k2, "instant", "lo"], "4e-99999"))
# An older format (no checked approx, no continuous touching) is refused, not misread.
forge("format-1", "2d", "a format-1 certificate", "certificate format", "format: expected \"eccd-certificate/2\"",
      setp(["format"], "eccd-certificate/1"))
# Item 7: continuous touching must be in the answer and cannot be called an overlap.
forge("rolling-2d-contact-interval-dropped", "rolling2d", "circles rolling in contact, contact_intervals dropped",
      "answer", "continuous touch off as an overlap", lambda c: c["answer"].pop("contact_intervals"))
forge("rolling-2d-status-overlapping", "rolling2d", "circles rolling in contact, claimed overlapping",
      "continuous touching", "gives touching, not overlapping", setp(["continuous_touching", "status"], "overlapping"))
forge("rolling-3d-contact-interval-dropped", "rolling3d", "spheres rolling in contact, contact_intervals dropped",
      "answer", "continuous touch off as an overlap", lambda c: c["answer"].pop("contact_intervals"))

with open(os.path.join(HERE, "forgeries.json"), "w") as f:
    f.write(json.dumps({"note": "written by make_forgeries.py; checked by tests/certificate/test_certificate_forgeries.cpp",
                        "valid": [{"file": f"valid-{k}.cert.json", "scene": v} for k, v in BASES.items()],
                        "forgeries": manifest}, indent=1) + "\n")
print(len(manifest), "forgeries written")
