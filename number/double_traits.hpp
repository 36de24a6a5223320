#pragma once
// scalar_traits<double>: IEEE binary64, round to nearest.
//
// The fast arithmetic whose trustworthiness the workbench measures. Conversion
// from an exact rational rounds to nearest (via MPFR, so the rounding is
// correct, not the double of p divided by the double of q). Exception, with
// the same result: when p and q both have at most 53 bits they are exact
// doubles, and one IEEE division is correctly rounded (the quotient is
// normal, |p/q| > 2^-53), so small constants (1/2, k/N, 2^-e) skip MPFR.
// Known failure modes: everything the robustness report measures.
#include "number/scalar_traits.hpp"

#include <cmath>
#include <cstdio>
#include <mpfr.h>

namespace eccd {

template <>
struct scalar_traits<double> {
  static constexpr bool is_exact = false;
  static Sign sign(double x) {
    if (std::isnan(x)) return Sign::uncertain;
    return x < 0 ? Sign::negative : (x > 0 ? Sign::positive : Sign::zero);
  }
  static double to_double(double x) { return x; }
  static double from_rational(const mpq_class& q, double /*like*/ = 0.0) {
    mpz_srcptr num = mpq_numref(q.get_mpq_t()), den = mpq_denref(q.get_mpq_t());
    if (mpz_sizeinbase(num, 2) <= 53 && mpz_sizeinbase(den, 2) <= 53) return mpz_get_d(num) / mpz_get_d(den);
    mpfr_t r;
    mpfr_init2(r, 53);
    mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDN);
    double d = mpfr_get_d(r, MPFR_RNDN);
    mpfr_clear(r);
    return d;
  }
  static double abs(double x) { return std::fabs(x); }
  static int precision(double) { return 53; }
  static std::string to_string(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
  }
};

}  // namespace eccd
