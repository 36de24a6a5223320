// kernel/cd_disc.hpp: CD-DISC (003 sections III, IV, VI), run here with the
// exact policy (exact/cd_disc_exact.hpp) so that every decision is the one the
// header's statement prescribes, and checked against independent values:
//   - two unit circles, one passing through the other (x(t) = 6t - 3): by hand,
//     λA - B has f = -(λ - 1)(λ² - (2 - c²)λ + 1) with c = 6t - 3, so
//     g3 = -1, g2 = 3 - c², g1 = c² - 3, g0 = 1, and Δ = c⁶ (c² - 4) (the
//     product of the squared root differences: q(1)² Δ(q) = c⁴ · c²(c² - 4)).
//     Δ's roots in [0, 1] are 1/6 and 5/6 (|c| = 2, external touches at
//     (∓1, 0)) and 1/2 (c = 0, concentric circles, a triple root λ = 1 > 0):
//     003 VI-B's example of a root of Δ that is no contact. Also the variants
//     1-3 of 003 VI-C and a start in overlap;
//   - Δ ≡ 0 (003 Corollary 7): two circles moving together, nested (never a
//     touch) or in external contact (touching on all of [0, 1]);
//   - 003 Example 2 (cases/paper003/example2.json): Δ of degree 96 (Table I,
//     24k with k = 4), the printed λ² coefficient of f up to a constant, the
//     single touch at t = 1/2 at the origin, and the sign of Δ at rational
//     instants against the discriminant of det(λA(t) - B(t)) computed in the
//     test from M(t) (its own 3x3 inverse, determinant and interpolation);
//   - discriminant_of's Hessian form (4DE - P²)/3 against the classical cubic
//     discriminant, over seeded random g (MPFR at 256 bits against mpq);
//   - contact_point at a triple root (D = 0: no point), and collect_reasons;
//   - an oracle: for circles under cubic translations the collision set is
//     where the centre distance is at most r1 + r2, decided exactly at 201
//     instants against the exact answer's intervals and contacts;
//   - with a running error bound (Bounded<double>), every decision on the
//     passing circles is the exact one, and what is undecided has a reason.
#include "exact/cd_disc_exact.hpp"
#include "floating/cd_disc_floating.hpp"
#include "io/scene_reader.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/prepared_scene.hpp"
#include "number/mpfr_real.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

// A 2D scene: shapes as semi-axes, motions as translations x(t), y(t) given
// as JSON polynomial arrays (M = [[1, 0, x], [0, 1, y], [0, 0, 1]]).
std::string translating(const std::string& axes, const std::string& x, const std::string& y) {
  return "{\"shape\": {\"semi_axes\": " + axes + "}, \"motion\": {\"type\": \"matrix\", \"m\": [[\"1\", \"0\", " + x +
         "], [\"0\", \"1\", " + y + "], [\"0\", \"0\", \"1\"]]}}";
}
Scene scene_of(const std::string& a, const std::string& b) {
  return parse_scene(
      "{\"format\": \"ellipse-ccd-scene/1\", \"name\": \"t\", \"dim\": 2, \"a\": " + a + ", \"b\": " + b + "}", "test");
}
MovingPair2<Rational> exact_pair(const Scene& s) {
  return to_arithmetic<Rational, H_2D>(prepare_pair<H_2D>(s), Rational(1));
}
PipelineResult<Rational> run_exact(const Scene& s, Variant v = Variant::answer) {
  ExactPolicy pol;
  return cd_disc(exact_pair(s), pol, v);
}
// The instant contains q: its bracket holds q (and is at most 2^-60 wide).
bool holds(const Instant& i, const Rational& q) {
  return i.certified() && *i.lo <= q && q <= *i.hi && *i.hi - *i.lo <= Rational(1, mpz_class(1) << 60);
}
RP lin(long a, long b) { return RP({Rational(b), Rational(a)}); }  // a t + b

// The two unit circles, A centred at (6t - 3, 0), B at the origin.
Scene passing_circles() {
  return scene_of(translating("[\"1\", \"1\"]", "[\"-3\", \"6\"]", "\"0\""),
                  translating("[\"1\", \"1\"]", "\"0\"", "\"0\""));
}

double num(const std::string& s) { return std::stod(s); }

}  // namespace

TEST_CASE("cd_disc on two unit circles passing through each other: g, Δ, roots, statuses and contacts by hand",
          "[kernel][cd_disc]") {
  const auto res = run_exact(passing_circles());
  const RP c = lin(6, -3), c2 = c * c;
  REQUIRE(res.g.size() == 4);
  // f is fixed up to a positive factor k (the exact preparation scales by positive rationals): g3 = -k.
  REQUIRE(res.g[3].degree() == 0);
  const Rational k = -res.g[3].c[0];
  REQUIRE(k > 0);
  const RP three = RP::constant(Rational(3));
  CHECK(res.g[2] == k * (three - c2));
  CHECK(res.g[1] == k * (c2 - three));
  CHECK(res.g[0] == RP::constant(k));

  ExactPolicy pol;
  const RP delta = discriminant_of(res.g, pol);
  const RP want = (k * k * k * k) * (c2 * c2 * c2 * (c2 - RP::constant(Rational(4))));
  CHECK(delta == want);
  CHECK(res.projection_degree == 8);
  CHECK_FALSE(res.projection_identically_zero);
  CHECK(res.status_at_0 == Status::separate);

  // The roots of Δ: 1/6 (touch), 1/2 (sixfold, concentric: overlap, not a contact), 5/6 (touch).
  REQUIRE(res.critical.size() == 3);
  CHECK(holds(res.critical[0].t, Rational(1, 6)));
  CHECK(res.critical[0].status == Status::touching);
  CHECK(res.critical[0].multiplicity == 1);
  CHECK(holds(res.critical[1].t, Rational(1, 2)));
  CHECK(res.critical[1].status == Status::overlapping);
  CHECK(res.critical[1].multiplicity == 6);
  CHECK(holds(res.critical[2].t, Rational(5, 6)));
  CHECK(res.critical[2].status == Status::touching);
  // One cell between consecutive roots, decided at a sample: separate, overlap, overlap, separate.
  REQUIRE(res.cells.size() == 4);
  const Status cells[4] = {Status::separate, Status::overlapping, Status::overlapping, Status::separate};
  for (int i = 0; i < 4; ++i) CHECK(res.cells[i].status == cells[i]);

  const Answer& a = res.answer;
  CHECK(a.collides);
  REQUIRE(a.intervals.size() == 1);
  CHECK(holds(a.intervals[0].first, Rational(1, 6)));
  CHECK(holds(a.intervals[0].second, Rational(5, 6)));
  REQUIRE(a.first_contact);
  CHECK(holds(*a.first_contact, Rational(1, 6)));
  REQUIRE(a.contacts.size() == 2);
  CHECK(holds(a.contacts[0], Rational(1, 6)));
  CHECK(holds(a.contacts[1], Rational(5, 6)));
  CHECK(a.undecided.empty());
  CHECK(res.undecided_reasons.empty());
  // Lemma 5: at t = 1/6 A is centred at (-2, 0) and touches B at (-1, 0), A's outward normal there (1, 0);
  // at t = 5/6 at (1, 0), normal (-1, 0). The points are taken at the bracket's mid-point (within 2^-64).
  REQUIRE(a.contact_points.size() == 2);
  const double px[2] = {-1, 1};
  for (int i = 0; i < 2; ++i) {
    REQUIRE(a.contact_points[i].x.size() == 2);
    CHECK(num(a.contact_points[i].x[0]) == Approx(px[i]).margin(1e-12));
    CHECK(num(a.contact_points[i].x[1]) == Approx(0).margin(1e-12));
    REQUIRE(a.contact_points[i].normal.size() == 2);
    CHECK(num(a.contact_points[i].normal[0]) == Approx(-px[i]).margin(1e-12));
    CHECK(num(a.contact_points[i].normal[1]) == Approx(0).margin(1e-12));
  }
}

TEST_CASE("cd_disc variants 1-3 of 003 VI-C on the passing circles", "[kernel][cd_disc]") {
  const Scene s = passing_circles();
  for (Variant v : {Variant::collides, Variant::first_contact}) {
    // Separate at t = 0: the first root of Δ is the first contact; every root found is listed as critical.
    const auto res = run_exact(s, v);
    CHECK(res.variant == v);
    CHECK(res.answer.collides);
    REQUIRE(res.answer.first_contact);
    CHECK(holds(*res.answer.first_contact, Rational(1, 6)));
    REQUIRE_FALSE(res.critical.empty());
    CHECK(holds(res.critical.front().t, Rational(1, 6)));
    CHECK(res.critical.front().status == Status::touching);
  }
  const auto all = run_exact(s, Variant::all_contacts);
  CHECK(all.answer.intervals.empty());  // variant 3: the contacts and their points, no intervals
  REQUIRE(all.answer.contacts.size() == 2);
  CHECK(holds(all.answer.contacts[1], Rational(5, 6)));
  CHECK(all.answer.contact_points.size() == 2);
}

TEST_CASE("cd_disc when the circles start in overlap: the concentric root at t = 0 is no touch", "[kernel][cd_disc]") {
  // A centred at (3t, 0): concentric at t = 0 (Δ's root there, a triple root λ = 1: D = 0, overlap), an
  // external touch at |c| = 2, t = 2/3, separate after.
  const Scene s = scene_of(translating("[\"1\", \"1\"]", "[\"0\", \"3\"]", "\"0\""),
                           translating("[\"1\", \"1\"]", "\"0\"", "\"0\""));
  const auto res = run_exact(s);
  CHECK(res.status_at_0 == Status::overlapping);
  const Answer& a = res.answer;
  CHECK(a.collides);
  REQUIRE(a.intervals.size() == 1);
  CHECK(a.intervals[0].first.certified());
  CHECK(*a.intervals[0].first.lo == 0);
  CHECK(*a.intervals[0].first.hi == 0);
  CHECK(holds(a.intervals[0].second, Rational(2, 3)));
  REQUIRE(a.contacts.size() == 1);
  CHECK(holds(a.contacts[0], Rational(2, 3)));
  REQUIRE(a.first_contact);
  CHECK(*a.first_contact->hi == 0);

  // Variants 1 and 2: overlapping at t = 0, so the first contact is t = 0 and no root is sought.
  const auto first = run_exact(s, Variant::first_contact);
  CHECK(first.answer.collides);
  REQUIRE(first.answer.first_contact);
  CHECK(*first.answer.first_contact->lo == 0);
  CHECK(first.critical.empty());
}

TEST_CASE("cd_disc with Δ identically zero: nested circles never touch, circles in contact touch throughout",
          "[kernel][cd_disc]") {
  // Both move by the same translation, so f(λ; t) does not depend on t and has a multiple root for every t.
  const std::string x = "[\"-1\", \"2\", \"5\"]", y = "[\"0\", \"1\"]";
  {
    // A unit circle inside a circle of radius 2, both centred on the same moving point:
    // λA - B = diag(λ - 1, λ - 1, 4 - λ), a double root λ = 1 > 0: overlapping, never touching.
    const auto res = run_exact(scene_of(translating("[\"1\", \"1\"]", x, y), translating("[\"2\", \"2\"]", x, y)));
    CHECK(res.projection_identically_zero);
    const Answer& a = res.answer;
    CHECK(a.collides);
    REQUIRE(a.intervals.size() == 1);
    CHECK(*a.intervals[0].first.hi == 0);
    CHECK(*a.intervals[0].second.lo == 1);
    CHECK(a.contact_intervals.empty());
    REQUIRE(a.first_contact);
    CHECK(*a.first_contact->hi == 0);
    // variants 1 and 2: colliding from t = 0, first contact 0
    const auto first = run_exact(scene_of(translating("[\"1\", \"1\"]", x, y), translating("[\"2\", \"2\"]", x, y)),
                                 Variant::first_contact);
    CHECK(first.answer.collides);
    REQUIRE(first.answer.first_contact);
    CHECK(*first.answer.first_contact->hi == 0);
  }
  {
    // Two unit circles at distance 2 moving together: f = -(λ - 1)(λ + 1)², a negative double root at every t.
    const std::string x2 = "[\"1\", \"2\", \"5\"]";
    const auto res = run_exact(scene_of(translating("[\"1\", \"1\"]", x, y), translating("[\"1\", \"1\"]", x2, y)));
    CHECK(res.projection_identically_zero);
    const Answer& a = res.answer;
    CHECK(a.collides);
    REQUIRE(a.intervals.size() == 1);
    REQUIRE(a.contact_intervals.size() == 1);
    CHECK(*a.contact_intervals[0].first.hi == 0);
    CHECK(*a.contact_intervals[0].second.lo == 1);
    CHECK(a.contacts.empty());  // continuous touching is not a list of isolated contacts
    REQUIRE_FALSE(res.cells.empty());
    for (const auto& cell : res.cells) CHECK(cell.status == Status::touching);
  }
}

namespace {

// 003 Example 2 rebuilt as in cases/paper003/make_example2.py, here from the printed polynomials.
const std::vector<long> kA = {4, -16, 0, 32, -16}, kB = {0, 16, -48, 32}, kX = {-40, 160, -240, 160},
                        kYA = {80, -400, 880, -960, 480}, kW = {4, -16, 32, -32, 16};
Rational eval(const std::vector<long>& p, const Rational& t, long s = 1) {
  Rational r = 0;
  for (int i = int(p.size()) - 1; i >= 0; --i) r = r * t + Rational(s * p[i]);
  return r;
}
using M3 = std::array<std::array<Rational, 3>, 3>;
Rational det3(const M3& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
M3 inverse3(const M3& m) {
  M3 r;
  const Rational d = det3(m);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {  // cofactor of (j, i)
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      r[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / d;
    }
  return r;
}
// X^T Q X <= 0 moved by M: M^-T Q M^-1.
M3 moved(const M3& q, const M3& m) {
  const M3 n = inverse3(m);
  M3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Rational s = 0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) s += n[k][i] * q[k][l] * n[l][j];
      r[i][j] = s;
    }
  return r;
}
// The discriminant of det(λA - B) as a cubic in λ: its values at λ = 0..3 interpolated (Newton's forward
// differences), then b²c² - 4ac³ - 4b³d - 27a²d² + 18abcd.
Rational pencil_discriminant(const M3& a, const M3& b) {
  Rational v[4];
  for (int l = 0; l < 4; ++l) {
    M3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = Rational(l) * a[i][j] - b[i][j];
    v[l] = det3(m);
  }
  const Rational d1 = v[1] - v[0], d2 = v[2] - 2 * v[1] + v[0], d3 = v[3] - 3 * v[2] + 3 * v[1] - v[0];
  // v0 + d1 λ + d2 λ(λ-1)/2 + d3 λ(λ-1)(λ-2)/6
  const Rational A = d3 / 6, B = d2 / 2 - d3 / 2, C = d1 - d2 / 2 + d3 / 3, D = v[0];
  return B * B * C * C - 4 * A * C * C * C - 4 * B * B * B * D - 27 * A * A * D * D + 18 * A * B * C * D;
}
M3 example2_motion(const Rational& t, bool is_a) {
  const Rational a = eval(kA, t), b = eval(kB, t), x = eval(kX, t), w = eval(kW, t);
  const Rational y = eval(kYA, t, is_a ? 1 : -1);
  if (is_a) return M3{{{a, -b, x}, {b, a, y}, {0, 0, w}}};
  return M3{{{a, b, x}, {-b, a, y}, {0, 0, w}}};
}

}  // namespace

TEST_CASE("cd_disc on 003 Example 2: degree 96, the printed g2, one touch at 1/2, Δ's sign at rational instants",
          "[kernel][cd_disc]") {
  const Scene s = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2.json");
  const auto pair = exact_pair(s);
  ExactPolicy pol;
  const auto res = cd_disc(pair, pol);
  // 003 Table I: the coefficients of f have degree 6k and Δ degree 24k for motions of degree k = 4.
  CHECK(res.g[2].degree() == 24);
  CHECK(res.projection_degree == 96);
  // 003 VI-C prints g2 = -135168 t^24 + 1622016 t^23 - 11304960 t^22 ... - 13: the same up to a constant.
  const RP& g2 = res.g[2];
  const Rational lead = g2.c[24];
  CHECK(g2.c[23] / lead == Rational(1622016) / Rational(-135168));
  CHECK(g2.c[22] / lead == Rational(-11304960) / Rational(-135168));
  CHECK(g2.c[0] / lead == Rational(-13) / Rational(-135168));
  // The disks touch externally at t = 1/2 at the origin and are separate at every other instant.
  const Answer& a = res.answer;
  CHECK(a.collides);
  REQUIRE(a.intervals.size() == 1);
  CHECK(holds(a.intervals[0].first, Rational(1, 2)));
  CHECK(holds(a.intervals[0].second, Rational(1, 2)));
  REQUIRE(a.contacts.size() == 1);
  CHECK(holds(a.contacts[0], Rational(1, 2)));
  REQUIRE(a.contact_points.size() == 1);
  CHECK(num(a.contact_points[0].x[0]) == Approx(0).margin(1e-9));
  CHECK(num(a.contact_points[0].x[1]) == Approx(0).margin(1e-9));
  CHECK(res.status_at_0 == Status::separate);

  // Δ(t) against the discriminant of det(λA(t) - B(t)) built here from M(t) (the shapes x²/25 + y²/100 <= 1):
  // the preparation multiplies A and B by positive functions, which keeps Δ's sign and its zeros.
  const RP delta = discriminant_of(res.g, pol);
  const M3 q{{{Rational(4), 0, 0}, {0, Rational(1), 0}, {0, 0, Rational(-100)}}};
  int checked = 0;
  for (int i = 0; i <= 24; ++i) {
    Rational t(i, 24);
    t.canonicalize();
    const Rational want = pencil_discriminant(moved(q, example2_motion(t, true)), moved(q, example2_motion(t, false)));
    INFO("t = " << t);
    CHECK(sgn(delta(t)) == sgn(want));
    if (i == 12) CHECK(want == 0);
    ++checked;
  }
  CHECK(checked == 25);
}

TEST_CASE("cd_disc's discriminant_of: the Hessian form (4DE - P^2)/3 is the classical cubic discriminant",
          "[kernel][cd_disc]") {
  // FloatingPolicy asks for the Hessian form; the classical one is built in mpq from the same g.
  static_assert(delta_from_hessian<FloatingPolicy<Mpfr>>());
  static_assert(!delta_from_hessian<ExactPolicy>());
  const Mpfr like(mpq_class(1), 256);
  FloatingPolicy<Mpfr> pol(Basis::bernstein, 256, like);
  std::mt19937_64 rng(43);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<RP> gq(4);
    std::vector<Poly<Mpfr>> gm(4);
    for (int k = 0; k < 4; ++k) {
      std::vector<Rational> c;
      const int deg = int(rng() % 4);
      for (int i = 0; i <= deg; ++i) c.push_back(Rational(long(rng() % 41) - 20));
      gq[k] = RP(c);
      gm[k] = map_coeffs<Mpfr>(gq[k], [&](const Rational& x) { return Mpfr(x, 256); });
    }
    const RP exact = cubic_discriminant(gq[3], gq[2], gq[1], gq[0]);
    const auto got = discriminant_of(gm, pol);
    const int n = int(got.b.size()) - 1;
    const Bern<Rational> want = to_bernstein(exact, std::max(n, std::max(exact.degree(), 0)));
    REQUIRE(int(want.b.size()) == n + 1);
    Rational scale = 1;
    for (const auto& x : want.b) scale = std::max(scale, Rational(abs(x)));
    for (int i = 0; i <= n; ++i) {
      mpq_class gotq;
      mpfr_get_q(gotq.get_mpq_t(), got.b[i].get());
      INFO("trial " << trial << " coefficient " << i);
      // 256-bit rounding of a few dozen operations on integers below 2^30: far below 2^-200 of the largest.
      CHECK(abs(gotq - want.b[i]) <= scale / Rational(mpz_class(1) << 200));
    }
  }
}

TEST_CASE("cd_disc's contact_point gives no point at a triple root, and collect_reasons names the cause",
          "[kernel][cd_disc]") {
  const auto pair = exact_pair(passing_circles());
  const PolyMatrix<Rational, 3> A = moving_quadric<Rational, H_2D>(pair.qa, pair.na);
  const PolyMatrix<Rational, 3> B = moving_quadric<Rational, H_2D>(pair.qb, pair.nb);
  const auto g = characteristic_coefficients<Rational, H_2D>(A, B);
  // t = 1/2: concentric, f = -(λ - 1)³, D = g2² - 3 g3 g1 = 0: Lemma 5 has no double root to use.
  const ContactPoint none = contact_point(A, B, g, Rational(1, 2));
  CHECK(none.x.empty());
  CHECK(none.normal.empty());
  // t = 1/6 exactly: the touch point (-1, 0) and the normal (1, 0), printed exactly.
  const ContactPoint at = contact_point(A, B, g, Rational(1, 6));
  REQUIRE(at.x.size() == 2);
  CHECK(num(at.x[0]) == -1);
  CHECK(num(at.x[1]) == 0);
  REQUIRE(at.normal.size() == 2);
  CHECK(num(at.normal[0]) == 1);
  CHECK(num(at.normal[1]) == 0);

  // PlainUndecided is a set of reasons.
  const PlainUndecided both = PlainUndecided::own_sign | PlainUndecided::isolated;
  CHECK(has(both, PlainUndecided::own_sign));
  CHECK(has(both, PlainUndecided::isolated));
  CHECK_FALSE(has(PlainUndecided::own_sign, PlainUndecided::isolated));
  CHECK_FALSE(has(PlainUndecided::none, PlainUndecided::own_sign));
  static_assert(plain_rounded<double>() && plain_rounded<Mpfr>());
  static_assert(!plain_rounded<Rational>() && !plain_rounded<Bounded<double>>());

  FloatingPolicy<double> dpol(Basis::bernstein, 53, 1.0);
  {
    PipelineResult<double> r;  // nothing undecided: no reason
    collect_reasons(r, dpol, PlainUndecided::isolated);
    CHECK(r.undecided_reasons.empty());
  }
  {
    PipelineResult<double> r;
    r.answer.undecided.push_back(Instant{});
    collect_reasons(r, dpol, both);
    REQUIRE(r.undecided_reasons.size() == 2);
    CHECK(r.undecided_reasons[0].find("a root of Δ") != std::string::npos);
    CHECK(r.undecided_reasons[1].find("f's coefficients") != std::string::npos);
  }
  {
    PipelineResult<double> r;
    r.answer.undecided.push_back(Instant{});
    dpol.notes = {"work bound", "work bound"};  // a policy's own notes win, each once
    collect_reasons(r, dpol, both);
    REQUIRE(r.undecided_reasons.size() == 1);
    CHECK(r.undecided_reasons[0] == "work bound");
  }
  {
    FloatingPolicy<Bounded<double>> bpol(Basis::bernstein, 53, Bounded<double>(1.0, 0));
    PipelineResult<Bounded<double>> r;
    r.answer.undecided.push_back(Instant{});
    collect_reasons(r, bpol);
    REQUIRE(r.undecided_reasons.size() == 1);
    CHECK(r.undecided_reasons[0].find("too close to zero") != std::string::npos);
  }
}

TEST_CASE("cd_disc's collision set for moving circles is where the centre distance is at most r1 + r2",
          "[kernel][cd_disc]") {
  // Two circles, A of radius r1 centred at (x(t), y(t)) (cubic polynomials), B of radius r2 at the origin:
  // the disks meet iff x² + y² <= (r1 + r2)², decided exactly in mpq at the instants k/200. Every instant
  // certainly inside an interval of the exact answer must satisfy it, every instant certainly outside all
  // must not; each contact is a root of x² + y² - (r1 + r2)² (an external touch, not an internal tangency).
  std::mt19937_64 rng(4345);
  int inside = 0, outside = 0, contacts = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const long r1 = 1 + long(rng() % 3), r2 = 1 + long(rng() % 4);
    std::vector<long> cx(4), cy(4);
    for (auto& c : cx) c = long(rng() % 13) - 6;
    for (auto& c : cy) c = long(rng() % 9) - 4;
    auto arr = [](const std::vector<long>& c) {
      std::string s = "[";
      for (std::size_t i = 0; i < c.size(); ++i) s += (i ? ", \"" : "\"") + std::to_string(c[i]) + "\"";
      return s + "]";
    };
    auto axes = [](long r) { return "[\"" + std::to_string(r) + "\", \"" + std::to_string(r) + "\"]"; };
    const Scene s = scene_of(translating(axes(r1), arr(cx), arr(cy)), translating(axes(r2), "\"0\"", "\"0\""));
    const auto res = run_exact(s);
    const Answer& a = res.answer;
    auto gap = [&](const Rational& t) {  // x² + y² - (r1 + r2)²
      Rational x = 0, y = 0;
      for (int i = 3; i >= 0; --i) {
        x = x * t + cx[i];
        y = y * t + cy[i];
      }
      return Rational(x * x + y * y - Rational((r1 + r2) * (r1 + r2)));
    };
    INFO("trial " << trial);
    CHECK(a.undecided.empty());
    for (int k = 0; k <= 200; ++k) {
      Rational t(k, 200);
      t.canonicalize();
      bool in = false, out = true;
      for (const auto& [lo, hi] : a.intervals) {
        if (*lo.hi <= t && t <= *hi.lo) in = true;
        if (!(t < *lo.lo || t > *hi.hi)) out = false;
      }
      if (in) {
        CHECK(gap(t) <= 0);
        ++inside;
      } else if (out) {
        CHECK(gap(t) > 0);
        ++outside;
      }
    }
    for (const auto& c : a.contacts) {
      CHECK(sgn(gap(*c.lo)) * sgn(gap(*c.hi)) <= 0);  // the bracket holds a root of the gap
      ++contacts;
    }
    CHECK(collides_claim(a) == std::optional<bool>(!a.intervals.empty()));
  }
  CHECK(inside > 100);
  CHECK(outside > 100);
  CHECK(contacts > 5);
}

TEST_CASE("cd_disc with a running error bound claims only what the exact run says", "[kernel][cd_disc]") {
  // The passing circles in Bounded<double> (the guard): Δ has a sixfold root at 1/2 that no bound resolves;
  // whatever the run decides must be the exact answer (1/6 and 5/6 touches, overlap between), and what it
  // leaves undecided carries a reason.
  const auto pair =
      to_arithmetic<Bounded<double>, H_2D>(prepare_pair<H_2D>(passing_circles()), Bounded<double>(1.0, 0));
  FloatingPolicy<Bounded<double>> pol(Basis::bernstein, 53, Bounded<double>(1.0, 0));
  const auto res = cd_disc(pair, pol);
  const Answer& a = res.answer;
  if (!a.undecided.empty()) CHECK_FALSE(res.undecided_reasons.empty());
  CHECK(collides_claim(a) != std::optional<bool>(false));
  for (const auto& c : a.contacts) {
    const bool known = std::abs(c.value - 1.0 / 6) < 1e-6 || std::abs(c.value - 5.0 / 6) < 1e-6;
    CHECK(known);
  }
  for (const auto& cell : res.cells) {
    if (cell.status == Status::uncertain) continue;
    const double t = cell.sample.value;  // separate outside [1/6, 5/6], overlapping inside
    CHECK(cell.status == ((t < 1.0 / 6 || t > 5.0 / 6) ? Status::separate : Status::overlapping));
  }
  CHECK(res.status_at_0 == Status::separate);
}

}  // namespace ECCD_UNITY_ID
