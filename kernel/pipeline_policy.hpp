#pragma once
// PipelinePolicy: what an arithmetic supplies to the projection pipelines
// (CD-DISC in 2D, kernel/cd_disc.hpp; the projection CCD in 3D,
// kernel/ccd_projection.hpp), as a C++20 concept.
//
// Statement. The pipelines are written once (docs/architecture.md, "Only the
// places that differ"); a policy P for the scalar
// type T supplies those places:
//   P::Rep                        how a projection polynomial is held (Poly<Rational> exact, Bern<T> rounded or
//   interval) P::Root                       a root of one in [0, 1] (a bracket, an approximation) build(g, formula)
//   formula(G) for G = {g_0..g_N}, f's coefficients, applied in the ring of the
//                                 policy's basis (kernel/basis_build.hpp); 2D formulas of (g3, g2, g1, g0)
//                                 go through build_cubic
//   identically_zero(q)           q ≡ 0 (interval policies may throw when they cannot tell)
//   roots(q, first_only)          q's roots in [0, 1], sorted; first_only: the leftmost is enough
//   sign_at(q, root)              q's sign at a root (exact: proved; rounded: at the approximation; may be uncertain)
//   sign_at_value(q, t)           q's sign at an instant t of type T
//   multiplicity(root)            as a root of q (floating: 1 simple, 2 a cluster)
//   sample_between(l, r)          an instant strictly between two roots (nullptr: 0 on the left, 1 on the right)
//   instant(root), instant_at(t)  the Answer's instants (kernel/answer.hpp)
//   value(root)                   a T at or near the root (contact points, display)
//   at_zero(root), at_one(root)   the root is t = 0 / t = 1
// The concept checks the signatures (the archetype formula returns G[0]); what
// the functions mean is the prose above and the policies' headers.
//
// Optional hooks (namespace policy_hooks): a policy that has them uses them,
// the others get the neutral default. Rounded policies have them (termination, honesty):
//   normalise_g(g) -> bool        scale g_0..g_N by one power of two (exact in binary; false if not finite)
//   trouble                       a std::string member: "" or why nothing can be decided (a non-finite value);
//                                 the pipeline then answers undecided on [0, 1] with it
//   notes                         a std::vector<std::string> member: why parts were left undecided
//   Root::unresolved              a bool member: the root's place is unknown (work bound, deadline)
// The certified policy has one more (local decisions, certified/ladder.hpp):
//   settle_status(t, s) -> Status the static test's status s at the instant t, uncertain in the policy's
//                                 arithmetic, decided another way (exactly at a rational t), or s
// Requirements on T: scalar_traits<T>.
#include "kernel/answer.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/polynomial.hpp"
#include "number/scalar_traits.hpp"

#include <concepts>
#include <string>
#include <vector>

namespace eccd {

namespace policy_detail {
// The archetype of a build formula: any ring formula of G = {g_0..g_N}.
struct FirstOf {
  template <class G>
  auto operator()(const G& g) const {
    return g[0];
  }
};
}  // namespace policy_detail

template <class P, class T>
concept PipelinePolicy = requires(const P& pol, const std::vector<Poly<T>>& g, const typename P::Rep& q,
                                  const typename P::Root& r, const typename P::Root* rp, const T& t, bool first_only) {
  { pol.build(g, policy_detail::FirstOf{}) } -> std::same_as<typename P::Rep>;
  { q.degree() } -> std::convertible_to<int>;
  { pol.identically_zero(q) } -> std::convertible_to<bool>;
  { pol.roots(q, first_only) } -> std::same_as<std::vector<typename P::Root>>;
  { pol.sign_at(q, r) } -> std::same_as<Sign>;
  { pol.sign_at_value(q, t) } -> std::same_as<Sign>;
  { pol.multiplicity(r) } -> std::convertible_to<int>;
  { pol.sample_between(rp, rp) } -> std::convertible_to<T>;
  { pol.instant(r) } -> std::same_as<Instant>;
  { pol.instant_at(t) } -> std::same_as<Instant>;
  { pol.value(r) } -> std::convertible_to<T>;
  { pol.at_zero(r) } -> std::convertible_to<bool>;
  { pol.at_one(r) } -> std::convertible_to<bool>;
};

// The optional hooks, each as a concept, and their neutral defaults.
template <class P, class G>
concept NormalisesG = requires(const P& pol, G& g) {
  { pol.normalise_g(g) } -> std::convertible_to<bool>;
};
template <class P>
concept ReportsTrouble = requires(const P& pol) {
  { pol.trouble } -> std::convertible_to<std::string>;
};
template <class P>
concept KeepsNotes = requires(const P& pol) {
  { pol.notes } -> std::convertible_to<std::vector<std::string>>;
};
template <class P, class T>
concept SettlesStatus = requires(const P& pol, const T& t, Status s) {
  { pol.settle_status(t, s) } -> std::same_as<Status>;
};
template <class R>
concept MayBeUnresolved = requires(const R& r) {
  { r.unresolved } -> std::convertible_to<bool>;
};

namespace policy_hooks {
template <class Policy, class G>
void normalise_g(const Policy& pol, G& g) {
  if constexpr (NormalisesG<Policy, G>) pol.normalise_g(g);
}
template <class Policy>
std::string trouble(const Policy& pol) {
  if constexpr (ReportsTrouble<Policy>)
    return pol.trouble;
  else
    return {};
}
template <class Policy>
std::vector<std::string> notes(const Policy& pol) {
  if constexpr (KeepsNotes<Policy>)
    return pol.notes;
  else
    return {};
}
template <class Policy, class T>
Status settle_status(const Policy& pol, const T& t, Status s) {
  if constexpr (SettlesStatus<Policy, T>)
    return s == Status::uncertain ? pol.settle_status(t, s) : s;
  else
    return s;
}
template <class Root>
bool unresolved(const Root& r) {
  if constexpr (MayBeUnresolved<Root>)
    return r.unresolved;
  else
    return false;
}
}  // namespace policy_hooks

}  // namespace eccd
