// Separating planes (api/separate.hpp; paper 000 sections 3 and 4), tag [separate].
//
// Every plane separate_at reports in exact arithmetic is re-checked here from
// first principles, sharing no code with the construction or its checks: the
// test builds its scenes itself (an ellipsoid with semi-axes D, a rational
// rotation R and a centre c0 + t v, written as a matrix motion), so the world
// solid at t is { x : (x - c)ᵀ (R D² Rᵀ)⁻¹ (x - c) <= 1 } and the largest value
// of n·x + o on it is n·c + o + sqrt(nᵀ R D² Rᵀ n) (the support function); a
// lies strictly on the negative side iff n·c + o < 0 and (n·c + o)² > nᵀΣn,
// b strictly on the positive side iff n·c + o > 0 and the same square
// inequality: all exact rationals, no square root.
#include "api/separate.hpp"
#include "api/solve.hpp"
#include "api/static_status.hpp"

#include <catch2/catch.hpp>

#include <gmpxx.h>

#include <cmath>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using Q = mpq_class;
using Vec = std::vector<Q>;
using Mat = std::vector<Vec>;

struct Body {
  Vec axes;   // semi-axes
  Mat R;      // rational rotation (orthogonal)
  Vec c0, v;  // centre c0 + t v
};

Mat identity(int d) {
  Mat m(d, Vec(d, Q(0)));
  for (int i = 0; i < d; ++i) m[i][i] = 1;
  return m;
}
Mat rot2() { return {{Q(3, 5), Q(-4, 5)}, {Q(4, 5), Q(3, 5)}}; }
Mat rot3a() {  // (1/25)[[-15, 0, 20], [16, -15, 12], [12, 20, 9]]
  return {{Q(-15, 25), Q(0), Q(20, 25)}, {Q(16, 25), Q(-15, 25), Q(12, 25)}, {Q(12, 25), Q(20, 25), Q(9, 25)}};
}
Mat rot3b() { return {{Q(3, 5), Q(-4, 5), Q(0)}, {Q(4, 5), Q(3, 5), Q(0)}, {Q(0), Q(0), Q(1)}}; }

std::string str(const Q& x) { return std::string("\"").append(x.get_str()).append("\""); }

std::string motion_json(const Body& b) {
  const int d = int(b.axes.size());
  std::string m = "{\"type\": \"matrix\", \"m\": [";
  for (int i = 0; i <= d; ++i) {
    m += i ? ", [" : "[";
    for (int j = 0; j <= d; ++j) {
      if (j) m += ", ";
      if (i == d)
        m += j == d ? "\"1\"" : "\"0\"";
      else if (j < d)
        m += str(b.R[i][j]);
      else
        m.append("[").append(str(b.c0[i])).append(", ").append(str(b.v[i])).append("]");
    }
    m += "]";
  }
  return m + "]}";
}

std::string scene_json(const Body& a, const Body& b, const std::string& name) {
  auto obj = [](const Body& x) {
    std::string s = "{\"shape\": {\"semi_axes\": [";
    for (std::size_t i = 0; i < x.axes.size(); ++i) s.append(i ? ", " : "").append(str(x.axes[i]));
    return s + "]}, \"motion\": " + motion_json(x) + "}";
  };
  return "{\"format\": \"ellipse-ccd-scene/1\", \"name\": \"" + name + "\", \"dim\": " + std::to_string(a.axes.size()) +
         ", \"a\": " + obj(a) + ", \"b\": " + obj(b) + "}";
}

// n·c + o and nᵀ R D² Rᵀ n for the body at t: first principles.
std::pair<Q, Q> support(const Body& b, const Q& t, const Vec& n, const Q& o) {
  const std::size_t d = b.axes.size();
  Q side = o;
  for (std::size_t i = 0; i < d; ++i) side += n[i] * (b.c0[i] + t * b.v[i]);
  Q spread = 0;  // |D Rᵀ n|²
  for (std::size_t k = 0; k < d; ++k) {
    Q r = 0;
    for (std::size_t i = 0; i < d; ++i) r += b.R[i][k] * n[i];
    spread += b.axes[k] * b.axes[k] * r * r;
  }
  return {side, spread};
}
// The plane strictly separates a (negative side) from b (positive side) at t.
bool separates_by_hand(const Body& a, const Body& b, const Q& t, const SeparatingPlane& p) {
  auto [sa, ka] = support(a, t, p.normal, p.offset);
  auto [sb, kb] = support(b, t, p.normal, p.offset);
  return sgn(sa) < 0 && sa * sa > ka && sgn(sb) > 0 && sb * sb > kb;
}

Body ball(int dim, const Q& r, Vec c0, Vec v) { return Body{Vec(dim, r), identity(dim), std::move(c0), std::move(v)}; }

SolveOptions arith(const char* name) {
  SolveOptions o;
  o.arith = parse_arithmetic(name);
  return o;
}

}  // namespace

TEST_CASE("exact separating planes pass an independent exact check (3D and 2D, far and nearly touching)",
          "[separate]") {
  struct Case {
    Body a, b;
    std::string name;
  };
  const Q eps6(1, 1000000), eps12("1/1000000000000");
  std::vector<Case> cases = {
      {Body{{3, 2, 1}, rot3a(), {0, 0, 0}, {0, 0, 0}}, Body{{1, 2, 3}, rot3b(), {7, 1, 0}, {-2, 0, 1}}, "rotated-3d"},
      {Body{{3, 2, 1}, identity(3), {0, 0, 0}, {0, 0, 0}}, ball(3, 1, {Q(4) + eps12, 0, 0}, {0, 0, 0}), "gap-1e-12-3d"},
      {ball(3, 1, {0, 0, 0}, {0, 0, 0}), Body{{2, 1, 1}, rot3a(), {Q(3) + eps6, 1, 2}, {1, -1, Q(1, 2)}}, "mixed-3d"},
      {Body{{3, 2}, rot2(), {0, 0}, {1, 0}}, Body{{1, 2}, identity(2), {6, 1}, {-1, 0}}, "rotated-2d"},
      {Body{{3, 2}, identity(2), {0, 0}, {0, 0}}, ball(2, 1, {Q(4) + eps12, 0}, {0, 0}), "gap-1e-12-2d"},
  };
  int checked = 0;
  for (const auto& c : cases) {
    Scene s = scene_from_text(scene_json(c.a, c.b, c.name), c.name);
    for (const Q& t : {Q(0), Q(1, 4), Q(1, 3), Q(1, 2), Q(1)}) {
      INFO(c.name << " at t = " << t.get_str());
      for (const char* ar : {"exact", "certified"}) {
        Separation sep = separate_at(s, t, arith(ar));
        const Status st = status_at(s, t, Arithmetic::exact());
        if (st != Status::separate) {
          CHECK(sep.status == to_string(st));  // the exact statement
          CHECK(!sep.plane);
          continue;
        }
        REQUIRE(sep.status == "separate");
        REQUIRE(sep.plane);
        CHECK(separates_by_hand(c.a, c.b, t, *sep.plane));
        CHECK(sep.checks.size() == 4);
        CHECK(sep.tangent_points.size() == 2);
        ++checked;
      }
    }
  }
  CHECK(checked >= 30);
}

TEST_CASE("separate_at: touching and overlapping are stated exactly, and floating says undecided or proves",
          "[separate]") {
  const Body a{{3, 2, 1}, identity(3), {0, 0, 0}, {0, 0, 0}};
  Scene touch = scene_from_text(scene_json(a, ball(3, 1, {4, 0, 0}, {0, 0, 0}), "touch"), "touch");
  Scene over = scene_from_text(scene_json(a, ball(3, 1, {Q(7, 2), 0, 0}, {0, 0, 0}), "over"), "over");
  CHECK(separate_at(touch, 0, arith("exact")).status == "touching");
  CHECK(separate_at(over, 0, arith("exact")).status == "overlapping");
  // Double cannot prove a touch: never "separate" with a plane.
  Separation d = separate_at(touch, 0, arith("double"));
  CHECK(d.status != "separate");
  if (d.status == "undecided") CHECK(!d.why.empty());
  // A pair 1e-12 apart: double must not claim a plane its error bound cannot prove; what it claims holds.
  const Body b = ball(3, 1, {Q(4) + Q("1/1000000000000"), 0, 0}, {0, 0, 0});
  Scene near = scene_from_text(scene_json(a, b, "near"), "near");
  for (const char* ar : {"double", "mpfr:64", "mpfr:256"}) {
    Separation f = separate_at(near, 0, arith(ar));
    INFO(ar << ": " << f.status << " " << f.why);
    CHECK((f.status == "separate" || f.status == "undecided"));
    if (f.status == "separate")
      CHECK(separates_by_hand(a, b, 0, *f.plane));
    else
      CHECK(!f.why.empty());
  }
  // Far apart: every arithmetic proves a plane, and it holds.
  const Body far = ball(3, 1, {6, 1, 0}, {0, 0, 0});
  Scene fs = scene_from_text(scene_json(a, far, "far"), "far");
  for (const char* ar : {"double", "mpfr:128"}) {
    Separation f = separate_at(fs, 0, arith(ar));
    REQUIRE(f.status == "separate");
    CHECK(separates_by_hand(a, far, 0, *f.plane));
  }
}

TEST_CASE("separate_at refuses what it cannot do", "[separate]") {
  const Body a = ball(2, 1, {0, 0}, {0, 0}), b = ball(2, 1, {3, 0}, {0, 0});
  Scene s = scene_from_text(scene_json(a, b, "two"), "two");
  CHECK_THROWS_AS(separate_at(s, Q(3, 2), arith("exact")), std::invalid_argument);
  CHECK_THROWS_AS(separate_at(s, Q(-1, 2), arith("double")), std::invalid_argument);
  Scene cyc = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example1.json");
  CHECK_THROWS_AS(separate_at(cyc, Q(1, 2), arith("exact")), std::invalid_argument);
  SeparatingPlane wrong{{Q(1), Q(0), Q(0)}, Q(0)};  // 3 entries for a 2D scene
  CHECK_THROWS_AS(plane_separates_on_frame(s, wrong, arith("exact")), std::invalid_argument);
}

TEST_CASE("plane_separates_on_frame: 000 section 4, decided on the whole frame", "[separate]") {
  for (int dim : {2, 3}) {
    auto vec = [dim](Q x) {
      Vec v(dim, Q(0));
      v[0] = x;
      return v;
    };
    SeparatingPlane x0{vec(1), Q(0)};  // the plane x = 0, a on x < 0
    INFO("dim " << dim);
    // Two balls translating apart: the plane x = 0 separates for all t.
    const Body a1 = ball(dim, 1, vec(-3), vec(-2)), b1 = ball(dim, 1, vec(3), vec(2));
    Scene apart = scene_from_text(scene_json(a1, b1, "apart"), "apart");
    for (const char* ar : {"exact", "certified", "double", "mpfr:128"}) {
      INFO(ar);
      CHECK(plane_separates_on_frame(apart, x0, arith(ar)) == PlaneCheck::separates);
    }
    for (int k = 0; k <= 16; ++k) CHECK(separates_by_hand(a1, b1, Q(k, 16), x0));  // by hand, on a grid
    // The same plane, flipped: b on the negative side: fails.
    SeparatingPlane flipped{vec(-1), Q(0)};
    for (const char* ar : {"exact", "double"})
      CHECK(plane_separates_on_frame(apart, flipped, arith(ar)) == PlaneCheck::fails);
    // a goes through the plane and b: a collision; the plane fails.
    const Body a2 = ball(dim, 1, vec(-3), vec(6));
    Scene collide = scene_from_text(scene_json(a2, b1, "collide"), "collide");
    for (const char* ar : {"exact", "certified", "double", "mpfr:128"}) {
      INFO(ar);
      CHECK(plane_separates_on_frame(collide, x0, arith(ar)) == PlaneCheck::fails);
    }
    // A plane that separates at t = 0 (made by separate_at) but is crossed late in the frame:
    // a's centre goes from x = -3 to x = -1/2, it meets x = 0 for t > 4/5. Never trusted beyond that.
    const Body a3 = ball(dim, 1, vec(-3), vec(Q(5, 2))), b3 = ball(dim, 1, vec(3), vec(0));
    Scene late = scene_from_text(scene_json(a3, b3, "late"), "late");
    Separation at0 = separate_at(late, 0, arith("exact"));
    REQUIRE(at0.status == "separate");
    CHECK(separates_by_hand(a3, b3, 0, *at0.plane));
    CHECK(!separates_by_hand(a3, b3, 1, *at0.plane));  // by hand: at t = 1 it no longer separates
    CHECK(plane_separates_on_frame(late, *at0.plane, arith("exact")) == PlaneCheck::fails);
    CHECK(plane_separates_on_frame(late, *at0.plane, arith("certified")) == PlaneCheck::fails);
    CHECK(plane_separates_on_frame(late, *at0.plane, arith("double")) != PlaneCheck::separates);
    // The plane made at t = 1 for the same frame: separates at t = 1, and over the whole frame?
    Separation at1 = separate_at(late, 1, arith("exact"));
    REQUIRE(at1.status == "separate");
    bool all_by_hand = true;
    for (int k = 0; k <= 64; ++k) all_by_hand = all_by_hand && separates_by_hand(a3, b3, Q(k, 64), *at1.plane);
    if (!all_by_hand) CHECK(plane_separates_on_frame(late, *at1.plane, arith("exact")) == PlaneCheck::fails);
    // Touching the plane exactly at t = 1 (a's centre ends at x = -1): not strictly separated, fails;
    // double must not say separates.
    const Body a4 = ball(dim, 1, vec(-3), vec(2));
    Scene touch = scene_from_text(scene_json(a4, b3, "touch-plane"), "touch-plane");
    CHECK(plane_separates_on_frame(touch, x0, arith("exact")) == PlaneCheck::fails);
    CHECK(plane_separates_on_frame(touch, x0, arith("certified")) == PlaneCheck::fails);
    CHECK(plane_separates_on_frame(touch, x0, arith("double")) != PlaneCheck::separates);
  }
}

TEST_CASE("plane_separates_on_frame agrees with the hand check on rotating scenes (kept planes of 000 section 4)",
          "[separate]") {
  // b rotates (a kinematic-free matrix motion: its rotation is fixed, its centre moves) towards a;
  // the plane made at t = 0 is kept; exact and certified agree, double never contradicts them.
  const Body a{{3, 2, 1}, rot3a(), {0, 0, 0}, {0, 0, 0}};
  for (const Q& speed : {Q(-1, 2), Q(-2), Q(-4)}) {
    const Body b{{1, 2, 3}, rot3b(), {8, 1, 0}, {speed, 0, Q(1, 3)}};
    Scene s = scene_from_text(scene_json(a, b, "kept"), "kept");
    Separation at0 = separate_at(s, 0, arith("exact"));
    REQUIRE(at0.status == "separate");
    const PlaneCheck ex = plane_separates_on_frame(s, *at0.plane, arith("exact"));
    CHECK(plane_separates_on_frame(s, *at0.plane, arith("certified")) == ex);
    const PlaneCheck d = plane_separates_on_frame(s, *at0.plane, arith("double"));
    CHECK((d == ex || d == PlaneCheck::unknown));
    bool all_by_hand = true;
    for (int k = 0; k <= 128; ++k) all_by_hand = all_by_hand && separates_by_hand(a, b, Q(k, 128), *at0.plane);
    if (ex == PlaneCheck::separates) CHECK(all_by_hand);  // a proof over [0, 1] holds on every grid point
    if (!all_by_hand) CHECK(ex == PlaneCheck::fails);
  }
}

TEST_CASE("contact points and normals: 3D in every arithmetic, 2D with normals", "[separate][contact]") {
  // cases/touch3d/touch-and-separate-rotated.json: one external contact at t = 1/2 at G(3, 0, 0) =
  // (-1.3, 1.17, 3.44) (its note, make_touch3d.py); a's outward normal there is R_G (1, 0, 0) =
  // (-15, 16, 12)/25, and b's gradient points the opposite way.
  Scene s = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/touch3d/touch-and-separate-rotated.json");
  const double want_x[3] = {-1.3, 1.17, 3.44}, want_n[3] = {-0.6, 0.64, 0.48};
  for (const char* ar : {"exact", "certified", "double", "mpfr:128"}) {
    INFO(ar);
    Solution r = solve(s, arith(ar));
    if (r.arith.floating() &&
        r.answer.contacts.empty()) {  // a floating run may not see this touch: undecided, never a guess
      CHECK(!r.answer.undecided.empty());
      continue;
    }
    REQUIRE(r.answer.contacts.size() == 1);
    REQUIRE(r.answer.contact_points.size() == 1);
    const ContactPoint& cp = r.answer.contact_points[0];
    REQUIRE(cp.x.size() == 3);
    REQUIRE(cp.normal.size() == 3);
    const double tol = std::string(ar) == "double" ? 1e-5 : 1e-8;
    double len = 0;
    for (int i = 0; i < 3; ++i) {
      CHECK(std::abs(std::stod(cp.x[i]) - want_x[i]) < tol);
      CHECK(std::abs(std::stod(cp.normal[i]) - want_n[i]) < tol);
      len += std::stod(cp.normal[i]) * std::stod(cp.normal[i]);
    }
    CHECK(std::abs(len - 1) < 1e-12);
  }
  // b's outward normal there is G applied to (-1, 0, 0) (b's centre is G(4, 0, 0) at t = 1/2, make_touch3d.py):
  // the opposite of the reported one, so the normal checked above is the common normal.
  // cases/touch3d/overlap-on-axis.json: contacts at t = 1/2 -+ sqrt(2)/4 (the ends of its collision interval), both at
  // (3, 0, 0), a's normal (1, 0, 0) (its note); the floating runs find both.
  Scene axis = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/touch3d/overlap-on-axis.json");
  for (const char* ar : {"double", "mpfr:128", "exact"}) {
    INFO(ar);
    Solution r = solve(axis, arith(ar));
    REQUIRE(r.answer.contacts.size() == 2);
    REQUIRE(r.answer.contact_points.size() == 2);
    for (const auto& cp : r.answer.contact_points) {
      REQUIRE(cp.x.size() == 3);
      REQUIRE(cp.normal.size() == 3);
      CHECK(std::abs(std::stod(cp.x[0]) - 3) < 1e-6);
      CHECK(std::abs(std::stod(cp.x[1])) < 1e-6);
      CHECK(std::abs(std::stod(cp.x[2])) < 1e-6);
      CHECK(std::abs(std::stod(cp.normal[0]) - 1) < 1e-9);
    }
  }
  // 2D: 003 Example 2 touches at t = 1/2 at the origin; a (above) has outward normal (0, -1).
  Scene e2 = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2.json");
  for (const char* ar : {"exact", "certified"}) {
    Solution r = solve(e2, arith(ar));
    REQUIRE(r.answer.contact_points.size() == 1);
    REQUIRE(r.answer.contact_points[0].normal.size() == 2);
    CHECK(std::abs(std::stod(r.answer.contact_points[0].normal[0])) < 1e-9);
    CHECK(std::abs(std::stod(r.answer.contact_points[0].normal[1]) + 1) < 1e-9);
  }
}

// Issue 21: certified separate_at takes the double construction when its bounded checks hold (bits 53, each
// check with its error bound) and the exact path otherwise (a 1e-12 gap: the double static test cannot decide).
// Either way the plane passes the first-principles check above, and the status agrees with exact.
TEST_CASE("certified separating planes: the double plane when its bounded checks hold, else exact", "[separate]") {
  const Q eps12("1/1000000000000");
  const Body far_a{{3, 2, 1}, rot3a(), {0, 0, 0}, {0, 0, 0}}, far_b{{1, 2, 3}, rot3b(), {7, 1, 0}, {-2, 0, 1}};
  const Body gap_a{{3, 2, 1}, identity(3), {0, 0, 0}, {0, 0, 0}};
  const Body gap_b = ball(3, 1, {Q(4) + eps12, 0, 0}, {0, 0, 0});
  Scene far = scene_from_text(scene_json(far_a, far_b, "far"), "far");
  Scene gap = scene_from_text(scene_json(gap_a, gap_b, "gap"), "gap");
  for (const Q& t : {Q(0), Q(1, 3), Q(1, 2)}) {
    INFO("t = " << t.get_str());
    REQUIRE(status_at(far, t, Arithmetic::exact()) == Status::separate);
    Separation c = separate_at(far, t, arith("certified"));
    REQUIRE(c.status == "separate");
    REQUIRE(c.plane);
    CHECK(c.bits == 53);  // the double path
    CHECK(separates_by_hand(far_a, far_b, t, *c.plane));
    REQUIRE(c.checks.size() == 4);
    bool bounded = false;
    for (const auto& ch : c.checks) bounded = bounded || ch.error_bound > 0;
    CHECK(bounded);
  }
  Separation g = separate_at(gap, Q(0), arith("certified"));
  REQUIRE(g.status == "separate");
  REQUIRE(g.plane);
  CHECK(g.bits >= 128);  // the exact path: the double one cannot prove a 1e-12 gap
  CHECK(separates_by_hand(gap_a, gap_b, Q(0), *g.plane));
  for (const auto& ch : g.checks) CHECK(ch.error_bound == 0);
  // Not separate: the exact statement, as in exact arithmetic.
  const Body touch_b = ball(3, 1, {Q(4), 0, 0}, {0, 0, 0});
  Scene touch = scene_from_text(scene_json(gap_a, touch_b, "touch"), "touch");
  Separation tc = separate_at(touch, Q(0), arith("certified"));
  CHECK(tc.status == to_string(status_at(touch, Q(0), Arithmetic::exact())));
  CHECK(!tc.plane);
}

}  // namespace ECCD_UNITY_ID
