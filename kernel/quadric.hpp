#pragma once
// Moving quadrics: A(t) = N(t)^T Q N(t), a positive multiple of M^-T Q M^-1.
//
// Statement. The solid X^T Q X <= 0 (object frame) moved by M(t) is
// X^T A(t) X <= 0 with A(t) = M(t)^-T Q M(t)^-1 (003 VI-A; 002 section 2;
// design.md). With N(t) from kernel/motion.hpp (M N = c I) we use
// N^T Q N = c^2 A(t): the positive factor c(t)^2 changes no sign and no root
// of f(λ;t). Requirements on T: ring operations.
#include "kernel/poly_matrix.hpp"

namespace eccd {

template <class T, int N>
PolyMatrix<T, N> moving_quadric(const Matrix<T, N>& q, const PolyMatrix<T, N>& n) {
  PolyMatrix<T, N> qn{};
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int k = 0; k < N; ++k)
        if (!is_zero(q[i][k]) && !n[k][j].is_zero()) qn[i][j] += q[i][k] * n[k][j];
  PolyMatrix<T, N> a{};
  for (int i = 0; i < N; ++i)
    for (int j = i; j < N; ++j) {
      Poly<T> s;
      for (int k = 0; k < N; ++k)
        if (!n[k][i].is_zero() && !qn[k][j].is_zero()) s += n[k][i] * qn[k][j];
      a[i][j] = s;
      a[j][i] = s;  // symmetric by construction
    }
  return a;
}

}  // namespace eccd
