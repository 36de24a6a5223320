#!/usr/bin/env python3
"""Writes paper 003's Example 2 and its shifted variants as scene files.

003 section VI-C, Example 2: two elliptic disks x^2/5^2 + y^2/10^2 <= 1 under the
quartic rational motions M_A, M_B printed in the paper. The text extraction
garbled the layout; rebuilt here so that
  - the upper-left block over w is a rotation for every t (a^2 + b^2 = w^2,
    a = -16t^4+32t^3-16t+4, b = 32t^3-48t^2+16t, w = 16t^4-32t^3+32t^2-16t+4),
  - the first-row translation entry of M_A is 160t^3-240t^2+160t-40 (as in M_B):
    the printed "-160t^3-240t^2+160t-40" puts A's centre at x = -40 at t = 1/2,
    where the disks do not touch; the reading used here makes them touch at
    t = 1/2 at the origin, and reproduces the printed lambda^2 coefficient of f
    (-135168 t^24 + 1622016 t^23 - 11304960 t^22 ... - 13) up to the factor
    625/1024, while the other reading that touches (-160t^3+240t^2-160t+40)
    does not.
The variants shift disk B (the lower disk) by d along y: "away" (towards -y,
near misses with minimum separation d at t = 1/2) and "towards" (short
overlaps), d = 1e-3, 1e-6, 1e-9, 1e-12, 1e-15: y_B(t) -> y_B(t) -/+ d w(t).
Numbers are written as exact decimal strings (scene-format.md).
Run from anywhere; then `eccd solve FILE --arith exact --write-answer` stores
the exact answers.
"""
from fractions import Fraction as F
import os as _os
import sys as _sys
_sys.path.insert(0, _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), ".."))
from scenelib import num as dec, write as write_in  # noqa: E402


def write(s):
    write_in(s, _os.path.dirname(_os.path.abspath(__file__)))


a = [4, -16, 0, 32, -16]
b = [0, 16, -48, 32]
nb = [-x for x in b]
x = [-40, 160, -240, 160]
yA = [80, -400, 880, -960, 480]
yB = [-80, 400, -880, 960, -480]
w = [4, -16, 32, -32, 16]


def poly(c):
    return [dec(v) for v in c]


def scene(name, yb, note):
    shape = {"semi_axes": ["5", "10"]}
    return {
        "format": "ellipse-ccd-scene/1",
        "name": name,
        "dim": 2,
        "a": {"shape": shape, "motion": {"type": "matrix", "m": [[poly(a), poly(nb), poly(x)], [poly(b), poly(a), poly(yA)], ["0", "0", poly(w)]]}},
        "b": {"shape": shape, "motion": {"type": "matrix", "m": [[poly(a), poly(b), poly(x)], [poly(nb), poly(a), poly(yb)], ["0", "0", poly(w)]]}},
        "note": note,
    }


src = "Source: paper 003 (Choi, Wang, Liu, Kim, IEEE T-RO 2006), section VI-C, Example 2; matrices rebuilt as explained in cases/paper003/make_example2.py."
write(scene("example2", yB, src + " The disks touch externally at t = 1/2 and are separate at every other instant."))
for e in (3, 6, 9, 12, 15):
    d = F(1, 10**e)
    away = [F(v) - d * wv for v, wv in zip(yB, w)]
    toward = [F(v) + d * wv for v, wv in zip(yB, w)]
    write(scene(f"example2-away-1e-{e}", away, src + f" Disk B shifted by d = 1e-{e} along -y (away from A): a near miss, separated by d at t = 1/2."))
    write(scene(f"example2-towards-1e-{e}", toward, src + f" Disk B shifted by d = 1e-{e} along +y (towards A): a short overlap around t = 1/2."))
