// Independent motions of every kind, in 2D (ellipses, H = 3) and 3D
// (ellipsoids, H = 4), against analytic answers (paper 001 section 4;
// kernel/trivariate_bernstein.hpp, certified/independent_proof.hpp,
// exact/independent_balls.hpp, floating/independent_ccd.hpp).
//
// Discs and balls on segments: c_A(s) = p + s d, c_B(t) = q + t e meet iff
// |c_A(s) - c_B(t)| <= R = r_A + r_B, so the s-set is { s : dist(c_A(s), B's
// segment) <= R } and the t-set likewise; every end below solves a linear or
// quadratic equation written next to its case (3D: the same data with z = 0,
// so the answers are the same). A body on the minor axis of a static ellipse
// (semi-axes 2, 1; 3D: 2, 1, 1) meets it iff its centre is within 1 + r of the
// centre along that axis (the vertex is the nearest point: the centre of
// curvature there lies on the other side). Exact, certified and double must
// all give these answers: exact and certified with brackets that hold the
// analytic ends (width <= 1e-9), double within 1e-8 of them.
// A disc (ball) turning about its own centre does not move as a set: its
// s-set is all of [0, 1] (or nothing) and the t-set that of the static disc.
// Turning bodies (no closed form) are scenes with stored exact answers in
// cases/independent (ellipses-turning, ellipsoids-turning), which
// `eccd regress` checks in exact and certified arithmetic.
#include "api/solve.hpp"
#include "kernel/polynomial.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace eccd;

namespace {

// One object: semi-axes, the centre's path c0 + x d (matrix motion [[I, c0 + x d], [0, 1]]), dim 2 or 3.
std::string object(int dim, std::vector<std::string> axes, std::vector<std::string> c0, std::vector<std::string> d) {
  if (dim == 3) {
    if (axes.size() == 2) axes.push_back(axes[1]);
    c0.push_back("0");
    d.push_back("0");
  }
  std::string a = "[";
  for (int i = 0; i < dim; ++i) a += std::string(i ? ", " : "") + "\"" + axes[i] + "\"";
  std::string m = "[";
  for (int i = 0; i <= dim; ++i) {
    m += i ? ", [" : "[";
    for (int j = 0; j < dim; ++j) m += std::string(j ? ", " : "") + (i == j ? "\"1\"" : "\"0\"");
    if (i < dim)
      m += ", [\"" + c0[i] + "\", \"" + d[i] + "\"]]";
    else
      m += ", \"1\"]";
  }
  return R"({"shape": {"semi_axes": )" + a + R"(]}, "motion": {"type": "matrix", "m": )" + m + "]}}";
}

std::string scene(int dim, const std::string& a, const std::string& b) {
  return R"({"format": "ellipse-ccd-scene/1", "name": "kind", "dim": )" + std::to_string(dim) +
         R"(, "parameters": "independent", "a": )" + a + R"(, "b": )" + b + "}";
}

// An analytic end: the only root of p in [a, b].
struct End {
  RPoly p;
  Rational a, b;
};
End at(const Rational& x) { return End{RPoly(std::vector<Rational>{-x, 1}), x, x}; }
End root(std::vector<Rational> p, const Rational& a, const Rational& b) { return End{RPoly(std::move(p)), a, b}; }
double value(const End& e) {
  if (e.a == e.b) return e.a.get_d();
  Rational lo = e.a, hi = e.b;
  const int s0 = sgn(e.p(lo));
  for (int i = 0; i < 80; ++i) {
    const Rational m = (lo + hi) / 2;
    (sgn(e.p(m)) == s0 ? lo : hi) = m;
  }
  return Rational((lo + hi) / 2).get_d();
}

struct Kind {
  std::string what;
  std::string a, b;  // objects (dim filled by make)
  std::vector<std::pair<End, End>> s, t;
};

void check_end(const Instant& i, const End& e, bool proved) {
  INFO("end near " << value(e) << ", reported " << i.approx);
  if (!proved) {
    CHECK(std::abs(i.value - value(e)) <= 1e-8);
    return;
  }
  REQUIRE(i.certified());
  CHECK(*i.hi - *i.lo <= Rational(1, 1000000000));
  if (e.a == e.b) {
    CHECK(*i.lo <= e.a);
    CHECK(e.a <= *i.hi);
  } else {
    CHECK(*i.lo >= e.a);
    CHECK(*i.hi <= e.b);
    CHECK(sgn(e.p(*i.lo)) * sgn(e.p(*i.hi)) <= 0);
  }
}

void check_intervals(const std::vector<std::pair<Instant, Instant>>& got, const std::vector<std::pair<End, End>>& want,
                     bool proved) {
  REQUIRE(got.size() == want.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    check_end(got[k].first, want[k].first, proved);
    check_end(got[k].second, want[k].second, proved);
  }
}

void check_kind(int dim, const Kind& k) {
  const Scene sc = scene_from_text(scene(dim, k.a, k.b), k.what);
  for (const char* arith : {"exact", "certified", "double"}) {
    INFO(dim << "D " << k.what << ", " << arith);
    SolveOptions o;
    o.arith = parse_arithmetic(arith);
    const Solution s = solve(sc, o);
    for (const auto& r : s.undecided_reasons) UNSCOPED_INFO("reason: " << r);
    CHECK(s.dim == dim);
    CHECK(s.answer.independent);
    const bool proved = std::string(arith) != "double";
    if (proved)
      CHECK(s.answer.undecided.empty());
    else  // double may leave an end located to within a few 2^-34 (said so), never more
      for (const auto& r : s.undecided_reasons) CHECK(r.find("is only located in this range") != std::string::npos);
    CHECK(s.answer.collides == !k.s.empty());
    if (proved) CHECK(s.certified);
    check_intervals(s.answer.s_intervals, k.s, proved);
    check_intervals(s.answer.t_intervals, k.t, proved);
  }
}

// dim-free descriptions: objects take their dim when the scene is made
struct Maker {
  int dim;
  std::string disc(const std::string& r, std::vector<std::string> c0, std::vector<std::string> d) const {
    return object(dim, {r, r}, c0, d);
  }
  std::string ellipse(std::vector<std::string> ax, std::vector<std::string> c0, std::vector<std::string> d) const {
    return object(dim, ax, c0, d);
  }
  // a disc (ball) of radius r at the origin turning about z by the rational rotation (1 - x^2, 2x) / (1 + x^2), 0 to 90
  // degrees
  std::string turning_disc(const std::string& r) const {
    const std::string w = R"(["1", "0", "1"])", a = R"(["1", "0", "-1"])";
    const std::string m =
        dim == 2 ? "[[" + a + R"(, ["0", "-2"], "0"], [["0", "2"], )" + a + R"(, "0"], ["0", "0", )" + w + "]]"
                 : "[[" + a + R"(, ["0", "-2"], "0", "0"], [["0", "2"], )" + a + R"(, "0", "0"], ["0", "0", )" + w +
                       R"(, "0"], ["0", "0", "0", )" + w + "]]";
    std::string axes = "[\"" + r + "\", \"" + r + "\"" + (dim == 3 ? ", \"" + r + "\"" : std::string("")) + "]";
    return R"({"shape": {"semi_axes": )" + axes + R"(}, "motion": {"type": "matrix", "m": )" + m + "}}";
  }
};

std::vector<Kind> kinds(const Maker& m) {
  const Rational one(1);
  return {
      // R = 1; c_A(s) = (2, -3 + 6s), c_B(t) = (6t - 1, 0): |6s - 3| <= 1 and |6t - 3| <= 1
      {"crossing",
       m.disc("1/2", {"2", "-3"}, {"0", "6"}),
       m.disc("1/2", {"-1", "0"}, {"6", "0"}),
       {{at(Rational(1, 3)), at(Rational(2, 3))}},
       {{at(Rational(1, 3)), at(Rational(2, 3))}}},
      // parallel paths 3 apart, R = 1: never
      {"parallel, apart", m.disc("1/2", {"-3", "0"}, {"6", "0"}), m.disc("1/2", {"-3", "3"}, {"6", "0"}), {}, {}},
      // parallel lanes 1/2 apart, R = 1: every s meets some t and back
      {"parallel lanes",
       m.disc("1/2", {"-3", "0"}, {"6", "0"}),
       m.disc("1/2", {"-3", "1/2"}, {"6", "0"}),
       {{at(Rational(0)), at(one)}},
       {{at(Rational(0)), at(one)}}},
      // only near the ends: c_A(s) = (3s, 0), c_B(t) = (7/2, 3t), R = 1: 7/2 - 3s <= 1, s >= 5/6;
      // (1/2)^2 + (3t)^2 <= 1, 12 t^2 - 1 <= 0, t <= sqrt(3)/6
      {"meeting only near the ends",
       m.disc("1/2", {"0", "0"}, {"3", "0"}),
       m.disc("1/2", {"7/2", "0"}, {"0", "3"}),
       {{at(Rational(5, 6)), at(one)}},
       {{at(Rational(0)), root({-1, 0, 12}, Rational(1, 4), Rational(3, 10))}}},
      // partial overlap of collinear paths: c_A(s) = (4s, 0), c_B(t) = (2 + 4t, 0), R = 1/3:
      // 4s >= 2 - 1/3, s >= 5/12; 2 + 4t <= 4 + 1/3, t <= 7/12
      {"partial overlap of paths",
       m.disc("1/6", {"0", "0"}, {"4", "0"}),
       m.disc("1/6", {"2", "0"}, {"4", "0"}),
       {{at(Rational(5, 12)), at(one)}},
       {{at(Rational(0)), at(Rational(7, 12))}}},
      // collinear lanes, opposite directions: c_A(s) = (4s, 0), c_B(t) = (5 - 4t, 0), R = 1/3:
      // 4s >= 1 - 1/3, s >= 1/6; 5 - 4t <= 4 + 1/3, t >= 1/6
      {"collinear lanes",
       m.disc("1/6", {"0", "0"}, {"4", "0"}),
       m.disc("1/6", {"5", "0"}, {"-4", "0"}),
       {{at(Rational(1, 6)), at(one)}},
       {{at(Rational(1, 6)), at(one)}}},
      // a static body: c_A(s) = (6s - 3, 1/2), B at the origin, R = 1: (6s - 3)^2 <= 3/4, 48 s^2 - 48 s + 11 <= 0
      {"a static disc",
       m.disc("1/2", {"-3", "1/2"}, {"6", "0"}),
       m.disc("1/2", {"0", "0"}, {"0", "0"}),
       {{root({11, -48, 48}, Rational(1, 3), Rational(1, 2)), root({11, -48, 48}, Rational(1, 2), Rational(2, 3))}},
       {{at(Rational(0)), at(one)}}},
      // a static ellipse (2, 1) and a disc r = 1/2 along its minor axis: c_A(s) = (0, 9s - 5), |9s - 5| <= 3/2
      {"a static ellipse",
       m.disc("1/2", {"0", "-5"}, {"0", "9"}),
       m.ellipse({"2", "1"}, {"0", "0"}, {"0", "0"}),
       {{at(Rational(7, 18)), at(Rational(13, 18))}},
       {{at(Rational(0)), at(one)}}},
      // a body turning in place (it does not move as a set): a disc r = 1 turning about its centre, the origin;
      // c_B(t) = (6t - 3, 1), R = 3/2: (6t - 3)^2 + 1 <= 9/4, 144 t^2 - 144 t + 31 <= 0; every s alike
      {"a body turning in place",
       m.turning_disc("1"),
       m.disc("1/2", {"-3", "1"}, {"6", "0"}),
       {{at(Rational(0)), at(one)}},
       {{root({31, -144, 144}, Rational(1, 4), Rational(1, 2)),
         root({31, -144, 144}, Rational(1, 2), Rational(3, 4))}}},
  };
}

}  // namespace

TEST_CASE("independent kinds in 2D: exact, certified and double against the analytic ends", "[independent][kinds]") {
  for (const Kind& k : kinds(Maker{2})) check_kind(2, k);
}

TEST_CASE("independent kinds in 3D: exact, certified and double against the analytic ends", "[independent][kinds]") {
  for (const Kind& k : kinds(Maker{3})) check_kind(3, k);
}

#include "floating/independent_ccd.hpp"
#include "io/scene_reader.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/trivariate_bernstein.hpp"
#include "number/double_traits.hpp"
#include "number/running_error.hpp"

namespace ECCD_UNITY_ID {
TEST_CASE("as published and guarded: plain double and Bounded<double> give the 2D crossing's ends",
          "[independent][kinds]") {
  // the floating pipeline is one template: plain T (as published) and Bounded<T> (guarded) on the same F
  const Maker m{2};
  Scene sc = scene_from_text(scene(2, m.disc("1/2", {"2", "-3"}, {"0", "6"}), m.disc("1/2", {"-1", "0"}, {"6", "0"})),
                             "crossing");
  sc.independent = false;  // prepare_pair is the shared-parameter preparation; F takes A's parameter as s, B's as t
  const PreparedPair<3> p = prepare_pair<3>(sc);
  const IndependentResult plain =
      ccd_independent(independent_ellipsoid_function<double, 3>(to_arithmetic_bernstein<double, 3>(p, 1.0)), 1.0);
  const Bounded<double> one(1.0, 0);
  const IndependentResult guarded = ccd_independent(
      independent_ellipsoid_function<Bounded<double>, 3>(to_arithmetic_bernstein<Bounded<double>, 3>(p, one)), one);
  for (const IndependentResult* r : {&plain, &guarded}) {
    CHECK(r->answer.collides);
    CHECK(r->answer.undecided.empty());
    REQUIRE(r->answer.s_intervals.size() == 1);
    REQUIRE(r->answer.t_intervals.size() == 1);
    CHECK(std::abs(r->answer.s_intervals[0].first.value - 1.0 / 3) <= 1e-8);
    CHECK(std::abs(r->answer.s_intervals[0].second.value - 2.0 / 3) <= 1e-8);
    CHECK(std::abs(r->answer.t_intervals[0].first.value - 1.0 / 3) <= 1e-8);
    CHECK(std::abs(r->answer.t_intervals[0].second.value - 2.0 / 3) <= 1e-8);
  }
}

TEST_CASE(
    "F(u, s, t) of ellipses has the ellipsoids' sign convention: F(0) = det A < 0, F(1) = det B < 0, > 0 where apart",
    "[independent][kinds]") {
  // discs r = 1/2 at (2, -3 + 6s) and (6t - 1, 0): apart at s = t = 0 (distance > 1), overlapping at s = t = 1/2 (same
  // centre)
  const Maker m{2};
  Scene sc = scene_from_text(scene(2, m.disc("1/2", {"2", "-3"}, {"0", "6"}), m.disc("1/2", {"-1", "0"}, {"6", "0"})),
                             "crossing");
  sc.independent = false;
  const TriBern<Rational> F = independent_ellipsoid_function<Rational, 3>(
      to_arithmetic_bernstein<Rational, 3>(prepare_pair<3>(sc), Rational(1)));
  const Rational h(1, 2), z(0), o(1);
  CHECK(sgn(F(z, h, h)) < 0);
  CHECK(sgn(F(o, h, h)) < 0);
  CHECK(sgn(F(h, z, z)) > 0);  // separate: F > 0 at some u (here u = 1/2, equal discs)
  for (int k = 1; k < 8; ++k) CHECK(sgn(F(Rational(k, 8), h, h)) < 0);  // the same disc twice: overlap, F < 0 on (0, 1)
}

TEST_CASE("hold_still: a disc or ball turning about its centre is held at s = 0, a moving or turning ellipse is not",
          "[independent][kinds]") {
  for (const int dim : {2, 3}) {
    INFO(dim << "D");
    const Maker m{dim};
    auto net = [&](const std::string& a, std::array<bool, 2>& still) {
      Scene sc = scene_from_text(scene(dim, a, m.disc("1/2", {"-3", "1"}, {"6", "0"})), "still");
      sc.independent = false;
      if (dim == 2)
        return independent_ellipsoid_function<Rational, 3>(
            to_arithmetic_bernstein<Rational, 3>(prepare_pair<3>(sc), Rational(1)), &still);
      return independent_ellipsoid_function<Rational, 4>(
          to_arithmetic_bernstein<Rational, 4>(prepare_pair<4>(sc), Rational(1)), &still);
    };
    std::array<bool, 2> still{};
    // turning in place: degree 0 in s, and F held at s = 0 equals the static disc's F exactly
    const TriBern<Rational> turning = net(m.turning_disc("1"), still);
    CHECK(still[0]);
    CHECK_FALSE(still[1]);
    CHECK(turning.n[1] == 0);
    std::array<bool, 2> still0{};
    const TriBern<Rational> fixed = net(m.disc("1", {"0", "0"}, {"0", "0"}), still0);
    CHECK_FALSE(still0[0]);  // already of degree 0: nothing to hold
    // A(0) = k Q with k > 0: each u-layer j of the net is the static one's times k^(H - j)
    REQUIRE(fixed.n == turning.n);
    for (int j = 0; j <= fixed.n[0]; ++j)
      for (int l = 0; l <= fixed.n[2]; ++l) {
        CHECK(fixed.at(j, 0, l) * turning.at(j, 0, 0) == turning.at(j, 0, l) * fixed.at(j, 0, 0));
        CHECK(sgn(fixed.at(j, 0, l)) * sgn(turning.at(j, 0, l)) >= 0);
      }
    // a translating disc moves as a set
    CHECK(net(m.disc("1", {"0", "0"}, {"1", "0"}), still).n[1] > 0);
    CHECK_FALSE(still[0]);
  }
  // an ellipse turning about its centre changes as a set (ellipses-turning's A): not held
  std::array<bool, 2> still{};
  Scene sc = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/independent/ellipses-turning.json");
  sc.independent = false;
  const TriBern<Rational> F = independent_ellipsoid_function<Rational, 3>(
      to_arithmetic_bernstein<Rational, 3>(prepare_pair<3>(sc), Rational(1)), &still);
  CHECK_FALSE(still[0]);
  CHECK(F.n[1] > 0);
}

}  // namespace ECCD_UNITY_ID
