#pragma once
// CD-DISC for cycloidal motions (003 sections IV and V, Example 1): the roots
// of the transcendental Δ(t) on [0, 1] isolated by validated subdivision, the
// cells between them decided by the static test at a sample, written once for
// the floating pipelines (T = Bounded<double>, Bounded<Mpfr>) and the
// certified one (T = MpfiInterval).
//
// Statement. As for rational motions (kernel/cd_disc.hpp), the contact status
// can change only at a root of Δ (003 Theorem 6, Corollary 7), so between
// consecutive roots it is decided at one sample (kernel/contact_status.hpp),
// and at a root it is touching iff f has a negative double root (signs of P
// and D). Δ is not a polynomial, so its roots are isolated on dyadic cells
// [a, b] of [0, 1] (a grid of 64, then bisection) with T read as an
// enclosure (number/enclosure.hpp):
//  - root-free: Δ([a, b]) excludes 0 (the better of the natural enclosure and
//    the mean-value form Δ(m) + Δ'([a, b])([a, b] - m));
//  - one simple root: Δ'([a, b]) excludes 0 (monotone, at most one root) and
//    Δ(a), Δ(b) have proved opposite signs (at least one): then bisection
//    narrows the bracket while the sign at the mid-point is proved;
//  - otherwise the cell is split, down to a width of 2^-max_depth; a cell
//    left then (Δ within its error bound on the whole cell: a double root, a
//    touch, two close roots or a near miss) is an undecided stretch, with the
//    proved bound ε >= |Δ| on it in the reason. It is never called a touch.
// Nothing is sampled without proof: a cell with no root is proved root-free,
// in the error-bounded sense of T (Bounded: a-priori bounds of every
// rounding, MPFR's sin/cos correctly rounded; MPFI: outward rounding). With
// MPFI every claim is a proof and the brackets [lo, hi] are exact dyadic
// rationals. The variants of 003 VI-C: 1 and 2 keep collides and the first
// contact, 3 the contacts and their points (Lemma 5), computed from the
// full isolation (no early stop).
// Requirements on T: as kernel/cycloidal_motion.hpp; enclosing (see above).
#include "kernel/answer.hpp"
#include "kernel/budget.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/collision_timeline.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/cycloidal_motion.hpp"
#include "kernel/pipeline_result.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace eccd {

struct CycloidalOptions {
  bool certified = false;   // instants with brackets (T = MpfiInterval)
  int max_depth = 40;       // smallest cell 2^-max_depth
  int refine_bits = 60;     // a simple root's bracket is narrowed to 2^-refine_bits (while signs are proved)
  long max_cells = 200000;  // work bound on cells examined
};

// One critical stretch of Δ: a proved simple root in (lo, hi), or an undecided stretch [lo, hi].
struct CycloidalCritical {
  mpq_class lo, hi;
  bool simple = true;
  double eps = 0;  // undecided: bound of |Δ| on [lo, hi]
};

template <class T>
class CycloidalIsolator {
 public:
  CycloidalIsolator(const CycloidalPair<T>& p, const T& like, const CycloidalOptions& o) : p_(p), like_(like), o_(o) {}

  T delta_point(const mpq_class& t) const { return cycloidal_delta<T>(p_, scalar_traits<T>::from_rational(t, like_)); }
  T delta_range(const mpq_class& a, const mpq_class& b) const {
    T x = range_of(a, b, like_);
    T nat = cycloidal_delta<T>(p_, x);
    if (sign(nat) != Sign::uncertain) return nat;
    mpq_class m = (a + b) / 2;
    T mv = delta_point(m) + dderiv_range(a, b) * range_of(mpq_class(a - m), mpq_class(b - m), like_);
    return sign(mv) != Sign::uncertain ? mv : nat;
  }
  T dderiv_range(const mpq_class& a, const mpq_class& b) const {
    T x = range_of(a, b, like_);
    Dual<T> t(x, T(1));
    return cycloidal_delta<Dual<T>>(p_, t).d;
  }

  std::vector<CycloidalCritical> run() {
    std::vector<CycloidalCritical> out;
    const int grid = 64;
    for (int k = 0; k < grid; ++k) {
      mpq_class a(k, grid), b(k + 1, grid);
      a.canonicalize();  // (gmpxx does not: 0/64 would not compare equal to 0)
      b.canonicalize();
      visit(a, b, 6, out);
    }
    // merge touching undecided stretches; try to prove a simple root on the merged stretch
    std::vector<CycloidalCritical> merged;
    for (auto& c : out) {
      if (!c.simple && !merged.empty() && !merged.back().simple && merged.back().hi == c.lo) {
        merged.back().hi = c.hi;
        merged.back().eps = std::max(merged.back().eps, c.eps);
      } else {
        merged.push_back(c);
      }
    }
    for (auto& c : merged) {
      if (c.simple) continue;
      mpq_class w = c.hi - c.lo;
      mpq_class a = std::max(mpq_class(0), mpq_class(c.lo - w)), b = std::min(mpq_class(1), mpq_class(c.hi + w));
      if (prove_simple(a, b)) {
        c.lo = a;
        c.hi = b;
        c.simple = true;
        refine(c);
      } else
        c.eps = magnitude_bound(delta_range(c.lo, c.hi));
    }
    return merged;
  }
  long cells() const { return cells_; }
  bool work_bound_hit() const { return hit_; }

 private:
  bool prove_simple(const mpq_class& a, const mpq_class& b) const {
    if (sign(dderiv_range(a, b)) == Sign::uncertain || sign(dderiv_range(a, b)) == Sign::zero) return false;
    Sign sa = sign(delta_point(a)), sb = sign(delta_point(b));
    return (sa == Sign::positive && sb == Sign::negative) || (sa == Sign::negative && sb == Sign::positive);
  }
  void refine(CycloidalCritical& c) const {
    Sign sl = sign(delta_point(c.lo));
    const mpq_class target(1, mpz_class(1) << o_.refine_bits);
    while (c.hi - c.lo > target) {
      check_deadline("cycloidal root refinement");
      mpq_class m = (c.lo + c.hi) / 2;
      Sign sm = sign(delta_point(m));
      if (sm == Sign::uncertain || sm == Sign::zero) break;  // the mid-point's sign is not proved: keep the bracket
      if (sm == sl)
        c.lo = m;
      else
        c.hi = m;
    }
  }
  void visit(const mpq_class& a, const mpq_class& b, int depth, std::vector<CycloidalCritical>& out) {
    check_deadline("cycloidal root isolation");
    ++cells_;
    Sign s = sign(delta_range(a, b));
    if (s == Sign::positive || s == Sign::negative) return;  // root-free, proved
    Sign d = sign(dderiv_range(a, b));
    if (d == Sign::positive || d == Sign::negative) {
      Sign sa = sign(delta_point(a)), sb = sign(delta_point(b));
      bool known = (sa == Sign::positive || sa == Sign::negative) && (sb == Sign::positive || sb == Sign::negative);
      if (known && sa == sb) return;  // monotone with equal end signs: root-free
      if (known) {
        CycloidalCritical c{a, b, true, 0};
        refine(c);
        out.push_back(c);
        return;
      }
    }
    if (depth >= o_.max_depth || cells_ >= o_.max_cells) {
      if (cells_ >= o_.max_cells) hit_ = true;
      out.push_back({a, b, false, 0});
      return;
    }
    mpq_class m = (a + b) / 2;
    visit(a, m, depth + 1, out);
    visit(m, b, depth + 1, out);
  }

  const CycloidalPair<T>& p_;
  T like_;
  CycloidalOptions o_;
  long cells_ = 0;
  bool hit_ = false;
};

// The last step of cycloidal_cd_disc: a reason for each stretch whose Δ sign
// was not proved (and for a work bound), then the answer cut to the variant.
template <class T>
void cycloidal_reasons_and_variant(PipelineResult<T>& res, const std::vector<CycloidalCritical>& crit,
                                   bool work_bound_hit, Variant variant) {
  Answer& ans = res.answer;
  for (auto& c : crit) {
    if (c.simple) continue;
    char eps[32];
    std::snprintf(eps, sizeof eps, "%.3g", c.eps);
    res.undecided_reasons.push_back("Δ has no proved sign on [" + decimal_string(c.lo, 25) + ", " +
                                    decimal_string(c.hi, 25) + "] (|Δ| <= " + eps +
                                    " there): a touch or near miss within that bound, or close roots; "
                                    "nothing is claimed there");
  }
  if (work_bound_hit) res.undecided_reasons.push_back("cycloidal root isolation: work bound reached (cells)");
  if (!ans.undecided.empty() && res.undecided_reasons.empty())
    res.undecided_reasons.push_back("a sign too close to zero to decide in this arithmetic");
  if (variant == Variant::collides || variant == Variant::first_contact) {
    ans.intervals.clear();
    ans.contacts.clear();
    ans.contact_points.clear();
    ans.contact_intervals.clear();
  } else if (variant == Variant::all_contacts) {
    ans.intervals.clear();
  }
}

template <class T>
PipelineResult<T> cycloidal_cd_disc(const CycloidalPair<T>& pair, const T& like, const CycloidalOptions& o,
                                    Variant variant = Variant::answer) {
  auto start = std::chrono::steady_clock::now();
  PipelineResult<T> res;
  res.variant = variant;
  CycloidalIsolator<T> iso(pair, like, o);
  std::vector<CycloidalCritical> crit = iso.run();
  res.counters.emplace_back("cells", iso.cells());

  auto point = [&](const mpq_class& t) { return scalar_traits<T>::from_rational(t, like); };
  auto instant_of = [&](const mpq_class& lo, const mpq_class& hi) {
    mpq_class mid = (lo + hi) / 2;
    if (o.certified) return bracketed_instant(mid, lo, hi);
    return rounded_instant(point(mid));
  };
  auto status_at = [&](const T& t) {
    auto g = cycloidal_g<T>(pair, t);
    return cubic_contact_status(g[3], g[2], g[1], g[0]);
  };
  auto root_status = [&](const CycloidalCritical& c) {
    if (!c.simple) return Status::uncertain;
    auto g = cycloidal_g<T>(pair, range_of(c.lo, c.hi, like));
    return status_at_multiple_root(sign(double_root_numerator(g[3], g[2], g[1], g[0])),
                                   sign(double_root_denominator(g[3], g[2], g[1])));
  };
  const mpq_class zero(0), one(1);
  res.status_at_0 = status_at(point(zero));
  std::vector<TimelineNode> seq;
  std::vector<const CycloidalCritical*> node_crit;
  auto push = [&](TimelineNode n, const CycloidalCritical* c) {
    seq.push_back(n);
    node_crit.push_back(c);
  };
  // An undecided stretch that reaches 0 or 1 makes that end undecided. (A
  // simple root's bracket may start at 0 or end at 1, but Δ's sign there is
  // proved non-zero, so the root is interior.)
  const CycloidalCritical* c0 =
      (!crit.empty() && !crit.front().simple && crit.front().lo == zero) ? &crit.front() : nullptr;
  const CycloidalCritical* c1 =
      (!crit.empty() && !crit.back().simple && crit.back().hi == one) ? &crit.back() : nullptr;
  auto end_status = [&](const mpq_class& t, const CycloidalCritical* c) {
    return c ? Status::uncertain : status_at(point(t));
  };
  push({instant_of(zero, zero), end_status(zero, c0), false}, c0);
  std::vector<const CycloidalCritical*> interior;
  for (auto& c : crit)
    if (&c != c0 && &c != c1) interior.push_back(&c);  // c0 == c1 is possible (all of [0, 1])
  for (std::size_t i = 0; i <= interior.size(); ++i) {
    mpq_class a = i ? interior[i - 1]->hi : (c0 ? c0->hi : zero);
    mpq_class b = i < interior.size() ? interior[i]->lo : (c1 ? c1->lo : one);
    mpq_class s = (a + b) / 2;
    // (a >= b only when one undecided stretch covers [0, 1]: nothing is known in between)
    Status cs = a < b ? status_at(point(s)) : Status::uncertain;
    push({instant_of(s, s), cs, true}, nullptr);
    res.cells.push_back({instant_of(s, s), cs});
    if (i < interior.size())
      push({instant_of(interior[i]->lo, interior[i]->hi), root_status(*interior[i]), false}, interior[i]);
  }
  push({instant_of(one, one), end_status(one, c1), false}, c1);
  check_isolated_instants(seq, false);
  res.timeline = seq;
  for (std::size_t k = 0; k < seq.size(); ++k)
    if (!seq[k].is_cell && node_crit[k])
      res.critical.push_back({seq[k].t, seq[k].status, node_crit[k]->simple ? 1 : 2});

  Answer& ans = res.answer;
  assemble_answer(seq, ans, [&](std::size_t k) {
    mpq_class t = node_crit[k] ? mpq_class((node_crit[k]->lo + node_crit[k]->hi) / 2) : (k == 0 ? zero : one);
    T tt = point(t);
    auto toc = [](const Matrix<T, 3>& m) {
      PolyMatrix<T, 3> r;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = Poly<T>(std::vector<T>{m[i][j]});
      return r;
    };
    auto g = cycloidal_g<T>(pair, tt);
    std::vector<Poly<T>> gp;
    for (auto& x : g) gp.push_back(Poly<T>(std::vector<T>{x}));
    ans.contact_points.push_back(
        contact_point(toc(cycloidal_quadric_at<T>(pair.a, tt)), toc(cycloidal_quadric_at<T>(pair.b, tt)), gp, tt));
  });
  cycloidal_reasons_and_variant(res, crit, iso.work_bound_hit(), variant);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

}  // namespace eccd
