#pragma once
// CD-DISC: continuous collision detection of two moving elliptic disks
// (003 sections III, IV and VI), written once for every arithmetic.
//
// Statement. f(λ;t) = det(λA(t) - B(t)) = g3 λ³ + g2 λ² + g1 λ + g0 (003 eq.
// (1)); Δ(t) its discriminant in λ (eq. (2)). Between consecutive real roots
// of Δ in [0, 1] the disks are either separate or overlapping throughout
// (status changes need a multiple root, Theorem 6, Corollary 7), so each cell
// is decided at one sample instant (kernel/contact_status.hpp). At a root t0
// of Δ, f has a multiple root; they touch externally iff it is a negative
// double root (Theorem 6.1; 003 VI-B: not every root of Δ is a contact, e.g.
// concentric circles), decided from the signs of P = 9g3g0 - g2g1 and
// D = g2² - 3g3g1 at t0; otherwise they overlap at t0. t = 0 and t = 1 are
// decided directly. The variants of 003 VI-C: 1 = collides?, 2 = first
// contact, 3 = all external contacts with contact points (Lemma 5); 0 (default)
// = the scene answer, with the maximal intervals of the collision set.
// Δ ≡ 0: f has a multiple root for every t, so the disks are never separate
// (Corollary 7): the collision set is [0, 1]; they touch where P·D < 0.
//
// The Policy supplies what differs by arithmetic (design.md: "only the places
// where the mathematics really differs branch"):
//   Rep                  how Δ, P, D are held (Poly<T> exact, Bern<T> floating)
//   Root                 a root of Δ in [0, 1]
//   build(g, formula)    Δ, P or D from g (formula applied in the ring of Rep)
//   identically_zero(r)
//   roots(delta, first_only)          sorted roots of Δ in [0, 1]
//   sign_at(q, root)                  sign of q at a root (exact: proved)
//   sign_at_value(q, t)               sign of q at an instant t of type T
//   multiplicity(root)                as a root of Δ (floating: 1 simple, 2 cluster)
//   sample_between(root*, root*)      an instant strictly between (nullptr = 0 / 1)
//   instant(root), instant_at(T)      Answer instants
//   value(root)                       a T near the root (contact points, display)
//   at_zero(root), at_one(root)
// Requirements on T: scalar_traits<T>, ring operations.
#include "kernel/answer.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/collision_timeline.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace eccd {

enum class Variant { answer = 0, collides = 1, first_contact = 2, all_contacts = 3 };

template <class T>
struct PipelineResult {
  Answer answer;
  Variant variant = Variant::answer;
  std::vector<Poly<T>> g;           // g_0 .. g_N (g_3 in 2D, g_4 in 3D), power form
  int projection_degree = -1;            // degree of Δ as built in this arithmetic and basis
  bool projection_identically_zero = false;
  int projection_index = 0;         // 3D: 0 = discriminant, k = psc_k (kernel/ccd_projection.hpp)
  Status status_at_0 = Status::uncertain;
  struct Critical { Instant t; Status status; int multiplicity = 0; };
  std::vector<Critical> critical;   // roots of Δ in [0, 1] with their status
  struct Cell { Instant sample; Status status; };
  std::vector<Cell> cells;
  std::vector<TimelineNode> timeline;  // instant, cell, ..., instant (kernel/collision_timeline.hpp)
  std::vector<std::pair<std::string, long>> counters;  // work done (method-specific)
  std::vector<std::string> undecided_reasons;  // floating: why the undecided instants are undecided
  double seconds = 0;
};

// Hooks of floating policies (issue 14): scaling of g by a power of two,
// non-finite values ("trouble": nothing can be decided) and notes on parts
// left undecided (work bound, deadline). Exact and interval policies have
// none of them, and these do nothing for them.
namespace policy_hooks {
template <class Policy, class G>
void normalise_g(const Policy& pol, G& g) {
  if constexpr (requires { pol.normalise_g(g); }) pol.normalise_g(g);
}
template <class Policy>
std::string trouble(const Policy& pol) {
  if constexpr (requires { pol.trouble; }) return pol.trouble;
  else return {};
}
template <class Policy>
std::vector<std::string> notes(const Policy& pol) {
  if constexpr (requires { pol.notes; }) return pol.notes;
  else return {};
}
template <class Root>
bool unresolved(const Root& r) {
  if constexpr (requires { r.unresolved; }) return r.unresolved;
  else return false;
}
}  // namespace policy_hooks

// Nothing can be decided (a non-finite value): the whole of [0, 1] is
// undecided, with the reason; never a confident answer.
template <class T>
void undecided_everywhere(PipelineResult<T>& res, const Instant& i0, const Instant& i1, const std::string& reason) {
  res.answer = Answer{};
  res.answer.collides = false;
  res.answer.undecided = {i0, i1};
  res.status_at_0 = Status::uncertain;
  res.timeline = {{i0, Status::uncertain, false}, {i0, Status::uncertain, true}, {i1, Status::uncertain, false}};
  res.cells = {{i0, Status::uncertain}};
  res.undecided_reasons.push_back(reason);
}

// The reasons a floating policy gave, once each, if anything is undecided.
template <class T, class Policy>
void collect_reasons(PipelineResult<T>& res, const Policy& pol) {
  if (res.answer.undecided.empty()) return;
  for (const auto& n : policy_hooks::notes(pol))
    if (std::find(res.undecided_reasons.begin(), res.undecided_reasons.end(), n) == res.undecided_reasons.end())
      res.undecided_reasons.push_back(n);
  if (res.undecided_reasons.empty()) res.undecided_reasons.push_back("a sign too close to zero to decide in this arithmetic");
}

// The start of a 3D result from g_0..g_4 in Bernstein form: variant, and g in power form for reporting.
template <class T>
PipelineResult<T> result_from_bernstein(const std::vector<Bern<T>>& g, bool first_contact_only) {
  PipelineResult<T> res;
  res.variant = first_contact_only ? Variant::first_contact : Variant::answer;
  for (const auto& gi : g) res.g.push_back(to_power(gi));
  return res;
}

// The contact point of Lemma 5: the null vector of λ0 A(t) - B(t), λ0 = P / (2D).
template <class T>
ContactPoint contact_point(const PolyMatrix<T, 3>& a, const PolyMatrix<T, 3>& b, const std::vector<Poly<T>>& g, const T& t) {
  T g3 = g[3](t), g2 = g[2](t), g1 = g[1](t), g0 = g[0](t);
  T p = double_root_numerator(g3, g2, g1, g0), d = double_root_denominator(g3, g2, g1);
  ContactPoint cp;
  if (is_zero(d)) return cp;
  T lam = p / (T(2) * d);
  Matrix<T, 3> m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) { T x = lam * a[i][j](t); m[i][j] = x - b[i][j](t); }
  // null vector: the largest cross product of two rows (rank 2, Lemma 5)
  T best[3] = {T(0), T(0), T(0)};
  double bestn = -1;
  for (int r = 0; r < 3; ++r) {
    const auto& u = m[r];
    const auto& v = m[(r + 1) % 3];
    T c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double n = std::abs(to_double(c[0])) + std::abs(to_double(c[1])) + std::abs(to_double(c[2]));
    if (n > bestn) { bestn = n; best[0] = c[0]; best[1] = c[1]; best[2] = c[2]; }
  }
  if (is_zero(best[2])) return cp;
  T x = best[0] / best[2], y = best[1] / best[2];
  auto show = [](const T& v) {  // display only
    if constexpr (scalar_traits<T>::is_exact) return decimal_string(v); else return scalar_traits<T>::to_string(v);
  };
  cp.x = {show(x), show(y)};
  return cp;
}

// Δ(t) from g_0..g_3 in the Policy's representation: what cd_disc root-finds
// (the harness in compare/ measures its coefficient error through this call).
// The common frame of a pipeline run, shared by CD-DISC (2D, below) and the
// projection (3D, kernel/ccd_projection.hpp): the run ends by collecting the
// policy's reasons and its time; a policy that already reported trouble
// (floating: a non-finite value) leaves [0, 1] undecided.
template <class T, class Policy>
PipelineResult<T> finish_run(PipelineResult<T>& res, const Policy& pol, std::chrono::steady_clock::time_point start) {
  collect_reasons(res, pol);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}
template <class T, class Policy>
bool undecided_on_trouble(PipelineResult<T>& res, Policy& pol, const T& zero, const T& one) {
  std::string why = policy_hooks::trouble(pol);
  if (why.empty()) return false;
  undecided_everywhere(res, pol.instant_at(zero), pol.instant_at(one), why);
  return true;
}

template <class T, class Policy>
auto discriminant_of(const std::vector<Poly<T>>& g, const Policy& pol) {
  return pol.build(g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
    return cubic_discriminant(g3, g2, g1, g0);
  });
}

template <class T, class Policy>
PipelineResult<T> cd_disc(const MovingPair<T, 3>& pair, Policy& pol, Variant variant = Variant::answer) {
  auto start = std::chrono::steady_clock::now();
  PipelineResult<T> res;
  res.variant = variant;
  const PolyMatrix<T, 3> A = moving_quadric<T, 3>(pair.qa, pair.na);
  const PolyMatrix<T, 3> B = moving_quadric<T, 3>(pair.qb, pair.nb);
  res.g = characteristic_coefficients<T, 3>(A, B);
  policy_hooks::normalise_g(pol, res.g);
  const auto& g = res.g;
  const T& like = pair.qa[0][0];
  const T zero = scalar_traits<T>::from_rational(mpq_class(0), like);
  const T one = scalar_traits<T>::from_rational(mpq_class(1), like);
  auto finish = [&]() { return finish_run(res, pol, start); };
  if (undecided_on_trouble(res, pol, zero, one)) return finish();

  auto status_at = [&](const T& t) { return cubic_contact_status(g[3](t), g[2](t), g[1](t), g[0](t)); };
  res.status_at_0 = status_at(zero);

  auto delta = discriminant_of(g, pol);
  auto P = pol.build(g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
    return double_root_numerator(g3, g2, g1, g0);
  });
  auto D = pol.build(g, [](const auto& g3, const auto& g2, const auto& g1, const auto&) {
    return double_root_denominator(g3, g2, g1);
  });
  res.projection_degree = delta.degree();
  Answer& ans = res.answer;
  const Instant i0 = pol.instant_at(zero), i1 = pol.instant_at(one);
  if (std::string why = policy_hooks::trouble(pol); !why.empty()) {
    undecided_everywhere(res, i0, i1, why);
    return finish();
  }

  if (pol.identically_zero(delta)) {
    res.projection_identically_zero = true;
    ans.collides = true;
    ans.intervals.push_back({i0, i1});
    ans.first_contact = i0;
    // Touching where the double root P/(2D) is negative: cells between roots of P·D.
    auto PD = pol.build(g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
      return double_root_numerator(g3, g2, g1, g0) * double_root_denominator(g3, g2, g1);
    });
    if (!pol.identically_zero(PD)) {
      auto rts = pol.roots(PD, false);
      for (std::size_t i = 0; i <= rts.size(); ++i) {
        T s = pol.sample_between(i ? &rts[i - 1] : nullptr, i < rts.size() ? &rts[i] : nullptr);
        Status st = status_at_multiple_root(pol.sign_at_value(P, s), pol.sign_at_value(D, s));
        res.cells.push_back({pol.instant_at(s), st});
        if (st == Status::touching)
          ans.contact_intervals.push_back({i ? pol.instant(rts[i - 1]) : i0, i < rts.size() ? pol.instant(rts[i]) : i1});
      }
    }
    return finish();
  }

  // Variants 1 and 2 (003 VI-C) stop at the first root when the disks start separate.
  bool first_only = (variant == Variant::collides || variant == Variant::first_contact);
  if (first_only && res.status_at_0 != Status::separate) {
    ans.collides = res.status_at_0 != Status::uncertain;
    ans.first_contact = i0;
    if (res.status_at_0 == Status::uncertain) ans.undecided.push_back(i0);
    return finish();
  }
  auto rts = pol.roots(delta, first_only);
  if (first_only) {
    if (!rts.empty() && policy_hooks::unresolved(rts.front())) {  // the first root is not known: undecided from there
      ans.collides = false;
      ans.undecided.push_back(pol.instant(rts.front()));
      res.critical.push_back({pol.instant(rts.front()), Status::uncertain, 0});
      return finish();
    }
    ans.collides = !rts.empty();
    if (!rts.empty()) ans.first_contact = pol.instant(rts.front());
    for (auto& r : rts) res.critical.push_back({pol.instant(r), Status::touching, 0});
    return finish();
  }

  // The timeline instant, cell, instant, ..., cell, instant over [0, 1]
  // (kernel/collision_timeline.hpp); roots[k] is the root of node k, if any.
  std::vector<TimelineNode> seq;
  std::vector<const typename Policy::Root*> node_root;
  std::vector<const typename Policy::Root*> interior;
  const typename Policy::Root* root0 = nullptr;
  const typename Policy::Root* root1 = nullptr;
  for (auto& r : rts) {
    if (pol.at_zero(r)) root0 = &r;
    else if (pol.at_one(r)) root1 = &r;
    else interior.push_back(&r);
  }
  auto root_status = [&](const typename Policy::Root& r) {
    return status_at_multiple_root(pol.sign_at(P, r), pol.sign_at(D, r));
  };
  auto endpoint_status = [&](const T& t, const typename Policy::Root* r) {
    Status s = status_at(t);
    if (r && root_status(*r) == Status::touching) s = Status::touching;
    return s;
  };
  auto push = [&](TimelineNode n, const typename Policy::Root* r) { seq.push_back(n); node_root.push_back(r); };
  push({i0, endpoint_status(zero, root0), false}, root0);
  for (std::size_t i = 0; i <= interior.size(); ++i) {
    const typename Policy::Root* l = i ? interior[i - 1] : nullptr;
    const typename Policy::Root* r = i < interior.size() ? interior[i] : nullptr;
    T s = pol.sample_between(l, r);
    Status cs = status_at(s);
    push({pol.instant_at(s), cs, true}, nullptr);
    res.cells.push_back({pol.instant_at(s), cs});
    if (r) push({pol.instant(*r), root_status(*r), false}, r);
  }
  push({i1, endpoint_status(one, root1), false}, root1);
  check_isolated_instants(seq, scalar_traits<T>::is_exact);
  res.timeline = seq;
  for (std::size_t k = 0; k < seq.size(); ++k)
    if (!seq[k].is_cell && node_root[k]) res.critical.push_back({seq[k].t, seq[k].status, pol.multiplicity(*node_root[k])});

  assemble_answer(seq, ans, [&](std::size_t k) {
    const T at = node_root[k] ? pol.value(*node_root[k]) : (k == 0 ? zero : one);
    ans.contact_points.push_back(contact_point(A, B, g, at));
  });
  if (variant == Variant::all_contacts) ans.intervals.clear();
  return finish();
}

}  // namespace eccd
