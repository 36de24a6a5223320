#pragma once
// Binomial coefficients C(n, k) as values of the scalar type T.
//
// Built by Pascal's rule in T starting from a value `like` of the run's
// precision, so that an Mpfr row carries the run's precision and a rational
// row is exact. Used by the Bernstein conversions (Farouki and Rajan 1987,
// cited by 003 section VI-C as [25]).
// Cost. The rows are cached: each thread keeps, per T and per precision of
// `like` (scalar_traits<T>::precision; from_rational depends on nothing
// else), the rows 0, 1, ... of Pascal's triangle built so far, and extends
// them on demand. A row is built once (O(n) from the previous one) instead of
// O(n²) on every call. The cache only grows and its rows never move (a
// std::deque), so a returned reference stays valid for the thread's life,
// calls for different degrees and precisions may interleave freely, and
// threads share nothing. The values are those of the uncached Pascal rule.
// Requirements on T: +, construction from int. Rounded for n > 56 in double.
// Bounded<double> (the guard, number/running_error.hpp): an entry of at most
// 2^53 whose two parents are exact is exact (a sum of integers below 2^53),
// so it carries the bound 0 instead of the generic sum's u|C(n, k)| (issue
// 30 point 5: the guard's bounds as tight as the arithmetic allows).
#include "number/running_error.hpp"
#include "number/scalar_traits.hpp"

#include <deque>
#include <map>
#include <stdexcept>
#include <vector>

namespace eccd {

// Row n of Pascal's triangle, C(n, 0..n), at like's precision.
template <class T>
const std::vector<T>& binomial_row(int n, const T& like) {
  if (n < 0) throw std::invalid_argument("binomial_row: negative degree");
  thread_local std::map<int, std::deque<std::vector<T>>> cache;  // precision -> rows 0, 1, ...
  std::deque<std::vector<T>>& rows = cache[scalar_traits<T>::precision(like)];
  if (rows.empty()) rows.emplace_back(1, scalar_traits<T>::from_rational(mpq_class(1), like));
  while (int(rows.size()) <= n) {
    const std::vector<T>& row = rows.back();
    const int m = int(row.size());
    std::vector<T> next(m + 1, row[0]);  // row[0] is the run's one
    for (int k = 1; k < m; ++k) {
      next[k] = row[k - 1] + row[k];
      if constexpr (std::is_same_v<T, Bounded<double>>)
        if (row[k - 1].bound() == 0 && row[k].bound() == 0 && next[k].value() <= 0x1p53)
          next[k] = T(next[k].value(), 0);
    }
    rows.push_back(std::move(next));
  }
  return rows[n];
}

}  // namespace eccd
