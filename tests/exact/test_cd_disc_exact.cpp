// The exact CD-DISC pipeline (003): paper values and an independent exact oracle.
#include "tests/support/scenes.hpp"

#include <catch2/catch.hpp>

#include <iostream>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

TEST_CASE("003 Example 2: the exact pipeline proves a single isolated touch at t = 1/2", "[exact][cd_disc][paper003]") {
  Scene s = read_scene_file(case_path("paper003/example2.json"));
  auto r = solve_exact(s);
  const Answer& a = r.answer;
  REQUIRE(a.collides);
  REQUIRE(a.intervals.size() == 1);
  const Instant& t0 = a.intervals[0].first;
  const Instant& t1 = a.intervals[0].second;
  REQUIRE(t0.certified());
  CHECK(*t0.lo == *t1.lo);
  CHECK(*t0.hi == *t1.hi);
  CHECK(*t0.lo <= Q(1, 2));
  CHECK(Q(1, 2) <= *t0.hi);
  Q width = *t0.hi - *t0.lo;
  CHECK(width <= Q(1, mpz_class(1) << 50));
  REQUIRE(a.contacts.size() == 1);
  REQUIRE(a.first_contact.has_value());
  CHECK(*a.first_contact->lo <= Q(1, 2));
  // Lemma 5: the contact point is the origin (A centred at (0, 10), B at (0, -10), semi-axis 10 along y).
  REQUIRE(a.contact_points.size() == 1);
  REQUIRE(a.contact_points[0].x.size() == 2);
  CHECK(std::abs(std::stod(a.contact_points[0].x[0])) < 1e-9);
  CHECK(std::abs(std::stod(a.contact_points[0].x[1])) < 1e-9);
}

TEST_CASE("003 Example 2: f's λ³ coefficient is the paper's up to a constant, and Δ has degree 96",
          "[exact][paper003]") {
  Scene s = read_scene_file(case_path("paper003/example2.json"));
  auto r = solve_exact(s);
  // 003 section VI-C prints g3(t) = -4096t^24 + 49152t^23 - ... + 24t - 1.
  const long printed[] = {-1,        24,       -288,     2288,      -13464,   62304,     -235136,  741312,    -1984752,
                          4564736,   -9090048, 15754752, -23835904, 31509504, -36360192, 36517888, -31756032, 23721984,
                          -15048704, 7974912,  -3446784, 1171456,   -294912,  49152,     -4096};
  const RPoly& g3 = r.g[3];
  REQUIRE(g3.degree() == 24);
  Q factor = g3.c[0] / Q(printed[0]);
  for (int i = 0; i <= 24; ++i) {
    INFO("coefficient of t^" << i);
    CHECK(g3.c[i] == factor * Q(printed[i]));
  }
  CHECK(r.projection_degree == 96);
}

TEST_CASE("003 Table I: Δ has degree 8 for linear translations", "[exact][paper003]") {
  // Two ellipses, fixed orientation, linear translations (003 VI-B, Fig. 6).
  Scene s = translation_scene(4, 2, rp({-10, 12}), rp({0, 1}), 3, 1, rp({0}), rp({1, -2}));
  auto r = solve_exact(s);
  CHECK(r.g[3].degree() == 0);
  CHECK(r.g[0].degree() == 0);
  CHECK(r.g[1].degree() == 2);
  CHECK(r.g[2].degree() == 2);
  CHECK(r.projection_degree == 8);
}

TEST_CASE("003 Example 2 shifted by d: away is collision-free, towards is one short overlap around 1/2",
          "[exact][paper003]") {
  for (const char* e : {"3", "6", "9", "12", "15"}) {
    std::string away = case_path(std::string("paper003/example2-away-1e-") + e + ".json");
    std::string toward = case_path(std::string("paper003/example2-towards-1e-") + e + ".json");
    INFO("d = 1e-" << e);
    auto ra = solve_exact(read_scene_file(away));
    CHECK_FALSE(ra.answer.collides);
    CHECK(ra.answer.intervals.empty());
    auto rt = solve_exact(read_scene_file(toward));
    REQUIRE(rt.answer.intervals.size() == 1);
    const auto& [s, f] = rt.answer.intervals[0];
    CHECK(*s.hi < Q(1, 2));
    CHECK(Q(1, 2) < *f.lo);
    CHECK(*f.hi - *s.lo < Q(1, 10));
    CHECK(rt.answer.contacts.size() == 2);  // enters and leaves by external tangency
  }
}

TEST_CASE("identical disks on identical motions: Δ ≡ 0 is handled, the collision set is [0, 1]",
          "[exact][degenerate]") {
  Scene s = translation_scene(3, 2, rp({0, 5}), rp({1}), 3, 2, rp({0, 5}), rp({1}));
  auto r = solve_exact(s);
  CHECK(r.projection_identically_zero);
  REQUIRE(r.answer.intervals.size() == 1);
  CHECK(*r.answer.intervals[0].first.lo == 0);
  CHECK(*r.answer.intervals[0].second.hi == 1);
  CHECK(r.answer.contacts.empty());
}

TEST_CASE("concentric circles: a root of Δ that is not a contact (003 VI-B)", "[exact][paper003]") {
  // Circle of radius 1 fixed at the origin; circle of radius 2 moving from
  // (-10, 0) to (10, 0): concentric at t = 1/2 (positive double root of f).
  Scene s = translation_scene(1, 1, rp({0}), rp({0}), 2, 2, rp({-10, 20}), rp({0}));
  auto r = solve_exact(s);
  bool found_half = false;
  for (const auto& c : r.critical)
    if (*c.t.lo <= Q(1, 2) && Q(1, 2) <= *c.t.hi) {
      found_half = true;
      CHECK(c.status == Status::overlapping);
    }
  CHECK(found_half);
  // first touch when the distance of centres is 3: t = 7/20; last at 13/20
  REQUIRE(r.answer.intervals.size() == 1);
  CHECK(*r.answer.intervals[0].first.lo == Q(7, 20));
  CHECK(*r.answer.intervals[0].second.lo == Q(13, 20));
  CHECK(r.answer.contacts.size() == 2);
}

TEST_CASE("random 2D scenes: the exact answer agrees with exact Sturm counts at many rational instants",
          "[exact][random]") {
  std::uint64_t seed = seed_from_env(0xeccd0002ull);
  std::cout << "random 2D scenes: seed " << seed << " (set ECCD_TEST_SEED to replay)\n";
  std::mt19937_64 rng(seed);
  int collide = 0;
  for (int trial = 0; trial < 12; ++trial) {
    int k = 1 + trial % 2;  // motion degree 2 or 4
    Scene s = random_kinematic_scene(rng, k);
    auto r = solve_exact(s);
    collide += r.answer.collides;
    for (int i = 0; i <= 64; ++i) {
      Q t(i, 64);
      t += Q(1, 1000003);  // off the dyadic grid of the cell samples
      if (t > 1) t = 1;
      bool ambiguous = false;
      bool in_c = in_answer_set(r.answer, t, ambiguous);
      if (ambiguous) continue;
      int neg = negative_root_count(s, t);
      INFO("seed " << seed << " trial " << trial << " t = " << t.get_str() << " negative roots " << neg);
      CHECK(in_c == (neg != 2));
    }
  }
  std::cout << "  " << collide << " of 12 random scenes collide\n";
}

}  // namespace ECCD_UNITY_ID
