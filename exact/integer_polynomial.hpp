#pragma once
// The primitive integer multiple of a rational polynomial.
//
// Statement. For p with rational coefficients c_i = n_i / d_i, let l be the
// lcm of the d_i and g the gcd of the l·c_i: the integers l·c_i / g are
// coprime and define a positive rational multiple of p, with the same roots
// and the same signs everywhere. Root isolation (exact/algebraic_roots.cpp),
// Descartes' rule (exact/descartes.hpp) and the certificate's written
// polynomials (exact/certificate_algebra.hpp) all work on it.
// Requirements: exact rationals (mpq_class in lowest terms, as GMP keeps them).
#include "number/rational_traits.hpp"
#include "kernel/polynomial.hpp"

#include <vector>

namespace eccd {

// Lowest degree first; all zero (and no division) for the zero polynomial.
inline std::vector<mpz_class> primitive_integer_multiple(const Poly<Rational>& p) {
  mpz_class l = 1;
  for (const auto& c : p.c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  std::vector<mpz_class> z(p.c.size());
  mpz_class g = 0, t;
  for (std::size_t i = 0; i < p.c.size(); ++i) {
    mpz_divexact(t.get_mpz_t(), l.get_mpz_t(), p.c[i].get_den_mpz_t());
    mpz_mul(z[i].get_mpz_t(), p.c[i].get_num_mpz_t(), t.get_mpz_t());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), z[i].get_mpz_t());
  }
  if (g > 1)
    for (auto& x : z) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
  return z;
}

}  // namespace eccd
