#pragma once
// Descartes' rule of signs on an interval: a cheap, exact bound on the number
// of real roots of a rational polynomial in an open interval (a, b).
//
// Statement (Descartes' rule; e.g. Collins-Akritas 1976, Basu-Pollack-Roy ch.
// 10). Map (a, b) onto (0, ∞) by t = (a + b x) / (1 + x) and let
// V = the number of sign changes of the coefficients of
// (1 + x)^n p((a + b x) / (1 + x)). Then V - (number of roots of p in (a, b),
// counted with multiplicity) is even and >= 0. Hence
//   V = 0  =>  p has no root in (a, b);
//   V = 1  =>  p has exactly one root in (a, b), and it is simple.
// The prover-side self-check (certificate/write/prover_self_check.hpp) uses these two facts
// only; it never needs V to be exact in other cases. Unlike a Sturm sequence
// (kernel/sturm.hpp), the cost does not explode with the degree: it is two
// O(n²) passes over integers (n = deg p <= a few hundred for the projection
// polynomials of the workbench).
// Requirements: exact rationals; a < b.
#include "exact/integer_polynomial.hpp"
#include "number/rational_traits.hpp"
#include "kernel/polynomial.hpp"
#include "kernel/sign_variations.hpp"

#include <stdexcept>
#include <vector>

namespace eccd {

inline int descartes_variations(const Poly<Rational>& p, const Rational& a, const Rational& b) {
  if (!(a < b)) throw std::invalid_argument("descartes_variations: needs a < b");
  if (p.is_zero()) throw std::invalid_argument("descartes_variations: the zero polynomial");
  const int n = p.degree();
  if (n < 1) return 0;
  // Integer coefficients c_i (a positive multiple of p).
  const std::vector<mpz_class> c = primitive_integer_multiple(p);
  // a = A/d, b - a = W/d with a common denominator d.
  mpz_class d;
  mpz_lcm(d.get_mpz_t(), a.get_den_mpz_t(), b.get_den_mpz_t());
  mpz_class A = a.get_num() * (d / a.get_den());
  mpz_class B = b.get_num() * (d / b.get_den());
  mpz_class W = B - A;
  // H(y) = d^n p((A + W y) / d) by Horner: H = c_n; H = H·(A + W y) + c_i d^(n-i).
  std::vector<mpz_class> h{c[n]};
  mpz_class dp = 1;
  for (int i = n - 1; i >= 0; --i) {
    dp *= d;
    std::vector<mpz_class> next(h.size() + 1);
    for (std::size_t k = 0; k < h.size(); ++k) {
      next[k] += h[k] * A;
      next[k + 1] += h[k] * W;
    }
    next[0] += c[i] * dp;
    h.swap(next);
  }
  // R(x) = x^n H(1/x) (reversed), then R(x + 1) by Taylor shift; count sign changes.
  std::vector<mpz_class> r(h.rbegin(), h.rend());
  for (int i = 0; i < n; ++i)
    for (int k = n - 1; k >= i; --k) r[k] += r[k + 1];
  return sign_variations_n(r.size(), [&](std::size_t k) { return sign_of_int(sgn(r[k])); }).count;
}

}  // namespace eccd
