// Local escalation (issue 18 point 2, certified/certified_policy.hpp "Local
// decisions", certified/point_oracle.hpp): one uncertain sign at one rational
// instant is decided there exactly instead of escalating the scene. Checked
// against the exact pipeline: the oracle's g(t) and static test equal the
// exact pipeline's at random dyadic instants; the exact value of a formula
// the policy keeps equals the exact projection's value; a scene that used to
// leave the interval rung on one sign is now decided in it, with the exact
// pipeline's answer; and every touch and near-miss scene of cases/ gets the
// stored (exact) answer.
#include "api/solve.hpp"
#include "certified/certified_policy.hpp"
#include "certified/ladder.hpp"
#include "certified/point_oracle.hpp"
#include "compare/regress.hpp"
#include "exact/cd_disc_exact.hpp"
#include "io/scene_reader.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quartic_touch_rule.hpp"
#include "number/interval.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

const std::string kCases = std::string(ECCD_SOURCE_DIR) + "/cases/";

// Random dyadic instants k / 2^20 in [0, 1], with 0 and 1.
std::vector<Rational> dyadics(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<long> k(0, 1L << 20);
  std::vector<Rational> ts{Rational(0), Rational(1)};
  for (int i = 0; i < n; ++i) ts.push_back(Rational(mpz_class(k(rng)), mpz_class(1L << 20)));
  return ts;
}

template <int H>
void check_oracle(const std::string& file, unsigned seed) {
  INFO(file);
  Scene s = read_scene_file(kCases + file);
  PreparedPair<H> p = prepare_pair<H>(s);
  const std::vector<Poly<Rational>> g = characteristic_of(to_arithmetic<Rational, H>(p, Rational(1)));
  PreparedPointOracle<H> oracle(p);
  for (const Rational& t : dyadics(seed, 12)) {
    INFO("t = " << t.get_str());
    const std::vector<Rational> gt = oracle.g_at(t);
    REQUIRE(gt.size() == std::size_t(H + 1));
    std::vector<Rational> ge;
    for (int i = 0; i <= H; ++i) ge.push_back(g[i].is_zero() ? Rational(0) : g[i](t));
    CHECK(gt == ge);
    // the static test, as the exact pipeline runs it at a sample
    const Status exact = H == 3 ? cubic_contact_status(ge[3], ge[2], ge[1], ge[0]) : quartic_contact_status(ge);
    CHECK(oracle.status_at(t) == exact);
  }
}

// The exact value the certified policy keeps for the projection it builds
// equals the exact pipeline's projection at the same instant.
template <int H>
void check_projection_sign(const std::string& file, unsigned seed) {
  INFO(file);
  Scene s = read_scene_file(kCases + file);
  PreparedPair<H> p = prepare_pair<H>(s);
  PreparedPointOracle<H> oracle(p);
  CertifiedPolicy<Interval> pol(Interval(0));
  pol.oracle = &oracle;
  const std::vector<Poly<Interval>> gi = characteristic_of(to_arithmetic<Interval, H>(p, Interval(0)));
  const std::vector<Poly<Rational>> ge = characteristic_of(to_arithmetic<Rational, H>(p, Rational(1)));
  auto formula = [](const auto& G) {
    if constexpr (H == 3)
      return cubic_discriminant(G[3], G[2], G[1], G[0]);
    else
      return quartic_discriminant(G[4], G[3], G[2], G[1], G[0]);
  };
  const auto q = pol.build(gi, formula);
  REQUIRE(bool(q.exact));
  const Poly<Rational> exact = formula(ge);
  for (const Rational& t : dyadics(seed, 8)) {
    INFO("t = " << t.get_str());
    const Rational v = exact.is_zero() ? Rational(0) : exact(t);
    const Sign want = sgn(v) > 0 ? Sign::positive : sgn(v) < 0 ? Sign::negative : Sign::zero;
    CHECK(pol.exact_sign(q, t) == want);
  }
}

bool is_touch_or_near_miss(const std::string& path) {
  for (const char* k : {"touch", "near-miss", "away", "towards", "short-overlap", "rolling"})
    if (path.find(k) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("the exact oracle at a rational instant agrees with the exact pipeline's g and static test", "[local]") {
  check_oracle<3>("generated/2d/2d-deg3-touch-kinematic-370301508307387.json", 1);
  check_oracle<3>("generated/2d/2d-deg4-colliding-kinematic-572211152701880.json", 2);
  check_oracle<3>("paper003/example2.json", 3);
  check_oracle<4>("paper002/example.json", 4);
  check_oracle<4>("generated/3d-euler/3d-deg3-touch-euler-4948564508118114.json", 5);
  check_oracle<4>("spheres/spheres-touch.json", 6);
}

TEST_CASE("the certified policy's exact value of a projection it built is the exact projection's", "[local]") {
  check_projection_sign<3>("generated/2d/2d-deg4-colliding-kinematic-572211152701880.json", 7);
  check_projection_sign<3>("paper003/example2.json", 8);
  check_projection_sign<4>("generated/3d-euler/3d-deg2-colliding-euler-3526122894755803.json", 9);
}

TEST_CASE("an identically zero projection is recognised exactly, not escalated", "[local]") {
  // Two spheres: λ = 1 is a double root of f for every t, so the quartic's
  // discriminant vanishes identically (002; kernel/ccd_projection.hpp). In
  // intervals its coefficients only enclose 0: without the oracle the policy
  // cannot tell and escalates; with it, the answer is proved from d + 1 values.
  Scene s = read_scene_file(kCases + "spheres/spheres-crossing.json");
  PreparedPair<4> p = prepare_pair<4>(s);
  PreparedPointOracle<4> oracle(p);
  const std::vector<Poly<Interval>> gi = characteristic_of(to_arithmetic<Interval, 4>(p, Interval(0)));
  auto disc = [](const auto& G) { return quartic_discriminant(G[4], G[3], G[2], G[1], G[0]); };
  CertifiedPolicy<Interval> plain(Interval(0));
  const auto q0 = plain.build(gi, disc);
  bool certain = true;
  for (const auto& x : q0.b) certain = certain && sign(x) != Sign::uncertain;
  if (!certain) CHECK_THROWS_AS(plain.identically_zero(q0), Escalate);
  CertifiedPolicy<Interval> pol(Interval(0));
  pol.oracle = &oracle;
  CHECK(pol.identically_zero(pol.build(gi, disc)));
  // the first subresultant coefficient psc_1 = s(1,1) does not vanish identically
  auto psc1 = [](const auto& G) { return subresultant_evidence(G, 1, 1); };
  CHECK_FALSE(pol.identically_zero(pol.build(gi, psc1)));
}

namespace {
long local_count(const Solution& s, const std::string& kind) {
  for (const auto& [k, n] : s.local_decisions)
    if (k == kind) return n;
  return 0;
}
}  // namespace

TEST_CASE("a 3D short overlap that left the interval rung on uncertain cell statuses is decided in it locally",
          "[local]") {
  // Without the oracle the interval rung leaves the statuses of the cells
  // inside the 1e-5-long overlap (depth 1e-9) uncertain and the scene goes
  // to exact; with it, each of those statuses is decided exactly at its
  // dyadic sample, and the answer is the stored (exact) one.
  Scene s = read_scene_file(kCases + "short-overlap/3d-deg2-short-overlap-1e-9-euler-18.json");
  REQUIRE(s.answer);
  PreparedPair<4> p = prepare_pair<4>(s);
  LadderBudget before;
  before.local = false;
  Solution old = run_certified<4>(p, {256}, Variant::answer, false, before);
  CHECK(old.decided_in == "exact");
  CHECK(old.local_decisions.empty());
  bool interval_gave_up = false;
  for (const Escalation& e : old.escalations)
    if (e.rung == "interval") interval_gave_up = e.reason.find("undecided") != std::string::npos;
  CHECK(interval_gave_up);
  Solution now = run_certified<4>(p, {256}, Variant::answer, false);
  CHECK(now.decided_in == "interval");
  CHECK(now.certified);
  CHECK(local_count(now, "cell_status") >= 1);
  CHECK(regress_differences(*s.answer, now.answer).empty());
  CHECK(regress_differences(old.answer, now.answer).empty());
}

TEST_CASE("a 2D rolling pair (Δ ≡ 0) is decided in intervals with an exact identically-zero test", "[local]") {
  // Two circles rolling on each other: f has a double root for every t, so Δ
  // vanishes identically (003 Corollary 7: never separate); the interval
  // coefficients only enclose 0, which used to send the scene to exact.
  Scene s = read_scene_file(kCases + "rolling/circles-rolling.json");
  REQUIRE(s.answer);
  PreparedPair<3> p = prepare_pair<3>(s);
  LadderBudget before;
  before.local = false;
  Solution old = run_certified<3>(p, {256}, Variant::answer, false, before);
  CHECK(old.decided_in == "exact");
  Solution now = run_certified<3>(p, {256}, Variant::answer, false);
  CHECK(now.decided_in == "interval");
  CHECK(local_count(now, "identically_zero") >= 1);
  CHECK(now.projection_identically_zero);
  CHECK(regress_differences(*s.answer, now.answer).empty());
  CHECK(regress_differences(run_exact<3>(p, Variant::answer, false).answer, now.answer).empty());
}

TEST_CASE("every touch and near-miss scene of cases/ gets the exact pipeline's answer in certified mode", "[local]") {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kCases)) {
    const std::string path = e.path().string();
    if (e.path().extension() != ".json" || !is_touch_or_near_miss(path)) continue;
    if (path.find("/animations/") != std::string::npos || path.find("/independent/") != std::string::npos) continue;
    Scene s = read_scene_file(path);
    if (!s.answer || s.independent) continue;
    INFO(path);
    SolveOptions o;
    o.arith = parse_arithmetic("certified");
    Solution c = solve(s, o);
    CHECK(c.certified);
    CHECK(regress_differences(*s.answer, c.answer).empty());
    ++n;
  }
  CHECK(n >= 40);
}

}  // namespace ECCD_UNITY_ID
