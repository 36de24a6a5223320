#pragma once
// Eigen with the workbench's floating scalars: fixed-size Eigen matrices of
// double or Mpfr (Eigen is the home of the floating linear
// algebra of the separating planes and contact points).
//
// Statement. Eigen needs a NumTraits specialisation for a custom scalar type
// ("Using custom scalar types", Eigen documentation); Mpfr
// (number/mpfr_real.hpp) carries its precision per value, so Eigen's
// Scalar(0) and Scalar(1) are Mpfr constants of kConstBits bits that take the
// precision of the other operand (number/mpfr_real.hpp). Only the operations
// that need no epsilon are used with Mpfr: products, transposes, blocks and
// the closed-form determinants of fixed sizes up to 4 (no pivoting
// decompositions, whose thresholds would be double's). The helper sqrt_of is
// the square root the constructions need, in T (double: std::sqrt; Mpfr:
// mpfr_sqrt at the operand's precision).
// Requirements on T: double or Mpfr.
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <cmath>

namespace Eigen {
template <>
struct NumTraits<eccd::Mpfr> : GenericNumTraits<eccd::Mpfr> {
  using Real = eccd::Mpfr;
  using NonInteger = eccd::Mpfr;
  using Nested = eccd::Mpfr;
  using Literal = eccd::Mpfr;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 10,
    AddCost = 10,
    MulCost = 40
  };
};
}  // namespace Eigen

namespace eccd {

template <class T, int R, int C = R>
using EMatrix = Eigen::Matrix<T, R, C>;
template <class T, int R>
using EVector = Eigen::Matrix<T, R, 1>;

inline double sqrt_of(const double& x) { return std::sqrt(x); }
inline Mpfr sqrt_of(const Mpfr& x) {
  Mpfr r = x;
  mpfr_sqrt(r.get(), x.get(), MPFR_RNDN);
  return r;
}
inline double abs_of(const double& x) { return std::fabs(x); }
inline Mpfr abs_of(const Mpfr& x) { return scalar_traits<Mpfr>::abs(x); }

}  // namespace eccd
