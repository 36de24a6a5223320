#pragma once
// PolyMatrix<T, N>: N x N matrices whose entries are polynomials Poly<T> in t.
//
// Statement. Motions M(t), their polynomial inverses N(t) (M N = c(t) I) and
// the moving quadrics A(t) = N(t)^T Q N(t) are polynomial matrices
// (docs/architecture.md; 003 section VI-A; 002 section 2). Determinants are expanded by
// Laplace along the first row: N is 3 or 4.
// Requirements on T: ring operations of Poly<T>.
#include "kernel/polynomial.hpp"

#include <array>

namespace eccd {

template <class T, int N>
using PolyMatrix = std::array<std::array<Poly<T>, N>, N>;

template <class T, int N>
using Matrix = std::array<std::array<T, N>, N>;

template <class T, int N>
PolyMatrix<T, N> identity_poly_matrix() {
  PolyMatrix<T, N> m{};
  for (int i = 0; i < N; ++i) m[i][i] = Poly<T>::constant(T(1));
  return m;
}

template <class T, int N>
PolyMatrix<T, N> transpose(const PolyMatrix<T, N>& a) {
  PolyMatrix<T, N> r{};
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) r[i][j] = a[j][i];
  return r;
}

template <class T, int N>
PolyMatrix<T, N> product(const PolyMatrix<T, N>& a, const PolyMatrix<T, N>& b) {
  PolyMatrix<T, N> r{};
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int k = 0; k < N; ++k)
        if (!a[i][k].is_zero() && !b[k][j].is_zero()) r[i][j] += a[i][k] * b[k][j];
  return r;
}

// Determinant of the square submatrix given by `rows` x `cols` (Laplace).
template <class T, int N>
Poly<T> minor_det(const PolyMatrix<T, N>& a, const std::array<int, N>& rows, const std::array<int, N>& cols, int n) {
  if (n == 1) return a[rows[0]][cols[0]];
  Poly<T> d;
  std::array<int, N> sub{};
  for (int j = 0; j < n; ++j) {
    const Poly<T>& e = a[rows[0]][cols[j]];
    if (e.is_zero()) continue;
    std::array<int, N> subrows{};
    for (int i = 1; i < n; ++i) subrows[i - 1] = rows[i];
    for (int k = 0, m = 0; k < n; ++k)
      if (k != j) sub[m++] = cols[k];
    Poly<T> term = e * minor_det<T, N>(a, subrows, sub, n - 1);
    if (j % 2)
      d -= term;
    else
      d += term;
  }
  return d;
}

template <class T, int N>
Poly<T> det(const PolyMatrix<T, N>& a) {
  std::array<int, N> idx{};
  for (int i = 0; i < N; ++i) idx[i] = i;
  return minor_det<T, N>(a, idx, idx, N);
}

// adj(a): adj(a) a = a adj(a) = det(a) I.
template <class T, int N>
PolyMatrix<T, N> adjugate(const PolyMatrix<T, N>& a) {
  PolyMatrix<T, N> r{};
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      std::array<int, N> rows{}, cols{};
      for (int k = 0, m = 0; k < N; ++k)
        if (k != j) rows[m++] = k;
      for (int k = 0, m = 0; k < N; ++k)
        if (k != i) cols[m++] = k;
      Poly<T> c = minor_det<T, N>(a, rows, cols, N - 1);
      r[i][j] = ((i + j) % 2) ? -c : c;
    }
  return r;
}

}  // namespace eccd
