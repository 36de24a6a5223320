// Tensor-product Bernstein polynomials against exact power-form evaluation,
// and the 4x4 characteristic polynomial (two spheres: λ = 1 is a double root).
#include "kernel/bivariate_bernstein.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/quadric.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <type_traits>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

TEMPLATE_TEST_CASE("bivariate Bernstein: conversion, evaluation and subdivision in u and t", "[kernel][bivariate]",
                   double, Mpfr, mpq_class) {
  using T = TestType;
  std::uint64_t seed = seed_from_env(99);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  std::vector<Poly<Q>> a;  // F(u, t) = sum_i a[i](t) u^i, degree 3 in u, 4 in t
  for (int i = 0; i <= 3; ++i) a.push_back(random_poly(rng, 4));
  auto exact = [&](const Q& u, const Q& t) {
    Q s = 0, ui = 1;
    for (const auto& p : a) {
      s += ui * p(t);
      ui *= u;
    }
    return s;
  };
  std::vector<Poly<T>> at;
  for (const auto& p : a) at.push_back(from_q<T>(p));
  BiBern<T> f = to_bibernstein(at, 3, 4);
  auto close = [&](const T& x, const Q& y) {
    T d = x - from_q<T>(y);
    return std::abs(to_double(d)) <= tolerance<T>() * 100;
  };
  const Q tau(2, 5);
  auto [tl, th] = split_t(f, from_q<T>(tau));
  auto [ul, uh] = split_u(f, from_q<T>(tau));
  for (Q u : {Q(0), Q(1, 3), Q(1)})
    for (Q t : {Q(0), Q(1, 2), Q(5, 7), Q(1)}) {
      INFO("u = " << u.get_str() << ", t = " << t.get_str());
      CHECK(close(f(from_q<T>(u), from_q<T>(t)), exact(u, t)));
      CHECK(close(tl(from_q<T>(u), from_q<T>(t)), exact(u, tau * t)));
      CHECK(close(th(from_q<T>(u), from_q<T>(t)), exact(u, tau + (1 - tau) * t)));
      CHECK(close(ul(from_q<T>(u), from_q<T>(t)), exact(tau * u, t)));
      CHECK(close(uh(from_q<T>(u), from_q<T>(t)), exact(tau + (1 - tau) * u, t)));
    }
  // a positive polynomial has a strictly positive control net after enough subdivision
  BiBern<T> one = to_bibernstein(std::vector<Poly<T>>{Poly<T>::constant(from_q<T>(Q(3)))}, 2, 2);
  CHECK(one.strict_sign() == 1);
}

TEST_CASE("4x4 characteristic polynomial: two spheres always have the double root λ = 1 (003 VII, 002)",
          "[kernel][characteristic]") {
  // x²+y²+z²-1 at the origin; x²+y²+z²-4 translated by (3t, 0, 0) (with
  // this normalisation of the two spheres the double root is λ = 1):
  // N(t) = [[1,0,0,-3t],[0,1,0,0],[0,0,1,0],[0,0,0,1]].
  Matrix<Q, 4> qa{}, qb{};
  for (int i = 0; i < 3; ++i) {
    qa[i][i] = 1;
    qb[i][i] = 1;
  }
  qa[3][3] = -1;
  qb[3][3] = -4;
  PolyMatrix<Q, 4> na = identity_poly_matrix<Q, 4>(), nb = identity_poly_matrix<Q, 4>();
  nb[0][3] = Poly<Q>({Q(0), Q(-3)});
  auto g = characteristic_coefficients<Q, H_3D>(moving_quadric<Q, H_3D>(qa, na), moving_quadric<Q, H_3D>(qb, nb));
  REQUIRE(g.size() == 5);
  for (Q t : {Q(0), Q(1, 3), Q(1)}) {
    Q f1 = 0, df1 = 0;
    for (int k = 0; k <= 4; ++k) {
      f1 += g[k](t);
      df1 += k * g[k](t);
    }
    CHECK(f1 == 0);   // f(1) = 0
    CHECK(df1 == 0);  // f'(1) = 0: a double root
  }
  CHECK(g[4].degree() == 0);  // det A, constant
}

TEMPLATE_TEST_CASE("split_u and split_t in place equal split() of every column and row", "[kernel][bivariate]", double,
                   Mpfr, mpq_class) {
  using T = TestType;
  std::mt19937_64 rng(seed_from_env(2718));
  std::vector<Poly<T>> at;
  for (int i = 0; i <= 4; ++i) at.push_back(from_q<T>(random_poly(rng, 9)));
  BiBern<T> f = to_bibernstein(at, 4, 9);
  auto same = [](const T& a, const T& b) {
    if constexpr (std::is_same_v<T, Mpfr>)
      return a.precision() == b.precision() && mpfr_equal_p(a.get(), b.get());
    else
      return a == b;
  };
  for (Q tq : {Q(1, 2), Q(3, 11)}) {
    const T tau = from_q<T>(tq);
    auto [ul, uh] = split_u(f, tau);
    auto [tl, th] = split_t(f, tau);
    bool all = true;
    for (int j = 0; j <= 9; ++j) {
      Bern<T> col;
      for (int i = 0; i <= 4; ++i) col.b.push_back(f.b[i][j]);
      auto [l, h] = split(col, tau);
      for (int i = 0; i <= 4; ++i) all = all && same(ul.b[i][j], l.b[i]) && same(uh.b[i][j], h.b[i]);
    }
    for (int i = 0; i <= 4; ++i) {
      auto [l, h] = split(Bern<T>(f.b[i]), tau);
      for (int j = 0; j <= 9; ++j) all = all && same(tl.b[i][j], l.b[j]) && same(th.b[i][j], h.b[j]);
    }
    CHECK(all);
  }
}

}  // namespace ECCD_UNITY_ID
