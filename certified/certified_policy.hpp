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

#include <cstring>
#include <optional>
#include <span>
#include <type_traits>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

// Why a rung gave up: `precision` (an interval too wide: more bits may
// decide it) or `multiple_root` (a piece with two or more sign changes left at
// 2^-max_depth: almost always a true multiple root, which no precision
// separates — every touch scene — so the ladder goes straight to exact).
struct Escalate : std::runtime_error {
  enum Kind { precision, multiple_root } kind;
  explicit Escalate(const std::string& what, Kind k = precision) : std::runtime_error(what), kind(k) {}
};

struct CertifiedRoot {
  Rational lo, hi;  // dyadic bracket holding exactly one root
};

template <class T>
struct CertifiedPolicy {
  using Rep = Bern<T>;
  using Root = CertifiedRoot;
  int max_depth = 48;    // isolation gives up (escalates) below pieces of width 2^-max_depth
  int refine_bits = 30;  // brackets are refined to width <= 2^-refine_bits while signs are certain
  T like;
  mutable long pieces = 0;  // Bernstein pieces examined (work counter)

  explicit CertifiedPolicy(const T& like_value = T(0)) : like(like_value) {}

  T of(const Rational& q) const { return scalar_traits<T>::from_rational(q, like); }

  // In the Bernstein basis (kernel/basis_build.hpp): its coefficients enclose the range, which sign_at uses.
  template <class F>
  Bern<T> build(const std::vector<Poly<T>>& g, F formula) const {
    if constexpr (std::is_same_v<T, Interval>) return formula(bernstein_g(g));  // Δ, P, D share g's conversion
    else return build_in_basis(Basis::bernstein, g, formula, T(0));
  }
  bool identically_zero(const Bern<T>& q) const {
    bool all_zero = true;
    for (const auto& x : q.b) {
      Sign s = eccd::sign(x);
      if (s == Sign::positive || s == Sign::negative) return false;
      if (s == Sign::uncertain) all_zero = false;
    }
    if (all_zero) return true;
    throw Escalate("cannot tell in interval arithmetic whether the projection vanishes identically");
  }

  std::vector<Root> roots(const Bern<T>& q, bool /*first_only*/) const {
    std::vector<Root> out;
    if (is_certain_nonzero(q.b.front()) == false || is_certain_nonzero(q.b.back()) == false)
      throw Escalate("the projection may vanish at t = 0 or t = 1");
    whole = &q;
    isolate(q, Rational(0), Rational(1), 0, out);
    whole = nullptr;
    return out;
  }
  // The certain sign of q over the whole bracket, or uncertain: the sign
  // shared by all Bernstein coefficients of q restricted to [lo, hi] (they
  // enclose its range there; two de Casteljau splits). Evaluating q at the
  // interval [lo, hi] instead would suffer the dependency problem: for
  // degree 100+ its width is many times q's true range.
  Sign sign_at(const Bern<T>& q, const Root& r) const {
    if (q.degree() <= 0) return eccd::sign(q.b.empty() ? T(0) : q.b[0]);
    std::vector<T> piece = q.b;
    if (r.lo > 0) keep_right(std::span<T>(piece), of(r.lo));
    if (r.hi < 1) keep_left(std::span<T>(piece), of((r.hi - r.lo) / (1 - r.lo)));
    Sign s = eccd::sign(piece.front());
    for (const auto& x : piece)
      if (eccd::sign(x) != s) return Sign::uncertain;
    return s;
  }
  Sign sign_at_value(const Bern<T>& q, const T& t) const { return eccd::sign(q(t)); }
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
  static bool is_certain_nonzero(const T& x) {
    Sign s = eccd::sign(x);
    return s == Sign::positive || s == Sign::negative;
  }
  // q is the restriction to [a, b] (reparameterised to [0, 1]); its end
  // coefficients (the values at a and b) have certain non-zero signs.
  void isolate(const Bern<T>& q, const Rational& a, const Rational& b, int depth, std::vector<Root>& out) const {
    ++pieces;
    check_deadline("certified root isolation");  // the rung's budget (certified/ladder.hpp)
    // An uncertain count (a coefficient whose interval holds 0) proves nothing: split.
    const SignVariations v = sign_variations(q.b);
    if (v.is(0)) return;
    if (v.is(1)) {
      refine(q, a, b, out);
      return;
    }
    if (depth >= max_depth)
      throw Escalate("interval root isolation cannot separate roots near t = " + decimal_string(a, 12) +
                     " (a multiple root, or roots closer than 2^-" + std::to_string(max_depth) + ")",
                     Escalate::multiple_root);
    // Split at the middle, or near it if the value there is not certainly non-zero.
    for (const char* frac : {"1/2", "7/16", "9/16", "3/8", "5/8"}) {
      Rational f(frac);
      auto [left, right] = split(q, of(f));
      if (!is_certain_nonzero(left.b.back())) continue;
      Rational m = a + f * (b - a);
      isolate(left, a, m, depth + 1, out);
      isolate(right, m, b, depth + 1, out);
      return;
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
  void refine(const Bern<T>& q, Rational a, Rational b, std::vector<Root>& out) const {
    const Sign sa = eccd::sign(q.b.front());
    Rational limit(mpz_class(1), mpz_class(1) << refine_bits);
    while (b - a > limit) {
      check_deadline("certified root refinement");
      Rational m = (a + b) / 2;
      Sign sm = eccd::sign(bernstein_at(*whole, m));
      if (sm != Sign::positive && sm != Sign::negative) break;  // keep the bracket we have
      if (sm == sa) a = m;
      else b = m;
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
  mutable const Bern<T>* whole = nullptr;  // the polynomial being isolated (for refine)
  // g_0..g_N in Bernstein form, as build_in_basis(bernstein) converts them,
  // kept for the next build with the same g: the same end points bit for bit
  // (compared, not assumed), hence the same conversion (issue 18: the three
  // builds of Δ, P and D converted g three times).
  mutable std::vector<Poly<T>> g_seen;
  mutable std::vector<Bern<T>> g_bern;
  const std::vector<Bern<T>>& bernstein_g(const std::vector<Poly<T>>& g) const {
    auto same = [](const Poly<T>& x, const Poly<T>& y) {
      return x.c.size() == y.c.size() && (x.c.empty() || std::memcmp(x.c.data(), y.c.data(), x.c.size() * sizeof(T)) == 0);
    };
    bool hit = g.size() == g_seen.size();
    for (std::size_t i = 0; hit && i < g.size(); ++i) hit = same(g[i], g_seen[i]);
    if (!hit) {
      g_seen = g;
      g_bern.assign(g.size(), Bern<T>());
      for (std::size_t i = 0; i < g.size(); ++i) g_bern[i] = bernstein_or_zero(g[i], T(0));
    }
    return g_bern;
  }
};

static_assert(PipelinePolicy<CertifiedPolicy<Interval>, Interval>);
static_assert(PipelinePolicy<CertifiedPolicy<MpfiInterval>, MpfiInterval>);

}  // namespace eccd
