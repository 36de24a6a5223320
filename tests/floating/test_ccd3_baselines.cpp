// The two 3D baselines (floating/ccd3_baselines.hpp) against the exact
// projection pipeline (kernel/ccd_projection.hpp with ExactPolicy) on the
// sphere scenes of cases/spheres, whose notes give the answers analytically.
// Asserted: the number of intervals, endpoint errors within the bound each
// baseline's construction gives, the containment property of sampling, and
// the documented blind spot of sampling (an isolated touch at t = 1/2 is seen
// only when 1/2 is a sample, i.e. for even N). Run in double and in MPFR at
// 128 bits (and once in exact arithmetic, where sampling's property is a proof).
#include "floating/ccd3_baselines.hpp"
#include "kernel/ccd_projection.hpp"
#include "tests/support/scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

namespace {

template <class T>
T base_like();
template <>
double base_like<double>() {
  return 1.0;
}
template <>
Mpfr base_like<Mpfr>() {
  return Mpfr(Q(1), 128);
}
template <>
Q base_like<Q>() {
  return Q(1);
}

Scene sphere_scene(const std::string& name) { return read_scene_file(case_path("spheres/" + name + ".json")); }

template <class T>
MovingPair3<T> pair_in(const Scene& s) {
  return to_arithmetic<T, H_3D>(prepare_pair<H_3D>(s), base_like<T>());
}

PipelineResult<Rational> exact_3d(const Scene& s, bool first_contact = false) {
  ExactPolicy pol;
  MovingPair3<Rational> m = to_arithmetic<Rational, H_3D>(prepare_pair<H_3D>(s), Rational(1));
  return ccd_projection(m, pol, first_contact);
}

// An exact instant as a double: the midpoint of its bracket (width <= 2^-64).
double value(const Instant& i) {
  if (i.certified()) {
    Q m = (*i.lo + *i.hi) / 2;
    return m.get_d();
  }
  return std::stod(i.approx);
}

std::string brief(const Answer& a) {
  std::string s = a.collides ? "collides" : "free";
  for (const auto& [x, y] : a.intervals) s += " [" + x.approx.substr(0, 12) + ", " + y.approx.substr(0, 12) + "]";
  if (!a.contacts.empty()) s += " contacts:" + std::to_string(a.contacts.size());
  if (!a.undecided.empty()) s += " undecided:" + std::to_string(a.undecided.size());
  return s;
}

// Largest endpoint error of `got` against `truth` (same number of intervals).
double max_endpoint_error(const Answer& got, const Answer& truth) {
  double e = 0;
  for (std::size_t i = 0; i < truth.intervals.size(); ++i) {
    e = std::max(e, std::abs(value(got.intervals[i].first) - value(truth.intervals[i].first)));
    e = std::max(e, std::abs(value(got.intervals[i].second) - value(truth.intervals[i].second)));
  }
  return e;
}

const std::vector<std::string> kWellSeparatedEvents{"spheres-crossing", "spheres-free", "spheres-overlap-start",
                                                    "spheres-overlap-end"};

}  // namespace

TEST_CASE("the exact ground truth reproduces the analytic answer of spheres-crossing", "[baseline3d]") {
  auto ex = exact_3d(sphere_scene("spheres-crossing"));
  REQUIRE(ex.answer.intervals.size() == 1);
  const double r = std::sqrt(139.0) / 32;
  CHECK(std::abs(value(ex.answer.intervals[0].first) - (0.5 - r)) < 1e-15);
  CHECK(std::abs(value(ex.answer.intervals[0].second) - (0.5 + r)) < 1e-15);
  CHECK(ex.answer.contacts.size() == 2);
}

TEMPLATE_TEST_CASE("sampling:100 and sampling:1000 find the exact intervals, each endpoint inside and within 1/N",
                   "[baseline3d][sampling]", double, Mpfr) {
  using T = TestType;
  for (const int N : {100, 1000})
    for (const auto& name : kWellSeparatedEvents) {
      INFO(name << ", N = " << N);
      Scene s = sphere_scene(name);
      auto ex = exact_3d(s);
      auto sa = ccd_sampling(pair_in<T>(s), N, false);
      INFO("exact " << brief(ex.answer) << "   sampling " << brief(sa.answer));
      CHECK(sa.variant == Variant::answer);
      CHECK(sa.status_at_0 == ex.status_at_0);
      CHECK(sa.cells.size() == std::size_t(N + 1));
      CHECK(sa.answer.undecided.empty());
      CHECK(sa.answer.collides == ex.answer.collides);
      REQUIRE(sa.answer.intervals.size() == ex.answer.intervals.size());
      CHECK(max_endpoint_error(sa.answer, ex.answer) < 1.0 / N);
      // the reported run lies inside the true interval: a start is a colliding
      // sample at or after the true start, an end one at or before the true end
      for (std::size_t i = 0; i < ex.answer.intervals.size(); ++i) {
        CHECK(value(sa.answer.intervals[i].first) >= value(ex.answer.intervals[i].first));
        CHECK(value(sa.answer.intervals[i].second) <= value(ex.answer.intervals[i].second));
      }
      // every run end with a separate neighbour is a transition: 2 for crossing, 1 for overlap-start/end
      std::size_t inner_ends = 0;
      for (const auto& [a, b] : ex.answer.intervals) inner_ends += (value(a) > 0) + (value(b) < 1);
      CHECK(sa.critical.size() == inner_ends);
    }
}

TEMPLATE_TEST_CASE("marching:100 finds the exact intervals, endpoints within 1/N of the truth",
                   "[baseline3d][marching]", double, Mpfr) {
  // The asserted bound is the grid spacing h = 1/N. A refined instant lies
  // in the strip [t_j, t_j + h] where the row status changes; when every row
  // has its true status (checked below against the exact static test at the
  // same instants) and a strip holds one event, the true instant lies in the
  // same strip. The interpolation does much better (O(h²) at a generic tip,
  // see the header; the report measures them), so
  // h/4 is asserted too: it fails if the refinement degenerates into
  // reporting grid rows (error up to h).
  using T = TestType;
  const int N = 100;
  for (const auto& name : kWellSeparatedEvents) {
    INFO(name);
    Scene s = sphere_scene(name);
    auto ex = exact_3d(s);
    auto ma = ccd_marching(pair_in<T>(s), N, false);
    INFO("exact " << brief(ex.answer) << "   marching " << brief(ma.answer));
    CHECK(ma.status_at_0 == (in_collision(ex.status_at_0) ? Status::overlapping : Status::separate));
    CHECK(ma.cells.size() == std::size_t(N + 1));
    CHECK(ma.answer.undecided.empty());
    CHECK(ma.answer.collides == ex.answer.collides);
    REQUIRE(ma.answer.intervals.size() == ex.answer.intervals.size());
    // the premise of the bound: every grid row has the true status (the exact
    // static test at the same instants j/N, i.e. sampling:N in exact arithmetic)
    auto rows = ccd_sampling(pair_in<Q>(s), N, false);
    REQUIRE(rows.cells.size() == ma.cells.size());
    for (std::size_t j = 0; j < rows.cells.size(); ++j) {
      INFO("row " << j);
      CHECK(in_collision(ma.cells[j].status) == in_collision(rows.cells[j].status));
    }
    const double err = max_endpoint_error(ma.answer, ex.answer);
    CHECK(err < 1.0 / N);
    CHECK(err < 0.25 / N);
    // every refined transition is a touch, as the exact contacts on these scenes
    CHECK(ma.answer.contacts.size() == ex.answer.contacts.size());
    CHECK(ma.critical.size() == ex.answer.contacts.size());
  }
}

TEMPLATE_TEST_CASE("sampling sees the isolated touch of spheres-touch only when 1/2 is a sample (even N)",
                   "[baseline3d][sampling]", double, Mpfr) {
  // A documented property of sampling, not a bug: the collision set is {1/2}.
  using T = TestType;
  Scene s = sphere_scene("spheres-touch");
  auto ex = exact_3d(s);
  REQUIRE(ex.answer.intervals.size() == 1);
  auto pair = pair_in<T>(s);
  for (int N : {999, 101, 7}) {
    INFO("odd N = " << N);
    auto sa = ccd_sampling(pair, N, false);
    CHECK_FALSE(sa.answer.collides);
    CHECK(sa.answer.contacts.empty());
  }
  for (int N : {1000, 100, 2}) {
    INFO("even N = " << N);
    auto sa = ccd_sampling(pair, N, false);
    INFO(brief(sa.answer));
    REQUIRE(sa.answer.intervals.size() == 1);
    CHECK(value(sa.answer.intervals[0].first) == 0.5);
    CHECK(value(sa.answer.intervals[0].second) == 0.5);
    REQUIRE(sa.answer.contacts.size() == 1);
    CHECK(value(sa.answer.contacts[0]) == 0.5);
    REQUIRE(sa.critical.size() == 1);
    CHECK(sa.critical[0].status == Status::touching);
  }
}

TEMPLATE_TEST_CASE("marching sees the isolated touch only through a grid row at 1/2", "[baseline3d][marching]", double,
                   Mpfr) {
  // With N odd no row is at 1/2 and both rows around it are separate: missed.
  // With N even the row at 1/2 has F(., 1/2) <= 0 with its maximum 0 between
  // grid points, so it is in collision, and the refined transitions on both
  // sides make a short interval around 1/2 (the grid cannot tell a touch
  // from a short overlap): within one strip of 1/2 on each side. Whether the
  // row at 1/2 computes as "in collision" is a knife edge (max F = 0 exactly,
  // attained between grid points: a rounded grid value may come out positive;
  // since the pencil is balanced (kernel/prepared_scene.hpp) MPFR's does), so
  // an even N may also miss the touch, but it may report nothing else.
  using T = TestType;
  Scene s = sphere_scene("spheres-touch");
  auto pair = pair_in<T>(s);
  for (int N : {99, 101}) {
    INFO("odd N = " << N);
    CHECK_FALSE(ccd_marching(pair, N, false).answer.collides);
  }
  for (int N : {100, 40}) {
    INFO("even N = " << N);
    auto ma = ccd_marching(pair, N, false);
    INFO(brief(ma.answer));
    REQUIRE(ma.answer.intervals.size() <= 1);
    if (ma.answer.intervals.empty()) {
      WARN("marching:" << N << " missed the touch at 1/2 (rounded row value positive)");
      continue;
    }
    const double a = value(ma.answer.intervals[0].first), b = value(ma.answer.intervals[0].second);
    CHECK(a <= 0.5);
    CHECK(b >= 0.5);
    CHECK(a > 0.5 - 1.0 / N);
    CHECK(b < 0.5 + 1.0 / N);
  }
}

TEMPLATE_TEST_CASE("first-contact-only stops after the first interval, with the same first contact", "[baseline3d]",
                   double, Mpfr) {
  using T = TestType;
  Scene s = sphere_scene("spheres-crossing");
  auto pair = pair_in<T>(s);
  auto full_s = ccd_sampling(pair, 1000, false), first_s = ccd_sampling(pair, 1000, true);
  auto full_m = ccd_marching(pair, 100, false), first_m = ccd_marching(pair, 100, true);
  for (const auto* r : {&first_s, &first_m}) {
    CHECK(r->variant == Variant::first_contact);
    REQUIRE(r->answer.first_contact.has_value());
    CHECK(r->answer.intervals.size() == 1);
  }
  CHECK(first_s.answer.first_contact->approx == full_s.answer.first_contact->approx);
  CHECK(first_m.answer.first_contact->approx == full_m.answer.first_contact->approx);
  CHECK(first_s.answer.intervals[0].second.approx == full_s.answer.intervals[0].second.approx);
  CHECK(first_m.answer.intervals[0].second.approx == full_m.answer.intervals[0].second.approx);
  // sampling stopped at the first separate sample after the run (about t = 0.869)
  CHECK(first_s.cells.size() < full_s.cells.size());
  CHECK(first_s.cells.size() == 870);
  CHECK(first_m.cells.size() < full_m.cells.size());
}

TEST_CASE("the baselines in exact arithmetic: sampling's run ends are proved inside the collision set",
          "[baseline3d][exact]") {
  const int N = 64;
  for (const auto& name : kWellSeparatedEvents) {
    INFO(name);
    Scene s = sphere_scene(name);
    auto ex = exact_3d(s);
    auto sa = ccd_sampling(pair_in<Q>(s), N, false);
    auto ma = ccd_marching(pair_in<Q>(s), N, false);
    REQUIRE(sa.answer.intervals.size() == ex.answer.intervals.size());
    REQUIRE(ma.answer.intervals.size() == ex.answer.intervals.size());
    for (std::size_t i = 0; i < ex.answer.intervals.size(); ++i) {
      CHECK(value(sa.answer.intervals[i].first) >= value(ex.answer.intervals[i].first));
      CHECK(value(sa.answer.intervals[i].second) <= value(ex.answer.intervals[i].second));
    }
    CHECK(max_endpoint_error(sa.answer, ex.answer) < 1.0 / N);
    CHECK(max_endpoint_error(ma.answer, ex.answer) < 1.0 / N);
  }
}

TEST_CASE("the baselines reject a grid without cells", "[baseline3d]") {
  auto pair = pair_in<double>(sphere_scene("spheres-crossing"));
  CHECK_THROWS_AS(ccd_sampling(pair, 0, false), std::invalid_argument);
  CHECK_THROWS_AS(ccd_marching(pair, -3, false), std::invalid_argument);
}

// 002's example (f of degree 36 in t) in MPFR at 128 bits: both baselines
// find the exact intervals within the grid spacing. (In double its g_i, built
// in the power basis, are wrong at the 1e-2 level near t = 0.86 by
// cancellation, which moves double's endpoints whatever N is: the report
// measures that, it is not a property to assert.)
TEST_CASE("paper002's example in MPFR 128: sampling and marching within 1/N of the exact intervals",
          "[baseline3d][paper002]") {
  Scene s = read_scene_file(case_path("paper002/example.json"));
  auto ex = exact_3d(s);
  REQUIRE(ex.answer.intervals.size() == 2);
  const auto pm = pair_in<Mpfr>(s);
  struct Run {
    const char* method;
    int N;
    PipelineResult<Mpfr> r;
  };
  std::vector<Run> runs;
  runs.push_back({"sampling", 100, ccd_sampling(pm, 100, false)});
  runs.push_back({"sampling", 1000, ccd_sampling(pm, 1000, false)});
  runs.push_back({"marching", 100, ccd_marching(pm, 100, false)});
  for (const auto& run : runs) {
    INFO(run.method << ":" << run.N << "  exact " << brief(ex.answer) << "   baseline " << brief(run.r.answer));
    CHECK(run.r.answer.undecided.empty());
    CHECK(run.r.answer.collides);
    REQUIRE(run.r.answer.intervals.size() == ex.answer.intervals.size());
    CHECK(max_endpoint_error(run.r.answer, ex.answer) < 1.0 / run.N);
  }
}

}  // namespace ECCD_UNITY_ID
