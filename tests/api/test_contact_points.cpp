// Contact points and normals of solved 3D scenes (api/contact_points.hpp),
// on scenes whose touching point is known by hand: an ellipsoid of semi-axes
// (1, 2, 3) at the origin (turned or not) and a unit sphere moving towards it
// along an axis, so that they touch at t = 1 at the end of an axis of the
// ellipsoid, where its outward normal is that axis.
//  - exact and certified runs (the bracket's midpoint, the exact A(t), B(t),
//    MPFR at 256 bits), double and MPFR runs (the instant's value, the rounded
//    scene) all give that point and normal, "0" (never "-0") for the zero
//    coordinates; a prepared pair handed in gives the same as none;
//  - one point per contact, in order; an instant outside [0, 1] or without a
//    value gets an empty point, and so does every contact of a floating run
//    whose rounded scene overflows (a translation coefficient of 1e400 is no
//    double), while MPFR, whose exponents reach further, still gives the point;
//  - left as they are: a 2D scene, a scene without contacts, one whose points
//    are there already, an independent-motions scene.
#include "api/contact_points.hpp"

#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

#include <limits>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
// a: semi-axes (1, 2, 3), static or turned by the quaternion `e`; b: a unit sphere whose centre moves by `path`
// (three polynomials in t, power basis).
Scene pair_scene(const std::string& motion_a, const std::string& path) {
  const std::string doc = R"({"format": "ellipse-ccd-scene/1", "name": "touch-axis", "dim": 3,
    "a": {"shape": {"semi_axes": ["1", "2", "3"]}, "motion": )" +
                          motion_a + R"(},
    "b": {"shape": {"semi_axes": ["1", "1", "1"]}, "motion": {"type": "euler", "e": ["1", "0", "0", "0"],
          "translation": )" +
                          path + R"(, "translation_denominator": "1"}}})";
  return parse_scene(doc, "touch-axis.json");
}
Instant at_one_certified() { return bracketed_instant(mpq_class(1), mpq_class(1), mpq_class(1)); }
Instant at_value(double t) {
  Instant i;
  i.approx = std::to_string(t);
  i.value = t;
  return i;
}
Solution with_contacts(const std::string& arith, std::vector<Instant> contacts) {
  Solution s;
  s.dim = 3;
  s.arith = parse_arithmetic(arith);
  s.answer.collides = true;
  s.answer.contacts = std::move(contacts);
  return s;
}
void check_point(const ContactPoint& cp, const std::vector<double>& x, const std::vector<double>& n, double tol) {
  REQUIRE(cp.x.size() == 3);
  REQUIRE(cp.normal.size() == 3);
  for (int i = 0; i < 3; ++i) {
    INFO("coordinate " << i << ": " << cp.x[i] << ", normal " << cp.normal[i]);
    CHECK(std::abs(std::stod(cp.x[i]) - x[i]) <= tol);
    CHECK(std::abs(std::stod(cp.normal[i]) - n[i]) <= tol);
    CHECK(cp.x[i] != "-0");
    CHECK(cp.normal[i] != "-0");
  }
}
}  // namespace

TEST_CASE("contact points: the touching point at the end of an axis, in every arithmetic", "[api][contact-points]") {
  const std::string still = R"({"type": "static"})";
  // b's centre (4 - 2t, 0, 0): it touches a's end (1, 0, 0) at t = 1 (centre 2 = 1 + 1).
  const Scene sx = pair_scene(still, R"([["4", "-2"], "0", "0"])");
  // b's centre (0, 5 - 2t, 0): touches (0, 2, 0) at t = 1; (0, 0, 6 - 2t): touches (0, 0, 3).
  const Scene sy = pair_scene(still, R"(["0", ["5", "-2"], "0"])");
  const Scene sz = pair_scene(still, R"(["0", "0", ["6", "-2"]])");
  // a turned a quarter about z (e = (1, 0, 0, 1), R = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]): its semi-axis 1 lies
  // along y and 2 along x; b's centre (0, 4 - 2t, 0) touches (0, 1, 0) at t = 1.
  const Scene turned = pair_scene(R"({"type": "euler", "e": ["1", "0", "0", "1"], "translation": ["0", "0", "0"],
                                      "translation_denominator": "1"})",
                                  R"(["0", ["4", "-2"], "0"])");
  struct Case {
    const Scene* s;
    std::vector<double> x, n;
  };
  const std::vector<Case> cases = {{&sx, {1, 0, 0}, {1, 0, 0}},
                                   {&sy, {0, 2, 0}, {0, 1, 0}},
                                   {&sz, {0, 0, 3}, {0, 0, 1}},
                                   {&turned, {0, 1, 0}, {0, 1, 0}}};
  for (const auto& c : cases) {
    for (const char* ar : {"exact", "certified", "double", "mpfr:128"}) {
      INFO(ar);
      const bool floating = parse_arithmetic(ar).floating();
      Solution s = with_contacts(ar, {floating ? at_value(1.0) : at_one_certified()});
      add_contact_points_3d(*c.s, s);
      REQUIRE(s.answer.contact_points.size() == 1);
      // The exact A(1), B(1) touch exactly; the floating runs see the rounded scene (here exact in binary).
      check_point(s.answer.contact_points[0], c.x, c.n, floating ? 1e-6 : 1e-15);
    }
    // The prepared pair handed in gives the same as none.
    const PreparedPair<4> pp = prepare_pair<H_3D>(*c.s);
    Solution a = with_contacts("exact", {at_one_certified()}), b = a;
    add_contact_points_3d(*c.s, a);
    add_contact_points_3d(*c.s, b, &pp);
    REQUIRE(b.answer.contact_points.size() == 1);
    CHECK(a.answer.contact_points[0].x == b.answer.contact_points[0].x);
    CHECK(a.answer.contact_points[0].normal == b.answer.contact_points[0].normal);
  }
}

TEST_CASE("contact points: one per contact, empty for instants outside [0, 1]", "[api][contact-points]") {
  const Scene sx = pair_scene(R"({"type": "static"})", R"([["4", "-2"], "0", "0"])");
  Instant none;  // no value, no bracket
  Solution s = with_contacts(
      "exact", {bracketed_instant(mpq_class(3, 2), mpq_class(3, 2), mpq_class(3, 2)), at_one_certified(), none});
  add_contact_points_3d(sx, s);
  REQUIRE(s.answer.contact_points.size() == 3);
  CHECK(s.answer.contact_points[0].x.empty());
  CHECK(s.answer.contact_points[0].normal.empty());
  check_point(s.answer.contact_points[1], {1, 0, 0}, {1, 0, 0}, 1e-15);
  CHECK(s.answer.contact_points[2].x.empty());
  Solution d = with_contacts("double", {at_value(-0.25), at_value(1.0)});
  add_contact_points_3d(sx, d);
  REQUIRE(d.answer.contact_points.size() == 2);
  CHECK(d.answer.contact_points[0].x.empty());
  check_point(d.answer.contact_points[1], {1, 0, 0}, {1, 0, 0}, 1e-6);
}

TEST_CASE("contact points: 2D, contact-free, already filled and independent scenes are left alone",
          "[api][contact-points]") {
  const Scene sx = pair_scene(R"({"type": "static"})", R"([["4", "-2"], "0", "0"])");
  Solution empty = with_contacts("exact", {});
  add_contact_points_3d(sx, empty);
  CHECK(empty.answer.contact_points.empty());
  Solution filled = with_contacts("exact", {at_one_certified()});
  filled.answer.contact_points.push_back(ContactPoint{{"7", "7", "7"}, {}});
  add_contact_points_3d(sx, filled);
  REQUIRE(filled.answer.contact_points.size() == 1);
  CHECK(filled.answer.contact_points[0].x[0] == "7");
  // 2D: 003 Example 2 (the 2D pipelines make their own points).
  const Scene e2 = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2.json");
  Solution two = with_contacts("exact", {bracketed_instant(mpq_class(1, 2), mpq_class(1, 2), mpq_class(1, 2))});
  add_contact_points_3d(e2, two);
  CHECK(two.answer.contact_points.empty());
  // Independent motions.
  const Scene ind = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/independent/spheres-cross.json");
  REQUIRE(ind.independent);
  Solution i = with_contacts("exact", {at_one_certified()});
  add_contact_points_3d(ind, i);
  CHECK(i.answer.contact_points.empty());
}

TEST_CASE("contact points: a floating run whose rounded scene overflows gives empty points", "[api][contact-points]") {
  // b's centre (0, 5 - 2t, 1e400 (1 - t)): at t = 1 it is (0, 3, 0) and touches a's end (0, 2, 0) as above, but
  // 1e400 rounds to infinity in double.
  const std::string doc = R"({"format": "ellipse-ccd-scene/1", "name": "huge", "dim": 3,
    "a": {"shape": {"semi_axes": ["1", "2", "3"]}, "motion": {"type": "static"}},
    "b": {"shape": {"semi_axes": ["1", "1", "1"]}, "motion": {"type": "euler", "e": ["1", "0", "0", "0"],
          "translation": ["0", ["5", "-2"], ["1e400", "-1e400"]], "translation_denominator": "1"}}})";
  const Scene s = parse_scene(doc, "huge.json");
  Solution d = with_contacts("double", {at_value(1.0), at_value(0.5)});
  add_contact_points_3d(s, d);
  REQUIRE(d.answer.contact_points.size() == 2);
  for (const auto& cp : d.answer.contact_points) {
    CHECK(cp.x.empty());
    CHECK(cp.normal.empty());
  }
  Solution m = with_contacts("mpfr:128", {at_value(1.0)});
  add_contact_points_3d(s, m);
  REQUIRE(m.answer.contact_points.size() == 1);
  check_point(m.answer.contact_points[0], {0, 2, 0}, {0, 1, 0}, 1e-6);
  Solution e = with_contacts("exact", {at_one_certified()});
  add_contact_points_3d(s, e);
  check_point(e.answer.contact_points[0], {0, 2, 0}, {0, 1, 0}, 1e-15);
}

}  // namespace ECCD_UNITY_ID
