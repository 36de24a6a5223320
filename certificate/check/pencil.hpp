#pragma once
// The pencil λA(t) - B(t) of a scene, by the checker's own route: values at
// rational points, never a symbolic expansion of f(λ; t).
//
// Statement (scene-format.md; design.md "use the adjugate"). The moving solid
// is A(t) = M(t)^-T Q M(t)^-1. The adjugate adj M(t) = det M(t) · M(t)^-1 is
// a polynomial matrix; the checker gets it by evaluating the cofactors of
// M(k) at the integers k = 0 .. (H - 1)·deg M and interpolating, divides out
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
// Also here: det M(t) has no root in [0, 1] (Sturm), and the determinant of a
// rational matrix (Gaussian elimination over Q).
// Requirements: GMP. Cost: O(D · H^4) rational operations for D points.
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
    if (p != c) { std::swap(m[p], m[c]); det = -det; }
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

// adj(M) / gcd of its entries, by evaluation at integers and interpolation.
inline PolyMatrix primitive_inverse(const PolyMatrix& M) {
  const std::size_t H = M.size();
  const int D = int(H - 1) * matrix_degree(M);
  std::vector<std::vector<std::vector<mpq_class>>> vals(H, std::vector<std::vector<mpq_class>>(H));
  for (int k = 0; k <= D; ++k) {
    const QMatrix m = at_point(M, mpq_class(k));
    for (std::size_t i = 0; i < H; ++i)
      for (std::size_t j = 0; j < H; ++j) {
        // adj[i][j] = (-1)^(i+j) det(minor without row j and column i)
        QMatrix minor;
        for (std::size_t r = 0; r < H; ++r) {
          if (r == j) continue;
          std::vector<mpq_class> row;
          for (std::size_t c = 0; c < H; ++c)
            if (c != i) row.push_back(m[r][c]);
          minor.push_back(row);
        }
        mpq_class v = H == 1 ? mpq_class(1) : determinant(minor);
        vals[i][j].push_back((i + j) % 2 ? mpq_class(-v) : v);
      }
  }
  PolyMatrix N(H, std::vector<QPoly>(H));
  QPoly g;
  for (std::size_t i = 0; i < H; ++i)
    for (std::size_t j = 0; j < H; ++j) {
      N[i][j] = interpolate_at_integers(vals[i][j]);
      if (!N[i][j].zero()) g = g.zero() ? mpq_class(1 / N[i][j].lead()) * N[i][j] : gcd(g, N[i][j]);
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

// det M(t) as a polynomial (evaluation and interpolation).
inline QPoly motion_determinant(const PolyMatrix& M) {
  const int D = int(M.size()) * matrix_degree(M);
  std::vector<mpq_class> v;
  for (int k = 0; k <= D; ++k) v.push_back(determinant(at_point(M, mpq_class(k))));
  return interpolate_at_integers(v);
}

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
using ZPolyMatrix = std::vector<std::vector<std::vector<mpz_class>>>;

inline ZPolyMatrix integer_matrix(const PolyMatrix& m) {
  mpz_class l = 1;
  for (const auto& row : m)
    for (const auto& e : row) l = denominator_lcm(e, l);
  ZPolyMatrix r;
  for (const auto& row : m) {
    r.emplace_back();
    for (const auto& e : row) r.back().push_back(integer_multiple(e, l));
  }
  return r;
}
inline ZMatrix integer_matrix(const QMatrix& m) {
  mpz_class l = 1;
  for (const auto& row : m)
    for (const auto& e : row) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), e.get_den_mpz_t());
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
inline std::vector<mpz_class> pencil_coefficients(const ZMatrix& A, const ZMatrix& B) {
  const std::size_t H = A.size();
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
  std::vector<std::vector<mpz_class>> sq(static_cast<std::size_t>(rows), std::vector<mpz_class>(static_cast<std::size_t>(rows)));
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
  return 256 * a2 * a * e2 * e - 192 * a2 * b * d * e2 - 128 * a2 * c2 * e2 + 144 * a2 * c * d2 * e - 27 * a2 * d2 * d2 +
         144 * a * b2 * c * e2 - 6 * a * b2 * d2 * e - 80 * a * b * c2 * d * e + 18 * a * b * c * d2 * d + 16 * a * c2 * c2 * e -
         4 * a * c2 * c * d2 - 27 * b2 * b2 * e2 + 18 * b2 * b * c * d * e - 4 * b2 * b * d2 * d - 4 * b2 * c2 * c * e + b2 * c2 * d2;
}

// The discriminant of the cubic a λ³ + b λ² + c λ + d.
inline mpq_class cubic_discriminant_at(const std::vector<mpq_class>& g) {
  const mpq_class &a = g[3], &b = g[2], &c = g[1], &d = g[0];
  return 18 * a * b * c * d - 4 * b * b * b * d + b * b * c * c - 4 * a * c * c * c - 27 * a * a * d * d;
}

}  // namespace eccd::check
