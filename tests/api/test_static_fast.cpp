// The fast double static test (issue 21, api/static_status.hpp): ForwardBound's
// a-priori error bound (number/forward_bound.hpp) and the sign rule of
// kernel/quartic_sign_status.hpp. It must never disagree with the exact
// status: on random pairs, on pairs built exactly touching (dyadic spheres
// and axis-aligned ellipsoids at distance r1 + r2, where it must say
// uncertain) and on near-touching ones, where a third of the sphere pairs at
// least must be decided (f's positive double root leaves the Sturm count open:
// kernel/negative_axis_status.hpp). Never timed (bench/eccd_bench.cpp).
#include "api/static_status.hpp"
#include "api/static_filter_simd.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/fast_quartic.hpp"
#include "kernel/quartic_sign_status.hpp"
#include "kernel/quartic_status.hpp"
#include "number/forward_bound.hpp"
#include "number/rational_traits.hpp"
#include "tests/support/arith.hpp"
#include "tests/support/poses.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using eccd::test::pose2;
using eccd::test::pose3;

// The double answer is the exact one or uncertain; counts the decided ones.
template <class Shape>
bool never_wrong(const Shape& a, const Shape& b) {
  Status d = static_status(a, b), ex = static_status(a, b, Arithmetic::exact());
  INFO("double " << to_string(d) << ", exact " << to_string(ex));
  CHECK((d == Status::uncertain || d == ex));
  return d != Status::uncertain;
}

}  // namespace

TEST_CASE("ForwardBound: a sign it claims is the exact sign of the same program on the given doubles", "[static]") {
  // Discriminants of quartics with clustered roots: heavy cancellation, so many signs are uncertain; a certain
  // one must be the exact sign of the discriminant of the same double coefficients.
  std::mt19937_64 rng(210001);
  std::uniform_real_distribution<double> r(-2, 2), tiny(-1e-6, 1e-6);
  int certain = 0, uncertain = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    double c0 = r(rng), roots[4] = {c0, c0 + tiny(rng), r(rng), trial % 2 ? r(rng) : c0 + tiny(rng) * 1e-4};
    // coefficients of prod (x - roots[i]) in double: exact leaves for the check below
    std::array<double, 5> p{1, 0, 0, 0, 0};  // decreasing powers
    for (double z : roots)
      for (int k = 4; k >= 1; --k) p[k] = p[k] - z * p[k - 1];
    ForwardBound f[5];
    mpq_class q[5];
    for (int k = 0; k < 5; ++k) {
      f[k] = ForwardBound::exact(p[k]);
      q[k] = mpq_class(p[k]);
    }
    Sign s = sign(quartic_discriminant(f[0], f[1], f[2], f[3], f[4]));
    Sign e = sign(quartic_discriminant(q[0], q[1], q[2], q[3], q[4]));
    if (s == Sign::uncertain) {
      ++uncertain;
      continue;
    }
    ++certain;
    REQUIRE(s == e);
  }
  CHECK(certain > 100);
  CHECK(uncertain > 100);  // the test reaches the bound's edge
}

TEST_CASE("quartic_sign_status equals the Sturm status in exact arithmetic, touches included", "[static]") {
  // B = Tᵀ diag(qb) T with T a rational rotation (3/5, 4/5 in a plane) and translation; A = diag(1/a², ..).
  std::mt19937_64 rng(210002);
  std::uniform_int_distribution<int> quarter(1, 12), off(-24, 24);
  int seen[3] = {0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    mpq_class a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = mpq_class(quarter(rng), 4);
      b[i] = mpq_class(quarter(rng), 4);
    }
    if (trial % 3 == 0) {
      a[1] = a[2] = a[0];
      b[1] = b[2] = b[0];
    }  // spheres
    mpq_class c[3] = {mpq_class(off(rng), 8), mpq_class(off(rng), 8), mpq_class(off(rng), 8)};
    if (trial % 3 == 0) {
      c[0] = a[0] + b[0];
      c[1] = c[2] = 0;
    }  // exactly touching spheres
    mpq_class R[3][3] = {{mpq_class(3, 5), mpq_class(-4, 5), 0}, {mpq_class(4, 5), mpq_class(3, 5), 0}, {0, 0, 1}};
    if (trial % 3 == 0)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R[i][j] = i == j ? 1 : 0;
    mpq_class T[4][4], qb[4] = {1 / (b[0] * b[0]), 1 / (b[1] * b[1]), 1 / (b[2] * b[2]), -1};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) T[i][j] = 0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) T[i][j] = R[j][i];
      T[i][3] = -(R[0][i] * c[0] + R[1][i] * c[1] + R[2][i] * c[2]);
    }
    T[3][3] = 1;
    std::array<std::array<mpq_class, 4>, 4> B;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        mpq_class s = 0;
        for (int k = 0; k < 4; ++k) s += T[k][i] * qb[k] * T[k][j];
        B[i][j] = s;
      }
    auto g = appendix_a_coefficients<mpq_class>(1 / (a[0] * a[0]), 1 / (a[1] * a[1]), 1 / (a[2] * a[2]), B);
    Status s = quartic_sign_status(g), want = quartic_contact_status(g);
    CHECK(std::string(to_string(s)) == to_string(want));
    seen[int(want == Status::separate ? 0 : want == Status::touching ? 1 : 2)]++;
  }
  CHECK(seen[0] > 10);
  CHECK(seen[1] > 10);
  CHECK(seen[2] > 10);
}

TEST_CASE("fast double static test never disagrees with the exact status (random, touching, near-touching)",
          "[static]") {
  std::uint64_t seed = test::seed_from_env(210003);
  INFO("seed " << seed << " (set ECCD_TEST_SEED to repeat)");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> axis(0.2, 3), ang(0, 6.3), pos(-4, 4), q(-1, 1);
  int decided3 = 0, decided2 = 0;
  const int n = 3000;
  for (int trial = 0; trial < n; ++trial) {
    INFO("trial " << trial);
    decided3 += never_wrong(Ellipsoid{{axis(rng), axis(rng), axis(rng)},
                                      pose3({q(rng), q(rng), q(rng), q(rng)}, pos(rng), pos(rng), pos(rng))},
                            Ellipsoid{{axis(rng), axis(rng), axis(rng)},
                                      pose3({q(rng), q(rng), q(rng), q(rng)}, pos(rng), pos(rng), pos(rng))});
    decided2 += never_wrong(Ellipse{{axis(rng), axis(rng)}, pose2(ang(rng), pos(rng), pos(rng))},
                            Ellipse{{axis(rng), axis(rng)}, pose2(ang(rng), pos(rng), pos(rng))});
  }
  CHECK(decided3 > n * 95 / 100);
  CHECK(decided2 > n * 95 / 100);

  // Touching and near-touching: spheres / axis-aligned ellipsoids with dyadic radii at distance r1 + r2 + eps,
  // along a dyadic direction (3/5, 4/5, 0 scaled: the centre is exact in double only along axes, so use axes).
  std::uniform_int_distribution<int> quarter(1, 12), axis_pick(0, 2);
  int touches = 0, near_decided = 0, near_asymmetric = 0, near_spheres = 0, near_spheres_decided = 0;
  for (int trial = 0; trial < 200; ++trial) {
    double r1 = quarter(rng) / 4.0, r2 = quarter(rng) / 4.0, s1 = quarter(rng) / 4.0, s2 = quarter(rng) / 4.0;
    int ax = axis_pick(rng);
    bool spheres = trial % 2 == 0;
    for (double eps : {0.0, 0x1p-8, -0x1p-8, 0x1p-20, -0x1p-20, 0x1p-40, -0x1p-40}) {
      INFO("trial " << trial << " eps " << eps);
      double c[3] = {0, 0, 0};
      c[ax] = r1 + r2 + eps;
      // Not spheres: the two axes across the line differ (s1, s1 + 1/8) so that f has no positive double
      // root (Δ = 0 by symmetry otherwise: the spheres' case, where the sign rule cannot decide).
      std::array<double, 3> ea{s1, s1, s1}, eb{s2, s2, s2};
      ea[(ax + 1) % 3] = s1 + 0.125;
      eb[(ax + 2) % 3] = s2 + 0.375;
      if (spheres) {
        ea = {r1, r1, r1};
        eb = {r2, r2, r2};
      }
      ea[ax] = r1;
      eb[ax] = r2;
      Ellipsoid a{ea, pose3({1, 0, 0, 0}, 0, 0, 0)}, b{eb, pose3({1, 0, 0, 0}, c[0], c[1], c[2])};
      Status d = static_status(a, b), ex = static_status(a, b, Arithmetic::exact());
      Status want = eps == 0 ? Status::touching : eps > 0 ? Status::separate : Status::overlapping;
      REQUIRE(std::string(to_string(ex)) == to_string(want));
      if (eps == 0) {
        ++touches;
        CHECK(d == Status::uncertain);  // a touch is a double root: double cannot prove it
      } else {
        CHECK((d == Status::uncertain || d == ex));
        if (!spheres) {
          ++near_asymmetric;
          near_decided += d != Status::uncertain;
        } else {  // f's positive double root: the Sturm count is open, the negative axis decides
          ++near_spheres;
          near_spheres_decided += d != Status::uncertain;
        }
      }
    }
  }
  CHECK(touches == 200);
  INFO(near_decided << " of " << near_asymmetric << " near-touching asymmetric pairs decided in double");
  CHECK(near_decided > near_asymmetric / 3);  // the 2^-8 and 2^-20 offsets at least are mostly decided
  INFO(near_spheres_decided << " of " << near_spheres << " near-touching sphere pairs decided in double");
  CHECK(near_spheres_decided > near_spheres / 3);  // kernel/negative_axis_status.hpp
}

TEST_CASE("static_status_batch gives static_status pair by pair (double and certified, 2D and 3D)", "[static]") {
  std::mt19937_64 rng(210004);
  std::uniform_real_distribution<double> axis(0.2, 3), ang(0, 6.3), pos(-4, 4), q(-1, 1);
  const int n = 1003;  // not a multiple of the block
  std::vector<Ellipsoid> a3, b3;
  std::vector<Ellipse> a2, b2;
  for (int i = 0; i < n; ++i) {
    if (i % 10 == 3) {  // exactly touching spheres along x
      a3.push_back(Ellipsoid{{0.5, 0.5, 0.5}, pose3({1, 0, 0, 0}, 0, 0, 0)});
      b3.push_back(Ellipsoid{{0.75, 0.75, 0.75}, pose3({1, 0, 0, 0}, 1.25, 0, 0)});
      a2.push_back(Ellipse{{0.5, 0.25}, pose2(0, 0, 0)});
      b2.push_back(Ellipse{{0.75, 1.5}, pose2(0, 1.25, 0)});
      continue;
    }
    a3.push_back(Ellipsoid{{axis(rng), axis(rng), axis(rng)},
                           pose3({q(rng), q(rng), q(rng), q(rng)}, pos(rng), pos(rng), pos(rng))});
    b3.push_back(Ellipsoid{{axis(rng), axis(rng), axis(rng)},
                           pose3({q(rng), q(rng), q(rng), q(rng)}, pos(rng), pos(rng), pos(rng))});
    a2.push_back(Ellipse{{axis(rng), axis(rng)}, pose2(ang(rng), pos(rng), pos(rng))});
    b2.push_back(Ellipse{{axis(rng), axis(rng)}, pose2(ang(rng), pos(rng), pos(rng))});
  }
  // Every instruction set this CPU runs (issue 36: AVX2 beside AVX-512, and pair by pair), each giving the single
  // pairs' answers.
  std::vector<simd::Isa> isas{simd::Isa::none};
  if (simd::has_avx2()) isas.push_back(simd::Isa::avx2);
  if (simd::has_avx512()) isas.push_back(simd::Isa::avx512);
  for (simd::Isa isa : isas)
    for (const Arithmetic& arith : {Arithmetic::double_precision(), Arithmetic::certified()}) {
      INFO(arith.name() << " " << simd::to_string(isa));
      simd::set_static_batch_isa_limit(isa);
      CHECK(simd::static_batch_isa() == isa);
      std::vector<Status> o3(n), o2(n);
      static_status_batch(std::span<const Ellipsoid>(a3), std::span<const Ellipsoid>(b3), std::span<Status>(o3), arith);
      static_status_batch(std::span<const Ellipse>(a2), std::span<const Ellipse>(b2), std::span<Status>(o2), arith);
      for (int i = 0; i < n; ++i) {
        INFO("pair " << i);
        CHECK(o3[i] == static_status(a3[i], b3[i], arith));
        CHECK(o2[i] == static_status(a2[i], b2[i], arith));
        if (i % 10 == 3) {
          CHECK(o3[i] == (arith.kind == Arithmetic::Double ? Status::uncertain : Status::touching));
          CHECK(o2[i] == (arith.kind == Arithmetic::Double ? Status::uncertain : Status::touching));
        }
      }
    }
  simd::set_static_batch_isa_limit(simd::Isa::avx512);
  CHECK(simd::static_batch_isa() == simd::cpu_isa());
  // Bad input: sizes, and a bad pair named by its index, nothing written.
  std::vector<Status> out(n, Status::separate);
  CHECK_THROWS_AS(static_status_batch(std::span<const Ellipsoid>(a3), std::span<const Ellipsoid>(b3).first(5),
                                      std::span<Status>(out)),
                  std::invalid_argument);
  b3[7].semi_axes[1] = -1;
  CHECK_THROWS_WITH(
      static_status_batch(std::span<const Ellipsoid>(a3), std::span<const Ellipsoid>(b3), std::span<Status>(out)),
      Catch::Contains("pair 7"));
  CHECK(out[0] == Status::separate);
}

}  // namespace ECCD_UNITY_ID
