#pragma once
// Does a fixed plane separate two moving objects for every t in [0, 1]?
// Frame coherence, paper 000 section 4, as two polynomial sign conditions.
//
// Statement. An object is the solid YᵀQY <= 0 in its own frame, moved by the
// homogeneous polynomial motion M(t) (scene-format.md; world X = M(t)Y, last
// row (0, ..., 0, w(t)), w ≠ 0 on [0, 1]). A world plane pᵀX = 0 is the plane
// q(t)ᵀY = 0 in the object's frame, q(t) = M(t)ᵀp (no denominator: a
// homogeneous plane may be scaled). A plane q misses the solid YᵀQY <= 0 iff
// qᵀQ⁻¹q < 0 (the unit sphere diag(1, .., 1, -1): |n|² - o² < 0, distance
// > 1; every ellipsoid is an affine image of it), i.e., since det Q < 0 for
// an ellipse or ellipsoid (signature (+, .., +, -)), iff
//     h(t) = q(t)ᵀ adj(Q) q(t) > 0.
// So the plane misses a(t) for all t in [0, 1] iff h_a > 0 on [0, 1], and
// likewise h_b (the two polynomial sign conditions, degree 2 deg M). If a
// plane never meets a continuously moving solid, the solid's centre never
// crosses it, so the sides need checking at one instant, t = 0: the centre
// of the object in its frame is Y_c = adj(Q) e_d (its last entry is the
// cofactor det Q_dd > 0, the upper-left block being positive definite), in
// the world M(t)Y_c, and the centre lies on the side sign(pᵀM(t)Y_c)·sign(w(t)).
// The plane separates (a strictly negative, b strictly positive, for every t)
// iff h_a > 0 and h_b > 0 on [0, 1], a's side at 0 is negative and b's positive.
//
// Deciding "h > 0 on [0, 1]" (positive_on_unit_interval):
//  - exact T (a proof): all Bernstein coefficients > 0 suffices; otherwise
//    h(0) > 0 and no root of h in [0, 1] (a Sturm count, kernel/sturm.hpp)
//    decides it, and h(0) <= 0 or a root in [0, 1] refutes it.
//  - T with an error bound (Bounded<double>, Bounded<Mpfr>): the Bernstein
//    coefficients on [0, 1], subdivided at midpoints (de Casteljau) to a
//    fixed depth: a piece whose coefficients are all certainly positive is
//    settled; an end value of a piece that is certainly <= 0 refutes (the
//    plane meets the solid there, within the error bound); what is left
//    after the depth is unknown, with the piece named.
// Requirements on T: scalar_traits<T>, ring operations, division by small
// integers (exact rationals, or Bounded<double>/Bounded<Mpfr>).
#include "kernel/bernstein.hpp"
#include "kernel/poly_matrix.hpp"
#include "kernel/ring_determinant.hpp"
#include "kernel/sturm.hpp"

#include <array>
#include <string>
#include <vector>

namespace eccd {

// adj(Q) of a constant matrix, by cofactors (any ring).
template <class T, int H>
Matrix<T, H> adjugate_of(const Matrix<T, H>& q, const T& zero) {
  Matrix<T, H> adj;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      std::vector<std::vector<T>> minor;
      for (int r = 0; r < H; ++r) {
        if (r == j) continue;  // adj = cofactorᵀ: entry (i, j) is the cofactor of (j, i)
        std::vector<T> row;
        for (int c = 0; c < H; ++c)
          if (c != i) row.push_back(q[r][c]);
        minor.push_back(row);
      }
      T d = ring_det(minor, zero);
      adj[i][j] = ((i + j) % 2) ? T(zero - d) : d;
    }
  return adj;
}

// The polynomials of one object against the plane p (see the statement).
template <class T, int H>
struct PlaneAgainstObject {
  Poly<T> miss;  // h(t) = q(t)ᵀ adj(Q) q(t): > 0 iff the plane misses the object at t
  Poly<T> side;  // pᵀ M(t) adj(Q) e_d: times sign w(t), the side of the object's centre
  Poly<T> w;     // M(t)'s last diagonal entry
};

template <class T, int H>
PlaneAgainstObject<T, H> plane_against_object(const Matrix<T, H>& q, const PolyMatrix<T, H>& m,
                                              const std::array<T, H>& p, const T& zero) {
  const Matrix<T, H> adj = adjugate_of<T, H>(q, zero);
  std::array<Poly<T>, H> qt;  // q(t) = M(t)ᵀ p
  for (int i = 0; i < H; ++i) {
    Poly<T> s;
    for (int j = 0; j < H; ++j)
      if (!m[j][i].is_zero() && !is_zero(p[j])) s += p[j] * m[j][i];
    qt[i] = s;
  }
  PlaneAgainstObject<T, H> out;
  for (int i = 0; i < H; ++i) {
    Poly<T> r;  // (adj q)_i
    for (int j = 0; j < H; ++j)
      if (!is_zero(adj[i][j]) && !qt[j].is_zero()) r += adj[i][j] * qt[j];
    if (!r.is_zero() && !qt[i].is_zero()) out.miss += qt[i] * r;
  }
  constexpr int d = H - 1;
  for (int i = 0; i < H; ++i)  // pᵀ M(t) Y_c, Y_c = adj(Q) e_d = column d of adj
    for (int k = 0; k < H; ++k)
      if (!is_zero(p[i]) && !m[i][k].is_zero() && !is_zero(adj[k][d])) out.side += (p[i] * adj[k][d]) * m[i][k];
  out.w = m[d][d];
  return out;
}

enum class OnInterval { positive, not_positive, unknown };

// Is h > 0 on [0, 1]? See the statement; `where` says what was left unknown.
template <class T>
OnInterval positive_on_unit_interval(const Poly<T>& h, std::string& where, int max_depth = 12) {
  if (h.is_zero()) return OnInterval::not_positive;
  const Bern<T> bern = to_bernstein(h);
  if constexpr (scalar_traits<T>::is_exact) {
    (void)max_depth;
    bool all = true;
    for (const T& c : bern.b) all = all && sign(c) == Sign::positive;
    if (all) return OnInterval::positive;
    const T zero(0), one(1);
    if (sign(h(zero)) != Sign::positive) return OnInterval::not_positive;
    return count_roots_closed(h, zero, one) == 0 ? OnInterval::positive : OnInterval::not_positive;
  } else {
    struct Piece {
      std::vector<T> b;
      int depth;
      double lo, hi;
    };
    std::vector<Piece> todo{{bern.b, 0, 0.0, 1.0}};
    while (!todo.empty()) {
      Piece pc = std::move(todo.back());
      todo.pop_back();
      if (sign(pc.b.front()) == Sign::negative || sign(pc.b.front()) == Sign::zero ||
          sign(pc.b.back()) == Sign::negative || sign(pc.b.back()) == Sign::zero)
        return OnInterval::not_positive;
      bool all = true;
      for (const T& c : pc.b) all = all && sign(c) == Sign::positive;
      if (all) continue;
      if (pc.depth >= max_depth) {
        where =
            "t in [" + std::to_string(pc.lo) + ", " + std::to_string(pc.hi) +
            "]: a Bernstein coefficient of the plane's polynomial is within its error bound of 0 or negative after " +
            std::to_string(max_depth) + " subdivisions";
        return OnInterval::unknown;
      }
      // de Casteljau at 1/2: left = first entries of the triangle, right = last ones.
      const std::size_t n = pc.b.size();
      std::vector<T> left(n), right(n), w = pc.b;
      const T half = T(1) / T(2);
      for (std::size_t r = 0; r < n; ++r) {
        left[r] = w[0];
        right[n - 1 - r] = w[n - 1 - r];
        for (std::size_t i = 0; i + 1 < n - r; ++i) w[i] = (w[i] + w[i + 1]) * half;
      }
      const double mid = (pc.lo + pc.hi) / 2;
      todo.push_back({std::move(right), pc.depth + 1, mid, pc.hi});
      todo.push_back({std::move(left), pc.depth + 1, pc.lo, mid});
    }
    return OnInterval::positive;
  }
}

// The same check for a 3D keyframe body (kernel/keyframe_motion.hpp, no
// deformation: M(τ) = [[R'(e), E c], [0, E]], e(τ) = (1 − τ)q0 + τq1 with q1
// already taken the shorter way round, R' = E R the quaternion matrix of
// kernel/motion.hpp, E = |e|², c(τ) = (1 − τ)c0 + τc1), in fixed-size
// polynomials and without allocation: the kept-plane check of an animation
// frame from numbers prepared once per body and key pose (api/animate.cpp).
// q(τ) = M(τ)ᵀp has degree 2 (its first three entries) and 3 (the last),
// h = qᵀ adj(Q) q degree 6; h > 0 on [0, 1] is proved by the scaled
// Bernstein coefficients s_k = Σ_j a_j C(6 − j, k − j) (= b_k C(6, k): integer
// weights) all certainly positive. That is sufficient, not necessary: a plane
// it cannot settle is `unknown` here and goes to the general check above.
// The centre's side at τ = 0 is the sign of pᵀM(0)Y_c = q(0)ᵀY_c (E(0) > 0).
// Requirements on T: Bounded<double> or exact rationals.
template <class T>
struct KeyframeBody3 {
  const std::array<std::array<T, 4>, 4>* adj = nullptr;  // adj(Q), prepared once per body
  std::array<T, 4> q0, q1;                               // the orientations at the frame's keys
  std::array<T, 3> c0, c1;                               // the centres
};

enum class FrameSides { separates, fails, unknown };

namespace plane_frame_detail {
template <class T, std::size_t N>
using FPoly = std::array<T, N>;  // coefficients of τ^0..τ^(N-1)

template <class T, std::size_t N, std::size_t M>
FPoly<T, N + M - 1> fmul(const FPoly<T, N>& x, const FPoly<T, M>& y) {
  FPoly<T, N + M - 1> r;
  r.fill(T(0));
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < M; ++j) r[i + j] += x[i] * y[j];
  return r;
}
// x + y + z + w with the signs given (each +1 or -1).
template <class T, std::size_t N>
FPoly<T, N> fsum(const FPoly<T, N>& x, int sy, const FPoly<T, N>& y, int sz = 0, const FPoly<T, N>* z = nullptr,
                 int sw = 0, const FPoly<T, N>* w = nullptr) {
  FPoly<T, N> r = x;
  for (std::size_t i = 0; i < N; ++i) {
    r[i] = sy > 0 ? T(r[i] + y[i]) : T(r[i] - y[i]);
    if (z) r[i] = sz > 0 ? T(r[i] + (*z)[i]) : T(r[i] - (*z)[i]);
    if (w) r[i] = sw > 0 ? T(r[i] + (*w)[i]) : T(r[i] - (*w)[i]);
  }
  return r;
}

// q(τ) = M(τ)ᵀp of a keyframe body. With e = (w, v), kernel/motion.hpp's
// quaternion matrix is R' = (w² − |v|²)I + 2vvᵀ + 2w[v]×, so the first three
// entries are R'ᵀn = (w² − |v|²)n + 2(v·n)v − 2w(v × n) (n = p's first three),
// the last E(c·n + p_3).
template <class T>
std::array<FPoly<T, 4>, 4> keyframe_plane_in_body(const KeyframeBody3<T>& b, const std::array<T, 4>& p) {
  FPoly<T, 2> e[4];
  for (int i = 0; i < 4; ++i) e[i] = {b.q0[i], T(b.q1[i] - b.q0[i])};
  FPoly<T, 3> sq[4];
  for (int i = 0; i < 4; ++i) sq[i] = fmul(e[i], e[i]);
  const FPoly<T, 3> a = fsum(sq[0], -1, sq[1], -1, &sq[2], -1, &sq[3]);  // w² − |v|²
  const FPoly<T, 3> E = fsum(sq[0], 1, sq[1], 1, &sq[2], 1, &sq[3]);
  FPoly<T, 2> vn{T(0), T(0)}, cross[3];  // v·n and v × n
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 2; ++k) vn[k] += e[i + 1][k] * p[i];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, l = (i + 2) % 3;
    for (int k = 0; k < 2; ++k) cross[i][k] = e[j + 1][k] * p[l] - e[l + 1][k] * p[j];
  }
  std::array<FPoly<T, 4>, 4> q;
  for (int i = 0; i < 3; ++i) {
    const FPoly<T, 3> u = fmul(vn, e[i + 1]), x = fmul(e[0], cross[i]);
    for (int k = 0; k < 3; ++k) q[i][k] = a[k] * p[i] + T(2) * T(u[k] - x[k]);
    q[i][3] = T(0);
  }
  FPoly<T, 2> side{p[3], T(0)};  // c(τ)·n + p_3
  for (int i = 0; i < 3; ++i) {
    side[0] += b.c0[i] * p[i];
    side[1] += T(b.c1[i] - b.c0[i]) * p[i];
  }
  q[3] = fmul(E, side);
  return q;
}
}  // namespace plane_frame_detail

template <class T>
FrameSides keyframe_plane_check(const std::array<T, 4>& p, const KeyframeBody3<T>& a, const KeyframeBody3<T>& b) {
  using namespace plane_frame_detail;
  static constexpr int C[7][7] = {{1, 0, 0, 0, 0, 0, 0},   {1, 1, 0, 0, 0, 0, 0}, {1, 2, 1, 0, 0, 0, 0},
                                  {1, 3, 3, 1, 0, 0, 0},   {1, 4, 6, 4, 1, 0, 0}, {1, 5, 10, 10, 5, 1, 0},
                                  {1, 6, 15, 20, 15, 6, 1}};
  bool unknown = false;
  for (int k = 0; k < 2; ++k) {
    const KeyframeBody3<T>& bd = k ? b : a;
    const auto& adj = *bd.adj;
    const std::array<FPoly<T, 4>, 4> q = keyframe_plane_in_body(bd, p);
    T side = T(0);
    for (int j = 0; j < 4; ++j) side += q[j][0] * adj[j][3];
    const Sign ss = scalar_traits<T>::sign(side), want = k ? Sign::positive : Sign::negative;
    if (ss == Sign::uncertain)
      unknown = true;
    else if (ss != want)
      return FrameSides::fails;
    FPoly<T, 7> h;  // qᵀ adj(Q) q; q_0..q_2 have degree 2, q_3 degree 3
    h.fill(T(0));
    for (int i = 0; i < 4; ++i) {
      FPoly<T, 4> ri;  // (adj q)_i
      for (int m = 0; m < 3; ++m) {
        ri[m] = adj[i][0] * q[0][m];
        for (int j = 1; j < 4; ++j) ri[m] += adj[i][j] * q[j][m];
      }
      ri[3] = adj[i][3] * q[3][3];
      const int n = i < 3 ? 3 : 4;
      for (int x = 0; x < n; ++x)
        for (int m = 0; m < 4; ++m) h[x + m] += q[i][x] * ri[m];
    }
    for (int m = 0; m < 7 && !unknown; ++m) {
      T s = h[m];
      for (int j = 0; j < m; ++j) s += (C[6 - j][m - j] == 1 ? h[j] : T(T(C[6 - j][m - j]) * h[j]));
      if (scalar_traits<T>::sign(s) != Sign::positive) unknown = true;
    }
  }
  return unknown ? FrameSides::unknown : FrameSides::separates;
}

}  // namespace eccd
