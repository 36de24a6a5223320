// Proved 3D answers by the Bézier zero-set analysis in intervals (certified/bezier_proof.hpp).
//
// Arithmetic. F's net for the localisation is built from the prepared pair in
// intervals of doubles (characteristic_bernstein<Interval, 4>: every entry of
// N(t) enclosed from its exact rational, every product widened outwards), so
// each control point encloses the exact one; for the ends the same net is built
// in MPFI at `bits` bits and read as a tensor net of degree 0 in s
// (kernel/trivariate_bernstein.hpp), on which certified/krawczyk.hpp runs.
// Strip ends are dyadic (2^-strip_depth), exact in double; de Casteljau at 1/2
// is exact in its parameter. Double (the nets' mid-points) only proposes
// witnesses u and Newton points; nothing is decided by it.
#include "certified/bezier_proof.hpp"

#include "certified/krawczyk.hpp"
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

using krawczyk_detail::Box;
using krawczyk_detail::Nets;
using krawczyk_detail::System;
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
    for (std::size_t i = 0; i < F_.b.size(); ++i)
      for (const auto& x : F_.b[i]) Fd_.b[i].push_back(x.mid());
  }

  long box_tests = 0, strip_tests = 0, exclusion_boxes = 0, krawczyk_tests = 0;
  const BiBern<Interval>& F() const { return F_; }

  // F < 0 on the faces u = 0 and u = 1 (their control points are the nets of det A(t), det B(t)).
  bool faces_negative() const {
    for (const auto& x : F_.b.front())
      if (sign(x) != Sign::negative) return false;
    for (const auto& x : F_.b.back())
      if (sign(x) != Sign::negative) return false;
    return true;
  }

  // The localisation: strips in t order, proved out / in, or not (at 2^-strip_depth).
  // Returns false when the work cap was reached (the strips then stop early).
  bool localise(std::vector<Strip>& out) {
    return strip(F_, 0.0, 1.0, 0, out);
  }

  // The end in the run [lo, hi] (out on one side, in on the other): "" and the piece, or why not.
  std::string prove_end(double lo, double hi, BezierPiece& piece) {
    ensure_mpfi();
    const mpq_class qlo(lo), qhi(hi);
    const double tm = 0.5 * (lo + hi);
    // seed: the witness u of max F(., tm) in double
    const double u0 = argmax_u(tm);
    System sys;
    sys.eqs = {{0, 0, 0}, {1, 0, 0}};
    sys.vars = {0, 2};
    sys.kind = "bezier-end";
    std::optional<std::array<double, 3>> x = krawczyk_detail::newton(*nets_, sys, {u0, 0.0, tm});
    if (!x) return "Newton's method on (F, F_u) did not converge from u = " + std::to_string(u0) + ", t = " + std::to_string(tm);
    const double ux = (*x)[0], tx = (*x)[2];
    if (!(ux > 0 && ux < 1) || !(tx > lo - (hi - lo) && tx < hi + (hi - lo)))
      return "Newton's method on (F, F_u) went outside the run (u = " + std::to_string(ux) + ", t = " + std::to_string(tx) + ")";
    const mpq_class uq(ux), tq(tx), w = qhi - qlo;
    std::string why = "Krawczyk's test failed around u = " + std::to_string(ux) + ", t = " + std::to_string(tx);
    for (const int f : {1024, 256, 64, 16, 4, 1}) {
      const mpq_class rho = w * f;
      if (rho > mpq_class(1, 16)) continue;
      Box X;
      X.lo = {mpq_class(uq - rho), std::min(qlo, mpq_class(tq - rho))};
      X.hi = {mpq_class(uq + rho), std::max(qhi, mpq_class(tq + rho))};
      if (sgn(X.lo[0]) <= 0 || X.hi[0] >= 1) continue;
      Box K;
      ++krawczyk_tests;
      if (!krawczyk_detail::krawczyk(*nets_, sys, X, K)) continue;
      std::string ex = exclude(qlo, qhi, X.lo[0], X.hi[0]);
      if (!ex.empty()) { why += ": " + ex; continue; }
      // tighten: Y <- Y ∩ K(Y) keeps the unique zero
      piece.kind = BezierPiece::end;
      piece.lo = Rational(qlo);
      piece.hi = Rational(qhi);
      piece.boxes = {BezierBox{Rational(X.lo[0]), Rational(X.hi[0]), Rational(X.lo[1]), Rational(X.hi[1])}};
      Box Y = X;
      for (int it = 0; it < 12; ++it) {
        Box K2;
        krawczyk_detail::krawczyk(*nets_, sys, Y, K2);
        if (K2.lo.size() != Y.lo.size()) break;
        bool ok = true;
        for (std::size_t v = 0; v < 2; ++v) {
          if (K2.lo[v] > Y.lo[v]) Y.lo[v] = K2.lo[v];
          if (K2.hi[v] < Y.hi[v]) Y.hi[v] = K2.hi[v];
          ok = ok && Y.lo[v] <= Y.hi[v];
        }
        if (!ok) return "internal inconsistency: Krawczyk's chain became empty around a proved zero";
        piece.boxes.push_back(BezierBox{Rational(Y.lo[0]), Rational(Y.hi[0]), Rational(Y.lo[1]), Rational(Y.hi[1])});
        if (Y.hi[1] - Y.lo[1] < mpq_class(1, mpz_class(1) << 100)) break;
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

  void ensure_mpfi() {
    if (nets_) return;
    const I like(Rational(0), opt_.bits);
    BiBern<I> f = ellipsoid_function(characteristic_bernstein<I, 4>(p_, false, like), like);
    TriBern<I> t;
    t.n = {f.degree_u(), 0, f.degree_t()};
    for (const auto& row : f.b)
      for (const auto& x : row) t.c.push_back(x);
    nets_.emplace(t, opt_.bits);
  }

  void check_work() {
    if (deadline_passed()) throw BudgetExhausted("bezier proof: " + deadline_reason());
  }

  // argmax over u of the double mid-point net at t (a witness only: 129 samples).
  double argmax_u(double t) const {
    Bern<double> col;
    for (const auto& row : Fd_.b) col.b.push_back(bernstein_value(std::span<const double>(row), t));
    double best = -INFINITY, ub = 0.5;
    for (int k = 1; k < 128; ++k) {
      const double u = k / 128.0, v = col(u);
      if (v > best) { best = v; ub = u; }
    }
    return ub;
  }
  double peak(double t) const {
    Bern<double> col;
    for (const auto& row : Fd_.b) col.b.push_back(bernstein_value(std::span<const double>(row), t));
    return col(argmax_u(t));
  }

  // One u-box containing u* (dyadic, guided bisection) with every control point > 0.
  bool positive_box(const BiBern<Interval>& f, double ustar, double lo, double hi, std::vector<BezierBox>& boxes) {
    BiBern<Interval> g = f;
    double u0 = 0, u1 = 1;
    for (int d = 0; d <= opt_.u_depth; ++d) {
      ++box_tests;
      const int s = g.strict_sign();
      if (s == 1) {
        boxes.push_back({rat(u0), rat(u1), rat(lo), rat(hi)});
        return true;
      }
      const double um = 0.5 * (u0 + u1);
      auto [a, b] = split_u(g, Interval(0.5, 0.5));
      if (ustar < um) { g = std::move(a); u1 = um; }
      else { g = std::move(b); u0 = um; }
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
    auto [a, b] = split_u(f, Interval(0.5, 0.5));
    const double um = 0.5 * (u0 + u1);
    return negative_all(a, u0, um, depth + 1, lo, hi, boxes) && negative_all(b, um, u1, depth + 1, lo, hi, boxes);
  }

  bool strip(const BiBern<Interval>& f, double lo, double hi, int depth, std::vector<Strip>& out) {
    check_work();
    if (box_tests > opt_.max_boxes) return false;
    ++strip_tests;
    const double tm = 0.5 * (lo + hi);
    Strip s;
    s.lo = lo;
    s.hi = hi;
    if (peak(tm) > 0) {
      s.kind = BezierPiece::out;
      s.proved = positive_box(f, argmax_u(tm), lo, hi, s.boxes);
    } else {
      s.kind = BezierPiece::in;
      s.proved = negative_all(f, 0, 1, 0, lo, hi, s.boxes);
    }
    if (s.proved || depth >= opt_.strip_depth) {
      if (!s.proved) s.boxes.clear();
      out.push_back(std::move(s));
      return true;
    }
    auto [a, b] = split_t(f, Interval(0.5, 0.5));
    return strip(a, lo, tm, depth + 1, out) && strip(b, tm, hi, depth + 1, out);
  }

  // Exclusion: on [0, 1] x [lo, hi] outside u in [xu0, xu1], F or F_u is of one sign on every box.
  std::string exclude(const mpq_class& lo, const mpq_class& hi, const mpq_class& xu0, const mpq_class& xu1) {
    const int bits = opt_.bits;
    const I half(mpq_class(1, 2), bits);
    struct Ex {
      TriBern<I> f, fu;
      mpq_class u0, u1;
      int depth;
    };
    std::vector<Ex> stack;
    stack.push_back(Ex{krawczyk_detail::restrict_axis(nets_->get({0, 0, 0}), 2, lo, hi, bits),
                       krawczyk_detail::restrict_axis(nets_->get({1, 0, 0}), 2, lo, hi, bits), 0, 1, 0});
    long n = 0;
    while (!stack.empty()) {
      Ex b = std::move(stack.back());
      stack.pop_back();
      ++exclusion_boxes;
      if (++n > opt_.max_boxes) return "the exclusion of other zeros of (F, F_u) needed more than " + std::to_string(opt_.max_boxes) + " boxes";
      check_work();
      if (b.u0 >= xu0 && b.u1 <= xu1) continue;
      if (b.f.strict_sign() != 0 || b.fu.strict_sign() != 0) continue;
      if (b.depth >= 40)
        return "another zero of (F, F_u) near u = " + decimal_string(b.u0, 8) + " could not be excluded";
      // split in u (the t-range is the run's, already narrow), and in t every other level
      const mpq_class um = (b.u0 + b.u1) / 2;
      auto [fl, fh] = b.f.split_half(0, half);
      auto [gl, gh] = b.fu.split_half(0, half);
      if (b.depth % 2 == 1) {
        auto [fll, flh] = fl.split_half(2, half);
        auto [fhl, fhh] = fh.split_half(2, half);
        auto [gll, glh] = gl.split_half(2, half);
        auto [ghl, ghh] = gh.split_half(2, half);
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

std::string where(double lo, double hi) { return "t in [" + decimal_string(mpq_class(lo), 12) + ", " + decimal_string(mpq_class(hi), 12) + "]"; }

}  // namespace

BezierProofResult prove_bezier(const PreparedPair<4>& p, const BezierProofOptions& options) {
  BezierProofResult r;
  Engine e(p, options);
  auto counters = [&] {
    r.work = {{"bezier_strip_tests", e.strip_tests}, {"bezier_box_tests", e.box_tests},
              {"bezier_exclusion_boxes", e.exclusion_boxes}, {"bezier_krawczyk_tests", e.krawczyk_tests},
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
  if (!e.faces_negative())
    return refuse("F(0, t) = det A(t) or F(1, t) = det B(t) is not proved < 0 by its control points in intervals of doubles");
  std::vector<Strip> strips;
  if (!e.localise(strips))
    return refuse("the localisation reached its work cap (" + std::to_string(options.max_boxes) + " box tests)");
  // merge neighbours of one kind (unproved strips into runs)
  std::vector<Strip> m;
  for (auto& s : strips) {
    if (!m.empty() && m.back().proved == s.proved && (!s.proved || m.back().kind == s.kind)) {
      m.back().hi = s.hi;
      for (auto& b : s.boxes) m.back().boxes.push_back(std::move(b));
    } else {
      m.push_back(std::move(s));
    }
  }
  // pieces, ends proved; the timeline for the answer
  std::vector<BezierPiece> pieces;
  std::vector<TimelineNode> seq;
  long n_ends = 0;
  auto status_of = [](BezierPiece::Kind k) { return k == BezierPiece::in ? Status::overlapping : Status::separate; };
  bool stopped = false;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Strip& s = m[i];
    if (s.proved) {
      BezierPiece pc;
      pc.kind = s.kind;
      pc.lo = rat(s.lo);
      pc.hi = rat(s.hi);
      pc.boxes = s.boxes;
      pieces.push_back(std::move(pc));
      continue;
    }
    const bool has_before = i > 0, has_after = i + 1 < m.size();
    if (!has_before || !has_after)
      return refuse(where(s.lo, s.hi) + ": nothing proved at " + (has_before ? "t = 1" : "t = 0") +
                    " (a touch, or a contact within 2^-" + std::to_string(options.strip_depth) + " of it)");
    if (m[i - 1].kind == m[i + 1].kind)
      return refuse(where(s.lo, s.hi) + std::string(": ") +
                    (m[i - 1].kind == BezierPiece::out ? "separate on both sides: a touch, a near miss or a collision narrower than the strips"
                                                       : "overlapping on both sides: a touching gap or none") +
                    " (a tangency cannot be proved by intervals)");
    BezierPiece pc;
    const std::string why = e.prove_end(s.lo, s.hi, pc);
    if (!why.empty()) return refuse(where(s.lo, s.hi) + ": an end of a collision interval lies here but is not proved: " + why);
    pieces.push_back(std::move(pc));
  }
  // the timeline: instants at 0, the ends and 1; cells between them
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
    if (options.first_contact && next == Status::separate) {
      seq.push_back({end, Status::touching, false});
      ++n_ends;
      stopped = true;
      break;
    }
    seq.push_back({end, Status::touching, false});
    ++n_ends;
    cur = next;
    cell_lo = bhi;
  }
  if (!stopped) {
    seq.push_back({exact_instant((cell_lo + 1) / 2), cur, true});
    seq.push_back({exact_instant(1), cur, false});
  }
  assemble_answer(seq, r.answer, [](std::size_t) {});
  if (options.first_contact && r.answer.intervals.size() > 1) r.answer.intervals.resize(1);
  r.decided = true;
  if (options.record) r.pieces = std::move(pieces);
  counters();
  r.work.emplace_back("bezier_proved_ends", n_ends);
  return r;
}

}  // namespace eccd
