// kernel/keyframe_motion.hpp: the rational motion between two key poses
// (docs/animation-format.md; 001 section 5). Checked against the rule written
// out in the test, at rational τ in mpq: M(τ) from the returned scene motion
// (kernel/motion.hpp's motion_matrix), divided by its corner, must be
// [[R(τ) D(τ), c(τ)], [0, 1]] with c and D interpolated linearly, and R(τ)
// the rotation of q(τ) = (1 - τ) q0 + τ q1' (q1' = -q1 when q0 · q1 < 0): in 2D
// cos = (w² - z²)/W, sin = 2wz/W (the turn by 2 atan2(z, w)), in 3D the
// `euler` matrix of scene-format.md over E = |q|². Over seeded random poses
// with and without deformation, in 2D and 3D: the motion's type (kinematic
// / euler without deformation, matrix with), the end poses, the shorter way,
// the degree bounds (3; 2 for a fixed centre without deformation),
// keyframe_weight and keyframe_deformation_det; dim 4 refused.
#include "kernel/keyframe_motion.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using test::q;  // a / b in lowest terms (tests/support/exact_values.hpp)
Rational small(std::mt19937_64& rng) { return q(long(rng() % 21) - 10, long(rng() % 4) + 1); }

KeyPose random_pose(std::mt19937_64& rng, int dim, bool deform) {
  KeyPose p;
  for (int i = 0; i < dim; ++i) p.position.push_back(small(rng));
  for (int i = 0; i < (dim == 2 ? 2 : 4); ++i) p.orientation.push_back(small(rng));
  if (p.orientation[0] == 0) p.orientation[0] = 1;
  if (deform) {
    std::vector<std::vector<Rational>> d(dim, std::vector<Rational>(dim));
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) d[i][j] = i == j ? q(long(rng() % 4) + 2, 2) : q(long(rng() % 5) - 2, 8);
    p.deformation = d;  // diagonally dominant: det > 0
  }
  return p;
}

// The expected affine matrix [[R D, c], [0, 1]] at τ (dim + 1 square).
std::vector<std::vector<Rational>> expected(const KeyPose& p0, const KeyPose& p1, int dim, const Rational& t) {
  std::vector<Rational> q1 = p1.orientation;
  Rational dot = 0;
  for (std::size_t i = 0; i < q1.size(); ++i) dot += p0.orientation[i] * q1[i];
  if (dot < 0)
    for (auto& x : q1) x = -x;
  std::vector<Rational> e;
  for (std::size_t i = 0; i < q1.size(); ++i) e.push_back((1 - t) * p0.orientation[i] + t * q1[i]);
  std::vector<std::vector<Rational>> r(dim, std::vector<Rational>(dim));
  if (dim == 2) {
    const Rational W = e[0] * e[0] + e[1] * e[1], c = (e[0] * e[0] - e[1] * e[1]) / W, s = 2 * e[0] * e[1] / W;
    r = {{c, -s}, {s, c}};
  } else {
    const Rational E = e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3];
    r = {{e[0] * e[0] + e[1] * e[1] - e[2] * e[2] - e[3] * e[3], 2 * (e[1] * e[2] - e[0] * e[3]),
          2 * (e[1] * e[3] + e[0] * e[2])},
         {2 * (e[1] * e[2] + e[0] * e[3]), e[0] * e[0] - e[1] * e[1] + e[2] * e[2] - e[3] * e[3],
          2 * (e[2] * e[3] - e[0] * e[1])},
         {2 * (e[1] * e[3] - e[0] * e[2]), 2 * (e[2] * e[3] + e[0] * e[1]),
          e[0] * e[0] - e[1] * e[1] - e[2] * e[2] + e[3] * e[3]}};
    for (auto& row : r)
      for (auto& x : row) x /= E;
  }
  auto dm = [&](const KeyPose& p, int i, int j) { return p.deformation ? (*p.deformation)[i][j] : Rational(i == j); };
  std::vector<std::vector<Rational>> m(dim + 1, std::vector<Rational>(dim + 1, Rational(0)));
  for (int i = 0; i < dim; ++i) {
    for (int j = 0; j < dim; ++j)
      for (int k = 0; k < dim; ++k) m[i][j] += r[i][k] * ((1 - t) * dm(p0, k, j) + t * dm(p1, k, j));
    m[i][dim] = (1 - t) * p0.position[i] + t * p1.position[i];
  }
  m[dim][dim] = 1;
  return m;
}

template <int H>
void check(std::mt19937_64& rng, int trials) {
  constexpr int dim = H - 1;
  for (int trial = 0; trial < trials; ++trial) {
    const bool deform = trial % 2 == 1;
    const KeyPose p0 = random_pose(rng, dim, deform), p1 = random_pose(rng, dim, deform && trial % 4 == 1);
    const Motion mo = keyframe_motion(p0, p1, dim);
    INFO("dim " << dim << " trial " << trial);
    // a deformation that is the identity written out counts as none
    auto identity = [&](const KeyPose& p) {
      if (!p.deformation) return true;
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
          if ((*p.deformation)[i][j] != Rational(i == j)) return false;
      return true;
    };
    if (!identity(p0) || !identity(p1))
      CHECK(std::holds_alternative<MatrixMotion>(mo));
    else
      CHECK(mo.index() == (dim == 2 ? Motion(KinematicMotion{}).index() : Motion(EulerMotion{}).index()));
    const PolyMatrix<Rational, H> m = motion_matrix<Rational, H>(mo, [](const Rational& x) { return x; });
    int deg = 0;
    for (const auto& row : m)
      for (const auto& e : row) deg = std::max(deg, e.degree());
    CHECK(deg <= 3);
    for (int j = 0; j < dim; ++j) CHECK(m[dim][j].is_zero());
    for (int s = 0; s <= 4; ++s) {
      const Rational t = q(s, 4);
      const auto want = expected(p0, p1, dim, t);
      const Rational w = m[dim][dim](t);
      REQUIRE(w != 0);
      for (int i = 0; i <= dim; ++i)
        for (int j = 0; j <= dim; ++j) CHECK(m[i][j](t) / w == want[i][j]);
    }
    // keyframe_weight is |q(τ)|² (the shorter way), keyframe_deformation_det is det D(τ).
    const RPoly W = keyframe_weight(p0.orientation, shorter_way(p0.orientation, p1.orientation));
    const RPoly dd = keyframe_deformation_det(p0, p1, dim);
    for (int s = 0; s <= 4; ++s) {
      const Rational t = q(s, 4);
      Rational qq = 0;
      const auto q1 = shorter_way(p0.orientation, p1.orientation);
      for (std::size_t i = 0; i < q1.size(); ++i) {
        const Rational x = (1 - t) * p0.orientation[i] + t * q1[i];
        qq += x * x;
      }
      CHECK(W(t) == qq);
      CHECK(dd(t) > 0);
    }
  }
}

}  // namespace

TEST_CASE("keyframe_motion is [[R(τ) D(τ), c(τ)], [0, 1]] up to its weight, in 2D and 3D",
          "[kernel][keyframe_motion]") {
  std::mt19937_64 rng(4333);
  check<3>(rng, 40);
  check<4>(rng, 40);
}

TEST_CASE("keyframe_motion takes the shorter way round and keeps degree 2 for a fixed centre",
          "[kernel][keyframe_motion]") {
  // 2D: q0 = (1, 0) (no turn), q1 = (-1, 0) (also no turn, the opposite sign): q0 · q1 < 0, so q1' = (1, 0)
  // and the body does not turn at all (the long way would pass through q = 0 at τ = 1/2).
  KeyPose a, b;
  a.position = {Rational(0), Rational(0)};
  b.position = {Rational(0), Rational(0)};
  a.orientation = {Rational(1), Rational(0)};
  b.orientation = {Rational(-1), Rational(0)};
  CHECK(shorter_way(a.orientation, b.orientation) == std::vector<Rational>{Rational(1), Rational(0)});
  const auto m = motion_matrix<Rational, 3>(keyframe_motion(a, b, 2), [](const Rational& x) { return x; });
  for (int s = 0; s <= 4; ++s) {
    const Rational t = q(s, 4);
    CHECK(m[0][0](t) == m[2][2](t));  // cos = 1
    CHECK(m[0][1](t) == 0);
  }
  // A quarter turn with a fixed centre: degree 2.
  b.orientation = {Rational(1), Rational(1)};
  const auto m2 = motion_matrix<Rational, 3>(keyframe_motion(a, b, 2), [](const Rational& x) { return x; });
  int deg = 0;
  for (const auto& row : m2)
    for (const auto& e : row) deg = std::max(deg, e.degree());
  CHECK(deg == 2);
  // At τ = 1 the rotation of (1, 1): by 2 atan2(1, 1) = π/2.
  CHECK(m2[0][0](Rational(1)) == 0);
  CHECK(m2[1][0](Rational(1)) / m2[2][2](Rational(1)) == 1);
  CHECK_THROWS_AS(keyframe_motion(a, b, 4), std::invalid_argument);
  CHECK(keyframe_is_identity(a, 2));
  a.deformation = std::vector<std::vector<Rational>>{{Rational(1), Rational(0)}, {Rational(0), Rational(1)}};
  CHECK(keyframe_is_identity(a, 2));  // the identity written out
  (*a.deformation)[0][1] = q(1, 2);
  CHECK_FALSE(keyframe_is_identity(a, 2));
}

}  // namespace ECCD_UNITY_ID
