#pragma once
// Tensor Bernstein nets in three variables (u, s, t) on [0, 1]^3, written for
// the checker of independent-motion certificates alone (certificate/check/
// independent_certificate.cpp), and the claim that such a net is the
// function F of a scene.
//
// Statement. Farin, "Curves and Surfaces for CAGD", chapters 5 and 16: a net
// p(u, s, t) = Σ c_ijk B_i^l(u) B_j^m(s) B_k^n(t) is restricted to a box by de
// Casteljau's algorithm along each axis (certificate/check/bernstein.hpp's
// keep_right / keep_left on the lines of that axis); by the convex hull
// property control points of one strict sign prove that sign on the box, and
// the hull of the control points encloses every value there. The derivative
// along an axis of a net on a box of side h there is (deg / h)(c_{k+1} - c_k).
// With T an outward-rounding interval type (certificate/check/interval.hpp)
// every computed control point encloses the exact one; with T = mpq_class
// everything is exact.
// The net claim (paper 001, section 4): F(u, s, t) = det((1 - u) A(s) + u B(t))
// with A = N_a^T Q_a N_a, B = N_b^T Q_b N_b, from a stated shape (a positive
// multiple of the scene's Q, with det Q < 0) and a stated inverse motion
// (N(x) M(x) = c(x) I, c free of roots in [0, 1], by Sturm; then A(x) is the
// moving solid times c(x)^2 > 0 and det A(x) = det(N)^2 det Q < 0, so F < 0 on
// the faces u = 0 and u = 1). Two polynomials of degrees at most (H, Ds, Dt)
// that agree on the integer grid {0..H} x {0..Ds} x {0..Dt} are equal, so the
// net is compared with det(...) there (values of the net: Bernstein basis at
// integers, exactly). A body that does not move as a set, A(x) = c(x) A(0),
// is checked at 2 deg N + 1 integers (both sides of degree <= 2 deg N); then
// c has no root in [0, 1] (det A(x) = c^H det A(0) ≠ 0) and c(0) = 1, so
// c > 0, and the net may be F with A(0) in place of A(x): F(u, x, .) has the
// sign of that net at u' = u / ((1 - u) c + u), an increasing map of [0, 1]
// onto itself (kernel's hold_still says the same for the writer).
// Requirements: GMP; the scene as read by certificate/check/scene.hpp.
#include "certificate/check/bernstein.hpp"
#include "certificate/check/claims.hpp"
#include "certificate/check/pencil.hpp"
#include "certificate/check/scene.hpp"

#include <array>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace eccd::check {

template <class T>
struct Net3 {
  std::array<int, 3> n{};  // degrees in u, s, t
  std::vector<T> c;        // c[(i (n[1] + 1) + j) (n[2] + 1) + k]
  std::size_t stride(int axis) const {
    return axis == 2 ? 1 : axis == 1 ? std::size_t(n[2] + 1) : std::size_t(n[1] + 1) * (n[2] + 1);
  }
  std::size_t index(int i, int j, int k) const { return (std::size_t(i) * (n[1] + 1) + j) * (n[2] + 1) + k; }
  const T& at(int i, int j, int k) const { return c[index(i, j, k)]; }
  T& at(int i, int j, int k) { return c[index(i, j, k)]; }
  bool line_start(std::size_t b, int axis) const { return (b / stride(axis)) % std::size_t(n[axis] + 1) == 0; }
  int strict_sign() const {
    const int s = c.empty() ? 0 : c[0].sign();
    for (const auto& x : c)
      if (x.sign() != s) return 0;
    return s;
  }
  T hull() const {
    T h = c[0];
    for (const auto& x : c) h = h.hull(x);
    return h;
  }
};

// The net restricted to [a, b] along `axis` (a != 1; outside [0, 1] too: an identity of polynomials), reparameterised
// to [0, 1].
template <class T, class Make>
Net3<T> restrict3(const Net3<T>& f, int axis, const mpq_class& a, const mpq_class& b, Make&& make) {
  if (a == 1) throw std::domain_error("a box starting at 1 cannot be restricted to");
  Net3<T> r = f;
  const bool cut_left = sgn(a) != 0, cut_right = b != 1;
  if ((!cut_left && !cut_right) || f.n[axis] == 0) return r;
  const T ta = make(a), tb = make(cut_right ? mpq_class((b - a) / (1 - a)) : mpq_class(1));
  for (std::size_t base = 0; base < f.c.size(); ++base) {
    if (!f.line_start(base, axis)) continue;
    if (cut_left) keep_right(r.c, base, f.stride(axis), f.n[axis], ta);
    if (cut_right) keep_left(r.c, base, f.stride(axis), f.n[axis], tb);
  }
  return r;
}

// The two halves along `axis` (`half` is 1/2 in T).
template <class T>
std::pair<Net3<T>, Net3<T>> split3(const Net3<T>& f, int axis, const T& half) {
  std::pair<Net3<T>, Net3<T>> r{f, f};
  if (f.n[axis] == 0) return r;
  for (std::size_t base = 0; base < f.c.size(); ++base) {
    if (!f.line_start(base, axis)) continue;
    keep_left(r.first.c, base, f.stride(axis), f.n[axis], half);
    keep_right(r.second.c, base, f.stride(axis), f.n[axis], half);
  }
  return r;
}

// The derivative along `axis` of a net on a box whose side there is `side` (1 for [0, 1]); a constant gives 0.
template <class T, class Make>
Net3<T> deriv3(const Net3<T>& f, int axis, const mpq_class& side, Make&& make) {
  Net3<T> r;
  r.n = f.n;
  const int deg = f.n[axis];
  r.n[axis] = std::max(deg - 1, 0);
  if (deg == 0) {
    r.c.assign(f.c.size(), make(mpq_class(0)));
    return r;
  }
  const T k = make(mpq_class(mpq_class(deg) / side));
  for (int i = 0; i <= r.n[0]; ++i)
    for (int j = 0; j <= r.n[1]; ++j)
      for (int l = 0; l <= r.n[2]; ++l) {
        std::array<int, 3> b{i, j, l};
        ++b[axis];
        r.c.push_back(k * (f.at(b[0], b[1], b[2]) - f.at(i, j, l)));
      }
  return r;
}

// The value at the box's centre (1/2, 1/2, 1/2): de Casteljau along each axis, the first point of each line.
template <class T>
T centre_value(Net3<T> f, const T& half) {
  for (int axis = 2; axis >= 0; --axis)
    for (std::size_t base = 0; base < f.c.size(); ++base)
      if (f.line_start(base, axis)) keep_right(f.c, base, f.stride(axis), f.n[axis], half);
  return f.c[0];
}

// The face t = 0 (end 0) or t = 1 (end 1): a net of degree 0 in t.
template <class T>
Net3<T> t_face(const Net3<T>& f, int end) {
  Net3<T> r;
  r.n = {f.n[0], f.n[1], 0};
  for (int i = 0; i <= f.n[0]; ++i)
    for (int j = 0; j <= f.n[1]; ++j) r.c.push_back(f.at(i, j, end ? f.n[2] : 0));
  return r;
}

// s and t exchanged.
template <class T>
Net3<T> swap_st(const Net3<T>& f) {
  Net3<T> r;
  r.n = {f.n[0], f.n[2], f.n[1]};
  r.c.resize(f.c.size());
  for (int i = 0; i <= f.n[0]; ++i)
    for (int j = 0; j <= f.n[1]; ++j)
      for (int k = 0; k <= f.n[2]; ++k) r.at(i, k, j) = f.at(i, j, k);
  return r;
}

template <class T, class Make>
Net3<T> converted3(const Net3<mpq_class>& f, Make&& make) {
  Net3<T> r;
  r.n = f.n;
  r.c.reserve(f.c.size());
  for (const auto& x : f.c) r.c.push_back(make(x));
  return r;
}

// F_t / t (end 0) or F_t / (1 - t) (end 1) exactly, when F_t's net vanishes on that face: with d_k the
// coefficients of F_t (degree m), B^m_k / t = (m / k) B^{m-1}_{k-1} and B^m_k / (1 - t) = (m / (m - k)) B^{m-1}_k.
inline std::optional<Net3<mpq_class>> edge_quotient(const Net3<mpq_class>& F, int end) {
  const int n = F.n[2], m = n - 1;
  if (m < 1) return std::nullopt;
  const int k0 = end == 0 ? 0 : m;
  for (int i = 0; i <= F.n[0]; ++i)
    for (int j = 0; j <= F.n[1]; ++j)
      if (F.at(i, j, k0 + 1) != F.at(i, j, k0)) return std::nullopt;
  Net3<mpq_class> G;
  G.n = {F.n[0], F.n[1], m - 1};
  for (int i = 0; i <= F.n[0]; ++i)
    for (int j = 0; j <= F.n[1]; ++j)
      for (int k = 0; k < m; ++k) {
        const int kd = end == 0 ? k + 1 : k;
        const mpq_class d = mpq_class(n) * (F.at(i, j, kd + 1) - F.at(i, j, kd));
        G.c.push_back(d * (end == 0 ? mpq_class(m, kd) : mpq_class(m, m - kd)));
      }
  return G;
}

// A stated shape: an H x H matrix, a positive multiple of the scene's Q, with det < 0.
inline QMatrix stated_shape_h(const json& j, const std::string& place, const QMatrix& Q, std::size_t max_bits) {
  const std::size_t H = Q.size();
  const std::string want = place + ": expected a " + std::to_string(H) + " x " + std::to_string(H) + " matrix";
  if (!j.is_array() || j.size() != H) reject("certificate format", want);
  QMatrix S(H, std::vector<mpq_class>(H));
  std::optional<mpq_class> lambda;
  for (std::size_t r = 0; r < H; ++r) {
    if (!j[r].is_array() || j[r].size() != H) reject("certificate format", want);
    for (std::size_t c = 0; c < H; ++c) {
      S[r][c] = rational(j[r][c], place + "[" + std::to_string(r) + "][" + std::to_string(c) + "]", max_bits);
      if (!lambda && sgn(Q[r][c]) != 0) lambda = S[r][c] / Q[r][c];
    }
  }
  if (!lambda || sgn(*lambda) <= 0) reject("net", place + " is not a positive multiple of the scene's shape");
  for (std::size_t r = 0; r < H; ++r)
    for (std::size_t c = 0; c < H; ++c)
      if (S[r][c] != *lambda * Q[r][c]) reject("net", place + " is not a positive multiple of the scene's shape");
  if (sgn(determinant(S)) >= 0) reject("net", place + ": det Q is not < 0 (not an ellipse or ellipsoid)");
  return S;
}

// A stated inverse motion: N(x) M(x) = c(x) I with c free of roots in [0, 1] (Sturm).
inline PolyMatrix stated_inverse_h(const json& j, const std::string& place, const PolyMatrix& M, std::size_t max_bits) {
  const std::size_t H = M.size();
  const std::string want =
      place + ": expected a " + std::to_string(H) + " x " + std::to_string(H) + " matrix of polynomials";
  if (!j.is_array() || j.size() != H) reject("certificate format", want);
  PolyMatrix N(H, std::vector<QPoly>(H));
  for (std::size_t r = 0; r < H; ++r) {
    if (!j[r].is_array() || j[r].size() != H) reject("certificate format", want);
    for (std::size_t c = 0; c < H; ++c) {
      const json& p = j[r][c];
      const std::string pl = place + "[" + std::to_string(r) + "][" + std::to_string(c) + "]";
      if (!p.is_array() || p.size() > 65)
        reject("certificate format", pl + ": expected power-basis coefficients (degree at most 64)");
      std::vector<mpq_class> cs;
      for (std::size_t k = 0; k < p.size(); ++k)
        cs.push_back(rational(p[k], pl + "[" + std::to_string(k) + "]", max_bits));
      N[r][c] = QPoly(std::move(cs));
    }
  }
  const int D = matrix_degree(N) + matrix_degree(M);
  std::vector<mpq_class> cv;
  for (int k = 0; k <= D; ++k) {
    const QMatrix n = at_point(N, mpq_class(k)), m = at_point(M, mpq_class(k));
    for (std::size_t r = 0; r < H; ++r)
      for (std::size_t c = 0; c < H; ++c) {
        mpq_class x = 0;
        for (std::size_t l = 0; l < H; ++l) x += n[r][l] * m[l][c];
        if ((r != c && sgn(x) != 0) || (r == c && c > 0 && x != cv.back()))
          reject("net",
                 place + " times the scene's M(x) is not a multiple of the identity at x = " + std::to_string(k));
        if (r == c && c == 0) cv.push_back(x);
      }
  }
  const QPoly cpoly = interpolate_at_integers(cv);
  if (cpoly.zero() || sgn(cpoly(0)) == 0 || sgn(cpoly(1)) == 0 || roots_between(cpoly, 0, 1) != 0)
    reject("net", place + " times M(x) is c(x) I with c vanishing in [0, 1]: not an inverse motion there");
  return N;
}

// A(x) = c(x) A(0) as polynomial matrices (A = N^T Q N, checked at 2 deg N + 1 integers); false when not.
inline bool holds_still(const QMatrix& Q, const PolyMatrix& N) {
  const QMatrix A0 = moving_quadric(Q, N, mpq_class(0));
  std::size_t ri = 0, rj = 0;
  while (ri < A0.size() && sgn(A0[ri][rj]) == 0)
    if (++rj == A0.size()) rj = 0, ++ri;
  if (ri == A0.size()) return false;
  for (int k = 1; k <= 2 * matrix_degree(N); ++k) {
    const QMatrix A = moving_quadric(Q, N, mpq_class(k));
    const mpq_class c = A[ri][rj] / A0[ri][rj];
    for (std::size_t i = 0; i < A.size(); ++i)
      for (std::size_t j = 0; j < A.size(); ++j)
        if (A[i][j] != c * A0[i][j]) return false;
  }
  return true;
}

// The values of the net at the integer grid {0..H} x {0..Ds} x {0..Dt}, exactly: [i][j][k].
inline std::vector<std::vector<std::vector<mpq_class>>> net_on_grid(const Net3<mpq_class>& f, int Ds, int Dt) {
  // basis[x][k] = C(n, k) x^k (1 - x)^(n - k) at the integers x = 0..D
  auto basis = [](int n, int D) {
    std::vector<std::vector<mpz_class>> b(std::size_t(D + 1), std::vector<mpz_class>(std::size_t(n + 1)));
    for (int x = 0; x <= D; ++x) {
      mpz_class binom = 1;
      for (int k = 0; k <= n; ++k) {
        if (k > 0) binom = binom * (n - k + 1) / k;
        mpz_class p, q;
        mpz_ui_pow_ui(p.get_mpz_t(), (unsigned long)x, (unsigned long)k);
        mpz_pow_ui(q.get_mpz_t(), mpz_class(1 - x).get_mpz_t(), (unsigned long)(n - k));
        b[x][k] = binom * p * q;
      }
    }
    return b;
  };
  const int H = f.n[0];
  const auto bu = basis(f.n[0], H), bs = basis(f.n[1], Ds), bt = basis(f.n[2], Dt);
  // contract t, then s, then u
  std::vector<std::vector<std::vector<mpq_class>>> a(
      std::size_t(H + 1),
      std::vector<std::vector<mpq_class>>(std::size_t(f.n[1] + 1), std::vector<mpq_class>(std::size_t(Dt + 1))));
  for (int i = 0; i <= f.n[0]; ++i)
    for (int j = 0; j <= f.n[1]; ++j)
      for (int z = 0; z <= Dt; ++z)
        for (int k = 0; k <= f.n[2]; ++k) a[i][j][z] += f.at(i, j, k) * bt[z][k];
  std::vector<std::vector<std::vector<mpq_class>>> b(
      std::size_t(H + 1),
      std::vector<std::vector<mpq_class>>(std::size_t(Ds + 1), std::vector<mpq_class>(std::size_t(Dt + 1))));
  for (int i = 0; i <= f.n[0]; ++i)
    for (int y = 0; y <= Ds; ++y)
      for (int z = 0; z <= Dt; ++z)
        for (int j = 0; j <= f.n[1]; ++j) b[i][y][z] += a[i][j][z] * bs[y][j];
  std::vector<std::vector<std::vector<mpq_class>>> r(
      std::size_t(H + 1),
      std::vector<std::vector<mpq_class>>(std::size_t(Ds + 1), std::vector<mpq_class>(std::size_t(Dt + 1))));
  for (int x = 0; x <= H; ++x)
    for (int y = 0; y <= Ds; ++y)
      for (int z = 0; z <= Dt; ++z)
        for (int i = 0; i <= f.n[0]; ++i) r[x][y][z] += b[i][y][z] * bu[x][i];
  return r;
}

}  // namespace eccd::check
