#pragma once
// Binomial coefficients C(n, k) as values of the scalar type T.
//
// Built by Pascal's rule in T starting from a value `like` of the run's
// precision, so that an Mpfr row carries the run's precision and a rational
// row is exact. Used by the Bernstein conversions (Farouki and Rajan 1987,
// cited by 003 section VI-C as [25]).
// Requirements on T: +, construction from int. Rounded for n > 56 in double.
#include "kernel/scalar_traits.hpp"

#include <vector>

namespace eccd {

template <class T>
std::vector<T> binomial_row(int n, const T& like) {
  T one = scalar_traits<T>::from_rational(mpq_class(1), like);
  std::vector<T> row(1, one);
  for (int m = 1; m <= n; ++m) {
    std::vector<T> next(m + 1, one);
    for (int k = 1; k < m; ++k) next[k] = row[k - 1] + row[k];
    row = std::move(next);
  }
  return row;
}

}  // namespace eccd
