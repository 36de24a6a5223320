#pragma once
// The pencil λA(t) - B(t) of a scene, by the checker's own route: values at
// rational points, never a symbolic expansion of f(λ; t).
//
// Statement (scene-format.md; docs/architecture.md "Use the adjugate"). The moving solid
// is A(t) = M(t)^-T Q M(t)^-1. The adjugate adj M(t) = det M(t) · M(t)^-1 is
// a polynomial matrix; the checker gets it by expanding the cofactors of
// L·M(t) (L > 0 clears M's denominators) on integer polynomials, divides out
// the gcd of its entries (Euclid over Q), and calls the result N(t). Any
// polynomial matrix c(t) M(t)^-1 with entries of content 1 equals N up to a
// non-zero constant (if c1 X and c2 X both have coprime entries, c1 / c2 is a
// constant), so the workbench's own N (kernel/prepared_scene.hpp: the
// motion's inverse form, its gcd divided out, scaled to primitive integers)
// is N times a constant, and its A(t) = N^T Q N is the checker's times a
// positive constant (Q is also scaled by a positive one). Hence a
// certificate's f = Σ g_k λ^k and the checker's h = det(λ N_a^T Q_a N_a -
// N_b^T Q_b N_b) satisfy g_k = α^k β^(H-k) h_k with α, β > 0: the roots λ
// are scaled by β/α > 0, their signs and multiplicities unchanged. The f
// claim checks exactly this, at deg + 1 points (two polynomials of degree at
// most deg that agree there are equal).
// Also here: det M(t) up to a positive constant (cofactors on integer
// polynomials), and the determinant of a rational matrix (Gaussian
// elimination over Q) and of an integer one (Bareiss).
// Requirements: GMP. Cost: O(D · H^4) integer operations for D points.
#include "certificate/check/qpoly.hpp"
#include "certificate/check/scene.hpp"

#include <algorithm>
#include <vector>

namespace eccd::check {

inline mpq_class determinant(QMatrix m) {
  const std::size_t n = m.size();
  mpq_class det = 1;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    while (p < n && sgn(m[p][c]) == 0) ++p;
    if (p == n) return 0;
    if (p != c) {
      std::swap(m[p], m[c]);
      det = -det;
    }
    det *= m[c][c];
    for (std::size_t r = c + 1; r < n; ++r) {
      if (sgn(m[r][c]) == 0) continue;
      const mpq_class k = m[r][c] / m[c][c];
      for (std::size_t j = c; j < n; ++j) m[r][j] -= k * m[c][j];
    }
  }
  return det;
}

// The determinant of an integer matrix (Bareiss: every division exact).
inline mpz_class determinant(std::vector<std::vector<mpz_class>> m) {
  const std::size_t n = m.size();
  if (n == 0) return 1;
  mpz_class prev = 1;
  int sign = 1;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (m[k][k] == 0) {
      std::size_t p = k + 1;
      while (p < n && m[p][k] == 0) ++p;
      if (p == n) return 0;
      std::swap(m[p], m[k]);
      sign = -sign;
    }
    for (std::size_t i = k + 1; i < n; ++i)
      for (std::size_t j = k + 1; j < n; ++j) {
        m[i][j] = m[i][j] * m[k][k] - m[i][k] * m[k][j];
        mpz_divexact(m[i][j].get_mpz_t(), m[i][j].get_mpz_t(), prev.get_mpz_t());
      }
    prev = m[k][k];
  }
  return sign * m[n - 1][n - 1];
}

inline QMatrix at_point(const PolyMatrix& m, const mpq_class& t) {
  QMatrix r(m.size(), std::vector<mpq_class>(m.size()));
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = 0; j < m.size(); ++j) r[i][j] = m[i][j](t);
  return r;
}

inline int matrix_degree(const PolyMatrix& m) {
  int d = 0;
  for (const auto& row : m)
    for (const auto& e : row) d = std::max(d, e.degree());
  return d;
}

// Integer polynomials (lowest degree first, trimmed): product, sum, and the
// determinant of a square matrix of them by cofactor expansion along the
// first row (H <= 4: at most 24 products of entries, no division).
using ZPoly = std::vector<mpz_class>;
inline ZPoly trimmed(ZPoly p) {
  while (!p.empty() && sgn(p.back()) == 0) p.pop_back();
  return p;
}
inline ZPoly product(const ZPoly& a, const ZPoly& b) {
  if (a.empty() || b.empty()) return {};
  ZPoly r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) mpz_addmul(r[i + j].get_mpz_t(), a[i].get_mpz_t(), b[j].get_mpz_t());
  return trimmed(std::move(r));
}
inline void add_to(ZPoly& acc, const ZPoly& p, int sign) {
  if (acc.size() < p.size()) acc.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (sign > 0)
      acc[i] += p[i];
    else
      acc[i] -= p[i];
  }
}
inline ZPoly determinant(const std::vector<std::vector<ZPoly>>& m) {
  const std::size_t n = m.size();
  if (n == 0) return ZPoly{mpz_class(1)};
  if (n == 1) return m[0][0];
  ZPoly d;
  for (std::size_t c = 0; c < n; ++c) {
    if (m[0][c].empty()) continue;
    std::vector<std::vector<ZPoly>> minor;
    for (std::size_t r = 1; r < n; ++r) {
      minor.emplace_back();
      for (std::size_t k = 0; k < n; ++k)
        if (k != c) minor.back().push_back(m[r][k]);
    }
    add_to(d, product(m[0][c], determinant(minor)), c % 2 ? -1 : 1);
  }
  return trimmed(std::move(d));
}
inline QPoly to_qpoly(const ZPoly& z) {
  std::vector<mpq_class> c;
  for (const auto& x : z) c.emplace_back(x);
  return QPoly(std::move(c));
}
using ZPolyMatrix = std::vector<std::vector<ZPoly>>;
inline ZPolyMatrix integer_matrix(const PolyMatrix& m);

// adj(L·M) / gcd of its entries (L > 0 the lcm of M's denominators): the
// cofactors on integer polynomials, then the monic gcd over Q (Euclid),
// stopped as soon as it is a constant.
inline PolyMatrix primitive_inverse(const PolyMatrix& M) {
  const std::size_t H = M.size();
  const ZPolyMatrix Z = integer_matrix(M);
  PolyMatrix N(H, std::vector<QPoly>(H));
  QPoly g;
  bool unit = false;  // the gcd is already a constant
  for (std::size_t i = 0; i < H; ++i)
    for (std::size_t j = 0; j < H; ++j) {
      // adj[i][j] = (-1)^(i+j) det(minor without row j and column i)
      std::vector<std::vector<ZPoly>> minor;
      for (std::size_t r = 0; r < H; ++r) {
        if (r == j) continue;
        minor.emplace_back();
        for (std::size_t c = 0; c < H; ++c)
          if (c != i) minor.back().push_back(Z[r][c]);
      }
      ZPoly v = determinant(minor);
      if ((i + j) % 2)
        for (auto& x : v) x = -x;
      N[i][j] = to_qpoly(v);
      if (N[i][j].zero() || unit) continue;
      g = g.zero() ? mpq_class(1 / N[i][j].lead()) * N[i][j] : gcd(g, N[i][j]);
      unit = g.degree() == 0;
    }
  if (g.degree() > 0)
    for (auto& row : N)
      for (auto& e : row) {
        QPoly q, r;
        divmod(e, g, q, r);
        e = q;
      }
  return N;
}

// det M(t) times a positive constant (L^H, L the lcm of M's denominators), by cofactors on integer polynomials.
inline QPoly motion_determinant(const PolyMatrix& M) { return to_qpoly(determinant(integer_matrix(M))); }

// N^T Q N at t.
inline QMatrix moving_quadric(const QMatrix& Q, const PolyMatrix& N, const mpq_class& t) {
  const QMatrix n = at_point(N, t);
  const std::size_t H = Q.size();
  QMatrix qn(H, std::vector<mpq_class>(H)), r(H, std::vector<mpq_class>(H));
  for (std::size_t i = 0; i < H; ++i)
    for (std::size_t j = 0; j < H; ++j)
      for (std::size_t k = 0; k < H; ++k) qn[i][j] += Q[i][k] * n[k][j];
  for (std::size_t i = 0; i < H; ++i)
    for (std::size_t j = 0; j < H; ++j)
      for (std::size_t k = 0; k < H; ++k) r[i][j] += n[k][i] * qn[k][j];
  return r;
}

// The same on integers, for the f claim's many points: a rational matrix (of
// numbers or polynomials) times the lcm of its denominators, a positive
// integer; N(t) at an integer t; N^T Q N; and H! times the coefficients of
// det(λA - B) (values at λ = 0 .. H by Bareiss, Newton's forward differences
// d_j, H! binom(λ, j) = (H!/j!) λ(λ-1)...(λ-j+1) expanded on integers).
using ZMatrix = std::vector<std::vector<mpz_class>>;

// The lcm of a matrix's denominators: integer_matrix(m) is m times it.
inline mpz_class denominators_lcm(const PolyMatrix& m) {
  mpz_class l = 1;
  for (const auto& row : m)
    for (const auto& e : row) l = denominator_lcm(e, l);
  return l;
}
inline mpz_class denominators_lcm(const QMatrix& m) {
  mpz_class l = 1;
  for (const auto& row : m)
    for (const auto& e : row) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), e.get_den_mpz_t());
  return l;
}
inline ZPolyMatrix integer_matrix(const PolyMatrix& m) {
  const mpz_class l = denominators_lcm(m);
  ZPolyMatrix r;
  for (const auto& row : m) {
    r.emplace_back();
    for (const auto& e : row) r.back().push_back(integer_multiple(e, l));
  }
  return r;
}
inline ZMatrix integer_matrix(const QMatrix& m) {
  const mpz_class l = denominators_lcm(m);
  ZMatrix r;
  for (const auto& row : m) {
    r.emplace_back();
    for (const auto& e : row) r.back().push_back(e.get_num() * (l / e.get_den()));
  }
  return r;
}
inline ZMatrix at_point(const ZPolyMatrix& m, const mpz_class& t) {
  ZMatrix r(m.size());
  for (std::size_t i = 0; i < m.size(); ++i)
    for (const auto& e : m[i]) r[i].push_back(value_at(e, t));
  return r;
}
inline ZMatrix moving_quadric(const ZMatrix& Q, const ZMatrix& n) {
  const std::size_t H = Q.size();
  ZMatrix qn(H, std::vector<mpz_class>(H)), r(H, std::vector<mpz_class>(H));
  for (std::size_t i = 0; i < H; ++i)
    for (std::size_t j = 0; j < H; ++j)
      for (std::size_t k = 0; k < H; ++k) qn[i][j] += Q[i][k] * n[k][j];
  for (std::size_t i = 0; i < H; ++i)
    for (std::size_t j = i; j < H; ++j) {
      for (std::size_t k = 0; k < H; ++k) r[i][j] += n[k][i] * qn[k][j];
      if (i != j) r[j][i] = r[i][j];  // N^T Q N is symmetric (Q is: the scene reader requires it)
    }
  return r;
}
// For H = 3 by the identity det(λA - B) = λ³ det A - λ² Σ C(A)_ij B_ij +
// λ Σ A_ij C(B)_ij - det B (C the cofactor matrix, C_ij = X_{i+1,j+1} X_{i+2,j+2}
// - X_{i+1,j+2} X_{i+2,j+1}, indices mod 3), times 3! as the route above.
inline ZMatrix cofactors3(const ZMatrix& X) {
  ZMatrix C(3, std::vector<mpz_class>(3));
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      C[i][j] = X[i1][j1] * X[i2][j2] - X[i1][j2] * X[i2][j1];
    }
  return C;
}
inline std::vector<mpz_class> pencil_coefficients(const ZMatrix& A, const ZMatrix& B) {
  const std::size_t H = A.size();
  if (H == 3) {
    const ZMatrix CA = cofactors3(A), CB = cofactors3(B);
    std::vector<mpz_class> out(4);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        mpz_submul(out[2].get_mpz_t(), CA[i][j].get_mpz_t(), B[i][j].get_mpz_t());
        mpz_addmul(out[1].get_mpz_t(), A[i][j].get_mpz_t(), CB[i][j].get_mpz_t());
      }
    for (std::size_t j = 0; j < 3; ++j) {
      mpz_addmul(out[3].get_mpz_t(), A[0][j].get_mpz_t(), CA[0][j].get_mpz_t());
      mpz_submul(out[0].get_mpz_t(), B[0][j].get_mpz_t(), CB[0][j].get_mpz_t());
    }
    for (auto& x : out) x *= 6;
    return out;
  }
  std::vector<mpz_class> d;
  for (std::size_t l = 0; l <= H; ++l) {
    ZMatrix m(H, std::vector<mpz_class>(H));
    for (std::size_t i = 0; i < H; ++i)
      for (std::size_t j = 0; j < H; ++j) m[i][j] = A[i][j] * (unsigned long)l - B[i][j];
    d.push_back(determinant(std::move(m)));
  }
  for (std::size_t j = 1; j <= H; ++j)  // forward differences: d[j] = Δ^j v(0)
    for (std::size_t i = H; i >= j; --i) d[i] -= d[i - 1];
  mpz_class hf = 1;
  for (std::size_t k = 2; k <= H; ++k) hf *= (unsigned long)k;
  std::vector<mpz_class> out(H + 1), ff{mpz_class(1)};
  mpz_class jf = 1;  // j!
  for (std::size_t j = 0; j <= H; ++j) {
    if (j > 0) jf *= (unsigned long)j;
    const mpz_class w = d[j] * (hf / jf);
    for (std::size_t k = 0; k < ff.size(); ++k) out[k] += w * ff[k];
    std::vector<mpz_class> next(ff.size() + 1);  // ff · (λ - j)
    for (std::size_t k = 0; k < ff.size(); ++k) {
      next[k + 1] += ff[k];
      next[k] -= ff[k] * (unsigned long)j;
    }
    ff.swap(next);
  }
  return out;
}

// The coefficients h_0 .. h_H of det(λA - B) (by values at λ = 0 .. H).
inline std::vector<mpq_class> pencil_coefficients(const QMatrix& A, const QMatrix& B) {
  const std::size_t H = A.size();
  std::vector<mpq_class> v;
  for (std::size_t l = 0; l <= H; ++l) {
    QMatrix m(H, std::vector<mpq_class>(H));
    for (std::size_t i = 0; i < H; ++i)
      for (std::size_t j = 0; j < H; ++j) m[i][j] = mpq_class(long(l)) * A[i][j] - B[i][j];
    v.push_back(determinant(m));
  }
  QPoly p = interpolate_at_integers(v);
  std::vector<mpq_class> c = p.c;
  c.resize(H + 1);
  return c;
}

// The same for integer coefficients (Bareiss): the value for c scaled by L is L^(2n-1-2j) times the one for c.
inline mpz_class subresultant_at(const std::vector<mpz_class>& c, int j, int i) {
  const int n = int(c.size()) - 1, m = n - 1;
  std::vector<mpz_class> d;
  for (int k = 1; k <= n; ++k) d.push_back(k * c[std::size_t(k)]);
  const int rows = n + m - 2 * j, top = n + m - j - 1;
  std::vector<std::vector<mpz_class>> sq(static_cast<std::size_t>(rows),
                                         std::vector<mpz_class>(static_cast<std::size_t>(rows)));
  for (int r = 0; r < rows; ++r) {
    const bool is_f = r < m - j;
    const std::vector<mpz_class>& p = is_f ? c : d;
    const int shift = is_f ? (m - j - 1 - r) : (n - j - 1 - (r - (m - j)));
    auto coeff = [&](int power) {
      const int k = power - shift;
      return (k >= 0 && k < int(p.size())) ? p[std::size_t(k)] : mpz_class(0);
    };
    for (int col = 0; col + 1 < rows; ++col) sq[std::size_t(r)][std::size_t(col)] = coeff(top - col);
    sq[std::size_t(r)][std::size_t(rows - 1)] = coeff(i);
  }
  return determinant(sq);
}
inline mpz_class cubic_discriminant_at(const std::vector<mpz_class>& g) {
  const mpz_class &a = g[3], &b = g[2], &c = g[1], &d = g[0];
  return 18 * a * b * c * d - 4 * b * b * b * d + b * b * c * c - 4 * a * c * c * c - 27 * a * a * d * d;
}

// The subresultant coefficient s(j, i) of S_j(f, f') for f = Σ c_k λ^k of
// degree n (c.size() = n + 1, c[n] ≠ 0 not required): the determinant of the
// n + m - 2j rows x^(m-j-1) f, ..., f, x^(n-j-1) f', ..., f' (m = n - 1)
// restricted to the columns of λ^(n+m-j-1) .. λ^(j+1) and that of λ^i.
inline mpq_class subresultant_at(const std::vector<mpq_class>& c, int j, int i) {
  const int n = int(c.size()) - 1, m = n - 1;
  std::vector<mpq_class> d;
  for (int k = 1; k <= n; ++k) d.push_back(mpq_class(k) * c[std::size_t(k)]);
  const int rows = n + m - 2 * j, top = n + m - j - 1;
  QMatrix sq(static_cast<std::size_t>(rows), std::vector<mpq_class>(static_cast<std::size_t>(rows)));
  for (int r = 0; r < rows; ++r) {
    const bool is_f = r < m - j;
    const std::vector<mpq_class>& p = is_f ? c : d;
    const int shift = is_f ? (m - j - 1 - r) : (n - j - 1 - (r - (m - j)));
    auto coeff = [&](int power) {
      const int k = power - shift;
      return (k >= 0 && k < int(p.size())) ? p[std::size_t(k)] : mpq_class(0);
    };
    for (int col = 0; col + 1 < rows; ++col) sq[std::size_t(r)][std::size_t(col)] = coeff(top - col);
    sq[std::size_t(r)][std::size_t(rows - 1)] = coeff(i);
  }
  return determinant(sq);
}

// The discriminant of the quartic a λ⁴ + b λ³ + c λ² + d λ + e, by its
// closed form (Res(f, f') = a · disc f for a quartic).
inline mpz_class quartic_discriminant_at(const std::vector<mpz_class>& g) {
  const mpz_class &a = g[4], &b = g[3], &c = g[2], &d = g[1], &e = g[0];
  const mpz_class a2 = a * a, b2 = b * b, c2 = c * c, d2 = d * d, e2 = e * e;
  return 256 * a2 * a * e2 * e - 192 * a2 * b * d * e2 - 128 * a2 * c2 * e2 + 144 * a2 * c * d2 * e -
         27 * a2 * d2 * d2 + 144 * a * b2 * c * e2 - 6 * a * b2 * d2 * e - 80 * a * b * c2 * d * e +
         18 * a * b * c * d2 * d + 16 * a * c2 * c2 * e - 4 * a * c2 * c * d2 - 27 * b2 * b2 * e2 +
         18 * b2 * b * c * d * e - 4 * b2 * b * d2 * d - 4 * b2 * c2 * c * e + b2 * c2 * d2;
}

// The discriminant of the cubic a λ³ + b λ² + c λ + d.
inline mpq_class cubic_discriminant_at(const std::vector<mpq_class>& g) {
  const mpq_class &a = g[3], &b = g[2], &c = g[1], &d = g[0];
  return 18 * a * b * c * d - 4 * b * b * b * d + b * b * c * c - 4 * a * c * c * c - 27 * a * a * d * d;
}

}  // namespace eccd::check
