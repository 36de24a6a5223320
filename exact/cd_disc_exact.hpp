#pragma once
// The exact CD-DISC pipeline: the policy that kernel/cd_disc.hpp needs in
// exact rational arithmetic, producing certified answers.
//
// Statement. Δ(t), P(t), D(t) are exact rational polynomials (power form:
// the basis does not matter when nothing is rounded). Its real roots in
// [0, 1] are isolated with rational brackets that provably hold one root each
// (exact/algebraic_roots.hpp); the status at a root t0 is decided from the
// exact signs of P and D at the algebraic number t0; each cell is decided at
// a short dyadic rational strictly between two brackets. No double is used on
// the way to any decision; decimal strings are for display.
// Guarantee: every instant of the answer carries a bracket [lo, hi] that
// contains it and no other root of Δ (0 and 1 and rational roots are exact).
#include "exact/algebraic_roots.hpp"
#include "exact/flint_poly.hpp"
#include "kernel/answer.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/pipeline_policy.hpp"
#include "number/simplest_rational.hpp"

namespace eccd {

// One root isolation the pipeline did: the polynomial and its roots in [0, 1].
struct Isolation {
  Poly<Rational> poly;
  std::vector<AlgebraicRoot> roots;
};

struct ExactPolicy {
  using Rep = Poly<Rational>;
  using Root = AlgebraicRoot;
  int bits = 64;  // brackets are refined to width <= 2^-bits
  // If set, every isolation is kept here, in order (certificate/write/exact_certificate.hpp
  // builds the certificate from the very roots the answer was decided on).
  std::vector<Isolation>* record = nullptr;

  // The formula in the power basis, kept in power form: nothing is rounded, so the basis does not matter
  // (kernel/basis_build.hpp). Computed in FLINT's rational polynomials (exact/flint_poly.hpp):
  // the very polynomial the formula gives in Poly<Rational>, faster.
  template <class F>
  Poly<Rational> build(const std::vector<Poly<Rational>>& g, F formula) const {
    std::vector<FlintQPoly> G;
    G.reserve(g.size());
    for (const auto& p : g) G.emplace_back(p);
    return Poly<Rational>(formula(G).to_poly());
  }
  bool identically_zero(const Poly<Rational>& q) const { return q.is_zero(); }

  std::vector<Root> roots(const Poly<Rational>& q, bool /*first_only: all roots are isolated anyway*/) const {
    std::vector<Root> rs = real_roots(q, Rational(0), Rational(1), bits);
    const Poly<Rational> t({Rational(0), Rational(1)}), t1({Rational(-1), Rational(1)});
    for (auto& r : rs) {
      if (eccd::sign_at(t, r) == Sign::zero) {
        r.lo = r.hi = 0;
        continue;
      }
      if (eccd::sign_at(t1, r) == Sign::zero) {
        r.lo = r.hi = 1;
        continue;
      }
      for (int b = 2 * bits; r.lo <= 0 || r.hi >= 1; b *= 2) refine(r, b);  // strictly inside (0, 1)
    }
    if (record) record->push_back({q, rs});
    return rs;
  }
  Sign sign_at(const Poly<Rational>& q, const Root& r) const { return eccd::sign_at(q, r); }
  Sign sign_at_value(const Poly<Rational>& q, const Rational& t) const { return eccd::sign(q(t)); }
  Rational sample_between(const Root* l, const Root* r) const {
    return simplest_dyadic_between(l ? l->hi : Rational(0), r ? r->lo : Rational(1));
  }
  Instant instant_at(const Rational& t) const { return bracketed_instant(t, t, t); }
  Instant instant(const Root& r) const {
    Rational mid = (r.lo + r.hi) / 2;
    return bracketed_instant(mid, r.lo, r.hi);
  }
  Rational value(const Root& r) const {
    Rational mid = (r.lo + r.hi) / 2;
    return mid;
  }
  int multiplicity(const Root& r) const { return r.multiplicity; }
  bool at_zero(const Root& r) const { return r.hi == 0; }
  bool at_one(const Root& r) const { return r.lo == 1; }
};

static_assert(PipelinePolicy<ExactPolicy, Rational>);

}  // namespace eccd
