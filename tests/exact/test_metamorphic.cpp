// Metamorphic tests of the exact pipeline (tests/support/metamorphic.hpp):
// swapping A and B, one common rigid motion (constant, and time-dependent)
// applied to both objects, reversing time (t -> 1 - t mirrors the intervals)
// and scaling space uniformly must not change the certified answer, beyond
// the mirroring. Scenes come from the generator (compare/scene_generator.hpp)
// with per-scene seeds derived from one base seed, which the environment
// variable ECCD_METAMORPHIC_SEED overrides; every scene prints one line with
// its seed, and a failure names it (Catch INFO).
//
// Scene set (about 20 s in Release on 2 cores): 2D kinematic degrees 2..4 x
// {colliding, free, touch, near-miss} x 3 seeds, the test-support random
// scenes, and "multi-pass" scenes built here (three separate intervals, so
// that the reversal of the interval order is exercised); 3D euler degrees
// 2..4 x the four families, affine degrees 1..3, random euler scenes and 3D
// multi-pass scenes. Each scene is compared with its matrix-form copy, the
// swap, three common rigid motions (constant; rotation constant and
// translation linear in t; rotation moving with t, matrix degree 2), a
// uniform scaling by a random rational k and the time reversal. The
// parameters of the transformations derive from the scene's seed.
#include "compare/scene_generator.hpp"
#include "compare/seeded_rng.hpp"
#include "io/scene_reader.hpp"
#include "tests/support/metamorphic.hpp"
#include "tests/support/scenes3d.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdlib>
#include <iostream>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;

namespace {

constexpr std::uint64_t kDefaultBaseSeed = 20260601;

std::uint64_t base_seed() {
  static const std::uint64_t seed = [] {
    const char* env = std::getenv("ECCD_METAMORPHIC_SEED");
    if (!env || !*env) return kDefaultBaseSeed;
    std::string s(env);
    if (s.find_first_not_of("0123456789") != std::string::npos || s.size() > 19)
      throw std::invalid_argument("ECCD_METAMORPHIC_SEED must be a non-negative whole number, got '" + s + "'");
    return std::uint64_t(std::stoull(s));
  }();
  static bool printed = false;
  if (!printed) {
    std::cout << "metamorphic: base seed=" << seed
              << (std::getenv("ECCD_METAMORPHIC_SEED") ? " (from ECCD_METAMORPHIC_SEED)"
                                                       : " (default; set ECCD_METAMORPHIC_SEED to change)")
              << "\n";
    printed = true;
  }
  return seed;
}

// Seeded parameters of the transformations (rotation, translation, k).
struct Rng : SeededRng {
  RPoly poly(int deg) {
    std::vector<Rational> c;
    for (int i = 0; i <= deg; ++i) c.push_back(frac(-9, 9, uniform(1, 4)));
    return RPoly(c);
  }
};

Answer exact_answer(const Scene& s) { return s.dim == 2 ? solve_exact(s).answer : solve_exact_3d(s).answer; }

// A random rational rotation (Pythagorean triple in 2D, integer quaternion
// in 3D) followed by a translation of degree `tdeg` in t.
PolyRows random_rigid(Rng& r, int dim, int tdeg) {
  if (dim == 2) {
    long m = r.uniform(2, 6), n = r.uniform(1, m - 1);
    long a = m * m - n * n, b = 2 * m * n;
    if (r.uniform(0, 1)) std::swap(a, b);
    if (r.uniform(0, 1)) a = -a;
    if (r.uniform(0, 1)) b = -b;
    return rigid_2d(a, b, r.poly(tdeg), r.poly(tdeg));
  }
  std::array<long, 4> e{};
  do {
    for (auto& x : e) x = r.uniform(-3, 3);
  } while (e[0] == 0 && e[1] == 0 && e[2] == 0 && e[3] == 0);
  return rigid_3d(e, {r.poly(tdeg), r.poly(tdeg), r.poly(tdeg)});
}

// A 2D rigid motion whose rotation also moves: the kinematic-image motion
// with d0..d3 linear in t (matrix degree 2), d2 kept away from zero.
PolyRows random_kinematic_g(Rng& r) {
  KinematicMotion k;
  for (int i = 0; i < 4; ++i) k.d[i] = r.poly(1);
  k.d[2] = RPoly(std::vector<Rational>{Rational(r.uniform(3, 6)), r.frac(-2, 2, 1)});  // |d2| >= 1 on [0, 1]
  return world_matrix(Motion(k), 2);
}

// A 3D rigid motion whose rotation also moves: quaternion linear in t (E > 0
// on [0, 1] since e0 stays away from zero), translation constant.
PolyRows random_euler_g(Rng& r) {
  EulerMotion em;
  em.e[0] = RPoly(std::vector<Rational>{Rational(r.uniform(3, 5)), r.frac(-2, 2, 1)});
  for (int i = 1; i < 4; ++i) em.e[i] = RPoly(std::vector<Rational>{r.frac(-3, 3, 1), r.frac(-3, 3, 1)});
  for (int i = 0; i < 3; ++i) em.v[i] = r.poly(0);
  em.v3 = RPoly::constant(Rational(1));
  return world_matrix(Motion(em), 3);
}

// A scene built here whose answer has several intervals (the generator's
// families have at most one): A rests at the origin; B's centre moves along x
// by x(t) = L (t - t1)(t - t2)(t - t3), so it passes through A three times,
// with a small constant offset in the other coordinates, while turning with a
// rotation of degree 2k: motion degree 3 + 2k. The t_i are
// rational, at least 1/5 apart, and L makes |x| > 12 between them (larger
// than both bounding radii), so the three passes are separate intervals.
Scene multi_pass_scene(int dim, std::uint64_t seed, int k) {
  Rng r{seed};
  std::vector<long> ts;
  while (ts.size() < 3) {
    long v = r.uniform(1, 9);
    bool ok = true;
    for (long u : ts) ok = ok && std::labs(u - v) >= 2;
    if (ok) ts.push_back(v);
  }
  RPoly x = RPoly::constant(Rational(r.uniform(3000, 5000)) * (r.uniform(0, 1) ? 1 : -1));
  for (long u : ts) x = x * RPoly(std::vector<Rational>{Rational(-u, 10), Rational(1)});
  for (auto& c : x.c) c.canonicalize();
  auto shape = [&]() {
    std::vector<std::vector<Rational>> q(dim + 1, std::vector<Rational>(dim + 1, Rational(0)));
    for (int i = 0; i < dim; ++i) q[i][i] = Rational(1) / r.frac(1, 9, 1);  // semi-axes^2 in 1..9
    q[dim][dim] = -1;
    return q;
  };
  Scene s;
  s.dim = dim;
  s.name = "multi-pass-" + std::to_string(dim) + "d-" + std::to_string(seed);
  s.a = {shape(), Motion(StaticMotion{})};
  std::vector<RPoly> centre{x};
  for (int i = 1; i < dim; ++i) centre.push_back(RPoly::constant(r.frac(-4, 4, 4)));
  auto rot = [&]() {
    if (k == 0) return RPoly::constant(r.frac(1, 6, 2));
    std::vector<Rational> c;
    for (int i = 0; i <= k; ++i) c.push_back(r.frac(-6, 6, 2));
    return RPoly(c);
  };
  if (dim == 2) {
    KinematicMotion km;
    do {
      km.d[2] = rot();
      km.d[3] = rot();
    } while (vanishes_on_unit_interval(km.d[2] * km.d[2] + km.d[3] * km.d[3]));
    km.d[0] = Rational(1, 2) * (centre[0] * km.d[3] + centre[1] * km.d[2]);
    km.d[1] = Rational(1, 2) * (centre[1] * km.d[3] - centre[0] * km.d[2]);
    s.b = {shape(), Motion(km)};
  } else {
    EulerMotion em;
    RPoly E;
    do {
      for (auto& e : em.e) e = rot();
      E = em.e[0] * em.e[0] + em.e[1] * em.e[1] + em.e[2] * em.e[2] + em.e[3] * em.e[3];
    } while (vanishes_on_unit_interval(E));
    for (int i = 0; i < 3; ++i) em.v[i] = centre[i];
    em.v3 = RPoly::constant(Rational(1));
    s.b = {shape(), Motion(em)};
  }
  return s;
}

struct Transformed {
  std::string name;
  Scene scene;
  bool mirrored = false;  // time reversal: compare with the mirrored original answer
};

struct SceneCase {
  GeneratorSpec spec;
  bool moving_rotation = true;  // also a common motion whose rotation depends on t
};

std::vector<Transformed> transforms_of(const Scene& s, const SceneCase& c) {
  Rng r{c.spec.seed ^ 0x6d6574616d6f7270ULL};
  std::vector<Transformed> out;
  out.push_back({"matrix", as_matrix_motion(s), false});
  out.push_back({"swap", swap_objects(s), false});
  PolyRows g0 = random_rigid(r, s.dim, 0), g1 = random_rigid(r, s.dim, 1);
  REQUIRE(is_rigid_motion(g0, s.dim));
  REQUIRE(is_rigid_motion(g1, s.dim));
  out.push_back({"rigid-const", with_common_motion(s, g0), false});
  out.push_back({"rigid-linear", with_common_motion(s, g1), false});
  if (c.moving_rotation) {
    PolyRows g2 = s.dim == 2 ? random_kinematic_g(r) : random_euler_g(r);
    REQUIRE(is_rigid_motion(g2, s.dim));
    out.push_back({"rigid-rotating", with_common_motion(s, g2), false});
  }
  Rational k(r.uniform(1, 12), r.uniform(1, 12));
  k.canonicalize();
  if (k == 1) k = Rational(7, 3);
  out.push_back({"scaled(" + k.get_str() + ")", scaled_space(s, k), false});
  out.push_back({"reversed", reversed_time(s), true});
  return out;
}

std::string spec_text(const GeneratorSpec& sp) {
  std::ostringstream o;
  o << "dim=" << sp.dim << " family=" << sp.family;
  if (sp.family == "near-miss") o << "(" << separation_label(sp.d_exponent) << ")";
  o << " motion=" << sp.motion << " degree=" << sp.degree << " seed=" << sp.seed;
  return o.str();
}

void run_case(SceneCase c, int index) {
  c.spec.seed = scene_seed(base_seed(), c.spec, index);
  const GeneratorSpec& sp = c.spec;
  INFO("metamorphic scene " << spec_text(sp) << " (base seed " << base_seed()
                            << "; rerun with ECCD_METAMORPHIC_SEED=" << base_seed() << ")");
  auto start = std::chrono::steady_clock::now();
  Scene s;
  if (sp.family == "multi-pass") {
    s = multi_pass_scene(sp.dim, sp.seed, (sp.degree - 3) / 2);
  } else if (sp.family == "random") {
    // The test-support random scenes (independent random motions of both
    // objects, tests/support/scenes*.hpp). std::mt19937_64 is portable; the
    // std distributions they use are those of this standard library, so
    // these seeds reproduce with libstdc++.
    std::mt19937_64 rng(sp.seed);
    s = sp.dim == 2 ? random_kinematic_scene(rng, sp.degree / 2) : random_euler_scene(rng, sp.degree / 2);
    s.name = "random-" + std::to_string(sp.dim) + "d-" + std::to_string(sp.seed);
  } else {
    GeneratedScene g = generate_scene(sp);
    s = parse_scene(g.doc.dump(), g.name);
  }
  Answer original = exact_answer(s);
  INFO("original answer: " << answer_text(original));
  REQUIRE(original.undecided.empty());
  std::string failed, slowest;
  double slowest_sec = -1;
  for (const auto& t : transforms_of(s, c)) {
    auto t_start = std::chrono::steady_clock::now();
    Answer got = exact_answer(t.scene);
    double t_sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    if (t_sec > slowest_sec) {
      slowest_sec = t_sec;
      slowest = t.name;
    }
    std::string why = answer_mismatch(t.mirrored ? mirror_answer(original) : original, got);
    INFO("transform " << t.name << ": answer " << answer_text(got));
    CHECK(why == "");
    if (!why.empty()) failed += " " + t.name + " (" + why + ")";
  }
  double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f s, slowest %s %.2f s", sec, slowest.c_str(), slowest_sec);
  std::cout << "metamorphic: " << spec_text(sp) << " intervals=" << original.intervals.size()
            << " contacts=" << original.contacts.size() << " transforms "
            << (failed.empty() ? std::string("ok") : "FAILED:" + failed) << " (" << buf << ")" << std::endl;
}

SceneCase scene_case(int dim, const std::string& family, const std::string& motion, int degree, int d_exponent = 0,
                     bool moving_rotation = true) {
  SceneCase c;
  c.spec.dim = dim;
  c.spec.family = family;
  c.spec.motion = motion;
  c.spec.degree = degree;
  c.spec.d_exponent = family == "near-miss" ? d_exponent : 0;
  c.moving_rotation = moving_rotation;
  return c;
}

// The scene set: every (motion, degree, family) below, `count` scenes each
// (scene i has seed scene_seed(base, spec, i)); near-miss scenes take their
// separation 10^-e from kNearMissExponents in turn.
struct Combination {
  int dim;
  std::string motion;
  std::vector<int> degrees;
  std::vector<std::string> families;
  int count;
  bool moving_rotation;
};
const std::vector<int> kNearMissExponents{4, 8, 12};

void run_combinations(const std::vector<Combination>& combos) {
  for (const auto& cb : combos)
    for (int degree : cb.degrees)
      for (const auto& family : cb.families)
        for (int i = 0; i < cb.count; ++i) {
          int e = kNearMissExponents[std::size_t(i) % kNearMissExponents.size()];
          SECTION(cb.motion + " " + family + " degree " + std::to_string(degree) + " #" + std::to_string(i)) {
            run_case(scene_case(cb.dim, family, cb.motion, degree, e, cb.moving_rotation), i);
          }
        }
}

}  // namespace

TEST_CASE(
    "metamorphic: 2D generated scenes keep their exact answer under swap, rigid motions, scaling and time reversal",
    "[metamorphic][exact]") {
  run_combinations({{2, "kinematic", {2, 3, 4}, {"colliding", "free", "touch", "near-miss"}, 3, true},
                    {2, "kinematic", {2, 4}, {"random"}, 4, true},
                    {2, "kinematic", {3, 5}, {"multi-pass"}, 4, true}});
}

TEST_CASE(
    "metamorphic: 3D generated scenes keep their exact answer under swap, rigid motions, scaling and time reversal",
    "[metamorphic][exact]") {
  run_combinations({{3, "euler", {2, 3, 4}, {"colliding", "free", "touch", "near-miss"}, 1, true},
                    {3, "affine", {1}, {"colliding", "free"}, 1, true},
                    {3, "affine", {2}, {"colliding", "free", "touch"}, 1, true},
                    {3, "affine", {3}, {"touch"}, 1, true},
                    {3, "euler", {2}, {"random"}, 4, true},
                    {3, "euler", {3, 5}, {"multi-pass"}, 2, true}});
}

TEST_CASE("metamorphic: the comparisons can fail", "[metamorphic][exact]") {
  // A touch scene whose instant t0 is not 1/2: its answer is not symmetric,
  // so the reversed scene's answer must match the mirrored original and must
  // NOT match the original itself (the mirroring is not vacuous), and the
  // original must not match its own mirror.
  GeneratorSpec sp;
  sp.dim = 2;
  sp.family = "touch";
  sp.motion = "kinematic";
  sp.degree = 2;
  GeneratedScene g;
  for (int i = 0;; ++i) {
    REQUIRE(i < 50);
    sp.seed = scene_seed(base_seed(), sp, 1000 + i);
    g = generate_scene(sp);
    REQUIRE(g.t0);
    if (*g.t0 != Rational(1, 2)) break;
  }
  INFO("scene " << spec_text(sp) << " t0=" << g.t0->get_str());
  Scene s = parse_scene(g.doc.dump(), g.name);
  Answer original = exact_answer(s), reversed = exact_answer(reversed_time(s));
  INFO("original " << answer_text(original) << "; reversed " << answer_text(reversed));
  REQUIRE(original.intervals.size() == 1);
  CHECK(answer_mismatch(mirror_answer(original), reversed) == "");
  CHECK(answer_mismatch(original, reversed) != "");
  CHECK(answer_mismatch(mirror_answer(original), original) != "");
  // The touch instant is rational: both brackets are exact, t0 and 1 - t0.
  CHECK(*original.intervals[0].first.lo == *g.t0);
  CHECK(*reversed.intervals[0].first.lo == Rational(1) - *g.t0);

  // Perturbations the comparison must reject.
  Answer moved = original;
  Rational shift = Rational(1, 1000);
  for (auto* x : {&moved.intervals[0].first, &moved.intervals[0].second}) {
    *x->lo += shift;
    *x->hi += shift;
  }
  CHECK(answer_mismatch(original, moved) != "");
  Answer fewer = original;
  fewer.contacts.clear();
  CHECK(answer_mismatch(original, fewer) != "");
  Answer flipped = original;
  flipped.collides = !flipped.collides;
  CHECK(answer_mismatch(original, flipped) != "");
  Answer uncertified = original;
  uncertified.intervals[0].first.lo.reset();
  CHECK(answer_mismatch(original, uncertified) != "");
  std::cout << "metamorphic: non-vacuity check on " << spec_text(sp) << " t0=" << g.t0->get_str() << " ok" << std::endl;

  // A scene with three intervals: the reversed answer matches the mirrored
  // original only with the interval order reversed and start / end swapped.
  std::uint64_t mp_seed = scene_seed(base_seed(), sp, 2000);
  INFO("multi-pass scene seed " << mp_seed);
  Scene m = multi_pass_scene(2, mp_seed, 0);
  Answer m_orig = exact_answer(m), m_rev = exact_answer(reversed_time(m));
  INFO("multi-pass original " << answer_text(m_orig) << "; reversed " << answer_text(m_rev));
  REQUIRE(m_orig.intervals.size() >= 2);
  CHECK(answer_mismatch(mirror_answer(m_orig), m_rev) == "");
  CHECK(answer_mismatch(m_orig, m_rev) != "");
  Answer keep_order = m_orig;  // each instant mirrored, start/end swapped, order kept
  for (auto& [st, en] : keep_order.intervals) {
    Instant a = mirror_instant(en), b = mirror_instant(st);
    st = a;
    en = b;
  }
  for (auto& c : keep_order.contacts) c = mirror_instant(c);
  keep_order.first_contact = keep_order.intervals.front().first;
  CHECK(answer_mismatch(keep_order, m_rev) != "");
  Answer no_swap = mirror_answer(m_orig);  // order reversed, start and end not swapped
  for (auto& iv : no_swap.intervals) std::swap(iv.first, iv.second);
  no_swap.first_contact = no_swap.intervals.front().first;
  CHECK(answer_mismatch(no_swap, m_rev) != "");
  std::cout << "metamorphic: non-vacuity check on multi-pass dim=2 seed=" << mp_seed
            << " intervals=" << m_orig.intervals.size() << " ok" << std::endl;
}

// Not run by default (hidden tag; minutes): the same relations on larger
// motion degrees and more seeds. Run with
//   eccd_tests "[metamorphic-large]"   (ECCD_METAMORPHIC_SEED as above)
TEST_CASE("metamorphic: larger degrees (hidden, slow)", "[.][metamorphic-large][exact]") {
  run_combinations({{2, "kinematic", {5, 6}, {"colliding", "free", "touch", "near-miss"}, 3, true},
                    {2, "kinematic", {6}, {"random"}, 4, true},
                    {2, "kinematic", {7}, {"multi-pass"}, 2, true}});
  run_combinations({{3, "euler", {5, 6}, {"colliding", "free", "touch", "near-miss"}, 1, true},
                    {3, "affine", {3, 4}, {"colliding", "free", "touch"}, 1, false},
                    {3, "euler", {4}, {"random"}, 2, true},
                    {3, "euler", {7}, {"multi-pass"}, 1, false}});
}

}  // namespace ECCD_UNITY_ID
