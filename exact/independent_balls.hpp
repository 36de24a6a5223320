#pragma once
// Exact answers of independent motions (paper 001 section 4) in the case
// where the projection is cheap: two balls (3D) or two discs (2D) whose
// centres move on straight lines (static or "matrix" motions whose linear
// block is a constant multiple of the identity, with translations of degree
// <= 1). A disc's centre is a point of the plane z = 0 below; everything else
// is the same.
//
// Statement. The s-intervals are the maximal intervals of
//   P_s = { s in [0, 1] : A(s) meets B(t) for some t in [0, 1] }.
// The ends of P_s are among the extreme points of the curve F = F_u = 0 in
// the t-direction (F = F_u = F_t = 0) and its crossings of t = 0 and t = 1
// (paper 001 section 4). For two balls of radii r_A, r_B (R = r_A + r_B) with
// centres c_A(s) = a + s d_A and c_B(t) = b + t d_B, A(s) and B(t) meet iff
// h(s, t) = |w(s) - t d_B|^2 - R^2 <= 0 with w = c_A(s) - b (the touching set
// F = F_u = 0 is h = 0), so that projection is explicit and needs no
// resultant: with g(s) = min over t in [0, 1] of h(s, t), attained at t*(s) =
// (w . d_B) / |d_B|^2 clamped to [0, 1], the ends of P_s are roots in [0, 1] of
//   h(s, 0), h(s, 1)                     (the extreme on t = 0 or t = 1),
//   D(s) = |w|^2 |d_B|^2 - (w . d_B)^2 - R^2 |d_B|^2   (h = h_t = 0, inside),
//   w . d_B and w . d_B - |d_B|^2        (where t* enters or leaves [0, 1]),
// all rational polynomials of degree <= 2. Their product's real roots in
// [0, 1] are isolated exactly (exact/algebraic_roots.hpp: disjoint rational
// brackets, one root each) and, with 0 and 1, cut [0, 1] into cells on which
// membership in P_s is constant. Each cell is decided at a rational sample by
// the caller's `meets_at` (api/solve.cpp: the exact shared-parameter pipeline
// on the scene with A fixed at A(sample) and B moving: does it collide?),
// and cross-checked with g(sample) <= 0 computed exactly here (a disagreement
// is an internal error, never an answer). A candidate point belongs to P_s if
// a neighbouring cell does (P_s is closed); otherwise iff g = 0 there, decided
// by exact signs at the algebraic number (sign_at). The t-intervals are the
// same with the roles of A and B exchanged. Every end is a certified bracket.
// Any other pair of independent motions is refused (ball_path returns
// nothing): the general projection by resultants of F, F_u, F_t is not
// implemented.
// Requirements: exact rationals throughout (no double on the way to a
// decision); algebraic numbers from exact/algebraic_roots.hpp.
#include "exact/algebraic_roots.hpp"
#include "kernel/answer.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <functional>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace eccd {

struct BallPath {
  Rational radius;                // r (rational)
  std::array<Rational, 3> c0, d;  // centre c0 + s d
};

namespace balls_detail {
inline std::optional<Rational> rational_sqrt(const Rational& q) {
  if (sgn(q) <= 0) return std::nullopt;
  mpz_class n = q.get_num(), d = q.get_den();
  if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return std::nullopt;
  mpz_class rn, rd;
  mpz_sqrt(rn.get_mpz_t(), n.get_mpz_t());
  mpz_sqrt(rd.get_mpz_t(), d.get_mpz_t());
  return Rational(rn, rd);
}
}  // namespace balls_detail

// The ball (disc) and its straight path, if the object is one: a shape
// diag(k, .., k, -m) (dim + 1 entries) with k, m > 0 and m/k a rational square,
// and a static motion or a matrix motion [[c I, p(s)], [0, c]] with c a
// non-zero constant and p of degree <= 1.
inline std::optional<BallPath> ball_path(const SceneObject& o) {
  const auto& Q = o.Q;
  if (Q.size() != 4 && Q.size() != 3) return std::nullopt;
  const int D = int(Q.size()) - 1;
  for (int i = 0; i <= D; ++i)
    for (int j = 0; j <= D; ++j)
      if (i != j && sgn(Q[i][j]) != 0) return std::nullopt;
  for (int i = 1; i < D; ++i)
    if (Q[i][i] != Q[0][0]) return std::nullopt;
  if (sgn(Q[0][0]) <= 0 || sgn(Q[D][D]) >= 0) return std::nullopt;
  const auto r = balls_detail::rational_sqrt(Rational(-Q[D][D] / Q[0][0]));
  if (!r) return std::nullopt;
  BallPath b;
  b.radius = *r;
  b.c0 = b.d = {Rational(0), Rational(0), Rational(0)};
  if (std::holds_alternative<StaticMotion>(o.motion)) return b;
  const auto* m = std::get_if<MatrixMotion>(&o.motion);
  if (!m || int(m->m.size()) != D + 1) return std::nullopt;
  auto constant = [](const RPoly& p, Rational& v) {
    if (p.degree() > 0) return false;
    v = p.is_zero() ? Rational(0) : p.c[0];
    return true;
  };
  Rational c;
  if (!constant(m->m[D][D], c) || sgn(c) == 0) return std::nullopt;
  for (int i = 0; i < D; ++i) {
    for (int j = 0; j < D; ++j) {
      Rational v;
      if (!constant(m->m[i][j], v) || v != (i == j ? c : Rational(0))) return std::nullopt;
    }
    const RPoly& p = m->m[i][D];
    if (p.degree() > 1) return std::nullopt;
    b.c0[i] = p.is_zero() ? Rational(0) : Rational(p.c[0] / c);
    b.d[i] = p.degree() == 1 ? Rational(p.c[1] / c) : Rational(0);
  }
  return b;
}

// The maximal intervals of P_s for ball A on its path (parameter s) against
// ball B on its path (t in [0, 1]); meets_at(s0) decides a rational s0.
inline std::vector<std::pair<Instant, Instant>> ball_projection(const BallPath& A, const BallPath& B,
                                                                const std::function<bool(const Rational&)>& meets_at) {
  const Rational R = A.radius + B.radius, R2 = R * R;
  // w(s) = (a - b) + s d_A as three linear polynomials
  std::array<RPoly, 3> w;
  Rational dd = 0;  // |d_B|^2
  for (int i = 0; i < 3; ++i) {
    w[i] = RPoly(std::vector<Rational>{Rational(A.c0[i] - B.c0[i]), A.d[i]});
    dd += B.d[i] * B.d[i];
  }
  auto dot = [](const std::array<RPoly, 3>& x, const std::array<RPoly, 3>& y) {
    RPoly s;
    for (int i = 0; i < 3; ++i) s = s + x[i] * y[i];
    return s;
  };
  std::array<RPoly, 3> w1, dB;
  for (int i = 0; i < 3; ++i) {
    dB[i] = RPoly::constant(B.d[i]);
    w1[i] = w[i] - dB[i];
  }
  const RPoly h0 = dot(w, w) - RPoly::constant(R2), h1 = dot(w1, w1) - RPoly::constant(R2);
  const RPoly lin = dot(w, dB);  // t* |d_B|^2
  const RPoly D = dot(w, w) * RPoly::constant(dd) - lin * lin - RPoly::constant(R2 * dd);
  const RPoly l1 = lin - RPoly::constant(dd);
  const bool moving = sgn(dd) != 0;
  std::vector<RPoly> cands{h0};
  if (moving) cands.insert(cands.end(), {h1, D, lin, l1});
  RPoly prod = RPoly::constant(Rational(1));
  for (const auto& p : cands)
    if (p.degree() >= 1) prod = prod * p;
  // g(s0) <= 0 exactly at a rational s0; g(r) == 0 at an algebraic r
  auto g_nonpositive = [&](const Rational& s0) {
    if (!moving) return sgn(h0(s0)) <= 0;
    const Rational l = lin(s0);
    if (sgn(l) <= 0) return sgn(h0(s0)) <= 0;
    if (l >= dd) return sgn(h1(s0)) <= 0;
    return sgn(D(s0)) <= 0;
  };
  auto g_zero_at = [&](const AlgebraicRoot& r) {
    if (!moving) return sign_at(h0, r) == Sign::zero;
    const Sign sl = sign_at(lin, r), s1 = sign_at(l1, r);
    if (sl != Sign::positive) return sign_at(h0, r) == Sign::zero;
    if (s1 != Sign::negative) return sign_at(h1, r) == Sign::zero;
    return sign_at(D, r) == Sign::zero;
  };
  std::vector<AlgebraicRoot> pts;
  pts.push_back(AlgebraicRoot{Rational(0), Rational(0), 1, nullptr});
  if (prod.degree() >= 1)
    for (auto& r : real_roots(prod, Rational(0), Rational(1)))
      if (!(r.is_rational() && (sgn(r.lo) == 0 || r.lo == 1))) pts.push_back(r);
  pts.push_back(AlgebraicRoot{Rational(1), Rational(1), 1, nullptr});
  // cells between consecutive points
  std::vector<bool> cell_in;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Rational sample = (pts[i].hi + pts[i + 1].lo) / 2;
    const bool in = meets_at(sample);
    if (in != g_nonpositive(sample))
      throw std::logic_error(
          "independent balls: the shared-parameter pipeline and the explicit distance disagree at s = " +
          sample.get_str());
    cell_in.push_back(in);
  }
  std::vector<bool> pt_in;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const bool left = i > 0 && cell_in[i - 1], right = i < cell_in.size() && cell_in[i];
    pt_in.push_back(left || right || g_zero_at(pts[i]));
  }
  auto instant = [](const AlgebraicRoot& r) { return bracketed_instant(Rational((r.lo + r.hi) / 2), r.lo, r.hi); };
  std::vector<std::pair<Instant, Instant>> out;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!pt_in[i]) continue;
    std::size_t j = i;
    while (j + 1 < pts.size() && cell_in[j] && pt_in[j + 1]) ++j;
    out.emplace_back(instant(pts[i]), instant(pts[j]));
    i = j;
  }
  return out;
}

}  // namespace eccd
