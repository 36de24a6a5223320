// The one build of a projection polynomial in a basis (kernel/basis_build.hpp):
// in exact arithmetic every basis gives the same polynomial. The sign
// variations are tests/kernel/test_sign_variations.cpp, the policy concept
// tests/kernel/test_pipeline_policy.cpp.
#include "exact/cd_disc_exact.hpp"
#include "kernel/basis_build.hpp"
#include "kernel/discriminant.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

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

}  // namespace ECCD_UNITY_ID
