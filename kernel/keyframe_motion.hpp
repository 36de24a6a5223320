#pragma once
// Keyframe motion: the rational motion of a body between two key poses.
//
// Statement (docs/animation-format.md, "The motion of a body in frame k";
// paper 001 section 5: centres linearly interpolated, orientations by a
// linear quaternion curve). A key pose is a centre c, an orientation q (3D: a
// quaternion [w, x, y, z]; 2D: a pair [w, z], the rotation by 2·atan2(z, w)),
// not necessarily of unit length, and an optional affine deformation D (the
// identity when absent). With the local time τ ∈ [0, 1] of the frame:
//   c(τ) = (1 − τ)c_0 + τc_1,
//   q(τ) = (1 − τ)q_0 + τq'_1,  q'_1 = −q_1 when q_0·q_1 < 0, else q_1
//          (the shorter way round: shorter_way below),
//   D(τ) = (1 − τ)D_0 + τD_1,
//   M(τ) = [[R(τ)·D(τ), c(τ)], [0, 1]],
// R(τ) the rotation of q(τ): 3D the `euler` matrix of scene-format.md with
// e = q(τ), 2D the `kinematic` rotation with d2 = w(τ), d3 = −z(τ). Its
// polynomial form W(τ)·R(τ) (W = |q(τ)|²) has degree 2 (keyframe_rotation).
// keyframe_motion writes M(τ) as a scene motion:
//   no deformation at either key (both absent or the identity):
//     3D `euler` with e = q(τ), translation c(τ), denominator 1;
//     2D `kinematic` with d2 = w(τ), d3 = −z(τ), d0 = (x d3 + y d2)/2,
//        d1 = (y d3 − x d2)/2 (then M's translation column is W·(x, y));
//   otherwise a `matrix` motion [[W R · D, W c], [0, W]] (= W·M(τ)).
// Every motion has degree 3 at most (2 with a fixed centre and no deformation).
// The scene generator's keyframe family (compare/scene_generator.cpp) and the
// animations (io/animation_reader.hpp, api/animate.hpp) both build their
// motions here: one interpolation rule in the workbench.
// Validity (W ≠ 0 and det D(τ) ≠ 0 on [0, 1]) is checked by the callers
// (keyframe_weight, keyframe_deformation_det give the polynomials).
// Requirements: exact rationals (number/rational_traits.hpp); the motions of
// a scene are exact, every arithmetic starts from them.
#include "kernel/motion.hpp"
#include "kernel/scene.hpp"

#include <optional>
#include <stdexcept>
#include <vector>

namespace eccd {

struct KeyPose {
  std::vector<Rational> position;                                 // dim entries
  std::vector<Rational> orientation;                              // 3D: [w, x, y, z]; 2D: [w, z]
  std::optional<std::vector<std::vector<Rational>>> deformation;  // dim x dim; absent = identity
};

// (1 − τ)a + τb as a polynomial in τ.
inline RPoly keyframe_lerp(const Rational& a, const Rational& b) { return RPoly(std::vector<Rational>{a, b - a}); }

// q'_1 of the rule: −q_1 when q_0·q_1 < 0 (exactly), else q_1.
inline std::vector<Rational> shorter_way(const std::vector<Rational>& q0, const std::vector<Rational>& q1) {
  Rational d = 0;
  for (std::size_t i = 0; i < q0.size(); ++i) d += q0[i] * q1[i];
  std::vector<Rational> out = q1;
  if (sgn(d) < 0)
    for (auto& x : out) x = -x;
  return out;
}

// q(τ) from q_0 and q'_1 (already the shorter way: shorter_way).
inline std::vector<RPoly> keyframe_orientation(const std::vector<Rational>& q0, const std::vector<Rational>& q1) {
  std::vector<RPoly> q;
  for (std::size_t i = 0; i < q0.size(); ++i) q.push_back(keyframe_lerp(q0[i], q1[i]));
  return q;
}

// W(τ) = |q(τ)|² (the rotation's weight; zero exactly where q(τ) = 0).
inline RPoly keyframe_weight(const std::vector<Rational>& q0, const std::vector<Rational>& q1) {
  RPoly w;
  for (const RPoly& x : keyframe_orientation(q0, q1)) w += x * x;
  return w;
}

// The homogeneous matrix [[W(τ)·R(τ), 0], [0, W(τ)]] (size dim + 1, degree 2)
// of q(τ) from q_0 and q'_1.
inline std::vector<std::vector<RPoly>> keyframe_rotation(const std::vector<Rational>& q0,
                                                         const std::vector<Rational>& q1, int dim) {
  std::vector<std::vector<RPoly>> h(dim + 1, std::vector<RPoly>(dim + 1));
  std::vector<RPoly> q = keyframe_orientation(q0, q1);
  if (dim == 2) {
    const RPoly& w = q[0];
    const RPoly& z = q[1];
    h[0][0] = w * w - z * z;
    h[0][1] = RPoly::constant(Rational(-2)) * w * z;
    h[1][0] = RPoly::constant(Rational(2)) * w * z;
    h[1][1] = w * w - z * z;
    h[2][2] = w * w + z * z;
    return h;
  }
  Poly<Rational> e[4] = {q[0], q[1], q[2], q[3]};
  auto R = quaternion_matrix(e);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) h[i][j] = R[i][j];
  h[3][3] = e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3];
  return h;
}

// D(τ) = (1 − τ)D_0 + τD_1 (the identity for an absent deformation).
inline std::vector<std::vector<RPoly>> keyframe_deformation(const KeyPose& p0, const KeyPose& p1, int dim) {
  auto entry = [&](const KeyPose& p, int i, int j) {
    return p.deformation ? (*p.deformation)[i][j] : Rational(i == j ? 1 : 0);
  };
  std::vector<std::vector<RPoly>> d(dim, std::vector<RPoly>(dim));
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) d[i][j] = keyframe_lerp(entry(p0, i, j), entry(p1, i, j));
  return d;
}

// det D(τ) (degree dim at most).
inline RPoly keyframe_deformation_det(const KeyPose& p0, const KeyPose& p1, int dim) {
  auto d = keyframe_deformation(p0, p1, dim);
  if (dim == 2) return d[0][0] * d[1][1] - d[0][1] * d[1][0];
  return d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
         d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
}

inline bool keyframe_is_identity(const KeyPose& p, int dim) {
  if (!p.deformation) return true;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
      if ((*p.deformation)[i][j] != Rational(i == j ? 1 : 0)) return false;
  return true;
}

// The motion M(τ) of a body between key poses p0 and p1 (see the statement).
inline Motion keyframe_motion(const KeyPose& p0, const KeyPose& p1, int dim) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("keyframe_motion: dim must be 2 or 3");
  const std::vector<Rational>& q0 = p0.orientation;
  const std::vector<Rational> q1 = shorter_way(q0, p1.orientation);
  const std::vector<Rational>& c0 = p0.position;
  const std::vector<Rational>& c1 = p1.position;
  if (keyframe_is_identity(p0, dim) && keyframe_is_identity(p1, dim)) {
    if (dim == 3) {
      EulerMotion em;
      std::vector<RPoly> q = keyframe_orientation(q0, q1);
      for (int i = 0; i < 4; ++i) em.e[i] = q[i];
      for (int i = 0; i < 3; ++i) em.v[i] = keyframe_lerp(c0[i], c1[i]);
      em.v3 = RPoly::constant(Rational(1));
      return em;
    }
    KinematicMotion km;
    RPoly x = keyframe_lerp(c0[0], c1[0]), y = keyframe_lerp(c0[1], c1[1]);
    km.d[2] = keyframe_lerp(q0[0], q1[0]);
    km.d[3] = keyframe_lerp(-q0[1], -q1[1]);
    km.d[0] = Rational(1, 2) * (x * km.d[3] + y * km.d[2]);
    km.d[1] = Rational(1, 2) * (y * km.d[3] - x * km.d[2]);
    return km;
  }
  std::vector<std::vector<RPoly>> h = keyframe_rotation(q0, q1, dim);
  std::vector<std::vector<RPoly>> d = keyframe_deformation(p0, p1, dim);
  const RPoly W = h[dim][dim];
  MatrixMotion mm;
  mm.m.assign(dim + 1, std::vector<RPoly>(dim + 1));
  for (int i = 0; i < dim; ++i) {
    for (int j = 0; j < dim; ++j) {
      RPoly s;
      for (int k = 0; k < dim; ++k) s += h[i][k] * d[k][j];
      mm.m[i][j] = s;
    }
    mm.m[i][dim] = W * keyframe_lerp(c0[i], c1[i]);
  }
  mm.m[dim][dim] = W;
  return mm;
}

}  // namespace eccd
