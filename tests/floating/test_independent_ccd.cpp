// Independent motions by subdivision of F(u, s, t)
// (floating/independent_ccd.hpp; paper 001 section 4), in plain double and
// guarded Bounded<double>, on unit discs on straight paths whose P_s and P_t
// are known in closed form (A(s) meets some B(t) iff the distance from A's
// centre to the segment B's centre sweeps is at most 2):
//   - A at (6, 6s - 3), B at (10t - 5, 0): A passes beyond the end (5, 0) of
//     B's segment, P_s = [(3 - √3)/6, (3 + √3)/6] (irrational ends:
//     1 + (6s - 3)² = 4), and B enters A's swept segment x = 6 when
//     10t - 5 >= 4, P_t = [9/10, 1]; the ends within the bisection's
//     tolerance 2^-s_depth (here 1e-9), no undecided instants;
//   - the same A shifted away (x = 8): no s, no t, collides = false, proved;
//   - a touch (x = 7: the distance to (5, 0) is 2 at s = 1/2 only): the answer
//     may leave it undecided but claims nothing wrong (a claimed interval holds
//     1/2; "no collision" is never claimed with nothing undecided);
//   - A not moving (degree 0 in s, one strip) at (6, 1): B reaches it when
//     (11 - 10t)² + 1 <= 4, P_t = [(11 - √3)/10, 1], and P_s = [0, 1];
//   - a budget of a few u-box tests: the run stops with reasons, claims
//     nothing false, and what it proves is still right;
//   - the work of the crossing scene (box tests, a count) and the same ends
//     when the u-pieces may go down to the depth limit on every t-piece.
#include "floating/independent_ccd.hpp"
#include "kernel/prepared_scene.hpp"
#include "number/double_traits.hpp"
#include "number/running_error.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

SceneObject unit_disc(const Rational& x0, const Rational& dx, const Rational& y0, const Rational& dy) {
  SceneObject o;
  o.Q = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  MatrixMotion m;
  m.m.assign(3, std::vector<RPoly>(3));
  for (int i = 0; i < 3; ++i) m.m[i][i] = RPoly::constant(Rational(1));
  m.m[0][2] = RPoly(std::vector<Rational>{x0, dx});
  m.m[1][2] = RPoly(std::vector<Rational>{y0, dy});
  o.motion = m;
  return o;
}

// A at (xa, ya0 + ya1 s), B at (10t - 5, 0): the net F(u, s, t) in T
template <class T>
TriBern<T> net(const Rational& xa, const T& like, const Rational& ya0 = -3, const Rational& ya1 = 6) {
  Scene sc;
  sc.dim = 2;
  sc.a = unit_disc(xa, 0, ya0, ya1);
  sc.b = unit_disc(-5, 10, 0, 0);
  sc.independent = false;  // prepare_pair's shared preparation; F takes A's parameter as s and B's as t
  return independent_ellipsoid_function<T, 3>(to_arithmetic_bernstein<T, 3>(prepare_pair<3>(sc), like));
}

template <class T>
T one_of();
template <>
double one_of<double>() {
  return 1.0;
}
template <>
Bounded<double> one_of<Bounded<double>>() {
  return Bounded<double>(1.0, 0);
}

}  // namespace

TEMPLATE_TEST_CASE("ccd_independent finds irrational and rational ends of P_s and P_t", "[floating][independent_ccd]",
                   double, Bounded<double>) {
  const TestType one = one_of<TestType>();
  const IndependentResult r = ccd_independent(net<TestType>(6, one), one);
  CHECK(r.answer.collides);
  CHECK(r.answer.undecided.empty());
  REQUIRE(r.answer.s_intervals.size() == 1);
  REQUIRE(r.answer.t_intervals.size() == 1);
  const double s0 = (3 - std::sqrt(3.0)) / 6, s1 = (3 + std::sqrt(3.0)) / 6;
  CHECK(std::fabs(r.answer.s_intervals[0].first.value - s0) <= 1e-9);
  CHECK(std::fabs(r.answer.s_intervals[0].second.value - s1) <= 1e-9);
  CHECK(std::fabs(r.answer.t_intervals[0].first.value - 0.9) <= 1e-9);
  CHECK(r.answer.t_intervals[0].second.value == 1.0);  // the interval reaches t = 1, proved in up to the end
  CHECK(r.degree_s >= 1);
  CHECK(r.degree_t >= 1);
  // the work (a count, not a time): the s-ends lie where B's path stops (t = 1), the t-end at a fold; the point
  // tests near them use t- and u-pieces of about one width (IndependentOptions::u_lead) and the edge t = 1 alone.
  // About 0.56 M box tests in both faces; 4.5 M when every t-piece was searched in u down to the depth limit.
  REQUIRE(r.counters.front().first == "box_tests");
  CHECK(r.counters.front().second <= 1000000);
}

// u_lead bounds how a proof is searched, not what it proves (a sub-box of a proved box is proved too): with the
// u-pieces of every t-piece allowed down to the depth limit (u_lead 64) the answer is the same and the work is
// more than 3 times larger on the crossing scene above (about 2.5 M box tests against 0.56 M).
TEMPLATE_TEST_CASE("ccd_independent's u-pieces follow the t-pieces' depth: the same ends for less work",
                   "[floating][independent_ccd]", double, Bounded<double>) {
  const TestType one = one_of<TestType>();
  IndependentOptions wide;
  wide.u_lead = 64;
  const IndependentResult r = ccd_independent(net<TestType>(6, one), one),
                          w = ccd_independent(net<TestType>(6, one), one, wide);
  CHECK(w.answer.undecided.empty());
  CHECK(r.counters.front().second * 3 < w.counters.front().second);
  REQUIRE(r.answer.s_intervals.size() == 1);
  REQUIRE(w.answer.s_intervals.size() == 1);
  REQUIRE(w.answer.t_intervals.size() == 1);
  CHECK(std::fabs(w.answer.s_intervals[0].first.value - r.answer.s_intervals[0].first.value) <= 1e-9);
  CHECK(std::fabs(w.answer.s_intervals[0].second.value - r.answer.s_intervals[0].second.value) <= 1e-9);
  CHECK(std::fabs(w.answer.t_intervals[0].first.value - r.answer.t_intervals[0].first.value) <= 1e-9);
}

TEMPLATE_TEST_CASE("ccd_independent proves a miss", "[floating][independent_ccd]", double, Bounded<double>) {
  const TestType one = one_of<TestType>();
  // A at x = 8: distance >= 3 from B's segment
  const IndependentResult r = ccd_independent(net<TestType>(8, one), one);
  CHECK_FALSE(r.answer.collides);
  CHECK(r.answer.undecided.empty());
  CHECK(r.answer.s_intervals.empty());
  CHECK(r.answer.t_intervals.empty());
}

TEMPLATE_TEST_CASE("ccd_independent on a touch and on a small budget claims nothing false",
                   "[floating][independent_ccd]", double, Bounded<double>) {
  const TestType one = one_of<TestType>();
  {  // A at x = 7: touches B(1) at s = 1/2 only
    const IndependentResult r = ccd_independent(net<TestType>(7, one), one);
    if (r.answer.undecided.empty()) CHECK(r.answer.collides);  // the touch is not a miss
    for (const auto& [a, b] : r.answer.s_intervals) {
      CHECK(a.value <= 0.5 + 1e-6);
      CHECK(b.value >= 0.5 - 1e-6);
      CHECK(b.value - a.value <= 1e-3);  // nothing more than the touching instant
    }
    for (const auto& [a, b] : r.answer.t_intervals) CHECK(b.value >= 1 - 1e-6);
  }
  {  // a budget of 50 u-box tests on the crossing scene
    IndependentOptions o;
    o.max_tests = 50;
    const IndependentResult r = ccd_independent(net<TestType>(6, one), one, o);
    CHECK_FALSE(r.answer.undecided.empty());
    CHECK_FALSE(r.undecided_reasons.empty());
    const double s0 = (3 - std::sqrt(3.0)) / 6, s1 = (3 + std::sqrt(3.0)) / 6;
    for (const auto& [a, b] : r.answer.s_intervals) {  // what is claimed in P_s is in P_s
      CHECK(a.value >= s0 - 1e-9);
      CHECK(b.value <= s1 + 1e-9);
    }
    for (const auto& [a, b] : r.answer.t_intervals) CHECK(a.value >= 0.9 - 1e-9);
  }
}

// Plain double only: the guarded arithmetic is run on the moving cases above (and doubles this file's time).
TEST_CASE("ccd_independent with a body that does not move", "[floating][independent_ccd]") {
  const double one = 1.0;
  // A fixed at (6, 1): B(t) = (10t - 5, 0) within 2 iff (11 - 10t)^2 + 1 <= 4 iff t >= (11 - √3)/10
  const IndependentResult r = ccd_independent(net<double>(6, one, 1, 0), one);
  CHECK(r.answer.collides);
  CHECK(r.answer.undecided.empty());
  CHECK(r.degree_s == 0);
  REQUIRE(r.answer.s_intervals.size() == 1);
  CHECK(r.answer.s_intervals[0].first.value == 0.0);
  CHECK(r.answer.s_intervals[0].second.value == 1.0);
  REQUIRE(r.answer.t_intervals.size() == 1);
  CHECK(std::fabs(r.answer.t_intervals[0].first.value - (11 - std::sqrt(3.0)) / 10) <= 1e-9);
  CHECK(r.answer.t_intervals[0].second.value == 1.0);
}

}  // namespace ECCD_UNITY_ID
