#pragma once
// Scene generators for the robustness report: seeded, reproducible pairs of
// moving ellipses (2D) or ellipsoids (3D) under rational motions of a chosen
// degree, in four families whose kind of answer is known by construction.
//
// Statement. Every number is an exact rational, so a scene is the same for
// every arithmetic; a generated scene is written in the scene format
// (../shared/spec/scene-format.md) and read back by the scene reader. The
// degree of a scene is the highest degree in t among the entries of M_A(t)
// and M_B(t) (the spec's definition); the generator checks it and retries
// with the next sub-seed if a leading coefficient cancels.
//
// Motions.
//   kinematic (2D, 003 eq. (3)): rotation part (d2, d3) of degree k, centre
//     path (x(t), y(t)) of degree p, d0 = (x d3 + y d2)/2, d1 = (y d3 - x d2)/2,
//     so the centre is exactly (x, y); degree 2k + p.
//   euler (3D, 002 section 2): quaternion e of degree k, translation v of
//     degree p over v3 = 1; degree 2k + p.
//   affine (3D): M = [[L(t), v(t)], [0, 1]] with L(t) a constant rational
//     rotation plus a perturbation whose Bernstein coefficients lie in
//     [-3/10, 3/10] (so ||L(t)|| <= 1.9), det L(t) ≠ 0 on [0, 1] checked exactly.
//
// Families.
//   colliding  random motions; B's centre path is shifted so that both
//              centres coincide at a rational t1: the solids overlap at t1.
//   free       the centre paths' Bernstein control points keep A in
//              x <= -(R_A + gap) and B in x >= R_B + gap (R = a bound on the
//              bounding-sphere radius): separated by the plane x = 0.
//   touch      touch-and-separate at a rational t0. In a common frame moved
//              by a rational motion G(t) (kinematic, euler or affine), A is
//              axis-aligned at the origin; B is placed so that at t0 it touches
//              A at a rational point p with opposite rational unit normals
//              (shapes given by semi_axes_squared so that p exists); B then
//              moves by s(t) = σ(t) n + a(t) τ with σ(t) = δ + (t - t0)² h(t),
//              h > 0 (Bernstein coefficients in [1/2, 3]), a(t0) = 0, τ ⊥ n,
//              and in 3D also twists about the normal line through p. The
//              tangent plane at p separates A from B + s(t) with gap σ(t), and
//              for δ = 0 they meet only at t0 (strict convexity), so the
//              collision set is exactly {t0}; affine maps keep touching and
//              separation.
//   near-miss  touch with δ = d = 10^-e: with a rigid G the minimum separation
//              over [0, 1] is exactly d, reached at t0, and the pair never
//              collides. (Not generated for affine motions, which do not keep
//              distances.)
// The pipelines never see these facts: the harness takes the exact pipeline
// as ground truth, and a test checks the construction against it.
// Requirements: exact rationals only (no floating value decides anything;
// a double square root only picks a rational radius that is then checked).
#include "exact/rational_traits.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace eccd {

struct GeneratorSpec {
  int dim = 2;
  int degree = 2;                    // motion degree, 1..8 (the report uses 2..6)
  std::string family = "colliding";  // colliding | free | touch | near-miss
  std::string motion = "kinematic";  // 2D: kinematic; 3D: euler | affine
  int d_exponent = 0;                // near-miss: separation d = 10^-d_exponent (>= 1)
  std::uint64_t seed = 1;            // this scene's seed
};

struct GeneratedScene {
  GeneratorSpec spec;
  std::string name;
  nlohmann::ordered_json doc;  // the scene file (format ellipse-ccd-scene/1)
  std::optional<Rational> t0;  // touch / near-miss: the constructed instant
};

// Throws std::invalid_argument for a spec it cannot build (unknown family or
// motion, a motion of the other dimension, near-miss with affine motion,
// touch/near-miss below degree 2).
GeneratedScene generate_scene(const GeneratorSpec& spec);

// The per-scene seed of scene `index` of a combination, from the run's seed.
std::uint64_t scene_seed(std::uint64_t run_seed, const GeneratorSpec& combination, int index);

// The motions of a dimension ("kinematic" in 2D; "euler", "affine" in 3D) and
// whether a family is generated for a motion.
std::vector<std::string> motions_for(int dim);
bool family_applies(const std::string& family, const std::string& motion);

// A run of the generator: every combination dim x degree x family x motion
// (x separation for near-miss), `count` scenes each, seeds from scene_seed.
struct GeneratePlan {
  std::vector<int> dims{2, 3};
  std::vector<int> degrees{2, 3, 4, 5, 6};
  std::vector<std::string> families{"colliding", "free", "touch", "near-miss"};
  std::vector<std::string> motions;  // empty = every motion of the dimension
  std::vector<int> d_exponents{2, 4, 6, 8, 10, 12, 14, 16};
  int count = 1;
  std::uint64_t seed = 20261121;
};
std::vector<GeneratorSpec> plan_scenes(const GeneratePlan& plan);

// The "key=value" facts the generator writes into the scene's note
// (family, dim, degree, motion, d, t0, seed), read back; nullopt if the note
// is not a generator's.
std::optional<GeneratorSpec> spec_from_note(const std::string& note);

// "1e-8" for exponent 8.
std::string separation_label(int d_exponent);

}  // namespace eccd
