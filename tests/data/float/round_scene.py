#!/usr/bin/env python3
"""Rewrite every number of a scene file as a decimal string with DIGITS
significant digits (issue 14's reproducers: what a user's data looks like).

usage: round_scene.py IN.json OUT.json DIGITS [NAME]
Numbers are exact rationals "p/q" or decimals; each is rounded to nearest
with DIGITS significant digits (Python's Fraction + Decimal, exact), written as
a decimal string. The stored answer, if any, is dropped (it belonged to the
unrounded scene)."""
import json, sys
from fractions import Fraction
from decimal import Decimal, getcontext

getcontext().prec = 200

def rnd(s, digits):
    q = Fraction(s)
    if q == 0:
        return "0"
    d = Decimal(q.numerator) / Decimal(q.denominator)
    out = format(d, "." + str(digits - 1) + "e")  # DIGITS significant digits
    v = Decimal(out)
    t = format(v.normalize(), "f") if abs(v) >= Decimal("1e-6") else format(v.normalize(), "e")
    return t

def walk(x, digits, key=None):
    if isinstance(x, dict):
        return {k: (v if k in ("format", "name", "note", "type") else walk(v, digits, k)) for k, v in x.items() if k != "answer"}
    if isinstance(x, list):
        return [walk(v, digits, key) for v in x]
    if isinstance(x, str):
        return rnd(x, digits)
    if isinstance(x, int):
        return x if key == "dim" else rnd(str(x), digits)
    return x

src, dst, digits = sys.argv[1], sys.argv[2], int(sys.argv[3])
scene = json.load(open(src))
out = walk(scene, digits)
out["dim"] = scene["dim"]
if len(sys.argv) > 4:
    out["name"] = sys.argv[4]
out["note"] = "every number of %s rounded to %d significant digits (tests/data/float/round_scene.py)" % (scene.get("name", src), digits)
json.dump(out, open(dst, "w"), indent=1)
