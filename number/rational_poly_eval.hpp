#pragma once
// The exact value of a rational polynomial at a rational point by Horner's
// scheme over the integers, with one reduction to lowest terms at the end
// (Horner in mpq arithmetic reduces every partial sum by a gcd of
// numbers that grow to n times the point's size).
//
// Statement. For p(t) = Σ c_i t^i with c_i = C_i / d (d the lcm of the
// denominators, C_i integers) and t = u / v in lowest terms (v > 0),
//   p(u/v) = (Σ C_i u^i v^(n-i)) / (d v^n),
// and the numerator is Horner's scheme s_n = C_n, s_i = s_(i+1) u + C_i v^(n-i).
// The quotient is put in lowest terms once: the same mpq value (and, GMP
// rationals being canonical, the same representation) as Horner in mpq.
// Requirements: GMP (mpq_class in lowest terms); c non-empty.
#include <gmpxx.h>

#include <vector>

namespace eccd {

inline mpq_class rational_poly_eval(const std::vector<mpq_class>& c, const mpq_class& t) {
  const int n = int(c.size()) - 1;
  mpz_class d = 1;
  for (const auto& x : c)
    if (mpz_cmp_ui(x.get_den_mpz_t(), 1) != 0) mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), x.get_den_mpz_t());
  const bool int_coeffs = d == 1;
  const bool int_point = mpz_cmp_ui(t.get_den_mpz_t(), 1) == 0;
  mpz_class s, vp = 1, term;
  auto coeff = [&](int i, mpz_class& out) {  // C_i
    if (int_coeffs) {
      mpz_set(out.get_mpz_t(), c[i].get_num_mpz_t());
      return;
    }
    mpz_divexact(out.get_mpz_t(), d.get_mpz_t(), c[i].get_den_mpz_t());
    mpz_mul(out.get_mpz_t(), out.get_mpz_t(), c[i].get_num_mpz_t());
  };
  coeff(n, s);
  for (int i = n - 1; i >= 0; --i) {
    mpz_mul(s.get_mpz_t(), s.get_mpz_t(), t.get_num_mpz_t());
    if (mpz_sgn(c[i].get_num_mpz_t()) == 0) {
      if (!int_point) mpz_mul(vp.get_mpz_t(), vp.get_mpz_t(), t.get_den_mpz_t());
      continue;
    }
    coeff(i, term);
    if (!int_point) {
      mpz_mul(vp.get_mpz_t(), vp.get_mpz_t(), t.get_den_mpz_t());
      mpz_mul(term.get_mpz_t(), term.get_mpz_t(), vp.get_mpz_t());
    }
    mpz_add(s.get_mpz_t(), s.get_mpz_t(), term.get_mpz_t());
  }
  mpq_class r;
  mpz_swap(r.get_num_mpz_t(), s.get_mpz_t());
  if (!int_point) mpz_mul(d.get_mpz_t(), d.get_mpz_t(), vp.get_mpz_t());
  if (d != 1) {
    mpz_swap(r.get_den_mpz_t(), d.get_mpz_t());
    r.canonicalize();
  }
  return r;
}

}  // namespace eccd
