#pragma once
// Moving quadrics: A(t) = N(t)^T Q N(t), a positive multiple of M^-T Q M^-1.
//
// Statement. The solid X^T Q X <= 0 (object frame) moved by M(t) is
// X^T A(t) X <= 0 with A(t) = M(t)^-T Q M(t)^-1 (003 VI-A; 002 section 2;
// docs/architecture.md). With N(t) from kernel/motion.hpp (M N = c I) we use
// N^T Q N = c^2 A(t): the positive factor c(t)^2 changes no sign and no root
// of f(λ;t). Requirements on T: ring operations.
#include "kernel/poly_matrix.hpp"
#include "kernel/ring_determinant.hpp"

namespace eccd {

// A = Nᵀ Q N with N's entries in any ring R (Poly<T> or Bern<T>), Q scalar.
template <class R, class S, int N>
std::array<std::array<R, N>, N> moving_quadric_in(const Matrix<S, N>& q, const std::array<std::array<R, N>, N>& n,
                                                  const R& zero) {
  std::array<std::array<R, N>, N> qn, a;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      R s = zero;
      for (int k = 0; k < N; ++k)
        if (!is_zero(q[i][k]) && !is_ring_zero(n[k][j])) s = s + q[i][k] * n[k][j];
      qn[i][j] = s;
    }
  for (int i = 0; i < N; ++i)
    for (int j = i; j < N; ++j) {
      R s = zero;
      for (int k = 0; k < N; ++k)
        if (!is_ring_zero(n[k][i]) && !is_ring_zero(qn[k][j])) s = s + n[k][i] * qn[k][j];
      a[i][j] = s;
      a[j][i] = s;  // symmetric by construction
    }
  return a;
}

// A(t) at one instant t: N(t)^T Q N(t) evaluated (balancing a pencil,
// kernel/prepared_scene.hpp and floating/rounded_input.hpp).
template <class T, int H>
Matrix<T, H> quadric_at(const Matrix<T, H>& q, const PolyMatrix<T, H>& n, const T& t) {
  Matrix<T, H> nt{}, r{};
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j)
      nt[i][j] = n[i][j].is_zero() ? scalar_traits<T>::from_rational(mpq_class(0), t) : n[i][j](t);
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      T s = scalar_traits<T>::from_rational(mpq_class(0), t);
      for (int k = 0; k < H; ++k)
        for (int l = 0; l < H; ++l) s = s + nt[k][i] * q[k][l] * nt[l][j];
      r[i][j] = s;
    }
  return r;
}

template <class T, int N>
PolyMatrix<T, N> moving_quadric(const Matrix<T, N>& q, const PolyMatrix<T, N>& n) {
  return moving_quadric_in<Poly<T>, T, N>(q, n, Poly<T>());
}

}  // namespace eccd
