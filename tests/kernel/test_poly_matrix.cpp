// kernel/poly_matrix.hpp: polynomial matrices, their transpose, product,
// Laplace determinant and adjugate. Checked against the scalar matrices of
// their values: at rational t, det(a)(t) is the Leibniz sum of a(t) (written
// in the test), product(a, b)(t) = a(t) b(t), transpose(a)(t) = a(t)ᵀ, and
// the defining identity adj(a) a = a adj(a) = det(a) I (as polynomials),
// over seeded random 3x3 and 4x4 matrices with zero entries; minor_det of a
// chosen submatrix; the translation motion's inverse by hand.
#include "kernel/poly_matrix.hpp"
#include "tests/support/leibniz.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

template <int N>
Rational leibniz(const Matrix<Rational, N>& a, int n = N) {
  return test::leibniz_det<Rational>(a, n);
}

template <int N>
PolyMatrix<Rational, N> random_poly_matrix(std::mt19937_64& rng) {
  PolyMatrix<Rational, N> m{};
  for (auto& row : m)
    for (auto& e : row) {
      if (rng() % 4 == 0) continue;
      std::vector<Rational> c;
      for (int k = 0, deg = int(rng() % 3); k <= deg; ++k) c.push_back(Rational(long(rng() % 11) - 5));
      e = RP(c);
    }
  return m;
}

template <int N>
Matrix<Rational, N> at(const PolyMatrix<Rational, N>& m, const Rational& t) {
  Matrix<Rational, N> r{};
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) r[i][j] = m[i][j](t);
  return r;
}

template <int N>
void check_identities(std::mt19937_64& rng, int trials) {
  for (int trial = 0; trial < trials; ++trial) {
    const auto a = random_poly_matrix<N>(rng), b = random_poly_matrix<N>(rng);
    const RP d = det<Rational, N>(a);
    const auto adj = adjugate<Rational, N>(a);
    const auto left = product<Rational, N>(adj, a), right = product<Rational, N>(a, adj);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        INFO("N = " << N << " trial " << trial << " entry " << i << "," << j);
        CHECK(left[i][j] == (i == j ? d : RP()));
        CHECK(right[i][j] == (i == j ? d : RP()));
      }
    const auto ab = product<Rational, N>(a, b), at_ = transpose<Rational, N>(a);
    for (int s = -2; s <= 3; ++s) {
      const Rational t(s);
      const auto va = at<N>(a, t), vb = at<N>(b, t);
      INFO("N = " << N << " trial " << trial << " t = " << t);
      CHECK(d(t) == leibniz<N>(va));
      const auto vab = at<N>(ab, t), vat = at<N>(at_, t);
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
          Rational x = 0;
          for (int k = 0; k < N; ++k) x += va[i][k] * vb[k][j];
          CHECK(vab[i][j] == x);
          CHECK(vat[i][j] == va[j][i]);
        }
    }
  }
}

}  // namespace

TEST_CASE("poly_matrix: det, adjugate, product and transpose agree with the matrices of values",
          "[kernel][poly_matrix]") {
  std::mt19937_64 rng(4310);
  check_identities<3>(rng, 40);
  check_identities<4>(rng, 20);
}

TEST_CASE("poly_matrix: identity, minor_det of a submatrix, the inverse of a translation", "[kernel][poly_matrix]") {
  const auto id = identity_poly_matrix<Rational, 3>();
  CHECK(det<Rational, 3>(id) == RP::constant(Rational(1)));
  CHECK(adjugate<Rational, 3>(id) == id);
  std::mt19937_64 rng(4311);
  const auto a = random_poly_matrix<4>(rng);
  CHECK(product<Rational, 4>(identity_poly_matrix<Rational, 4>(), a) == a);
  CHECK(product<Rational, 4>(a, identity_poly_matrix<Rational, 4>()) == a);
  // The 2x2 minor of rows {1, 3}, columns {0, 2}.
  const RP m = minor_det<Rational, 4>(a, {1, 3, 0, 0}, {0, 2, 0, 0}, 2);
  CHECK(m == a[1][0] * a[3][2] - a[1][2] * a[3][0]);
  // M = [[1, 0, x], [0, 1, y], [0, 0, 1]] with x = 2t - 1, y = t²: adj M = [[1, 0, -x], [0, 1, -y], [0, 0, 1]].
  PolyMatrix<Rational, 3> mt = identity_poly_matrix<Rational, 3>();
  mt[0][2] = RP({Rational(-1), Rational(2)});
  mt[1][2] = RP({Rational(0), Rational(0), Rational(1)});
  const auto inv = adjugate<Rational, 3>(mt);
  CHECK(det<Rational, 3>(mt) == RP::constant(Rational(1)));
  CHECK(inv[0][2] == -mt[0][2]);
  CHECK(inv[1][2] == -mt[1][2]);
  CHECK(inv[0][0] == RP::constant(Rational(1)));
  CHECK(inv[2][0].is_zero());
  CHECK(inv[0][1].is_zero());
}

}  // namespace ECCD_UNITY_ID
