// The characteristic polynomial f(λ;t) = det(λA(t) - B(t)) = Σ g_k(t) λ^k
// (kernel/characteristic_polynomial.hpp; 003 section III eq. (1), 002
// section 3). Checked in exact arithmetic: for random 3x3 and 4x4 matrices
// of polynomials in t, Σ g_k(t) λ^k equals the determinant of λA(t) - B(t)
// expanded by cofactors, at enough (λ, t) to fix a polynomial of f's
// degrees; and on two unit circles at distance 3, 2 and 1 (f = (λ - 1)
// (-λ² - 7λ - 1), -(λ - 1)(λ + 1)², (λ - 1)(-λ² + λ - 1)) the static test
// gives 003 Theorem 6's separate, touching and overlapping.
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/contact_status.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

Rational at(const Poly<Rational>& p, const Rational& t) { return p.is_zero() ? Rational(0) : Rational(p(t)); }

// The determinant by cofactor expansion along the first row.
Rational cofactor_det(const std::vector<std::vector<Rational>>& m) {
  const std::size_t n = m.size();
  if (n == 1) return m[0][0];
  Rational d = 0;
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<std::vector<Rational>> minor;
    for (std::size_t i = 1; i < n; ++i) {
      std::vector<Rational> row;
      for (std::size_t k = 0; k < n; ++k)
        if (k != j) row.push_back(m[i][k]);
      minor.push_back(row);
    }
    const Rational c = m[0][j] * cofactor_det(minor);
    d += j % 2 ? Rational(-c) : c;
  }
  return d;
}

template <int H>
void check_identity(std::mt19937_64& rng) {
  std::uniform_int_distribution<long> c(-9, 9), den(1, 4);
  auto random_entry = [&]() {
    std::vector<Rational> cs;
    for (int k = 0; k < 2; ++k) {  // linear in t
      Rational q(c(rng), den(rng));
      q.canonicalize();
      cs.push_back(q);
    }
    return Poly<Rational>(cs);
  };
  PolyMatrix<Rational, H> a, b;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      a[i][j] = random_entry();
      b[i][j] = random_entry();
    }
  const std::vector<Poly<Rational>> g = characteristic_coefficients<Rational, H>(a, b);
  REQUIRE(g.size() == std::size_t(H + 1));
  // f has degree H in λ and at most H in t: H + 1 values of each fix it
  for (int li = 0; li <= H; ++li)
    for (int ti = 0; ti <= H; ++ti) {
      Rational lam(li * 3 - 4, 2), t(ti, H);
      lam.canonicalize();  // gmpxx compares canonical forms only
      t.canonicalize();
      std::vector<std::vector<Rational>> m(H, std::vector<Rational>(H));
      for (int i = 0; i < H; ++i)
        for (int j = 0; j < H; ++j) m[i][j] = lam * at(a[i][j], t) - at(b[i][j], t);
      Rational f = 0, power = 1;
      for (int k = 0; k <= H; ++k) {
        f += at(g[k], t) * power;
        power *= lam;
      }
      INFO("λ = " << lam.get_str() << ", t = " << t.get_str());
      CHECK(f == cofactor_det(m));
    }
}

// A unit circle x² + y² - 1 (as a 3x3 matrix, constant in t) centred at (d, 0).
PolyMatrix<Rational, 3> unit_circle_at(long d) {
  auto k = [](long v) { return Poly<Rational>(std::vector<Rational>{Rational(v)}); };
  PolyMatrix<Rational, 3> q;
  q[0] = {k(1), k(0), k(-d)};
  q[1] = {k(0), k(1), k(0)};
  q[2] = {k(-d), k(0), k(d * d - 1)};
  return q;
}

}  // namespace

TEST_CASE("f's coefficients are det(λA(t) - B(t)) expanded by cofactors, 3x3 and 4x4",
          "[kernel][characteristic_polynomial][exact]") {
  std::mt19937_64 rng(378);
  for (int trial = 0; trial < 10; ++trial) {
    INFO("trial " << trial);
    check_identity<3>(rng);
    check_identity<4>(rng);
  }
}

TEST_CASE("two unit circles at distance 3, 2 and 1 are separate, touching and overlapping",
          "[kernel][characteristic_polynomial][contact_status]") {
  const Status want[] = {Status::overlapping, Status::touching, Status::separate};
  for (long d = 1; d <= 3; ++d) {
    const auto g = characteristic_coefficients<Rational, 3>(unit_circle_at(0), unit_circle_at(d));
    const Rational t(0);
    INFO("distance " << d);
    // f(λ) = (λ - 1)((λ - 1)(1 - d² - λ) - d²): g3 = -1 and f(1) = 0 for every d
    CHECK(at(g[3], t) == -1);
    CHECK(at(g[3], t) + at(g[2], t) + at(g[1], t) + at(g[0], t) == 0);
    CHECK(cubic_contact_status(at(g[3], t), at(g[2], t), at(g[1], t), at(g[0], t)) == want[d - 1]);
  }
}

}  // namespace ECCD_UNITY_ID
