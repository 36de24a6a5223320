#pragma once
// The characteristic polynomial f(λ;t) = det(λA(t) - B(t)) = sum_k g_k(t) λ^k.
//
// Statement. 003 section III eq. (1) (3x3, cubic in λ) and 002 section 3 /
// 001 section 3 (4x4, quartic). Convention (design.md): det(λA - B); the
// solids are separate iff f has two distinct negative roots, touching
// externally iff a negative double root, overlapping iff no negative root.
// (000 writes det(λA + B) and positive roots; not used here.)
// Computation: det is multilinear in the columns, so
//   g_k = (-1)^(N-k) * sum over column sets S with |S| = k of det(C_S),
// C_S taking column j from A if j in S and from B otherwise (2^N determinants).
// Requirements on T: ring operations.
#include "kernel/poly_matrix.hpp"

#include <bit>
#include <vector>

namespace eccd {

template <class T, int N>
std::vector<Poly<T>> characteristic_coefficients(const PolyMatrix<T, N>& a, const PolyMatrix<T, N>& b) {
  std::vector<Poly<T>> g(N + 1);
  for (unsigned mask = 0; mask < (1u << N); ++mask) {
    PolyMatrix<T, N> c{};
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) c[i][j] = (mask >> j & 1u) ? a[i][j] : b[i][j];
    int k = std::popcount(mask);
    Poly<T> d = det<T, N>(c);
    if ((N - k) % 2) g[k] -= d; else g[k] += d;
  }
  return g;
}

}  // namespace eccd
