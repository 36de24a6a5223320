#pragma once
// Proved answers of independent motions for general rational motions of two
// ellipsoids or two ellipses: every cell of s (and of t) is
// decided by a proof about the exact F, and every end of an s- or t-interval
// is a rational bracket that provably holds exactly one end.
//
// Statement. Paper 001, section 4, "CCD for independent motions": with
// F(u, s, t) = det((u - 1)A(s) - uB(t)) (kernel/trivariate_bernstein.hpp),
// A(s) and B(t) meet iff F(., s, t) <= 0 on (0, 1); the answer is the
// projection P_s = { s : A(s) meets B(t) for some t in [0, 1] } as maximal
// closed intervals, and P_t likewise. The paper projects the extreme points
// F = F_u = F_t = 0 (ends of P_s) and F = F_u = F_s = 0 (ends of P_t) by
// resultants; their degrees in 3D run into the thousands, so the ends are
// proved instead by the method below, which needs only F's tensor Bernstein
// net (degree 4 in u, a few in s and t).
//  1. F's net is built EXACTLY from the exact scene (rationals, once) and
//     enclosed coefficient by coefficient in intervals: of doubles for the
//     localisation (number/interval.hpp, each operation widened outwards) and
//     MPFI for the ends (number/mpfi_interval.hpp, outward rounding, `bits`
//     bits; also for the localisation with localise_in_mpfi). Every sign taken
//     from an interval that does not contain 0 is the sign of the exact
//     number it encloses; de Casteljau in interval arithmetic (also at an
//     interval parameter) encloses the exact sub-net, so the convex hull
//     property turns "every interval > 0" into a proof that F > 0 on the box.
//     The net's faces u = 0 and u = 1 are checked once to be < 0 (F(0, s, t) =
//     det A(s), F(1, s, t) = det B(t)), so a maximum of F(., s, t) equal to 0
//     lies inside (0, 1).
//  2. Localisation: the subdivision of floating/independent_ccd.hpp (the same
//     template, T = Interval): a strip of s proved "out" (every (s, t)
//     separate, a witness u) or "in" (some t with F < 0 for every u) is a
//     theorem about the exact F. The floating pipeline's bisection by point
//     tests is switched off (s_depth = 0): it proves single values of s,
//     not the ranges between them. What remains are runs [lo, hi] of
//     unresolved strips (width 2^-16 each) between proved strips.
//  3. An end in [lo, hi]. Lemma: if s* in (0, 1) is an end of P_s, there are
//     t* in [0, 1], u* in (0, 1) with F = F_u = 0 at (u*, s*, t*) and
//     (t* = 0 or t* = 1 or F_t = 0 or F_uu = 0) there. (Proof: A(s*), B(t*)
//     meet for some t*, and not with interior overlap, else nearby s would
//     too; so max_u F(., s*, t*) = 0, at u* in (0, 1) with F_u = 0. F has at
//     most two roots in (0, 1) counted with multiplicity (they are the
//     negative roots of the quartic f, which has two positive ones: 001
//     section 2), so u* is the only maximiser; if F_uu(u*) < 0, t* in (0, 1)
//     and F_t != 0, the implicit function theorem makes G(s, t) = max_u F
//     smooth near (s*, t*) with G_t = F_t != 0, so every s near s* has a t
//     with G(s, t) < 0 and s* is no end.) Call that set C. Proof that [lo, hi]
//     holds exactly one end:
//     a. a point (u~, s~, t~) from Newton's method in double on the square
//        system (F, F_u, F_t) in (u, s, t) (a fold), or on (F, F_u) in (u, s)
//        at t = 0 or t = 1 (an end where the path of B stops); double only
//        proposes, nothing is decided by it;
//     b. Krawczyk's test (Krawczyk 1969; Moore, Kearfott, Cloud, "Introduction
//        to Interval Analysis", 2009, section 8.2) on a box X around it whose
//        s-range covers [lo, hi]: K(X) = x~ - Y f(x~) + (I - Y J(X))(X - x~)
//        inside the interior of X proves that X holds exactly one zero of the
//        system (Y: any matrix, here the inverse of J's mid-point in double);
//        for a fold, F_uu < 0 on X and X's t-range inside (0, 1) (so C meets X
//        in that zero only); at t = t_b, F_t and F_uu of one sign on X's (u, t)
//        box times [lo, hi] (so C meets it on t = t_b only, in that zero);
//     c. exclusion of C from the rest of the strip: the nets of F, F_u, F_t,
//        F_uu restricted to s in [lo, hi] are cut in (u, t) into boxes until
//        each lies in X's (u, t) range or has F of one sign, or F_u of one
//        sign, or (t-range inside (0, 1) and F_t and F_uu of one sign);
//     then C meets the strip in one point, of s-coordinate s_p; by the lemma
//     every end of P_s in (lo, hi) is s_p, and since lo is proved out and hi
//     in (or the reverse) P_s ∩ [lo, hi] is [s_p, hi] (or [lo, s_p]): exactly
//     one end. Its bracket is K's s-range (Krawczyk iterated on X ∩ K(X),
//     which keeps the zero) intersected with [lo, hi], rational end points.
//     d. when a-c fail on [lo, hi], the run is narrowed (narrowed_run: the
//        strip proofs of step 2 once more inside it, strips down to 1/16 of
//        its width) and a-c are tried on the run that remains. Where the
//        fold is flat in t (G = max_u F, |G_tt| small against |G_st|), the
//        points with G_t = 0 sweep |G_st / G_tt| run widths of t across the
//        run: X's t-range must cover that sweep for c to close, while
//        Krawczyk's test needs X small against G_tt. The narrower run
//        shrinks the sweep; its proved sides are strips like any other.
//  4. P_t: the same on F with s and t exchanged (TriBern::swap_st).
// What is not claimed: a run between two proved-out values (a touch, a near
// miss or a meeting narrower than the strips) or two proved-in values (a
// touching gap), and any end whose Krawczyk test or exclusion fails (a
// degenerate end: a touch, a cusp, two ends closer than the strips); those
// ranges go to `undecided` with where and why. The ends of [0, 1] are exact.
// Work is bounded (box tests of the localisation, exclusion boxes per end).
// Ellipses (H = 3) and ellipsoids (H = 4) alike: kernel/trivariate_bernstein.hpp
// gives F the same sign convention in both, and the lemma's "at most two roots
// in (0, 1)" holds for the cubic too (its negative roots).
// Degenerate paths. A body that does not move as a set (static, or turning
// in place: A(s) = c(s) A(0), c > 0) is held at s = 0 when F's net is built
// (kernel/trivariate_bernstein.hpp, hold_still: the meeting sets are the
// same), and a net of nominal degree > 0 that does not depend on a parameter
// is F = p G with p of one sign along it (TriBern::without_positive_factor,
// checked exactly); either way the proof runs on a net of degree 0 there. Its
// projection is then all of [0, 1] or nothing, and the other projection's
// ends are the lower-dimensional problem: F = F_u = 0 in (u, s) (system
// "free"), proved by Krawczyk's test in (u, s) and the exclusion of other
// zeros of (F, F_u) for u outside X's u-range and every t (no condition on
// F_t, which is identically 0). Paths that run along each other in the same
// lane only make P_s or P_t all of [0, 1] (no end to prove) or put the
// extreme on t = 0 or 1 (the edge systems above). A path that leaves its
// start (or reaches its end) sideways to the other body makes F_t vanish
// identically on that face (the distance changes to second order); then the
// edge system's "F_t of one sign" is asked of F_t / t (or F_t / (1 - t)),
// built exactly (edge_quotient): one sign of it on X's box means F_t != 0
// there off the face, which is all that the uniqueness of C in X needs.
// Cost (Release, CPU seconds of one core, a loaded machine): every scene of
// cases/independent 0.01-0.55 s (ellipsoids-cross and -turning 0.5 s, most
// of it the localisation in intervals of doubles), generated pairs of
// ellipsoids turning by degree-2 Euler parameters 0.02-1.1 s. The
// localisation's work is bounded in coefficient operations (box tests times
// the net's size, IndependentProofOptions::localise_work), so a large net
// stops early and says where, rather than running for minutes.
// Requirements: the exact net TriBern<Rational>; intervals Interval and
// MpfiInterval; double only for the Newton points and Y (any value is sound
// there).
#include "certified/exclusion.hpp"
#include "certified/krawczyk.hpp"
#include "floating/independent_ccd.hpp"
#include "kernel/answer.hpp"
#include "kernel/trivariate_bernstein.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"
#include "number/rational_traits.hpp"

#include <gmpxx.h>
#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace eccd {

struct IndependentProofOptions {
  int bits = 160;  // MPFI precision of the enclosed net
  IndependentOptions localise = [] {
    IndependentOptions o;
    o.strip_depth = 16;  // strips down to 2^-16; Krawczyk gives the fine bracket
    o.s_depth = 0;       // no bisection by point tests: it proves single values, not the ranges between them
    o.max_tests = 1000000;
    return o;
  }();
  double localise_work = 2e8;  // ... and at most this many coefficient operations (box tests times the net's size)
  bool localise_in_mpfi =
      false;               // localisation in intervals of doubles (number/interval.hpp: also enclosures) or in MPFI
  long max_boxes = 20000;  // exclusion boxes per box X, 3x that per end (a proved end needed 60 to 300 in the cases)
  int max_box_depth = 36;
  bool record = false;  // keep the proof (strip witness boxes, Krawczyk boxes) in the result: for the certificate
  // an end not proved on its run: the run's strips once more, down to 2^-narrow_depth of its width
  // (narrowed_run; 0: never), within this many box tests
  int narrow_depth = 4;
  long narrow_tests = 200000;
};

// What a proof of one projection consists of, for the certificate (certificate/write/independent_certificate.hpp).
struct IndependentEndRecord {
  mpq_class run_lo, run_hi;  // the run of unresolved strips holding the end
  std::string system;        // "fold", "t = 0", "t = 1" (the other parameter named by var)
  std::vector<std::vector<mpq_class>> chain_lo, chain_hi;  // X = Y_0 (K(X) inside X), Y_{i+1} contains Y_i ∩ K(Y_i)
  mpq_class lo, hi;  // the bracket: [max(run_lo, Y_last.s_lo), min(run_hi, Y_last.s_hi)]
};
struct IndependentProjectionRecord {
  std::vector<independent_subdivision::Piece> pieces;  // in order, proved ones with their witness boxes
  std::vector<IndependentEndRecord> ends;
};

struct IndependentProofResult {
  IndependentProjectionRecord s_record, t_record;  // filled (witness boxes) when IndependentProofOptions::record
  Answer answer;                                   // independent = true; instants with proved brackets
  std::vector<std::string> undecided_reasons;
  std::vector<std::string> proofs;  // one line per end: how it was proved
  std::vector<std::pair<std::string, long>> counters;
  int degree_s = 0, degree_t = 0;
  double seconds = 0;
};

// F = p G with p of one sign along s or t (a body that does not move as a set): G, of degree 0 there
// (TriBern::without_positive_factor, exact); else F. Axis s first, then t. The proofs below run on it;
// the certificate writer (certificate/write/independent_certificate.cpp) refuses a net it changes.
inline TriBern<Rational> independent_net_reduced(const TriBern<Rational>& exact) {
  TriBern<Rational> reduced = exact;
  for (int axis : {1, 2})
    if (auto g = reduced.without_positive_factor(axis)) reduced = std::move(*g);
  return reduced;
}

namespace independent_proof_detail {

using I = MpfiInterval;
using independent_subdivision::Piece;
using independent_subdivision::Strip;

using namespace krawczyk_method;  // Nets, System, Box, newton, krawczyk (certified/krawczyk.hpp)

struct EndProof {
  bool proved = false;
  mpq_class lo, hi;  // the bracket of the end
  std::string system;
  std::vector<std::vector<mpq_class>> chain_lo, chain_hi;
  std::string how, why;
  long boxes = 0;
};

// F_t / t (edge 0) or F_t / (1 - t) (edge 1), exactly, when F_t vanishes
// identically on that face of the net (t = 0: every d_0 = 0, with d_k the
// Bernstein coefficients n (c_{k+1} - c_k) of F_t, degree m = n - 1); then
// B^m_k(t) / t = (m / k) B^{m-1}_{k-1}(t) and B^m_k(t) / (1 - t) =
// (m / (m - k)) B^{m-1}_k(t). A path that starts or stops moving "sideways"
// (the distance to the other body changes only to second order there) gives
// such a face: the edge system's condition "F_t of one sign" then cannot
// hold, but "F_t / t of one sign" says the same for t != t_b.
inline std::optional<TriBern<I>> edge_quotient(const TriBern<Rational>& F, int edge, int bits) {
  const int n = F.n[2], m = n - 1;
  if (m < 1) return std::nullopt;
  const int k0 = edge == 0 ? 0 : m;
  for (int i = 0; i <= F.n[0]; ++i)
    for (int j = 0; j <= F.n[1]; ++j)
      if (F.at(i, j, k0 + 1) != F.at(i, j, k0)) return std::nullopt;
  TriBern<I> G;
  G.n = {F.n[0], F.n[1], m - 1};
  for (int i = 0; i <= F.n[0]; ++i)
    for (int j = 0; j <= F.n[1]; ++j)
      for (int k = 0; k < m; ++k) {
        const int kd = edge == 0 ? k + 1 : k;  // the coefficient d_kd of F_t
        const Rational d = Rational(n) * (F.at(i, j, kd + 1) - F.at(i, j, kd));
        const Rational w = edge == 0 ? Rational(m, kd) : Rational(m, m - kd);
        G.c.emplace_back(Rational(d * w), bits);
      }
  return G;
}

class EndProver {
 public:
  EndProver(Nets& nets, const IndependentProofOptions& o, std::array<std::optional<TriBern<I>>, 2> quotients = {})
      : nets_(nets), opt_(o), quotients_(std::move(quotients)) {}
  long boxes = 0, krawczyk_tests = 0;

  // [lo, hi]: a run of s between proved values of opposite status; var: "s" or "t" for the texts.
  EndProof prove(const mpq_class& lo, const mpq_class& hi, const std::string& var) {
    EndProof best;
    best.why = "no candidate extreme point (F = F_u = F_" + std::string(var == "s" ? "t" : "s") +
               " = 0, or F = F_u = 0 on an end of the other path) was proved unique there";
    const double sm = nearest_double((lo + hi) / 2);
    // seeds: the other parameter where max_u F is smallest, interior and on the two ends
    const int NT = 64, NU = 64;
    std::vector<std::pair<double, std::array<double, 3>>> seeds;
    double best_g = 1e300;
    std::array<double, 3> best_x{};
    for (int k = 0; k <= NT; ++k) {
      const double t = double(k) / NT;
      double g = -1e300, ua = 0.5;
      for (int j = 1; j < NU; ++j) {
        const double u = double(j) / NU, v = nets_.eval_mid({0, 0, 0}, {u, sm, t});
        if (v > g) {
          g = v;
          ua = u;
        }
      }
      if (k == 0 || k == NT)
        seeds.push_back({g, {ua, sm, t}});
      else if (g < best_g) {
        best_g = g;
        best_x = {ua, sm, t};
      }
    }
    seeds.push_back({best_g, best_x});
    // F does not depend on the other parameter (that body does not move, kernel/trivariate_bernstein.hpp,
    // without_positive_factor): every t is alike, one seed on t = 0 and the system F = F_u = 0 in (u, s)
    const bool free = nets_.get({0, 0, 0}).n[2] == 0;
    if (free) seeds.erase(seeds.begin() + 1, seeds.end());
    const long start_boxes = boxes;
    std::sort(seeds.begin(), seeds.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [g, x0] : seeds) {
      (void)g;
      const bool edge = x0[2] == 0.0 || x0[2] == 1.0;
      System sys;
      sys.eqs = {{0, 0, 0}, {1, 0, 0}};
      sys.vars = {0, 1};
      if (free) {
        sys.fixed_t = mpq_class(0);
        sys.kind = "free";
      } else if (edge) {
        sys.fixed_t = mpq_class(x0[2] == 0.0 ? 0 : 1);
        sys.kind = var == "s" ? "t" : "s";
        sys.kind += std::string(" = ") + (x0[2] == 0.0 ? "0" : "1");
      } else {
        sys.eqs.push_back({0, 0, 1});
        sys.vars.push_back(2);
        sys.kind = "fold";
      }
      if (boxes - start_boxes > 3 * opt_.max_boxes) {
        best.why += "; stopped after " + std::to_string(boxes - start_boxes) + " exclusion boxes for this end";
        break;
      }
      auto x = newton(nets_, sys, x0);
      if (!x) continue;
      if (!edge && ((*x)[2] <= 0 || (*x)[2] >= 1)) continue;
      const mpq_class xs = exact_of((*x)[1]);
      if (xs < lo - (hi - lo) || xs > hi + (hi - lo)) continue;  // Newton went to another extreme point
      budget_end_ = start_boxes + 3 * opt_.max_boxes;
      EndProof p = prove_at(sys, *x, lo, hi, var);
      if (p.proved) return p;
      best.why = p.why;
    }
    return best;
  }

 private:
  Nets& nets_;
  const IndependentProofOptions& opt_;
  std::array<std::optional<TriBern<I>>, 2> quotients_;  // edge_quotient on t = 0 and t = 1, where F_t vanishes there

  // X <- K(X) ∩ X, at most 12 times, keeps the unique zero; each box joins the proof's chain. False if a box
  // empties, which cannot happen for a proved zero (then nothing is claimed).
  bool tighten(const System& sys, Box& Y, EndProof& r) {
    r.chain_lo = {Y.lo};
    r.chain_hi = {Y.hi};
    for (int it = 0; it < 12; ++it) {
      Box K2;
      krawczyk(nets_, sys, Y, K2);
      if (K2.lo.size() != Y.lo.size()) break;  // not computable (an infinite end): keep Y
      bool ok = true;
      for (std::size_t v = 0; v < Y.lo.size(); ++v) {
        if (K2.lo[v] > Y.lo[v]) Y.lo[v] = K2.lo[v];
        if (K2.hi[v] < Y.hi[v]) Y.hi[v] = K2.hi[v];
        ok = ok && Y.lo[v] <= Y.hi[v];
      }
      if (!ok) return false;
      r.chain_lo.push_back(Y.lo);
      r.chain_hi.push_back(Y.hi);
      if (Y.hi[1] - Y.lo[1] < mpq_class(1, mpz_class(1) << 100)) break;
    }
    return true;
  }

  EndProof prove_at(const System& sys, const std::array<double, 3>& x, const mpq_class& lo, const mpq_class& hi,
                    const std::string& var) {
    EndProof r;
    const int bits = nets_.bits();
    const mpq_class w = hi - lo;
    const mpq_class s0 = exact_of(x[1]), u0 = exact_of(x[0]), t0 = exact_of(x[2]);
    const std::string other = var == "s" ? "t" : "s";
    r.why = "Krawczyk's test failed around the extreme point near " + var + " = " + decimal_string(s0, 12) + " (" +
            (sys.kind == "fold"   ? "a fold, " + other + " = " + decimal_string(t0, 8)
             : sys.kind == "free" ? "F does not depend on " + other
                                  : "on " + sys.kind) +
            ")";
    // each rung's failed condition, one entry per distinct cause with the rungs (half-widths in strip widths)
    std::vector<std::pair<std::string, std::string>> fails;
    auto fail = [&fails](const std::string& cause, int f, const std::string& where = "") {
      auto it = std::find_if(fails.begin(), fails.end(), [&](const auto& c) { return c.first == cause; });
      if (it == fails.end()) it = fails.insert(fails.end(), {cause, ""});
      it->second += (it->second.empty() ? "" : "; ") + std::to_string(f) + (where.empty() ? "" : " near " + where);
    };
    // the (u, t) half-width of X: the fold's branch of F = F_u = 0 spreads ~sqrt(w) in t across the strip, and
    // Krawczyk's test needs X small: a ladder from wide to narrow
    for (const int f : {1024, 256, 64, 16, 4, 1}) {
      const mpq_class rho = w * f;
      if (boxes > budget_end_) break;
      if (rho > mpq_class(1, 16)) continue;
      // X: u0 ± rho, s-range covering [lo, hi] and s0 ± rho, t0 ± rho (fold) or fixed t
      Box X;
      X.lo = {u0 - rho, std::min(lo, mpq_class(s0 - rho))};
      X.hi = {u0 + rho, std::max(hi, mpq_class(s0 + rho))};
      if (!sys.fixed_t) {
        X.lo.push_back(t0 - rho);
        X.hi.push_back(t0 + rho);
      }
      Box K;
      ++krawczyk_tests;
      if (!krawczyk(nets_, sys, X, K)) {
        fail("K(X) is not inside X", f);
        continue;
      }
      // the (u, t) box that the exclusion leaves to X, and the conditions that make C meet it in the zero only
      mpq_class xu0 = X.lo[0], xu1 = X.hi[0], xt0, xt1;
      std::array<I, 3> region{I(X.lo[0], X.hi[0], bits), I(lo, hi, bits), I(mpq_class(0), bits)};
      if (sys.kind == "free") {  // every t alike: X's (u, t) box is its u-range times [0, 1]
        xt0 = 0;
        xt1 = 1;
        region[1] = I(std::min(lo, X.lo[1]), std::max(hi, X.hi[1]), bits);
      } else if (sys.fixed_t) {
        const bool at0 = sgn(*sys.fixed_t) == 0;
        xt0 = at0 ? mpq_class(0) : mpq_class(1 - rho);
        xt1 = at0 ? rho : mpq_class(1);
        region[1] = I(std::min(lo, X.lo[1]), std::max(hi, X.hi[1]), bits);
        region[2] = I(xt0, xt1, bits);
        const auto& q = quotients_[at0 ? 0 : 1];
        const bool ft =
            one_sign(nets_.eval({0, 0, 1}, region)) || (q && one_sign((*q)(region[0], region[1], region[2])));
        if (!ft || !one_sign(nets_.eval({2, 0, 0}, region))) {
          fail("F_" + other + " or F_uu changes sign near that end of the path", f);
          continue;
        }
      } else {
        xt0 = X.lo[2];
        xt1 = X.hi[2];
        region[1] = I(X.lo[1], X.hi[1], bits);
        region[2] = I(xt0, xt1, bits);
        if (sgn(xt0) <= 0 || xt1 >= 1 || sign(nets_.eval({2, 0, 0}, region)) != Sign::negative) {
          fail("F_uu is not proved < 0 there (a degenerate touch?)", f);
          continue;
        }
      }
      std::string ex = exclude(lo, hi, xu0, xu1, xt0, xt1);
      if (!ex.empty()) {
        fail(ex, f, ex == "another possible extreme point could not be excluded" ? stuck_at_ : "");
        continue;
      }
      // tighten: X <- K(X) ∩ X keeps the unique zero
      r.system = sys.kind == "free" || !sys.fixed_t ? sys.kind : sys.kind.substr(4);  // "fold", "free", "0", "1"
      Box Y = X;
      if (!tighten(sys, Y, r)) return r;
      r.lo = std::max(lo, Y.lo[1]);
      r.hi = std::min(hi, Y.hi[1]);
      if (r.lo > r.hi) {
        r.why = "the proved extreme point lies outside the run (internal inconsistency)";
        return r;
      }
      r.proved = true;
      r.how =
          var + " in [" + decimal_string(lo, 12) + ", " + decimal_string(hi, 12) + "]: one end, " +
          (sys.kind == "fold"   ? "a fold F = F_u = F_" + other + " = 0 (Krawczyk, F_uu < 0)"
           : sys.kind == "free" ? "F = F_u = 0 in (u, " + var + "), F not depending on " + other + " (Krawczyk)"
                                : "F = F_u = 0 on " + sys.kind + " (Krawczyk, F_" + other + " and F_uu of one sign)") +
          ", the rest of the strip excluded in " + std::to_string(last_boxes_) + " boxes";
      return r;
    }
    for (std::size_t i = 0; i < fails.size(); ++i)
      r.why += (i ? "; " : ": ") + fails[i].first + " (X's half-width in strip widths: " + fails[i].second + ")";
    return r;
  }

  long last_boxes_ = 0;
  std::string stuck_at_;  // where the last exclusion that could not close stopped
  long budget_end_ = 0;   // exclusion boxes allowed up to here for the current end

  static bool one_sign(const I& x) {
    const Sign s = sign(x);
    return s == Sign::positive || s == Sign::negative;
  }

  // Exclude C from s in [lo, hi] outside the (u, t) box [xu0, xu1] x [xt0, xt1]; "" on success, else why not.
  std::string exclude(const mpq_class& lo, const mpq_class& hi, const mpq_class& xu0, const mpq_class& xu1,
                      const mpq_class& xt0, const mpq_class& xt1) {
    const int bits = nets_.bits();
    std::array<TriBern<I>, 4> f;  // F, F_u, F_t, F_uu on s in [lo, hi]
    const std::array<std::array<int, 3>, 4> ords{{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {2, 0, 0}}};
    for (int i = 0; i < 4; ++i) f[i] = restrict_axis(nets_.get(ords[i]), 1, lo, hi, bits);
    auto excluded = [](const std::array<TriBern<I>, 4>& g, const ExclusionRegion& r) {
      if (g[0].strict_sign() != 0 || g[1].strict_sign() != 0) return true;
      return sgn(r.t0) > 0 && r.t1 < 1 && g[2].strict_sign() != 0 && g[3].strict_sign() != 0;
    };
    const ExclusionResult e = exclude_region(std::move(f), 0, 2, {0, 1, 0, 1}, {xu0, xu1, xt0, xt1}, excluded,
                                             opt_.max_boxes, opt_.max_box_depth, 1, I(mpq_class(1, 2), bits));
    boxes += e.boxes;
    last_boxes_ = e.boxes;
    if (e.status == ExclusionResult::too_many_boxes)
      return "the exclusion of other extreme points needed more than " + std::to_string(opt_.max_boxes) + " boxes";
    if (e.status == ExclusionResult::deadline) return deadline_reason();
    if (e.status == ExclusionResult::stuck) {
      stuck_at_ = "u = " + decimal_string(e.u0, 8) + ", other parameter = " + decimal_string(e.t0, 8);
      return "another possible extreme point could not be excluded";
    }
    return "";
  }
};

// A run whose end was not proved: the strip proofs of the localisation once more inside it, on the
// net restricted to the run (MPFI), down to strips 2^-narrow_depth of its width. The extreme point's
// system has the run's whole range of the proof's parameter in its box X, and where the fold is flat
// in the other parameter (G_ss small against G_st, G = max_u F) the points with G_s = 0 sweep a range
// of it many times the run's width: X's other range must cover that sweep for the exclusion to close,
// and Krawczyk's test needs X small against G_ss. A narrower run shrinks the sweep with it. The pieces
// (absolute, in order) when they are proved pieces of status `before`, one run of unknown ones, proved
// pieces of status `after`; else nothing (the run is left as it was).
inline std::optional<std::vector<Piece>> narrowed_run(const TriBern<I>& F, const mpq_class& lo, const mpq_class& hi,
                                                      Strip before, Strip after, const IndependentProofOptions& opt,
                                                      long& tests) {
  IndependentOptions o = opt.localise;
  o.strip_depth = opt.narrow_depth;
  o.s_depth = 0;
  // the sub-strips lie deeper than the localisation's strips: their u- and t-pieces go at least as deep as
  // those of its last strips
  o.min_limit = std::max(o.min_limit, opt.localise.strip_depth / 2 + o.extra_depth);
  o.max_tests = opt.narrow_tests;
  // the restricted net in MPFI, then each coefficient's enclosure widened outwards to doubles (the
  // localisation's arithmetic: an enclosure of the same exact sub-net, the same proofs, far cheaper)
  const TriBern<I> sub = restrict_axis(F, 1, lo, hi, opt.bits);
  TriBern<Interval> subd;
  subd.n = sub.n;
  for (const I& c : sub.c) subd.c.push_back(Enclose<Interval>::hull(lower(c), upper(c), 0));
  independent_subdivision::Projector<Interval> proj(o, subd.c[0]);
  proj.record = opt.record;
  std::vector<Piece> ps = proj.project(subd);
  tests += proj.tests;
  const mpq_class w = hi - lo;
  for (auto& p : ps) {
    p.lo = lo + w * p.lo;
    p.hi = lo + w * p.hi;
  }
  std::size_t i = 0;
  while (i < ps.size() && ps[i].status == before) ++i;
  if (i == ps.size() || ps[i].status != Strip::unknown || !ps[i].examined) return std::nullopt;
  for (std::size_t j = i + 1; j < ps.size(); ++j)
    if (ps[j].status != after) return std::nullopt;
  return ps;
}

// The end in the run [lo, hi]: proved there, or on the narrower run that narrowed_run leaves. `run` is the
// run the proof is about; `pieces` (when narrowed) the pieces that replace [lo, hi].
inline EndProof prove_end(EndProver& prover, const TriBern<I>& F, const mpq_class& lo, const mpq_class& hi,
                          Strip before, Strip after, const std::string& var, const IndependentProofOptions& opt,
                          long& tests, std::pair<mpq_class, mpq_class>& run, std::vector<Piece>& pieces) {
  run = {lo, hi};
  EndProof e = prover.prove(lo, hi, var);
  if (e.proved || opt.narrow_depth <= 0) return e;
  const auto sub = narrowed_run(F, lo, hi, before, after, opt, tests);
  if (!sub) return e;
  const auto u = std::find_if(sub->begin(), sub->end(), [](const Piece& p) { return p.status == Strip::unknown; });
  EndProof e2 = prover.prove(u->lo, u->hi, var);
  if (!e2.proved) {
    e.why += "; on the narrower run " + var + " in [" + decimal_string(u->lo, 12) + ", " + decimal_string(u->hi, 12) +
             "] (its sides proved by finer strips): " + e2.why;
    return e;
  }
  run = {u->lo, u->hi};
  pieces = *sub;
  e2.how += " (the run " + var + " in [" + decimal_string(lo, 12) + ", " + decimal_string(hi, 12) +
            "] narrowed by finer strips)";
  return e2;
}

// The recorded pieces with the run `run` replaced by its finer pieces (narrowed_run).
inline void splice_run(std::vector<Piece>& pieces, const Piece& run, const std::vector<Piece>& finer) {
  const auto at =
      std::find_if(pieces.begin(), pieces.end(), [&](const Piece& q) { return q.lo == run.lo && q.hi == run.hi; });
  if (at == pieces.end()) throw std::logic_error("independent proof: a narrowed run not among the pieces");
  pieces.insert(pieces.erase(at), finer.begin(), finer.end());
}

// Neighbouring pieces of one status as one piece (examined only if both were).
inline std::vector<Piece> merge_equal_neighbours(const std::vector<Piece>& pieces) {
  std::vector<Piece> m;
  for (const auto& p : pieces)
    if (!m.empty() && m.back().status == p.status) {
      m.back().hi = p.hi;
      m.back().examined = m.back().examined && p.examined;
    } else {
      m.push_back(p);
    }
  return m;
}

// One projection (axis 1 of F) with proved ends; `var` is "s" or "t". The
// localisation runs on FL (the same exact net enclosed in L: Interval or MpfiInterval).
template <class L>
std::vector<std::pair<Instant, Instant>> proved_projection(const TriBern<Rational>& exact, const TriBern<I>& F,
                                                           const TriBern<L>& FL, const IndependentProofOptions& opt,
                                                           const char* var, IndependentProofResult& res, long& tests,
                                                           long& boxes, long& kz) {
  using independent_subdivision::Projector;
  Projector<L> proj(opt.localise, FL.c[0]);
  proj.record = opt.record;
  std::vector<Piece> pieces = proj.project(FL);
  tests += proj.tests;
  IndependentProjectionRecord& rec = std::string(var) == "s" ? res.s_record : res.t_record;
  if (opt.record) rec.pieces = pieces;
  const std::vector<Piece> m = merge_equal_neighbours(pieces);
  Nets nets(F, opt.bits);
  EndProver prover(nets, opt, {edge_quotient(exact, 0, opt.bits), edge_quotient(exact, 1, opt.bits)});
  const std::string v = var;
  const std::string why_stop = proj.stop_reason.empty() ? "" : " (" + proj.stop_reason + ")";
  auto range = [&](const mpq_class& a, const mpq_class& b) {
    return v + " in [" + decimal_string(a, 12) + ", " + decimal_string(b, 12) + "]";
  };
  auto undecided = [&](const mpq_class& a, const mpq_class& b, const std::string& why) {
    res.answer.undecided.push_back(independent_subdivision::located((a + b) / 2, (b - a) / 2));
    res.undecided_reasons.push_back(range(a, b) + ": " + why);
  };
  // resolved pieces with the instants of their ends
  struct R {
    Strip status;
    Instant lo, hi;
  };
  std::vector<R> out;
  auto exact_instant = [](const mpq_class& x) { return bracketed_instant(x, x, x); };
  Instant pending = exact_instant(mpq_class(0));
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Piece& p = m[i];
    if (p.status != Strip::unknown) {
      const Instant hi_end = exact_instant(p.hi);
      out.push_back({p.status, pending, hi_end});
      pending = hi_end;
      continue;
    }
    const bool has_before = i > 0, has_after = i + 1 < m.size();
    const Strip before = has_before ? m[i - 1].status : Strip::out, after = has_after ? m[i + 1].status : Strip::out;
    if (!p.examined || (!has_before && !has_after)) {
      undecided(p.lo, p.hi, (p.examined ? "nothing proved" : "not examined, the run stopped") + why_stop);
      const Instant hi_end = exact_instant(p.hi);
      out.push_back({Strip::out, pending, hi_end});  // for the intervals only: the reason says it is not known
      pending = hi_end;
      continue;
    }
    if (before == after || !has_before || !has_after) {
      undecided(
          p.lo, p.hi,
          std::string(before == Strip::in
                          ? "inside the meeting set on both sides: a touching gap or none"
                          : "separate on both sides: a touch, a near miss or a meeting narrower than the strips") +
              " could not be told apart (a touch cannot be proved by enclosure)" + why_stop);
      const Instant hi_end = exact_instant(p.hi);
      if (!out.empty() && out.back().status == before)
        out.back().hi = hi_end;
      else
        out.push_back({before, pending, hi_end});
      pending = hi_end;
      continue;
    }
    std::pair<mpq_class, mpq_class> run;
    std::vector<Piece> finer;  // the run's pieces when its end was proved on a narrower run
    EndProof e = prove_end(prover, F, p.lo, p.hi, before, after, v, opt, tests, run, finer);
    Instant end;
    if (e.proved) {
      end = bracketed_instant((e.lo + e.hi) / 2, e.lo, e.hi);
      res.proofs.push_back(e.how);
      if (opt.record) {
        rec.ends.push_back(IndependentEndRecord{run.first, run.second, e.system, e.chain_lo, e.chain_hi, e.lo, e.hi});
        if (!finer.empty()) splice_run(rec.pieces, p, finer);
      }
    } else {
      undecided(p.lo, p.hi,
                "an end of the " + v + "-intervals lies here (" + v + " = " + decimal_string(p.lo, 12) + " proved " +
                    (before == Strip::in ? "in" : "out") + ", " + decimal_string(p.hi, 12) + " proved " +
                    (after == Strip::in ? "in" : "out") + ") but it is not proved to be one: " + e.why);
      end = independent_subdivision::located((p.lo + p.hi) / 2, (p.hi - p.lo) / 2);
    }
    out.back().hi = end;
    pending = end;
  }
  boxes += prover.boxes;
  kz += prover.krawczyk_tests;
  std::vector<std::pair<Instant, Instant>> iv;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i].status != Strip::in) continue;
    std::size_t j = i;
    while (j + 1 < out.size() && out[j + 1].status == Strip::in) ++j;
    iv.emplace_back(out[i].lo, out[j].hi);
    i = j;
  }
  return iv;
}

// The face u = index i of the exact net < 0 on [0, 1]^2: every control point of a sub-box < 0, by exact
// halving (along s where the face depends on s, else along t) down to 2^-12; false when not proved.
inline bool face_negative(const TriBern<Rational>& net, int i) {
  TriBern<Rational> face;
  face.n = {0, net.n[1], net.n[2]};
  for (int j = 0; j <= net.n[1]; ++j)
    for (int k = 0; k <= net.n[2]; ++k) face.c.push_back(net.at(i, j, k));
  auto constant_along = [](const TriBern<Rational>& f, int axis) {
    const std::size_t st = f.stride(axis), len = std::size_t(f.n[axis]) + 1;
    for (std::size_t b = 0; b < f.c.size(); ++b)
      if ((b / st) % len != 0 && f.c[b] != f.c[b - ((b / st) % len) * st]) return false;
    return true;
  };
  const Rational half(1, 2);
  std::vector<std::pair<TriBern<Rational>, int>> stack{{face, 0}};
  long boxes = 0;
  while (!stack.empty()) {
    auto [f, d] = std::move(stack.back());
    stack.pop_back();
    if (f.strict_sign() == -1) continue;
    if (f.strict_sign() == 1 || d >= 24 || ++boxes > 4096) return false;
    const int axis = constant_along(f, 1) ? 2 : constant_along(f, 2) ? 1 : 1 + d % 2;
    if (f.n[axis] == 0) return false;
    auto halves = f.split_half(axis, half);
    stack.emplace_back(std::move(halves.first), d + 1);
    stack.emplace_back(std::move(halves.second), d + 1);
  }
  return true;
}

}  // namespace independent_proof_detail

// The proved answer of an independent scene from F's exact net (kernel/trivariate_bernstein.hpp, T = Rational).
inline IndependentProofResult prove_independent(const TriBern<Rational>& exact,
                                                const IndependentProofOptions& opt = {}) {
  using namespace independent_proof_detail;
  const auto start = std::chrono::steady_clock::now();
  IndependentProofResult r;
  r.answer.independent = true;
  r.degree_s = exact.n[1];
  r.degree_t = exact.n[2];
  // a net that does not depend on a parameter: F = p G with p > 0 along it, G of degree 0 there
  // (independent_net_reduced; the certificate's writer refuses a net this changes)
  const TriBern<Rational> reduced = independent_net_reduced(exact);
  const TriBern<Rational>& net = reduced;
  TriBern<I> F;
  F.n = net.n;
  F.c.reserve(net.c.size());
  for (const auto& q : net.c) F.c.emplace_back(q, opt.bits);
  // F < 0 on the faces u = 0 and u = 1: exact signs of the faces' nets, subdivided exactly where the hull
  // of the whole face does not show it (a turning body: det A(s) < 0 with Bernstein coefficients of both signs)
  if (!face_negative(net, 0) || !face_negative(net, net.n[0]))
    throw std::invalid_argument(
        "independent motions: F(0, s, t) = det A(s) or F(1, s, t) = det B(t) is not proved < 0 on [0, 1]^2 (a "
        "degenerate "
        "motion matrix?): the proof of the interval ends needs it");
  long tests = 0, boxes = 0, kz = 0;
  // the localisation's work bound in coefficient operations: a box test costs about the net's size
  IndependentProofOptions o2 = opt;
  o2.localise.max_tests =
      std::max(20000L, std::min(opt.localise.max_tests, long(opt.localise_work / double(net.c.size()))));
  const IndependentProofOptions& opt_run = o2;
  if (opt.localise_in_mpfi) {
    r.answer.s_intervals = proved_projection(net, F, F, opt_run, "s", r, tests, boxes, kz);
    r.answer.t_intervals =
        proved_projection(net.swap_st(), F.swap_st(), F.swap_st(), opt_run, "t", r, tests, boxes, kz);
  } else {
    TriBern<Interval> FL;
    FL.n = net.n;
    for (const auto& q : net.c) FL.c.push_back(scalar_traits<Interval>::from_rational(q));
    r.answer.s_intervals = proved_projection(net, F, FL, opt_run, "s", r, tests, boxes, kz);
    r.answer.t_intervals =
        proved_projection(net.swap_st(), F.swap_st(), FL.swap_st(), opt_run, "t", r, tests, boxes, kz);
  }
  r.answer.collides = !r.answer.s_intervals.empty() || !r.answer.t_intervals.empty();
  if (r.answer.s_intervals.empty() != r.answer.t_intervals.empty()) {
    r.undecided_reasons.push_back(
        "one projection found a meeting and the other none (a meeting set thinner than the strips)");
    r.answer.undecided.push_back(Instant{"0", std::nullopt, std::nullopt, 0.0});
  }
  r.undecided_reasons = independent_subdivision::one_per_cause(r.undecided_reasons);
  r.counters = {
      {"box_tests", tests}, {"exclusion_boxes", boxes}, {"krawczyk_tests", kz}, {"proved_ends", long(r.proofs.size())}};
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace eccd
