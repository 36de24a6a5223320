#pragma once
// The certified policy: kernel/cd_disc.hpp (2D) and kernel/ccd_projection.hpp
// (3D) in interval arithmetic (number/interval.hpp), where every decision is
// proved or the scene escalates (`--arith certified`, certified/ladder.hpp).
//
// Statement. The projection polynomial (Δ in 2D, the discriminant or psc_k in
// 3D) is built in Bernstein form over intervals that enclose the exact
// coefficients. Its roots in [0, 1] are isolated by Bernstein subdivision with
// Descartes' rule for the Bernstein basis (the number V of sign changes of the
// coefficients bounds the roots in the open interval, with the same parity):
// a piece where every coefficient has a certain sign and V = 0 holds no root;
// V = 1 with certain non-zero end values holds exactly one root, and the piece
// is its bracket, refined by bisection while the midpoint's sign is certain.
// Every sign at a root is the certain sign of the polynomial's range over the
// whole bracket (interval evaluation); every cell is decided at a dyadic
// sample whose static test signs are all certain. Anything uncertain — a
// coefficient or value whose interval contains 0, a piece that stays
// undecided down to 2^-max_depth (a multiple root: every touch-and-separate
// scene), a possible root at a split point, a projection that may vanish
// identically — throws Escalate, and the caller re-solves the scene in a
// stronger arithmetic: the same policy over MPFI intervals of higher
// precision, then exact rationals (the ladder is certified/ladder.hpp's
// run_certified). With no Escalate, the answer is certified: brackets are
// dyadic rationals that provably hold one root each. Isolation and refinement
// ask the running thread's deadline at every piece and every bisection step
// (check_deadline, kernel/budget.hpp): the ladder gives each rung a budget.
//
// Local decisions (certified/ladder.hpp). With an exact oracle at rational
// instants (certified/point_oracle.hpp, `oracle`; the ladder sets it), one
// uncertain sign at one rational point is decided there exactly instead of
// escalating the scene: every polynomial built carries its formula, and its
// exact value at a rational t is formula(g(t)) (the formula commutes with
// evaluation). Decided locally, each counted by kind in `local`:
//   - "end_sign": the projection's sign at t = 0 or t = 1 (a zero there is a
//     root at the end, which this policy does not take: Escalate rational_root);
//   - "split_sign": at a split point of the isolation where the interval value
//     is uncertain at all five candidate dyadics, the exact sign at the first
//     candidate where it is non-zero (only at depth < 12: deeper, the piece is
//     next to a multiple root or a cluster, and the scene escalates to the next rung,
//     so touches cost what they cost without the oracle); the sign of a piece's
//     end value is then the exact one, not the interval's. At most
//     max_local_splits (4) exact evaluations per run go to this: a polynomial whose interval
//     coefficients are uncertain on every piece would otherwise make one at
//     each of up to 2^12 pieces;
//   - "identically_zero": whether a polynomial of degree d whose interval
//     coefficients all hold 0 vanishes identically: exactly, from its values
//     at t = 0, 1, ..., d (zero at all of them: zero; else not);
//   - "cell_status": the static test at a dyadic sample (a cell, t = 0, t = 1)
//     whose interval signs are uncertain (settle_status, the optional hook of
//     kernel/pipeline_policy.hpp).
// Every exact evaluation is between two looks at the deadline, so the rung's
// budget still bounds its time (certified/ladder.hpp: δ includes one exact
// evaluation at a point). Without an oracle every uncertain sign escalates.
// Requirements on T: Interval or MpfiInterval — scalar_traits<T> whose sign()
// is certain-or-uncertain and whose operations enclose exact results, plus
// interval_hull(lo, hi, like) and exact_point(x) (number/interval.hpp,
// number/mpfi_interval.hpp).
#include "number/simplest_rational.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"
#include "kernel/answer.hpp"
#include "kernel/basis_build.hpp"
#include "kernel/bernstein.hpp"
#include "kernel/budget.hpp"
#include "kernel/pipeline_policy.hpp"
#include "kernel/polynomial.hpp"
#include "certified/point_oracle.hpp"

#include <chrono>
#include <functional>
#include <map>

#include <optional>
#include <span>
#include <type_traits>
#include <variant>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

// Why a rung gave up: `precision` (an interval too wide: more bits may
// decide it) or `multiple_root` (a piece with two or more sign changes left at
// 2^-max_depth: almost always a true multiple root, which no precision
// separates — every touch scene — so the ladder goes straight to exact).
struct Escalate : std::runtime_error {
  // rational_root: the projection vanishes exactly at a rational point this
  // policy cannot place a root at (t = 0, t = 1, a split point): no precision
  // helps either, so the ladder treats it like multiple_root.
  enum Kind { precision, multiple_root, rational_root } kind;
  explicit Escalate(const std::string& what, Kind k = precision) : std::runtime_error(what), kind(k) {}
};

struct CertifiedRoot {
  Rational lo, hi;  // dyadic bracket holding exactly one root
};

// A polynomial of the certified policy: its Bernstein coefficients over
// intervals and, when the policy has an oracle, its formula in g_0..g_H, to
// be evaluated exactly at a rational instant.
template <class T>
struct CertifiedRep : Bern<T> {
  using Exact = std::function<Poly<Rational>(const std::vector<Poly<Rational>>&)>;
  Exact exact;  // empty: no exact value available
  CertifiedRep() = default;
  CertifiedRep(Bern<T> net) : Bern<T>(std::move(net)) {}  // NOLINT: a plain Bernstein polynomial, no formula
  CertifiedRep(Bern<T> net, Exact e) : Bern<T>(std::move(net)), exact(std::move(e)) {}
};

template <class T>
struct CertifiedPolicy {
  using Rep = CertifiedRep<T>;
  using Root = CertifiedRoot;
  int max_depth = 48;    // isolation gives up (escalates) below pieces of width 2^-max_depth
  int refine_bits = 30;  // brackets are refined to width <= 2^-refine_bits while signs are certain
  T like;
  mutable long pieces = 0;                   // Bernstein pieces examined (work counter)
  const ExactPointOracle* oracle = nullptr;  // exact values at rational instants (local decisions); may be null
  long max_local_splits = 4;  // exact split-point evaluations allowed per run (beyond: escalate as without the oracle)
  mutable long local_split_evaluations = 0;
  mutable std::map<std::string, long> local;  // decisions made locally with the oracle, by kind (see above)
  // Seconds spent in the oracle's exact evaluations (the ladder's MPFI budget leaves them out).
  mutable double local_seconds = 0;
  struct LocalClock {  // adds its lifetime to a counter
    double& total;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    explicit LocalClock(double& t) : total(t) {}
    ~LocalClock() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  };

  explicit CertifiedPolicy(const T& like_value = T(0)) : like(like_value) {}

  T of(const Rational& q) const { return scalar_traits<T>::from_rational(q, like); }

  // In the Bernstein basis (kernel/basis_build.hpp): its coefficients enclose the range, which sign_at uses.
  template <class F>
  Rep build(const std::vector<Poly<T>>& g, F formula) const {
    Rep r;
    if constexpr (std::is_same_v<T, Interval>)
      r = Rep(formula(bernstein_g(g)));  // Δ, P, D share g's conversion
    else
      r = Rep(build_in_basis(Basis::bernstein, g, formula, T(0)));
    if (oracle)  // the formula is a stateless ring formula (kernel/basis_build.hpp): held by value
      r.exact = [formula](const std::vector<Poly<Rational>>& G) { return Poly<Rational>(formula(G)); };
    return r;
  }
  // q's exact sign at the rational t, or uncertain when there is no oracle or formula.
  Sign exact_sign(const Rep& q, const Rational& t) const {
    if (!oracle || !q.exact) return Sign::uncertain;
    const LocalClock clock(local_seconds);
    std::vector<Poly<Rational>> G;
    for (const Rational& c : oracle->g_at(t)) G.push_back(Poly<Rational>(std::vector<Rational>{c}));
    const Poly<Rational> v = q.exact(G);
    return v.is_zero() ? Sign::zero : (sgn(v.c[0]) > 0 ? Sign::positive : Sign::negative);
  }
  bool identically_zero(const Rep& q) const {
    bool all_zero = true;
    for (const auto& x : q.b) {
      Sign s = eccd::sign(x);
      if (s == Sign::positive || s == Sign::negative) return false;
      if (s == Sign::uncertain) all_zero = false;
    }
    if (all_zero) return true;
    if (oracle && q.exact) {
      // Local: a polynomial of degree <= d that vanishes at d + 1 points is
      // zero. The points need not lie in [0, 1]: the integers 0..d keep the
      // numbers small.
      const int d = q.degree();
      for (int i = 0; i <= d; ++i) {
        check_deadline("certified: exact identically-zero test");
        if (exact_sign(q, Rational(i)) != Sign::zero) {
          ++local["identically_zero"];
          return false;
        }
      }
      ++local["identically_zero"];
      return true;
    }
    throw Escalate("cannot tell in interval arithmetic whether the projection vanishes identically");
  }
  // The hook of kernel/pipeline_policy.hpp: a static test whose interval signs
  // are uncertain at a point instant, decided there exactly.
  Status settle_status(const T& t, Status s) const {
    if (s != Status::uncertain || !oracle) return s;
    std::optional<Rational> q = exact_point(t);
    if (!q) return s;
    check_deadline("certified: exact static test at a sample");
    ++local["cell_status"];
    const LocalClock clock(local_seconds);
    return oracle->status_at(*q);
  }

  std::vector<Root> roots(const Rep& q, bool /*first_only*/) const {
    std::vector<Root> out;
    local_in_isolation = false;
    const Sign s0 = end_sign(q, 0), s1 = end_sign(q, 1);
    whole = &q;
    try {
      isolate(q, Rational(0), Rational(1), 0, out, s0, s1);
    } catch (const Escalate& e) {
      whole = nullptr;
      // Without the local decisions this isolation would have given up
      // earlier, on precision (an MPFI rung may decide it): a later failure
      // that looks like a multiple root is not taken for one.
      if (local_in_isolation && e.kind == Escalate::multiple_root)
        throw Escalate(std::string(e.what()) + " (after local decisions; without them: precision)",
                       Escalate::precision);
      throw;
    }
    whole = nullptr;
    return out;
  }
  // The certain sign of q over the whole bracket, or uncertain: the sign
  // shared by all Bernstein coefficients of q restricted to [lo, hi] (they
  // enclose its range there; two de Casteljau splits). Evaluating q at the
  // interval [lo, hi] instead would suffer the dependency problem: for
  // degree 100+ its width is many times q's true range.
  Sign sign_at(const Rep& q, const Root& r) const {
    if (q.degree() <= 0) return eccd::sign(q.b.empty() ? T(0) : q.b[0]);
    std::vector<T> piece = q.b;
    if (r.lo > 0) keep_right(std::span<T>(piece), of(r.lo));
    if (r.hi < 1) keep_left(std::span<T>(piece), of((r.hi - r.lo) / (1 - r.lo)));
    Sign s = eccd::sign(piece.front());
    for (const auto& x : piece)
      if (eccd::sign(x) != s) return Sign::uncertain;
    return s;
  }
  Sign sign_at_value(const Rep& q, const T& t) const { return eccd::sign(q(t)); }
  // Two brackets from neighbouring pieces of the subdivision may share their
  // end point m (each root lies in the OPEN bracket, and the split point m had
  // a certain non-zero value, isolate): m itself is then strictly between the
  // two roots, and the only dyadic there (simplest_dyadic_between needs a < b).
  T sample_between(const Root* l, const Root* r) const {
    const Rational a = l ? l->hi : Rational(0), b = r ? r->lo : Rational(1);
    if (a < b) return of(simplest_dyadic_between(a, b));
    T m = of(a);
    if (!exact_point(m)) throw Escalate("a sample point between two adjacent root brackets is not representable");
    return m;
  }
  // Point intervals only (0, 1 and dyadic samples): their exact value.
  Instant instant_at(const T& t) const {
    std::optional<Rational> q = exact_point(t);
    if (!q) throw std::logic_error("internal error: a certified instant that is not a point");
    return bracketed_instant(*q, *q, *q);
  }
  Instant instant(const Root& r) const {
    Rational mid = (r.lo + r.hi) / 2;
    return bracketed_instant(mid, r.lo, r.hi);
  }
  T value(const Root& r) const { return interval_hull(r.lo, r.hi, like); }
  int multiplicity(const Root&) const { return 1; }
  bool at_zero(const Root&) const { return false; }
  bool at_one(const Root&) const { return false; }

 private:
  // q's certain non-zero sign at t = e (0 or 1): its end coefficient's, or
  // decided locally by the oracle; otherwise Escalate.
  Sign end_sign(const Rep& q, int e) const {
    const Sign s = eccd::sign(e ? q.b.back() : q.b.front());
    if (s == Sign::positive || s == Sign::negative) return s;
    check_deadline("certified: exact sign at an end");
    const Sign x = exact_sign(q, Rational(e));
    if (x == Sign::positive || x == Sign::negative) {
      ++local["end_sign"];
      local_in_isolation = true;
      return x;
    }
    if (x == Sign::zero)
      throw Escalate(std::string("the projection vanishes exactly at t = ") + (e ? "1" : "0") +
                         " (decided locally; a root at an end is left to the exact rung)",
                     Escalate::rational_root);
    throw Escalate("the projection may vanish at t = 0 or t = 1");
  }
  // q is the restriction to [a, b] (reparameterised to [0, 1]); its values at
  // a and b have the certain non-zero signs sa and sb (the end coefficients'
  // intervals may hold 0 when a sign was decided locally).
  void isolate(const Bern<T>& q, const Rational& a, const Rational& b, int depth, std::vector<Root>& out, Sign sa,
               Sign sb) const {
    ++pieces;
    check_deadline("certified root isolation");  // the rung's budget (certified/ladder.hpp)
    // An uncertain count (a coefficient whose interval holds 0) proves nothing: split.
    const std::size_t n = q.b.size();
    const SignVariations v = sign_variations_n(n, [&](std::size_t k) {
      return k == 0 ? sa : k + 1 == n ? sb : eccd::sign(q.b[k]);
    });
    if (v.is(0)) return;
    if (v.is(1)) {
      refine(a, b, sa, out);
      return;
    }
    if (depth >= max_depth)
      throw Escalate("interval root isolation cannot separate roots near t = " + decimal_string(a, 12) +
                         " (a multiple root, or roots closer than 2^-" + std::to_string(max_depth) + ")",
                     Escalate::multiple_root);
    // Split at the middle, or near it if the value there is not certainly non-zero.
    static const char* const fracs[] = {"1/2", "7/16", "9/16", "3/8", "5/8"};
    for (const char* frac : fracs) {
      Rational f(frac);
      auto [left, right] = split(q, of(f));
      const Sign sm = eccd::sign(left.b.back());
      if (sm != Sign::positive && sm != Sign::negative) continue;
      Rational m = a + f * (b - a);
      isolate(left, a, m, depth + 1, out, sa, sm);
      isolate(right, m, b, depth + 1, out, sm, sb);
      return;
    }
    // Local: the exact sign at the first candidate where it is not zero
    // (shallow pieces only, see the prose block).
    if (depth < 12 && oracle && whole && whole->exact && local_split_evaluations < max_local_splits) {
      bool vanishes = false;
      for (const char* frac : fracs) {
        check_deadline("certified: exact sign at a split point");
        Rational f(frac);
        Rational m = a + f * (b - a);
        ++local_split_evaluations;
        const Sign sm = exact_sign(*whole, m);
        if (sm == Sign::zero) vanishes = true;
        if (sm != Sign::positive && sm != Sign::negative) continue;
        ++local["split_sign"];
        local_in_isolation = true;
        auto [left, right] = split(q, of(f));
        isolate(left, a, m, depth + 1, out, sa, sm);
        isolate(right, m, b, depth + 1, out, sm, sb);
        return;
      }
      if (vanishes)
        throw Escalate("the projection vanishes exactly at a split point near t = " + decimal_string(a, 12) +
                           " (decided locally; left to the exact rung)",
                       Escalate::rational_root);
    }
    // Deep in the subdivision (pieces of width <= 2^-12) a polynomial too flat
    // to sign at five points of a piece is near a multiple root or a tight
    // cluster, like the isolation failure above: report it as such, so the
    // ladder does not spend an MPFI rung on it (measured: on every touch scene
    // of the corpus that rung failed too, at 10x the cost of exact).
    throw Escalate("the projection may vanish at a subdivision point near t = " + decimal_string(a, 12),
                   depth >= 12 ? Escalate::multiple_root : Escalate::precision);
  }
  // One root in (a, b) of the piece q: bisect while the midpoint's sign is
  // certain, evaluating the whole polynomial at the midpoint in O(n).
  void refine(Rational a, Rational b, Sign sa, std::vector<Root>& out) const {
    Rational limit(mpz_class(1), mpz_class(1) << refine_bits);
    while (b - a > limit) {
      check_deadline("certified root refinement");
      Rational m = (a + b) / 2;
      Sign sm = eccd::sign(bernstein_at(*whole, m));
      if (sm != Sign::positive && sm != Sign::negative) break;  // keep the bracket we have
      if (sm == sa)
        a = m;
      else
        b = m;
    }
    out.push_back({a, b});
  }
  // q(t) at a rational t in (0, 1) in O(n): (1-t)^n Σ b_i C(n,i) s^i with
  // s = t/(1-t) for t <= 1/2, and the mirrored form for t > 1/2.
  T bernstein_at(const Bern<T>& q, const Rational& t) const {
    const int n = q.degree();
    bool mirror = t > Rational(1, 2);
    T x = of(mirror ? Rational(1 - t) : t), y = of(mirror ? t : Rational(1 - t));
    T s = x / y, acc = T(0), pw = T(1);
    const std::vector<T>& binom = binomial_row(n, like);  // cached (kernel/binomial.hpp)
    // Horner from the top: acc = Σ_{i} b_i C(n,i) s^i.
    for (int i = n; i >= 0; --i) acc = acc * s + q.b[mirror ? n - i : i] * binom[i];
    for (int k = 0; k < n; ++k) pw = pw * y;
    return acc * pw;
  }
  mutable const Rep* whole = nullptr;       // the polynomial being isolated (for refine and the local split signs)
  mutable bool local_in_isolation = false;  // roots() used a local decision (end or split sign)
  // g_0..g_N in Bernstein form, converted once for the builds of Δ, P and D (kernel/basis_build.hpp).
  // (Interval only: MPFI values are not compared bit for bit).
  mutable std::conditional_t<std::is_same_v<T, Interval>, BernsteinOfG<T>, std::monostate> g_bern;
  const std::vector<Bern<T>>& bernstein_g(const std::vector<Poly<T>>& g) const requires std::is_same_v<T, Interval> {
    return g_bern.of(g, T(0));
  }
};

static_assert(PipelinePolicy<CertifiedPolicy<Interval>, Interval>);
static_assert(PipelinePolicy<CertifiedPolicy<MpfiInterval>, MpfiInterval>);

}  // namespace eccd
