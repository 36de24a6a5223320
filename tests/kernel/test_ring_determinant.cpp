// kernel/ring_determinant.hpp: ring_det (the signed sum over placements of
// rows into column sets, any commutative ring) and field_det (Gaussian
// elimination with partial pivoting). Checked against the Leibniz formula
// det a = sum over permutations σ of sgn(σ) prod_r a[r][σ(r)], written here
// with the sign counted by inversions, in mpq over seeded random matrices of
// sizes 1..6 (dense, sparse, singular), and in the rings of polynomials
// (Poly<Rational>, Bern<Rational>: the determinant's values at rational t are
// the determinants of the values); field_det exactly in mpq and in double
// within a bound (Hadamard's: the rounding error is a small multiple of
// 2^-53 times the product of the rows' norms); is_ring_zero on each kind.
#include "kernel/bernstein.hpp"
#include "kernel/polynomial.hpp"
#include "kernel/ring_determinant.hpp"
#include "tests/support/leibniz.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using Mat = std::vector<std::vector<Rational>>;

Rational leibniz(const Mat& a) { return test::leibniz_det<Rational>(a, int(a.size())); }

Rational small(std::mt19937_64& rng) {
  Rational x(long(rng() % 19) - 9, long(rng() % 5) + 1);
  x.canonicalize();
  return x;
}

Mat random_matrix(std::mt19937_64& rng, int k, int zero_one_in) {
  Mat a(k, std::vector<Rational>(k));
  for (auto& row : a)
    for (auto& x : row) x = (rng() % zero_one_in == 0) ? Rational(0) : small(rng);
  if (k >= 2 && rng() % 4 == 0) {  // singular: a row a combination of two others
    const Rational f = small(rng);
    for (int j = 0; j < k; ++j) a[k - 1][j] = a[0][j] + f * a[1 % k][j];
  }
  return a;
}

}  // namespace

TEST_CASE("ring_det over the rationals is the Leibniz sum", "[kernel][ring_determinant]") {
  std::mt19937_64 rng(4305);
  int singular = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int k = 1 + int(trial % 6);
    const Mat a = random_matrix(rng, k, trial % 3 == 0 ? 2 : 9);
    const Rational want = leibniz(a);
    INFO("trial " << trial << " size " << k);
    CHECK(ring_det(a, Rational(0)) == want);
    singular += want == 0;
  }
  CHECK(singular > 10);  // the singular and sparse cases were reached
  const Mat zero_row = {{Rational(1), Rational(2)}, {Rational(0), Rational(0)}};
  CHECK(ring_det(zero_row, Rational(0)) == 0);  // no placement of the last row: the zero element
}

TEST_CASE("ring_det over polynomials: the values of the determinant are the determinants of the values",
          "[kernel][ring_determinant]") {
  std::mt19937_64 rng(4306);
  for (int trial = 0; trial < 40; ++trial) {
    const int k = 1 + int(trial % 4);
    std::vector<std::vector<Poly<Rational>>> p(k, std::vector<Poly<Rational>>(k));
    std::vector<std::vector<Bern<Rational>>> b(k, std::vector<Bern<Rational>>(k));
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        std::vector<Rational> c;
        const int deg = int(rng() % 3);
        for (int e = 0; e <= deg; ++e) c.push_back(small(rng));
        if (rng() % 5 == 0) c.assign(1, Rational(0));
        p[i][j] = Poly<Rational>(c);
        b[i][j] = to_bernstein(Poly<Rational>(c), 2);  // all of one degree
      }
    const Poly<Rational> dp = ring_det(p, Poly<Rational>());
    Bern<Rational> zb;
    zb.b.assign(1, Rational(0));
    const Bern<Rational> db = ring_det(b, zb);
    for (int s = 0; s <= 6; ++s) {
      Rational t(s - 1, 4);  // inside and outside [0, 1]
      t.canonicalize();
      Mat at(k, std::vector<Rational>(k));
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) at[i][j] = p[i][j](t);
      const Rational want = leibniz(at);
      INFO("trial " << trial << " t = " << t);
      CHECK(dp(t) == want);
      if (t >= 0 && t <= 1) CHECK(db(t) == want);
    }
  }
}

TEST_CASE("field_det is the determinant: exactly in mpq, to rounding in double", "[kernel][ring_determinant]") {
  std::mt19937_64 rng(4307);
  for (int trial = 0; trial < 200; ++trial) {
    const Mat a = random_matrix(rng, 4, trial % 2 ? 3 : 50);
    std::array<std::array<Rational, 4>, 4> q;
    std::array<std::array<double, 4>, 4> d;
    double hadamard = 1;
    for (int i = 0; i < 4; ++i) {
      double norm = 0;
      for (int j = 0; j < 4; ++j) {
        q[i][j] = a[i][j];
        d[i][j] = a[i][j].get_d();
        norm += d[i][j] * d[i][j];
      }
      hadamard *= std::sqrt(norm);
    }
    const Rational want = leibniz(a);
    INFO("trial " << trial);
    CHECK(field_det<Rational, 4>(q) == want);
    // The entries are rounded (k/5 is not a double) and elimination rounds: a small multiple of 2^-53 of the
    // Hadamard bound covers both (Wilkinson's bound for partial pivoting at n = 4 is far below 64 units).
    CHECK(std::abs(field_det<double, 4>(d) - want.get_d()) <= 64 * 0x1p-53 * hadamard);
  }
  std::array<std::array<Rational, 3>, 3> sing{};
  sing[0] = {Rational(1), Rational(2), Rational(3)};
  sing[1] = {Rational(2), Rational(4), Rational(6)};
  sing[2] = {Rational(0), Rational(1), Rational(5)};
  CHECK(field_det<Rational, 3>(sing) == 0);
}

TEST_CASE("is_ring_zero knows the zero of each ring", "[kernel][ring_determinant]") {
  CHECK(is_ring_zero(Rational(0)));
  CHECK_FALSE(is_ring_zero(Rational(1, 3)));
  CHECK(is_ring_zero(0.0));
  CHECK(is_ring_zero(Poly<Rational>()));
  CHECK_FALSE(is_ring_zero(Poly<Rational>::constant(Rational(2))));
  Bern<Rational> b;
  b.b = {Rational(0), Rational(0), Rational(0)};
  CHECK(is_ring_zero(b));  // every Bernstein coefficient zero
  b.b[1] = Rational(-1);
  CHECK_FALSE(is_ring_zero(b));
}

}  // namespace ECCD_UNITY_ID
