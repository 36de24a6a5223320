// Sturm sequences (kernel/sturm.hpp): root counts of polynomials with known
// rational roots in all three arithmetics, a multiple root in exact
// arithmetic, and the fixed-capacity version against the Poly<T> one.
#include "kernel/sturm.hpp"
#include "tests/support/arith.hpp"

#include <catch2/catch.hpp>

#include <optional>
#include <random>
#include <type_traits>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::test;
using Q = mpq_class;

TEMPLATE_TEST_CASE("Sturm counts distinct real roots of a square-free polynomial", "[kernel][sturm]", double, Mpfr,
                   mpq_class) {
  using T = TestType;
  // (t - 1/3) (t - 1/2) (t + 2) (t - 3/2)
  Poly<Q> p = Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 2), Q(1)}) * Poly<Q>({Q(2), Q(1)}) * Poly<Q>({Q(-3, 2), Q(1)});
  CHECK(count_roots_closed(from_q<T>(p), from_q<T>(Q(0)), from_q<T>(Q(1))) == 2);
  CHECK(count_roots<T>(from_q<T>(p), std::optional<T>(), std::optional<T>(from_q<T>(Q(0)))) == 1);
  CHECK(count_roots<T>(from_q<T>(p), std::optional<T>(), std::optional<T>()) == 4);
  CHECK(count_roots_closed(from_q<T>(p), from_q<T>(Q(2, 5)), from_q<T>(Q(1))) == 1);
  if constexpr (scalar_traits<T>::is_exact)  // a root exactly at an end: decidable only exactly
    CHECK(count_roots_closed(from_q<T>(p), from_q<T>(Q(1, 2)), from_q<T>(Q(1))) == 1);
}

TEST_CASE("exact Sturm counts distinct roots of a polynomial with a multiple root", "[kernel][sturm][exact]") {
  // (t - 1/3)² (t - 1/2) (t + 2): distinct roots in [0, 1]: 1/3 and 1/2. (In
  // rounded arithmetic a multiple root makes the Sturm sequence ill-posed.)
  Poly<Q> p = Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 2), Q(1)}) * Poly<Q>({Q(2), Q(1)});
  CHECK(count_roots_closed(p, Q(0), Q(1)) == 2);
  CHECK(count_roots<Q>(p, std::optional<Q>(), std::optional<Q>(Q(0))) == 1);
  CHECK(count_roots<Q>(p, std::optional<Q>(), std::optional<Q>()) == 3);
  CHECK(count_roots_closed(p, Q(1, 3), Q(1, 2)) == 2);
}

TEMPLATE_TEST_CASE("fixed-capacity Sturm (count_roots_inline) counts as the Poly<T> version", "[kernel][sturm]", double,
                   Mpfr, mpq_class) {
  using T = TestType;
  std::mt19937_64 rng(seed_from_env(31337));
  for (int trial = 0; trial < 200; ++trial) {
    Poly<Q> pq = random_poly(rng, trial % 5);
    if (trial % 7 == 0)
      pq = Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 3), Q(1)}) * random_poly(rng, trial % 3);  // a double root
    std::vector<T> c;
    for (int i = 0; i <= 4; ++i) c.push_back(from_q<T>(pq.coeff(i)));  // zero leading coefficients included
    Poly<T> p(c);
    INFO("trial " << trial << ", degree " << pq.degree());
    for (auto [a, b] : {std::pair<std::optional<Q>, std::optional<Q>>{std::nullopt, Q(0)},
                        {std::nullopt, std::nullopt},
                        {Q(-1), Q(1, 3)},
                        {Q(0), Q(1)}}) {
      std::optional<T> at = a ? std::optional<T>(from_q<T>(*a)) : std::nullopt;
      std::optional<T> bt = b ? std::optional<T>(from_q<T>(*b)) : std::nullopt;
      CHECK(count_roots_inline<5, T>(std::span<const T>(c), at, bt) == count_roots(p, at, bt));
    }
  }
  if constexpr (scalar_traits<T>::is_exact) {
    // (t - 1/3)² (t + 2): the gcd division counts the double root at an end once
    Poly<Q> p = Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(-1, 3), Q(1)}) * Poly<Q>({Q(2), Q(1)});
    CHECK(count_roots_inline<5, Q>(std::span<const Q>(p.c), Q(-3), Q(1, 3)) == 2);
    CHECK(count_roots_inline<5, Q>(std::span<const Q>(p.c), Q(1, 3), std::nullopt) == 0);
  }
  if constexpr (std::is_same_v<T, double>) {  // an uncertain sign (NaN): no count, as for intervals
    std::vector<double> c{1.0, std::nan(""), -3.0, 0.5, 1.0};
    CHECK(count_roots_inline<5, double>(std::span<const double>(c), std::nullopt, 0.0) == -2);
    CHECK(count_roots(Poly<double>(c), std::optional<double>(), std::optional<double>(0.0)) == -2);
  }
  std::vector<T> zero(3, from_q<T>(Q(0)));
  CHECK(count_roots_inline<5, T>(std::span<const T>(zero), std::nullopt, std::nullopt) == -1);
  std::vector<T> six(6, from_q<T>(Q(1)));
  auto too_many = [&] { return count_roots_inline<5, T>(std::span<const T>(six), std::nullopt, std::nullopt); };
  CHECK_THROWS_AS(too_many(), std::length_error);
}

}  // namespace ECCD_UNITY_ID
