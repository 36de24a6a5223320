// kernel/ellipsoid_function.hpp: F(u, t) = det((u - 1)A(t) - uB(t)) in
// tensor-product Bernstein form (001 section 4). Checked against:
//   - the defining identity F(u, t) = sum_i g_i(t) (u - 1)^i u^(4-i), evaluated
//     directly in mpq at seeded random rational (u, t) for random g_0..g_4 of
//     mixed degrees (a zero g_i included), for the power-form and the
//     Bernstein-form entry, for ellipsoid_function_at (a quartic in u) and
//     ellipsoid_function_along (a polynomial in t); the same in double within
//     a relative 1e-12 (a few dozen roundings of small integers);
//   - two unit spheres, A centred at (6t - 3, 0, 0), B at the origin: by hand
//     f(λ) = -(λ - 1)² (λ² - (2 - c²)λ + 1), c = 6t - 3; F's corners are
//     F(0, t) = g_4 = det A and F(1, t) = g_0 = det B; at c = 3 (separate) F > 0
//     somewhere in (0, 1) (at u = 1/2, λ = -1, between the two negative
//     roots), at c = 2 (touching) max F = 0 at u = 1/2, at c = 1
//     (overlapping) F < 0 on (0, 1), as the header's statement says;
//   - moving spheres of radii r1, r2 with g from moving_quadric and
//     characteristic_coefficients: F(r1/(r1 + r2), t) has the sign of
//     d(t)² - (r1 + r2)² (derived in the test), and F < 0 on (0, 1) where they
//     overlap, at 41 instants per scene.
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "number/rational_traits.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

using test::q;  // a / b in lowest terms (tests/support/exact_values.hpp)

Rational direct(const std::vector<RP>& g, const Rational& u, const Rational& t) {
  Rational s = 0;
  for (int i = 0; i <= 4; ++i) {
    Rational term = g[i](t);
    for (int k = 0; k < i; ++k) term *= u - 1;
    for (int k = 0; k < 4 - i; ++k) term *= u;
    s += term;
  }
  return s;
}

std::vector<RP> random_g(std::mt19937_64& rng) {
  std::vector<RP> g(5);
  for (int k = 0; k < 5; ++k) {
    if (rng() % 7 == 0) continue;  // the zero polynomial
    std::vector<Rational> c;
    const int deg = int(rng() % 6);
    for (int i = 0; i <= deg; ++i) {
      Rational x(long(rng() % 201) - 100, long(rng() % 9) + 1);
      x.canonicalize();
      c.push_back(x);
    }
    g[k] = RP(c);
  }
  return g;
}
Rational random_unit(std::mt19937_64& rng) {
  Rational x(long(rng() % 1001), 1000);
  x.canonicalize();
  return x;
}

}  // namespace

TEST_CASE("ellipsoid_function is sum_i g_i(t) (u - 1)^i u^(4-i), exactly, in every entry point",
          "[kernel][ellipsoid_function]") {
  std::mt19937_64 rng(4301);
  const Rational one(1);
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<RP> g = random_g(rng);
    const BiBern<Rational> F = ellipsoid_function(g, one);
    int n = 0;
    for (const auto& gi : g) n = std::max(n, gi.degree());
    CHECK(F.degree_u() == 4);
    CHECK(F.degree_t() == n);
    const BiBern<Rational> Fb = ellipsoid_function(to_bernstein_all(g, one), one);
    CHECK(Fb.b == F.b);
    for (int k = 0; k < 5; ++k) {
      const Rational u = random_unit(rng), t = random_unit(rng);
      INFO("trial " << trial << " u = " << u << " t = " << t);
      const Rational want = direct(g, u, t);
      CHECK(F(u, t) == want);
      CHECK(ellipsoid_function_at(F, t)(u) == want);
      CHECK(ellipsoid_function_along(F, u)(t) == want);
      ++checked;
    }
    // The corners: F(0, t) = g_4(t), F(1, t) = g_0(t).
    const Rational t = random_unit(rng);
    CHECK(F(Rational(0), t) == g[4](t));
    CHECK(F(one, t) == g[0](t));
  }
  CHECK(checked == 200);
}

// ellipsoid_function_along evaluates all columns at once (keep_u_right): the values of a column-by-column
// evaluation (bernstein_value) bit for bit in double, and in Bounded<double> the same values and bounds, at the
// midpoint (the running bound of a sum), at points where the a-priori bound applies, and with u0 carrying a
// bound of its own (the running bound).
TEST_CASE("ellipsoid_function_along is the column-by-column evaluation, bit for bit", "[kernel][ellipsoid_function]") {
  std::mt19937_64 rng(4303);
  std::uniform_real_distribution<double> val(-1.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const int n = int(rng() % 40);
    BiBern<double> Fd;
    BiBern<Bounded<double>> Fb;
    for (int i = 0; i <= 4; ++i) {
      std::vector<double> row;
      std::vector<Bounded<double>> brow;
      for (int j = 0; j <= n; ++j) {
        row.push_back(std::ldexp(val(rng), -int(rng() % 30)));
        brow.emplace_back(row.back(), j % 3 ? std::fabs(row.back()) * 0x1p-50 : 0.0);
      }
      Fd.b.push_back(row);
      Fb.b.push_back(brow);
    }
    for (const double u : {0.5, 0.3, 0.0, 1.0, 0.96875}) {
      for (const double ue : {0.0, 0x1p-60}) {
        INFO("trial " << trial << " degree " << n << " u0 = " << u << " with bound " << ue);
        const Bounded<double> ub(u, ue);
        const Bern<Bounded<double>> along = ellipsoid_function_along(Fb, ub);
        const Bern<double> alongd = ellipsoid_function_along(Fd, u);
        REQUIRE(along.b.size() == std::size_t(n + 1));
        for (int j = 0; j <= n; ++j) {
          std::vector<Bounded<double>> col;
          std::vector<double> cold;
          for (int i = 0; i <= 4; ++i) {
            col.push_back(Fb.b[i][j]);
            cold.push_back(Fd.b[i][j]);
          }
          const Bounded<double> want = bernstein_value(std::span<const Bounded<double>>(col), ub);
          CHECK(along.b[j].value() == want.value());  // == on doubles is meant: bit for bit
          CHECK(along.b[j].bound() == want.bound());
          CHECK(alongd.b[j] == bernstein_value(std::span<const double>(cold), u));
          ++compared;
        }
      }
    }
  }
  CHECK(compared > 2000);
}

TEST_CASE("ellipsoid_function in double agrees with the exact F to rounding", "[kernel][ellipsoid_function]") {
  std::mt19937_64 rng(4302);
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<RP> g = random_g(rng);
    std::vector<Poly<double>> gd;
    for (const auto& gi : g) gd.push_back(map_coeffs<double>(gi, [](const Rational& x) { return x.get_d(); }));
    const BiBern<double> F = ellipsoid_function(gd, 1.0);
    for (int k = 0; k < 5; ++k) {
      const Rational u = random_unit(rng), t = random_unit(rng);
      // A scale for the error: the same sum with every term taken in absolute value.
      Rational scale = 0;
      for (int i = 0; i <= 4; ++i) {
        Rational m = 0, tp = 1;
        for (const auto& c : g[i].c) {
          m += abs(c) * tp;
          tp *= t;
        }
        scale += m;
      }
      const double want = direct(g, u, t).get_d();
      INFO("trial " << trial);
      CHECK(std::abs(F(u.get_d(), t.get_d()) - want) <= 1e-12 * scale.get_d());
    }
  }
}

TEST_CASE("ellipsoid_function of two unit spheres is positive somewhere iff they are separate",
          "[kernel][ellipsoid_function]") {
  // f = -(λ - 1)² (λ² - (2 - c²)λ + 1) = -(λ² - 2λ + 1)(λ² - (2 - c²)λ + 1), c = 6t - 3, expanded by hand:
  // g4 = -1, g3 = (2 - c²) + 2, g2 = -(1 + 2(2 - c²) + 1), g1 = (2 - c²) + 2, g0 = -1.
  const RP c({Rational(-3), Rational(6)}), c2 = c * c, k = RP::constant(Rational(2)) - c2;
  const RP two = RP::constant(Rational(2)), m1 = RP::constant(Rational(-1));
  const std::vector<RP> g = {m1, k + two, -(two + two * k), k + two, m1};
  const BiBern<Rational> F = ellipsoid_function(g, Rational(1));
  // The corners: det A = det B = -1 for unit spheres.
  for (int i = 0; i <= 10; ++i) {
    CHECK(F(Rational(0), q(i, 10)) == -1);
    CHECK(F(Rational(1), q(i, 10)) == -1);
  }
  const Rational half(1, 2);
  // t = 1, c = 3: separate; at u = 1/2 (λ = -1) F = u⁴ f(-1) = f(-1) / 16, f(-1) = -(4)(1 + (2 - 9) + 1) = 20.
  CHECK(F(half, Rational(1)) == Rational(5, 4));
  // t = 5/6, c = 2: touching, F(1/2) = 0 and F <= 0 on a grid of (0, 1).
  CHECK(F(half, Rational(5, 6)) == 0);
  // t = 2/3, c = 1: overlapping, F < 0 on the grid.
  for (int i = 1; i < 64; ++i) {
    const Rational u = q(i, 64);
    CHECK(F(u, Rational(5, 6)) <= 0);
    CHECK(F(u, Rational(2, 3)) < 0);
  }
  // The quartic in u at a fixed t and the polynomial in t at a fixed u are the same function.
  const Bern<Rational> at = ellipsoid_function_at(F, Rational(5, 6));
  CHECK(at.degree() == 4);
  CHECK(at(half) == 0);
  const Bern<Rational> along = ellipsoid_function_along(F, half);
  CHECK(along.degree() == 2);  // the g_i depend on t through c² only: n = max deg g_i = 2
  CHECK(along(Rational(5, 6)) == 0);
  CHECK(along(Rational(1, 6)) == 0);  // c = -2: the other touch
}

TEST_CASE("ellipsoid_function of moving spheres from the pipeline's g: its sign at u* is the distance test",
          "[kernel][ellipsoid_function]") {
  // Spheres of radii r1, r2, A centred at c(t) (quadratic translations), B at the origin. With d = |c|, f(λ) =
  // (λ - 1)² q(λ), q(λ) = -r1² λ² + (r1² + r2² - d²) λ - r2² (the block along c); at λ* = -r2/r1 (the geometric
  // mean of q's roots) q(λ*) = (r2/r1)(d² - (r1 + r2)²), so at u* = 1/(1 - λ*) = r1/(r1 + r2) F has the sign of
  // d² - (r1 + r2)²: positive iff separate, zero iff touching. When they overlap F < 0 on all of (0, 1).
  // g comes from the pipeline's own set-up (moving_quadric, characteristic_coefficients) on N = M⁻¹.
  std::mt19937_64 rng(4347);
  int pos = 0, neg = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const long r1 = 1 + long(rng() % 3), r2 = 1 + long(rng() % 3);
    Matrix<Rational, 4> qa{}, qb{};
    for (int i = 0; i < 3; ++i) qa[i][i] = qb[i][i] = 1;
    qa[3][3] = -r1 * r1;
    qb[3][3] = -r2 * r2;
    PolyMatrix<Rational, 4> na = identity_poly_matrix<Rational, 4>(), nb = identity_poly_matrix<Rational, 4>();
    RP c[3];
    for (int i = 0; i < 3; ++i) {
      c[i] = RP({Rational(long(rng() % 13) - 6), Rational(long(rng() % 13) - 6), Rational(long(rng() % 13) - 6)});
      na[i][3] = -c[i];  // the inverse of the translation by c(t)
    }
    const auto g = characteristic_coefficients<Rational, H_3D>(moving_quadric<Rational, 4>(qa, na),
                                                               moving_quadric<Rational, 4>(qb, nb));
    const BiBern<Rational> F = ellipsoid_function(g, Rational(1));
    const Rational ustar = q(r1, r1 + r2);
    for (int k = 0; k <= 40; ++k) {
      const Rational t = q(k, 40);
      Rational d2 = 0;
      for (const auto& ci : c) d2 += ci(t) * ci(t);
      const int want = sgn(d2 - Rational((r1 + r2) * (r1 + r2)));
      INFO("trial " << trial << " t = " << t);
      CHECK(sgn(F(ustar, t)) == want);
      if (want < 0)
        for (int i = 1; i < 32; ++i) CHECK(F(q(i, 32), t) < 0);
      pos += want > 0;
      neg += want < 0;
    }
  }
  CHECK(pos > 20);
  CHECK(neg > 20);
}

}  // namespace ECCD_UNITY_ID
