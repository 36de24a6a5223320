#pragma once
// Independent motions by subdivision of F(u, s, t): which parts of A's path
// (s) enter B's swept volume and which parts of B's path (t) enter A's,
// written once for double and MPFR.
//
// Statement. Paper 001, section 4, "CCD for independent motions": A(s) and
// B(t) meet iff F(u, s, t) = det((u - 1)A(s) - uB(t)) <= 0 for every u in
// (0, 1) (kernel/trivariate_bernstein.hpp). The answer (scene-format.md,
// "Independent motions") is the projection on s of the meeting set
//   P_s = { s : some t in [0, 1] with A(s), B(t) meeting },
// as maximal closed intervals, and likewise P_t. Sign tests of the Bézier
// method (001 section 4) on boxes of F's tensor Bernstein net:
//  - a box U x S x T whose control points are all > 0 proves F > 0 on it: every
//    (s, t) of S x T is separate (a witness u in U);
//  - boxes U_1 .. U_m covering [0, 1] in u, each with all control points < 0,
//    prove F < 0 for all u: every (s, t) of S x T meets (overlap).
// classify_u splits u adaptively (halves) to find one or the other. A strip
// S x [0, 1] is "in" P_s as soon as one sub-box S x T is proved to overlap
// (then every s of S has a t), "out" when sub-boxes S x T_i covering [0, 1]
// in t are all proved separate, and otherwise split in s at 1/2. The u- and
// t-splits of a strip of width 2^-d go at most d/2 + extra_depth deep: near
// an end s* of P_s the margin of F on a strip at distance ~w from s* is ~w,
// while the hull's error over a t- or u-piece of width τ around the extreme
// point is ~τ² (F is quadratic there), so pieces of width ~sqrt(w) suffice.
// Within that limit the u-pieces of a t-piece of width 2^-e go at most
// e + u_lead deep: the hull's error over the t-piece is then no longer
// smaller than over the u-pieces, so finer u-pieces decide nothing that
// halving the t-piece would not (a sub-box of a proved box is proved too);
// the t-piece is split instead. Without that bound a t-piece too wide for
// any proof would be searched in u down to the limit over the whole range
// where F's sign changes: millions of box tests for one point near an end. A
// t-piece at the depth limit, or one on which F does not depend on t (a net
// of degree 0 there: its halves are the same piece), gets the full limit.
// Strips stop at width 2^-strip_depth (2^-18): an end of P_s lies in a run of
// unresolved strips between one proved in and one proved out. Inside that run
// the end is then located by bisection on single values s = x (F restricted
// to s = x, TriBern::at_s; the same tests with zero width in s, with finer t-
// and u-pieces until the value is decided), down to 2^-s_depth (2^-34 =
// 5.8e-11). A value is first tried on the edges t = 0 and t = 1 alone
// (F(u, x, 0) < 0 for every u proves x in): where the other path's end
// holds the extreme point, the t with F < 0 for all u form a range only as
// wide as the distance to the end, which the box search would have to
// resolve in t. A value that stays unknown (e.g. exactly at the end) is replaced
// by the two quarter points. One point test may use at most a tenth of the
// run's box tests (point_share): a value too close to the end for the
// arithmetic or the pieces' depth would otherwise use them all; a value that
// used its share is not tested again. The reported end is the mid-point of the final
// bracket. What this does not prove: that P_s crosses only once inside the
// run (a gap or a second interval narrower than the run, < 2^-18, would be
// missed there); the strip proofs cover everything outside the runs. A run
// that the bisection could not shrink below 4 x 2^-s_depth is reported in
// `undecided` with its range. P_t: the same on F with s and t exchanged.
// Honesty and termination: every sign is taken by scalar_traits<T>::sign,
// which for T = Bounded<U> (number/running_error.hpp) is "uncertain" inside
// the running error bound, so a proof in rounded arithmetic is a proof of the
// exact F's sign. Work is bounded (max_tests u-box tests, and the run's
// deadline, kernel/budget.hpp); strips left open then, runs of unresolved
// strips between two proved-out strips (a touch, a near miss or a collision
// narrower than a strip) or between two proved-in strips (a touching gap) are
// reported in `undecided` (values of s or of t) with where and why; nothing
// there is guessed.
// Requirements on T: scalar_traits<T> (from_rational, sign); intended for
// Bounded<double> and Bounded<Mpfr> (guarded), and plain double and Mpfr (as
// published: signs taken at face value). Ellipses and ellipsoids alike (F's
// sign convention is the same for H = 3 and 4). A net of degree 0 in s (that
// body does not move) is one strip: its sub-strips are the same function.
#include "kernel/answer.hpp"
#include "kernel/budget.hpp"
#include "kernel/trivariate_bernstein.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace eccd {

struct IndependentOptions {
  int strip_depth = 18;  // strips (proofs for whole ranges of s) of width down to 2^-strip_depth
  int s_depth = 34;     // an end inside such a strip: bisection by point tests down to 2^-s_depth (the ends' tolerance)
  int min_limit = 4;    // ... and at least this deep (wide strips fail fast and are split: cheaper than deep pieces)
  int extra_depth = 2;  // t- and u-pieces of a strip at depth d: at most d/2 + extra_depth deep
  int u_lead = 2;  // ... and the u-pieces of a t-piece at depth e at most e + u_lead deep (the depth limit at most)
  long max_tests = 40000000;  // u-box sign tests for the whole run (both projections; ~3e6 per second in double)
  // One point test may use at most max_tests / point_share box tests (at least 10000): a value closer to an end
  // than the arithmetic or the pieces' depth can tell apart would otherwise take the whole run's work.
  int point_share = 10;
};

struct IndependentResult {
  Answer answer;  // independent = true
  std::vector<std::string> undecided_reasons;
  std::vector<std::pair<std::string, long>> counters;
  int degree_s = 0, degree_t = 0;
  double seconds = 0;
};

// The subdivision's pieces (strips, dyadic cells, the projector), public: the
// proofs of certified/independent_proof.hpp and the certificate writer
// (certificate/write/independent_certificate.cpp) build on them.
namespace independent_subdivision {

enum class Strip { in, out, unknown };

// A dyadic range [i / 2^d, (i + 1) / 2^d] of u or t (within the strip's own [0, 1]).
struct Dyadic {
  int d = 0;
  unsigned long long i = 0;
};
// One box of a strip's proof: t-range x u-range, all control points > 0 (out) or < 0 (in).
struct WitnessBox {
  Dyadic t, u;
};

struct Piece {
  mpq_class lo, hi;
  Strip status;
  // Filled when the Projector records witnesses: "in": boxes with one t-range whose u-ranges cover [0, 1], each < 0;
  // "out": boxes each > 0 whose t-ranges cover [0, 1].
  std::vector<WitnessBox> witness = {};
  bool examined = true;  // false: the run stopped (work bound, deadline) before this piece was looked at
};

template <class T>
class Projector {
 public:
  Projector(const IndependentOptions& o, const T& like)
      : opt_(o), half_(scalar_traits<T>::from_rational(mpq_class(1, 2), like)), step_(half_) {}

  long tests = 0, strips = 0, points = 0;
  std::string stop_reason;
  std::string point_note;  // "" or why the bisection of an end stopped early (a point test reached its share)
  bool record =
      false;  // keep each proved strip's boxes in Piece::witness (certificate/write/independent_certificate.hpp)

  // The pieces of [0, 1] along axis 1 of F (s), in order.
  std::vector<Piece> project(const TriBern<T>& F) {
    std::vector<Piece> out;
    walk(F, mpq_class(0), mpq_class(1), 0, out);
    // a run of unresolved strips between a proved-in and a proved-out one holds an end: bisect it by point tests
    std::vector<Piece> runs;
    for (auto& p : out)
      if (!runs.empty() && runs.back().status == Strip::unknown && p.status == Strip::unknown) {
        runs.back().hi = p.hi;
        runs.back().examined = runs.back().examined && p.examined;
      } else {
        runs.push_back(p);
      }
    std::vector<Piece> refined;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Strip before = i > 0 ? runs[i - 1].status : Strip::out,
                  after = i + 1 < runs.size() ? runs[i + 1].status : Strip::out;
      if (runs[i].status != Strip::unknown || before == after || !runs[i].examined) {
        refined.push_back(runs[i]);
        continue;
      }
      mpq_class lo = runs[i].lo, hi = runs[i].hi;
      const mpq_class tol = mpq_class(1) / mpq_class(mpz_class(1) << opt_.s_depth);
      std::vector<mpq_class> spent;  // values whose point test used up its share: not tested again
      auto status_of = [&](const mpq_class& x, int depth) {
        if (std::find(spent.begin(), spent.end(), x) != spent.end()) return Strip::unknown;
        const Strip r = point(F, x, depth);
        if (point_over()) spent.push_back(x);
        return r;
      };
      for (int depth = opt_.strip_depth; hi - lo > tol && !stopped(); ++depth) {
        // the mid-point; if it stays unknown (e.g. exactly at the end), the quarter points
        const mpq_class mid = (lo + hi) / 2;
        const Strip r = status_of(mid, depth);
        if (r != Strip::unknown) {
          (r == before ? lo : hi) = mid;
          continue;
        }
        const mpq_class q1 = (lo + mid) / 2, q3 = (mid + hi) / 2;
        const bool moved_lo = status_of(q1, depth + 1) == before, moved_hi = status_of(q3, depth + 1) == after;
        if (moved_lo) lo = q1;
        if (moved_hi) hi = q3;
        if (!moved_lo && !moved_hi) break;
      }
      if (lo != runs[i].lo) refined.push_back({runs[i].lo, lo, before});
      refined.push_back({lo, hi, Strip::unknown});
      refined.back().examined = runs[i].examined;
      if (hi != runs[i].hi) refined.push_back({hi, runs[i].hi, after});
    }
    return refined;
  }

 private:
  IndependentOptions opt_;
  T half_;
  HalvingStep<T> step_;  // de Casteljau's step at 1/2 (number/halving_step.hpp)
  // Nets no longer in use, kept with their numbers' storage: a split or a copy into one of them allocates
  // nothing (an MPFR number's allocation cost as much as its arithmetic here).
  std::vector<TriBern<T>> spare_;

  TriBern<T> spare() {
    if (spare_.empty()) return TriBern<T>{};
    TriBern<T> f = std::move(spare_.back());
    spare_.pop_back();
    return f;
  }
  TriBern<T> copy_of(const TriBern<T>& x) {
    TriBern<T> f = spare();
    if (f.c.size() != x.c.size()) return x;
    f.n = x.n;
    std::copy(x.c.begin(), x.c.end(), f.c.begin());
    return f;
  }
  // The two halves of f along axis, on the stack as (right, left): the left half is worked on first.
  void push_halves(std::vector<std::tuple<TriBern<T>, int, unsigned long long>>& stack, TriBern<T>&& f, int axis, int d,
                   unsigned long long i) {
    TriBern<T> lo = spare();
    f.split_half_into(axis, step_, lo);
    stack.emplace_back(std::move(f), d + 1, 2 * i + 1);
    stack.emplace_back(std::move(lo), d + 1, 2 * i);
  }
  void recycle(std::vector<std::tuple<TriBern<T>, int, unsigned long long>>& stack) {
    for (auto& e : stack) spare_.push_back(std::move(std::get<0>(e)));
    stack.clear();
  }

  // The status of the single value s = x (F restricted to it): the edges t = 0 and t = 1 alone (edge_in), then
  // finer t- and u-pieces until decided (a value at distance d from an end needs pieces of ~sqrt(d), or t-pieces
  // of ~d to prove it in where the extreme is on t = 0 or 1: the edge's own line proves that).
  // At most max_tests / point_share box tests (point_over() after the call says it used them all; the value is then
  // unknown and point_note says why).
  Strip point(const TriBern<T>& F, const mpq_class& x, int depth) {
    const TriBern<T> at = F.at_s(scalar_traits<T>::from_rational(x, half_));
    const long share = std::max(10000L, opt_.max_tests / std::max(1, opt_.point_share));
    point_limit_ = tests + share;
    const int base = std::max(opt_.min_limit, depth / 2 + opt_.extra_depth);
    Strip r = edge_in(at, std::min(depth + 4, base + 8)) ? Strip::in : Strip::unknown;
    for (int lim = base; r == Strip::unknown && lim <= std::min(depth + 4, base + 8) && !stopped() && !point_over();
         lim += 2) {
      r = classify_strip(at, lim);
      ++points;
    }
    if (point_over()) {
      r = Strip::unknown;  // a strip cut short by the share proves nothing
      point_note = "a point test near the end used its share of the work (" + std::to_string(share) +
                   " box tests): the value is too close to the end for this arithmetic or depth";
    }
    point_limit_ = std::numeric_limits<long>::max();
    return r;
  }
  // The value's net `at` proved in on one of the edges t = 0 or t = 1 alone: F(u, x, t_e) < 0 for every u
  // (u-pieces down to 2^-u_limit). Where the other path's end holds the extreme point, the t with F < 0 for
  // all u form a range of width ~ the distance to the end, against ~ its square root at a fold: the box
  // search would need t-pieces that narrow, the edge's own line in u needs none.
  bool edge_in(const TriBern<T>& at, int u_limit) {
    for (const int k : {0, at.n[2]}) {
      TriBern<T> line;
      line.n = {at.n[0], 0, 0};
      for (int i = 0; i <= at.n[0]; ++i) line.c.push_back(at.at(i, 0, k));
      if (classify_u(line, u_limit) == -1) return true;
      if (at.n[2] == 0) break;
    }
    return false;
  }
  long point_limit_ = std::numeric_limits<long>::max();  // the current point test's last box test
  bool point_over() const { return tests > point_limit_; }

  bool stopped() {
    if (!stop_reason.empty()) return true;
    if (tests > opt_.max_tests)
      stop_reason = "work bound reached (" + std::to_string(opt_.max_tests) + " box tests)";
    else if (deadline_passed())
      stop_reason = deadline_reason();
    return !stop_reason.empty();
  }

  // +1: a u-piece with F > 0 on the whole box (separate); -1: F < 0 on it for all u (overlap); 0: neither proved.
  // Pruning: the control points f(i, j, k), i = 0..n_u, with (j, k) a corner
  // of the (s, t) box are the Bernstein coefficients in u of F(u, s_c, t_c)
  // on the u-piece, for that corner (s_c, t_c). All of them > 0 for one corner
  // means F > 0 somewhere in the box: no overlap proof for the box. All < 0
  // for one corner means F < 0 on the piece at that corner: no separation
  // proof from this piece or its sub-pieces. A piece that can help neither
  // proof is dropped (it needs a finer s or t, which the caller provides).
  int classify_u(const TriBern<T>& box, int u_limit) {
    std::vector<std::tuple<TriBern<T>, int, unsigned long long>> stack;
    stack.emplace_back(copy_of(box), 0, 0ULL);
    bool unknown = false, can_overlap = true;
    if (record) neg_u_.clear();
    while (!stack.empty()) {
      auto [f, d, ui] = std::move(stack.back());
      stack.pop_back();
      ++tests;
      const int sg = f.strict_sign();
      if (sg == 1) {
        if (record) pos_u_ = Dyadic{d, ui};
        spare_.push_back(std::move(f));
        recycle(stack);
        return 1;
      }
      if (sg == -1) {
        if (record) neg_u_.push_back(Dyadic{d, ui});
        spare_.push_back(std::move(f));
        continue;
      }
      bool pos = false, neg = false;  // some corner's edge all positive / all negative
      for (int j : {0, f.n[1]})
        for (int k : {0, f.n[2]}) {
          bool all_pos = true, all_neg = true;
          for (int i = 0; i <= f.n[0]; ++i) {
            const Sign c = sign(f.at(i, j, k));
            all_pos = all_pos && c == Sign::positive;
            all_neg = all_neg && c == Sign::negative;
          }
          pos = pos || all_pos;
          neg = neg || all_neg;
        }
      if (pos) can_overlap = false;
      if ((neg && !can_overlap) || d >= u_limit) {  // helps neither proof, or as deep as allowed
        unknown = true;
        spare_.push_back(std::move(f));
        continue;
      }
      push_halves(stack, std::move(f), 0, d, ui);
    }
    return unknown ? 0 : -1;
  }

  Strip classify_strip(const TriBern<T>& strip, int limit) {
    std::vector<std::tuple<TriBern<T>, int, unsigned long long>> stack;
    stack.emplace_back(copy_of(strip), 0, 0ULL);
    bool unknown = false;
    if (record) witness_.clear();
    while (!stack.empty()) {
      if (stopped() || point_over()) {
        recycle(stack);
        return Strip::unknown;
      }
      auto [f, d, ti] = std::move(stack.back());
      stack.pop_back();
      const bool flat_t = f.n[2] == 0;  // F does not depend on t here: splitting t gives the same piece again
      const int r = classify_u(f, flat_t ? limit : std::min(limit, d + opt_.u_lead));
      if (r == -1) {
        if (record) {
          witness_.clear();
          for (const Dyadic& u : neg_u_) witness_.push_back(WitnessBox{Dyadic{d, ti}, u});
        }
        spare_.push_back(std::move(f));
        recycle(stack);
        return Strip::in;
      }
      if (r == 1) {
        if (record) witness_.push_back(WitnessBox{Dyadic{d, ti}, pos_u_});
        spare_.push_back(std::move(f));
        continue;
      }
      if (d >= limit || flat_t) {
        unknown = true;
        spare_.push_back(std::move(f));
        continue;
      }
      push_halves(stack, std::move(f), 2, d, ti);
    }
    return unknown ? Strip::unknown : Strip::out;
  }

  std::vector<Dyadic> neg_u_;
  Dyadic pos_u_;
  std::vector<WitnessBox> witness_;

  void walk(const TriBern<T>& strip, const mpq_class& lo, const mpq_class& hi, int depth, std::vector<Piece>& out) {
    ++strips;
    const Strip r =
        stopped() ? Strip::unknown : classify_strip(strip, std::max(opt_.min_limit, depth / 2 + opt_.extra_depth));
    // F of degree 0 in s (that body does not move): every sub-strip is this strip again, splitting decides nothing
    if (r != Strip::unknown || depth >= opt_.strip_depth || !stop_reason.empty() || strip.n[1] == 0) {
      out.push_back({lo, hi, r});
      out.back().examined =
          r != Strip::unknown || stop_reason.empty();  // unknown because the run stopped: not examined
      if (record && r != Strip::unknown) out.back().witness = witness_;
      return;
    }
    auto halves = strip.split_half(1, half_);
    const mpq_class mid = (lo + hi) / 2;
    walk(halves.first, lo, mid, depth + 1, out);
    walk(halves.second, mid, hi, depth + 1, out);
  }
};

// Reasons "WHERE: CAUSE" with one entry per distinct cause: the places of one
// cause are joined ("s in [a, b], t in [c, d]: CAUSE"), in the order the
// causes first appear; a reason without "WHERE: " is kept once as it is.
inline std::vector<std::string> one_per_cause(const std::vector<std::string>& reasons) {
  std::vector<std::pair<std::string, std::string>> by_cause;  // cause, places
  for (const auto& r : reasons) {
    const auto cut = r.find(": ");
    const bool placed = cut != std::string::npos && (r.rfind("s in [", 0) == 0 || r.rfind("t in [", 0) == 0);
    const std::string cause = placed ? r.substr(cut + 2) : r, where = placed ? r.substr(0, cut) : "";
    auto it = std::find_if(by_cause.begin(), by_cause.end(), [&](const auto& e) { return e.first == cause; });
    if (it == by_cause.end())
      by_cause.emplace_back(cause, where);
    else if (!where.empty() && it->second.find(where) == std::string::npos)
      it->second += (it->second.empty() ? "" : ", ") + where;
  }
  std::vector<std::string> out;
  for (const auto& [cause, where] : by_cause) out.push_back(where.empty() ? cause : where + ": " + cause);
  return out;
}

// An end or a point known to within w (not certified: no bracket).
inline Instant located(const mpq_class& x, const mpq_class& w) {
  if (sgn(w) == 0) return Instant{decimal_string(x, 20), std::nullopt, std::nullopt, nearest_double(x)};
  return Instant{decimal_string(x, bracket_digits(x - w, x + w)), std::nullopt, std::nullopt, nearest_double(x)};
}

// Pieces -> maximal intervals of the "in" set, plus undecided values and reasons (`var` is "s" or "t").
inline std::vector<std::pair<Instant, Instant>> intervals_of(std::vector<Piece> pieces, const char* var, int s_depth,
                                                             const std::string& stop_reason,
                                                             std::vector<Instant>& undecided,
                                                             std::vector<std::string>& reasons,
                                                             const std::string& end_note = "") {
  auto merge = [](std::vector<Piece>& v) {
    std::vector<Piece> m;
    for (auto& p : v)
      if (!m.empty() && m.back().status == p.status) {
        m.back().hi = p.hi;
        m.back().examined = m.back().examined && p.examined;
      } else {
        m.push_back(p);
      }
    v = std::move(m);
  };
  merge(pieces);
  mpq_class strip(1);
  strip /= mpq_class(mpz_class(1) << s_depth);
  const std::string v = var;
  auto range = [&](const Piece& p) {
    return v + " in [" + decimal_string(p.lo, 12) + ", " + decimal_string(p.hi, 12) + "]";
  };
  const std::string why = stop_reason.empty() ? "" : " (" + stop_reason + ")";
  std::vector<Piece> resolved;
  std::vector<mpq_class> end_width;  // per resolved piece: the uncertainty of its hi end (0 = exact)
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Piece p = pieces[i];
    if (p.status != Strip::unknown) {
      resolved.push_back(p);
      end_width.push_back(0);
      continue;
    }
    const Strip before = i > 0 ? pieces[i - 1].status : Strip::out;
    const Strip after = i + 1 < pieces.size() ? pieces[i + 1].status : Strip::out;
    const mpq_class mid = (p.lo + p.hi) / 2, w = p.hi - p.lo;
    if (!p.examined) {  // the run stopped before looking here: nothing is said about it, in or out
      undecided.push_back(located(mid, w / 2));
      reasons.push_back(range(p) + ": not examined, the run stopped" + why);
      p.status = Strip::out;  // for the intervals only: `collides` and the reasons say what is not known
      resolved.push_back(p);
      end_width.push_back(0);
      continue;
    }
    if (before == after) {  // in-unknown-in or out-unknown-out (the ends of [0, 1] count as out)
      undecided.push_back(located(mid, w / 2));
      reasons.push_back(range(p) + ": " +
                        (before == Strip::in
                             ? "inside the meeting set on both sides: a touching gap or none"
                             : "separate on both sides: a touch, a near miss or a collision narrower than the strips") +
                        " could not be told apart" + why);
      p.status = before;
      resolved.push_back(p);
      end_width.push_back(0);
      continue;
    }
    if (w > 4 * strip) {
      undecided.push_back(located(mid, w / 2));
      const std::string note = !why.empty() || end_note.empty() ? why : " (" + end_note + ")";
      reasons.push_back(range(p) + ": an end of the " + v + "-intervals is only located in this range" + note);
    }
    resolved.push_back({p.lo, mid, before});
    end_width.push_back(w / 2);
    resolved.push_back({mid, p.hi, after});
    end_width.push_back(0);
  }
  // merge again, keeping the end uncertainty of the last piece of each run
  std::vector<std::pair<Instant, Instant>> out;
  mpq_class start_w = 0;
  for (std::size_t i = 0; i < resolved.size(); ++i) {
    if (resolved[i].status != Strip::in) {
      start_w = end_width[i];
      continue;
    }
    std::size_t j = i;
    while (j + 1 < resolved.size() && resolved[j + 1].status == Strip::in) ++j;
    out.emplace_back(located(resolved[i].lo, start_w), located(resolved[j].hi, end_width[j]));
    start_w = end_width[j];
    i = j;
  }
  return out;
}

}  // namespace independent_subdivision

// The answer of an independent scene from F(u, s, t) (kernel/trivariate_bernstein.hpp).
template <class T>
IndependentResult ccd_independent(const TriBern<T>& F, const T& like, const IndependentOptions& opt = {}) {
  using namespace independent_subdivision;
  const auto start = std::chrono::steady_clock::now();
  IndependentResult r;
  r.answer.independent = true;
  r.degree_s = F.n[1];
  r.degree_t = F.n[2];
  IndependentOptions half = opt;  // the work bound: half for each projection, and what s leaves to t
  half.max_tests = opt.max_tests / 2;
  Projector<T> ps(half, like);
  auto s_pieces = ps.project(F);
  half.max_tests = opt.max_tests - std::min(ps.tests, opt.max_tests / 2);
  Projector<T> pt(half, like);
  auto t_pieces = pt.project(F.swap_st());
  r.answer.s_intervals =
      intervals_of(s_pieces, "s", opt.s_depth, ps.stop_reason, r.answer.undecided, r.undecided_reasons, ps.point_note);
  r.answer.t_intervals =
      intervals_of(t_pieces, "t", opt.s_depth, pt.stop_reason, r.answer.undecided, r.undecided_reasons, pt.point_note);
  r.answer.collides = !r.answer.s_intervals.empty() || !r.answer.t_intervals.empty();
  if (r.answer.s_intervals.empty() != r.answer.t_intervals.empty()) {
    r.undecided_reasons.push_back(
        "one projection found a meeting and the other none (a meeting set thinner than the strips)");
    r.answer.undecided.push_back(Instant{"0", std::nullopt, std::nullopt, 0.0});
  }
  r.undecided_reasons = one_per_cause(r.undecided_reasons);
  r.counters = {
      {"box_tests", ps.tests + pt.tests}, {"strips", ps.strips + pt.strips}, {"point_tests", ps.points + pt.points}};
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace eccd
