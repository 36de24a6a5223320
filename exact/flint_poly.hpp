#pragma once
// Square-free factorisation and gcd of integer polynomials by FLINT.
//
// Statement. For a non-zero integer polynomial z (lowest degree first),
// flint_square_free_factors(z) returns the square-free factorisation
// z = c · F_1^m_1 · ... · F_s^m_s (c an integer constant, 1 <= m_1 < ... <
// m_s, the F_i of degree >= 1, square-free, pairwise coprime, primitive with
// positive leading coefficient), and flint_gcd(a, b) the greatest common
// divisor of a and b as a primitive integer polynomial with positive leading
// coefficient (the constant 1 when they are coprime). Both are exact: FLINT
// (Debian libflint-dev, version 2.9) computes fmpz_poly_gcd by heuristic and
// multimodular gcds whose candidates are checked by exact division over Z
// (a proof, not a probability), and fmpz_poly_factor_squarefree is Yun's
// algorithm on those gcds. Measured: CGAL's modular gcd
// (Polynomial<Residue>::euclidean_division) took a fifth of the exact 2D and
// 3D pipelines; exact/algebraic_roots.cpp asks these instead
// (tests/exact/test_flint_poly.cpp compares them with CGAL's on every
// polynomial of cases/).
// FlintQPoly: a rational polynomial in FLINT's fmpq_poly (one integer
// polynomial over one common denominator, canonical: the numerator's content
// is coprime with the denominator), a ring as kernel/ring_determinant.hpp and
// the formulas of kernel/discriminant.hpp and kernel/subresultants.hpp need it
// (+, -, *, int *, is_zero). Exact: it converts back to the very Poly<Rational>
// the same formula gives in Poly<Rational> (GMP's rationals are canonical too),
// so ExactPolicy (exact/cd_disc_exact.hpp) builds Δ, the projection and
// s(j,i) in it (in Poly<Rational> those builds take a third of paper 002's exact run).
// Only exact/flint_poly.cpp includes FLINT (its headers define macros such as
// `ulong`); this header uses GMP's C++ numbers and an opaque handle only.
// Requirements: integer coefficients (mpz_class) with the leading one non-zero
// for the two functions; any Poly<Rational> for FlintQPoly.
#include "number/rational_traits.hpp"
#include "kernel/polynomial.hpp"

#include <gmpxx.h>

#include <memory>

#include <utility>
#include <vector>

namespace eccd {

std::vector<std::pair<std::vector<mpz_class>, int>> flint_square_free_factors(const std::vector<mpz_class>& z);
std::vector<mpz_class> flint_gcd(const std::vector<mpz_class>& a, const std::vector<mpz_class>& b);

struct FlintQPolyImpl;  // holds an fmpq_poly_t (exact/flint_poly.cpp)

class FlintQPoly {
 public:
  FlintQPoly();
  explicit FlintQPoly(const Poly<Rational>& p);
  FlintQPoly(const FlintQPoly& o);
  FlintQPoly(FlintQPoly&& o) noexcept;
  FlintQPoly& operator=(const FlintQPoly& o);
  FlintQPoly& operator=(FlintQPoly&& o) noexcept;
  ~FlintQPoly();
  Poly<Rational> to_poly() const;
  bool is_zero() const;
  friend FlintQPoly operator+(const FlintQPoly& a, const FlintQPoly& b);
  friend FlintQPoly operator-(const FlintQPoly& a, const FlintQPoly& b);
  friend FlintQPoly operator*(const FlintQPoly& a, const FlintQPoly& b);
  friend FlintQPoly operator*(long k, const FlintQPoly& a);

 private:
  std::unique_ptr<FlintQPolyImpl> p_;
};

}  // namespace eccd
