#pragma once
// Scene: one pair of moving objects, as read from a scene file
// (../shared/spec/scene-format.md, format "ellipse-ccd-scene/1").
//
// Every number of a scene is an exact rational, so the scene is held in exact
// rationals; a pipeline converts what it needs into its own arithmetic.
// Motions are kept in the form the file gave (static, matrix, kinematic,
// euler, cycloidal); kernel/motion.hpp turns the rational forms into
// polynomial matrices.
#include "number/rational_traits.hpp"
#include "kernel/answer.hpp"
#include "kernel/polynomial.hpp"

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace eccd {

// The size H = dim + 1 of a scene's homogeneous matrices (Q, M(t)): the
// template parameter H of MovingPair, PreparedPair and the motion functions.
inline constexpr int H_2D = 3;  // ellipses in the plane
inline constexpr int H_3D = 4;  // ellipsoids in space

using RPoly = Poly<Rational>;

struct StaticMotion {};
struct MatrixMotion {  // M(t) entry by entry; size (dim+1) x (dim+1)
  std::vector<std::vector<RPoly>> m;
};
struct KinematicMotion {  // 2D, 003 eq. (3)
  std::array<RPoly, 4> d;
};
struct EulerMotion {  // 3D, 002 section 2: quaternion e and translation v / v3
  std::array<RPoly, 4> e;
  std::array<RPoly, 3> v;
  RPoly v3;
};
struct CycloidalMotion {         // 2D, not rational (003 section V)
  Rational theta0, theta1;       // angle = pi * (theta0 + theta1 t)
  std::array<Rational, 2> x, y;  // translation (x0 + x1 t, y0 + y1 t)
};
using Motion = std::variant<StaticMotion, MatrixMotion, KinematicMotion, EulerMotion, CycloidalMotion>;

inline const char* motion_type_name(const Motion& m) {
  static const char* names[] = {"static", "matrix", "kinematic", "euler", "cycloidal"};
  return names[m.index()];
}

struct SceneObject {
  std::vector<std::vector<Rational>> Q;  // (dim+1) x (dim+1), X^T Q X <= 0 is the solid
  Motion motion;
};

struct Scene {
  std::string path;  // file it was read from ("" if built in memory)
  std::string name;
  std::string note;
  int dim = 2;
  SceneObject a, b;
  // "parameters" (scene-format.md, "Independent motions"): false = "shared"
  // (A(t) and B(t) at one t, the default); true = "independent" (A(s), B(t),
  // s and t unrelated; its answer has s_intervals and t_intervals).
  bool independent = false;
  std::optional<Answer> answer;  // stored answer, if the file has one
  std::string source_text;       // the JSON text it was read from (io/scene_reader.hpp); "" if built in code
};

}  // namespace eccd
