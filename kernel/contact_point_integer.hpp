#pragma once
// The contact point of Lemma 5 (003) in exact arithmetic over the integers:
// the same point, digits and normal as contact_point<mpq_class>
// (kernel/cd_disc.hpp), with one common denominator instead of a reduction to
// lowest terms after every rational operation (measured: those gcds took a
// quarter of the exact 2D pipeline).
//
// Statement. At the rational instant t = u/v (the root's bracket mid-point),
// λ0 = P / (2D) with P = 9 g3 g0 - g2 g1, D = g2² - 3 g3 g1 (003 Lemma 5;
// kernel/discriminant.hpp), and the point is X = (x, y, 1) with X ∝ a null
// vector of m = λ0 A(t) - B(t), taken as the cross product c of the two rows
// of m with the largest |c0| + |c1| + |c2| (in double: the selection only),
// x = c0 / c2, y = c1 / c2. Here:
//  - G_k = g_k(t) · Dg v^Ng are integers (Dg the lcm of the g's coefficient
//    denominators, Ng their largest degree); P and D are homogeneous of
//    degree 2 in the g's, so P(G) / (2 D(G)) = λ0 exactly;
//  - A(t) = IA / (DA v^NA), B(t) = IB / (DB v^NB) with integer matrices IA, IB
//    (common denominators likewise), and
//      M = s m = P(G) DB v^NB · IA - 2 D(G) DA v^NA · IB,   s = 2 D(G) DA v^NA DB v^NB ≠ 0,
//    an integer matrix; its row cross products are C = s² c (s² > 0);
//  - the selection reads to_double(c_k) = mpq_get_d(c_k), which truncates the
//    value c_k = C_k / s² towards zero to 53 bits: truncated_double computes
//    that from C_k and s² without reducing the fraction (for magnitudes in
//    [2^-1000, 2^1000]; outside, the fraction is reduced and mpq_get_d asked);
//  - x = C0 / C2, y = C1 / C2 (the same values), printed by decimal_string's
//    rule (MPFR at 256 bits, rounded to nearest: the value decides, not the
//    representation), and the normal's components (a_i0 x + a_i1 y + a_i2)(t)
//    read by the same truncation as to_double.
// So every string equals contact_point<mpq_class>'s (tests/kernel/
// test_contact_point_integer.cpp compares them).
// Requirements: T = mpq_class (GMP); MPFR for the digits.
#include "kernel/answer.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/poly_matrix.hpp"
#include "kernel/polynomial.hpp"

#include <gmpxx.h>
#include <mpfr.h>

#include <cmath>
#include <string>
#include <vector>

namespace eccd {

namespace contact_integer_detail {

// out[i] = q_i(u/v) · D · v^N for the polynomials qs (D the lcm of all their
// coefficients' denominators, N their largest degree): integers.
inline void common_denominator_values(const std::vector<const Poly<mpq_class>*>& qs, const mpq_class& t,
                                      std::vector<mpz_class>& out, mpz_class& D, int& N) {
  D = 1;
  N = 0;
  for (const auto* q : qs) {
    N = std::max(N, int(q->c.size()) - 1);
    for (const auto& c : q->c)
      if (mpz_cmp_ui(c.get_den_mpz_t(), 1) != 0) mpz_lcm(D.get_mpz_t(), D.get_mpz_t(), c.get_den_mpz_t());
  }
  const mpz_class& u = t.get_num();
  const mpz_class& v = t.get_den();
  std::vector<mpz_class> vp(std::size_t(N) + 1);
  vp[0] = 1;
  for (int i = 1; i <= N; ++i) vp[i] = vp[i - 1] * v;
  out.assign(qs.size(), mpz_class(0));
  mpz_class C, term;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const auto& c = qs[k]->c;
    const int n = int(c.size()) - 1;
    if (n < 0) continue;
    auto coeff = [&](int i) {  // C_i = c_i · D
      mpz_divexact(C.get_mpz_t(), D.get_mpz_t(), c[i].get_den_mpz_t());
      C *= c[i].get_num();
    };
    mpz_class& s = out[k];
    coeff(n);
    s = C;
    for (int i = n - 1; i >= 0; --i) {
      s *= u;
      if (sgn(c[i]) == 0) continue;
      coeff(i);
      mpz_mul(term.get_mpz_t(), C.get_mpz_t(), vp[n - i].get_mpz_t());
      s += term;
    }
    s *= vp[N - n];
  }
}

// mpq_get_d of the value n / d (d > 0), i.e. n / d truncated towards zero to
// 53 bits, without reducing the fraction: false when |n / d| may lie outside
// [2^-1000, 2^1000] (the caller then reduces it).
inline bool truncated_double(const mpz_class& n, const mpz_class& d, double& out) {
  if (sgn(n) == 0) {
    out = 0.0;
    return true;
  }
  // |n| >= 2^(bn-1), d < 2^bd, so q = trunc(|n| 2^e / d) >= 2^63 for e = bd - bn + 64,
  // and q < 2^65: truncating q to 53 bits is truncating |n| 2^e / d (the dropped bits are below q's 12th).
  const long e = long(mpz_sizeinbase(d.get_mpz_t(), 2)) - long(mpz_sizeinbase(n.get_mpz_t(), 2)) + 64;
  if (e > 1000 + 64 || e < -1000 + 64) return false;
  mpz_class q = abs(n);
  if (e >= 0) {
    q <<= static_cast<unsigned long>(e);
    mpz_tdiv_q(q.get_mpz_t(), q.get_mpz_t(), d.get_mpz_t());
  } else {
    mpz_class dd = d << static_cast<unsigned long>(-e);
    mpz_tdiv_q(q.get_mpz_t(), q.get_mpz_t(), dd.get_mpz_t());
  }
  const double r = std::ldexp(mpz_get_d(q.get_mpz_t()), int(-e));  // mpz_get_d truncates; ldexp is exact here
  out = sgn(n) < 0 ? -r : r;
  return true;
}

inline double to_double_of(const mpz_class& n, const mpz_class& d) {
  double r;
  if (truncated_double(n, d, r)) return r;
  mpq_class q(n, d);
  q.canonicalize();
  return q.get_d();
}

// decimal_string (kernel/answer.hpp) of the value n / d, d != 0: MPFR rounds the
// quotient of the two exact integers to nearest at 256 bits, as mpfr_set_q does for the reduced fraction.
inline std::string decimal_string_of(const mpz_class& n, const mpz_class& d, int digits = 20) {
  mpfr_t N, Dn, r;
  mpfr_init2(N, mpfr_prec_t(std::max<std::size_t>(mpz_sizeinbase(n.get_mpz_t(), 2), 2)));
  mpfr_init2(Dn, mpfr_prec_t(std::max<std::size_t>(mpz_sizeinbase(d.get_mpz_t(), 2), 2)));
  mpfr_init2(r, 256);
  mpfr_set_z(N, n.get_mpz_t(), MPFR_RNDN);   // exact
  mpfr_set_z(Dn, d.get_mpz_t(), MPFR_RNDN);  // exact
  mpfr_div(r, N, Dn, MPFR_RNDN);
  char* s = nullptr;
  mpfr_asprintf(&s, "%.*Rg", digits, r);
  std::string out(s);
  mpfr_free_str(s);
  mpfr_clear(N);
  mpfr_clear(Dn);
  mpfr_clear(r);
  return out;
}

}  // namespace contact_integer_detail

inline ContactPoint contact_point_integer(const PolyMatrix<mpq_class, 3>& a, const PolyMatrix<mpq_class, 3>& b,
                                          const std::vector<Poly<mpq_class>>& g, const mpq_class& t) {
  using namespace contact_integer_detail;
  ContactPoint cp;
  std::vector<mpz_class> G, IA, IB;
  mpz_class Dg, DA, DB;
  int Ng, NA, NB;
  common_denominator_values({&g[0], &g[1], &g[2], &g[3]}, t, G, Dg, Ng);
  const mpz_class P = double_root_numerator(G[3], G[2], G[1], G[0]);
  const mpz_class D = double_root_denominator(G[3], G[2], G[1]);
  if (sgn(D) == 0) return cp;
  std::vector<const Poly<mpq_class>*> pa, pb;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      pa.push_back(&a[i][j]);
      pb.push_back(&b[i][j]);
    }
  common_denominator_values(pa, t, IA, DA, NA);
  common_denominator_values(pb, t, IB, DB, NB);
  mpz_class vNA, vNB;
  mpz_pow_ui(vNA.get_mpz_t(), t.get_den_mpz_t(), static_cast<unsigned long>(NA));
  mpz_pow_ui(vNB.get_mpz_t(), t.get_den_mpz_t(), static_cast<unsigned long>(NB));
  const mpz_class KA = P * DB * vNB, KB = 2 * D * DA * vNA;  // M = KA · IA - KB · IB = s m
  const mpz_class s = KB * DB * vNB;
  const mpz_class s2 = s * s;
  mpz_class M[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M[i][j] = KA * IA[3 * i + j] - KB * IB[3 * i + j];
  mpz_class best[3] = {0, 0, 0};
  double bestn = -1;
  for (int r = 0; r < 3; ++r) {
    const auto& u = M[r];
    const auto& w = M[(r + 1) % 3];
    mpz_class c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    double n = std::abs(to_double_of(c[0], s2)) + std::abs(to_double_of(c[1], s2)) + std::abs(to_double_of(c[2], s2));
    if (n > bestn) {
      bestn = n;
      best[0] = c[0];
      best[1] = c[1];
      best[2] = c[2];
    }
  }
  if (sgn(best[2]) == 0) return cp;
  cp.x = {decimal_string_of(best[0], best[2]), decimal_string_of(best[1], best[2])};
  // The common normal: (a_i0 x + a_i1 y + a_i2)(t) = (IA_i0 C0 + IA_i1 C1 + IA_i2 C2) / (DA v^NA C2), in double
  // (display only).
  const mpz_class den = DA * vNA * best[2];
  double n[2];
  for (int i = 0; i < 2; ++i) {
    mpz_class num = IA[3 * i] * best[0] + IA[3 * i + 1] * best[1] + IA[3 * i + 2] * best[2];
    n[i] = sgn(den) < 0 ? to_double_of(mpz_class(-num), mpz_class(-den)) : to_double_of(num, den);
  }
  const double len = std::hypot(n[0], n[1]);
  if (len > 0 && std::isfinite(len))
    cp.normal = {decimal_string_of_double(n[0] / len), decimal_string_of_double(n[1] / len)};
  return cp;
}

}  // namespace eccd
