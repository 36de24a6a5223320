// The floating pipelines' rounded start (floating/rounded_input.hpp).
// tests/floating/test_float_input.cpp checks whole floating answers in this
// input mode; here the stages of round_pair themselves:
//   - each shape matrix is the scene's Q rounded entry by entry and scaled
//     by one power of two so that its largest entry has binary exponent 0
//     (|x| in [1/2, 1)); for MPFR the rounding of 1/3 and 1/10 is within
//     half a unit of the run's precision, after the power-of-two scale;
//   - N(t) of a translation is the adjugate of M(t) up to a power of two, so
//     the characteristic polynomial of the rounded pair of two translating
//     unit discs is a positive multiple of the hand-computed
//     g = (1, c²-3, 3-c², -1), c = 6t - 3 (see
//     tests/exact/test_certificate_algebra.cpp); all numbers here are small
//     integers, exact in double, so this is checked exactly (mpq_class) at
//     rational t;
//   - the pencil balance: B's Q scaled by 2^-k, k the rounded mean of
//     log2|det B(t) / det A(t)| / H over t = 0, 1/2, 1, leaves that mean
//     within 1/2 of 0 (recomputed here exactly from the rounded pair);
//     a power-of-two factor in the scene's Q_B changes nothing;
//   - overflow: an entry beyond double's range is reported in `trouble` with
//     the stage and the object; dimension mismatch and independent scenes
//     are refused;
//   - to_bernstein_pair and characteristic_bernstein_of (both set-ups): the
//     Bernstein forms evaluate to the power forms' values (exactly here);
//     normalise_coefficients scales by one power of two and refuses a
//     non-finite value.
#include "floating/rounded_input.hpp"
#include "io/scene_reader.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "number/mpfr_real.hpp"
#include "number/running_error.hpp"

#include <catch2/catch.hpp>

#include <mpfr.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

Scene translating_discs(const Rational& scale_b) {
  Scene s;
  s.dim = 2;
  s.a.Q = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  s.b.Q = {{scale_b, 0, 0}, {0, scale_b, 0}, {0, 0, -scale_b}};
  s.a.motion = StaticMotion{};
  MatrixMotion m;
  m.m.assign(3, std::vector<RPoly>(3));
  for (int i = 0; i < 3; ++i) m.m[i][i] = RPoly::constant(Rational(1));
  m.m[0][2] = RPoly(std::vector<Rational>{-3, 6});  // x moves by c(t) = 6t - 3
  s.b.motion = m;
  return s;
}

mpq_class ex(double x) { return mpq_class(x); }
mpq_class ex(const Mpfr& x) {
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), x.get());
  return q;
}

mpq_class value(const Poly<double>& p, const mpq_class& t) {
  mpq_class r = 0;
  for (int i = p.degree(); i >= 0; --i) r = r * t + ex(p.c[i]);
  return r;
}

// Is r a power of two (positive)?
bool power_of_two(const mpq_class& r) {
  return r > 0 && mpz_popcount(r.get_num_mpz_t()) == 1 && mpz_popcount(r.get_den_mpz_t()) == 1;
}

template <class T, int H>
void check_top_exponent_zero(const Matrix<T, H>& q) {
  mpq_class top = 0;
  for (const auto& row : q)
    for (const auto& x : row) top = std::max(top, mpq_class(abs(ex(x))));
  CHECK(top >= mpq_class(1, 2));
  CHECK(top < 1);
}

}  // namespace

TEST_CASE("round_pair of translating discs: shapes scaled by powers of two, f a positive multiple of the hand one",
          "[floating][rounded_input]") {
  std::string trouble = "stale";
  const MovingPair<double, 3> m = round_pair<double, 3>(translating_discs(1), 0.0, trouble);
  CHECK(trouble.empty());
  check_top_exponent_zero<double, 3>(m.qa);
  // Q_A = diag(1, 1, -1) scaled by one power of two
  const mpq_class s = ex(m.qa[0][0]);
  CHECK(power_of_two(s));
  CHECK(ex(m.qa[1][1]) == s);
  CHECK(ex(m.qa[2][2]) == -s);
  CHECK(ex(m.qa[0][1]) == 0);
  const std::vector<Poly<double>> g = characteristic_of(m);
  REQUIRE(g.size() == 4);
  for (int k = 0; k <= 24; ++k) {
    mpq_class t(k, 24);
    t.canonicalize();
    const mpq_class c = 6 * t - 3, c2 = c * c;
    const std::vector<mpq_class> h{1, c2 - 3, 3 - c2, -1};
    const mpq_class lambda = value(g[0], t);
    INFO("t = " << t);
    CHECK(lambda > 0);
    for (int i = 0; i < 4; ++i) CHECK(value(g[i], t) == lambda * h[i]);
  }
}

TEST_CASE("round_pair balances the pencil by the determinants' ratio", "[floating][rounded_input]") {
  std::string trouble;
  // B given as 2^20 times the same disc: normalising Q_B removes the factor, the pair is the same
  const MovingPair<double, 3> m1 = round_pair<double, 3>(translating_discs(1), 0.0, trouble);
  const MovingPair<double, 3> m20 = round_pair<double, 3>(translating_discs(Rational(1 << 20)), 0.0, trouble);
  REQUIRE(trouble.empty());
  CHECK(m20.qb == m1.qb);
  // B = 3 A (not a power of two) and B = 1000 A: after the balance the mean over t = 0, 1/2, 1 of
  // log2|det B(t)| - log2|det A(t)|, divided by H, is within 1/2 of 0 (the rule's rounding), plus
  // 1/H for the binary exponents of the rounded determinants against the exact ones used here
  for (const Rational& f : {Rational(3), Rational(1000), Rational(1, 77)}) {
    const MovingPair<double, 3> m = round_pair<double, 3>(translating_discs(f), 0.0, trouble);
    REQUIRE(trouble.empty());
    double sum = 0;
    for (const mpq_class& t : {mpq_class(0), mpq_class(1, 2), mpq_class(1)}) {
      auto det_at = [&](const Matrix<double, 3>& q, const PolyMatrix<double, 3>& n) {
        mpq_class nt[3][3], a[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) nt[i][j] = n[i][j].is_zero() ? mpq_class(0) : value(n[i][j], t);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            a[i][j] = 0;
            for (int k = 0; k < 3; ++k)
              for (int l = 0; l < 3; ++l) a[i][j] += nt[k][i] * ex(q[k][l]) * nt[l][j];
          }
        const mpq_class d = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                            a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                            a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        return std::log2(std::fabs(d.get_d()));
      };
      sum += det_at(m.qb, m.nb) - det_at(m.qa, m.na);
    }
    INFO("B = " << f << " A");
    CHECK(std::fabs(sum / (3 * 3)) <= 0.5 + 1.0 / 3);
  }
}

// The guarded face balances the pencil on the values alone (floating/rounded_input.hpp): its pair must be the
// as-published one bit for bit, Q_B's power of two included (a k computed differently would scale Q_B by
// another power of two), and its bounds finite.
template <int H>
void check_guarded_pair_is_published(const Scene& s) {
  std::string t1, t2;
  const MovingPair<double, H> plain = round_pair<double, H>(s, 0.0, t1);
  const MovingPair<Bounded<double>, H> guarded = round_pair<Bounded<double>, H>(s, Bounded<double>(0.0, 0), t2);
  REQUIRE(t1.empty());
  REQUIRE(t2.empty());
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      INFO("entry " << i << ", " << j);
      CHECK(guarded.qa[i][j].value() == plain.qa[i][j]);  // == on doubles is meant: the same bits
      CHECK(guarded.qb[i][j].value() == plain.qb[i][j]);
      CHECK(std::isfinite(guarded.qb[i][j].bound()));
      for (const auto& [g, p] :
           {std::pair{&guarded.na[i][j], &plain.na[i][j]}, std::pair{&guarded.nb[i][j], &plain.nb[i][j]}}) {
        REQUIRE(g->c.size() == p->c.size());
        for (std::size_t k = 0; k < p->c.size(); ++k) CHECK(g->c[k].value() == p->c[k]);
      }
    }
}

TEST_CASE("round_pair with a running error bound holds the as-published pair bit for bit, its balance included",
          "[floating][rounded_input]") {
  for (const Rational& f : {Rational(1), Rational(3), Rational(1000), Rational(1, 77)}) {
    INFO("B = " << f << " A");
    check_guarded_pair_is_published<3>(translating_discs(f));
  }
  for (const char* file : {"/cases/paper003/example2.json", "/cases/paper002/example.json"}) {
    INFO(file);
    const Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + file);
    if (s.dim == 2)
      check_guarded_pair_is_published<3>(s);
    else
      check_guarded_pair_is_published<4>(s);
  }
}

TEST_CASE("round_pair in MPFR rounds each entry once to the run's precision", "[floating][rounded_input]") {
  Scene s = translating_discs(1);
  s.a.Q = {{Rational(1, 3), 0, 0}, {0, Rational(1, 10), 0}, {0, 0, -1}};
  std::string trouble;
  const Mpfr like(mpq_class(0), 113);
  const MovingPair<Mpfr, 3> m = round_pair<Mpfr, 3>(s, like, trouble);
  REQUIRE(trouble.empty());
  // the largest entry |-1| becomes -1/2: the scale is 2^-1; the others are their roundings to 113 bits, halved
  CHECK(ex(m.qa[2][2]) == mpq_class(-1, 2));
  const mpq_class half_ulp(1, mpz_class(1) << 114);
  CHECK(abs(2 * ex(m.qa[0][0]) - mpq_class(1, 3)) <= half_ulp * mpq_class(1, 3) * 2);
  CHECK(abs(2 * ex(m.qa[1][1]) - mpq_class(1, 10)) <= half_ulp * mpq_class(1, 10) * 2);
  CHECK(2 * ex(m.qa[0][0]) != mpq_class(1, 3));  // rounded, not exact
  CHECK(m.qa[0][0].precision() == 113);
}

TEST_CASE("round_pair reports overflow and refuses what it cannot take", "[floating][rounded_input]") {
  std::string trouble;
  Scene s = translating_discs(1);
  mpz_class huge;
  mpz_ui_pow_ui(huge.get_mpz_t(), 10, 400);
  s.a.Q[0][0] = Rational(huge);
  round_pair<double, 3>(s, 0.0, trouble);
  CHECK(trouble.find("shape matrix of object a") != std::string::npos);

  s = translating_discs(1);
  std::get<MatrixMotion>(s.b.motion).m[0][2] = RPoly(std::vector<Rational>{Rational(huge), 1});
  round_pair<double, 3>(s, 0.0, trouble);
  CHECK(trouble.find("N(t) of object b") != std::string::npos);

  s = translating_discs(1);
  CHECK_THROWS_AS((round_pair<double, 4>(s, 0.0, trouble)), std::invalid_argument);
  s.independent = true;
  CHECK_THROWS_AS((round_pair<double, 3>(s, 0.0, trouble)), IndependentMotionsRefused);
}

TEST_CASE("to_bernstein_pair and characteristic_bernstein_of evaluate like the power forms",
          "[floating][rounded_input]") {
  std::string trouble;
  const MovingPair<double, 3> m = round_pair<double, 3>(translating_discs(1), 0.0, trouble);
  REQUIRE(trouble.empty());
  const MovingPairBern<double, 3> b = to_bernstein_pair<double, 3>(m);
  const std::vector<Poly<double>> gp = characteristic_of(m);
  for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double want = m.nb[i][j].is_zero() ? 0.0 : m.nb[i][j](t);
        CHECK(b.nb[i][j](t) == want);  // degree <= 1 with dyadic values: exact in double
      }
    for (bool power : {false, true}) {
      const std::vector<Bern<double>> gb = characteristic_bernstein_of<double, 3>(m, power);
      REQUIRE(gb.size() == 4);
      for (int k = 0; k < 4; ++k) {
        INFO("t = " << t << ", g_" << k << ", power products " << power);
        CHECK(gb[k](t) == Approx(gp[k].is_zero() ? 0.0 : gp[k](t)).margin(1e-12));
      }
    }
  }
  // normalise_coefficients: one power of two for all, the largest in [1/2, 1)
  std::vector<Bern<double>> g{Bern<double>({3.0, -12.0}), Bern<double>({0.5})};
  REQUIRE(normalise_coefficients(g));
  CHECK(g[0].b == std::vector<double>{3.0 / 16, -12.0 / 16});
  CHECK(g[1].b == std::vector<double>{0.5 / 16});
  std::vector<Poly<double>> gi{Poly<double>(std::vector<double>{1.0, std::numeric_limits<double>::infinity()})};
  CHECK_FALSE(normalise_coefficients(gi));
  CHECK(gi[0].c[0] == 1.0);  // nothing scaled
}

}  // namespace ECCD_UNITY_ID
