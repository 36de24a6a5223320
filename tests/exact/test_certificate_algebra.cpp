// The polynomials a certificate speaks about (exact/certificate_algebra.hpp),
// on scenes whose characteristic polynomial is computed by hand, and the
// decimal approximations a certificate writes.
//
// The scenes: A the unit disc (ball) at the origin, B the unit disc (ball)
// translated to (c(t), 0), c = 6t - 3. Hand computation (2D):
//   det(λA - B) = det [[λ-1, 0, c], [0, λ-1, 0], [c, 0, 1-c²-λ]]
//               = -(λ-1)((λ-1)² + c²λ) = -λ³ + (3-c²)λ² + (c²-3)λ + 1,
// so g = (1, c²-3, 3-c², -1) up to a positive factor (the prepared scene's
// primitive integer form). The discs touch at |c| = 2 (t = 1/6, 5/6) and are
// concentric at t = 1/2. In 3D the extra factor (λ - 1) makes λ = 1 a double
// root for every t: the discriminant vanishes identically (002 section III)
// and the first non-vanishing psc_k must be used; it is zero where the
// quadratic factor has a double root, i.e. at the touching instants.
// Checked: g proportional to the hand computation at random t with a
// positive factor; projection the cubic discriminant (formula written out
// here) up to a positive factor and zero exactly at 1/6 and 5/6; the
// evidence P = 9 g3 g0 - g2 g1 and D = g2² - 3 g3 g1; unknown evidence names
// refused; status_at separate / touching / overlapping; in 3D the vanishing
// list and a psc projection that vanishes at the touching instants.
// The decimals: approx_in_bracket lies in its bracket with the fewest places
// (one place fewer leaves it), read_approx reads back its exact value and the
// unit of its last digit; decimal_with_places and decimal_value agree and round
// half up; coefficient_bits, integer_coefficient_bits, integer_coefficients.
#include "exact/certificate_algebra.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

Scene translating_discs(int dim) {
  Scene s;
  s.dim = dim;
  const int D = dim + 1;
  std::vector<std::vector<Rational>> Q(D, std::vector<Rational>(D, Rational(0)));
  for (int i = 0; i < dim; ++i) Q[i][i] = 1;
  Q[dim][dim] = -1;
  s.a.Q = s.b.Q = Q;
  s.a.motion = StaticMotion{};
  MatrixMotion m;
  m.m.assign(D, std::vector<RPoly>(D));
  for (int i = 0; i < D; ++i) m.m[i][i] = RPoly::constant(Rational(1));
  m.m[0][dim] = RPoly(std::vector<Rational>{-3, 6});  // x moves by c(t) = 6t - 3
  s.b.motion = m;
  return s;
}

std::vector<Rational> hand_g(const Rational& t) {
  const Rational c = 6 * t - 3, c2 = c * c;
  return {1, c2 - 3, 3 - c2, -1};
}

Rational disc3(const Rational& a, const Rational& b, const Rational& c, const Rational& d) {
  // the discriminant of a x³ + b x² + c x + d
  return 18 * a * b * c * d - 4 * b * b * b * d + b * b * c * c - 4 * a * c * c * c - 27 * a * a * d * d;
}

}  // namespace

TEST_CASE("certificate_algebra of two translating discs matches the hand computation", "[exact][certificate_algebra]") {
  const CertificateAlgebra a = certificate_algebra(translating_discs(2));
  REQUIRE(a.dim == 2);
  REQUIRE(a.g.size() == 4);
  CHECK(a.projection_name == "discriminant");
  CHECK(a.vanishing.empty());
  SeededRng rng{31};
  for (int k = 0; k < 12; ++k) {
    const Rational t = rng.frac(0, 60, 60);
    const std::vector<Rational> h = hand_g(t);
    const Rational lambda = a.g[3](t) / h[3];  // the positive factor at t
    INFO("t = " << t);
    CHECK(lambda > 0);
    for (int i = 0; i < 4; ++i) CHECK(a.g[i](t) == lambda * h[i]);
    // Δ scales by lambda^4; P and D by lambda^2
    CHECK(a.projection(t) == lambda * lambda * lambda * lambda * disc3(h[3], h[2], h[1], h[0]));
    CHECK(a.evidence("P")(t) == lambda * lambda * (9 * h[3] * h[0] - h[2] * h[1]));
    CHECK(a.evidence("D")(t) == lambda * lambda * (h[2] * h[2] - 3 * h[3] * h[1]));
  }
  // the touching instants are roots of the projection; the discs are separate at the ends
  CHECK(sgn(a.projection(Rational(1, 6))) == 0);
  CHECK(sgn(a.projection(Rational(5, 6))) == 0);
  CHECK(sgn(a.projection(Rational(0))) != 0);
  CHECK(a.status_at(Rational(0)) == Status::separate);
  CHECK(a.status_at(Rational(1)) == Status::separate);
  CHECK(a.status_at(Rational(1, 6)) == Status::touching);
  CHECK(a.status_at(Rational(5, 6)) == Status::touching);
  CHECK(a.status_at(Rational(1, 2)) == Status::overlapping);
  CHECK(a.status_at(Rational(1, 7)) == Status::separate);           // |c| = 15/7 > 2
  CHECK(a.status_at(Rational(1, 5)) == Status::overlapping);        // |c| = 9/5 < 2
  CHECK_THROWS_AS(a.evidence("disc(S_2)"), std::invalid_argument);  // a 3D name
  CHECK_THROWS_AS(a.evidence("Q"), std::invalid_argument);
}

TEST_CASE("certificate_algebra of two translating balls falls back to a psc", "[exact][certificate_algebra]") {
  const CertificateAlgebra a = certificate_algebra(translating_discs(3));
  REQUIRE(a.dim == 3);
  REQUIRE(a.g.size() == 5);
  // λ = 1 is a double root of the quartic for every t: the discriminant vanishes identically
  REQUIRE_FALSE(a.vanishing.empty());
  CHECK(a.vanishing.front() == "discriminant");
  CHECK(a.projection_index >= 1);
  CHECK(a.projection_name == "psc_" + std::to_string(a.projection_index));
  CHECK_FALSE(a.projection.is_zero());
  // g(1) = 0 at every t (λ = 1 is a root)
  for (const Rational& t : {Rational(0), Rational(1, 3), Rational(7, 9)}) {
    Rational f1 = 0;
    for (const auto& gk : a.g) f1 += gk(t);
    CHECK(f1 == 0);
  }
  // the touching instants: the quadratic factor (λ-1)² + c²λ has a double root, the gcd grows
  CHECK(sgn(a.projection(Rational(1, 6))) == 0);
  CHECK(sgn(a.projection(Rational(5, 6))) == 0);
  CHECK(sgn(a.projection(Rational(0))) != 0);
  CHECK(a.status_at(Rational(0)) == Status::separate);
  CHECK(a.status_at(Rational(1, 6)) == Status::touching);
  CHECK(a.status_at(Rational(1, 2)) == Status::overlapping);
  CHECK_NOTHROW(a.evidence("disc(S_2)"));
  CHECK_NOTHROW(a.evidence("s(2,1)"));
  CHECK_THROWS_AS(a.evidence("s(1,2)"), std::invalid_argument);  // i > j
  CHECK_THROWS_AS(a.evidence("s(4,1)"), std::invalid_argument);  // j > 3
  CHECK_THROWS_AS(a.evidence("s(2,1"), std::invalid_argument);
  CHECK_THROWS_AS(a.evidence("P"), std::invalid_argument);  // a 2D name
}

TEST_CASE("certificate_algebra decimals: fewest places inside the bracket, read back exactly",
          "[exact][certificate_algebra]") {
  SeededRng rng{32};
  for (int k = 0; k < 300; ++k) {
    const Rational lo = rng.frac(-100000, 100000, rng.uniform(1, 100000));
    const Rational hi = lo + (k % 10 == 0 ? Rational(0) : rng.frac(1, 1000, rng.uniform(1, 10000000)));
    const std::string s = approx_in_bracket(lo, hi);
    const auto v = read_approx(s, 200);
    INFO("[" << lo << ", " << hi << "] -> " << s);
    REQUIRE(v);
    if (lo == hi) {
      // a point: exact when it has at most 40 places, else rounded to 40 places
      const std::size_t dot = s.find('.');
      const std::size_t places = dot == std::string::npos ? 0 : s.size() - dot - 1;
      if (places < 40) CHECK(v->value == lo);
      if (places == 40) CHECK(abs(v->value - lo) <= v->unit / 2);
      continue;
    }
    CHECK(lo <= v->value);
    CHECK(v->value <= hi);
    // one place fewer: the mid-point rounded there leaves the bracket (or there is no place to drop)
    const std::size_t dot = s.find('.');
    if (dot != std::string::npos) {
      const int places = int(s.size() - dot - 1);
      const Rational fewer = decimal_value((lo + hi) / 2, places - 1);
      CHECK((fewer < lo || fewer > hi));
      mpz_class p10;
      mpz_ui_pow_ui(p10.get_mpz_t(), 10, unsigned(places));
      CHECK(v->unit == Rational(1, p10));  // the unit of the last written digit
    }
  }
  // half up, also for negative numbers
  CHECK(decimal_with_places(Rational(5, 2), 0) == "3");
  CHECK(decimal_with_places(Rational(-5, 2), 0) == "-2");
  CHECK(decimal_with_places(Rational(-1, 2), 0) == "0");
  CHECK(decimal_with_places(Rational(1, 8), 2) == "0.13");
  CHECK(decimal_with_places(Rational(-1, 8), 2) == "-0.12");
  CHECK(decimal_with_places(Rational(7, 1000), 2) == "0.01");
  CHECK(decimal_with_places(Rational(1234), 1) == "1234.0");
  for (int k = 0; k < 50; ++k) {
    const Rational x = rng.frac(-99999, 99999, rng.uniform(1, 9999));
    const int places = int(rng.uniform(0, 8));
    const auto r = read_approx(decimal_with_places(x, places), 100);
    REQUIRE(r);
    CHECK(r->value == decimal_value(x, places));
    CHECK(abs(r->value - x) <= Rational(1, 2) * r->unit);
  }
  CHECK(read_approx("-3e2", 10)->value == -300);
  CHECK(read_approx("-3e2", 10)->unit == 100);
  CHECK(read_approx("+.5", 10)->value == Rational(1, 2));
  for (const char* bad : {"", "-", ".", "1.2.3", "1e", "1e+", "e5", "1x", "0x10", "1e100001", " 1", "1 "})
    CHECK_FALSE(read_approx(bad, 100));
  CHECK_FALSE(read_approx("12345", 4));  // too long
}

TEST_CASE("certificate_algebra coefficient sizes and written coefficients", "[exact][certificate_algebra]") {
  // 3/4 - (5/6) x + 2 x²: l = 12, integers 9, -10, 24 (gcd 1)
  const Poly<Rational> p(std::vector<Rational>{Rational(3, 4), Rational(-5, 6), 2});
  CHECK(integer_coefficients(p) == std::vector<std::string>{"9", "-10", "24"});
  CHECK(integer_coefficient_bits(p) == 5);  // 24 < 32
  CHECK(coefficient_bits(p) == 3);          // 5 and 6: 3 bits; 4: 3 bits
  const Poly<Rational> q(std::vector<Rational>{Rational(1, 1024), Rational(-300)});
  CHECK(coefficient_bits(q) == 11);  // 1024 = 2^10
  CHECK(integer_coefficients(q) == std::vector<std::string>{"1", "-307200"});
  CHECK(integer_coefficients(Poly<Rational>()).empty());
}

}  // namespace ECCD_UNITY_ID
