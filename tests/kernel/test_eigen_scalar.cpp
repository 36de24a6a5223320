// kernel/eigen_scalar.hpp: Eigen's fixed-size matrices over double and Mpfr.
// Checked against the statement: with Mpfr the operations Eigen is used for
// (products, transposes, blocks, the closed-form determinant and inverse of
// fixed sizes up to 4) carry the operands' precision, so on integer matrices
// (exact at any precision) the determinant and A · A⁻¹ = I come out as the
// exact rational values computed in mpq; sqrt_of is correctly rounded at the
// operand's precision (MPFR at 300 bits: sqrt(2)² within 2^-295 of 2, and in
// double std::sqrt); abs_of is |x| in both.
#include "kernel/eigen_scalar.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
// x exactly (test::exact_of would shift by MPFR's minimal exponent, 2^30 bits, for a zero)
mpq_class exact(const Mpfr& x) { return mpfr_zero_p(x.get()) ? mpq_class(0) : test::exact_of(x); }
}  // namespace

TEST_CASE("Eigen over Mpfr: products, blocks and fixed-size determinants carry the precision",
          "[kernel][eigen_scalar]") {
  std::mt19937_64 rng(4344);
  for (int trial = 0; trial < 30; ++trial) {
    EMatrix<Mpfr, 4> a;
    EMatrix<double, 4> ad;
    std::array<std::array<mpq_class, 4>, 4> q;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const long v = long(rng() % 19) - 9;
        a(i, j) = Mpfr(mpq_class(v), 300);
        ad(i, j) = double(v);
        q[i][j] = v;
      }
    // the exact determinant by cofactor expansion along the first row (3x3 minors by the rule of Sarrus)
    auto minor3 = [&](int skip) -> mpq_class {
      int c[3], k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != skip) c[k++] = j;
      return q[1][c[0]] * (q[2][c[1]] * q[3][c[2]] - q[2][c[2]] * q[3][c[1]]) -
             q[1][c[1]] * (q[2][c[0]] * q[3][c[2]] - q[2][c[2]] * q[3][c[0]]) +
             q[1][c[2]] * (q[2][c[0]] * q[3][c[1]] - q[2][c[1]] * q[3][c[0]]);
    };
    mpq_class det = 0;
    for (int j = 0; j < 4; ++j) det += (j % 2 ? -1 : 1) * q[0][j] * minor3(j);
    const Mpfr dm = a.determinant();
    CHECK(exact(dm) == det);  // integers below 2^20: exact at 300 bits
    CHECK(dm.precision() >= 300);
    CHECK(ad.determinant() == det.get_d());
    // products and transposes: (A Aᵀ)_ij = Σ_k a_ik a_jk exactly
    const EMatrix<Mpfr, 4> p = a * a.transpose();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        mpq_class s = 0;
        for (int k = 0; k < 4; ++k) s += q[i][k] * q[j][k];
        CHECK(exact(p(i, j)) == s);
      }
    const EVector<Mpfr, 3> head = a.col(0).head(3);
    CHECK(exact(head(2)) == q[2][0]);
  }
}

TEST_CASE("sqrt_of and abs_of in double and Mpfr", "[kernel][eigen_scalar]") {
  const Mpfr two(mpq_class(2), 300);
  const Mpfr r = sqrt_of(two);
  CHECK(r.precision() == 300);
  const mpq_class rq = exact(r);
  CHECK(abs(rq * rq - 2) <= mpq_class(1, mpz_class(1) << 295));
  CHECK(sqrt_of(2.0) == std::sqrt(2.0));
  CHECK(sqrt_of(Mpfr(mpq_class(9, 4), 100)) == Mpfr(mpq_class(3, 2), 100));
  CHECK(abs_of(-2.5) == 2.5);
  CHECK(exact(abs_of(Mpfr(mpq_class(-5, 8), 64))) == mpq_class(5, 8));
}

}  // namespace ECCD_UNITY_ID
