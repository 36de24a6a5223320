// The static test of two elliptic disks from the root pattern of
// f(λ) = g3 λ³ + g2 λ² + g1 λ + g0 (kernel/contact_status.hpp; 003 section II,
// Theorem 6: separate iff f has two distinct negative roots, touching
// externally iff a negative double root, otherwise overlapping; Lemma 1: f
// always has a positive root). f is built from its roots, so the expected
// status is read off the roots: every pattern of three roots in
// {-3, -2, -1, 1, 2, 3} (and a complex pair) with a positive root, at both
// signs of the leading coefficient, in exact rationals and in double (the
// inputs are small integers, so double computes the same signs). Three
// distinct real roots that Lemma 1 forbids (one negative, or three) read as 1
// or 3 sign changes: `uncertain`, never a status.
#include "kernel/contact_status.hpp"
#include "kernel/discriminant.hpp"
#include "number/double_traits.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <optional>
#include <set>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// The coefficients g3, g2, g1, g0 of c (λ - r1)(λ - r2)(λ - r3).
std::array<Rational, 4> from_roots(const Rational& c, const Rational& r1, const Rational& r2, const Rational& r3) {
  const Rational s1 = r1 + r2 + r3, s2 = r1 * r2 + r1 * r3 + r2 * r3, s3 = r1 * r2 * r3;
  return {c, Rational(-c * s1), Rational(c * s2), Rational(-c * s3)};
}

// Theorem 6, read off the roots (sorted, with a positive root); for three
// distinct roots that Lemma 1 forbids (one negative and two positive),
// `uncertain`; nothing for a forbidden pattern with a repeated root.
std::optional<Status> expected(const std::array<int, 3>& r) {
  if (r[0] < 0 && r[1] > 0) {
    if (r[0] != r[1] && r[1] != r[2]) return Status::uncertain;
    return std::nullopt;
  }
  std::multiset<int> neg;
  for (int x : r)
    if (x < 0) neg.insert(x);
  if (neg.size() == 2 && *neg.begin() != *neg.rbegin()) return Status::separate;
  if (neg.size() == 2) return Status::touching;
  return Status::overlapping;
}

template <class T>
Status status_of(const std::array<Rational, 4>& g) {
  auto in = [](const Rational& q) { return scalar_traits<T>::from_rational(q, T(1)); };
  return cubic_contact_status(in(g[0]), in(g[1]), in(g[2]), in(g[3]));
}

}  // namespace

TEST_CASE("the static test gives Theorem 6's status for every root pattern with a positive root",
          "[kernel][contact_status]") {
  const int values[] = {-3, -2, -1, 1, 2, 3};
  int checked = 0;
  for (int a : values)
    for (int b : values)
      for (int c : values) {
        if (a > b || b > c || c < 0) continue;  // sorted, with a positive root (Lemma 1)
        const std::array<int, 3> r{a, b, c};
        const std::optional<Status> want = expected(r);
        if (!want) continue;
        for (long lead : {1L, -3L}) {
          const auto g = from_roots(Rational(lead), Rational(a), Rational(b), Rational(c));
          INFO("roots " << a << ", " << b << ", " << c << ", leading coefficient " << lead);
          CHECK(status_of<Rational>(g) == *want);
          CHECK(status_of<double>(g) == *want);
          ++checked;
        }
      }
  CHECK(checked == 2 * (28 + 9));  // the allowed patterns and the forbidden ones with distinct roots
}

TEST_CASE("the static test: known configurations, and patterns Lemma 1 forbids", "[kernel][contact_status]") {
  auto status = [](const Rational& c, const Rational& r1, const Rational& r2, const Rational& r3) {
    return status_of<Rational>(from_roots(c, r1, r2, r3));
  };
  CHECK(status(Rational(1), Rational(-1, 3), Rational(-5, 2), Rational(7)) == Status::separate);
  CHECK(status(Rational(2), Rational(-3, 4), Rational(-3, 4), Rational(1, 5)) == Status::touching);
  CHECK(status(Rational(1), Rational(1, 2), Rational(1, 2), Rational(1, 2)) == Status::overlapping);  // triple root
  // a complex pair and a positive root: (λ² + 1)(λ - 2), Δ < 0
  CHECK(cubic_contact_status(Rational(1), Rational(-2), Rational(1), Rational(-2)) == Status::overlapping);
  // three distinct negative roots (Lemma 1 forbids them): 3 sign changes, no status
  CHECK(status(Rational(1), Rational(-1), Rational(-2), Rational(-3)) == Status::uncertain);
}

TEST_CASE("status at a multiple root, collision and names", "[kernel][contact_status]") {
  CHECK(status_at_multiple_root(Sign::positive, Sign::negative) == Status::touching);
  CHECK(status_at_multiple_root(Sign::negative, Sign::positive) == Status::touching);
  CHECK(status_at_multiple_root(Sign::positive, Sign::positive) == Status::overlapping);
  CHECK(status_at_multiple_root(Sign::zero, Sign::positive) == Status::overlapping);  // λ0 = 0
  CHECK(status_at_multiple_root(Sign::negative, Sign::zero) == Status::overlapping);  // triple root
  CHECK(status_at_multiple_root(Sign::uncertain, Sign::positive) == Status::uncertain);
  CHECK(status_at_multiple_root(Sign::positive, Sign::uncertain) == Status::uncertain);
  CHECK(in_collision(Status::touching));
  CHECK(in_collision(Status::overlapping));
  CHECK_FALSE(in_collision(Status::separate));
  CHECK_FALSE(in_collision(Status::uncertain));
  CHECK(std::string(to_string(Status::touching)) == "touching");
}

}  // namespace ECCD_UNITY_ID
