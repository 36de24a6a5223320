#pragma once
// scalar_traits<mpq_class>: exact rationals (GMP), the workbench's ground truth.
//
// Every operation is exact; sign() is the true sign. to_double() exists for
// display and reports only and must never be used on the way to a decision.
// With gmpxx expression templates, never keep an arithmetic result in `auto`:
// write `mpq_class x = a * b;`.
#include "number/scalar_traits.hpp"

#include <mpfr.h>

namespace eccd {

using Rational = mpq_class;
using Integer = mpz_class;

template <>
struct scalar_traits<mpq_class> {
  static constexpr bool is_exact = true;
  static Sign sign(const mpq_class& x) { return sign_of_int(sgn(x)); }
  // Display only.
  static double to_double(const mpq_class& x) { return x.get_d(); }  // display only, never on the way to a decision
  static mpq_class from_rational(const mpq_class& q, const mpq_class& /*like*/ = mpq_class()) { return q; }
  static mpq_class abs(const mpq_class& x) { return mpq_class(::abs(x)); }
  static int precision(const mpq_class&) { return 0; }
  static std::string to_string(const mpq_class& x) { return x.get_str(); }
};

}  // namespace eccd
