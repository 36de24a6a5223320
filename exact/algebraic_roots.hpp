#pragma once
// Certified real roots of a rational polynomial, and exact signs of other
// polynomials at them.
//
// Statement. The exact pipeline must place every critical instant t0 (a real
// root of Δ(t) or of a projection polynomial: a real algebraic number) in a
// rational bracket that provably holds it and no other root, and must decide
// signs of polynomials at t0 exactly, never by evaluating near t0 in floating
// point (design.md, "Mathematics the code must get right"). Both are done by
// CGAL's Algebraic_kernel_d_1 over GMP integers (square-free factorisation by
// modular gcd, isolation by the Bitstream Descartes method, signs at algebraic
// numbers by gcd and refinement), behind this small interface so that only
// exact/algebraic_roots.cpp includes CGAL.
// Requirements: polynomials with exact rational coefficients (mpq_class); they
// are scaled to primitive integer polynomials (a positive factor).
// Guarantees of real_roots(): every real root of p in [a, b] is listed once,
// in increasing order, with its multiplicity; brackets are pairwise disjoint,
// each holds exactly one real root of p, has width <= 2^-bits, and is [r, r]
// when CGAL has found the root to be rational r.
#include "exact/rational_traits.hpp"
#include "kernel/polynomial.hpp"

#include <memory>
#include <vector>

namespace eccd {

struct AlgebraicRootImpl;  // holds CGAL's Algebraic_real_1

struct AlgebraicRoot {
  Rational lo, hi;
  int multiplicity = 1;
  std::shared_ptr<const AlgebraicRootImpl> impl;
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

}  // namespace eccd
