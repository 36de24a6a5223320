#pragma once
// The floating CD-DISC pipelines (double and MPFR): the policy that
// kernel/cd_disc.hpp needs in rounded arithmetic.
//
// Statement. 003 section VI-C: Δ(t) built in one of three bases (power,
// bernstein, scaled_bernstein: kernel/basis_build.hpp), then its roots in
// [0, 1] found by Bernstein subdivision (floating/bernstein_roots.hpp).
// Signs at a root are the signs of the computed values at the root's
// approximation: nothing here is certified.
// Scaling and termination: g_0..g_N are scaled by a power of two
// so that the largest coefficient has exponent 0 (number/pow2_scaling.hpp;
// exact, changes no root and no sign; Δ, P, D and the subresultant
// coefficients built from them then stay in range: products of a few values
// below 1 with binomial weights). A non-finite value sets `trouble` (the
// pipeline then answers undecided on [0, 1] with it). Root isolation has a
// work bound and asks the deadline (floating/bernstein_roots.hpp); a root
// cluster it could not resolve has uncertain signs, so its instant is
// undecided, and the reason is kept in `notes`.
// Requirements on T: scalar_traits<T> with is_exact == false.
#include "floating/bernstein_roots.hpp"
#include "kernel/bernstein_horner.hpp"
#include "number/pow2_scaling.hpp"
#include "kernel/answer.hpp"
#include "kernel/basis_build.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/pipeline_policy.hpp"
#include "kernel/scaled_bernstein.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <string>

namespace eccd {

template <class T>
struct FloatingPolicy {
  using Rep = Bern<T>;
  using Root = FloatRoot<T>;
  Basis basis = Basis::bernstein;
  int bits = 53;
  T like;
  // Δ in the Hessian form (kernel/cd_disc.hpp, discriminant_of), in every face: with a running
  // error bound too (fewer and shorter products for the guard, and its values are then
  // bit for bit the as-published ones, so where the guard decides it gives the published answer).
  static constexpr bool delta_from_hessian = true;
  long max_pieces = 20000;                 // root isolation work bound (per polynomial)
  mutable std::string trouble;             // "" or why nothing can be decided (a non-finite value)
  mutable std::vector<std::string> notes;  // why parts were left undecided (work bound, deadline)
  // g_0..g_N in Bernstein form, converted once for the builds of one run (kernel/basis_build.hpp); unused
  // for scalar types compared by value (MPFR).
  mutable std::conditional_t<std::is_trivially_copyable_v<T>, BernsteinOfG<T>, std::monostate> g_bern;

  FloatingPolicy(Basis b, int precision_bits, const T& like_value) : basis(b), bits(precision_bits), like(like_value) {}

  // formula(G) with G = {g_0, ..., g_N} in the ring of the basis; the result in Bernstein form
  // (kernel/basis_build.hpp). Not rescaled: g is (normalise_g), so Δ and the
  // others stay in range, and the harness measures these coefficients against
  // exact ones unscaled.
  template <class F>
  Bern<T> build(const std::vector<Poly<T>>& g, F formula) const {
    Bern<T> out;
    if constexpr (std::is_trivially_copyable_v<T>) {  // Δ, P and D share g's conversion
      if (basis != Basis::power)
        out = build_from_bernstein(basis, g_bern.of(g, T(T(0) * like)), formula);
      else
        out = build_in_basis(basis, g, formula, T(T(0) * like));
    } else {
      out = build_in_basis(basis, g, formula, T(T(0) * like));
    }
    if (!all_finite(out.b) && trouble.empty())
      trouble = "overflow: a non-finite coefficient in a polynomial built from f (Δ, P, D or a subresultant)";
    return out;
  }
  // Scales g_0..g_N by one power of two (the caller's first step); false if not finite.
  bool normalise_g(std::vector<Poly<T>>& g) const {
    bool ok = normalise_pow2<T>([&](auto f) {
      for (auto& gi : g)
        for (auto& x : gi.c) f(x);
    });
    if (!ok && trouble.empty()) trouble = "overflow: a non-finite coefficient of f (g_k)";
    return ok;
  }
  bool identically_zero(const Bern<T>& q) const {
    for (const auto& x : q.b)
      if (!is_zero(x)) return false;
    return true;
  }
  std::vector<Root> roots(const Bern<T>& q, bool first_only) const {
    BernsteinRootOptions<T> o;
    o.precision_bits = bits;
    o.first_only = first_only;
    // Work bound: about 1e8 coefficient operations in double, 2e6 in MPFR (each de Casteljau split is O(n^2)).
    const double ops = (std::is_same_v<T, double> || std::is_same_v<T, Bounded<double>>) ? 1e8 : 2e6;
    const double n1 = double(q.b.size());
    o.max_pieces = std::clamp(long(ops / (n1 * n1)), 64L, max_pieces);
    auto r = bernstein_roots(q, o);
    if (!o.stopped.empty()) notes.push_back(o.stopped);
    return r;
  }
  // With a running error bound (number/running_error.hpp) a cluster is a
  // place where Δ's sign is unknown: there may be a double root (a touch),
  // two close roots or none, so nothing is claimed there.
  // The value at the root in O(n) (kernel/bernstein_horner.hpp: the same order of
  // error as de Casteljau's). With a running error bound that value's bound decides where it
  // can (the as-published value, bit for bit), and only where it cannot, de Casteljau's
  // triangle, whose bound is smaller, is asked (O(n^2)): both bound the exact value at the
  // same point, so either decision is that value's sign.
  Sign sign_at(const Bern<T>& q, const Root& r) const {
    if (unknown_inside(r)) return Sign::uncertain;
    const BernsteinHorner<T> horner{std::span<const T>(q.b)};
    const Sign s = eccd::sign(horner(r.value));
    if constexpr (has_error_bound_v<T>)
      if (s == Sign::uncertain && horner.linear()) return eccd::sign(q(r.value));
    return s;
  }
  Sign sign_at_value(const Bern<T>& q, const T& t) const { return eccd::sign(q(t)); }
  T sample_between(const Root* l, const Root* r) const {
    T a = l ? l->hi : scalar_traits<T>::from_rational(mpq_class(0), like);
    T b = r ? r->lo : scalar_traits<T>::from_rational(mpq_class(1), like);
    T s = a + b;
    return point_of(T(scalar_traits<T>::from_rational(mpq_class(1, 2), like) * s));
  }
  Instant instant_at(const T& t) const { return rounded_instant(t); }
  Instant instant(const Root& r) const { return instant_at(r.value); }
  T value(const Root& r) const { return r.value; }
  int multiplicity(const Root& r) const { return r.cluster ? 2 : 1; }
  // An unresolved stretch is at an end only if it is all there (else it is interior, with uncertain status).
  // With a running error bound so is a cluster (nothing is known inside it).
  bool unknown_inside(const Root& r) const { return r.unresolved || (has_error_bound_v<T> && r.cluster); }
  bool at_zero(const Root& r) const {
    return !((unknown_inside(r) ? r.hi : r.lo) > scalar_traits<T>::from_rational(mpq_class(0), like));
  }
  bool at_one(const Root& r) const {
    return !((unknown_inside(r) ? r.lo : r.hi) < scalar_traits<T>::from_rational(mpq_class(1), like));
  }
};

static_assert(PipelinePolicy<FloatingPolicy<double>, double>);
static_assert(PipelinePolicy<FloatingPolicy<Mpfr>, Mpfr>);
static_assert(PipelinePolicy<FloatingPolicy<Bounded<double>>, Bounded<double>>);

}  // namespace eccd
