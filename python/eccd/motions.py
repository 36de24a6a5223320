"""Motions of the scene format (docs/scene-format.md, "Motion") as dicts, for eccd.Scene.from_motions.

A polynomial in t is a coefficient list in the power basis, lowest degree first ([1, 0.5] is 1 + t/2), a
single number (a constant), or bernstein([c0, ..., cn]). Numbers may be ints, floats (their shortest
round-trip decimal), Fractions or strings such as '1/3'; numpy arrays work as lists.
"""
from __future__ import annotations

from typing import Any, Optional, Sequence

__all__ = ["bernstein", "static", "matrix", "euler", "kinematic", "cycloidal"]


def bernstein(coefficients: Sequence[Any]) -> dict:
    """A polynomial by its Bernstein coefficients on [0, 1]."""
    return {"bernstein": list(coefficients)}


def static() -> dict:
    """M(t) = I."""
    return {"type": "static"}


def matrix(m: Sequence[Sequence[Any]]) -> dict:
    """M(t) entry by entry ((dim+1) x (dim+1) polynomials; last row 0, ..., 0, w(t))."""
    return {"type": "matrix", "m": [list(row) for row in m]}


def euler(e: Sequence[Any], translation: Sequence[Any], translation_denominator: Optional[Any] = None) -> dict:
    """3D: the rotation of the quaternion curve e(t) = (e0, e1, e2, e3), translation (v0, v1, v2) / v3."""
    d = {"type": "euler", "e": list(e), "translation": list(translation)}
    if translation_denominator is not None:
        d["translation_denominator"] = translation_denominator
    return d


def kinematic(d: Sequence[Any]) -> dict:
    """2D: the kinematic image curve (d0, d1, d2, d3)."""
    return {"type": "kinematic", "d": list(d)}


def cycloidal(angle_over_pi: Sequence[Any], translation: Sequence[Sequence[Any]]) -> dict:
    """2D, not rational: rotation by pi (theta0 + theta1 t), translation (x0 + x1 t, y0 + y1 t)."""
    return {"type": "cycloidal", "angle_over_pi": list(angle_over_pi), "translation": [list(r) for r in translation]}
