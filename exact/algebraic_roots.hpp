#pragma once
// Certified real roots of a rational polynomial, and exact signs of other
// polynomials at them.
//
// Statement. The exact pipeline must place every critical instant t0 (a real
// root of Δ(t) or of a projection polynomial: a real algebraic number) in a
// rational bracket that provably holds it and no other root, and must decide
// signs of polynomials at t0 exactly, never by evaluating near t0 in floating
// point (docs/architecture.md, "Exact at a critical instant"). Isolation of
// every real root (Descartes' method) is CGAL's Algebraic_kernel_d_1 over CORE::BigInt (CORE ships inside CGAL's
// headers; measured 1.5-4x faster than the kernel over CGAL::Gmpz with MPFI on the workbench's polynomials).
// On [0, 1] (what the pipelines ask for) only the roots there are isolated, by Descartes' bisection of (0, 1) in GMP
// integers, after a modular certificate that the polynomial is square-free (else after FLINT's square-free
// factorisation, exact/flint_poly.hpp, which also does the gcds); other ranges use CGAL's isolation of every
// real root. What follows isolation is done in exact/algebraic_roots.cpp on the isolating intervals, with integers
// only: refinement by quadratic interval refinement (Abbott, "Quadratic interval refinement for real roots", 2006;
// exact signs of the square-free factor at dyadic points), exact comparison with the ends of the range, and signs at a
// root (a Taylor bound at the bracket's midpoint proves the sign constant on
// the bracket; when it cannot, gcd with the factor: zero iff the gcd changes
// sign over the bracket; else refinement until the bound decides).
// Only exact/algebraic_roots.cpp includes CGAL.
// Requirements: polynomials with exact rational coefficients (mpq_class); they
// are scaled to primitive integer polynomials (a positive factor).
// Guarantees of real_roots(): every real root of p in [a, b] is listed once,
// in increasing order, with its multiplicity; brackets are pairwise disjoint,
// each holds exactly one real root of p (and of its square-free factor, which
// does not vanish at non-degenerate bracket ends), has width <= 2^-bits, and
// is [r, r] when the root is found to be the rational r (a root at a or b, a
// dyadic grid point hit by refinement, or the simplest rational in the
// bracket).
// Brackets are dyadic; refine() and sign_at() accept any other bracket
// lo < hi of the root (not only those real_roots() made) that isolates it for
// its square-free factor: the factor has no other root in [lo, hi] and does
// not vanish at lo and hi.
#include "number/rational_traits.hpp"
#include "kernel/polynomial.hpp"

#include <memory>
#include <vector>

namespace eccd {

struct AlgebraicRootImpl;  // the root's square-free factor (integer coefficients, and as CGAL's polynomial)

struct AlgebraicRoot {
  Rational lo, hi;
  int multiplicity = 1;
  std::shared_ptr<const AlgebraicRootImpl> impl;  // may be null for a rational root
  bool is_rational() const { return lo == hi; }
};

std::vector<AlgebraicRoot> real_roots(const Poly<Rational>& p, const Rational& a, const Rational& b, int bits = 64);
// The exact sign of q at the algebraic number r.
Sign sign_at(const Poly<Rational>& q, const AlgebraicRoot& r);
// Shrinks r's bracket to width <= 2^-bits (it stays a bracket of the same root).
void refine(AlgebraicRoot& r, int bits);

// Square-free factorisation p = c · F_1^m_1 · ... · F_s^m_s (c a rational
// constant, m_1 < ... < m_s, the F_i square-free and pairwise coprime, each a
// primitive integer polynomial with positive leading coefficient). A root of p
// of multiplicity m is a simple root of the F_i with m_i = m.
std::vector<std::pair<Poly<Rational>, int>> square_free_factors(const Poly<Rational>& p);
// gcd(p, q) as a primitive integer polynomial with positive leading coefficient.
Poly<Rational> polynomial_gcd(const Poly<Rational>& p, const Poly<Rational>& q);
// The same two by CGAL's modular gcd (FLINT computes them in the pipelines,
// exact/flint_poly.hpp), kept as the reference the tests compare them with.
std::vector<std::pair<Poly<Rational>, int>> square_free_factors_cgal(const Poly<Rational>& p);
Poly<Rational> polynomial_gcd_cgal(const Poly<Rational>& p, const Poly<Rational>& q);

}  // namespace eccd
