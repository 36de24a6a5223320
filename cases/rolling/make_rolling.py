#!/usr/bin/env python3
"""Writes two scenes of continuous touching: one object rolls around another,
in external contact at every instant of [0, 1] (docs/answer-format.md,
`contact_intervals`).

circles-rolling (dim 2): unit circles; A static at the origin; B's centre on
  the circle of radius 2 around A, c_B(t) = 2 ((1 - t^2), 2t) / (1 + t^2)
  (a quarter turn, t = tan(theta/2)), and B turning with it: the "matrix"
  motion M(t) = [[1 - t^2, -2t, 2(1 - t^2)], [2t, 1 - t^2, 4t], [0, 0, 1 + t^2]]
  (homogeneous, w = 1 + t^2 > 0; the upper-left block has det (1 + t^2)^2).
  |c_B| = 2 = r_A + r_B at every t: the disks touch externally all the time,
  so the discriminant of f(lambda; t) vanishes identically (a negative double
  root at every t, 003 Theorem 6 and Corollary 7) and the status never
  changes. Exact answer: C = [0, 1], collides, first contact 0, no isolated
  external contacts, contact_intervals [[0, 1]].
spheres-rolling (dim 3): unit balls; A static at the origin; B an "euler"
  motion with e = (1, 0, 0, t) (rotation about z by 2 atan t) and translation
  (2(1 - t^2), 4t, 0) / (1 + t^2): the same rolling in the plane z = 0. The
  quartic's discriminant vanishes identically (two balls always give a double
  root, cases/spheres/make_spheres.py) and so does psc_1; the projection is
  psc_2 = (1 + t^2)^4 with no root in [0, 1], one touching cell. Exact answer
  as above.

Run from anywhere; the files are written next to this script. Then
`eccd solve FILE --arith exact --write-answer` stores the exact answers.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from scenelib import write  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
NOTE = ("Continuous touching, written by cases/rolling/make_rolling.py: B rolls a quarter turn around A, "
        "centre distance 2 = r_A + r_B at every t. C = [0, 1], no isolated contacts, contact interval [0, 1].")

circles = {
    "format": "ellipse-ccd-scene/1",
    "name": "circles-rolling",
    "dim": 2,
    "a": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "static"}},
    "b": {"shape": {"semi_axes": ["1", "1"]},
          "motion": {"type": "matrix", "m": [[["1", "0", "-1"], ["0", "-2"], ["2", "0", "-2"]],
                                             [["0", "2"], ["1", "0", "-1"], ["0", "4"]],
                                             ["0", "0", ["1", "0", "1"]]]}},
    "note": NOTE,
}
spheres = {
    "format": "ellipse-ccd-scene/1",
    "name": "spheres-rolling",
    "dim": 3,
    "a": {"shape": {"semi_axes": ["1", "1", "1"]}, "motion": {"type": "static"}},
    "b": {"shape": {"semi_axes": ["1", "1", "1"]},
          "motion": {"type": "euler", "e": ["1", "0", "0", ["0", "1"]],
                     "translation": [["2", "0", "-2"], ["0", "4"], "0"], "translation_denominator": ["1", "0", "1"]}},
    "note": NOTE,
}
for s in (circles, spheres):
    write(s, HERE)
    print("wrote", os.path.join(HERE, s["name"] + ".json"))
