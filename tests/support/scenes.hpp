#pragma once
// Test support: scenes built in memory, running the templated pipeline, and an
// independent exact oracle for the status at a rational instant.
#include "exact/cd_disc_exact.hpp"
#include "floating/cd_disc_floating.hpp"
#include "io/scene_reader.hpp"
#include "kernel/sturm.hpp"
#include "tests/support/arith.hpp"

#include <random>
#include <sstream>

namespace eccd::test {

inline std::string case_path(const std::string& rel) { return std::string(ECCD_SOURCE_DIR) + "/cases/" + rel; }

inline PipelineResult<Rational> solve_exact(const Scene& s, Variant v = Variant::answer) {
  ExactPolicy pol;
  auto m = to_arithmetic<Rational, H_2D>(prepare_pair<H_2D>(s), Rational(1));
  return cd_disc(m, pol, v);
}

template <class T>
PipelineResult<T> solve_floating(const Scene& s, Basis basis, int bits, const T& like, Variant v = Variant::answer) {
  FloatingPolicy<T> pol(basis, bits, like);
  auto m = to_arithmetic<T, H_2D>(prepare_pair<H_2D>(s), like);
  return cd_disc(m, pol, v);
}

inline RPoly rp(std::initializer_list<long> c) {
  RPoly p;
  for (long x : c) p.c.push_back(Rational(x));
  p.trim();
  return p;
}

// Two ellipses with semi-axes (a0, a1), (b0, b1), each under a translation
// M = [[1, 0, x(t)], [0, 1, y(t)], [0, 0, 1]].
inline Scene translation_scene(Rational a0, Rational a1, RPoly xa, RPoly ya, Rational b0, Rational b1, RPoly xb,
                               RPoly yb) {
  Scene s;
  s.name = "translations";
  s.dim = 2;
  auto shape = [](Rational u, Rational v) {
    std::vector<std::vector<Rational>> q(3, std::vector<Rational>(3, Rational(0)));
    q[0][0] = 1 / (u * u);
    q[1][1] = 1 / (v * v);
    q[2][2] = -1;
    return q;
  };
  auto motion = [](RPoly x, RPoly y) {
    MatrixMotion m;
    m.m = {{rp({1}), RPoly(), x}, {RPoly(), rp({1}), y}, {RPoly(), RPoly(), rp({1})}};
    return Motion(m);
  };
  s.a = {shape(a0, a1), motion(xa, ya)};
  s.b = {shape(b0, b1), motion(xb, yb)};
  return s;
}

// A random 2D scene: random ellipses under random kinematic-image motions
// with d_i of degree k (motion degree 2k); denominators checked exactly.
inline Scene random_kinematic_scene(std::mt19937_64& rng, int k) {
  std::uniform_int_distribution<int> small(-6, 6), axis(1, 6);
  auto rand_poly = [&](int deg, int c0) {
    RPoly p;
    p.c.push_back(Rational(c0));
    for (int i = 1; i <= deg; ++i) p.c.push_back(Rational(small(rng), 2));
    p.trim();
    return p;
  };
  auto shape = [&]() {
    std::vector<std::vector<Rational>> q(3, std::vector<Rational>(3, Rational(0)));
    Rational u = axis(rng), v = axis(rng);
    q[0][0] = 1 / (u * u);
    q[1][1] = 1 / (v * v);
    q[2][2] = -1;
    return q;
  };
  auto motion = [&]() {
    while (true) {
      KinematicMotion m;
      for (int i = 0; i < 4; ++i) m.d[i] = rand_poly(k, i < 2 ? small(rng) : small(rng) + (i == 2 ? 8 : 0));
      RPoly den = m.d[2] * m.d[2] + m.d[3] * m.d[3];
      if (count_roots_closed(den, Rational(0), Rational(1)) == 0) return Motion(m);
    }
  };
  Scene s;
  s.name = "random";
  s.dim = 2;
  s.a = {shape(), motion()};
  s.b = {shape(), motion()};
  return s;
}

// The oracle: A(t) = M^-T Q M^-1 from the motion matrix itself (not from the
// pipeline's polynomial inverse), f(λ) = det(λA - B) by interpolation at
// λ = 0..3, and the exact Sturm count of its distinct negative roots.
inline int negative_root_count(const Scene& s, const Rational& t) {
  auto quadric_at = [&](const SceneObject& o) {
    auto id = [](const Rational& q) { return q; };
    PolyMatrix<Rational, 3> m = motion_matrix<Rational, 3>(o.motion, id);
    Rational M[3][3], inv[3][3], A[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[i][j] = m[i][j](t);
    Rational det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                   M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                   M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
        inv[i][j] = (M[r0][c0] * M[r1][c1] - M[r0][c1] * M[r1][c0]) / det;
      }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Rational acc = 0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) acc += inv[k][i] * o.Q[k][l] * inv[l][j];
        A[i][j] = acc;
      }
    return std::vector<Rational>{A[0][0], A[0][1], A[0][2], A[1][0], A[1][1], A[1][2], A[2][0], A[2][1], A[2][2]};
  };
  auto a = quadric_at(s.a), b = quadric_at(s.b);
  auto f = [&](const Rational& lam) {
    Rational m[9];
    for (int i = 0; i < 9; ++i) m[i] = lam * a[i] - b[i];
    Rational d =
        m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
    return d;
  };
  // Lagrange interpolation through λ = 0, 1, 2, 3 into power form.
  RPoly poly;
  for (int i = 0; i < 4; ++i) {
    RPoly basis = rp({1});
    Rational den = 1;
    for (int j = 0; j < 4; ++j)
      if (j != i) {
        basis = basis * rp({-j, 1});
        den *= (i - j);
      }
    poly += (f(Rational(i)) / den) * basis;
  }
  return count_roots<Rational>(poly, std::optional<Rational>(), std::optional<Rational>(Rational(0)));
}

inline bool in_answer_set(const Answer& a, const Rational& t, bool& ambiguous) {
  ambiguous = false;
  for (const auto& [s, e] : a.intervals) {
    if (*s.lo <= t && t <= *e.hi) {
      if (t <= *s.hi || t >= *e.lo) ambiguous = !(s.lo == s.hi && e.lo == e.hi);
      return true;
    }
  }
  return false;
}

}  // namespace eccd::test
