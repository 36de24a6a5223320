#pragma once
// The Bézier zero-set analysis of F(u, t) = det((u-1)A(t) - uB(t)): 3D
// continuous collision detection without a projection polynomial, written
// once for every arithmetic.
//
// Statement. 001 section 4 ("CCD for moving ellipsoids", "Finding all
// collision intervals", "Finding the first contact time only"). At t0 the
// ellipsoids are separate iff F(u, t0) > 0 for some u in (0, 1)
// (kernel/ellipsoid_function.hpp). The method:
//  1. a first pass of static tests at samples+1 equally spaced instants;
//  2. between two samples that are both separate (001 case 1): Bézier
//     shooting BS[a -> b]: û = argmax F(., a) (a root of the cubic F_u), then
//     the first root t̂ of F(û, t) on [a, b] by Bézier clipping/subdivision of
//     the univariate Bernstein polynomial F(û, .): no root = a miss, and the
//     pair is separate on [a, b] (F(û, t) > 0 there); a hit is repeated from t̂
//     (iterative shooting, quadratic convergence at a regular contact, 001
//     Appendix B). Every hit t̂ is a lower bound of the first contact after a,
//     so the iteration converges to it. Shooting from both ends onto one
//     instant is a tangential touch; otherwise the gap is subdivided.
//     A miss needs F(û, .) > 0 on the whole of [t, b]. Rounded, the shot's
//     start F(û, t) is computed twice (the peak over u at t, and G(0) after
//     restricting F(û, .) to [t, b]); as t converges onto a contact both are
//     at the noise level and may differ in sign. An empty root list with
//     G(0) <= 0 must not be read as a miss (in the scene "missed-0.021"
//     both shots converge, the one from the far end would then "miss", and a
//     collision of 2 % of [0, 1] would be reported separate). A non-positive
//     G(0) means the shot has converged at t;
//  3. between two overlapping samples (case 2): all control points of F over
//     (0, 1) x [a, b] negative = overlap on [a, b]; else subdivide in t;
//  4. a transition (case 3): the Gaussian-circle test — all 2D control points
//     of ∇F = (F_u, F_t) over the part of (0, 1) x [a, b] where F may vanish
//     lie on one side of a line through the origin, so the zero-set has no
//     loop there — then iterative shooting from the separate end gives the
//     contact instant; if the test fails, subdivide at the midpoint.
// first_contact_only stops after the first collision interval (001's
// first-contact mode; the interval's end is still computed).
//
// Arithmetics. double and MPFR run all of the above; nothing is certified,
// and a gap that subdivision cannot close at the arithmetic's resolution
// (2^-min(p/2, 30), where a double root's instant is only known to ~sqrt(eps)) is
// reported as a touch if both sides are separate, or `uncertain`. The exact
// 3D pipeline is the projection (kernel/ccd_projection.hpp), not this method.
// Termination and honesty: g is scaled by a power of two first
// and a non-finite coefficient or control point makes [0, 1] undecided with
// the reason; when the subdivision cap (max_subdivisions) or the run's
// deadline is hit, every gap not yet resolved is an undecided cell (never a
// guess), and shots stop at the deadline. With a running error bound
// (T = Bounded<U>, number/running_error.hpp) static tests decide by signs
// sure under the bound (else uncertain): separate by a witness u with F(u, t0)
// surely positive, overlapping only by control points of F(., t0) that are all
// surely negative (split in u where needed), never by a negative value at the
// peak found (a peak located in rounded arithmetic can miss a narrow positive
// window: with a needle of semi-axes (1, 1e20, 1) a thousandth away that
// would read "collides"); misses of a shot are proofs; a pair of overlapping ends that no
// control net certifies is undecided (plain T accepts it below overlap_depth);
// and a touch found by two shots meeting is reported uncertain (a tangency
// cannot be told from a near-miss in rounded arithmetic).
// Requirements on T: an ordered field with scalar_traits<T>. Shooting and the
// Gaussian test need rounded T (the test's cross-product signs are taken of the
// gradients' control points rounded to double).
// Cost: the inner loops (static tests, shooting, Gaussian test) restrict and
// subdivide F in place and use the constants 0, 1, 1/2 made once per run
// (zero_, one_, half_) instead of converting rationals each time. Speed:
// the Gaussian test's u-pieces are made in buffers kept per depth (no heap
// in its recursion), the deadline is read on every 16th poll only (a poll
// comes once per shot iteration or gap, so a run overshoots its deadline by
// at most 15 of those), and only the instants that reach the answer or a
// cell are formatted as text (the others, about half, would be %.17g-printed and
// thrown away).
#include "floating/bernstein_peak.hpp"
#include "floating/bernstein_restrict.hpp"
#include "floating/bernstein_roots.hpp"
#include "floating/gauss_cone.hpp"
#include "kernel/budget.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/collision_timeline.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/quartic_status.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace eccd {

struct BezierOptions {
  int samples = 32;               // first pass: static tests at samples + 1 instants
  int max_shots = 64;             // iterations of one iterative Bézier shooting
  int gauss_depth = 5;            // the Gaussian-circle test splits u into 2^gauss_depth pieces
  int u_depth = 10;               // overlap certificates split u adaptively, at most this deep
  int max_depth = 40;             // t-subdivision depth below one sample interval
  long max_subdivisions = 20000;  // work cap for the whole run (then every open gap is closed as at the depth limit)
  int overlap_depth = 10;         // t-subdivision depth between two overlapping instants
  bool first_contact_only = false;
};

template <class T>
class BezierZeroSet {
 public:
  using Peak = eccd::Peak<T>;
  enum class ShotKind { miss, converged, inconclusive };
  struct Shot {
    ShotKind kind;
    T t;
  };

  // g: the coefficients g_0..g_4 of f(λ;t) in Bernstein form in t.
  BezierZeroSet(const std::vector<Bern<T>>& g, const T& like, int bits, BezierOptions opt)
      : g_(g), like_(like), bits_(bits), opt_(opt), F_(ellipsoid_function(g, like)) {
    zero_ = q(0);
    one_ = q(1);
    half_ = q(1, 2);
    eps_t_ = pow2(-(bits * 3 / 4));
    // Contacts closer than this are one tangential touch, and no interval is
    // split below it: a double root's instant is known to ~sqrt(eps) at best,
    // and shooting converges only linearly onto a tangency. It follows the
    // precision all the way (2^-(p/2); no fixed cap: a near-miss at 1e-14 is
    // not a touch at 4096 bits); where subdivision reaches its depth limit
    // before that, the instant is reported uncertain, not as a touch.
    touch_tol_ = pow2(-(bits / 2));
    noise_ = pow2(-(bits - 8));
    degree_u_ = F_.degree_u();
    for (int i = 0; i <= degree_u_; ++i) abscissa_.push_back(q(i, std::max(degree_u_, 1)));
  }

  const BiBern<T>& F() const { return F_; }
  long shots = 0, shot_iterations = 0, subdivisions = 0, gauss_tests = 0, gauss_passed = 0, overlap_certificates = 0,
       overlap_unverified = 0;
  std::string stopped;  // "" or why part of [0, 1] was left undecided (work bound, deadline)

  // argmax of F(., t0) on [0, 1] and the value there.
  Peak peak(const T& t0) const { return argmax(ellipsoid_function_at(F_, t0)); }

  // The static status at t0. Exact: Sturm (a proof); rounded: sign of max_u F(u, t0).
  Status status(const T& t0) const {
    if constexpr (scalar_traits<T>::is_exact) {
      return quartic_status_at(g_, t0);
    } else {
      Bern<T> f = ellipsoid_function_at(F_, t0);
      if constexpr (has_error_bound_v<T>) {
        // Before the peak (its root finding would be a quarter of a query),
        // two decisions that need none: every control point surely negative
        // (then F(., t0) < 0 on [0, 1] by the convex hull, and no peak could be
        // surely positive), or F surely positive at the abscissa i/m of the
        // largest control point (a witness u, which proves separation).
        bool negative = true;
        std::size_t top = 0;
        for (std::size_t i = 0; i < f.b.size(); ++i) {
          negative = negative && sign(f.b[i]) == Sign::negative;
          if (f.b[i] > f.b[top]) top = i;
        }
        if (negative) return Status::overlapping;
        if (f.degree() == degree_u_ && sign(f(abscissa_[top])) == Sign::positive) return Status::separate;
      }
      Peak p = argmax(f);
      if constexpr (has_error_bound_v<T>) {
        // With a running error bound the sign of the peak decides, or nothing does.
        // A peak value that is not certainly positive may still hide a separating u
        // elsewhere, so try the control points: all certainly negative = overlap.
        // A surely negative value at the peak found is no proof: the peak is
        // located in plain arithmetic, and a narrow positive window of F(., t0)
        // (a needle: semi-axes (1, 1e20, 1) a thousandth away, where F > 0 only
        // within ~1e-20 of u = 0) is missed by a witness that is off by more
        // than the window, which would read "overlapping" on an interval where
        // the solids never meet. Only the control points of F(., t0), split in
        // u where needed, prove overlap.
        // The split also finds such a window: an end control point of a piece
        // is F's value at that u, so a surely positive one is a witness.
        Sign s = sign(p.value);
        if (s == Sign::positive) return Status::separate;
        long pieces = 0;
        T witness = zero_;
        return classify_on_u(std::span<const T>(f.b), 0, pieces, zero_, one_, witness);
      }
      // A peak within rounding noise of 0 (relative to F(., t0)'s coefficients) is a touch as far
      // as this arithmetic can tell.
      T scale = zero_;
      for (const auto& x : f.b) {
        T ax = scalar_traits<T>::abs(x);
        if (ax > scale) scale = ax;
      }
      if (!(scalar_traits<T>::abs(p.value) > noise_ * scale)) return Status::touching;
      Sign s = sign(p.value);
      if (s == Sign::positive) return Status::separate;
      if (s == Sign::negative) return Status::overlapping;
      if (s == Sign::zero) return Status::touching;
      return Status::uncertain;
    }
  }

  // Certificate of overlap on [a, b]: every control point of F over
  // (0,1) x [a, b] negative, after splitting u into up to 2^gauss_depth pieces
  // (the control net in u alone is often too loose near u's ends).
  bool overlap_on(const T& a, const T& b) const { return negative_in_u(restrict_t(F_, a, b, one_), opt_.u_depth); }
  bool negative_in_u(const BiBern<T>& f, int depth) const {
    int s = f.strict_sign();
    if (s == -1) return true;
    if (s == 1 || depth == 0) return false;
    for (const auto& row : f.b)  // a positive control point on the boundary rows: F > 0 somewhere
      for (std::size_t j : {std::size_t(0), row.size() - 1})
        if (sign(row[j]) == Sign::positive && (&row == &f.b.front() || &row == &f.b.back())) return false;
    auto [lo, hi] = split_u(f, half_);
    return negative_in_u(lo, depth - 1) && negative_in_u(hi, depth - 1);
  }

  // One instant's F(., t0) (f, on a piece of [0, 1] in u) decided by its
  // control points alone: overlapping if every piece's control points are
  // surely negative (F < 0 on the piece, convex hull); separate if an end
  // control point of a piece (F's value at that u) is surely positive;
  // uncertain otherwise. Pieces are halved where neither holds, at most
  // kUDepth deep and kUPieces in all (a narrow positive window, as the
  // pencil's balancing by a power of two makes for a needle, sits within
  // 2^-33 of u = 0; only the pieces around it are split).
  static constexpr int kUDepth = 64;
  static constexpr long kUPieces = 1024;
  // f is F(., t0) on [u0, u1] (dyadic ends); `witness` receives the u of a
  // surely positive end control point when the answer is separate.
  // Both halves from one de Casteljau triangle (split_into, bit for bit keep_left / keep_right's),
  // on the stack for the small degrees of F in u (no allocation per level of a deep descent to a needle).
  Status classify_on_u(std::span<const T> f, int depth, long& pieces, const T& u0, const T& u1, T& witness) const {
    ++pieces;
    if (sign(f.front()) == Sign::positive) {
      witness = u0;
      return Status::separate;
    }
    if (sign(f.back()) == Sign::positive) {
      witness = u1;
      return Status::separate;
    }
    bool all = true, none = true;
    for (const auto& x : f) {
      const Sign s = sign(x);
      all = all && s == Sign::negative;
      none = none && s == Sign::uncertain;
    }
    if (all) return Status::overlapping;
    // No control point with a sign: under a running error bound (|b_i| <= e_i for every i) every piece split
    // from this one has none either (a split's entries are convex combinations, each bound at least the same
    // combination of the e_i), so no split can decide here: uncertain now, not after kUDepth levels or
    // kUPieces pieces (which the rest of [0, 1] in u keeps). Plain T never reads uncertain.
    if (none || depth >= kUDepth || pieces >= kUPieces) return Status::uncertain;
    auto halves = [&](std::span<T> lo, std::span<T> hi) {
      split_into(f, half_, lo, hi);
      const T um = point_of(T(half_ * (u0 + u1)));
      const Status a = classify_on_u(lo, depth + 1, pieces, u0, um, witness);
      if (a == Status::separate) return a;
      const Status b = classify_on_u(hi, depth + 1, pieces, um, u1, witness);
      if (b == Status::separate) return b;
      return a == Status::overlapping && b == Status::overlapping ? Status::overlapping : Status::uncertain;
    };
    constexpr std::size_t kStack = 12;
    if constexpr (std::is_trivially_copyable_v<T>) {
      if (f.size() <= kStack) {
        T lo[kStack], hi[kStack];
        return halves(std::span<T>(lo, f.size()), std::span<T>(hi, f.size()));
      }
    }
    std::vector<T> lo(f.begin(), f.end()), hi(f.begin(), f.end());
    return halves(std::span<T>(lo), std::span<T>(hi));
  }

  // The peak of F(., t0), or under a running bound, when its value is not
  // surely positive, a witness u the control points of F(., t0) find (a
  // narrow positive window the peak search missed); the value at it.
  Peak shot_peak(const T& t0) const {
    const Bern<T> f = ellipsoid_function_at(F_, t0);  // F(., t0) once, for the peak and the control points
    Peak p = argmax(f);
    if constexpr (has_error_bound_v<T>) {
      if (sign(p.value) != Sign::positive) {
        long pieces = 0;
        T w = zero_;
        if (classify_on_u(std::span<const T>(f.b), 0, pieces, zero_, one_, w) == Status::separate) {
          T v = f(w);
          if (sign(v) == Sign::positive) return {w, v};
        }
      }
    }
    return p;
  }

  // Iterative Bézier shooting from the separate instant `from` towards `to` (either direction).
  Shot shoot(const T& from, const T& to) {
    ++shots;
    T t = from;
    for (int it = 0; it < opt_.max_shots; ++it) {
      if (out_of_time()) return {ShotKind::inconclusive, t};
      ++shot_iterations;
      Peak p = shot_peak(t);
      if (!(p.value > zero_)) return {ShotKind::converged, t};
      bool forward = to > t;
      Bern<T> G = restrict_to(ellipsoid_function_along(F_, p.u), forward ? t : to, forward ? to : t, one_);
      if (!forward) std::reverse(G.b.begin(), G.b.end());  // parameter s runs from t towards `to`
      bool positive = true;
      for (const auto& x : G.b) positive = positive && sign(x) == Sign::positive;
      if (positive) return {ShotKind::miss, to};
      // G(0) = F(û, t) is the peak value again, by another rounding: at the
      // noise level it can come out <= 0 although p.value > 0. Then G has no
      // root to find (possibly all negative), which is no miss: t is the
      // contact as far as this arithmetic can tell (the scene "missed-0.021").
      if (sign(G.b.front()) != Sign::positive) return {ShotKind::converged, t};
      BernsteinRootOptions<T> ro;
      // Relative to [t, to]: roots to 2^-53 of it, clusters below 2^-30 of it
      // (near a tangency G is rounding noise throughout, and finer clusters
      // would make the subdivision explore an exponential number of pieces).
      ro.precision_bits = std::min(bits_, 56);
      ro.first_only = true;
      ro.max_pieces = 2000;
      // With a running error bound the first root (or cluster, where G's sign
      // is uncertain) starts where G may first vanish: G is surely positive
      // before it, so the hit stays a lower bound of the contact. No root at
      // all: every piece had one sure sign, so G > 0 throughout if it starts so.
      auto roots = bernstein_roots(G, ro);
      if (roots.empty()) {
        if constexpr (has_error_bound_v<T>)
          if (sign(G.b.front()) != Sign::positive) return {ShotKind::inconclusive, t};
        return {ShotKind::miss, to};
      }
      T s = roots.front().lo;                // the hit: F(û, .) > 0 before it
      T tn = point_of(T(t + s * (to - t)));  // an evaluation point (number/running_error.hpp)
      T step = tn - t;
      if (sign(step) == Sign::negative) step = -step;
      t = tn;
      if (!(step > eps_t_)) {
        // Stuck at the start of a stretch where G's sign is uncertain: the contact is
        // somewhere at or after t, not known to be at t.
        if constexpr (has_error_bound_v<T>)
          if (roots.front().cluster) return {ShotKind::inconclusive, t};
        return {ShotKind::converged, t};
      }
    }
    return {ShotKind::inconclusive, t};
  }

  // The Gaussian-circle test on (0, 1) x [a, b] (001 section 4, case 3).
  bool loop_free(const T& a, const T& b) {
    ++gauss_tests;
    BiBern<T> Fab = restrict_t(F_, a, b, one_);
    std::vector<std::pair<double, double>>& pts = gauss_pts_;
    pts.clear();
    const double wt = to_double(b - a);
    if (int(gauss_piece_.size()) < opt_.gauss_depth) gauss_piece_.resize(std::max(opt_.gauss_depth, 0));
    collect_gradient(Fab, opt_.gauss_depth, 1.0, wt, pts);
    bool ok = bezier_detail::pointed(pts);
    if (ok) ++gauss_passed;
    return ok;
  }

  // All collision intervals (or the first one) as a timeline.
  std::vector<TimelineNode> run() {
    std::vector<T> ts;
    std::vector<Status> st;
    for (int k = 0; k <= opt_.samples; ++k) {
      ts.push_back(q(k, opt_.samples));
      st.push_back(status(ts.back()));
    }
    seq_.clear();
    seq_t_.clear();
    push_instant(ts[0], st[0]);
    for (int k = 0; k < opt_.samples; ++k) {
      resolve(ts[k], st[k], ts[k + 1], st[k + 1], 0);
      push_instant(ts[k + 1], st[k + 1]);
      if (opt_.first_contact_only && first_run_closed()) break;
    }
    format_kept();
    return seq_;
  }

 private:
  std::vector<Bern<T>> g_;
  T like_;
  int bits_;
  BezierOptions opt_;
  BiBern<T> F_;
  T zero_, one_, half_, eps_t_, touch_tol_, noise_;
  std::vector<TimelineNode> seq_;
  int degree_u_ = 0;
  std::vector<T> abscissa_;             // i / degree_u_, i = 0..degree_u_ (status's witnesses)
  std::vector<T> seq_t_;                // the instant of seq_[k] in T (its text is made by format_kept)
  std::vector<BiBern<T>> gauss_piece_;  // collect_gradient's u-piece at each depth (storage reused)
  std::vector<T> small_ints_;           // 0, 1, 2, ... as T (small_int)
  std::vector<std::pair<double, double>> gauss_pts_;
  unsigned polls_ = 0;
  bool late_ = false;

  // deadline_passed() on every 16th call (see the header's Cost paragraph); once passed, always.
  bool out_of_time() {
    if (late_) return true;
    if (polls_++ % 16 != 0) return false;
    late_ = deadline_passed();
    return late_;
  }

  T q(long n, long d = 1) const { return scalar_traits<T>::from_rational(mpq_class(n, d), like_); }
  T pow2(int e) const {
    mpq_class v = e >= 0 ? mpq_class(mpz_class(1) << e) : mpq_class(1, mpz_class(1) << (-e));
    return scalar_traits<T>::from_rational(v, like_);
  }

  Peak argmax(const Bern<T>& f) const {
    if constexpr (scalar_traits<T>::is_exact) {
      // Any u is a valid witness: round the argmax found in double to a rational.
      Bern<double> fd;
      for (const auto& x : f.b) fd.b.push_back(to_double(x));
      double ud = bern_argmax(fd, 53).u;
      T u(ud);
      return {u, f(u)};
    } else {
      return bern_argmax(f, bits_, zero_, one_);
    }
  }

  // Control points of ∇F (in the coordinates of the whole square) over the
  // u-pieces of f where F may vanish. The pieces are split_u's (keep_u_left /
  // keep_u_right on a copy: the same values), made in gauss_piece_[depth - 1].
  void collect_gradient(const BiBern<T>& f, int depth, double wu, double wt,
                        std::vector<std::pair<double, double>>& pts) {
    if (f.strict_sign() == -1) return;  // F < 0 on this piece: no zero-set here
    if (depth > 0) {
      BiBern<T>& piece = gauss_piece_[depth - 1];
      piece.b.resize(f.b.size());
      for (std::size_t i = 0; i < f.b.size(); ++i) piece.b[i].assign(f.b[i].begin(), f.b[i].end());
      keep_u_left(piece, half_);
      collect_gradient(piece, depth - 1, wu / 2, wt, pts);
      for (std::size_t i = 0; i < f.b.size(); ++i) piece.b[i].assign(f.b[i].begin(), f.b[i].end());
      keep_u_right(piece, half_);
      collect_gradient(piece, depth - 1, wu / 2, wt, pts);
      return;
    }
    // pts gets (F_u, F_t) at control point (i, j) as entry i (n + 1) + j: the
    // derivative in u (t) elevated back to degree m (n), whose entry k is
    // k (c_k − c_{k−1}) + (m − k)(c_{k+1} − c_k) along each column (row) c
    // (the values derivative_into then elevate_into by one give, without
    // their binomial divisions and scratch vectors).
    const int m = f.degree_u(), n = f.degree_t();
    const std::size_t base = pts.size();
    pts.resize(base + std::size_t(m + 1) * std::size_t(n + 1));
    auto at = [&](int i, int j) -> std::pair<double, double>& {
      return pts[base + std::size_t(i) * std::size_t(n + 1) + j];
    };
    // Directions only (no sign is read from them): in the plain arithmetic under a running bound, the same values.
    using P = PlainOf<T>;
    using V = typename P::type;
    auto elevated_derivative = [&](auto c, int k, int deg) {
      V e = P::of(zero_);
      if (k > 0) {
        V d = P::of(c(k)) - P::of(c(k - 1));
        e = P::of(small_int(k)) * d;
      }
      if (k < deg) {
        V d = P::of(c(k + 1)) - P::of(c(k));
        V term = P::of(small_int(deg - k)) * d;
        e = k > 0 ? V(e + term) : term;
      }
      return e;
    };
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= m; ++i)
        at(i, j).first = to_double(elevated_derivative([&](int k) -> const T& { return f.b[k][j]; }, i, m)) / wu;
    for (int i = 0; i <= m; ++i) {
      const std::vector<T>& row = f.b[i];
      for (int j = 0; j <= n; ++j)
        at(i, j).second = to_double(elevated_derivative([&](int k) -> const T& { return row[k]; }, j, n)) / wt;
    }
  }

  // k as T (0 <= k <= the larger degree of F), made once per run.
  const T& small_int(int k) {
    while (int(small_ints_.size()) <= k) small_ints_.push_back(q(long(small_ints_.size())));
    return small_ints_[k];
  }

  void push_instant(const T& t, Status s) { push_node(t, s, false); }
  void push_cell(const T& a, const T& b, Status s) { push_node(T(half_ * (a + b)), s, true); }
  void push_node(const T& t, Status s, bool cell) {
    seq_.push_back({Instant{std::string(), std::nullopt, std::nullopt, to_double(t)}, s, cell});
    seq_t_.push_back(t);
  }
  // The text of every node that can reach the answer: every cell (the
  // solution lists each cell's sample), every instant whose status is not
  // separate or overlapping (a touch, an undecided instant), the two ends, and
  // every instant next to a cell of another status (an interval's or a
  // contact interval's end, and an overlapping instant between separate
  // cells, which check_isolated_instants makes undecided). An instant inside
  // a run of one status (separate or overlapping) appears nowhere
  // (assemble_answer), so it keeps only its double value.
  void format_kept() {
    const std::size_t last = seq_.size() - 1;
    for (std::size_t k = 0; k < seq_.size(); ++k) {
      const TimelineNode& nd = seq_[k];
      const bool plain = !nd.is_cell && (nd.status == Status::separate || nd.status == Status::overlapping) && k > 0 &&
                         k < last && seq_[k - 1].status == nd.status && seq_[k + 1].status == nd.status;
      if (!plain) seq_[k].t = instant(seq_t_[k]);
    }
  }
  Instant instant(const T& t) const {
    if constexpr (scalar_traits<T>::is_exact)
      return Instant{decimal_string(t), t, t, nearest_double(t)};
    else
      return rounded_instant(t);
  }
  bool first_run_closed() const {
    bool seen = false;
    for (const auto& n : seq_) {
      if (in_collision(n.status))
        seen = true;
      else if (seen && n.status == Status::separate)
        return true;
    }
    return false;
  }
  T mid(const T& a, const T& b) const { return point_of(T(half_ * (a + b))); }

  // Fills the open interval (a, b) between two decided instants.
  void resolve(const T& a, Status sa, const T& b, Status sb, int depth) {
    if (sa == Status::uncertain || sb == Status::uncertain) {
      push_cell(a, b, Status::uncertain);
      return;
    }
    if constexpr (scalar_traits<T>::is_exact) {
      // Exact: certificates only; a gap goes to the projection (ccd_projection).
      (void)depth;
      push_cell(a, b, Status::uncertain);
      return;
    } else {
      // Out of work (the run's subdivision cap or its deadline): this gap is
      // undecided, with the reason; never guessed.
      if (out_of_work()) {
        push_cell(a, b, Status::uncertain);
        return;
      }
      const bool sepa = sa == Status::separate, sepb = sb == Status::separate;
      const bool at_limit = depth >= opt_.max_depth || !(b - a > touch_tol_);
      if ((sa == Status::touching && sepb) || (sepa && sb == Status::touching))
        resolve_touch_end(a, sa, b, sb, depth, at_limit);
      else if (sepa && sepb)
        resolve_separate_ends(a, sa, b, sb, depth, at_limit);
      else if (sepa != sepb)
        resolve_transition(a, sa, b, sb, depth, at_limit);
      else
        resolve_collision_ends(a, sa, b, sb, depth, at_limit);
    }
  }

  // The run's subdivision cap or its deadline reached (the first time, stopped says which).
  bool out_of_work() {
    if (subdivisions < opt_.max_subdivisions && !out_of_time()) return false;
    if (stopped.empty())
      stopped = late_ ? deadline_reason()
                      : "Bezier subdivision stopped at its work bound of " + std::to_string(opt_.max_subdivisions) +
                            " subdivisions";
    return true;
  }

  // A sample at a touch next to a separate one: separate up to it if shooting from the separate end reaches it.
  void resolve_touch_end(const T& a, Status sa, const T& b, Status sb, int depth, bool at_limit) {
    const bool sepb = sb == Status::separate;
    Shot s = sepb ? shoot(b, a) : shoot(a, b);
    T d = s.t - (sepb ? a : b);
    if (sign(d) == Sign::negative) d = -d;
    if (s.kind == ShotKind::miss || (s.kind == ShotKind::converged && !(d > touch_tol_)) || at_limit) {
      push_cell(a, b, Status::separate);
      return;
    }
    split_at(a, sa, mid(a, b), b, sb, depth);
  }

  // Both ends separate: a shot from either end that misses proves the gap separate; shots that meet are a
  // tangential touch.
  void resolve_separate_ends(const T& a, Status sa, const T& b, Status sb, int depth, bool at_limit) {
    Shot f = shoot(a, b);
    if (f.kind == ShotKind::miss) {
      push_cell(a, b, Status::separate);
      return;
    }
    Shot k = shoot(b, a);
    if (k.kind == ShotKind::miss) {
      push_cell(a, b, Status::separate);
      return;
    }
    T gap = k.t - f.t;
    if (!(gap > touch_tol_)) {  // both shots met: a tangential touch
      T c = mid(f.t, k.t);
      push_cell(a, c, Status::separate);
      // With a running error bound a tangency is never sure (it may be a near-miss): undecided.
      push_instant(c, has_error_bound_v<T> ? Status::uncertain : Status::touching);
      push_cell(c, b, Status::separate);
      return;
    }
    if (at_limit) {
      T c = mid(f.t, k.t);
      push_cell(a, c, Status::separate);
      push_instant(c, Status::uncertain);
      push_cell(c, b, Status::separate);
      return;
    }
    split_at(a, sa, mid(f.t, k.t), b, sb, depth);
  }

  // One end separate, the other in collision: the contact is where a shot from the separate end hits.
  void resolve_transition(const T& a, Status sa, const T& b, Status sb, int depth, bool at_limit) {
    const bool sepa = sa == Status::separate;
    const T& from = sepa ? a : b;
    const T& to = sepa ? b : a;
    bool ok = at_limit || loop_free(a, b);
    if (ok) {
      Shot s = shoot(from, to);
      // A miss here contradicts the overlapping end (by continuity there
      // is a contact in between): rounding spoiled the shot, so split
      // instead of guessing, unless at the resolution limit.
      if (s.kind == ShotKind::converged || at_limit) {
        T c = s.t;
        Status cs = s.kind == ShotKind::inconclusive ? Status::uncertain : Status::touching;
        if (s.kind == ShotKind::miss) c = to;  // no hit before the overlapping end: the contact is there
        if (!(c > a)) c = a;
        if (!(c < b)) c = b;
        push_cell(a, c, sa == Status::touching ? Status::overlapping : sa);
        push_instant(c, cs);
        push_cell(c, b, sb == Status::touching ? Status::overlapping : sb);
        return;
      }
    }
    split_at(a, sa, mid(a, b), b, sb, depth);
  }

  // Both ends in collision: overlapping if certified so on (a, b).
  void resolve_collision_ends(const T& a, Status sa, const T& b, Status sb, int depth, bool at_limit) {
    if (overlap_on(a, b)) {
      ++overlap_certificates;
      push_cell(a, b, Status::overlapping);
      return;
    }
    // Below 2^-overlap_depth of a sample interval an uncertified overlapping
    // pair of ends is accepted (a separate pocket that short is missed).
    // With a running error bound that would be a guess: the cell is undecided.
    if (at_limit || depth >= opt_.overlap_depth) {
      ++overlap_unverified;
      push_cell(a, b, has_error_bound_v<T> ? Status::uncertain : Status::overlapping);
      return;
    }
    split_at(a, sa, mid(a, b), b, sb, depth);
  }

  void split_at(const T& a, Status sa, const T& m, const T& b, Status sb, int depth) {
    ++subdivisions;
    Status sm = status(m);
    resolve(a, sa, m, sm, depth + 1);
    push_instant(m, sm);
    resolve(m, sm, b, sb, depth + 1);
  }
};

// The Bézier pipeline: 001 section 4 on F(u, t), from g_0..g_4 in Bernstein form.
template <class T>
PipelineResult<T> ccd_bezier(const std::vector<Bern<T>>& g, const T& like, int bits, BezierOptions opt = {}) {
  auto start = std::chrono::steady_clock::now();
  std::vector<Bern<T>> gs = g;
  std::string trouble;
  if constexpr (!scalar_traits<T>::is_exact) {  // scaled by a power of two; non-finite: nothing to decide
    if (!normalise_pow2<T>([&](auto f) {
          for (auto& gi : gs)
            for (auto& x : gi.b) f(x);
        }))
      trouble = "overflow: a non-finite coefficient of f (g_k)";
  }
  PipelineResult<T> res = result_from_bernstein(gs, opt.first_contact_only);
  if (!trouble.empty()) {
    Instant i0{"0", std::nullopt, std::nullopt}, i1{"1", std::nullopt, std::nullopt};
    undecided_everywhere(res, i0, i1, trouble);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return res;
  }
  BezierZeroSet<T> z(gs, like, bits, opt);
  if constexpr (!scalar_traits<T>::is_exact) {
    bool finite = true;
    for (const auto& row : z.F().b)
      for (const auto& x : row) finite = finite && is_finite_value(x);
    if (!finite) {
      Instant i0{"0", std::nullopt, std::nullopt}, i1{"1", std::nullopt, std::nullopt};
      undecided_everywhere(res, i0, i1, "overflow: a non-finite control point of F(u, t)");
      res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return res;
    }
  }
  std::vector<TimelineNode> seq = z.run();
  res.status_at_0 = seq.front().status;
  res.projection_degree = z.F().degree_t();
  for (std::size_t k = 0; k < seq.size(); ++k) {
    if (seq[k].is_cell)
      res.cells.push_back({seq[k].t, seq[k].status});
    else if (seq[k].status == Status::touching || seq[k].status == Status::uncertain)
      res.critical.push_back({seq[k].t, seq[k].status, 0});
  }
  check_isolated_instants(seq, false);
  assemble_answer(seq, res.answer, [](std::size_t) {});
  if (opt.first_contact_only && res.answer.intervals.size() > 1) res.answer.intervals.resize(1);
  res.counters = {{"shots", z.shots},
                  {"shot_iterations", z.shot_iterations},
                  {"subdivisions", z.subdivisions},
                  {"gauss_tests", z.gauss_tests},
                  {"gauss_passed", z.gauss_passed},
                  {"overlap_certificates", z.overlap_certificates},
                  {"overlap_unverified", z.overlap_unverified}};
  if (!z.stopped.empty()) res.undecided_reasons.push_back(z.stopped);
  if (!res.answer.undecided.empty() && res.undecided_reasons.empty())
    res.undecided_reasons.push_back("a status or contact the Bezier method could not resolve in this arithmetic");
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

}  // namespace eccd
