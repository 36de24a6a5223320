#pragma once
// Test support for the 3D pipelines: running them on a scene, random
// ellipsoid scenes under Euler-parameter motions, and an independent exact
// oracle for the status at a rational instant.
#include "api/solve.hpp"
#include "io/solution_json.hpp"
#include "exact/cd_disc_exact.hpp"
#include "floating/cd_disc_floating.hpp"
#include "floating/bezier_ccd.hpp"
#include "kernel/ccd_projection.hpp"
#include "io/scene_reader.hpp"
#include "kernel/sturm.hpp"
#include "tests/support/scenes.hpp"

#include <random>

namespace eccd::test {

inline PipelineResult<Rational> solve_exact_3d(const Scene& s, bool first_contact = false) {
  ExactPolicy pol;
  auto m = to_arithmetic<Rational, H_3D>(prepare_pair<H_3D>(s), Rational(1));
  return ccd_projection(m, pol, first_contact);
}

// The Bézier pipeline with f built in Bernstein form (the `eccd solve` default).
template <class T>
PipelineResult<T> solve_bezier_3d(const Scene& s, int bits, const T& like, bool first_contact = false) {
  auto g = characteristic_of(to_arithmetic_bernstein<T, H_3D>(prepare_pair<H_3D>(s), like));
  BezierOptions o;
  o.first_contact_only = first_contact;
  return ccd_bezier(g, like, bits, o);
}

// A random pair of ellipsoids (semi-axes 1..5) under Euler-parameter motions
// whose e_i and translations have degree k (rational motion of degree 2k).
inline Scene random_euler_scene(std::mt19937_64& rng, int k) {
  std::uniform_int_distribution<int> small(-6, 6), axis(1, 5), pos(-5, 5);
  auto rand_poly = [&](int deg, int c0, int range) {
    RPoly p;
    std::uniform_int_distribution<int> c(-range, range);
    p.c.push_back(Rational(c0));
    for (int i = 1; i <= deg; ++i) p.c.push_back(Rational(c(rng)));
    p.trim();
    return p;
  };
  auto shape = [&]() {
    std::vector<std::vector<Rational>> q(4, std::vector<Rational>(4, Rational(0)));
    for (int i = 0; i < 3; ++i) {
      Rational a = axis(rng);
      q[i][i] = 1 / (a * a);
    }
    q[3][3] = -1;
    return q;
  };
  auto motion = [&]() {
    while (true) {
      EulerMotion m;
      for (int i = 0; i < 4; ++i) m.e[i] = rand_poly(k, small(rng), 4);
      for (int i = 0; i < 3; ++i) m.v[i] = rand_poly(k, pos(rng), 8);
      m.v3 = rp({1});
      RPoly E = m.e[0] * m.e[0] + m.e[1] * m.e[1] + m.e[2] * m.e[2] + m.e[3] * m.e[3];
      if (!E.is_zero() && count_roots_closed(E, Rational(0), Rational(1)) == 0) return Motion(m);
    }
  };
  Scene s;
  s.name = "random3d";
  s.dim = 3;
  s.a = {shape(), motion()};
  s.b = {shape(), motion()};
  return s;
}

// Exact rational N x N inverse by Gauss-Jordan (the oracle does not use the
// pipeline's polynomial inverse).
template <int N>
std::array<std::array<Rational, N>, N> inverse(std::array<std::array<Rational, N>, N> m) {
  std::array<std::array<Rational, N>, N> inv{};
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) inv[i][j] = i == j ? 1 : 0;
  for (int c = 0; c < N; ++c) {
    int p = c;
    while (m[p][c] == 0) ++p;
    std::swap(m[p], m[c]);
    std::swap(inv[p], inv[c]);
    Rational d = m[c][c];
    for (int j = 0; j < N; ++j) {
      m[c][j] /= d;
      inv[c][j] /= d;
    }
    for (int r = 0; r < N; ++r)
      if (r != c && m[r][c] != 0) {
        Rational f = m[r][c];
        for (int j = 0; j < N; ++j) {
          m[r][j] -= f * m[c][j];
          inv[r][j] -= f * inv[c][j];
        }
      }
  }
  return inv;
}

// Exact determinant (Gaussian elimination over the rationals): the kernel's,
// which no pipeline decision uses (it only balances the pencil).
template <int N>
Rational det_rational(const std::array<std::array<Rational, N>, N>& m) {
  return field_det<Rational, N>(m);
}

// Distinct negative roots of det(λA(t) - B(t)) with A(t) = M(t)^-T Q M(t)^-1
// from the motion matrix itself, f interpolated at λ = 0..4, exact Sturm count.
inline int negative_root_count_3d(const Scene& s, const Rational& t) {
  using M4 = std::array<std::array<Rational, 4>, 4>;
  auto quadric_at = [&](const SceneObject& o) {
    auto id = [](const Rational& q) { return q; };
    PolyMatrix<Rational, 4> m = motion_matrix<Rational, 4>(o.motion, id);
    M4 M{}, A{};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) M[i][j] = m[i][j](t);
    M4 inv = inverse<4>(M);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        Rational acc = 0;
        for (int k = 0; k < 4; ++k)
          for (int l = 0; l < 4; ++l) acc += inv[k][i] * o.Q[k][l] * inv[l][j];
        A[i][j] = acc;
      }
    return A;
  };
  M4 a = quadric_at(s.a), b = quadric_at(s.b);
  RPoly poly;
  for (int i = 0; i <= 4; ++i) {
    M4 m{};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[r][c] = Rational(i) * a[r][c] - b[r][c];
    RPoly basis = rp({1});
    Rational den = 1;
    for (int j = 0; j <= 4; ++j)
      if (j != i) {
        basis = basis * rp({-j, 1});
        den *= (i - j);
      }
    poly += (det_rational<4>(m) / den) * basis;
  }
  return count_roots<Rational>(poly, std::optional<Rational>(), std::optional<Rational>(Rational(0)));
}

}  // namespace eccd::test
