#pragma once
// quadric_det_at: det A(t) = det(N(t)^T Q N(t)) of a moving quadric at one
// rational instant t, exactly, in integer arithmetic (the pencil balancing of
// kernel/prepared_scene.hpp asks for it at t = 0, 1/2, 1; forming A(t) in
// rationals instead costs a quarter of a 2D certified run).
//
// Statement. det(N^T Q N) = det Q · (det N)^2 (multiplicativity of the
// determinant). With t = a/b (b > 0), d the largest degree of N's entries and
// L the lcm of the denominators of their coefficients, M = L·b^d·N(t) has the
// integer entries L Σ_k c_k a^k b^(d-k); with L_Q the lcm of Q's denominators,
// L_Q·Q is an integer matrix. So
//   det A(t) = det(L_Q Q) · det(M)^2 / (L_Q^H · (L b^d)^(2H)),
// the same rational as the determinant of A(t) formed in rationals (mpq
// keeps it canonical, so even its representation is the same). The integer
// determinants are taken by Bareiss's fraction-free elimination (every
// division exact; Bareiss 1968).
// Requirements: H x H matrices of Rational (mpq_class) and of Poly<Rational>.
#include "kernel/poly_matrix.hpp"
#include "kernel/polynomial.hpp"
#include "number/rational_traits.hpp"

#include <algorithm>
#include <utility>

namespace eccd {

// det of an integer matrix (Bareiss).
template <int H>
mpz_class bareiss_det(Matrix<mpz_class, H> m) {
  mpz_class prev = 1;
  int sign = 1;
  for (int k = 0; k + 1 < H; ++k) {
    if (m[k][k] == 0) {
      int r = k + 1;
      while (r < H && m[r][k] == 0) ++r;
      if (r == H) return 0;
      std::swap(m[k], m[r]);
      sign = -sign;
    }
    for (int i = k + 1; i < H; ++i)
      for (int j = k + 1; j < H; ++j) {
        m[i][j] = m[i][j] * m[k][k] - m[i][k] * m[k][j];
        mpz_divexact(m[i][j].get_mpz_t(), m[i][j].get_mpz_t(), prev.get_mpz_t());
      }
    prev = m[k][k];
  }
  return sign > 0 ? mpz_class(m[H - 1][H - 1]) : mpz_class(-m[H - 1][H - 1]);
}

template <int H>
Rational quadric_det_at(const Matrix<Rational, H>& q, const PolyMatrix<Rational, H>& n, const Rational& t) {
  mpz_class lq = 1, ln = 1;
  int d = 0;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      mpz_lcm(lq.get_mpz_t(), lq.get_mpz_t(), q[i][j].get_den_mpz_t());
      d = std::max(d, n[i][j].degree());
      for (const Rational& c : n[i][j].c) mpz_lcm(ln.get_mpz_t(), ln.get_mpz_t(), c.get_den_mpz_t());
    }
  const mpz_class a = t.get_num(), b = t.get_den();
  Matrix<mpz_class, H> iq{}, m{};
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      iq[i][j] = q[i][j].get_num() * (lq / q[i][j].get_den());
      // L Σ_k c_k a^k b^(d-k), by Horner in (a, b): s <- s·a + c_k·b^(d-k) from the top
      mpz_class s = 0, bp = 1;  // bp = b^(d-k) for the current k, built from the top
      const auto& c = n[i][j].c;
      const int deg = n[i][j].degree();
      if (deg >= 0) {
        for (int k = deg; k >= 0; --k) {
          if (ln == 1)
            s = s * a + c[k].get_num() * bp;  // integer coefficients (after make_primitive)
          else
            s = s * a + (c[k].get_num() * (ln / c[k].get_den())) * bp;
          bp *= b;
        }
        // s = Σ_k c_k L a^k b^(deg-k); scale to b^d
        for (int k = deg; k < d; ++k) s *= b;
      }
      m[i][j] = s;
    }
  const mpz_class dq = bareiss_det<H>(iq), dm = bareiss_det<H>(m);
  mpz_class den, scale;
  mpz_pow_ui(den.get_mpz_t(), lq.get_mpz_t(), H);
  mpz_pow_ui(scale.get_mpz_t(), b.get_mpz_t(), static_cast<unsigned long>(d));
  scale *= ln;
  mpz_class s2;
  mpz_pow_ui(s2.get_mpz_t(), scale.get_mpz_t(), 2 * H);
  Rational r(dq * dm * dm, den * s2);
  r.canonicalize();
  return r;
}

}  // namespace eccd
