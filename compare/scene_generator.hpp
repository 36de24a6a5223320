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
//   overlap    both solids translate linearly (degree 1,
//              motion "translation"): at t0 B is pushed δ = 10^-e into A along
//              the common normal of a touching pose (as for touch), and moves
//              along the tangent plane with constant velocity, so the pair
//              just overlaps on a short interval around t0 (overlap depth δ
//              along the normal; lengths ~ sqrt(δ)). This is the class of
//              "missed-0.021", which the double Bézier method once reported
//              collision-free (floating/bezier_ccd.hpp, step 2).
//   graze      the same with δ = 0: the collision set is exactly {t0}, an
//              isolated touch (strict convexity, as for touch).
//   decimal    realistic input: a scene of a generic
//              family (colliding, free or touch, chosen by the seed; the note
//              says which) whose every coefficient and semi-axis is rounded to
//              a decimal of `digits` significant digits (6, 9, 12, 15), as a
//              simulator or CAD file writes it. Written as decimals; they are
//              exact rationals, so the exact pipeline stays the ground truth.
//   keyframe   keyframed rigid motions: each body has two key poses (position,
//              orientation quaternion; 2D: [w, z]) written as decimals of
//              `digits` significant digits, interpolated exactly by the rule of
//              ../shared/spec/animation-format.md, "The motion of a body in
//              frame k" (paper 001 section 5): centre (1-τ)c_0 + τc_1,
//              orientation (1-τ)q_0 + τq'_1 with q'_1 = -q_1 when q_0·q_1 < 0,
//              rotation of 3D: the `euler` matrix of e = q(τ), 2D: `kinematic`
//              with d2 = w(τ), d3 = -z(τ). One such joint gives degree 2 (fixed
//              centre) or 3; degrees 4-6 chain 2 or 3 keyframed joints with
//              constant decimal bone offsets (a skeleton: root joint, elbow,
//              wrist), the root's centre fixed or interpolated; every joint
//              follows the same rule. One joint is written as `euler` (3D) or
//              `kinematic` (2D) with Bernstein coefficients = the key values;
//              a chain as a `matrix` motion (exact products of the decimals).
//              The interpolation is kernel/keyframe_motion.hpp's, the code
//              `eccd animate` runs (one rule for the family and animations).
//   cycloidal, independent: motions that are not shared-parameter
//              rational ones: cycloidal (2D, 003 section V) and independent
//              straight paths A(s), B(t) (3D, 001 section 4), each with a kind
//              (colliding, free, touch, ...) picked by the seed and stated in
//              the note; generated once per dimension at degree 1, in their own
//              functions (compare/motion_families.hpp, which describes them).
// The pipelines never see these facts: the harness takes the exact pipeline
// as ground truth, and a test checks the construction against it.
// Requirements: exact rationals only (no floating value decides anything;
// a double square root only picks a rational radius that is then checked).
#include "number/rational_traits.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace eccd {

struct GeneratorSpec {
  int dim = 2;
  int degree = 2;                    // motion degree, 1..8 (the report uses 2..6)
  std::string family = "colliding";  // colliding | free | touch | near-miss | overlap | graze | decimal | keyframe |
                                     // cycloidal | independent
  std::string motion = "kinematic";  // 2D: kinematic; 3D: euler | affine; overlap and graze: translation
  int d_exponent = 0;                // near-miss: separation d = 10^-d_exponent (>= 1); overlap: depth 10^-d_exponent
  int digits = 0;                    // decimal, keyframe: significant digits of every number (1..30)
  std::uint64_t seed = 1;            // this scene's seed
};

struct GeneratedScene {
  GeneratorSpec spec;
  std::string name;
  nlohmann::ordered_json doc;  // the scene file (format ellipse-ccd-scene/1)
  std::optional<Rational> t0;  // touch / near-miss: the constructed instant
};

// Throws std::invalid_argument for a spec it cannot build (unknown family or
// motion, a motion of the other dimension, near-miss or keyframe with affine
// motion, touch/near-miss below degree 2, overlap/graze not of degree 1 with
// motion translation, decimal/keyframe without digits, keyframe outside 2..6).
GeneratedScene generate_scene(const GeneratorSpec& spec);

// The per-scene seed of scene `index` of a combination, from the run's seed.
std::uint64_t scene_seed(std::uint64_t run_seed, const GeneratorSpec& combination, int index);

// The motions of a dimension ("kinematic" in 2D; "euler", "affine" in 3D) and
// whether a family is generated for a motion (overlap and graze: only the
// motion "translation", of degree 1, in both dimensions).
std::vector<std::string> motions_for(int dim);
bool family_applies(const std::string& family, const std::string& motion);
// Families whose scenes are linear translations (degree 1 whatever the plan's degrees).
bool linear_family(const std::string& family);
// The families of the realistic-input kind (decimal, keyframe).
bool realistic_family(const std::string& family);

// A run of the generator: every combination dim x degree x family x motion
// (x separation for near-miss, x depth for overlap, x digits for decimal and
// keyframe), `count` scenes each, seeds from scene_seed. Overlap and graze
// scenes are generated once per dimension (degree 1), not per degree.
struct GeneratePlan {
  std::vector<int> dims{2, 3};
  std::vector<int> degrees{2, 3, 4, 5, 6};
  std::vector<std::string> families{"colliding", "free",  "touch",   "near-miss",
                                    "overlap",   "graze", "decimal", "keyframe"};
  std::vector<std::string> motions;  // empty = every motion of the dimension
  std::vector<int> d_exponents{2, 4, 6, 8, 10, 12, 14, 16};
  std::vector<int> depth_exponents{3, 5, 7, 9};  // overlap depths 10^-e
  std::vector<int> digits{6, 9, 12, 15};         // decimal and keyframe
  int count = 1;
  std::uint64_t seed = 20261121;
};
std::vector<GeneratorSpec> plan_scenes(const GeneratePlan& plan);

// The "key=value" facts the generator writes into the scene's note
// (family, dim, degree, motion, d, depth, digits, base, t0, seed), read back;
// nullopt if the note is not a generator's.
std::optional<GeneratorSpec> spec_from_note(const std::string& note);

// "1e-8" for exponent 8.
std::string separation_label(int d_exponent);

// x rounded to `digits` significant decimal digits (half away from zero),
// exactly; and an exact decimal string for a rational whose denominator has
// no prime factor but 2 and 5 (else "p/q").
Rational round_significant(const Rational& x, int digits);
std::string exact_decimal(const Rational& x);

}  // namespace eccd
