#pragma once
// Exact products of integer and rational polynomials by Kronecker
// substitution: one big GMP integer product instead of n·m coefficient
// products (measured: the exact pipeline spends most of its time in
// products of degree-100+ polynomials with coefficients of hundreds of bits).
//
// Statement (Kronecker substitution; e.g. von zur Gathen & Gerhard, Modern
// Computer Algebra, section 8.4). Let x, y be integer polynomials (lowest
// degree first) and z = x·y. Each |z_k| <= min(n_x, n_y) · max|x_i| · max|y_j|
// < 2^(b-1) for b >= bits(x) + bits(y) + ceil(log2 min(n_x, n_y)) + 1. Then
// X = Σ x_i 2^(b i), Y likewise, Z = X·Y = Σ z_k 2^(b k), and the z_k are the
// unique digits of Z in base 2^b with every digit in (-2^(b-1), 2^(b-1)):
// read off |Z| from the lowest digit up, an unsigned chunk u (plus the carry
// c from below) is the digit v = u + c if v < 2^(b-1), else v - 2^b with a
// carry of 1. Everything is exact; GMP's product of Z (Toom / FFT) makes the
// cost about M(n·b) instead of n² M(b).
// Rational polynomials: with d_x the lcm of x's denominators, x = X/d_x with
// integer X (likewise y), so x·y = (X·Y) / (d_x d_y), each coefficient put in
// lowest terms: the very mpq values the schoolbook product gives (GMP keeps
// rationals canonical, so equal values are equal representations).
// Requirements: GMP (mpz_class, mpq_class in lowest terms). Small products
// (few coefficients) go through the schoolbook loop, which is faster there.
#include <gmpxx.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace eccd {

namespace detail {

inline std::size_t max_bits(const mpz_class* x, std::size_t n) {
  std::size_t b = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (mpz_sgn(x[i].get_mpz_t())) b = std::max(b, mpz_sizeinbase(x[i].get_mpz_t(), 2));
  return b;
}

// Σ x_i 2^(64·L·i) with signed x_i, |x_i| < 2^(64·L).
inline void kronecker_pack(mpz_class& out, const mpz_class* x, std::size_t n, std::size_t L) {
  std::vector<mp_limb_t> pos(n * L, 0), neg(n * L, 0);
  bool any_neg = false;
  for (std::size_t i = 0; i < n; ++i) {
    const mpz_srcptr v = x[i].get_mpz_t();
    const int s = mpz_sgn(v);
    if (!s) continue;
    const std::size_t sz = mpz_size(v);
    const mp_limb_t* src = mpz_limbs_read(v);
    std::copy(src, src + sz, (s > 0 ? pos : neg).begin() + std::ptrdiff_t(i * L));
    any_neg = any_neg || s < 0;
  }
  mpz_import(out.get_mpz_t(), n * L, -1, sizeof(mp_limb_t), 0, 0, pos.data());
  if (any_neg) {
    mpz_class m;
    mpz_import(m.get_mpz_t(), n * L, -1, sizeof(mp_limb_t), 0, 0, neg.data());
    out -= m;
  }
}

}  // namespace detail

// z = x·y (lowest degree first; nx, ny >= 1). z gets nx + ny - 1 coefficients.
inline void integer_poly_product(const mpz_class* x, std::size_t nx, const mpz_class* y, std::size_t ny,
                                 std::vector<mpz_class>& z) {
  z.assign(nx + ny - 1, mpz_class(0));
  const std::size_t bx = detail::max_bits(x, nx), by = detail::max_bits(y, ny);
  if (bx == 0 || by == 0) return;
  if (std::min(nx, ny) <= 2 || nx * ny <= 16) {  // schoolbook: cheaper for tiny products
    for (std::size_t i = 0; i < nx; ++i) {
      if (!mpz_sgn(x[i].get_mpz_t())) continue;
      for (std::size_t j = 0; j < ny; ++j) mpz_addmul(z[i + j].get_mpz_t(), x[i].get_mpz_t(), y[j].get_mpz_t());
    }
    return;
  }
  std::size_t lg = 0;
  while ((std::size_t(1) << lg) < std::min(nx, ny)) ++lg;
  const std::size_t b_min = bx + by + lg + 1;
  const std::size_t L = (b_min + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS;  // digit size in limbs
  const std::size_t b = L * GMP_NUMB_BITS;
  mpz_class X, Y, Z;
  detail::kronecker_pack(X, x, nx, L);
  detail::kronecker_pack(Y, y, ny, L);
  if (x == y && nx == ny)
    Z = X * X;
  else
    Z = X * Y;
  const int sZ = mpz_sgn(Z.get_mpz_t());
  if (!sZ) return;
  const std::size_t zs = mpz_size(Z.get_mpz_t());
  const mp_limb_t* zl = mpz_limbs_read(Z.get_mpz_t());
  mpz_class pow2b;
  mpz_setbit(pow2b.get_mpz_t(), b);
  int carry = 0;
  for (std::size_t k = 0; k < z.size(); ++k) {
    mpz_class& v = z[k];
    const std::size_t off = k * L;
    if (off < zs) {
      const std::size_t cnt = std::min(L, zs - off);
      mpz_import(v.get_mpz_t(), cnt, -1, sizeof(mp_limb_t), 0, 0, zl + off);
    } else {
      v = 0;
    }
    if (carry) v += 1;
    if (mpz_sgn(v.get_mpz_t()) && mpz_sizeinbase(v.get_mpz_t(), 2) >= b) {  // v >= 2^(b-1)
      v -= pow2b;
      carry = 1;
    } else {
      carry = 0;
    }
    if (sZ < 0) mpz_neg(v.get_mpz_t(), v.get_mpz_t());
  }
}

// The product of two rational polynomials (lowest degree first, both non-empty),
// exact and in lowest terms; the caller trims trailing zeros.
inline std::vector<mpq_class> rational_poly_product(const std::vector<mpq_class>& a, const std::vector<mpq_class>& b) {
  auto clear = [](const std::vector<mpq_class>& p, std::vector<mpz_class>& num, mpz_class& den) {
    den = 1;
    for (const auto& c : p)
      if (mpz_cmp_ui(c.get_den_mpz_t(), 1) != 0) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), c.get_den_mpz_t());
    num.resize(p.size());
    const bool one = den == 1;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (one) {
        num[i] = p[i].get_num();
        continue;
      }
      mpz_divexact(num[i].get_mpz_t(), den.get_mpz_t(), p[i].get_den_mpz_t());
      num[i] *= p[i].get_num();
    }
  };
  std::vector<mpz_class> na, nb, nz;
  mpz_class da, db;
  clear(a, na, da);
  if (&a == &b) {
    db = da;
    integer_poly_product(na.data(), na.size(), na.data(), na.size(), nz);
  } else {
    clear(b, nb, db);
    integer_poly_product(na.data(), na.size(), nb.data(), nb.size(), nz);
  }
  const mpz_class d = da * db;
  const bool one = d == 1;
  std::vector<mpq_class> r(nz.size());
  for (std::size_t k = 0; k < nz.size(); ++k) {
    mpz_swap(r[k].get_num_mpz_t(), nz[k].get_mpz_t());
    if (!one) {
      mpz_set(r[k].get_den_mpz_t(), d.get_mpz_t());
      r[k].canonicalize();
    }
  }
  return r;
}

}  // namespace eccd
