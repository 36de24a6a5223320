// Issue 21's speed-ups of the 3D Bézier pipeline must not change what it
// computes:
//  - g_0..g_H by the shared expansion over the 3^H column states
//    (kernel/characteristic_polynomial.hpp) equal, bit for bit and with the
//    same running error bounds, the sum of the 2^H determinants det(C_S) by
//    ring_det, the formula it replaced (003 section III eq. (1), 002 section 3);
//  - the peak's witness u located in plain double to half the precision
//    (floating/bezier_ccd.hpp, bern_argmax) gives the peak value of the quartic
//    F(., t0) to the rounding noise of double: compared with the peak found in
//    MPFR at 200 bits;
//  - keep_u_left / keep_u_right give split_u's pieces.
#include "floating/bezier_ccd.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "number/rational_traits.hpp"
#include "number/running_error.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// The formula the shared expansion replaced: one ring_det per column set.
template <class R, int H>
std::vector<R> by_column_sets(const std::array<std::array<R, H>, H>& a, const std::array<std::array<R, H>, H>& b,
                              const R& zero) {
  std::vector<R> g(H + 1, zero);
  for (unsigned mask = 0; mask < (1u << H); ++mask) {
    std::vector<std::vector<R>> c(H, std::vector<R>(H, zero));
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) c[i][j] = (mask >> j & 1u) ? a[i][j] : b[i][j];
    const int k = std::popcount(mask);
    R d = ring_det(c, zero);
    if ((H - k) % 2)
      g[k] = g[k] - d;
    else
      g[k] = g[k] + d;
  }
  return g;
}

template <class T, int H>
void random_matrices(std::mt19937_64& rng, std::array<std::array<Bern<T>, H>, H>& a,
                     std::array<std::array<Bern<T>, H>, H>& b, auto make) {
  std::normal_distribution<double> nd(0.0, 1.0);
  std::uniform_int_distribution<int> deg(0, 2), zero_one(0, 5);
  for (auto* m : {&a, &b})
    for (auto& row : *m)
      for (auto& e : row) {
        e.b.clear();
        const bool zero = zero_one(rng) == 0;  // some zero entries: ring_det skips them
        for (int k = 0; k <= (zero ? 0 : deg(rng)); ++k) e.b.push_back(make(zero ? 0.0 : nd(rng)));
      }
}

}  // namespace

TEST_CASE("g_k by the shared expansion equal the 2^H determinants bit for bit", "[kernel][bezier][speed21]") {
  std::uint64_t seed = test::seed_from_env(2121);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  int compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    {  // double, 4x4 (3D)
      std::array<std::array<Bern<double>, 4>, 4> a, b;
      random_matrices<double, 4>(rng, a, b, [](double x) { return x; });
      const Bern<double> zero(std::vector<double>{0.0});
      const auto got = characteristic_coefficients_in<Bern<double>, 4>(a, b, zero);
      const auto want = by_column_sets<Bern<double>, 4>(a, b, zero);
      REQUIRE(got.size() == want.size());
      for (std::size_t k = 0; k < got.size(); ++k) {
        REQUIRE(got[k].b.size() == want[k].b.size());
        for (std::size_t i = 0; i < got[k].b.size(); ++i) {
          REQUIRE(got[k].b[i] == want[k].b[i]);  // the same operations in the same order
          ++compared;
        }
      }
    }
    {  // Bounded<double>, 4x4: values and running error bounds
      std::uniform_real_distribution<double> err(0.0, 1e-15);
      std::array<std::array<Bern<Bounded<double>>, 4>, 4> a, b;
      random_matrices<Bounded<double>, 4>(rng, a, b,
                                          [&](double x) { return Bounded<double>(x, x == 0 ? 0.0 : err(rng)); });
      const Bern<Bounded<double>> zero(std::vector<Bounded<double>>{Bounded<double>(0.0, 0.0)});
      const auto got = characteristic_coefficients_in<Bern<Bounded<double>>, 4>(a, b, zero);
      const auto want = by_column_sets<Bern<Bounded<double>>, 4>(a, b, zero);
      for (std::size_t k = 0; k < got.size(); ++k) {
        REQUIRE(got[k].b.size() == want[k].b.size());
        for (std::size_t i = 0; i < got[k].b.size(); ++i) {
          REQUIRE(got[k].b[i].value() == want[k].b[i].value());
          REQUIRE(got[k].b[i].bound() == want[k].b[i].bound());
        }
      }
    }
    {  // rationals, 3x3 (2D), scalar entries
      std::uniform_int_distribution<int> num(-9, 9), den(1, 7);
      std::array<std::array<Rational, 3>, 3> a, b;
      for (auto* m : {&a, &b})
        for (auto& row : *m)
          for (auto& e : row) e = Rational(mpq_class(num(rng), den(rng)));
      const auto got = characteristic_coefficients_in<Rational, 3>(a, b, Rational(0));
      const auto want = by_column_sets<Rational, 3>(a, b, Rational(0));
      for (std::size_t k = 0; k < got.size(); ++k) REQUIRE(got[k] == want[k]);
    }
  }
  CHECK(compared > 1000);
}

TEST_CASE("the peak of F(., t0) from a half-precision witness u is the peak to double's noise",
          "[floating][bezier][speed21]") {
  std::uint64_t seed = test::seed_from_env(5021);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> nd(0.0, 1.0);
  double worst = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // F(., t0) of two ellipsoids: a quartic, negative at both ends (det A < 0, det B < 0)
    Bern<double> f;
    f.b = {-std::fabs(nd(rng)) - 0.01, nd(rng), nd(rng), nd(rng), -std::fabs(nd(rng)) - 0.01};
    Bern<Mpfr> fm;
    Bern<Bounded<double>> fb;
    for (double x : f.b) {
      fm.b.push_back(Mpfr(x, 200));
      fb.b.push_back(Bounded<double>(x, 0.0));
    }
    double scale = 0;
    for (double x : f.b) scale = std::max(scale, std::fabs(x));
    const auto pd = bern_argmax(f, 53);
    const auto pb = bern_argmax(fb, 53);
    const auto pm = bern_argmax(fm, 200);
    const double vm = to_double(pm.value);
    // the witness is found in the same plain double either way
    REQUIRE(pb.u.value() == pd.u);
    REQUIRE(pb.value.value() == pd.value);
    // at most a few roundings of the evaluation below the true peak (never above it by more than them)
    const double diff = std::fabs(pd.value - vm) / scale;
    worst = std::max(worst, diff);
    REQUIRE(diff < 0x1p-48);
  }
  INFO("worst relative difference " << worst);
  CHECK(worst < 0x1p-48);
}

TEST_CASE("keep_u_left and keep_u_right are split_u's pieces", "[kernel][bezier][speed21]") {
  std::mt19937_64 rng(test::seed_from_env(77));
  std::normal_distribution<double> nd(0.0, 1.0);
  BiBern<double> f;
  f.b.assign(5, std::vector<double>(7));
  for (auto& row : f.b)
    for (auto& x : row) x = nd(rng);
  for (double tau : {0.5, 0.25, 0.7}) {
    auto [lo, hi] = split_u(f, tau);
    BiBern<double> l = f, h = f;
    keep_u_left(l, tau);
    keep_u_right(h, tau);
    REQUIRE(l.b == lo.b);
    REQUIRE(h.b == hi.b);
    // the pieces meet: F(tau, t) is the left piece at u = 1 and the right piece at u = 0
    for (std::size_t j = 0; j < f.b[0].size(); ++j) {
      REQUIRE(std::fabs(l.b.back()[j] - h.b.front()[j]) <= 1e-12);
      std::vector<double> col;
      for (const auto& row : f.b) col.push_back(row[j]);
      REQUIRE(std::fabs(bernstein_value(std::span<const double>(col), tau) - h.b.front()[j]) <= 1e-12);
    }
  }
}

}  // namespace ECCD_UNITY_ID
