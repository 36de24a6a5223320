// The pieces every pipeline shares: sign variations with an uncertain flag
// (kernel/sign_variations.hpp), the policy concept (kernel/pipeline_policy.hpp)
// and the one build of a projection polynomial in a basis (kernel/basis_build.hpp).
#include "certified/certified_policy.hpp"
#include "exact/cd_disc_exact.hpp"
#include "exact/descartes.hpp"
#include "floating/cd_disc_floating.hpp"
#include "kernel/basis_build.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/pipeline_policy.hpp"
#include "kernel/sign_variations.hpp"
#include "number/interval.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

TEST_CASE("sign variations: zeros skipped, exact counts", "[kernel][sign_variations]") {
  CHECK(sign_variations(std::vector<Q>{1, -2, 0, 3, -1}).is(3));
  CHECK(sign_variations(std::vector<Q>{0, 0, 5, 0, 7}).is(0));
  CHECK(sign_variations(std::vector<Q>{}).is(0));
  CHECK(sign_variations(std::vector<double>{-1.0, 0.0, 0.0, 2.0}).is(1));
  CHECK_FALSE(sign_variations(std::vector<Q>{1, -1}).uncertain);
}

TEST_CASE("sign variations report an uncertain sign instead of skipping it", "[kernel][sign_variations]") {
  // [1, [-1, 1], -1]: 1 or 2 changes are possible (the middle sign is unknown);
  // skipping the middle value would claim exactly 1, hence one simple root.
  std::vector<Interval> xs{Interval(1), Interval(-1.0, 1.0), Interval(-1)};
  SignVariations v = sign_variations(xs);
  CHECK(v.uncertain);
  CHECK_FALSE(v.is(1));
  // certain intervals count as their sign
  std::vector<Interval> ys{Interval(1.0, 2.0), Interval(-3.0, -2.0), Interval(0), Interval(1.0, 1.5)};
  CHECK(sign_variations(ys).is(2));
}

TEST_CASE("the certified policy does not take an uncertain count for one root",
          "[kernel][sign_variations][certified]") {
  // The middle coefficients' signs stay unknown on every piece: the policy
  // must escalate, never report a bracket it has not proved.
  Bern<Interval> q({Interval(1), Interval(-1.0, 1.0), Interval(-1.0, 1.0), Interval(-1)});
  CertifiedPolicy<Interval> pol(Interval(1));
  pol.max_depth = 12;
  CHECK_THROWS_AS(pol.roots(q, false), Escalate);
}

TEST_CASE("Descartes on an interval agrees with the number of roots for products of linear factors",
          "[kernel][sign_variations][descartes]") {
  // p = (t - 1/5)(t - 1/2)(t - 4/5)(t - 2): on (0, 1) three simple roots; V = 3 (V - #roots even, >= 0).
  Poly<Q> p({Q(1)});
  for (Q r : {Q(1, 5), Q(1, 2), Q(4, 5), Q(2)}) p = p * Poly<Q>({Q(-r), Q(1)});
  CHECK(descartes_variations(p, Q(0), Q(1)) == 3);
  CHECK(descartes_variations(p, Q(0), Q(3, 10)) == 1);
  CHECK(descartes_variations(p, Q(3, 10), Q(2, 5)) == 0);
}

namespace {
struct NotAPolicy {
  using Rep = Poly<Q>;
  using Root = int;
};
}  // namespace

TEST_CASE("the pipeline policies satisfy the concept, other types do not", "[kernel][policy]") {
  STATIC_REQUIRE(PipelinePolicy<ExactPolicy, Rational>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<double>, double>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<Mpfr>, Mpfr>);
  STATIC_REQUIRE(PipelinePolicy<CertifiedPolicy<Interval>, Interval>);
  STATIC_REQUIRE_FALSE(PipelinePolicy<NotAPolicy, Rational>);
  STATIC_REQUIRE_FALSE(PipelinePolicy<ExactPolicy, double>);  // an exact policy takes rational instants
  // the optional hooks: rounded policies have them, exact and interval ones do not
  STATIC_REQUIRE(ReportsTrouble<FloatingPolicy<double>>);
  STATIC_REQUIRE(KeepsNotes<FloatingPolicy<double>>);
  STATIC_REQUIRE(NormalisesG<FloatingPolicy<double>, std::vector<Poly<double>>>);
  STATIC_REQUIRE(MayBeUnresolved<FloatRoot<double>>);
  STATIC_REQUIRE_FALSE(ReportsTrouble<ExactPolicy>);
  STATIC_REQUIRE_FALSE(NormalisesG<ExactPolicy, std::vector<Poly<Rational>>>);
  STATIC_REQUIRE_FALSE(MayBeUnresolved<AlgebraicRoot>);
}

TEST_CASE("a projection built in each basis is the same polynomial in exact arithmetic", "[kernel][basis]") {
  std::mt19937_64 rng(16);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Poly<Q>> g;
    for (int k = 0; k <= 3; ++k) g.push_back(random_poly(rng, 2 + trial % 3));
    auto disc = [](const auto& G) { return cubic_discriminant(G[3], G[2], G[1], G[0]); };
    Bern<Q> p = build_in_basis(Basis::power, g, disc, Q(0));
    Bern<Q> b = build_in_basis(Basis::bernstein, g, disc, Q(0));
    Bern<Q> s = build_in_basis(Basis::scaled_bernstein, g, disc, Q(0));
    Poly<Q> want = disc(g);
    INFO("trial " << trial);
    CHECK(to_power(p) == want);
    CHECK(to_power(b) == want);
    CHECK(to_power(s) == want);
    // the exact policy keeps the power form itself; the cubic form goes through the same build
    ExactPolicy ex;
    CHECK(build_cubic(ex, g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
            return cubic_discriminant(g3, g2, g1, g0);
          }) == want);
  }
}
