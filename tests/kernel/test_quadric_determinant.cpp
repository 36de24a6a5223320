// kernel/quadric_determinant.hpp: det A(t) = det(N(t)ᵀ Q N(t)) at a rational t
// in integer arithmetic (Bareiss). Checked against the determinant of A(t)
// formed in mpq in the test (N(t) evaluated, Nᵀ Q N multiplied out, and its
// determinant by the Leibniz sum), over seeded random rational Q and N(t)
// (non-integer coefficients, entries of different degrees, zero entries) at
// rational t of either sign, t = 0 and t = 1, in 2D (H = 3) and 3D (H = 4);
// the canonical representation too (the header says "the same rational").
// bareiss_det against the Leibniz sum on integer matrices, singular ones and
// ones that need a row swap included.
#include "kernel/quadric_determinant.hpp"
#include "tests/support/leibniz.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

template <class T, int H>
T leibniz(const Matrix<T, H>& a) {
  return test::leibniz_det<T>(a, H);
}

Rational small(std::mt19937_64& rng) {
  Rational x(long(rng() % 41) - 20, long(rng() % 7) + 1);
  x.canonicalize();
  return x;
}

template <int H>
void check_random(std::mt19937_64& rng, int trials) {
  for (int trial = 0; trial < trials; ++trial) {
    Matrix<Rational, H> q{};
    for (int i = 0; i < H; ++i)
      for (int j = i; j < H; ++j) q[i][j] = q[j][i] = small(rng);
    PolyMatrix<Rational, H> n{};
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        if (rng() % 4 == 0) continue;  // a zero entry
        std::vector<Rational> c;
        const int deg = int(rng() % 4);
        for (int e = 0; e <= deg; ++e) c.push_back(small(rng));
        n[i][j] = Poly<Rational>(c);
      }
    for (int s = 0; s < 5; ++s) {
      Rational t = s == 0 ? Rational(0) : s == 1 ? Rational(1) : small(rng);
      t.canonicalize();
      Matrix<Rational, H> nt{}, a{};
      for (int i = 0; i < H; ++i)
        for (int j = 0; j < H; ++j) nt[i][j] = n[i][j](t);
      for (int i = 0; i < H; ++i)
        for (int j = 0; j < H; ++j) {
          Rational x = 0;
          for (int k = 0; k < H; ++k)
            for (int l = 0; l < H; ++l) x += nt[k][i] * q[k][l] * nt[l][j];
          a[i][j] = x;
        }
      const Rational want = leibniz<Rational, H>(a);
      const Rational got = quadric_det_at<H>(q, n, t);
      INFO("H = " << H << " trial " << trial << " t = " << t);
      CHECK(got == want);
      // canonical: the same numerator and denominator
      CHECK(got.get_num() == want.get_num());
      CHECK(got.get_den() == want.get_den());
    }
  }
}

}  // namespace

TEST_CASE("bareiss_det is the Leibniz sum of an integer matrix", "[kernel][quadric_determinant]") {
  std::mt19937_64 rng(4308);
  int swaps = 0, singular = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Matrix<mpz_class, 4> m{};
    for (auto& row : m)
      for (auto& x : row) x = (rng() % 3 == 0) ? 0 : long(rng() % 2001) - 1000;
    if (trial % 5 == 0) m[3] = m[1];  // singular
    swaps += m[0][0] == 0;
    const mpz_class want = leibniz<mpz_class, 4>(m);
    singular += want == 0;
    INFO("trial " << trial);
    CHECK(bareiss_det<4>(m) == want);
  }
  CHECK(swaps > 10);     // a zero pivot at the start was met
  CHECK(singular > 10);  // and singular matrices
  Matrix<mpz_class, 3> z{};
  z[0] = {0, 1, 2};
  z[1] = {0, 3, 4};
  z[2] = {0, 5, 6};  // a zero column: no pivot anywhere
  CHECK(bareiss_det<3>(z) == 0);
}

TEST_CASE("quadric_det_at is det(N(t)^T Q N(t)) formed in rationals", "[kernel][quadric_determinant]") {
  std::mt19937_64 rng(4309);
  check_random<3>(rng, 60);
  check_random<4>(rng, 30);
}

}  // namespace ECCD_UNITY_ID
