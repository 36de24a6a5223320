#pragma once
// Continuous collision detection of two ellipsoids whose relative motion is a
// translation along a straight line (constant orientations, translations of
// degree at most 1 in t), by the contact function of Perram and Wertheim,
// with the roots in t in closed form and a few Newton steps in λ.
//
// Statement (Perram and Wertheim 1985, docs/references.md "Other sources";
// the same pencil as 001 section 4 and 002 section 3, read through Σ = S^-1).
// An ellipsoid with centre c and shape S (x − c)ᵀS(x − c) <= 1 has Σ = S^-1.
// For two of them with d = c_b − c_a and G(λ) = (1 − λ)Σ_a + λΣ_b,
//   H(λ, t) = λ(1 − λ) dᵀ adj(G(λ)) d − det G(λ)
// is det G (K − 1) with K Perram and Wertheim's contact function, so the
// closed ellipsoids are separate at t iff H(λ, t) > 0 for some λ in (0, 1).
// When d(t) = p + t w is linear and Σ_a, Σ_b are constant (both bodies keep
// their orientation), H has degree 4 in λ and 2 in t, with the t² coefficient
// λ(1 − λ) wᵀ adj(G) w >= 0: for each λ the instants where H(λ, ·) <= 0 form
// an interval [t₋(λ), t₊(λ)] (the roots of a quadratic), and the collision set
// on the whole line of times is their intersection [max t₋, min t₊] (one
// interval, possibly empty: d(t) runs along a line through the convex
// Minkowski sum). The first and last contacts are found by Newton's method on
// g(λ) = H_λ(λ, t±(λ)) from the best of a grid of λ (each step a closed-form
// root in t), a miss by the λ that maximises min_t H(λ, t).
//
// What is proved, and how (Bounded<T>; plain T takes the same signs plainly).
// Every claim rests on a sign of an expression evaluated at chosen points (λ,
// t, x: exact doubles) from the scene's exact numbers rounded once, so its
// error bound holds against the exact value at those points:
//  - separate on [a, b] with witness λ: H(λ, ·) is convex (its t² coefficient
//    is >= 0 exactly, G(λ) being positive definite), so it lies above its
//    tangent at any t_c; both ends of that tangent line on [a, b] positive
//    proves H(λ, t) > 0 on [a, b];
//  - overlapping at t: a point x with (x − c)ᵀ adj(Σ) (x − c) < det Σ for
//    both bodies (x = c_a + (1 − λ)Σ_a G(λ)^-1 d, the point of the contact
//    function, at the λ where both quadratic forms are equal);
//  - overlapping on [t1, t2] from overlap at t1 and t2: the collision set is
//    one interval.
// An interval end e is reported when separation is proved up to e − δ and
// overlap from e + δ (δ at most 2^-24, well inside the harness's tolerance);
// a start or end clamped to 0 or 1 needs overlap proved there; an end inside
// (0, 1) is also a contact (the bodies touch externally as they meet or part).
// When any proof
// fails (a touch, a graze, a miss too narrow for the grid, a start within δ of
// contact, an unsure sign), translation_ccd returns nothing and the caller
// runs the general Bézier method (floating/bezier_ccd.hpp) instead.
// Requirements on T: double or Bounded<double> (the search runs on the plain
// values, which are the same in both faces; the proofs use T).
// The contact points of the answer (display only) are the contact function's
// points at the ends found, with A's outward normal along G(λ)^-1 d.
// Cost: a few hundred floating operations for the set-up (one 3x3 adjugate
// per body and of the pencil), a grid of 24 closed-form roots, about five
// Newton steps per end, and two or three proofs; no allocation after the
// scene's numbers are read.
#include "kernel/answer.hpp"
#include "kernel/motion.hpp"
#include "kernel/scene.hpp"
#include "number/running_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eccd {

namespace translation_detail {

template <class T>
using M3 = std::array<std::array<T, 3>, 3>;
template <class T>
using V3 = std::array<T, 3>;

inline double plain(double x) { return x; }
inline double plain(const Bounded<double>& x) { return x.value(); }
template <class T>
T point(double x) {
  if constexpr (has_error_bound_v<T>)
    return T(x, 0);
  else
    return x;
}
template <class T>
bool surely_positive(const T& x) {
  return scalar_traits<T>::sign(x) == Sign::positive;
}

// The constant coefficient of p, or its t coefficient (k = 1); zero past its degree.
template <class T>
T coef(const Poly<T>& p, int k) {
  return int(p.c.size()) > k ? p.c[k] : T(0);
}

template <class T>
M3<T> adjugate3(const M3<T>& g) {
  M3<T> a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      a[i][j] = g[(j + 1) % 3][(i + 1) % 3] * g[(j + 2) % 3][(i + 2) % 3] -
                g[(j + 1) % 3][(i + 2) % 3] * g[(j + 2) % 3][(i + 1) % 3];
  return a;
}
template <class T>
T det3(const M3<T>& g, const M3<T>& adj) {
  return g[0][0] * adj[0][0] + g[0][1] * adj[1][0] + g[0][2] * adj[2][0];
}
template <class T>
T quad_form(const M3<T>& m, const V3<T>& x, const V3<T>& y) {
  T s = T(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += x[i] * (m[i][j] * y[j]);
  return s;
}

// A body of a translating pair in the world frame: Σ (with adjugate and
// determinant, for membership) and its centre c0 + t c1.
template <class T>
struct Body {
  M3<T> sigma, adj;
  T det;
  V3<T> c0, c1;
};

// Whether a polynomial's degree is at most k (the exact scene's numbers).
inline bool degree_at_most(const RPoly& p, int k) { return p.degree() <= k; }

// The scene object's motion as x = L x_b + τ0 + t τ1 (L constant), or false.
template <class T, class Conv>
bool affine_translation(const Motion& motion, Conv conv, M3<T>& L, V3<T>& t0, V3<T>& t1) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) L[i][j] = T(i == j ? 1 : 0);
    t0[i] = T(0);
    t1[i] = T(0);
  }
  if (std::holds_alternative<StaticMotion>(motion)) return true;
  if (const auto* e = std::get_if<EulerMotion>(&motion)) {
    for (const RPoly& q : e->e)
      if (!degree_at_most(q, 0)) return false;
    for (const RPoly& v : e->v)
      if (!degree_at_most(v, 1)) return false;
    if (e->v3.degree() != 0) return false;
    const EulerParts<T> x = euler_parts<T>(*e, conv);  // R' = E R, x_world = R' x_b / E + v / v3
    const T E = coef(x.E, 0), v3 = coef(x.v3, 0);
    if (!(plain(E) > 0) || plain(v3) == 0) return false;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) L[i][j] = coef(x.r[i][j], 0) / E;
      t0[i] = coef(x.v[i], 0) / v3;
      t1[i] = coef(x.v[i], 1) / v3;
    }
    return true;
  }
  if (const auto* m = std::get_if<MatrixMotion>(&motion)) {
    if (m->m.size() != 4) return false;
    for (int j = 0; j < 3; ++j)
      if (!m->m[3][j].is_zero()) return false;
    if (m->m[3][3].degree() != 0) return false;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        if (!degree_at_most(m->m[i][j], 0)) return false;
      if (!degree_at_most(m->m[i][3], 1)) return false;
    }
    const T w = conv(m->m[3][3].c[0]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) L[i][j] = (m->m[i][j].is_zero() ? T(0) : conv(m->m[i][j].c[0])) / w;
      const RPoly& tau = m->m[i][3];
      t0[i] = (tau.degree() >= 0 ? conv(tau.c[0]) : T(0)) / w;
      t1[i] = (tau.degree() >= 1 ? conv(tau.c[1]) : T(0)) / w;
    }
    return true;
  }
  return false;
}

// Body of a scene object in T, or nothing when its motion is not a translation of degree <= 1 or its shape
// is not read as an ellipsoid in the plain values.
template <class T>
std::optional<Body<T>> translating_body(const SceneObject& o, const T& like) {
  auto conv = [&](const Rational& q) { return scalar_traits<T>::from_rational(q, like); };
  M3<T> L;
  V3<T> t0, t1;
  if (o.Q.size() != 4 || !affine_translation<T>(o.motion, conv, L, t0, t1)) return std::nullopt;
  M3<T> S;
  V3<T> s;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) S[i][j] = conv(o.Q[i][j]);
    s[i] = conv(o.Q[i][3]);
  }
  const T sigma0 = conv(o.Q[3][3]);
  const M3<T> adjS = adjugate3(S);
  const T detS = det3(S, adjS);
  if (!(plain(detS) > 0) || !(plain(S[0][0]) > 0)) return std::nullopt;
  V3<T> c;  // the body's centre: −S^-1 s
  for (int i = 0; i < 3; ++i) c[i] = -((adjS[i][0] * s[0] + adjS[i][1] * s[1] + adjS[i][2] * s[2]) / detS);
  const T rho = -(s[0] * c[0] + s[1] * c[1] + s[2] * c[2]) - sigma0;  // (x − c)ᵀ S (x − c) <= rho
  if (!(plain(rho) > 0)) return std::nullopt;
  Body<T> b;
  M3<T> LS;  // L Σ_body, Σ_body = rho S^-1
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T acc = T(0);
      for (int k = 0; k < 3; ++k) acc += L[i][k] * adjS[k][j];
      LS[i][j] = acc * rho / detS;
    }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      T acc = T(0);
      for (int k = 0; k < 3; ++k) acc += LS[i][k] * L[j][k];
      b.sigma[i][j] = acc;
    }
    T acc = T(0);
    for (int k = 0; k < 3; ++k) acc += L[i][k] * c[k];
    b.c0[i] = acc + t0[i];
    b.c1[i] = t1[i];
  }
  b.adj = adjugate3(b.sigma);
  b.det = det3(b.sigma, b.adj);
  return b;
}

}  // namespace translation_detail

// The pair, prepared once: both bodies and H's coefficients, H(λ, t) =
// Σ_k t^k Σ_j h[k][j] λ^j, in T and as plain doubles (hd) for the search.
template <class T>
struct TranslatingPair {
  translation_detail::Body<T> a, b;
  std::array<std::array<T, 5>, 3> h;
  std::array<std::array<double, 5>, 3> hd;
};

// The pair of a scene whose relative motion is a translation of degree <= 1, or nothing.
template <class T>
std::optional<TranslatingPair<T>> translating_pair(const Scene& scene, const T& like) {
  using namespace translation_detail;
  if (scene.dim != 3 || scene.independent) return std::nullopt;
  auto a = translating_body<T>(scene.a, like);
  if (!a) return std::nullopt;
  auto b = translating_body<T>(scene.b, like);
  if (!b) return std::nullopt;
  TranslatingPair<T> P{*a, *b, {}, {}};
  V3<T> p, w;
  for (int i = 0; i < 3; ++i) {
    p[i] = b->c0[i] - a->c0[i];
    w[i] = b->c1[i] - a->c1[i];
  }
  // adj(G0 + λ G1) = A0 + λ A1 + λ² A2 and det = g0 + g1 λ + g2 λ² + g3 λ³, G0 = Σ_a, G1 = Σ_b − Σ_a.
  M3<T> G0 = a->sigma, G1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) G1[i][j] = b->sigma[i][j] - a->sigma[i][j];
  M3<T> A[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int r1 = (j + 1) % 3, c1 = (i + 1) % 3, r2 = (j + 2) % 3, c2 = (i + 2) % 3;
      // (x1 + λ y1)(x2 + λ y2) − (x3 + λ y3)(x4 + λ y4)
      const T &x1 = G0[r1][c1], &y1 = G1[r1][c1], &x2 = G0[r2][c2], &y2 = G1[r2][c2];
      const T &x3 = G0[r1][c2], &y3 = G1[r1][c2], &x4 = G0[r2][c1], &y4 = G1[r2][c1];
      A[0][i][j] = x1 * x2 - x3 * x4;
      A[1][i][j] = (x1 * y2 + y1 * x2) - (x3 * y4 + y3 * x4);
      A[2][i][j] = y1 * y2 - y3 * y4;
    }
  T g[4] = {T(0), T(0), T(0), T(0)};
  for (int j = 0; j < 3; ++j) {  // det = Σ_j G_0j adj_j0
    g[0] += G0[0][j] * A[0][j][0];
    g[1] += G0[0][j] * A[1][j][0] + G1[0][j] * A[0][j][0];
    g[2] += G0[0][j] * A[2][j][0] + G1[0][j] * A[1][j][0];
    g[3] += G1[0][j] * A[2][j][0];
  }
  // λ(1 − λ)(q0 + q1 λ + q2 λ²) = q0 λ + (q1 − q0) λ² + (q2 − q1) λ³ − q2 λ⁴, for q = pᵀAp, 2pᵀAw, wᵀAw.
  for (int k = 0; k < 3; ++k) {
    T q[3];
    for (int i = 0; i < 3; ++i)
      q[i] = k == 0 ? quad_form(A[i], p, p) : k == 1 ? T(2) * quad_form(A[i], p, w) : quad_form(A[i], w, w);
    auto& hk = P.h[k];
    hk = {T(0), q[0], q[1] - q[0], q[2] - q[1], -q[2]};
    if (k == 0)
      for (int j = 0; j < 4; ++j) hk[j] -= g[j];
  }
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 5; ++j) P.hd[k][j] = plain(P.h[k][j]);
  return P;
}

// What translation_ccd found: the answer and its work, or nothing (the caller falls back).
struct TranslationResult {
  Answer answer;
  long newton_steps = 0, proofs = 0;
};

namespace translation_detail {

// The search, on plain doubles: h_k(λ) and its first two derivatives.
struct Hk {
  double v[3], d1[3], d2[3];
};
inline Hk eval_hk(const std::array<std::array<double, 5>, 3>& h, double l) {
  Hk r;
  for (int k = 0; k < 3; ++k) {
    const auto& c = h[k];
    r.v[k] = (((c[4] * l + c[3]) * l + c[2]) * l + c[1]) * l + c[0];
    r.d1[k] = ((4 * c[4] * l + 3 * c[3]) * l + 2 * c[2]) * l + c[1];
    r.d2[k] = (12 * c[4] * l + 6 * c[3]) * l + 2 * c[2];
  }
  return r;
}
// The roots t₋ <= t₊ of h2 t² + h1 t + h0 (a stable quadratic formula); false when there are none or h2 <= 0.
inline bool t_roots(const Hk& e, double& lo, double& hi) {
  const double a = e.v[2], b = e.v[1], c = e.v[0], disc = b * b - 4 * a * c;
  if (!(a > 0) || !(disc >= 0)) return false;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  const double r1 = q / a, r2 = q != 0 ? c / q : r1;
  lo = std::min(r1, r2);
  hi = std::max(r1, r2);
  return true;
}
// min over t of H(λ, t) (h2 > 0), the margin of λ as a witness for every t.
inline double line_margin(const Hk& e) { return e.v[0] - e.v[1] * e.v[1] / (4 * e.v[2]); }

// The first contact (upper = false: the λ maximising t₋) or the last (upper: minimising t₊), refined by
// Newton's method on H_λ(λ, t(λ)) = 0 inside [lo, hi]; false if a root in t went missing.
inline bool refine_end(const std::array<std::array<double, 5>, 3>& h, bool upper, double lo, double hi, double& lam,
                       double& t, long& steps) {
  for (int it = 0; it < 40; ++it) {
    const Hk e = eval_hk(h, lam);
    double r0, r1;
    if (!t_roots(e, r0, r1)) return false;
    t = upper ? r1 : r0;
    const double Hl = e.d1[0] + t * (e.d1[1] + t * e.d1[2]);
    const double Ht = e.v[1] + 2 * t * e.v[2];
    const double Hll = e.d2[0] + t * (e.d2[1] + t * e.d2[2]);
    const double Hlt = e.d1[1] + 2 * t * e.d1[2];
    if (Ht == 0) return false;
    const double dt = -Hl / Ht;        // t'(λ)
    const double g1 = Hll + Hlt * dt;  // d/dλ of H_λ(λ, t(λ))
    ++steps;
    double next = g1 != 0 ? lam - Hl / g1 : 0.5 * (lo + hi);
    if (!(next > lo)) next = 0.5 * (lam + lo);  // Newton left the bracket: halve towards its side
    if (!(next < hi)) next = 0.5 * (lam + hi);
    if (std::abs(next - lam) <= 1e-15 * std::max(1.0, std::abs(lam))) {
      lam = next;
      break;
    }
    lam = next;
  }
  const Hk e = eval_hk(h, lam);
  double r0, r1;
  if (!t_roots(e, r0, r1)) return false;
  t = upper ? r1 : r0;
  return true;
}

// H(λ, ·) > 0 on [a, b], proved in T by the tangent at t_c (the vertex of the convex quadratic, clamped).
template <class T>
bool separate_on(const TranslatingPair<T>& P, double lam, double a, double b) {
  const T L = point<T>(lam);
  T hk[3];
  for (int k = 0; k < 3; ++k) {
    const auto& c = P.h[k];
    hk[k] = (((c[4] * L + c[3]) * L + c[2]) * L + c[1]) * L + c[0];
  }
  const double h1 = plain(hk[1]), h2 = plain(hk[2]);
  const double tc = std::clamp(h2 > 0 ? -h1 / (2 * h2) : a, a, b);
  const T t = point<T>(tc);
  const T H = hk[0] + t * (hk[1] + t * hk[2]), Ht = hk[1] + T(2) * t * hk[2];
  return surely_positive(T(H + Ht * (point<T>(a) - t))) && surely_positive(T(H + Ht * (point<T>(b) - t)));
}

// y = G(λ)^-1 d and the two quadratic forms of the contact point x(λ) = c_a + (1 − λ)Σ_a y (plain doubles).
struct ContactPoint3 {
  double y[3], qa, qb;
};
template <class T>
ContactPoint3 contact_point(const TranslatingPair<T>& P, const double (&d)[3], double lam) {
  M3<double> G, Sa, Sb;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Sa[i][j] = plain(P.a.sigma[i][j]);
      Sb[i][j] = plain(P.b.sigma[i][j]);
      G[i][j] = (1 - lam) * Sa[i][j] + lam * Sb[i][j];
    }
  const M3<double> adj = adjugate3(G);
  const double det = det3(G, adj);
  ContactPoint3 r;
  for (int i = 0; i < 3; ++i) r.y[i] = (adj[i][0] * d[0] + adj[i][1] * d[1] + adj[i][2] * d[2]) / det;
  const V3<double> y{r.y[0], r.y[1], r.y[2]};
  r.qa = (1 - lam) * (1 - lam) * quad_form(Sa, y, y);
  r.qb = lam * lam * quad_form(Sb, y, y);
  return r;
}

// The body contains x at instant t, strictly, proved in T: (x − c)ᵀ adj(Σ) (x − c) < det Σ.
template <class T>
bool contains(const Body<T>& b, const double (&x)[3], double t) {
  const T tt = point<T>(t);
  V3<T> r;
  for (int i = 0; i < 3; ++i) r[i] = point<T>(x[i]) - (b.c0[i] + tt * b.c1[i]);
  return surely_positive(T(b.det - quad_form(b.adj, r, r)));
}

// The bodies overlap at t, proved by a common point: the contact function's point at the λ where its two
// quadratic forms are equal (regula falsi, Illinois variant, on (1 − λ)² yᵀΣ_a y − λ² yᵀΣ_b y).
template <class T>
bool overlap_at(const TranslatingPair<T>& P, double t) {
  double d[3], ca[3];
  for (int i = 0; i < 3; ++i) {
    ca[i] = plain(P.a.c0[i]) + t * plain(P.a.c1[i]);
    d[i] = plain(P.b.c0[i]) + t * plain(P.b.c1[i]) - ca[i];
  }
  double lo = 0, hi = 1, flo = 1, fhi = -1, lam = 0.5;
  ContactPoint3 c = contact_point(P, d, lam);
  int side = 0;
  for (int it = 0; it < 100; ++it) {
    if (c.qa < 1 && c.qb < 1) break;
    const double f = c.qa - c.qb;
    if (f > 0) {
      lo = lam;
      flo = f;
      if (side == 1) fhi *= 0.5;
      side = 1;
    } else {
      hi = lam;
      fhi = f;
      if (side == -1) flo *= 0.5;
      side = -1;
    }
    if (!(hi - lo > 1e-17)) break;
    lam = (flo == 1 && fhi == -1) ? 0.5 * (lo + hi) : lo + (hi - lo) * flo / (flo - fhi);
    if (!(lam > lo && lam < hi)) lam = 0.5 * (lo + hi);
    c = contact_point(P, d, lam);
  }
  double x[3];
  M3<double> Sa;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Sa[i][j] = plain(P.a.sigma[i][j]);
  for (int i = 0; i < 3; ++i) x[i] = ca[i] + (1 - lam) * (Sa[i][0] * c.y[0] + Sa[i][1] * c.y[1] + Sa[i][2] * c.y[2]);
  return contains(P.a, x, t) && contains(P.b, x, t);
}

// The contact point at a contact (λ, t) (display only): the contact function's point x = c_a + (1 − λ)Σ_a y,
// y = G(λ)^-1 d, and A's unit outward normal there, along y.
template <class T>
ContactPoint touching_point(const TranslatingPair<T>& P, double lam, double t) {
  double d[3], ca[3];
  for (int i = 0; i < 3; ++i) {
    ca[i] = plain(P.a.c0[i]) + t * plain(P.a.c1[i]);
    d[i] = plain(P.b.c0[i]) + t * plain(P.b.c1[i]) - ca[i];
  }
  const ContactPoint3 c = contact_point(P, d, lam);
  const double len = std::sqrt(c.y[0] * c.y[0] + c.y[1] * c.y[1] + c.y[2] * c.y[2]);
  ContactPoint out;
  auto text = [](double v) { return v == 0 ? std::string("0") : scalar_traits<double>::to_string(v); };
  for (int i = 0; i < 3; ++i) {
    double x = ca[i];
    for (int j = 0; j < 3; ++j) x += (1 - lam) * plain(P.a.sigma[i][j]) * c.y[j];
    out.x.push_back(text(x));
    out.normal.push_back(text(len > 0 ? c.y[i] / len : 0.0));
  }
  return out;
}

// The λ maximising min_t H(λ, t) near a grid point (golden section on [lo, hi]).
inline double best_line_witness(const std::array<std::array<double, 5>, 3>& h, double lo, double hi) {
  const double g = 0.6180339887498949;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  auto m = [&](double l) {
    const Hk e = eval_hk(h, l);
    return e.v[2] > 0 ? line_margin(e) : -HUGE_VAL;
  };
  double f1 = m(x1), f2 = m(x2);
  for (int it = 0; it < 60 && hi - lo > 1e-13; ++it) {
    if (f1 < f2) {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = m(x2);
    } else {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = m(x1);
    }
  }
  return f1 < f2 ? x2 : x1;
}

}  // namespace translation_detail

// Decide the translating pair on [0, 1], or nothing when a proof fails (see the header prose).
template <class T>
std::optional<TranslationResult> translation_ccd(const TranslatingPair<T>& P) {
  using namespace translation_detail;
  constexpr int N = 24;
  TranslationResult r;
  double tin = -HUGE_VAL, tout = HUGE_VAL, lin = 0, lout = 0, best_margin = -HUGE_VAL, lmiss = 0;
  for (int k = 0; k < N; ++k) {
    const double l = (k + 0.5) / N;
    const Hk e = eval_hk(P.hd, l);
    if (!(e.v[2] > 0)) return std::nullopt;  // no relative translation, or not read as a pencil of ellipsoids
    const double m = line_margin(e);
    if (m > best_margin) {
      best_margin = m;
      lmiss = l;
    }
    double r0, r1;
    if (!t_roots(e, r0, r1)) continue;
    if (r0 > tin) {
      tin = r0;
      lin = l;
    }
    if (r1 < tout) {
      tout = r1;
      lout = l;
    }
  }
  auto bracket = [](double l) { return std::make_pair(std::max(0.0, l - 1.0 / N), std::min(1.0, l + 1.0 / N)); };
  auto separate = [&](double lam) {
    ++r.proofs;
    if (!separate_on(P, lam, 0, 1)) return false;
    r.answer.collides = false;
    return true;
  };
  if (best_margin > 0 || tin > tout) {  // the line of d(t) misses the Minkowski sum
    const auto [lo, hi] = bracket(lmiss);
    if (best_margin > 0 && separate(lmiss)) return r;
    if (separate(best_line_witness(P.hd, lo, hi))) return r;
    return std::nullopt;
  }
  {
    const auto [lo, hi] = bracket(lin);
    if (!refine_end(P.hd, false, lo, hi, lin, tin, r.newton_steps)) return std::nullopt;
  }
  {
    const auto [lo, hi] = bracket(lout);
    if (!refine_end(P.hd, true, lo, hi, lout, tout, r.newton_steps)) return std::nullopt;
  }
  if (!(tin <= tout)) return std::nullopt;
  if (tin > 1) return separate(lin) ? std::optional(r) : std::nullopt;
  if (tout < 0) return separate(lout) ? std::optional(r) : std::nullopt;
  for (const double delta : {0x1p-42, 0x1p-32, 0x1p-24}) {
    if ((tin > 0 && tin - delta <= 0) || (tout < 1 && tout + delta >= 1)) return std::nullopt;
    const double p1 = tin <= 0 ? 0.0 : tin + delta, p2 = tout >= 1 ? 1.0 : tout - delta;
    if (!(p1 <= p2)) return std::nullopt;
    r.proofs += 2;
    if (tin > 0 && !separate_on(P, lin, 0, tin - delta)) continue;
    if (tout < 1 && !separate_on(P, lout, tout + delta, 1)) continue;
    r.proofs += 2;
    if (!overlap_at(P, p1) || (p2 != p1 && !overlap_at(P, p2))) continue;
    const Instant s = rounded_instant(point<T>(std::max(tin, 0.0))), e = rounded_instant(point<T>(std::min(tout, 1.0)));
    r.answer.collides = true;
    r.answer.intervals.push_back({s, e});
    r.answer.first_contact = s;
    if (tin > 0) {  // entering and leaving are external tangencies
      r.answer.contacts.push_back(s);
      r.answer.contact_points.push_back(touching_point(P, lin, tin));
    }
    if (tout < 1) {
      r.answer.contacts.push_back(e);
      r.answer.contact_points.push_back(touching_point(P, lout, tout));
    }
    return r;
  }
  return std::nullopt;
}

}  // namespace eccd
