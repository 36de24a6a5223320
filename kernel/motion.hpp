#pragma once
// Rational motions as homogeneous polynomial matrices, and their polynomial
// inverses.
//
// Statement. A motion M(t) maps the object frame to the world frame; the
// moving solid is A(t) = M(t)^-T Q M(t)^-1 (scene-format.md; 003 VI-A;
// 002 section 2). Instead of M^-1 we build a polynomial matrix N(t) with
// M(t) N(t) = c(t) I, c(t) ≠ 0 on [0, 1]: then N^T Q N = c^2 M^-T Q M^-1 is a
// positive multiple of A(t), which changes no root of f(λ;t) = det(λA - B)
// (docs/architecture.md, "Use the adjugate").
//   static:    N = I.
//   matrix:    M = [[L, v], [0, w]]  ->  N = adj(M) = [[w adj L, -adj(L) v], [0, det L]].
//   kinematic: 003 eq. (3) and its inverse as printed after it (c = (d2²+d3²)²).
//   euler:     M = [[v3 R', E v], [0, E v3]] with R' = E R the quaternion
//              matrix (002 section 2); N = [[v3 R'^T, -R'^T v], [0, E v3]].
// Any common polynomial factor of N's entries is removed exactly when the
// scene is prepared (kernel/prepared_scene.hpp): the adjugate of 003 Example
// 2's M_A carries the factor w, and without removing it Δ has degree 192
// instead of the paper's 96.
// Requirements on T: ring operations; coefficients come from the exact scene
// through `conv` (Rational -> T).
#include "kernel/poly_matrix.hpp"
#include "kernel/scene.hpp"

#include <stdexcept>

namespace eccd {

template <class T, class Conv>
Poly<T> convert_poly(const RPoly& p, Conv conv) {
  return map_coeffs<T>(p, conv);
}

// R' = E R for the quaternion (e0, e1, e2, e3) (scene-format.md, `euler`).
template <class T>
PolyMatrix<T, 4> quaternion_matrix(const Poly<T> (&e)[4]) {
  PolyMatrix<T, 4> r{};
  Poly<T> e00 = e[0] * e[0], e11 = e[1] * e[1], e22 = e[2] * e[2], e33 = e[3] * e[3];
  r[0][0] = e00 + e11 - e22 - e33;
  r[0][1] = 2 * (e[1] * e[2] - e[0] * e[3]);
  r[0][2] = 2 * (e[1] * e[3] + e[0] * e[2]);
  r[1][0] = 2 * (e[1] * e[2] + e[0] * e[3]);
  r[1][1] = e00 - e11 + e22 - e33;
  r[1][2] = 2 * (e[2] * e[3] - e[0] * e[1]);
  r[2][0] = 2 * (e[1] * e[3] - e[0] * e[2]);
  r[2][1] = 2 * (e[2] * e[3] + e[0] * e[1]);
  r[2][2] = e00 - e11 - e22 + e33;
  return r;
}

// The polynomials of an euler motion: R' = E R, E, the translation v and its denominator v3.
template <class T>
struct EulerParts {
  PolyMatrix<T, 4> r;
  Poly<T> E, v3;
  Poly<T> v[3];
};
template <class T, class Conv>
EulerParts<T> euler_parts(const EulerMotion& e, Conv conv) {
  auto P = [&](const RPoly& p) { return convert_poly<T>(p, conv); };
  Poly<T> q[4] = {P(e.e[0]), P(e.e[1]), P(e.e[2]), P(e.e[3])};
  EulerParts<T> x;
  x.r = quaternion_matrix(q);
  x.E = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  x.v3 = P(e.v3);
  for (int i = 0; i < 3; ++i) x.v[i] = P(e.v[i]);
  return x;
}

// The motion matrix M(t) itself (used for centres and pictures).
template <class T, int N, class Conv>
PolyMatrix<T, N> motion_matrix(const Motion& motion, Conv conv) {
  PolyMatrix<T, N> m = identity_poly_matrix<T, N>();
  auto P = [&](const RPoly& p) { return convert_poly<T>(p, conv); };
  if (std::holds_alternative<StaticMotion>(motion)) return m;
  if (auto* mm = std::get_if<MatrixMotion>(&motion)) {
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) m[i][j] = P(mm->m[i][j]);
    return m;
  }
  if (auto* k = std::get_if<KinematicMotion>(&motion)) {
    static_assert(N == 3 || N == 4);
    if constexpr (N == 3) {
      Poly<T> d0 = P(k->d[0]), d1 = P(k->d[1]), d2 = P(k->d[2]), d3 = P(k->d[3]);
      Poly<T> c = d2 * d2 - d3 * d3, s = 2 * (d2 * d3);
      m[0][0] = c;
      m[0][1] = s;
      m[0][2] = 2 * (d0 * d3 - d1 * d2);
      m[1][0] = -s;
      m[1][1] = c;
      m[1][2] = 2 * (d0 * d2 + d1 * d3);
      m[2][0] = Poly<T>();
      m[2][1] = Poly<T>();
      m[2][2] = d2 * d2 + d3 * d3;
      return m;
    }
    throw std::invalid_argument("kinematic motions are 2D only");
  }
  if (auto* e = std::get_if<EulerMotion>(&motion)) {
    if constexpr (N == 4) {
      EulerParts<T> x = euler_parts<T>(*e, conv);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] = x.v3 * x.r[i][j];
        m[i][3] = x.E * x.v[i];
        m[3][i] = Poly<T>();
      }
      m[3][3] = x.E * x.v3;
      return m;
    }
    throw std::invalid_argument("euler motions are 3D only");
  }
  throw std::invalid_argument("a cycloidal motion is not rational: it has no polynomial matrix");
}

// N(t) with M(t) N(t) = c(t) I (see the header comment for each form).
template <class T, int N, class Conv>
PolyMatrix<T, N> motion_inverse(const Motion& motion, Conv conv) {
  if (std::holds_alternative<StaticMotion>(motion)) return identity_poly_matrix<T, N>();
  auto P = [&](const RPoly& p) { return convert_poly<T>(p, conv); };
  if (auto* k = std::get_if<KinematicMotion>(&motion)) {
    if constexpr (N == 3) {
      Poly<T> d0 = P(k->d[0]), d1 = P(k->d[1]), d2 = P(k->d[2]), d3 = P(k->d[3]);
      Poly<T> c = d2 * d2 - d3 * d3, s = 2 * (d2 * d3);
      PolyMatrix<T, 3> n{};
      n[0][0] = c;
      n[0][1] = -s;
      n[0][2] = 2 * (d1 * d2 + d0 * d3);
      n[1][0] = s;
      n[1][1] = c;
      n[1][2] = 2 * (d1 * d3 - d0 * d2);
      n[2][2] = d2 * d2 + d3 * d3;
      return n;
    }
    throw std::invalid_argument("kinematic motions are 2D only");
  }
  if (auto* e = std::get_if<EulerMotion>(&motion)) {
    if constexpr (N == 4) {
      EulerParts<T> x = euler_parts<T>(*e, conv);
      PolyMatrix<T, 4> n{};
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) n[i][j] = x.v3 * x.r[j][i];
        Poly<T> acc;
        for (int j = 0; j < 3; ++j) acc += x.r[j][i] * x.v[j];
        n[i][3] = -acc;
      }
      n[3][3] = x.E * x.v3;
      return n;
    }
    throw std::invalid_argument("euler motions are 3D only");
  }
  // matrix: the adjugate (block form, valid because the last row is (0,...,0,w)).
  PolyMatrix<T, N> m = motion_matrix<T, N>(motion, conv);
  return adjugate<T, N>(m);
}

}  // namespace eccd
