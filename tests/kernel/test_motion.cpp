// Every rational motion form: its polynomial inverse N satisfies M N = c(t) I
// exactly, with c(t) not identically zero (kernel/motion.hpp).
#include "kernel/motion.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

namespace {
template <int N>
void check_inverse(const Motion& m) {
  auto id = [](const Q& q) { return q; };
  PolyMatrix<Q, N> M = motion_matrix<Q, N>(m, id);
  PolyMatrix<Q, N> Ninv = motion_inverse<Q, N>(m, id);
  PolyMatrix<Q, N> P = product<Q, N>(M, Ninv);
  REQUIRE_FALSE(P[0][0].is_zero());
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      INFO("entry " << i << "," << j);
      if (i == j)
        CHECK(P[i][j] == P[0][0]);
      else
        CHECK(P[i][j].is_zero());
    }
}
}  // namespace

TEST_CASE("motion inverses: M N = c(t) I for every rational form", "[kernel][motion]") {
  std::uint64_t seed = seed_from_env(42);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 5; ++trial) {
    KinematicMotion k;
    for (auto& d : k.d) d = random_poly(rng, 2);
    check_inverse<H_2D>(Motion(k));
    EulerMotion e;
    for (auto& x : e.e) x = random_poly(rng, 2);
    for (auto& x : e.v) x = random_poly(rng, 3);
    e.v3 = random_poly(rng, 1);
    check_inverse<H_3D>(Motion(e));
    MatrixMotion mm;
    mm.m.assign(3, std::vector<RPoly>(3));
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 3; ++j) mm.m[i][j] = random_poly(rng, 2);
    mm.m[2][2] = random_poly(rng, 1);
    check_inverse<H_2D>(Motion(mm));
  }
  check_inverse<H_2D>(Motion(StaticMotion{}));
}

}  // namespace ECCD_UNITY_ID
