#pragma once
// Continuous collision detection of two moving ellipsoids by projection onto
// the time axis: the exact 3D pipeline (and a floating variant of it).
//
// Statement. f(λ;t) = det(λA(t) - B(t)) = sum g_k(t) λ^k (002 section III).
// The number of distinct negative roots of f(.;t), hence the status (002
// Theorem 1, kernel/quartic_status.hpp), can only change where f(.;t) gains a
// multiple root (roots move continuously, g4 = det A(t) and g0 = det B(t) do
// not vanish). Those instants are roots of the projection polynomial
//   P(t) = Disc_λ f (t) (kernel/discriminant.hpp), or, when it vanishes
//   identically (two spheres: λ = 1 is a double root for every t), the first
//   principal subresultant coefficient psc_k(f, ∂f/∂λ) that does not
//   (kernel/subresultants.hpp).
// P's real roots in [0, 1] split [0, 1] into cells of constant status, each
// decided at one sample instant by the static test. At a root t* of P,
// gcd(f, f') has degree j = the least j > k with psc_j(t*) ≠ 0, equals
// S_j(λ; t*), and its real roots are the multiple roots of f(.;t*). The pair
// touches externally at t* iff one of them is negative:
//   j = 1: the double root -s10/s11;        j = 3: the quadruple root -s32/(3 s33);
//   j = 2: a real root of s22 λ² + s21 λ + s20 is negative (signs of the
//          coefficients and of s21² - 4 s22 s20).
// "Both neighbouring cells separate" does not mean no touch: every
// root is decided this way. A root that is not a touch takes the status of its
// cells (which then must agree). Signs at t* come from the Policy: exact signs
// at an algebraic number for the exact pipeline (exact/cd_disc_exact.hpp),
// signs of rounded values near t* for the floating ones.
// Requirements on T: those of the Policy (kernel/pipeline_policy.hpp).
#include "kernel/answer.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/collision_timeline.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/quartic_status.hpp"
#include "kernel/quartic_touch_rule.hpp"
#include "kernel/subresultants.hpp"

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace eccd {

template <class T, PipelinePolicy<T> Policy>
PipelineResult<T> ccd_projection(const MovingPair3<T>& pair, Policy& pol, bool first_contact_only = false) {
  auto start = std::chrono::steady_clock::now();
  using Rep = typename Policy::Rep;
  using Root = typename Policy::Root;
  PipelineResult<T> res;
  res.variant = first_contact_only ? Variant::first_contact : Variant::answer;
  res.g = characteristic_of(pair);
  const std::pair<T, T> ends = start_run(res, pol, pair.qa[0][0]);  // floating: g scaled by a power of two
  const T &zero = ends.first, &one = ends.second;
  const auto& g = res.g;
  auto finish = [&]() { return finish_run(res, pol, start); };
  if (undecided_on_trouble(res, pol, zero, one)) return finish();
  auto status_at = [&](const T& t) { return policy_hooks::settle_status(pol, t, quartic_status_at(g, t)); };
  res.status_at_0 = status_at(zero);

  // Subresultant coefficients s_{j,i}(t) (kernel/quartic_touch_rule.hpp), built on demand in the Policy's ring.
  std::map<std::pair<int, int>, Rep> sub;
  auto s = [&](int j, int i) -> const Rep& {
    auto key = std::make_pair(j, i);
    auto it = sub.find(key);
    if (it == sub.end())
      it = sub.emplace(key, pol.build(g, [j, i](const auto& G) { return subresultant_evidence(G, j, i); })).first;
    return it->second;
  };
  Rep proj = pol.build(g, [](const auto& G) { return quartic_discriminant(G[4], G[3], G[2], G[1], G[0]); });
  int k = 0;
  while (pol.identically_zero(proj) && k < 3) {
    ++k;
    proj = s(k, k);
  }
  if (pol.identically_zero(proj))
    throw std::logic_error("internal error: psc_3 of the characteristic quartic vanishes");
  if (undecided_on_trouble(res, pol, zero, one)) return finish();
  res.projection_index = k;
  res.projection_degree = proj.degree();
  res.projection_identically_zero = k > 0;
  auto rts = pol.roots(proj, false);

  // Is there a negative multiple root of f at the root r of the projection?
  auto touches_at = [&](const Root& r) -> Sign {  // positive = yes, zero = no, uncertain
    return negative_multiple_root(k, [&](int j, int i) { return pol.sign_at(s(j, i), r); });
  };

  std::vector<const Root*> interior;
  for (auto& r : rts)
    if (!pol.at_zero(r) && !pol.at_one(r)) interior.push_back(&r);
  std::vector<TimelineNode> seq;
  std::vector<const Root*> node_root;
  std::vector<Sign> touch;
  auto push = [&](TimelineNode n, const Root* r, Sign tch) {
    seq.push_back(n);
    node_root.push_back(r);
    touch.push_back(tch);
  };
  push({pol.instant_at(zero), res.status_at_0, false}, nullptr, Sign::zero);
  bool stopped = false;
  for (std::size_t i = 0; i <= interior.size(); ++i) {
    const Root* l = i ? interior[i - 1] : nullptr;
    const Root* r = i < interior.size() ? interior[i] : nullptr;
    T smp = pol.sample_between(l, r);
    Status cs = status_at(smp);
    if (first_contact_only && cs == Status::separate && i > 0 && in_collision(seq.back().status)) {
      stopped = true;  // the first collision interval has ended
      break;
    }
    push({pol.instant_at(smp), cs, true}, nullptr, Sign::zero);
    res.cells.push_back({pol.instant_at(smp), cs});
    if (r) {
      Sign tch = touches_at(*r);
      push({pol.instant(*r), tch == Sign::positive ? Status::touching : Status::separate, false}, r, tch);
    }
  }
  if (!stopped) push({pol.instant_at(one), status_at(one), false}, nullptr, Sign::zero);
  // A root that is not a touch carries the status of its cells.
  for (std::size_t n = 2; n < seq.size(); n += 2) {
    if (!node_root[n] || touch[n] == Sign::positive) continue;
    Status left = seq[n - 1].status, right = n + 1 < seq.size() ? seq[n + 1].status : left;
    if (touch[n] == Sign::uncertain) {
      seq[n].status = Status::uncertain;
      continue;
    }
    if (left == right) {
      seq[n].status = left;
      continue;
    }
    if constexpr (scalar_traits<T>::is_exact)
      throw std::logic_error("internal error: the status changes at a root of the projection without a touch");
    seq[n].status = Status::uncertain;
  }
  check_isolated_instants(seq, scalar_traits<T>::is_exact);
  res.timeline = seq;
  for (std::size_t n = 0; n < seq.size(); ++n)
    if (node_root[n]) res.critical.push_back({seq[n].t, seq[n].status, pol.multiplicity(*node_root[n])});
  assemble_answer(seq, res.answer, [](std::size_t) {});
  if (first_contact_only && res.answer.intervals.size() > 1) res.answer.intervals.resize(1);
  return finish();
}

}  // namespace eccd

namespace eccd {

// The projection pipeline of a dimension: CD-DISC in 2D (H = dim + 1 = 3; its
// projection is Δ) and the projection CCD above in 3D (H = 4). Exact, interval and
// floating policies all enter here, so the dispatch is written once.
template <class T, int H, PipelinePolicy<T> Policy>
PipelineResult<T> projection_pipeline(const MovingPair<T, H>& pair, Policy& pol, Variant variant = Variant::answer,
                                      bool first_contact_only = false) {
  if constexpr (H == H_2D)
    return cd_disc(pair, pol, variant);
  else
    return ccd_projection(pair, pol, first_contact_only);
}

}  // namespace eccd
