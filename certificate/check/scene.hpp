#pragma once
// The checker's own reading of a scene file (../shared/spec/scene-format.md,
// "ellipse-ccd-scene/1"): what a certificate speaks about, and no more.
//
// Statement. The workbench's scene reader (io/scene_reader.hpp) validates far
// more and includes the exact root isolation of exact/; the checker must not
// depend on it. This reader takes the scene's JSON (certificate/check/
// strict_json.hpp) and gives, in exact rationals:
//   - dim (2 or 3), whether the motions are independent, and whether a
//     motion is cycloidal (not rational: no exact certificate applies), with
//     its parameters θ0, θ1, x0, x1, y0, y1 (scene-format.md);
//   - each object's shape matrix Q (H = dim + 1; X^T Q X <= 0 the solid):
//     semi_axes a_i give diag(1/a_i², ..., -1), semi_axes_squared s_i give
//     diag(1/s_i, ..., -1), matrix is taken as written;
//   - each rational motion as a polynomial matrix M(t) up to a non-zero
//     polynomial factor (which changes no root of f(λ;t), see
//     certificate/check/pencil.hpp): static I; matrix as written; kinematic
//     003 eq. (3); euler [[v3 R', E v], [0, E v3]] with R' = E·R the
//     quaternion matrix (scene-format.md).
// Numbers: "-63", "3/7", "1.8", "2.5e-3" (exact decimal value, exponent at
// most 10000 in size) or a JSON integer; a JSON number with a fraction part
// or exponent is refused. Polynomials: an array of power-basis coefficients,
// {"bernstein": [...]}, or a bare number. Everything else is the workbench
// reader's business: a scene the checker cannot read throws SceneReadError
// naming the file and the JSON place. Shapes and motions are not re-validated
// (a real ellipse, w(t) ≠ 0): the checker checks instead that det M(t) has
// no root in [0, 1] (certificate/check/pencil.hpp).
// Requirements: GMP; nlohmann json.
#include "certificate/check/qpoly.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace eccd::check {

struct SceneReadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using QMatrix = std::vector<std::vector<mpq_class>>;
using PolyMatrix = std::vector<std::vector<QPoly>>;

struct CheckObject {
  QMatrix Q;
  PolyMatrix M;             // empty for a cycloidal motion
  std::string motion_type;  // static, matrix, kinematic, euler, cycloidal
  std::vector<mpq_class>
      cycloid;  // cycloidal: θ0, θ1, x0, x1, y0, y1 (angle π(θ0 + θ1 t), translation (x0 + x1 t, y0 + y1 t))
};

struct CheckScene {
  int dim = 2;
  bool independent = false;
  bool cycloidal = false;
  CheckObject a, b;
  nlohmann::json doc;  // the scene's JSON, for the certificate's scene claim
};

// `doc` as parsed by parse_strict; `label` names the file in messages.
CheckScene read_check_scene(const nlohmann::json& doc, const std::string& label);

// An exact number of the scene format (string or JSON integer); throws SceneReadError naming label and place.
mpq_class scene_number(const nlohmann::json& j, const std::string& label, const std::string& place);

}  // namespace eccd::check
