// kernel/quadric_classification.hpp: the affine type of a conic / quadric
// surface Xᵀ Q X = 0 from the inertia of its upper-left block and the sign of
// det Q. Checked against:
//   - one hand-made normal form of every kind in 2D and 3D (x² + y² - 1, the
//     parabola y = x², the hyperboloids x² + y² - z² ∓ 1, the paraboloids
//     z = x² ± y², cones, cylinders, line pairs ...), with the classical names;
//   - invariance: the type is an affine invariant, so Pᵀ Q P for a random
//     rational affine map P = [[L, v], [0, 1]] (det L ≠ 0) and a positive
//     multiple of Q keep the kind (seeded, over every normal form);
//   - symmetric_inertia against the eigenvalues computed by Eigen in double
//     for random symmetric integer blocks whose eigenvalues are far from 0
//     (and exact zero eigenvalues from rank-deficient blocks).
#include "kernel/quadric_classification.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using QM = std::vector<std::vector<mpq_class>>;
using K = QuadricKind;

QM diag(std::vector<long> d) {
  QM q(d.size(), std::vector<mpq_class>(d.size(), mpq_class(0)));
  for (std::size_t i = 0; i < d.size(); ++i) q[i][i] = d[i];
  return q;
}
// x_i x_last coefficient c: entries (i, last) and (last, i) = c / 2 (the form has 2 · (c/2) x_i).
QM with_linear(QM q, int i, long c) {
  const int last = int(q.size()) - 1;
  q[i][last] = q[last][i] = mpq_class(c, 2);
  q[i][last].canonicalize();
  q[last][i].canonicalize();
  return q;
}

struct Case {
  QM q;
  int dim;
  K kind;
  const char* words;  // a part of the description
};

std::vector<Case> normal_forms() {
  return {
      {diag({1, 1, -1}), 2, K::real_ellipsoid, ""},
      {diag({4, 1, -100}), 2, K::real_ellipsoid, ""},
      {diag({-1, -1, 1}), 2, K::wrong_sign, "wrong sign"},
      {diag({1, 1, 1}), 2, K::imaginary, "imaginary ellipse"},
      {diag({-1, -1, -1}), 2, K::imaginary, "the whole plane"},
      {diag({1, 1, 0}), 2, K::single_point, "single point"},
      {diag({1, -1, -1}), 2, K::hyperbola, "hyperbola"},
      {diag({1, -1, 0}), 2, K::degenerate, "intersecting lines"},
      {with_linear(diag({1, 0, 0}), 1, -1), 2, K::parabola, "parabola"},  // x² - y
      {diag({1, 0, -1}), 2, K::degenerate, "parallel lines"},
      {with_linear(diag({0, 0, 0}), 0, 2), 2, K::degenerate, "block is zero"},  // 2x: a line
      {diag({1, 1, 1, -1}), 3, K::real_ellipsoid, ""},
      {diag({-1, -1, -1, 1}), 3, K::wrong_sign, "wrong sign"},
      {diag({1, 1, 1, 1}), 3, K::imaginary, "imaginary ellipsoid"},
      {diag({-1, -1, -1, -1}), 3, K::imaginary, "all of space"},
      {diag({1, 2, 3, 0}), 3, K::single_point, "single point"},
      {diag({1, 1, -1, -1}), 3, K::hyperboloid_one_sheet, "one sheet"},   // x² + y² = z² + 1
      {diag({1, 1, -1, 1}), 3, K::hyperboloid_two_sheets, "two sheets"},  // x² + y² + 1 = z²
      {diag({1, 1, -1, 0}), 3, K::degenerate, "cone"},
      {with_linear(diag({1, 1, 0, 0}), 2, -1), 3, K::elliptic_paraboloid, "elliptic paraboloid"},
      {with_linear(diag({1, -1, 0, 0}), 2, -1), 3, K::hyperbolic_paraboloid, "hyperbolic paraboloid"},
      {diag({1, 1, 0, -1}), 3, K::degenerate, "elliptic cylinder"},
      {diag({1, -1, 0, -1}), 3, K::degenerate, "hyperbolic cylinder"},
      {with_linear(diag({1, 0, 0, 0}), 1, -1), 3, K::degenerate, "parabolic cylinder"},
  };
}

mpq_class small(std::mt19937_64& rng) {
  mpq_class x(long(rng() % 13) - 6, long(rng() % 3) + 1);
  x.canonicalize();
  return x;
}

}  // namespace

TEST_CASE("classify_quadric names every normal form", "[kernel][quadric_classification]") {
  for (const Case& c : normal_forms()) {
    const QuadricClass r = classify_quadric(c.q, c.dim);
    INFO("expected: " << c.words << "; got: " << r.description);
    CHECK(r.kind == c.kind);
    CHECK(r.ok() == (c.kind == K::real_ellipsoid));
    if (c.kind == K::real_ellipsoid)
      CHECK(r.description.empty());
    else
      CHECK(r.description.find(c.words) != std::string::npos);
  }
}

TEST_CASE("classify_quadric is invariant under affine maps and positive scaling", "[kernel][quadric_classification]") {
  std::mt19937_64 rng(4313);
  int maps = 0;
  for (const Case& c : normal_forms()) {
    const int h = c.dim + 1;
    for (int trial = 0; trial < 10; ++trial) {
      // P = [[L, v], [0, 1]] with det L != 0 (rejected and redrawn otherwise).
      QM p(h, std::vector<mpq_class>(h, mpq_class(0)));
      QM l(c.dim, std::vector<mpq_class>(c.dim));
      do {
        for (int i = 0; i < c.dim; ++i)
          for (int j = 0; j < c.dim; ++j) l[i][j] = small(rng);
      } while (ring_det(l, mpq_class(0)) == 0);
      for (int i = 0; i < c.dim; ++i) {
        for (int j = 0; j < c.dim; ++j) p[i][j] = l[i][j];
        p[i][c.dim] = small(rng);
      }
      p[c.dim][c.dim] = 1;
      const mpq_class scale(long(rng() % 9) + 1, long(rng() % 4) + 1);
      QM m(h, std::vector<mpq_class>(h, mpq_class(0)));
      for (int i = 0; i < h; ++i)
        for (int j = 0; j < h; ++j)
          for (int k = 0; k < h; ++k)
            for (int n = 0; n < h; ++n) m[i][j] += p[k][i] * c.q[k][n] * p[n][j];
      for (auto& row : m)
        for (auto& x : row) x *= scale;
      INFO(c.words << " trial " << trial);
      CHECK(classify_quadric(m, c.dim).kind == c.kind);
      ++maps;
    }
  }
  CHECK(maps == 240);
}

TEST_CASE("symmetric_inertia counts the signs of the eigenvalues", "[kernel][quadric_classification]") {
  std::mt19937_64 rng(4314);
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 1 + trial % 3;
    // B = Cᵀ D C: symmetric with a chosen rank (D diagonal, some zeros): exact zero eigenvalues.
    QM a(n, std::vector<mpq_class>(n, mpq_class(0)));
    Eigen::MatrixXd ad(n, n);
    std::vector<long> d(n), c(n * n);
    for (auto& x : d) x = (rng() % 4 == 0) ? 0 : long(rng() % 11) - 5;
    for (auto& x : c) x = long(rng() % 7) - 3;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        long s = 0;
        for (int k = 0; k < n; ++k) s += c[k * n + i] * d[k] * c[k * n + j];
        a[i][j] = s;
        ad(i, j) = double(s);
      }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(ad);
    const auto ev = es.eigenvalues();
    const double big = ev.cwiseAbs().maxCoeff() + 1;
    int pos = 0, neg = 0, zero = 0;
    bool clear = true;
    // Integer matrices: a non-zero eigenvalue is at least 1e-3 of the largest here, a zero one far smaller.
    for (int i = 0; i < n; ++i) {
      if (std::abs(ev(i)) < 1e-9 * big)
        ++zero;
      else if (std::abs(ev(i)) < 1e-3)
        clear = false;
      else
        (ev(i) > 0 ? pos : neg)++;
    }
    if (!clear) continue;
    const auto in = quadric_detail::symmetric_inertia(a);
    INFO("trial " << trial);
    CHECK(in.pos == pos);
    CHECK(in.neg == neg);
    CHECK(in.zero == zero);
    ++checked;
  }
  CHECK(checked > 300);
}

}  // namespace ECCD_UNITY_ID
