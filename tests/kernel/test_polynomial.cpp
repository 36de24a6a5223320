// kernel/polynomial.hpp: Poly<T> in the power basis. Checked against
// independent computations in the test: the naive double loop for products
// (the library takes Kronecker substitution or common-denominator paths for
// mpq, by length), the naive Horner loop and a sum of powers for values (the
// library's mpq Horner is integer, rational_poly_eval), the term-by-term
// derivative, and the division identity a = b q + r with deg r < deg b; gcd
// is monic, divides both and is a multiple of every common factor built in.
// Over seeded random rationals (canonical and of mixed sizes), and in double,
// Mpfr and Bounded<double> (the bound of a product and of Horner encloses
// the exact value). Edge cases: trim of exact zeros, the zero polynomial's
// degree -1 and value 0, coeff out of range, division by zero (domain_error).
#include "kernel/polynomial.hpp"
#include "number/mpfr_real.hpp"
#include "number/rational_traits.hpp"
#include "number/running_error.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

RP random_poly(std::mt19937_64& rng, int max_deg, int bits) {
  std::vector<Rational> c;
  for (int i = 0, n = int(rng() % (max_deg + 1)); i <= n; ++i)
    c.push_back(rng() % 4 == 0 ? Rational(0) : test::random_rational(rng, bits));
  return RP(c);
}
std::vector<Rational> naive_product(const RP& a, const RP& b) {
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<Rational> r(a.c.size() + b.c.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.c.size(); ++i)
    for (std::size_t j = 0; j < b.c.size(); ++j) r[i + j] += a.c[i] * b.c[j];
  while (!r.empty() && r.back() == 0) r.pop_back();
  return r;
}
Rational naive_value(const RP& p, const Rational& t) {
  Rational s = 0, tp = 1;
  for (const auto& c : p.c) {
    s += c * tp;
    tp *= t;
  }
  return s;
}

}  // namespace

TEST_CASE("Poly<Rational>: products, values, sums and derivatives against naive loops", "[kernel][polynomial]") {
  std::mt19937_64 rng(4320);
  for (int trial = 0; trial < 300; ++trial) {
    const int bits = trial % 3 == 0 ? 90 : 20;  // long coefficients too (the Kronecker path packs them)
    const RP a = random_poly(rng, 1 + trial % 12, bits), b = random_poly(rng, 1 + trial % 7, bits);
    INFO("trial " << trial);
    const RP p = a * b;
    CHECK(p.c == naive_product(a, b));
    for (const auto& x : p.c) CHECK(x.get_den() > 0);
    const Rational t = test::random_rational(rng, 12);
    CHECK(a(t) == naive_value(a, t));
    CHECK(p(t) == a(t) * b(t));
    CHECK((a + b)(t) == a(t) + b(t));
    CHECK((a - b)(t) == a(t) - b(t));
    CHECK((-a)(t) == -a(t));
    CHECK((Rational(3, 7) * a)(t) == Rational(3, 7) * a(t));
    CHECK((2 * a)(t) == 2 * a(t));
    const RP d = derivative(a);
    for (int i = 1; i <= a.degree(); ++i) CHECK(d.coeff(i - 1) == i * a.c[i]);
    CHECK(d.degree() == (a.degree() <= 0 ? -1 : a.degree() - 1));
    // the result is trimmed: no exact zero at the top
    for (const RP* r : {&p, &d}) CHECK((r->is_zero() || r->lead() != 0));
  }
}

TEST_CASE("Poly<Rational>: a = b q + r with deg r < deg b, and the monic gcd", "[kernel][polynomial]") {
  std::mt19937_64 rng(4321);
  for (int trial = 0; trial < 100; ++trial) {
    const RP a = random_poly(rng, 9, 16), b = random_poly(rng, 5, 16);
    if (b.is_zero()) {
      RP q, r;
      CHECK_THROWS_AS(divide(a, b, q, r), std::domain_error);
      continue;
    }
    RP q, r;
    divide(a, b, q, r);
    INFO("trial " << trial);
    CHECK(b * q + r == a);
    CHECK(r.degree() < b.degree());
    // gcd of h f and h g with a built-in common factor h: a multiple of h, monic, dividing both
    const RP h = RP({test::random_rational(rng, 8), Rational(1)}) * RP({Rational(2), Rational(0), Rational(1)});
    const RP f = h * random_poly(rng, 4, 8), g = h * random_poly(rng, 4, 8);
    if (f.is_zero() || g.is_zero()) continue;
    const RP c = gcd(f, g);
    CHECK(c.lead() == 1);
    RP qq, rr;
    divide(f, c, qq, rr);
    CHECK(rr.is_zero());
    divide(g, c, qq, rr);
    CHECK(rr.is_zero());
    divide(c, h, qq, rr);
    CHECK(rr.is_zero());
  }
}

TEST_CASE("Poly: trim, the zero polynomial, coeff and map_coeffs", "[kernel][polynomial]") {
  const RP z({Rational(0), Rational(0)});
  CHECK(z.is_zero());
  CHECK(z.degree() == -1);
  CHECK(z(Rational(5)) == 0);
  CHECK(RP::constant(Rational(0)).is_zero());
  const RP p({Rational(1), Rational(0), Rational(-2), Rational(0)});  // 1 - 2t², the top zero trimmed
  CHECK(p.degree() == 2);
  CHECK(p.coeff(1) == 0);
  CHECK(p.coeff(7) == 0);
  CHECK(p.coeff(-1) == 0);
  CHECK(p - p == z);
  CHECK((p * z).is_zero());
  const Poly<double> pd = map_coeffs<double>(p, [](const Rational& x) { return x.get_d(); });
  CHECK(pd.c == std::vector<double>{1.0, 0.0, -2.0});
  CHECK(pd(0.5) == 0.5);
  CHECK(derivative(RP::constant(Rational(4))).is_zero());
}

TEST_CASE("Poly in rounded arithmetics: double and MPFR near the exact value, Bounded<double> encloses it",
          "[kernel][polynomial]") {
  std::mt19937_64 rng(4322);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<double> ca, cb;
    for (int i = 0, n = 1 + int(rng() % 10); i <= n; ++i) ca.push_back(u(rng));
    for (int i = 0, n = 1 + int(rng() % 10); i <= n; ++i) cb.push_back(u(rng));
    const Poly<double> a(ca), b(cb);
    const RP ea = map_coeffs<Rational>(a, [](double x) { return Rational(x); });
    const RP eb = map_coeffs<Rational>(b, [](double x) { return Rational(x); });
    const double t = u(rng);
    const Rational et(t);
    const Rational want = (ea * eb)(et);
    // double: |error| of Horner on the product's coefficients, each a sum of <= 11 products: well under
    // 64 ulps of the sum of absolute terms (at most 11 * 11 here since |coefficients|, |t| <= 1).
    CHECK(std::abs((a * b)(t)-want.get_d()) <= 64 * 0x1p-53 * 121);
    // MPFR at 200 bits: the same to 2^-190.
    const Poly<Mpfr> am = map_coeffs<Mpfr>(ea, [](const Rational& x) { return Mpfr(x, 200); });
    const Poly<Mpfr> bm = map_coeffs<Mpfr>(eb, [](const Rational& x) { return Mpfr(x, 200); });
    const Rational vm = test::exact_of((am * bm)(Mpfr(et, 200)));
    CHECK(abs(vm - want) <= Rational(121) / Rational(mpz_class(1) << 190));
    // Bounded<double>: the running bound encloses the exact value of the product at t.
    const Poly<Bounded<double>> ab = map_coeffs<Bounded<double>>(a, [](double x) { return Bounded<double>(x, 0); });
    const Poly<Bounded<double>> bb = map_coeffs<Bounded<double>>(b, [](double x) { return Bounded<double>(x, 0); });
    const Bounded<double> v = (ab * bb)(Bounded<double>(t, 0));
    INFO("trial " << trial);
    CHECK(abs(Rational(v.value()) - want) <= test::exact_of(static_cast<long double>(v.bound())));
  }
}

}  // namespace ECCD_UNITY_ID
