#pragma once
// Scaling by powers of two, and finiteness, in the floating arithmetics.
//
// Statement. A careful floating implementation keeps its numbers near 1 in
// size: multiplying a polynomial, a matrix or the pencil λA - B by 2^k is
// exact in binary floating point (ldexp, mpfr_mul_2si; no rounding unless the
// result leaves the exponent range) and changes no root and no sign that the
// pipelines decide from (A(t) -> 2^k A(t) and f -> 2^k f leave the roots of
// f(λ;t) and of Δ(t) where they are; B -> 2^k B scales every root λ by 2^k,
// which keeps its sign). Each stage of a floating pipeline (shape matrix,
// motion inverse N(t), A(t) and B(t), f's coefficients g_k, Δ or F(u,t))
// scales its own values so that the largest has binary exponent 0; a value
// that is NaN or ±Inf at any stage makes the stage report it (the pipeline
// then answers "undecided" with the reason, never a guess). No paper section:
// termination and honesty are what a floating implementation owes its caller.
// Requirements on T: double or Mpfr (overloads below); exact arithmetics
// never call this.
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"

#include <climits>
#include <cmath>
#include <mpfr.h>
#include <vector>

namespace eccd {

inline bool is_finite_value(double x) { return std::isfinite(x); }
inline bool is_finite_value(const Mpfr& x) { return mpfr_number_p(x.get()) != 0; }

// e with 2^(e-1) <= |x| < 2^e; LONG_MIN for 0 (and for a non-finite x).
inline long binary_exponent(double x) {
  if (x == 0 || !std::isfinite(x)) return LONG_MIN;
  int e = 0;
  std::frexp(x, &e);
  return e;
}
inline long binary_exponent(const Mpfr& x) {
  if (!mpfr_regular_p(x.get())) return LONG_MIN;
  return long(mpfr_get_exp(x.get()));
}

// x * 2^k (exact unless it leaves the exponent range).
inline double times_pow2(double x, long k) {
  if (k > 4000) k = 4000;
  if (k < -4000) k = -4000;
  return std::ldexp(x, int(k));
}
inline Mpfr times_pow2(const Mpfr& x, long k) {
  Mpfr r(x);
  mpfr_mul_2si(r.get(), r.get(), k, MPFR_RNDN);
  return r;
}

// Scales every value visited by `each` (each(f) calls f(T&) on every value)
// by one power of two, so that the largest has binary exponent 0. Returns
// false (and scales nothing) if a value is not finite.
template <class T, class Each>
bool normalise_pow2(Each each) {
  bool finite = true;
  long top = LONG_MIN;
  each([&](T& x) {
    if (!is_finite_value(x)) finite = false;
    long e = binary_exponent(x);
    if (e > top) top = e;
  });
  if (!finite) return false;
  if (top == LONG_MIN || top == 0) return true;
  each([&](T& x) { x = times_pow2(x, -top); });
  return true;
}

template <class T>
bool all_finite(const std::vector<T>& xs) {
  for (const auto& x : xs)
    if (!is_finite_value(x)) return false;
  return true;
}

}  // namespace eccd
