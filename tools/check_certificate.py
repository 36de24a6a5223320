#!/usr/bin/env python3
"""check_certificate.py SCENE CERT: a second, independent checker of eccd's
exact certificates ("eccd-certificate/2", 2D and 3D), in Python with the
standard library only (fractions, json). It shares no code with eccd: an
auditor reads it in an hour (docs/checking.md).

Exit 0 VALID, 1 REJECTED (the claim and why), 2 unreadable input or a format
it does not cover.

What it proves, in order (the claim names of eccd-check):
  scene       the certificate's dim, a, b are the scene file's; det M(t) has
              no root in [0, 1] (Sturm) for either object;
  f           g_k = alpha^k beta^(H-k) h_k (alpha, beta > 0), h the
              coefficients of det(lambda A(t) - B(t)), A = N^T Q N with N the
              adjugate of M (interpolated at integers) over the gcd of its
              entries: the roots lambda are those of the scene up to a
              positive factor; checked at deg + 1 points;
  projection  the candidates listed vanish identically and P is a constant
              multiple of the named one (2D: the cubic's discriminant; 3D:
              P * g_4 against psc_0 = Res(f, f'), or psc_k), at deg + 1 points;
  factors     prod F_i^m_i is a constant multiple of P (at deg + 1 points);
  timeline    instant, cell, ..., instant from [0, 0] to [1, 1], in order;
  brackets    Descartes' rule: one root of its factor, none of the others;
  gaps        every piece between brackets and gap points: Descartes 0;
  cells       the static test: f(lambda; t) has >= 2 distinct negative
              roots (separate), else a negative multiple root (touching),
              else overlapping (Sturm sequences);
  instants    rational: the static test; irrational: the evidence signs
              proved on the bracket (Descartes 0 and the sign at lo, or a
              common factor with its one root there), then 003 Theorem 6
              (2D) or the subresultant touch rule (3D);
  answer      assembled here from the checked timeline, equal to the
              certificate's (brackets exactly, approx inside its bracket).

The code is the package certificate_checker/ beside this script, one module
per step: errors, inputs (strict JSON and numbers), polynomials, matrices,
scene, algebra (scene, f, projection, factors), timeline (timeline,
brackets, gaps), instants (cells, instants), answer, continuous (2D
continuous touching), check (the claims in order) and cli.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from certificate_checker.check import check  # noqa: E402  (the claims, for callers that import this file)
from certificate_checker.cli import check_index, main  # noqa: E402

__all__ = ["check", "check_index", "main"]

if __name__ == "__main__":
    sys.exit(main(sys.argv))
