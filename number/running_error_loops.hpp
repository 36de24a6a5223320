#pragma once
// The guard's inner loops in one pass: a convolution and a de Casteljau
// triangle of Bounded<double> values (number/running_error.hpp) whose error
// bounds are accumulated beside the plain-double values in the same loop,
// with the rounding of the bound's own arithmetic covered once per output
// instead of once per operation (the guard's cost, reports/performance.md).
//
// Statement (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd
// ed., sections 2.2, 3.1 and 5.1: the running error bound of Horner's rule,
// here of the two loops that build and subdivide Δ). The values are computed
// by exactly the plain-double operations of the generic loops they replace,
// in the same order (no FMA: the project builds without -mfma), so they are
// bit for bit those of Bounded<double>'s operators and of plain double. The
// bounds are those of Bounded<double>'s operators, summed per output:
//   product p = fl(a b):  |ab - exact| <= |a| eb + |b| ea + ea eb, plus the
//       rounding u|p| (|fl(x) - x| <= u|fl(x)|, round to nearest) and, if it
//       underflows, at most 2^-1075;
//   sum r = fl(r' + p):   the rounding u|r| (sums of doubles that underflow
//       are exact);
//   so the convolution c_k = sum_{i+j=k} x_i y_j carries
//       E_k = sum (|x_i| ey_j + ex_i (|y_j| + ey_j)) + u sum (|p| + |r|),
//   and one step of de Casteljau, w_i <- s w_i + t w_{i+1}, carries
//       |s| e_i + es (|w_i| + e_i) + |t| e_{i+1} + et (|w_{i+1}| + e_{i+1})
//       + u (|x| + |y| + |w_i new|);
//   at the midpoint (bisection: t = 1/2 exactly, so s* = 1/2) the products
//   are exact halvings and a step carries (e_i + e_{i+1}) / 2 + u |w_i new|.
// Rounding of the bound's arithmetic: every bound quantity is a sum or a
// product of non-negative doubles rounded to nearest, so each rounding makes
// it at least (1 - u) times its exact value; a quantity reached through at
// most k roundings is at least (1 - u)^k times the exact bound expression,
// and (1 - u)^-k <= 1 + 2ku for ku <= 1/2. A convolution output of `terms`
// terms is at most 2 terms + 8 roundings deep, a de Casteljau output after L
// levels at most 8 L + 8: each output is multiplied once by
// 1 + (terms + 8) 2^-50, resp. 1 + (8 L + 8) 2^-51, which is at least
// 1 + 2ku. Underflow of a product of the bound (values are normalised, so
// this is theoretical) loses at most 2^-1075 each: 2^-1072 per term or step
// covers the value's and the bound's products together.
// The per-operation enlargement 2^-50 of Bounded<double> is replaced by these
// factors, so the bounds differ from the operator-by-operation ones only in
// the last bits (both are upper bounds of the same error).
// The conversion's terms a c / d (sum_of_ratios) add the quotient's
// rounding u|q| and the division bound of Bounded's operator/.
// Requirements: Bounded<double> only (the double guard); Bounded<Mpfr> keeps
// the generic loops.
#include "number/running_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace eccd::running_error_loops {

using BD = Bounded<double>;
inline constexpr double kU = 0x1p-53;
inline constexpr double kTiny = 0x1p-1072;  // per term or step: value and bound products that underflow

// The a-priori bound of a de Casteljau triangle (Higham section 3.1's
// γ argument on the triangle's paths), used by the three triangles below
// where it applies: s and t non-negative, each with a relative error at most
// ρ (s = s*(1 + α), t = t*(1 + β), |α|, |β| <= ρ, s* + t* = 1 exactly, e.g. t
// a point and s = fl(1 - t)). Every entry after r rounds is
// sum_i C(r,i) s^(r-i) t^i b_i over r + 1 inputs, each path r products and r
// sums, so the computed entry is sum_i B*_i b_i (1 + θ_i) with B*_i the exact
// weights (summing to 1) and |θ_i| <= (1 + ρ)^r (1 + u)^(2r) - 1 <= Γ =
// L / (1 - L), L = n (ρ + 2u). Its error against the exact entry is then at
// most sum B*_i (e_i + Γ |b_i|): the same triangle applied to the
// non-negative w_i = e_i + Γ |b_i|, which, computed with the rounded s and t
// (each rounding of a non-negative quantity makes it at least (1 - u) times
// its exact value), is at least (1 - L)(1 - u)^2 times that sum: each entry's
// bound is the computed w entry times `scale` >= 1 / (1 - L - 4u). Products
// that underflow lose at most 2^-1075 each: kTiny per round and entry.
// A step then costs two products and a sum for w beside the value's, where
// the running bound of de_casteljau's generic branch costs six products,
// nine sums and five absolute values; both bound the same error, this one
// with Γ n (ρ + 2u) in place of the per-step roundings: it counts |b_i| where
// the running bound counts the intermediate values, which cancel where signs
// mix, so it is looser there (kAprioriMaxDegree). Not applicable
// (ok = false: the running bound is used) when s or t is negative or not
// finite, or L > 2^-10, or n > kAprioriMaxDegree.
// Above this degree the triangle keeps the running bound: counting |b_i| instead of the cancelled
// intermediate values costs more the higher the degree (measured on coefficients of mixed signs: up to x9.4
// the operators' bound at degree 24, x50 at 144, tests/number/test_running_error_loops.cpp), and the
// high degrees are 2D's Δ (degree up to 144), whose subdivision reads signs closest to zero. A single value
// (de_casteljau_value) is the exception: it is one sign read, so above this degree it keeps the a-priori bound
// where that bound decides its sign and asks the running triangle only where it does not.
inline constexpr int kAprioriMaxDegree = 32;
// Subdivision (de_casteljau, de_casteljau_rows) keeps the a-priori bound up to degree 40: paper 002's F is of degree
// 36 in t, and its t-subdivisions with the running bound were 15 % of its guarded run. Measured (stop 48): the same
// answers (collides, undecided instants) with both limits on the 758 guarded double runs of cases/ and the report's
// scenes, both input modes; the guard's record unchanged; paper 002 guarded / as published x1.77 -> x1.65
// (three alternating runs of each build). 2D's Δ above degree 40 keeps the running bound.
inline constexpr int kAprioriMaxDegreeSplit = 40;
struct AprioriTriangle {
  bool ok = false;
  double gamma = 0, scale = 0;
};
// Not at the midpoint either (t = 1/2 exactly, s = 1/2: TriangleStep::mid below): there the running bound of a
// sum alone is as cheap and tighter, and every triangle takes it (ok = false).
inline AprioriTriangle apriori_triangle(const BD& s, const BD& t, int n, int max_degree = kAprioriMaxDegree) {
  AprioriTriangle a;
  const double sv = s.value(), tv = t.value(), se = s.bound(), te = t.bound();
  if (tv == 0.5 && te == 0 && sv == 0.5) return a;  // the midpoint (the same test as TriangleStep::mid)
  if (!(sv >= 0 && tv >= 0 && std::isfinite(sv) && std::isfinite(tv) && se >= 0 && te >= 0)) return a;
  auto rel = [](double v, double e) {
    return e == 0 ? 0.0 : (v > 0 ? e / v : std::numeric_limits<double>::infinity());
  };
  const double rho = std::max(rel(sv, se), rel(tv, te)) * (1.0 + 0x1p-50);
  const double L = double(n) * (rho + 2.0 * kU) * (1.0 + 0x1p-50);
  if (!(L <= 0x1p-10) || n > max_degree) return a;
  a.ok = true;
  a.gamma = L / (1.0 - L) * (1.0 + 0x1p-48);
  a.scale = (1.0 + 0x1p-48) / (1.0 - L - 4.0 * kU);
  return a;
}

// A triangle's working rows: the values and bounds of b unpacked, on the stack up to degree 63 (the 3D
// method's many low-degree calls), else in per-thread buffers (one triangle at a time per thread).
struct WorkingRows {
  double vs[64], es[64];
  double* v = vs;
  double* e = es;
  explicit WorkingRows(std::span<const BD> b) {
    if (b.size() > 64) {
      thread_local std::vector<double> vh, eh;
      vh.resize(b.size());
      eh.resize(b.size());
      v = vh.data();
      e = eh.data();
    }
    for (std::size_t i = 0; i < b.size(); ++i) {
      v[i] = b[i].value();
      e[i] = b[i].bound();
    }
  }
  WorkingRows(const WorkingRows&) = delete;
  WorkingRows& operator=(const WorkingRows&) = delete;
};

// One step of a triangle, (a, ea), (b, eb) -> (s a + t b, its bound), in the two bounds above: the running
// bound (the header's statement; the factor of its levels is applied where an output is final) and the a-priori
// one (on w = e + Γ|b|, scaled at the end). The value is the same plain-double s a + t b in both.
struct TriangleStep {
  double sv, sa, se, tv, ta, te;
  bool mid;  // the midpoint: the weights exactly 1/2 (below)
  TriangleStep(const BD& s, const BD& t)
      : sv(s.value()),
        sa(std::fabs(sv)),
        se(s.bound()),
        tv(t.value()),
        ta(std::fabs(tv)),
        te(t.bound()),
        mid(tv == 0.5 && te == 0 && sv == 0.5) {}
  void running(double a, double ea, double b, double eb, double& v, double& e) const {
    const double x = sv * a, y = tv * b, nw = x + y;
    e = sa * ea + se * (std::fabs(a) + ea) + ta * eb + te * (std::fabs(b) + eb) +
        (kU * (std::fabs(x) + std::fabs(y) + std::fabs(nw)) + 2.0 * kTiny);
    v = nw;
  }
  // The midpoint (bisection's split): t* = 1/2 exactly (t's bound is zero) and so s* = 1 - t* = 1/2 (the
  // triangle's contract, as for the a-priori bound; s = fl(1 - 1/2) = 1/2). Both products are exact halvings
  // (but for underflow, at most 2^-1075 each), so the step's only rounding is the sum's: the exact step
  // (a* + b*) / 2 is within u|v| + (ea + eb) / 2 + 2^-1074 of v. The same plain-double value as `running`;
  // its bound is at most `running`'s (no rounding terms of the products, no terms in s's bound), at most 4
  // roundings deep per level (inside running_factor's 8).
  void midpoint(double a, double ea, double b, double eb, double& v, double& e) const {
    const double x = sv * a, y = tv * b, nw = x + y;
    e = (0.5 * ea + 0.5 * eb) + (kU * std::fabs(nw) + 2.0 * kTiny);
    v = nw;
  }
  void apriori(double a, double ea, double b, double eb, double& v, double& e) const {
    const double x = sv * a, y = tv * b;
    e = (sv * ea + tv * eb) + kTiny;
    v = x + y;
  }
  // The running bound's factor for an output reached after `levels` levels.
  static double running_factor(int levels) { return 1.0 + (8.0 * levels + 8.0) * 0x1p-51; }
};

// The triangle's n rounds in place on the rows v, e (round r: entry i <- step(entry i, entry i + 1) for
// i = 0..n - r), the a-priori step where `ap` applies (e already holds w), else the running one; after round
// r, `round(r, factor)` may read the entries final from that round on (0 and n - r), whose bounds are e times
// factor.
template <class Round>
inline void triangle_rounds(double* __restrict vp, double* __restrict ep, int n, const TriangleStep& st,
                            const AprioriTriangle& ap, Round&& round) {
  if (st.mid) {  // exact weights: the running bound of a sum only (tighter than the a-priori one, as cheap)
    for (int r = 1; r <= n; ++r) {
      for (int i = 0; i + r <= n; ++i) st.midpoint(vp[i], ep[i], vp[i + 1], ep[i + 1], vp[i], ep[i]);
      round(r, TriangleStep::running_factor(r));
    }
    return;
  }
  if (ap.ok) {
    for (int r = 1; r <= n; ++r) {
      for (int i = 0; i + r <= n; ++i) st.apriori(vp[i], ep[i], vp[i + 1], ep[i + 1], vp[i], ep[i]);
      round(r, ap.scale);
    }
    return;
  }
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i + r <= n; ++i) st.running(vp[i], ep[i], vp[i + 1], ep[i + 1], vp[i], ep[i]);
    round(r, TriangleStep::running_factor(r));
  }
}

// w_i = e_i + Γ|b_i|: the rows the a-priori triangle runs on.
inline void apriori_rows(double* v, double* e, std::size_t count, const AprioriTriangle& ap) {
  for (std::size_t i = 0; i < count; ++i) e[i] = e[i] + ap.gamma * std::fabs(v[i]);
}

// The products of convolve below on plain arrays: values xv, yv, bounds xe, ye, and yae = |yv| + ye; rv, mu
// and E (x.size() + y.size() - 1 entries, zero on entry) receive the value sums, the sums of |p| + |r| and the
// propagated bounds. The arrays do not overlap, and the parameters say so (__restrict, honoured for the
// parameters of a function that is not inlined): the compiler then runs the inner loop on vectors, each lane
// one output with its own products and sums in the scalar loop's order, so the values are bit for bit the
// scalar ones.
[[gnu::noinline]] inline void convolve_arrays(std::size_t m1, std::size_t n1, const double* __restrict xv,
                                              const double* __restrict xe, const double* __restrict yv,
                                              const double* __restrict ye, const double* __restrict yae,
                                              double* __restrict rv, double* __restrict mu, double* __restrict E) {
  for (std::size_t i = 0; i < m1; ++i) {
    const double a = xv[i], aa = std::fabs(a), ae = xe[i];
    double* __restrict r = rv + i;
    double* __restrict m = mu + i;
    double* __restrict e = E + i;
    for (std::size_t j = 0; j < n1; ++j) {
      const double p = a * yv[j];
      const double s = r[j] + p;
      r[j] = s;
      m[j] += std::fabs(p) + std::fabs(s);
      e[j] += aa * ye[j] + ae * yae[j];
    }
  }
}

// out[k] = sum_{i+j=k} x[i] * y[j], accumulated i outer, j inner from 0 (the
// generic loop's order); out.size() == x.size() + y.size() - 1.
inline void convolve(std::span<const BD> x, std::span<const BD> y, std::span<BD> out) {
  const std::size_t m1 = x.size(), n1 = y.size(), K = out.size();
  thread_local std::vector<double> buf;
  if (buf.size() < 2 * m1 + 3 * n1 + 3 * K) buf.resize(2 * m1 + 3 * n1 + 3 * K);  // grows once per thread
  double* xv = buf.data();
  double* xe = xv + m1;
  double* yv = xe + m1;
  double* ye = yv + n1;
  double* yae = ye + n1;
  double* rv = yae + n1;
  double* mu = rv + K;
  double* E = mu + K;
  std::fill(rv, rv + 3 * K, 0.0);  // the sums start at zero; the inputs are all written below
  for (std::size_t i = 0; i < m1; ++i) {
    xv[i] = x[i].value();
    xe[i] = x[i].bound();
  }
  for (std::size_t j = 0; j < n1; ++j) {
    yv[j] = y[j].value();
    ye[j] = y[j].bound();
    yae[j] = std::fabs(yv[j]) + ye[j];
  }
  convolve_arrays(m1, n1, xv, xe, yv, ye, yae, rv, mu, E);
  for (std::size_t k = 0; k < K; ++k) {
    const std::size_t lo = k + 1 > n1 ? k + 1 - n1 : 0, hi = std::min(k, m1 - 1);
    const double terms = hi >= lo ? double(hi - lo + 1) : 0.0;
    const double b = (E[k] + kU * mu[k] + terms * kTiny) * (1.0 + (terms + 8.0) * 0x1p-50);
    out[k] = BD(rv[k], b);
  }
}

// The de Casteljau triangle at t in place on w (s = 1 - t, both with their
// bounds, as the generic loop computes them). If left is non-null, left[r]
// receives w[0] after round r (r = 0..n): split()'s left piece; w ends as
// the right piece (its entry i after round n - i), or w[0] as the value at t.
inline void de_casteljau(std::span<BD> w, const BD& s, const BD& t, BD* left) {
  const int n = int(w.size()) - 1;
  WorkingRows rows{std::span<const BD>(w)};
  const TriangleStep st(s, t);
  const AprioriTriangle ap = apriori_triangle(s, t, n, kAprioriMaxDegreeSplit);
  if (ap.ok) apriori_rows(rows.v, rows.e, w.size(), ap);
  if (left) left[0] = w[0];
  const double* v = rows.v;
  const double* e = rows.e;
  triangle_rounds(rows.v, rows.e, n, st, ap, [&](int r, double factor) {
    if (left) left[r] = BD(v[0], e[0] * factor);
    w[n - r] = BD(v[n - r], e[n - r] * factor);  // final from this round on (split's right piece; w[0]: the value)
  });
}

// The value at t of the polynomial with Bernstein coefficients b (s = 1 - t,
// both with their bounds): de_casteljau's triangle above without its split,
// read from b and written nowhere else, so that an evaluation costs no copy of
// b and no initialised working row (the 3D method evaluates many polynomials
// of low degree: measured, the copy and the zeroed row were a quarter of the
// guarded paper-002 run). The same products, sums and bound per step as
// de_casteljau, so the same value and bound, bit for bit.
// An upper bound of sum_i C(n,i) s*^(n-i) t*^i w_i for w_i >= 0 in O(n),
// where the triangle would take O(n^2): with a = max(s, t) >= 1/2 and
// x = min(s, t) / a <= 1, the sum is a^n times a polynomial in x with
// non-negative coefficients C(n,i) w_i (binom: C(n, .), exact integers for
// n <= 56), evaluated by Horner's rule. No term cancels, so each rounding
// (4n + 4 of them on a term's path: x, the Horner products and sums, the
// products C(n,i) w_i, the powers of a, the final product) and each factor
// s or t (2n on a path, with relative errors at most ρ) scales a term by at
// least (1 - u) resp. (1 - ρ): the computed sum is at least (1 - L') times
// the exact one, L' = 2nρ + (4n + 4)u, and is divided by that. Products that
// underflow (x^i near t = 0) lose at most 2^-1075 each: kTiny per step.
// Returns -1 when it does not apply (n > 56, L' > 2^-10).
inline double bernstein_sum_nonnegative(const double* w, int n, const double* binom, double sv, double tv, double rho) {
  if (n > 56) return -1;
  const double Lp = (2.0 * n * rho + (4.0 * n + 4.0) * kU) * (1.0 + 0x1p-50);
  if (!(Lp <= 0x1p-10)) return -1;
  const bool rev = tv > sv;
  const double a = rev ? tv : sv, x = (rev ? sv : tv) / a, y = x * x;
  // Horner's rule in y = x^2 on the terms of even and of odd power, two independent chains (a single chain's
  // latency was most of this sum's time): sum = E(y) + x O(y). A term of power i passes through at most i/2
  // Horner steps (two roundings each) and i/2 roundings of y, and carries x's errors i times, as in one
  // chain: inside the count above.
  auto c = [&](int p) {  // the coefficient of x^p
    const int i = rev ? n - p : p;
    return binom[i] * w[i];
  };
  int top = n;
  double even = 0, odd = 0;
  if (top % 2) {  // the odd chain starts one power higher
    odd = c(top);
    --top;
  }
  even = c(top);
  for (int p = top - 2; p >= 0; p -= 2) {
    even = even * y + c(p);
    odd = odd * y + c(p + 1);
  }
  const double acc = even + x * odd;
  double an = 1, base = a;  // a^n by squaring: at most 2 log2(n) roundings, fewer than n
  for (int k = n; k > 0; k >>= 1) {
    if (k & 1) an *= base;
    base *= base;
  }
  return acc * an / (1.0 - Lp) * (1.0 + 0x1p-48) + (2.0 * n + 2.0) * kTiny;
}

// A value is one sign read, so above kAprioriMaxDegree it takes the a-priori bound where that bound already
// decides the sign (|value| > bound), and only where it does not, the running triangle (tighter where signs
// mix) is run too: both bound the error of the same plain-double value, so the smaller one is kept.
inline BD de_casteljau_value(std::span<const BD> b, const BD& s, const BD& t, const double* binom = nullptr) {
  const int n = int(b.size()) - 1;
  if (n == 0) return b[0];
  const TriangleStep st(s, t);
  const AprioriTriangle ap = apriori_triangle(s, t, n, std::numeric_limits<int>::max());
  double apriori_bound = std::numeric_limits<double>::infinity(), value = 0;
  {
    WorkingRows rows(b);
    double* __restrict vp = rows.v;
    if (ap.ok) {
      apriori_rows(rows.v, rows.e, b.size(), ap);
      // The bound's sum in O(n) where it applies (the value's triangle is then the plain one), else its triangle.
      const double rho =
          std::max(s.value() > 0 ? s.bound() / s.value() : 0.0, t.value() > 0 ? t.bound() / t.value() : 0.0) *
          (1.0 + 0x1p-50);
      const double E = binom ? bernstein_sum_nonnegative(rows.e, n, binom, st.sv, st.tv, rho) : -1.0;
      if (E >= 0) {  // the value's triangle alone: the plain one
        for (int r = 1; r <= n; ++r)
          for (int i = 0; i + r <= n; ++i) {
            const double x = st.sv * vp[i], y = st.tv * vp[i + 1];
            vp[i] = x + y;
          }
        value = rows.v[0];
        apriori_bound = E * ap.scale;
      } else {
        double factor = 1;
        triangle_rounds(rows.v, rows.e, n, st, ap, [&](int, double f) { factor = f; });
        value = rows.v[0];
        apriori_bound = rows.e[0] * factor;
      }
      if (n <= kAprioriMaxDegree || std::fabs(value) > apriori_bound) return BD(value, apriori_bound);
    }
  }
  WorkingRows rows(b);  // the running triangle: where no a-priori bound applies, or it leaves the sign open
  double factor = 1;
  triangle_rounds(rows.v, rows.e, n, st, AprioriTriangle{}, [&](int, double f) { factor = f; });
  return BD(rows.v[0], std::min(rows.e[0] * factor, apriori_bound));
}

// Degree elevation by r of q (kernel/bernstein.hpp, elevate_into) when the
// binomial rows cn = C(n, .), cr = C(r, .), cnr = C(n + r, .) are exact
// integers (n + r <= 56, kernel/binomial.hpp): the values by the generic
// loop's operations in its order (term = (cn_j cr_(k-j)) q_j, summed from the
// lowest j, divided by cnr_k), so bit for bit the same. The bound is the
// a-priori one of a convex combination (the weights cn_j cr_(k-j) / cnr_k sum
// to 1, Vandermonde): each value is sum W_j q_j (1 + θ_j) with |θ_j| <= γ_K,
// K = terms + 3 (the binomials' product, the product with q_j, the sums, the
// division), so its error is at most sum W_j (e_j + γ_K |q_j|): the same
// elevation applied to w_j = e_j + γ_K |q_j| >= 0, which computed by the same
// operations is at least (1 - u)^(K + 2) times that sum (two roundings in
// w_j): scaled by 1 / (1 - (K + 2) u). Underflow: kTiny per term. Against
// the running bound of Bounded's operators (per operation 4 products, 5 sums
// and 3 absolute values beside the value's), two products, a sum and a
// division per term.
inline void elevate_exact_binomials(std::span<const BD> q, int r, const BD* cn, const BD* cr, const BD* cnr,
                                    std::vector<BD>& out) {
  const int n = int(q.size()) - 1;
  const double K = double(std::min(n, r) + 1) + 3.0;
  const double gamma = K * kU / (1.0 - K * kU) * (1.0 + 0x1p-50);
  const double scale = (1.0 + 0x1p-48) / (1.0 - (K + 2.0) * kU);
  double ws[64];
  thread_local std::vector<double> wh;
  double* w = ws;
  if (q.size() > 64) {
    wh.resize(q.size());
    w = wh.data();
  }
  for (int j = 0; j <= n; ++j) w[j] = q[j].bound() + gamma * std::fabs(q[j].value());
  out.resize(n + r + 1);
  for (int k = 0; k <= n + r; ++k) {
    double acc = 0, bnd = 0;
    const int lo = std::max(0, k - r), hi = std::min(n, k);
    for (int j = lo; j <= hi; ++j) {
      const double c = cn[j].value() * cr[k - j].value();
      acc = acc + c * q[j].value();
      bnd = bnd + c * w[j];
    }
    const double d = cnr[k].value();
    out[k] = BD(acc / d, (bnd / d + double(hi - lo + 1) * kTiny) * scale);
  }
}

// The de Casteljau rounds of a tensor-product net along its first index, on
// every column at once (a BiBern's keep_u_right / keep_u_left): rows f[0..m]
// of equal length; right: round r sets f[i] <- s f[i] + t f[i + 1] for
// i = 0..m - r (f ends as the piece on [t, 1]); left: f[i] <- s f[i - 1] + t f[i]
// for i = m down to r (the piece on [0, t]). The same products and sums per
// column as de_casteljau above, so the same bound per step; every entry is at
// most m levels deep, and all of them take the factor of m levels at the end.
inline void de_casteljau_rows(std::vector<std::vector<BD>>& f, const BD& s, const BD& t, bool left) {
  const int m = int(f.size()) - 1;
  if (m <= 0) return;
  const std::size_t cols = f[0].size();
  thread_local std::vector<double> v, e;
  v.resize(std::size_t(m + 1) * cols);
  e.resize(v.size());
  for (int i = 0; i <= m; ++i)
    for (std::size_t j = 0; j < cols; ++j) {
      v[i * cols + j] = f[i][j].value();
      e[i * cols + j] = f[i][j].bound();
    }
  const TriangleStep st(s, t);
  const AprioriTriangle ap = apriori_triangle(s, t, m, kAprioriMaxDegreeSplit);
  if (ap.ok) apriori_rows(v.data(), e.data(), v.size(), ap);
  // Row d <- s row a + t row b, column by column (d is a or b: each column reads before it writes).
  auto step = [&](int d, int a, int b) {
    double *vd = v.data() + d * cols, *ed = e.data() + d * cols;
    const double *va = v.data() + a * cols, *ea = e.data() + a * cols, *vb = v.data() + b * cols,
                 *eb = e.data() + b * cols;
    if (st.mid)
      for (std::size_t j = 0; j < cols; ++j) st.midpoint(va[j], ea[j], vb[j], eb[j], vd[j], ed[j]);
    else if (ap.ok)
      for (std::size_t j = 0; j < cols; ++j) st.apriori(va[j], ea[j], vb[j], eb[j], vd[j], ed[j]);
    else
      for (std::size_t j = 0; j < cols; ++j) st.running(va[j], ea[j], vb[j], eb[j], vd[j], ed[j]);
  };
  for (int r = 1; r <= m; ++r) {
    if (left)
      for (int i = m; i >= r; --i) step(i, i - 1, i);
    else
      for (int i = 0; i + r <= m; ++i) step(i, i, i + 1);
  }
  // The a-priori bound covers every entry but the row no round writes (its input bound, not w's); the running
  // bound's factor of m levels covers every entry.
  const double factor = ap.ok ? ap.scale : TriangleStep::running_factor(m);
  const int untouched = ap.ok ? (left ? 0 : m) : -1;
  for (int i = 0; i <= m; ++i)
    if (i != untouched)
      for (std::size_t j = 0; j < cols; ++j) f[i][j] = BD(v[i * cols + j], e[i * cols + j] * factor);
}

// Horner's rule r <- r t + c_i from the leading coefficient (Higham section
// 5.1's running error bound, with errors in t and in the c_i): one step
// carries |r| et + |t| er + er et + e_ci + u (|r t| + |r t + c_i|), at most
// 8 roundings deep per step like a de Casteljau level.
inline BD horner(std::span<const BD> c, const BD& t) {
  const int n = int(c.size()) - 1;
  if (n < 0) return BD(0);
  const double tv = t.value(), ta = std::fabs(tv), te = t.bound();
  double r = c[n].value(), e = c[n].bound();
  for (int i = n - 1; i >= 0; --i) {
    const double p = r * tv, s = p + c[i].value();
    e = std::fabs(r) * te + ta * e + e * te + c[i].bound() + (kU * (std::fabs(p) + std::fabs(s)) + kTiny);
    r = s;
  }
  return BD(r, e * (1.0 + (8.0 * n + 8.0) * 0x1p-51));
}

// sum_{i=0..terms-1} (a[i] * c[i]) / d[i], accumulated from 0 in order (the
// power-to-Bernstein conversion's inner loop, kernel/bernstein.hpp). The
// quotient's bound is Bounded's: (|p| ed + |d| ep) / (|d| (|d| - ed)) + u|q|,
// infinite where |d| <= ed; a rounding of the denominator makes it at most
// (1 + u) times larger, so its quotient at least (1 - u) times smaller: the
// same count of roundings as above, at most 14 + terms deep.
// f, if given, holds per divisor the two factors of that bound (divisor_factors
// below): the quotient's bound is then formed as |p| f.alpha[i] + ep f.beta[i],
// two products instead of a second division, so that a term costs the plain
// division of its value and no other. Each factor is at least (1 - u)^4 times
// its exact value (four roundings of non-negative quantities, each in the
// direction that could make it smaller), as many as the division route's
// difference, product and quotient and one product more: inside the same count.
struct DivisorFactors {
  std::vector<double> alpha, beta;  // per divisor: ed / (|d| (|d| - ed)) and 1 / (|d| - ed), both rounded
};
inline BD sum_of_ratios(const BD* a, const BD* c, const BD* d, int terms, const DivisorFactors* f = nullptr) {
  double acc = 0, E = 0, mu = 0;
  const double* alpha = f ? f->alpha.data() : nullptr;
  const double* beta = f ? f->beta.data() : nullptr;
  for (int i = 0; i < terms; ++i) {
    const double av = a[i].value(), cv = c[i].value(), dv = d[i].value();
    const double ae = a[i].bound(), ce = c[i].bound();
    const double p = av * cv, q = p / dv;
    acc = acc + q;
    const double pa = std::fabs(p);
    const double ep = std::fabs(av) * ce + std::fabs(cv) * ae + ae * ce + (kU * pa + kTiny);
    if (f) {
      E += pa * alpha[i] + ep * beta[i];
    } else {
      const double da = std::fabs(dv), de = d[i].bound();
      if (!(da > de))
        E = std::numeric_limits<double>::infinity();
      else
        E += (pa * de + da * ep) / (da * (da - de));
    }
    mu += std::fabs(q) + std::fabs(acc);
  }
  return BD(acc, (E + kU * mu + double(terms) * 2.0 * kTiny) * (1.0 + (double(terms) + 16.0) * 0x1p-50));
}

// The factors of each quotient's bound by d[i] into out (see sum_of_ratios): for a divisor without error
// alpha = 0 and beta = fl(1 / |d|); else, with w = fl(1 / fl(|d| fl(|d| - ed))), alpha = fl(ed w) and
// beta = fl(|d| w). False if some |d[i]| <= ed[i] or a value is not finite: the quotient's bound is then
// infinite or the factors meaningless, and sum_of_ratios takes the division route.
inline bool divisor_factors(std::span<const BD> d, DivisorFactors& out) {
  out.alpha.resize(d.size());
  out.beta.resize(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double da = std::fabs(d[i].value()), de = d[i].bound();
    if (!(da > de) || !std::isfinite(da) || !std::isfinite(de)) return false;
    if (de == 0) {
      out.alpha[i] = 0;
      out.beta[i] = 1.0 / da;
    } else {
      const double w = 1.0 / (da * (da - de));
      out.alpha[i] = de * w;
      out.beta[i] = da * w;
    }
    if (!std::isfinite(out.alpha[i]) || !std::isfinite(out.beta[i])) return false;
  }
  return true;
}

}  // namespace eccd::running_error_loops
