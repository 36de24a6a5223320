#pragma once
// rational_convolution: the product of two polynomials with rational
// coefficients (coefficient lists, low to high) over common denominators:
// one integer convolution instead of a rational multiply and a rational add
// (each with its gcds) per pair of coefficients (the exact
// preparation of a scene, kernel/prepared_scene.hpp, and the exact pipeline
// spend their polynomial products here).
//
// Statement. With L_a, L_b the lcms of the denominators of a and b,
// A_i = L_a a_i and B_j = L_b b_j are integers, and
//   (a·b)_k = Σ_{i+j=k} a_i b_j = (Σ_{i+j=k} A_i B_j) / (L_a L_b),
// an identity of rationals; mpq_class canonicalises the quotient, so the
// result is the same rational, in the same canonical form, as the
// coefficient-by-coefficient product. Trailing zero coefficients are the
// caller's to trim, as in the coefficient-by-coefficient product.
// Requirements: mpq_class coefficients (GMP, canonical), both lists non-empty.
#include <gmpxx.h>

#include <algorithm>
#include <vector>

namespace eccd {

// Empty when a common denominator would be much longer than the longest
// single one (many unrelated denominators: the integers would grow by their
// number); the caller then multiplies coefficient by coefficient.
inline std::vector<mpq_class> rational_convolution(const std::vector<mpq_class>& a, const std::vector<mpq_class>& b) {
  bool too_long = false;
  auto scaled = [&too_long](const std::vector<mpq_class>& x, mpz_class& l) {
    l = 1;
    std::size_t longest = 0;
    for (const auto& c : x) {
      mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
      longest = std::max(longest, mpz_sizeinbase(c.get_den_mpz_t(), 2));
    }
    if (mpz_sizeinbase(l.get_mpz_t(), 2) > 2 * longest + 64) {
      too_long = true;
      return std::vector<mpz_class>();
    }
    std::vector<mpz_class> r(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (mpz_cmp_ui(x[i].get_den_mpz_t(), 1) == 0)
        r[i] = x[i].get_num() * l;
      else {
        mpz_divexact(r[i].get_mpz_t(), l.get_mpz_t(), x[i].get_den_mpz_t());
        r[i] *= x[i].get_num();
      }
    }
    return r;
  };
  mpz_class la, lb;
  const std::vector<mpz_class> A = scaled(a, la), B = scaled(b, lb);
  if (too_long) return {};
  std::vector<mpz_class> s(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < A.size(); ++i) {
    if (A[i] == 0) continue;
    for (std::size_t j = 0; j < B.size(); ++j) mpz_addmul(s[i + j].get_mpz_t(), A[i].get_mpz_t(), B[j].get_mpz_t());
  }
  const mpz_class den = la * lb;
  std::vector<mpq_class> r(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    mpq_set_num(r[k].get_mpq_t(), s[k].get_mpz_t());
    mpq_set_den(r[k].get_mpq_t(), den.get_mpz_t());
    r[k].canonicalize();
  }
  return r;
}

}  // namespace eccd
