// The enclosures behind cycloidal certificates
// (certificate/write/cycloidal_enclosures.hpp), on scenes whose Δ is known
// exactly although the motion is cycloidal: A the unit disc at the origin,
// B the unit disc translated by (6t - 3, 0) and turned by π θ1 t about its
// centre. A disc is invariant under turns about its centre, so for every θ1
// f(λ; t) = -(λ-1)(λ² + (c²-2)λ + 1), c = 6t - 3, up to a non-zero factor
// (tests/exact/test_certificate_algebra.cpp), and the sign of Δ(t) is that of
// the discriminant of g = (1, c²-3, 3-c², -1) (Δ is homogeneous of degree 4 in
// g: any common factor of g keeps its sign). Δ vanishes at t = 1/6 and 5/6
// (|c| = 2, simple roots: external touches) and at t = 1/2 (c = 0, a double
// root of Δ in c: concentric discs). θ1 = 0 (a pure translation) and
// θ1 = 5/3 (the enclosures go through sin and cos) are both checked:
//   - delta_sign_at and delta_sign_over claim only the exact sign (never a
//     sign at a root); root_free (and root_free_by's name) only on brackets
//     free of 1/6, 1/2, 5/6; simple_root only on a bracket holding exactly
//     one of 1/6 and 5/6 (never around the double root 1/2); and they do
//     prove these on brackets clear of the roots (not vacuous);
//   - status_at agrees with the centre distance (separate beyond 2,
//     overlapping within) or says uncertain; status_at_root at 1/6 is
//     touching; magnitude_upper is a non-negative bound that shrinks with
//     the bracket around a root.
#include "certificate/write/cycloidal_enclosures.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

Scene discs(const Rational& theta1) {
  Scene s;
  s.dim = 2;
  s.a.Q = s.b.Q = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
  s.a.motion = StaticMotion{};
  CycloidalMotion m;
  m.theta0 = 0;
  m.theta1 = theta1;
  m.x = {-3, 6};
  m.y = {0, 0};
  s.b.motion = m;
  return s;
}

int exact_delta_sign(const mpq_class& t) {
  const mpq_class c = 6 * t - 3, c2 = c * c;
  const mpq_class a = -1, b = 3 - c2, cc = c2 - 3, d = 1;  // g3, g2, g1, g0
  const mpq_class disc =
      18 * a * b * cc * d - 4 * b * b * b * d + b * b * cc * cc - 4 * a * cc * cc * cc - 27 * a * a * d * d;
  return sgn(disc);
}

int as_int(Sign s) { return s == Sign::positive ? 1 : s == Sign::negative ? -1 : s == Sign::zero ? 0 : 2; }

int roots_in(const mpq_class& a, const mpq_class& b, bool open) {  // of 1/6, 1/2, 5/6
  int n = 0;
  for (const mpq_class& r : {mpq_class(1, 6), mpq_class(1, 2), mpq_class(5, 6)})
    n += open ? (a < r && r < b) : (a <= r && r <= b);
  return n;
}

}  // namespace

TEST_CASE("CycloidalEnclosures prove only the exact signs and roots of Δ", "[certificate][cycloidal_enclosures]") {
  for (const Rational& theta1 : {Rational(0), Rational(5, 3)}) {
    const CycloidalEnclosures E(discs(theta1), 128);
    SeededRng rng{707};
    long proved_at = 0, proved_free = 0, proved_simple = 0;
    for (int k = 0; k < 120; ++k) {
      const mpq_class t = rng.frac(0, 600, 600);
      const int s = as_int(E.delta_sign_at(t));
      INFO("θ1 = " << theta1 << ", t = " << t);
      if (s != 2) {
        CHECK(s == exact_delta_sign(t));
        proved_at += s != 0;
      }
      const mpq_class a = rng.frac(0, 580, 600), b = a + rng.frac(1, 20, 600);
      const bool free = E.root_free(a, b);
      CHECK((E.root_free_by(a, b) != nullptr) == free);
      if (free) {
        ++proved_free;
        CHECK(roots_in(a, b, false) == 0);
        const int so = as_int(E.delta_sign_over(a, b));
        if (so != 2 && so != 0) CHECK(so == exact_delta_sign((a + b) / 2));
      }
      if (E.simple_root(a, b)) {
        ++proved_simple;
        CHECK(roots_in(a, b, true) == 1);
        CHECK_FALSE((a < mpq_class(1, 2) && mpq_class(1, 2) < b));
      }
    }
    // the exact roots: no sign claimed there; brackets around them
    for (const mpq_class& r : {mpq_class(1, 6), mpq_class(1, 2), mpq_class(5, 6)}) {
      const int s = as_int(E.delta_sign_at(r));
      CHECK((s == 0 || s == 2));
      CHECK_FALSE(E.root_free(r - mpq_class(1, 1000), r + mpq_class(1, 1000)));
    }
    const mpq_class eps(1, 1000);
    CHECK(E.simple_root(mpq_class(1, 6) - eps, mpq_class(1, 6) + eps));
    CHECK(E.simple_root(mpq_class(5, 6) - eps, mpq_class(5, 6) + eps));
    CHECK_FALSE(E.simple_root(mpq_class(1, 2) - eps, mpq_class(1, 2) + eps));  // a double root of Δ
    CHECK(proved_at >= 100);
    CHECK(proved_free >= 10);  // wide brackets often fail (the natural enclosure overestimates): not vacuous
    // narrow brackets clear of the roots are proved root-free
    for (const mpq_class& a : {mpq_class(1, 20), mpq_class(3, 10), mpq_class(7, 10), mpq_class(19, 20)})
      CHECK(E.root_free(a, a + mpq_class(1, 1000)));
    // status: the centre distance |6t - 3| against 2
    for (int k = 0; k <= 24; ++k) {
      mpq_class t(k, 24);
      t.canonicalize();
      const Status st = E.status_at(t);
      const mpq_class dist = abs(6 * t - 3);
      if (st == Status::uncertain) continue;
      if (dist > 2) CHECK(st == Status::separate);
      if (dist < 2) CHECK(st == Status::overlapping);
      if (dist == 2) CHECK(st == Status::touching);
    }
    CHECK(E.status_at(mpq_class(0)) == Status::separate);
    CHECK(E.status_at(mpq_class(1, 3)) == Status::overlapping);
    CHECK(E.status_at_root(mpq_class(1, 6) - eps, mpq_class(1, 6) + eps) == Status::touching);
    // magnitude: a bound, smaller on a narrower bracket around the root
    const mpq_class wide = E.magnitude_upper(mpq_class(1, 6) - eps, mpq_class(1, 6) + eps);
    const mpq_class narrow = E.magnitude_upper(mpq_class(1, 6) - eps / 100, mpq_class(1, 6) + eps / 100);
    CHECK(narrow >= 0);
    CHECK(narrow < wide);
  }
}

}  // namespace ECCD_UNITY_ID
