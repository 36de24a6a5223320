// Proved 3D answers by the Bézier zero-set analysis in intervals (certified/bezier_proof.hpp).
//
// Arithmetic. F's net for the localisation is built from the prepared pair in
// intervals of doubles (characteristic_bernstein<Interval, 4>: every entry of
// N(t) enclosed from its exact rational, every product widened outwards), so
// each control point encloses the exact one. For the ends Krawczyk's test
// (certified/krawczyk.hpp, on a tensor net of degree 0 in s) runs on that net
// first (cheap; brackets ~1e-12 wide), then on the same net held in MPFI, and
// only where both fail on the net built in MPFI at `bits` bits. The exclusion
// of other zeros of (F, F_u) runs on the net of doubles.
// Strip ends are dyadic (2^-strip_depth), exact in double; de Casteljau at 1/2
// is exact in its parameter. Double (the nets' mid-points) only proposes
// witnesses u and Newton points; nothing is decided by it.
#include "certified/bezier_proof.hpp"

#include "certified/krawczyk.hpp"
#include "floating/bezier_ccd.hpp"  // restrict_t
#include "kernel/bivariate_bernstein.hpp"
#include "kernel/budget.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/collision_timeline.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

namespace eccd {

namespace {

using krawczyk_method::Box;
using krawczyk_method::Nets;
using krawczyk_method::System;
using I = MpfiInterval;

Rational rat(double d) { return Rational(mpq_class(d)); }  // dyadic strip ends and box corners: exact

// What the localisation proved about one strip [lo, hi] of t.
struct Strip {
  BezierPiece::Kind kind = BezierPiece::out;
  bool proved = false;
  double lo = 0, hi = 0;
  std::vector<BezierBox> boxes;
};

class Engine {
 public:
  Engine(const PreparedPair<4>& p, const BezierProofOptions& o) : p_(p), opt_(o) {
    F_ = ellipsoid_function(characteristic_bernstein<Interval, 4>(p, false, Interval(0)), Interval(0));
    Fd_.b = std::vector<std::vector<double>>(F_.b.size());
    double scale = 0, width = 0;
    for (std::size_t i = 0; i < F_.b.size(); ++i)
      for (const auto& x : F_.b[i]) {
        Fd_.b[i].push_back(x.mid());
        scale = std::max(scale, std::max(std::fabs(x.lo), std::fabs(x.hi)));
        width = std::max(width, x.width());
      }
    // |Fd(u, t) - F(u, t)| <= half the widest interval of the net (the mid-points) plus de Casteljau's rounding
    // in double (a few ulps of the scale): far below this margin, so a double value beyond it has F's sign.
    sure_margin_ = std::isfinite(scale) && std::isfinite(width) ? width + 1e-9 * scale : INFINITY;
  }

  long box_tests = 0, strip_tests = 0, exclusion_boxes = 0, krawczyk_tests = 0;
  const BiBern<Interval>& F() const { return F_; }
  std::string stop_reason(const BezierProofOptions& o) const {
    if (unresolved_ > kMaxUnresolved)
      return "more than " + std::to_string(kMaxUnresolved) + " strips of width 2^-" + std::to_string(o.strip_depth) +
             " unresolved (a touching stretch, a tangency or an ill-conditioned net)";
    return "its work cap (" + std::to_string(o.max_boxes) + " box tests) was reached";
  }

  // The localisation: strips in t order, proved out / in, or not (at 2^-strip_depth).
  // Returns false when the work cap was reached or more than kMaxUnresolved strips stayed unresolved.
  bool localise(std::vector<Strip>& out) { return strip(F_, 0.0, 1.0, 0, out); }

  // The end in the run [lo, hi] (out on one side, in on the other): "" and the piece, or why not.
  // Krawczyk's test first on the localisation's net in intervals of doubles, then on the same net held in
  // MPFI, then on the net built in MPFI at `bits` (each an enclosure of the exact net: each a proof).
  std::string prove_end(double lo, double hi, BezierPiece& piece) {
    if (!dnets_) {
      TriBern<Interval> t;
      t.n = {F_.degree_u(), 0, F_.degree_t()};
      for (const auto& row : F_.b)
        for (const auto& x : row) t.c.push_back(x);
      dnets_.emplace(t, opt_.bits);
    }
    std::string why = prove_end_with(*dnets_, lo, hi, piece);
    if (why.empty()) return why;
    use_full_net_ = false;
    ensure_mpfi();
    std::string why2 = prove_end_with(nets(), lo, hi, piece);
    if (why2.empty()) return why2;
    use_full_net_ = true;
    ensure_mpfi();
    why2 = prove_end_with(nets(), lo, hi, piece);
    use_full_net_ = false;
    return why2.empty() ? why2 : why2 + " (also in intervals of doubles: " + why + ")";
  }

  template <class IT>
  std::string prove_end_with(krawczyk_method::NetsT<IT>& nets, double lo, double hi, BezierPiece& piece) {
    const mpq_class qlo(lo), qhi(hi);
    const double tm = 0.5 * (lo + hi);
    // seed: the witness u of max F(., tm) in double
    const double u0 = argmax_u(tm);
    System sys;
    sys.eqs = {{0, 0, 0}, {1, 0, 0}};
    sys.vars = {0, 2};
    sys.kind = "bezier-end";
    std::optional<std::array<double, 3>> x = krawczyk_method::newton(nets, sys, {u0, 0.0, tm});
    if (!x)
      x = std::array<double, 3>{refine_argmax(u0, tm), 0.0, tm};  // no Newton point: the witness u at the run's middle
    const double ux = (*x)[0], tx = (*x)[2];
    if (!(ux > 0 && ux < 1) || !(tx > lo - (hi - lo) && tx < hi + (hi - lo)))
      return "Newton's method on (F, F_u) went outside the run (u = " + std::to_string(ux) +
             ", t = " + std::to_string(tx) + ")";
    const mpq_class uq(ux), tq(tx), w = qhi - qlo;
    std::string why = "Krawczyk's test failed around u = " + std::to_string(ux) + ", t = " + std::to_string(tx);
    for (const int f : {64, 16, 4, 256, 1, 1024}) {
      const mpq_class rho = w * f;
      if (rho > mpq_class(1, 16)) continue;
      Box X;
      X.lo = {mpq_class(uq - rho), std::min(qlo, mpq_class(tq - rho))};
      X.hi = {mpq_class(uq + rho), std::max(qhi, mpq_class(tq + rho))};
      if (sgn(X.lo[0]) <= 0 || X.hi[0] >= 1) continue;
      Box K;
      ++krawczyk_tests;
      if (!krawczyk_method::krawczyk(nets, sys, X, K)) continue;
      std::string ex = exclude(qlo, qhi, X.lo[0], X.hi[0]);
      if (!ex.empty()) {
        why += ": " + ex;
        continue;
      }
      // tighten: Y <- Y ∩ K(Y) keeps the unique zero
      piece.kind = BezierPiece::end;
      piece.lo = Rational(qlo);
      piece.hi = Rational(qhi);
      piece.boxes = {BezierBox{Rational(X.lo[0]), Rational(X.hi[0]), Rational(X.lo[1]), Rational(X.hi[1])}};
      Box Y = X;
      for (int it = 0; it < 12; ++it) {
        Box K2;
        krawczyk_method::krawczyk(nets, sys, Y, K2);
        if (K2.lo.size() != Y.lo.size()) break;
        bool ok = true;
        for (std::size_t v = 0; v < 2; ++v) {
          if (K2.lo[v] > Y.lo[v]) Y.lo[v] = K2.lo[v];
          if (K2.hi[v] < Y.hi[v]) Y.hi[v] = K2.hi[v];
          ok = ok && Y.lo[v] <= Y.hi[v];
        }
        if (!ok) return "internal inconsistency: Krawczyk's chain became empty around a proved zero";
        const mpq_class before = piece.boxes.back().t_hi - piece.boxes.back().t_lo;
        piece.boxes.push_back(BezierBox{Rational(Y.lo[0]), Rational(Y.hi[0]), Rational(Y.lo[1]), Rational(Y.hi[1])});
        if (Y.hi[1] - Y.lo[1] < mpq_class(1, mpz_class(1) << 100)) break;
        if (2 * (Y.hi[1] - Y.lo[1]) > before) break;  // no longer converging: the net's width is reached
      }
      const mpq_class blo = std::max(qlo, Y.lo[1]), bhi = std::min(qhi, Y.hi[1]);
      if (blo > bhi) return "the proved zero of (F, F_u) lies outside the run (internal inconsistency)";
      piece.bracket_lo = Rational(blo);
      piece.bracket_hi = Rational(bhi);
      return "";
    }
    return why;
  }

 private:
  const PreparedPair<4>& p_;
  const BezierProofOptions& opt_;
  BiBern<Interval> F_;
  BiBern<double> Fd_;
  std::optional<Nets> nets_;
  std::optional<krawczyk_method::NetsT<Interval>> dnets_;
  long unresolved_ = 0;
  double sure_margin_ = INFINITY;
  static constexpr long kMaxUnresolved = 64;  // unresolved strips at the finest level, in all

  // The nets for Krawczyk's test, in MPFI at `bits`: first the localisation's net of intervals of
  // doubles held exactly in MPFI (an enclosure of the exact net, nothing to compute: cheap; brackets
  // then ~1e-14 wide), and only where that fails the net built in MPFI from the prepared pair.
  bool use_full_net_ = false;
  std::optional<Nets> full_nets_;
  void ensure_mpfi() {
    if (use_full_net_) {
      if (!full_nets_) {
        const I like(Rational(0), opt_.bits);
        BiBern<I> f = ellipsoid_function(characteristic_bernstein<I, 4>(p_, false, like), like);
        TriBern<I> t;
        t.n = {f.degree_u(), 0, f.degree_t()};
        for (const auto& row : f.b)
          for (const auto& x : row) t.c.push_back(x);
        full_nets_.emplace(t, opt_.bits);
      }
      return;
    }
    if (nets_) return;
    TriBern<I> t;
    t.n = {F_.degree_u(), 0, F_.degree_t()};
    for (const auto& row : F_.b)
      for (const auto& x : row) t.c.emplace_back(mpq_class(x.lo), mpq_class(x.hi), opt_.bits);
    nets_.emplace(t, opt_.bits);
  }
  Nets& nets() { return use_full_net_ ? *full_nets_ : *nets_; }

  void check_work() {
    if (deadline_passed()) throw BudgetExhausted("bezier proof: " + deadline_reason());
  }

  // argmax over u of the double mid-point net at t and the value there (a witness only: 127 samples).
  // The 127 de Casteljau evaluations run side by side (one by one they cost a sixth of the degree-1 certified query):
  // the same products and sums as bernstein_value at each u, in the same order, so the same values bit for bit.
  std::pair<double, double> witness(double t) const {
    Bern<double> col;
    for (const auto& row : Fd_.b) col.b.push_back(bernstein_value(std::span<const double>(row), t));
    double best = -INFINITY, ub = 0.5;
    constexpr int K = 127;
    const int n = int(col.b.size());
    if (n >= 1 && n <= kWitnessRows) {
      alignas(64) double w[kWitnessRows][K], su[K], uu[K];
      for (int k = 0; k < K; ++k) {
        uu[k] = (k + 1) / 128.0;
        su[k] = 1.0 - uu[k];
      }
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < K; ++k) w[i][k] = col.b[i];
      for (int r = 1; r < n; ++r)
        for (int i = 0; i + r < n; ++i)
          for (int k = 0; k < K; ++k) {
            const double x = su[k] * w[i][k];
            const double y = uu[k] * w[i + 1][k];
            w[i][k] = x + y;
          }
      for (int k = 0; k < K; ++k)
        if (w[0][k] > best) {
          best = w[0][k];
          ub = uu[k];
        }
      return {ub, best};
    }
    for (int k = 1; k < 128; ++k) {
      const double u = k / 128.0, v = col(u);
      if (v > best) {
        best = v;
        ub = u;
      }
    }
    return {ub, best};
  }
  static constexpr int kWitnessRows = 17;  // F's degree in u plus one (5 for ellipsoids), with room
  double argmax_u(double t) const { return witness(t).first; }
  // F(u, t) of the double mid-point net (a proposal; see sure_margin_).
  double value_at(double u, double t) const {
    Bern<double> col;
    for (const auto& row : Fd_.b) col.b.push_back(bernstein_value(std::span<const double>(row), t));
    return col(u);
  }
  // The maximiser of the double net's F(., t) near u0 (golden-section search in [u0 - 1/128, u0 + 1/128]).
  double refine_argmax(double u0, double t) const {
    Bern<double> col;
    for (const auto& row : Fd_.b) col.b.push_back(bernstein_value(std::span<const double>(row), t));
    double a = std::max(0.0, u0 - 1.0 / 128), b = std::min(1.0, u0 + 1.0 / 128);
    const double r = 0.6180339887498949;
    for (int k = 0; k < 80; ++k) {
      const double c = b - r * (b - a), d = a + r * (b - a);
      if (col(c) > col(d))
        b = d;
      else
        a = c;
    }
    return 0.5 * (a + b);
  }
  // One u-box containing u* (dyadic, guided bisection) with every control point > 0.
  bool positive_box(const BiBern<Interval>& f, double ustar, double lo, double hi, std::vector<BezierBox>& boxes) {
    BiBern<Interval> g = f;
    double u0 = 0, u1 = 1;
    for (int d = 0; d <= opt_.u_depth; ++d) {
      // a box touching u = 0 or u = 1 holds F(0, t) = det A(t) < 0 or F(1, t) = det B(t) < 0: not tried
      const int s = u0 > 0 && u1 < 1 ? (++box_tests, g.strict_sign()) : 0;
      if (s == 1) {
        boxes.push_back({rat(u0), rat(u1), rat(lo), rat(hi)});
        return true;
      }
      const double um = 0.5 * (u0 + u1);
      // only the half that holds u* is computed (both halves cost a sixth of a certified 3D query)
      if (ustar < um) {
        keep_u_left(g, Interval(0.5, 0.5));
        u1 = um;
      } else {
        keep_u_right(g, Interval(0.5, 0.5));
        u0 = um;
      }
    }
    return false;
  }

  // Every u-piece (adaptive, at most u_depth deep) with every control point < 0.
  bool negative_all(const BiBern<Interval>& f, double u0, double u1, int depth, double lo, double hi,
                    std::vector<BezierBox>& boxes) {
    ++box_tests;
    const int s = f.strict_sign();
    if (s == -1) {
      boxes.push_back({rat(u0), rat(u1), rat(lo), rat(hi)});
      return true;
    }
    if (s == 1 || depth >= opt_.u_depth || box_tests > opt_.max_boxes) return false;
    // a corner control point is F's value there (enclosed): > 0 means F > 0 somewhere
    for (const Interval* c : {&f.b.front().front(), &f.b.front().back(), &f.b.back().front(), &f.b.back().back()})
      if (sign(*c) == Sign::positive) return false;
    const double um = 0.5 * (u0 + u1);
    {  // the right half is computed only when the left one was proved (the same values as split_u's)
      BiBern<Interval> a = f;
      keep_u_left(a, Interval(0.5, 0.5));
      if (!negative_all(a, u0, um, depth + 1, lo, hi, boxes)) return false;
    }
    BiBern<Interval> b = f;
    keep_u_right(b, Interval(0.5, 0.5));
    return negative_all(b, um, u1, depth + 1, lo, hi, boxes);
  }

  bool strip(const BiBern<Interval>& f, double lo, double hi, int depth, std::vector<Strip>& out) {
    check_work();
    if (box_tests > opt_.max_boxes) return false;
    ++strip_tests;
    const double tm = 0.5 * (lo + hi);
    Strip s;
    s.lo = lo;
    s.hi = hi;
    const auto [ustar, top] = witness(tm);
    // A box test that must fail is skipped (the strips that hold an end fail their box tests at
    // every depth): F(u*, lo) or F(u*, hi) surely < 0 (every u-box around u* then has F <= 0 somewhere, so not
    // every control point is > 0), or F(u, lo) or F(u, hi) surely > 0 for some u (not every control point of
    // every u-piece is < 0). "Surely": the double value beyond sure_margin_ (see the constructor). The strip is
    // then not proved, exactly as the failed test would leave it; only the box count differs.
    if (top > 0) {
      s.kind = BezierPiece::out;
      const bool fails = value_at(ustar, lo) < -sure_margin_ || value_at(ustar, hi) < -sure_margin_;
      s.proved = !fails && positive_box(f, ustar, lo, hi, s.boxes);
    } else {
      s.kind = BezierPiece::in;
      const bool fails = witness(lo).second > sure_margin_ || witness(hi).second > sure_margin_;
      s.proved = !fails && negative_all(f, 0, 1, 0, lo, hi, s.boxes);
    }
    if (s.proved || depth >= opt_.strip_depth) {
      // a regular end leaves a few unresolved strips; many are a touching stretch or a tangency: not provable here
      if (!s.proved && ++unresolved_ > kMaxUnresolved) return false;
      if (!s.proved) s.boxes.clear();
      out.push_back(std::move(s));
      return true;
    }
    auto [a, b] = split_t(f, Interval(0.5, 0.5));
    return strip(a, lo, tm, depth + 1, out) && strip(b, tm, hi, depth + 1, out);
  }

  // Exclusion: on [0, 1] x [lo, hi] outside u in [xu0, xu1], F or F_u is of one sign on every box
  // (the nets of F and F_u in intervals of doubles: signs of enclosures, so a proof as in MPFI).
  std::string exclude(const mpq_class& lo, const mpq_class& hi, const mpq_class& xu0, const mpq_class& xu1) {
    const Interval half(0.5, 0.5);
    const double dlo = nearest_double(lo), dhi = nearest_double(hi);
    if (mpq_class(dlo) != lo || mpq_class(dhi) != hi) return "the run's ends are not doubles (internal)";
    struct Ex {
      BiBern<Interval> f, fu;
      double u0, u1;
      int depth;
    };
    BiBern<Interval> f = restrict_t(F_, Interval(dlo, dlo), Interval(dhi, dhi), Interval(1));
    BiBern<Interval> fu;  // F_u: m (b[i+1] - b[i])
    const int m = f.degree_u();
    for (int i = 0; i < m; ++i) {
      fu.b.emplace_back();
      for (std::size_t j = 0; j < f.b[i].size(); ++j) fu.b.back().push_back(Interval(m) * (f.b[i + 1][j] - f.b[i][j]));
    }
    // the lemma needs F(0, t) = det A(t) < 0 and F(1, t) = det B(t) < 0 on the run (a maximum 0 lies inside (0, 1))
    for (const auto* row : {&f.b.front(), &f.b.back()})
      for (const auto& x : *row)
        if (sign(x) != Sign::negative) return "F(0, t) = det A(t) or F(1, t) = det B(t) is not proved < 0 on the run";
    std::vector<Ex> stack;
    stack.push_back(Ex{std::move(f), std::move(fu), 0.0, 1.0, 0});
    long n = 0;
    while (!stack.empty()) {
      Ex b = std::move(stack.back());
      stack.pop_back();
      ++exclusion_boxes;
      if (++n > opt_.max_boxes)
        return "the exclusion of other zeros of (F, F_u) needed more than " + std::to_string(opt_.max_boxes) + " boxes";
      check_work();
      if (mpq_class(b.u0) >= xu0 && mpq_class(b.u1) <= xu1) continue;
      if (b.f.strict_sign() != 0 || b.fu.strict_sign() != 0) continue;
      if (b.depth >= 40) return "another zero of (F, F_u) near u = " + std::to_string(b.u0) + " could not be excluded";
      // split in u (the t-range is the run's, already narrow; a t-split costs a degree in t squared),
      // and below depth 12 in t every other level
      const double um = 0.5 * (b.u0 + b.u1);
      auto [fl, fh] = split_u(b.f, half);
      auto [gl, gh] = split_u(b.fu, half);
      if (b.depth >= 12 && b.depth % 2 == 1) {
        auto [fll, flh] = split_t(fl, half);
        auto [fhl, fhh] = split_t(fh, half);
        auto [gll, glh] = split_t(gl, half);
        auto [ghl, ghh] = split_t(gh, half);
        stack.push_back(Ex{std::move(fhh), std::move(ghh), um, b.u1, b.depth + 1});
        stack.push_back(Ex{std::move(fhl), std::move(ghl), um, b.u1, b.depth + 1});
        stack.push_back(Ex{std::move(flh), std::move(glh), b.u0, um, b.depth + 1});
        stack.push_back(Ex{std::move(fll), std::move(gll), b.u0, um, b.depth + 1});
      } else {
        stack.push_back(Ex{std::move(fh), std::move(gh), um, b.u1, b.depth + 1});
        stack.push_back(Ex{std::move(fl), std::move(gl), b.u0, um, b.depth + 1});
      }
    }
    return "";
  }
};

Instant exact_instant(const mpq_class& x) { return bracketed_instant(x, x, x); }

std::string where(double lo, double hi) {
  return "t in [" + decimal_string(mpq_class(lo), 12) + ", " + decimal_string(mpq_class(hi), 12) + "]";
}

// Neighbours of one kind merged (unproved strips into runs).
std::vector<Strip> merged_strips(std::vector<Strip>& strips) {
  std::vector<Strip> m;
  for (auto& s : strips) {
    if (!m.empty() && m.back().proved == s.proved && (!s.proved || m.back().kind == s.kind)) {
      m.back().hi = s.hi;
      for (auto& b : s.boxes) m.back().boxes.push_back(std::move(b));
    } else {
      m.push_back(std::move(s));
    }
  }
  return m;
}

// The pieces of a proved strip: an out-strip is one piece (the boxes' t-ranges cover it); an in-strip one piece
// per t-range (the contract: every box spans the piece's t-range).
void add_proved_pieces(const Strip& s, std::vector<BezierPiece>& pieces) {
  if (s.kind == BezierPiece::out) {
    BezierPiece pc;
    pc.kind = s.kind;
    pc.lo = rat(s.lo);
    pc.hi = rat(s.hi);
    pc.boxes = s.boxes;
    pieces.push_back(std::move(pc));
    return;
  }
  for (const BezierBox& b : s.boxes) {
    if (pieces.empty() || pieces.back().kind != BezierPiece::in || pieces.back().lo != b.t_lo) {
      BezierPiece pc;
      pc.kind = BezierPiece::in;
      pc.lo = b.t_lo;
      pc.hi = b.t_hi;
      pieces.push_back(std::move(pc));
    }
    pieces.back().boxes.push_back(b);
  }
}

// Why the unproved run m[i] cannot hold one end of a collision interval, or "" when it may (between an in- and an
// out-run).
std::string unprovable_run(const std::vector<Strip>& m, std::size_t i, const BezierProofOptions& options) {
  const Strip& s = m[i];
  const bool has_before = i > 0, has_after = i + 1 < m.size();
  if (!has_before || !has_after)
    return where(s.lo, s.hi) + ": nothing proved at " + (has_before ? "t = 1" : "t = 0") +
           " (a touch, or a contact within 2^-" + std::to_string(options.strip_depth) + " of it)";
  if (m[i - 1].kind == m[i + 1].kind)
    return where(s.lo, s.hi) + std::string(": ") +
           (m[i - 1].kind == BezierPiece::out
                ? "separate on both sides: a touch, a near miss or a collision narrower than the strips"
                : "overlapping on both sides: a touching gap or none") +
           " (a tangency cannot be proved by intervals)";
  return "";
}

// The timeline: instants at 0, the ends and 1; cells between them (with first_contact, up to the first end of a
// collision). Counts the ends in n_ends.
std::vector<TimelineNode> piece_timeline(const std::vector<BezierPiece>& pieces, bool first_contact, long& n_ends) {
  auto status_of = [](BezierPiece::Kind k) { return k == BezierPiece::in ? Status::overlapping : Status::separate; };
  std::vector<TimelineNode> seq;
  const Status s0 = status_of(pieces.front().kind);
  seq.push_back({exact_instant(0), s0, false});
  Status cur = s0;
  mpq_class cell_lo = 0;
  for (const auto& pc : pieces) {
    if (pc.kind != BezierPiece::end) continue;
    const mpq_class blo = pc.bracket_lo, bhi = pc.bracket_hi;
    const Instant end = bracketed_instant((blo + bhi) / 2, blo, bhi);
    seq.push_back({exact_instant((cell_lo + blo) / 2), cur, true});
    const Status next = cur == Status::separate ? Status::overlapping : Status::separate;
    seq.push_back({end, Status::touching, false});
    ++n_ends;
    if (first_contact && next == Status::separate) return seq;
    cur = next;
    cell_lo = bhi;
  }
  seq.push_back({exact_instant((cell_lo + 1) / 2), cur, true});
  seq.push_back({exact_instant(1), cur, false});
  return seq;
}

}  // namespace

BezierProofResult prove_bezier(const PreparedPair<4>& p, const BezierProofOptions& options) {
  BezierProofResult r;
  Engine e(p, options);
  auto counters = [&] {
    r.work = {{"bezier_strip_tests", e.strip_tests},
              {"bezier_box_tests", e.box_tests},
              {"bezier_exclusion_boxes", e.exclusion_boxes},
              {"bezier_krawczyk_tests", e.krawczyk_tests},
              {"bezier_degree_t", long(e.F().degree_t())}};
  };
  auto refuse = [&](const std::string& why) {
    r.decided = false;
    r.reason = why;
    r.answer = Answer{};
    r.pieces.clear();
    counters();
    return r;
  };
  std::vector<Strip> strips;
  if (!e.localise(strips)) return refuse("the localisation stopped: " + e.stop_reason(options));
  const std::vector<Strip> m = merged_strips(strips);
  // pieces, ends proved
  std::vector<BezierPiece> pieces;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Strip& s = m[i];
    if (s.proved) {
      add_proved_pieces(s, pieces);
      continue;
    }
    const std::string unprovable = unprovable_run(m, i, options);
    if (!unprovable.empty()) return refuse(unprovable);
    BezierPiece pc;
    const std::string why = e.prove_end(s.lo, s.hi, pc);
    if (!why.empty())
      return refuse(where(s.lo, s.hi) + ": an end of a collision interval lies here but is not proved: " + why);
    pieces.push_back(std::move(pc));
  }
  long n_ends = 0;
  const std::vector<TimelineNode> seq = piece_timeline(pieces, options.first_contact, n_ends);
  assemble_answer(seq, r.answer, [](std::size_t) {});
  if (options.first_contact && r.answer.intervals.size() > 1) r.answer.intervals.resize(1);
  r.decided = true;
  if (options.record) r.pieces = std::move(pieces);
  counters();
  r.work.emplace_back("bezier_proved_ends", n_ends);
  return r;
}

}  // namespace eccd
