#pragma once
// scalar_traits<T>: what the templated kernel needs to know about an arithmetic.
//
// Statement. Every stage of the workbench is a function template of the scalar type T. Seven types specialise
// scalar_traits: the point types `double` (number/double_traits.hpp), `Mpfr` with a per-value precision
// (number/mpfr_real.hpp) and exact GMP rationals `mpq_class` (number/rational_traits.hpp); the enclosures `Interval`
// (number/interval.hpp), `MpfiInterval` (number/mpfi_interval.hpp), `Bounded<T>` (number/running_error.hpp) and
// `ForwardBound` (number/forward_bound.hpp). Code branches only where the mathematics differs, on `is_exact`.
//
// Each specialisation provides
//   static constexpr bool is_exact;
//   static Sign   sign(const T&);                 // exact sign of the value held
//   static double to_double(const T&);            // display and reporting only
//   static T      from_rational(const mpq_class&, const T& like); // rounded to like's precision
//   static T      abs(const T&);
//   static int    precision(const T&);            // bits of mantissa; 0 = exact
//   static std::string to_string(const T&);       // p/q for exact, decimal otherwise
//
// Signs are three-valued where the arithmetic is rounded: a floating pipeline
// that can bound its error may return Sign::uncertain; nothing turns
// "uncertain" into a sign silently (docs/architecture.md, "Uncertain is a fourth sign").
//
// Requirements on T: a commutative ring with +, -, *, unary -, comparison with
// T, construction from small int (T(3)); division only where a header says so.
#include <gmpxx.h>
#include <string>

namespace eccd {

enum class Sign { negative = -1, zero = 0, positive = 1, uncertain = 2 };

inline Sign sign_of_int(long v) { return v < 0 ? Sign::negative : (v > 0 ? Sign::positive : Sign::zero); }
inline Sign operator*(Sign a, Sign b) {
  if (a == Sign::uncertain || b == Sign::uncertain) return Sign::uncertain;
  return sign_of_int(long(a) * long(b));
}
inline const char* to_string(Sign s) {
  switch (s) {
    case Sign::negative:
      return "negative";
    case Sign::zero:
      return "zero";
    case Sign::positive:
      return "positive";
    default:
      return "uncertain";
  }
}

template <class T>
struct scalar_traits;  // specialised per arithmetic

template <class T>
inline Sign sign(const T& x) {
  return scalar_traits<T>::sign(x);
}
template <class T>
inline double to_double(const T& x) {
  return scalar_traits<T>::to_double(x);
}
template <class T>
inline bool is_zero(const T& x) {
  return scalar_traits<T>::sign(x) == Sign::zero;
}

}  // namespace eccd
