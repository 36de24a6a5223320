#pragma once
// Real roots in [0, 1] of a polynomial in Bernstein form, by de Casteljau
// subdivision, in rounded arithmetic.
//
// Statement. 003 section VI-C (Variants 2 and 3): subdivide Δ(t) by de
// Casteljau and discard a piece whose Bernstein coefficients all have one
// strict sign (convex hull property). Here a piece whose coefficients have
// exactly one sign change and whose end values have opposite strict signs
// holds exactly one simple root (Descartes' rule for the Bernstein basis), and
// is refined by modified regula falsi to the working precision: from degree 16
// upward each step's value is O(n) (Horner in t/(1-t):
// kernel/bernstein_horner.hpp), the first point is where the control polygon
// crosses zero and the damping is Anderson-Björck's; below degree 16 the steps
// are Illinois' from the ends on de Casteljau values. The
// subdivision stays de Casteljau. A piece narrower than
// `cluster_width` that is neither is reported as a root cluster (a double
// root, as at a touch, or roots closer than the arithmetic can separate);
// roots closer than cluster_width to each other are merged into one cluster. `first_only` stops after the leftmost root
// (Variant 2). Nothing here is certified: with rounded coefficients a
// reported root may be spurious and a double root may be missed; that is what
// the harness measures against the exact pipeline.
// Work bound: at most `max_pieces` pieces are examined, and the
// run's deadline (kernel/budget.hpp) is asked once per piece and once per
// refinement step of a simple root (a root whose refinement it stops is
// reported unresolved, with its piece). When either is
// hit, every piece not yet examined (in order, leftmost first) is reported as
// an `unresolved` root cluster covering it, and `stopped` says why: the
// caller turns those into undecided instants, never into an answer. A
// polynomial whose coefficients are not all finite is unresolved on [0, 1].
// Requirements on T: +, -, *, comparison, scalar_traits<T> (precision).
// Known failure modes: a double root perturbed by ε splits or vanishes at
// distance ~ sqrt(ε), so roots closer than cluster_width = 2^-min(p/2+2, 64)
// are merged; when the rounding noise of Δ is far above 2^-p a double root
// can still split into two reported roots.
#include "number/pow2_scaling.hpp"
#include "number/running_error.hpp"
#include "kernel/bernstein.hpp"
#include "kernel/bernstein_horner.hpp"
#include "kernel/budget.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace eccd {

template <class T>
struct FloatRoot {
  T lo, hi, value;          // the root lies in [lo, hi] as far as rounded arithmetic can tell
  bool cluster = false;     // true: a multiple root or an unresolved cluster
  bool unresolved = false;  // true: the work bound or the deadline stopped the search here (roots unknown)
};

template <class T>
struct BernsteinRootOptions {
  int precision_bits = 53;
  // Where a simple root is refined to: 2^-(simple_bits - 3) of its piece (0: precision_bits). Clusters and the
  // merging of close roots follow precision_bits either way. A caller that needs only a witness near the
  // root (bern_argmax: the peak's u) asks for fewer bits than the arithmetic has.
  int simple_bits = 0;
  bool first_only = false;
  long max_pieces = 20000;      // work bound: pieces examined (de Casteljau splits are O(n^2) each)
  mutable std::string stopped;  // out: "" or why the search stopped early
};

// Where the control polygon of b (one sign change, b.front() of sign sa) crosses zero,
// in [0, 1]: an evaluation point only (its error does not matter); 1/2 if it cannot be formed.
template <class T>
T control_polygon_zero(std::span<const T> b, Sign sa, const T& half) {
  const int n = int(b.size()) - 1;
  int i = 0;  // the last coefficient of sign sa before the change
  for (int k = 1; k <= n; ++k) {
    Sign sk = sign(b[k]);
    if (sk == sa) {
      i = k;
      continue;
    }
    if (sk == Sign::zero) continue;
    T d = b[i] - b[k];
    T x = (T(i) + T(k - i) * (b[i] / d)) / T(n);
    return x > T(0) && x < T(1) ? x : half;
  }
  return half;
}

// Modified regula falsi (Anderson-Björck) on a piece b with exactly one simple
// root and end signs sa, -sa: [lo, hi] ⊂ [0, 1] around the root, narrower than
// `width` unless a value's sign is unknown or zero, `max_iter` steps, or the
// deadline (out_of_time). Only the values' signs are read (value_sign).
template <class V>
std::pair<V, V> refine_simple_root(std::span<const V> b, Sign sa, int max_iter, const V& width, const V& zero,
                                   const V& one, const V& half, bool low_degree, bool& out_of_time) {
  V lo = zero, hi = one, flo = b.front(), fhi = b.back();
  int side = 0;
  // The piece's values in O(n) each from degree 16 on (kernel/bernstein_horner.hpp:
  // the same order of error as de Casteljau's triangle, which it falls back to).
  const BernsteinHorner<V> piece_value{b};
  // With the O(n) values (degree >= 16; below, the steps are Illinois' from the
  // ends on de Casteljau values): the first point is where the control polygon
  // crosses zero (close to the curve once one sign change is left; from the end
  // values alone the secant crept towards a root near an end by doubling steps,
  // ~8 of ~16 evaluations at n = 144), and the damping is Anderson-Björck's (below).
  const bool fast = piece_value.linear();
  const V x_first = fast ? point_of(control_polygon_zero(b, sa, half)) : half;
  for (int it = 0; it < max_iter && hi - lo > width; ++it) {
    // Each step evaluates the piece; at degree ~100 in MPFR the up to 4p steps
    // took seconds past the deadline: ask it every step, except below degree 8,
    // where eight steps cost less than the clock read they would each add.
    if ((low_degree ? it % 8 == 0 : true) && deadline_passed()) {
      out_of_time = true;
      break;
    }
    V den = fhi - flo;
    V x = it == 0 && fast
              ? x_first
              : point_of(V((lo * fhi - hi * flo) / den));  // an evaluation point: its own error does not matter
    if (!(x > lo && x < hi)) x = point_of(V(half * (lo + hi)));
    V fx = piece_value(x);
    Sign sx = value_sign(fx);
    if (sx == Sign::uncertain) break;
    if (sx == Sign::zero) {
      lo = x;
      hi = x;
      break;
    }
    // An end kept twice has its value scaled: Illinois by 1/2; Anderson-Björck
    // (fast) by m = 1 - f(x)/f(replaced end), 1/2 if that is not in (0, 1):
    // with Illinois' fixed 1/2 the last steps crawled by halvings.
    auto damp = [&](const V& f_new, const V& f_old) {
      if (!fast) return half;
      V m = one - f_new / f_old;
      return m > zero && m < one ? m : half;
    };
    if (sx == sa) {
      if (side == -1) fhi = damp(fx, flo) * fhi;
      lo = x;
      flo = fx;
      side = -1;
    } else {
      if (side == 1) flo = damp(fx, fhi) * flo;
      hi = x;
      fhi = fx;
      side = 1;
    }
  }
  return {lo, hi};
}

// A piece of the subdivision: q, the polynomial's Bernstein coefficients on [a, b] ⊂ [0, 1].
template <class T>
struct BernPiece {
  Bern<T> q;
  T a, b;
};

// Every coefficient of one strict sign: no root in the piece (convex hull property).
template <class T>
bool strict_one_sign(const Bern<T>& q) {
  Sign s0 = sign(q.b.front());
  if (s0 == Sign::zero || s0 == Sign::uncertain) return false;
  for (const auto& x : q.b)
    if (sign(x) != s0) return false;
  return true;
}

// Appends r to the roots found so far (leftmost first). A root closer to the previous one than the arithmetic can
// separate two roots (a perturbed double root splits by ~sqrt(eps)), or an unresolved one after an unresolved
// one, joins it: one cluster.
template <class T>
void add_float_root(std::vector<FloatRoot<T>>& out, FloatRoot<T> r, const T& cluster_width, const T& half) {
  if (!out.empty() && (!(r.lo - out.back().hi > cluster_width) || (r.unresolved && out.back().unresolved))) {
    out.back().unresolved = out.back().unresolved || r.unresolved;
    out.back().hi = r.hi;
    out.back().value = point_of(T(half * (out.back().lo + out.back().hi)));
    out.back().cluster = true;
    return;
  }
  out.push_back(std::move(r));
}

// The piece pc holds exactly one simple root (end signs sa and -sa): modified regula falsi (Anderson-Björck),
// which converges superlinearly, down to the working precision (simple_width of the piece). The root is proved to
// be in the piece; only its location is refined, by the values' signs, so under a running bound this runs in the
// plain arithmetic (the same values). A root the deadline stops is unresolved (and opt.stopped says so).
template <class T>
FloatRoot<T> located_simple_root(const BernPiece<T>& pc, Sign sa, const BernsteinRootOptions<T>& opt,
                                 const T& simple_width, const T& zero, const T& one, const T& half, bool low_degree) {
  using P = PlainOf<T>;
  using V = typename P::type;
  std::span<const V> values;
  if constexpr (has_error_bound_v<T>) {
    thread_local std::vector<V> plain;
    plain.clear();
    for (const auto& x : pc.q.b) plain.push_back(P::of(x));
    values = std::span<const V>(plain);
  } else {
    values = std::span<const V>(pc.q.b);
  }
  bool out_of_time = false;
  auto [lo_v, hi_v] = refine_simple_root<V>(values, sa, 4 * opt.precision_bits, P::of(simple_width), P::of(zero),
                                            P::of(one), P::of(half), low_degree, out_of_time);
  const T lo = P::lift(lo_v), hi = P::lift(hi_v);
  const T w = pc.b - pc.a;
  T rlo = point_of(T(pc.a + w * lo)), rhi = point_of(T(pc.a + w * hi));
  if (out_of_time) {  // a root is in [rlo, rhi], but not located to the working precision: unresolved
    opt.stopped = deadline_reason();
    return {rlo, rhi, point_of(T(half * (rlo + rhi))), true, true};
  }
  return {rlo, rhi, point_of(T(half * (rlo + rhi))), false};
}

template <class T>
std::vector<FloatRoot<T>> bernstein_roots(const Bern<T>& p, const BernsteinRootOptions<T>& opt) {
  const T& like = like_of(p.b);
  const T zero = scalar_traits<T>::from_rational(mpq_class(0), like);
  const T one = scalar_traits<T>::from_rational(mpq_class(1), like);
  // 2^e as a T of the run's precision: 1 scaled by a power of two, exact in
  // every rounded T, so the same value (and zero error bound) as converting
  // the rational 2^e, without a GMP conversion per constant (the
  // Bézier method calls this for every static test).
  auto pow2 = [&](int e) { return T(times_pow2(one, long(e))); };
  // Below this width a piece that still may hold roots is a cluster: roots
  // this close cannot be told from a double root in p-bit arithmetic, and
  // deeper subdivision (O(n²) per level) would not make a double root better
  // conditioned. Capped at 2^-64: cluster instants are reported to ~5e-20.
  const T cluster_width = pow2(-std::min(opt.precision_bits / 2 + 2, 64));
  const T simple_width = pow2(-((opt.simple_bits > 0 ? opt.simple_bits : opt.precision_bits) - 3));
  const T half = pow2(-1);
  std::vector<FloatRoot<T>> out;
  auto add = [&](FloatRoot<T> r) { add_float_root(out, std::move(r), cluster_width, half); };

  std::vector<BernPiece<T>> stack;  // depth-first, leftmost first
  for (const auto& x : p.b)
    if (!is_finite_value(x)) {  // NaN or Inf: nothing can be decided
      opt.stopped = "non-finite coefficient";
      out.push_back({zero, one, half, true, true});
      return out;
    }
  stack.push_back({p, zero, one});
  long pieces = 0;
  const bool low_degree = p.degree() < 8;
  while (!stack.empty()) {
    if (++pieces > opt.max_pieces || deadline_passed()) {
      opt.stopped = deadline_passed()
                        ? deadline_reason()
                        : "root isolation stopped at its work bound of " + std::to_string(opt.max_pieces) + " pieces";
      while (!stack.empty()) {  // leftmost first: what is left is unresolved
        BernPiece<T> rest = std::move(stack.back());
        stack.pop_back();
        if (strict_one_sign(rest.q)) continue;
        add({rest.a, rest.b, half * (rest.a + rest.b), true, true});
      }
      break;
    }
    BernPiece<T> pc = std::move(stack.back());
    stack.pop_back();
    if (opt.first_only && !out.empty() && pc.a > out.back().hi) break;  // leftmost root is final
    if (strict_one_sign(pc.q)) continue;
    T w = pc.b - pc.a;
    if constexpr (has_error_bound_v<T>) {
      // Every coefficient within its error bound of 0: the polynomial is noise
      // here, and subdivision cannot make the bound smaller; a cluster (its
      // signs are uncertain to the caller).
      bool all_uncertain = true;
      for (const auto& x : pc.q.b) all_uncertain = all_uncertain && sign(x) == Sign::uncertain;
      if (all_uncertain) {
        add({pc.a, pc.b, point_of(T(half * (pc.a + pc.b))), true});
        continue;
      }
    }
    Sign sa = sign(pc.q.b.front()), sb = sign(pc.q.b.back());
    // Descartes' rule needs every coefficient's sign: an uncertain one (a
    // running error bound) leaves the count unknown, and the piece is split.
    if (sign_variations(pc.q.b).is(1) && sa != Sign::zero && sb != Sign::zero && sa != sb) {
      add(located_simple_root(pc, sa, opt, simple_width, zero, one, half, low_degree));
    } else if (!(w > cluster_width)) {
      add({pc.a, pc.b, half * (pc.a + pc.b), true});
    } else {
      auto [l, r] = split(pc.q, half);
      T m = point_of(T(half * (pc.a + pc.b)));
      stack.push_back({std::move(r), m, pc.b});
      stack.push_back({std::move(l), pc.a, m});
    }
  }
  return out;
}

}  // namespace eccd
