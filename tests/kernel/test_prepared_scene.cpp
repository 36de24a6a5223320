// kernel/prepared_scene.hpp: the exact preparation of a scene (Q and N(t) as
// primitive integer matrices, the polynomial content of N divided out, the
// pencil balanced by a power of two) and its rounding to an arithmetic.
// Checked against the header's statement:
//   - make_primitive: one positive factor turns a list of rationals into
//     coprime integers (checked in mpq over seeded random lists);
//   - remove_polynomial_content: N = h(t) P(t) with a known common factor h
//     becomes a positive multiple of P;
//   - prepare_pair on 003 Example 2 (cases/paper003/example2.json): M(t) N(t)
//     is a non-zero multiple of I at rational t (M(t) built in the test from
//     the printed polynomials), N's entries have degree 4 = k after the
//     content is divided out (the 003 Table I degrees), integer and primitive;
//   - balance_pencil: a unit circle against a circle of radius 2^10 scales
//     B's shape by 2^-7 (k = round(20 / 3), log2 |det B / det A| = 20), and
//     changes no answer of the exact pipeline (same roots, statuses, answer);
//   - refusals: a 2D scene for the 3D pipeline, a cycloidal motion
//     (NotRationalMotion), independent motions (IndependentMotionsRefused);
//     parse_input_mode;
//   - to_arithmetic (double: the nearest double of each rational) and
//     to_arithmetic_bernstein (each entry's exact Bernstein form, rounded);
//   - no status changes: on random kinematic scenes the static status from
//     the prepared pencil equals the one from A = M⁻ᵀ Q M⁻¹ formed in mpq
//     from the motion matrices, at rational instants.
#include "exact/cd_disc_exact.hpp"
#include "io/scene_reader.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/prepared_scene.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

using test::q;  // a / b in lowest terms (tests/support/exact_values.hpp)
bool is_integer(const Rational& x) { return x.get_den() == 1; }

Scene scene_text(const std::string& a, const std::string& b, const std::string& extra = "", int dim = 2) {
  return parse_scene("{\"format\": \"ellipse-ccd-scene/1\", \"name\": \"t\", \"dim\": " + std::to_string(dim) +
                         ", \"a\": " + a + ", \"b\": " + b + extra + "}",
                     "test");
}
std::string circle(const std::string& r, const std::string& motion) {
  return "{\"shape\": {\"semi_axes\": [\"" + r + "\", \"" + r + "\"]}, \"motion\": " + motion + "}";
}
std::string shift(const std::string& x) {
  return "{\"type\": \"matrix\", \"m\": [[\"1\", \"0\", " + x + "], [\"0\", \"1\", \"0\"], [\"0\", \"0\", \"1\"]]}";
}
const std::string kStatic = "{\"type\": \"static\"}";

}  // namespace

TEST_CASE("make_primitive scales rationals by one positive factor to coprime integers", "[kernel][prepared_scene]") {
  std::mt19937_64 rng(4303);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + int(rng() % 8);
    std::vector<Rational> x(n), orig(n);
    for (int i = 0; i < n; ++i) {
      x[i] = q(long(rng() % 2001) - 1000, long(rng() % 97) + 1);
      if (rng() % 5 == 0) x[i] = 0;
      orig[i] = x[i];
    }
    std::vector<Rational*> ptrs;
    for (auto& v : x) ptrs.push_back(&v);
    make_primitive(ptrs);
    mpz_class g = 0;
    std::optional<Rational> factor;
    for (int i = 0; i < n; ++i) {
      INFO("trial " << trial << " entry " << i);
      REQUIRE(is_integer(x[i]));
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x[i].get_num_mpz_t());
      CHECK((x[i] == 0) == (orig[i] == 0));
      if (orig[i] != 0) {
        const Rational f = x[i] / orig[i];
        CHECK(f > 0);
        if (factor) CHECK(f == *factor);
        factor = f;
      }
    }
    if (factor)
      CHECK(g == 1);
    else
      CHECK(g == 0);  // all zero: nothing to scale, left as it was
  }
}

TEST_CASE("remove_polynomial_content divides the common polynomial factor of N out", "[kernel][prepared_scene]") {
  // N = h P with h = (t + 2)(t - 3) (negative on [0, 1]: only |N| matters, A = Nᵀ Q N) and P's entries coprime.
  const RP h = RP({Rational(2), Rational(1)}) * RP({Rational(-3), Rational(1)});
  PolyMatrix<Rational, 3> p{}, n{};
  std::mt19937_64 rng(4304);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      std::vector<Rational> c;
      for (int k = 0; k < 3; ++k) c.push_back(q(long(rng() % 21) - 10, long(rng() % 4) + 1));
      p[i][j] = RP(c);
    }
  p[2][0] = RP();                       // a zero entry
  p[2][2] = RP::constant(Rational(1));  // a constant entry: the gcd of P's entries is 1
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) n[i][j] = q(3, 7) * (h * p[i][j]);
  remove_polynomial_content<3>(n);
  // Now N is a positive multiple of P: compare through the constant entry.
  REQUIRE(n[2][2].degree() == 0);
  const Rational f = n[2][2].c[0];
  CHECK(f > 0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      INFO(i << "," << j);
      CHECK(n[i][j] == f * p[i][j]);
      for (const auto& c : n[i][j].c) CHECK(is_integer(c));
    }
}

TEST_CASE("prepare_pair on 003 Example 2: M N is a multiple of I, N of degree k = 4, primitive integers",
          "[kernel][prepared_scene]") {
  const Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2.json");
  const PreparedPair2 p = prepare_pair<H_2D>(s);
  // M(t) of A and B from the polynomials printed in 003 VI-C (cases/paper003/make_example2.py).
  const std::vector<long> a = {4, -16, 0, 32, -16}, b = {0, 16, -48, 32}, x = {-40, 160, -240, 160},
                          y = {80, -400, 880, -960, 480}, w = {4, -16, 32, -32, 16};
  auto ev = [](const std::vector<long>& c, const Rational& t, long sgn) {
    Rational r = 0;
    for (int i = int(c.size()) - 1; i >= 0; --i) r = r * t + Rational(sgn * c[i]);
    return r;
  };
  for (int which = 0; which < 2; ++which) {
    const PolyMatrix<Rational, 3>& n = which == 0 ? p.na : p.nb;
    const long sb = which == 0 ? -1 : 1;  // M_A has -b above b, M_B the transpose
    int maxdeg = 0;
    std::vector<Rational*> all;
    PolyMatrix<Rational, 3> copy = n;
    for (auto& row : copy)
      for (auto& e : row) {
        maxdeg = std::max(maxdeg, e.degree());
        for (auto& c : e.c) {
          CHECK(is_integer(c));
          all.push_back(&c);
        }
      }
    CHECK(maxdeg == 4);
    make_primitive(all);  // already primitive: unchanged
    CHECK(copy == n);
    for (int i = 0; i <= 8; ++i) {
      const Rational t = q(i, 8);
      const Rational m[3][3] = {{ev(a, t, 1), ev(b, t, sb), ev(x, t, 1)},
                                {ev(b, t, -sb), ev(a, t, 1), ev(y, t, which == 0 ? 1 : -1)},
                                {0, 0, ev(w, t, 1)}};
      Rational mn[3][3];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          mn[r][c] = 0;
          for (int k = 0; k < 3; ++k) mn[r][c] += m[r][k] * n[k][c](t);
        }
      INFO("object " << which << " t = " << t);
      CHECK(mn[0][0] != 0);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) CHECK(mn[r][c] == (r == c ? mn[0][0] : Rational(0)));
    }
  }
  // The shapes x²/25 + y²/100 <= 1 as primitive integers: diag(4, 1, -100) (before balancing B: both have det -400).
  CHECK(p.qa[0][0] == 4);
  CHECK(p.qa[1][1] == 1);
  CHECK(p.qa[2][2] == -100);
  CHECK(p.qa[0][1] == 0);
}

TEST_CASE("balance_pencil scales B by a power of two and changes no answer", "[kernel][prepared_scene]") {
  // A: unit circle centred at (5t - 2, 0); B: a static circle of radius 1024, shape diag(1, 1, -2^20).
  // log2 |det B / det A| = 20 at every t, so k = round(20 / 3) = 7 and B's shape is divided by 128.
  const Scene s = scene_text(circle("1", shift("[\"1021\", \"5\"]")), circle("1024", kStatic));
  PreparedPair2 raw;
  raw.qa = shape_matrix<H_2D>(s.a);
  raw.qb = shape_matrix<H_2D>(s.b);
  raw.na = motion_inverse<Rational, H_2D>(s.a.motion, [](const Rational& r) { return r; });
  raw.nb = motion_inverse<Rational, H_2D>(s.b.motion, [](const Rational& r) { return r; });
  remove_polynomial_content<H_2D>(raw.na);
  remove_polynomial_content<H_2D>(raw.nb);
  CHECK(raw.qb[2][2] == -(Rational(1) << 20));
  const PreparedPair2 p = prepare_pair<H_2D>(s);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      CHECK(p.qb[i][j] == raw.qb[i][j] / 128);
      CHECK(p.qa[i][j] == raw.qa[i][j]);
    }
  // The same exact answer with and without the balancing (a positive factor on B scales every root λ).
  ExactPolicy pol;
  const auto balanced = cd_disc(to_arithmetic<Rational, H_2D>(p, Rational(1)), pol);
  const auto plain = cd_disc(to_arithmetic<Rational, H_2D>(raw, Rational(1)), pol);
  REQUIRE(balanced.timeline.size() == plain.timeline.size());
  for (std::size_t k = 0; k < plain.timeline.size(); ++k) {
    CHECK(balanced.timeline[k].status == plain.timeline[k].status);
    CHECK(balanced.timeline[k].t.lo == plain.timeline[k].t.lo);
    CHECK(balanced.timeline[k].t.hi == plain.timeline[k].t.hi);
  }
  CHECK(balanced.answer.collides == plain.answer.collides);
  REQUIRE(balanced.answer.intervals.size() == 1);
  // By hand: the centre distance is 1021 + 5t; the unit circle lies inside B while 1021 + 5t <= 1023
  // (t <= 2/5, an internal touch there: a root of Δ, no contact), crosses B's rim until 1021 + 5t = 1025
  // (t = 4/5, the one external touch) and is separate after: the collision set is [0, 4/5].
  CHECK(*balanced.answer.intervals[0].first.hi == 0);
  const auto& end = balanced.answer.intervals[0].second;
  CHECK(*end.lo <= q(4, 5));
  CHECK(q(4, 5) <= *end.hi);
  REQUIRE(balanced.answer.contacts.size() == 1);
}

TEST_CASE("prepare_pair refuses what it cannot represent, with a message that says why", "[kernel][prepared_scene]") {
  const Scene s2 = scene_text(circle("1", kStatic), circle("2", shift("[\"3\", \"1\"]")));
  CHECK_NOTHROW(prepare_pair<H_2D>(s2));
  CHECK_THROWS_AS(prepare_pair<H_3D>(s2), std::invalid_argument);
  const Scene cyc = scene_text(circle("1",
                                      "{\"type\": \"cycloidal\", \"angle_over_pi\": [\"0\", \"1\"], "
                                      "\"translation\": [[\"0\", \"1\"], [\"0\", \"0\"]]}"),
                               circle("2", kStatic));
  try {
    prepare_pair<H_2D>(cyc);
    FAIL("a cycloidal motion was prepared");
  } catch (const NotRationalMotion& e) {
    CHECK(std::string(e.what()).find("object a has a cycloidal motion") != std::string::npos);
  }
  const Scene ind =
      scene_text(circle("1", kStatic), circle("2", shift("[\"3\", \"1\"]")), ", \"parameters\": \"independent\"");
  REQUIRE(ind.independent);
  CHECK_THROWS_AS(prepare_pair<H_2D>(ind), IndependentMotionsRefused);
  try {
    refuse_independent(ind, "the test pipeline");
    FAIL("independent motions were accepted");
  } catch (const IndependentMotionsRefused& e) {
    CHECK(std::string(e.what()).find("the test pipeline treats one shared t") != std::string::npos);
  }
  CHECK_NOTHROW(refuse_independent(s2));

  CHECK(parse_input_mode("rounded") == InputMode::rounded);
  CHECK(parse_input_mode("prepared") == InputMode::prepared);
  CHECK(std::string(to_string(InputMode::rounded)) == "rounded");
  CHECK(std::string(to_string(InputMode::prepared)) == "prepared");
  try {
    parse_input_mode("Rounded");
    FAIL("a wrong mode was accepted");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) == "Rounded: expected rounded or prepared");
  }
}

TEST_CASE("to_arithmetic and to_arithmetic_bernstein round the prepared rationals one by one",
          "[kernel][prepared_scene]") {
  const Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2.json");
  const PreparedPair2 p = prepare_pair<H_2D>(s);
  const MovingPair2<double> d = to_arithmetic<double, H_2D>(p, 1.0);
  const MovingPairBern2<Rational> be = to_arithmetic_bernstein<Rational, H_2D>(p, Rational(1));
  const MovingPairBern2<double> bd = to_arithmetic_bernstein<double, H_2D>(p, 1.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      CHECK(d.qa[i][j] == p.qa[i][j].get_d());  // small integers: exact in double
      CHECK(d.qb[i][j] == p.qb[i][j].get_d());
      const RP& e = p.na[i][j];
      REQUIRE(d.na[i][j].c.size() == e.c.size());
      for (std::size_t k = 0; k < e.c.size(); ++k)
        CHECK(d.na[i][j].c[k] == scalar_traits<double>::from_rational(e.c[k]));
      // The Bernstein form on [0, 1]: the same polynomial (values at rational t), the zero entry as [0].
      const Bern<Rational>& bb = be.na[i][j];
      if (e.is_zero()) {
        CHECK(bb.b.size() == 1);
        CHECK(bb.b[0] == 0);
        continue;
      }
      CHECK(bb.degree() == e.degree());
      for (int k = 0; k <= 4; ++k) CHECK(bb(q(k, 4)) == e(q(k, 4)));
      REQUIRE(bd.na[i][j].b.size() == bb.b.size());
      for (std::size_t k = 0; k < bb.b.size(); ++k)
        CHECK(bd.na[i][j].b[k] == scalar_traits<double>::from_rational(bb.b[k]));
    }
}

TEST_CASE("prepare_pair changes no status: the prepared pencil and M^-T Q M^-1 agree at rational instants",
          "[kernel][prepared_scene]") {
  // Random 2D kinematic motions (turning and translating, degree 2 and 4 matrices) with rational semi-axes:
  // at each t = k/16 the static status from the prepared pair's f equals the one from A = M⁻ᵀ Q M⁻¹ formed
  // here in mpq from motion_matrix (the scaling, the content division and the balancing multiply A and B by
  // positive functions and constants only).
  std::mt19937_64 rng(4346);
  auto poly = [&](int deg) {
    std::string s = "[";
    for (int i = 0; i <= deg; ++i) s += (i ? ", \"" : "\"") + std::to_string(long(rng() % 9) - 4) + "\"";
    return s + "]";
  };
  int compared = 0, separate = 0, overlapping = 0;
  for (int trial = 0; trial < 16; ++trial) {
    auto obj = [&](int deg) {
      const std::string ax = "[\"" + std::to_string(1 + rng() % 4) + "/2\", \"" + std::to_string(1 + rng() % 3) + "\"]";
      // d2 and d3 never both zero: d2 = 2 + t² > 0
      return "{\"shape\": {\"semi_axes\": " + ax + "}, \"motion\": {\"type\": \"kinematic\", \"d\": [" + poly(deg) +
             ", " + poly(deg) + ", [\"2\", \"0\", \"1\"], " + poly(1) + "]}}";
    };
    const Scene s = scene_text(obj(1 + trial % 2), obj(1));
    const PreparedPair2 p = prepare_pair<H_2D>(s);
    const auto A = moving_quadric<Rational, H_2D>(p.qa, p.na), B = moving_quadric<Rational, H_2D>(p.qb, p.nb);
    const auto g = characteristic_coefficients<Rational, H_2D>(A, B);
    auto raw = [&](const SceneObject& o, const Rational& t) {
      const auto m = motion_matrix<Rational, H_2D>(o.motion, [](const Rational& x) { return x; });
      Matrix<Rational, 3> mt{};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) mt[i][j] = m[i][j](t);
      // M⁻¹ by cofactors over the determinant
      const Rational det = mt[0][0] * (mt[1][1] * mt[2][2] - mt[1][2] * mt[2][1]) -
                           mt[0][1] * (mt[1][0] * mt[2][2] - mt[1][2] * mt[2][0]) +
                           mt[0][2] * (mt[1][0] * mt[2][1] - mt[1][1] * mt[2][0]);
      Matrix<Rational, 3> inv{};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
          inv[i][j] = (mt[r0][c0] * mt[r1][c1] - mt[r0][c1] * mt[r1][c0]) / det;
        }
      Matrix<Rational, 3> a{};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l) a[i][j] += inv[k][i] * o.Q[k][l] * inv[l][j];
      return a;
    };
    for (int k = 0; k <= 16; ++k) {
      const Rational t = q(k, 16);
      const Matrix<Rational, 3> a = raw(s.a, t), b = raw(s.b, t);
      // f(λ) = det(λa - b) from its values at λ = 0..3
      Rational v[4];
      for (int l = 0; l < 4; ++l) {
        Matrix<Rational, 3> m;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) m[i][j] = l * a[i][j] - b[i][j];
        v[l] = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      }
      const Rational d1 = v[1] - v[0], d2 = v[2] - 2 * v[1] + v[0], d3 = v[3] - 3 * v[2] + 3 * v[1] - v[0];
      const Status want =
          cubic_contact_status(Rational(d3 / 6), Rational(d2 / 2 - d3 / 2), Rational(d1 - d2 / 2 + d3 / 3), v[0]);
      const Status got = cubic_contact_status(g[3](t), g[2](t), g[1](t), g[0](t));
      INFO("trial " << trial << " t = " << t);
      CHECK(got == want);
      separate += want == Status::separate;
      overlapping += want == Status::overlapping;
      ++compared;
    }
  }
  CHECK(compared == 16 * 17);
  CHECK(separate > 10);
  CHECK(overlapping > 10);
}

}  // namespace ECCD_UNITY_ID
