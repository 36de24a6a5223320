#pragma once
// TriBern<T>: the ellipsoid function of independent motions,
//   F(u, s, t) = (-1)^H det((u - 1) A(s) - u B(t)) = det((1 - u) A(s) + u B(t)),
// as a tensor-product polynomial in Bernstein form over [0, 1]^3, and the
// subdivision it needs. H = 4 (ellipsoids) or H = 3 (ellipses).
//
// Statement. Paper 001, section 4, "CCD for independent motions": A moves as
// A(s), B as B(t) with s and t unrelated; A(s) and B(t) are separate iff
// F(u, s, t) > 0 for some u in (0, 1) (for fixed s and t this is the static
// test of kernel/ellipsoid_function.hpp, H = 4). Ellipses (H = 3, paper 003
// section III): f(λ) = det(λA - B) is a cubic with f(0) = -det B > 0 and
// f -> +inf as λ -> -inf (det A < 0), separate iff two distinct negative
// roots, between which f < 0; det((u - 1)A - uB) = u^3 f((u - 1)/u) then has
// the sign of f, and the factor (-1)^H = -1 turns it into the ellipsoids'
// convention: F(0) = det A < 0, F(1) = det B < 0, separate iff F > 0 for some
// u in (0, 1), touching iff max F = 0 there, overlapping iff F < 0 on (0, 1),
// and F(., s, t) has at most two roots in (0, 1) in both dimensions (the
// negative roots of f). Everything built on F (floating/independent_ccd.hpp,
// certified/independent_proof.hpp) is therefore the same for H = 3 and 4.
// F is built the way the
// shared-parameter F(u, t) is (kernel/ellipsoid_function.hpp): with
// f(λ; s, t) = det(λA(s) - B(t)) = sum_k g_k(s, t) λ^k, F = sum_k g_k (u - 1)^k u^(H-k)
// and (u - 1)^k u^(H-k) = (-1)^k B^H_{H-k}(u) / C(H, k), so F's Bernstein
// coefficient of B^H_j(u) is (-1)^(H-j) g_{H-j} / C(H, j), times (-1)^H.
// g_k: det is multilinear in the columns (kernel/characteristic_polynomial.hpp),
// g_k = (-1)^(H-k) sum_{|S| = k} det(C_S), C_S with the columns S from A(s) and
// the others from B(t); by the Laplace expansion along the columns S,
//   det(C_S) = sum_{|R| = k} (-1)^(ΣR + ΣS) det A(s)[R, S] det B(t)[R', S'],
// a sum of products of a polynomial in s and one in t: in Bernstein form the
// tensor (outer) product of the two coefficient vectors, each raised to the
// largest degree that occurs. The minors are ring_det of the univariate
// Bernstein entries of A(s) = N_A(s)^T Q_A N_A(s) (kernel/quadric.hpp,
// moving_quadric_in), so nothing of the shared-parameter set-up is copied.
// Sub-boxes: split_half(axis) halves the box along u (0), s (1) or t (2) by
// de Casteljau at 1/2 (kernel/bernstein.hpp); the control points of a box
// bound F on it (convex hull), so "every control point > 0" proves F > 0 on
// the box and "every control point < 0" proves F < 0 on it.
// Requirements on T: the ring operations and scalar_traits<T> (from_rational,
// sign); with T = Rational everything is exact (the tests compare F(u, s, s)
// with the shared F(u, t) at s = t exactly).
#include "kernel/bernstein.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/ring_determinant.hpp"
#include "number/halving_step.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <optional>
#include <utility>
#include <vector>

namespace eccd {

template <class T>
struct TriBern {
  std::array<int, 3> n{};  // degrees in u, s, t
  std::vector<T> c;        // c[(i (n[1]+1) + j) (n[2]+1) + k]
  std::size_t index(int i, int j, int k) const { return (std::size_t(i) * (n[1] + 1) + j) * (n[2] + 1) + k; }
  const T& at(int i, int j, int k) const { return c[index(i, j, k)]; }
  T& at(int i, int j, int k) { return c[index(i, j, k)]; }
  std::size_t stride(int axis) const {
    return axis == 2 ? 1 : axis == 1 ? std::size_t(n[2] + 1) : std::size_t(n[1] + 1) * (n[2] + 1);
  }

  // Every control point strictly positive (+1), strictly negative (-1), or neither (0, also when a sign is uncertain).
  int strict_sign() const {
    const Sign s0 = sign(c[0]);
    if (s0 != Sign::positive && s0 != Sign::negative) return 0;
    for (const auto& x : c)
      if (sign(x) != s0) return 0;
    return s0 == Sign::positive ? 1 : -1;
  }

  // The two halves along `axis` (0 = u, 1 = s, 2 = t), by de Casteljau at 1/2,
  // in place on the lines of the right half: round r of keep_right
  // (kernel/bernstein.hpp) leaves the left half's coefficient r in the line's
  // first place (the same operations as keep_left's, in the same order), so
  // no line is copied (a copy of an MPFR number allocates). Each step is
  // number/halving_step.hpp's (for guarded MPFR an addition and an exponent
  // shift, with the written-out steps' value and bound).
  std::pair<TriBern, TriBern> split_half(int axis, const T& half) const& {
    TriBern copy = *this;
    return std::move(copy).split_half(axis, half);
  }
  // The same, consuming this net: it becomes the right half (one copy fewer).
  std::pair<TriBern, TriBern> split_half(int axis, const T& half) && {
    HalvingStep<T> step(half);
    TriBern lo;
    split_half_into(axis, step, lo);
    return {std::move(lo), std::move(*this)};
  }
  // The same in place: this net becomes the right half and `lo` the left. A
  // `lo` of this net's size keeps its numbers' storage (a caller that reuses
  // nets allocates nothing); any other `lo` is replaced by a copy first.
  void split_half_into(int axis, HalvingStep<T>& step, TriBern& lo) {
    const std::size_t st = stride(axis), len = std::size_t(n[axis]) + 1;
    if (lo.c.size() != c.size() || len == 1) {
      lo.c = c;
    } else {
      for (std::size_t block = 0; block < c.size(); block += st * len)
        for (std::size_t base = block; base < block + st; ++base) lo.c[base] = c[base];
    }
    lo.n = n;
    if (len == 1) return;
    // the lines along axis start at the points whose coordinate on the axis is 0: st of them in each block of st * len
    for (std::size_t block = 0; block < c.size(); block += st * len)
      for (std::size_t base = block; base < block + st; ++base) {
        T* h = c.data() + base;
        for (std::size_t r = 1; r < len; ++r) {
          for (std::size_t i = 0; i + r < len; ++i) step(h[i * st], h[(i + 1) * st]);
          lo.c[base + r * st] = h[0];
        }
      }
  }

  // F with s fixed at x (degree 0 in s): a box of zero width in s.
  TriBern at_s(const T& x) const {
    TriBern r;
    r.n = {n[0], 0, n[2]};
    r.c.reserve(std::size_t(n[0] + 1) * (n[2] + 1));
    std::vector<T> line(std::size_t(n[1]) + 1);
    for (int i = 0; i <= n[0]; ++i)
      for (int k = 0; k <= n[2]; ++k) {
        for (int j = 0; j <= n[1]; ++j) line[j] = at(i, j, k);
        r.c.push_back(bernstein_value(std::span<const T>(line), x));
      }
    return r;
  }

  // Degenerate paths: when F(u, s, t) = p(x) G(the other two) along `axis`
  // (x = s or t; every line of the net along the axis a multiple of one line
  // p, checked by exact cross-multiplication) and p has one strict sign on
  // [0, 1] (all its Bernstein coefficients of one sign, convex hull), G
  // (degree 0 along the axis, scaled so that sign G = sign F everywhere)
  // has F's signs at every point. F's face u = 1 is det B(t), free of s, so
  // along s such a p is a constant: this catches a net of nominal degree > 0
  // that does not depend on the parameter. A body turning in place makes F
  // depend on its parameter through u (no such factor): hold_still below
  // reduces that one, when F is built. The answer is then the lower-dimensional
  // problem of G. Nothing is returned when F is not of that form, when p's
  // sign is not proved, or when T is not exact (a rounded net's lines are
  // proportional only approximately; its static bodies already have degree 0).
  std::optional<TriBern> without_positive_factor(int axis) const {
    if constexpr (!scalar_traits<T>::is_exact) {
      (void)axis;
      return std::nullopt;
    } else {
      if (n[axis] == 0) return std::nullopt;
      const std::size_t st = stride(axis), len = std::size_t(n[axis]) + 1;
      std::optional<std::size_t> ref;  // the first point of the line p
      for (std::size_t base = 0; base < c.size() && !ref; ++base) {
        if ((base / st) % len != 0) continue;
        for (std::size_t m = 0; m < len; ++m)
          if (sign(c[base + m * st]) != Sign::zero) {
            ref = base;
            break;
          }
      }
      if (!ref) return std::nullopt;
      const Sign sp = sign(c[*ref]);
      for (std::size_t m = 0; m < len; ++m)
        if (sign(c[*ref + m * st]) != sp || sp == Sign::zero) return std::nullopt;
      TriBern r;
      r.n = n;
      r.n[axis] = 0;
      r.c.reserve(c.size() / len);
      const T& p0 = c[*ref];
      for (std::size_t base = 0; base < c.size(); ++base) {
        if ((base / st) % len != 0) continue;
        // the line is lam * p with lam = line[0] / p[0]; check line[m] p[0] == line[0] p[m]
        for (std::size_t m = 1; m < len; ++m) {
          const T lhs = c[base + m * st] * p0, rhs = c[base] * c[*ref + m * st];
          if (!(lhs == rhs)) return std::nullopt;
        }
        T g = c[base] / p0;
        if (sp == Sign::negative) g = -g;
        r.c.push_back(g);
      }
      return r;
    }
  }

  // s and t exchanged: the same function with the roles of A and B's parameters swapped.
  TriBern swap_st() const {
    TriBern r;
    r.n = {n[0], n[2], n[1]};
    r.c.resize(c.size());
    for (int i = 0; i <= n[0]; ++i)
      for (int j = 0; j <= n[1]; ++j)
        for (int k = 0; k <= n[2]; ++k) r.at(i, k, j) = at(i, j, k);
    return r;
  }

  // F at one point (u, s, t): de Casteljau along t, then s, then u.
  T operator()(const T& u, const T& s, const T& t) const {
    Bern<T> cu;
    for (int i = 0; i <= n[0]; ++i) {
      Bern<T> cs;
      for (int j = 0; j <= n[1]; ++j) {
        std::vector<T> row(c.begin() + index(i, j, 0), c.begin() + index(i, j, 0) + n[2] + 1);
        cs.b.push_back(bernstein_value(std::span<const T>(row), t));
      }
      cu.b.push_back(cs(s));
    }
    return cu(u);
  }
};

// A body that does not move as a set: its moving solid A(x) = N(x)^T Q N(x)
// (Bernstein entries) is c(x) A(0) with c > 0 on [0, 1] (a static body whose
// matrix only scales, or a ball or a body of revolution turning about its
// centre and axis). Then (1 - u) c A(0) + u B = k ((1 - u') A(0) + u' B) with
// k = (1 - u) c + u > 0 and u' = u / k, an increasing map of [0, 1] onto
// itself for each x: F(u, x, .) has the sign of F(u', 0, .), so the pair meets
// at (x, y) iff it meets at (0, y), and every proof about F holds for the net
// built from the constant A(0) (degree 0 in x: the lower-dimensional problem).
// Checked exactly (T exact only): every entry e satisfies e(x) r(0) = r(x) e(0)
// as polynomials (coefficients of one degree, cross-multiplied) for an entry r
// with r(0) != 0, and c = r / r(0) has all Bernstein coefficients > 0 on the
// pieces of an exact halving (at most 2^6 of them). On success `m` becomes
// the constant A(0) and true is returned; false leaves `m` as it was (also
// for a body already of degree 0, and for every inexact T).
template <class T, int H>
bool hold_still(std::array<std::array<Bern<T>, H>, H>& m) {
  if constexpr (!scalar_traits<T>::is_exact) {
    (void)m;
    return false;
  } else {
    int D = 0;
    for (const auto& row : m)
      for (const auto& e : row) D = std::max(D, e.degree());
    if (D == 0) return false;
    std::array<std::array<Bern<T>, H>, H> e{};
    const Bern<T>* ref = nullptr;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        e[i][j] = elevate(m[i][j], D - m[i][j].degree());
        if (!ref && sign(e[i][j].b[0]) != Sign::zero) ref = &e[i][j];
      }
    if (!ref) return false;
    const T& r0 = ref->b[0];
    for (const auto& row : e)
      for (const auto& x : row)
        for (int k = 1; k <= D; ++k)
          if (!(x.b[k] * r0 == ref->b[k] * x.b[0])) return false;
    std::vector<std::pair<std::vector<T>, int>> pieces{{ref->b, 0}};
    const T half = scalar_traits<T>::from_rational(mpq_class(1, 2), r0);
    while (!pieces.empty()) {
      auto [c, d] = std::move(pieces.back());
      pieces.pop_back();
      if (std::all_of(c.begin(), c.end(), [&](const T& x) { return sign(x) == sign(r0); })) continue;
      if (d >= 6) return false;
      std::vector<T> lo = c, hi = c;
      keep_left(std::span<T>(lo), half);
      keep_right(std::span<T>(hi), half);
      pieces.push_back({std::move(lo), d + 1});
      pieces.push_back({std::move(hi), d + 1});
    }
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) m[i][j] = Bern<T>(std::vector<T>{e[i][j].b[0]});
    return true;
  }
}

// The same on a prepared pair (exact motions, before any conversion to an
// inexact T): a body that does not move as a set gets the constant N(0) in
// place of N(x), so every arithmetic builds the held net. Returns which of A
// and B was held.
template <int H>
std::array<bool, 2> hold_still_pair(PreparedPair<H>& p) {
  std::array<bool, 2> held{};
  Bern<Rational> zero;
  zero.b.push_back(Rational(0));
  for (int k = 0; k < 2; ++k) {
    PolyMatrix<Rational, H>& n = k ? p.nb : p.na;
    std::array<std::array<Bern<Rational>, H>, H> nb;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) nb[i][j] = n[i][j].is_zero() ? zero : to_bernstein(n[i][j]);
    auto a = moving_quadric_in<Bern<Rational>, Rational, H>(k ? p.qb : p.qa, nb, zero);
    if (!hold_still<Rational, H>(a)) continue;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) n[i][j] = Poly<Rational>::constant(n[i][j].is_zero() ? Rational(0) : n[i][j].c[0]);
    held[k] = true;
  }
  return held;
}

// F(u, s, t) of a pair whose N_A, N_B are in Bernstein form (the first factor's
// parameter is s, the second's t); H = 4 (ellipsoids, paper 001) or 3 (ellipses).
// A body that does not move as a set gives degree 0 in its parameter: a static
// one by its motion, one that turns in place by hold_still (exact T only; the
// flags `still` say which of A and B was so reduced).
template <class T, int H>
TriBern<T> independent_ellipsoid_function(const MovingPairBern<T, H>& pair, std::array<bool, 2>* still = nullptr) {
  const T zero_s = scalar_traits<T>::from_rational(mpq_class(0), pair.qa[0][0]);
  const T one_s = scalar_traits<T>::from_rational(mpq_class(1), pair.qa[0][0]);
  Bern<T> zero;
  zero.b.push_back(zero_s);
  Bern<T> one;
  one.b.push_back(one_s);
  auto a = moving_quadric_in<Bern<T>, T, H>(pair.qa, pair.na, zero);
  auto b = moving_quadric_in<Bern<T>, T, H>(pair.qb, pair.nb, zero);
  const bool still_a = hold_still<T, H>(a), still_b = hold_still<T, H>(b);
  if (still) *still = {still_a, still_b};
  // minor of m on rows R, columns S (bit masks); the empty minor is 1
  auto minor = [&](const std::array<std::array<Bern<T>, H>, H>& m, unsigned rows, unsigned cols) {
    if (rows == 0) return one;
    std::vector<std::vector<Bern<T>>> sub;
    for (int i = 0; i < H; ++i) {
      if (!(rows >> i & 1u)) continue;
      sub.emplace_back();
      for (int j = 0; j < H; ++j)
        if (cols >> j & 1u) sub.back().push_back(m[i][j]);
    }
    return ring_det(sub, zero);
  };
  struct Term {
    int k;
    bool negative;
    Bern<T> in_s, in_t;
  };
  std::vector<Term> terms;
  int ds = 0, dt = 0;
  const unsigned all = (1u << H) - 1;
  for (unsigned S = 0; S <= all; ++S) {
    const int k = std::popcount(S);
    for (unsigned R = 0; R <= all; ++R) {
      if (std::popcount(R) != k) continue;
      int parity = (H - k);
      for (int i = 0; i < H; ++i) parity += (R >> i & 1u ? i : 0) + (S >> i & 1u ? i : 0);
      Term tm{k, parity % 2 != 0, minor(a, R, S), minor(b, all & ~R, all & ~S)};
      ds = std::max(ds, tm.in_s.degree());
      dt = std::max(dt, tm.in_t.degree());
      terms.push_back(std::move(tm));
    }
  }
  // g_k(s, t) as bivariate Bernstein nets (index [p][q]: s, t)
  std::vector<std::vector<T>> g(H + 1, std::vector<T>(std::size_t(ds + 1) * (dt + 1), zero_s));
  for (const auto& tm : terms) {
    const Bern<T> x = elevate(tm.in_s, ds - tm.in_s.degree());
    const Bern<T> y = elevate(tm.in_t, dt - tm.in_t.degree());
    auto& gk = g[tm.k];
    for (int p = 0; p <= ds; ++p)
      for (int q = 0; q <= dt; ++q) {
        const T v = x.b[p] * y.b[q];
        T& cell = gk[std::size_t(p) * (dt + 1) + q];
        if (tm.negative)
          cell = cell - v;
        else
          cell = cell + v;
      }
  }
  TriBern<T> F;
  F.n = {H, ds, dt};
  F.c.assign(std::size_t(H + 1) * (ds + 1) * (dt + 1), zero_s);
  auto choose = [](int n, int r) {
    long v = 1;
    for (int i = 1; i <= r; ++i) v = v * (n - r + i) / i;
    return v;
  };
  for (int j = 0; j <= H; ++j) {
    const T w = scalar_traits<T>::from_rational(mpq_class(j % 2 ? -1 : 1, choose(H, j)), zero_s);  // (-1)^(H-j) (-1)^H
    for (int p = 0; p <= ds; ++p)
      for (int q = 0; q <= dt; ++q) F.at(j, p, q) = w * g[H - j][std::size_t(p) * (dt + 1) + q];
  }
  return F;
}

}  // namespace eccd
