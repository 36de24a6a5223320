#pragma once
// Test support: the determinant by Leibniz's formula, the sum over the n!
// permutations of signed products, as the tests' reference for the library's
// eliminations and expansions (kernel/ring_determinant.hpp,
// kernel/quadric_determinant.hpp, kernel/poly_matrix.hpp, F's net); it shares
// no code with them. a[r][c] for r, c < n (any nested random-access storage);
// T a commutative ring with 0, 1, *, + and - (exact: mpq_class, Poly<mpq_class>).
#include <algorithm>
#include <numeric>
#include <vector>

namespace eccd::test {

template <class T, class Matrix>
T leibniz_det(const Matrix& a, int n) {
  std::vector<int> p(n);
  std::iota(p.begin(), p.end(), 0);
  T s = T(0);
  do {
    int inv = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) inv += p[i] > p[j];
    T prod = T(1);
    for (int r = 0; r < n; ++r) prod *= a[r][p[r]];
    if (inv % 2)
      s -= prod;
    else
      s += prod;
  } while (std::next_permutation(p.begin(), p.end()));
  return s;
}

}  // namespace eccd::test
