// The building blocks the scene generators share (compare/scene_generator.cpp
// and compare/realistic_families.cpp; not part of the API).
//
// Statement. Exact rational geometry for constructing scenes: random
// rational unit vectors and rotations (Householder reflections), shapes with
// a prescribed outward normal at a point (for touching families),
// homogeneous polynomial motion matrices, the checks a generated weight must
// pass, and the JSON writers of shapes and motions (exact "p/q" strings, or
// exact decimals while g_decimal_output is set for the realistic families).
// Built is what a family's builder returns: both shapes and motions, and the
// instant t0 of the constructed event if any. Everything is seeded by the
// caller's Rng, so a scene is a function of its GeneratorSpec.
// Requirements: GMP rationals (number/rational_traits.hpp), nlohmann json.
#pragma once

#include "compare/scene_generator.hpp"
#include "compare/seeded_rng.hpp"

#include "kernel/motion.hpp"
#include "kernel/poly_matrix.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace eccd::scene_building {

using Rng = SeededRng;
using Vec = std::vector<Rational>;
using Mat = std::vector<Vec>;
// Homogeneous polynomial matrices (size dim + 1).
using HMat = std::vector<std::vector<RPoly>>;

// Squared semi-axes alpha and the point x on x^T diag(1/alpha) x = 1 whose
// outward normal is the unit vector n.
struct Tangency {
  Vec alpha, point;
};

// One generated pair: shapes (squared semi-axes alpha, or semi-axes for the
// realistic families), motions and the instant t0 of the constructed event.
struct Built {
  Vec alpha_a, alpha_b;
  Motion ma, mb;
  std::optional<Rational> t0;
  Vec axes_a, axes_b;                                    // realistic families: semi-axes (decimals) instead of alpha
  std::optional<nlohmann::ordered_json> json_a, json_b;  // keyframe: the motion as written (Bernstein key values)
  std::string base;                                      // decimal: the family it was rounded from
};

template <int N>
HMat to_hmat(const Motion& m) {
  auto M = motion_matrix<Rational, N>(m, [](const Rational& x) { return x; });
  HMat h(N, std::vector<RPoly>(N));
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) h[i][j] = M[i][j];
  return h;
}

// Set while writing a realistic-input scene: numbers are written as exact decimals.
extern thread_local bool g_decimal_output;

RPoly constant(const Rational& c);
RPoly from_bernstein(const std::vector<Rational>& ctrl);
RPoly random_poly(Rng& r, int deg, long lo, long hi, long den);
bool vanishes_on_unit_interval(const RPoly& p);
bool badly_scaled(const RPoly& w);
Rational dot(const Vec& a, const Vec& b);
Vec random_unit(Rng& r, int dim);
Tangency shape_with_normal(Rng& r, const Vec& n);
Mat identity(int n);
Mat mat_mul(const Mat& a, const Mat& b);
Vec mat_vec(const Mat& a, const Vec& v);
Mat householder(const Vec& w);
Vec orthogonal_to(Rng& r, const Vec& n);
Mat rotation_taking(Rng& r, const Vec& m, const Vec& n);
HMat hmul(const HMat& a, const HMat& b);
HMat hconst(const Mat& rot, const Vec& shift);
int hdegree(const HMat& h);
std::string number_text(const Rational& x);
nlohmann::ordered_json poly_json(const RPoly& p);
nlohmann::ordered_json bern_json(const Rational& c0, const Rational& c1);
nlohmann::ordered_json motion_json(const Motion& m);
nlohmann::ordered_json shape_json(const Vec& alpha);
nlohmann::ordered_json semi_axes_json(const Vec& axes);
Vec random_axes(Rng& r, int dim);
int motion_degree(int dim, const Motion& m);

// 10^e, exactly (e may be negative).
Rational pow10(int e);

// The families' builders (compare/scene_generator.cpp: colliding, free,
// touch, near-miss; compare/realistic_families.cpp: decimal, keyframe,
// overlap and graze). Each throws std::domain_error for a pick to retry.
Built build_random(Rng& r, const GeneratorSpec& s);
Built build_touch(Rng& r, const GeneratorSpec& s);
Built build_decimal(Rng& r, const GeneratorSpec& s);
Built build_keyframe(Rng& r, const GeneratorSpec& s);
Built build_linear_overlap(Rng& r, const GeneratorSpec& s);

}  // namespace eccd::scene_building
