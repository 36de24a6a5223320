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
// What differs by arithmetic comes from a policy (kernel/pipeline_policy.hpp:
// the concept PipelinePolicy, and the optional hooks of rounded policies);
// every run returns a PipelineResult (kernel/pipeline_result.hpp).
// Requirements on T: scalar_traits<T>, ring operations.
#include "kernel/answer.hpp"
#include "kernel/basis_build.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/collision_timeline.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/contact_point_integer.hpp"
#include "kernel/pipeline_policy.hpp"
#include "kernel/pipeline_result.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "number/mpfr_real.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <string>
#include <vector>

namespace eccd {

// Why a rounded run left an instant undecided when its policy gave no note.
// Only an enclosing arithmetic (an error bound, an interval) knows that a sign
// is "too close to zero"; plain double or MPFR (the as-published face, issue
// 30 point 4) has no bound, and leaves an instant undecided for one of two
// reasons the pipeline can tell apart (cd_disc below):
//   own_sign   the values computed there give no status: f's coefficients
//              read with 1 or 3 sign changes (impossible for two ellipses in
//              exact arithmetic, contact_status.hpp), or a NaN;
//   isolated   a root of Δ the rounded computation placed between two
//              separate cells where P and D did not read as a touch
//              (collision_timeline.hpp: a spurious root, or a touch the
//              rounded values could not place).
enum class PlainUndecided { none = 0, own_sign = 1, isolated = 2 };
inline PlainUndecided operator|(PlainUndecided a, PlainUndecided b) { return PlainUndecided(int(a) | int(b)); }
inline bool has(PlainUndecided a, PlainUndecided b) { return (int(a) & int(b)) != 0; }

template <class T>
constexpr bool plain_rounded() {  // plain T: no bound of its own (double, Mpfr)
  return !scalar_traits<T>::is_exact && (std::is_same_v<T, double> || std::is_same_v<T, Mpfr>);
}

// The reasons a floating policy gave, once each, if anything is undecided.
template <class T, PipelinePolicy<T> Policy>
void collect_reasons(PipelineResult<T>& res, const Policy& pol, PlainUndecided plain = PlainUndecided::none) {
  if (res.answer.undecided.empty()) return;
  for (const auto& n : policy_hooks::notes(pol))
    if (std::find(res.undecided_reasons.begin(), res.undecided_reasons.end(), n) == res.undecided_reasons.end())
      res.undecided_reasons.push_back(n);
  if (!res.undecided_reasons.empty()) return;
  if constexpr (plain_rounded<T>()) {
    if (has(plain, PlainUndecided::isolated))
      res.undecided_reasons.push_back(
          "a root of Δ the rounded computation placed between two separate cells, where P and D did "
          "not read as a touch (a spurious root, or a touch it could not place): no status there");
    if (has(plain, PlainUndecided::own_sign))
      res.undecided_reasons.push_back(
          "the rounded values of f's coefficients at an instant give no status (a sign pattern "
          "impossible for two ellipses, or a NaN): no status there");
    if (plain == PlainUndecided::none)  // a pipeline that does not tell (ccd_projection.hpp)
      res.undecided_reasons.push_back(
          "the rounded values at an instant give no status (signs that match no configuration, "
          "or a NaN): no status there");
  } else {
    res.undecided_reasons.push_back("a sign too close to zero to decide in this arithmetic");
  }
}

// The contact point of Lemma 5: the null vector of λ0 A(t) - B(t), λ0 = P / (2D).
template <class T>
ContactPoint contact_point(const PolyMatrix<T, 3>& a, const PolyMatrix<T, 3>& b, const std::vector<Poly<T>>& g,
                           const T& t) {
  T g3 = g[3](t), g2 = g[2](t), g1 = g[1](t), g0 = g[0](t);
  T p = double_root_numerator(g3, g2, g1, g0), d = double_root_denominator(g3, g2, g1);
  ContactPoint cp;
  if (is_zero(d)) return cp;
  T lam = p / (T(2) * d);
  Matrix<T, 3> m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T x = lam * a[i][j](t);
      m[i][j] = x - b[i][j](t);
    }
  // null vector: the largest cross product of two rows (rank 2, Lemma 5)
  T best[3] = {T(0), T(0), T(0)};
  double bestn = -1;
  for (int r = 0; r < 3; ++r) {
    const auto& u = m[r];
    const auto& v = m[(r + 1) % 3];
    T c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double n = std::abs(to_double(c[0])) + std::abs(to_double(c[1])) + std::abs(to_double(c[2]));
    if (n > bestn) {
      bestn = n;
      best[0] = c[0];
      best[1] = c[1];
      best[2] = c[2];
    }
  }
  if (is_zero(best[2])) return cp;
  T x = best[0] / best[2], y = best[1] / best[2];
  auto show = [](const T& v) {  // display only
    if constexpr (scalar_traits<T>::is_exact)
      return decimal_string(v);
    else
      return scalar_traits<T>::to_string(v);
  };
  cp.x = {show(x), show(y)};
  // The common normal: the gradient (A X) of a at X = (x, y, 1), as a unit vector in double (display only).
  double n[2];
  for (int i = 0; i < 2; ++i) n[i] = to_double(T(a[i][0](t) * x + a[i][1](t) * y + a[i][2](t)));
  const double len = std::hypot(n[0], n[1]);
  if (len > 0 && std::isfinite(len))
    cp.normal = {decimal_string_of_double(n[0] / len), decimal_string_of_double(n[1] / len)};
  return cp;
}

// The common frame of a pipeline run, shared by CD-DISC (2D, below) and the
// projection (3D, kernel/ccd_projection.hpp): the run starts from g scaled by
// the policy's hook (start_run) and ends by collecting the
// policy's reasons and its time; a policy that already reported trouble
// (floating: a non-finite value) leaves [0, 1] undecided.
template <class T, PipelinePolicy<T> Policy>
std::pair<T, T> start_run(PipelineResult<T>& res, const Policy& pol,
                          const T& like) {  // g normalised (hook); {0, 1} in T
  policy_hooks::normalise_g(pol, res.g);
  return {scalar_traits<T>::from_rational(mpq_class(0), like), scalar_traits<T>::from_rational(mpq_class(1), like)};
}
template <class T, PipelinePolicy<T> Policy>
PipelineResult<T> finish_run(PipelineResult<T>& res, const Policy& pol, std::chrono::steady_clock::time_point start,
                             PlainUndecided plain = PlainUndecided::none) {
  collect_reasons(res, pol, plain);
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}
template <class T, PipelinePolicy<T> Policy>
bool undecided_on_trouble(PipelineResult<T>& res, Policy& pol, const T& zero, const T& one) {
  std::string why = policy_hooks::trouble(pol);
  if (why.empty()) return false;
  undecided_everywhere(res, pol.instant_at(zero), pol.instant_at(one), why);
  return true;
}

// Δ(t) from g_0..g_3 in the Policy's representation: what cd_disc root-finds
// (the harness in compare/ measures its coefficient error through this call).
// A policy with `static constexpr bool delta_from_hessian = true` (the plain
// floating ones: floating/cd_disc_floating.hpp) gets Δ in the Hessian form
// Δ = (4 D E - P²) / 3, with D = g2² - 3 g3 g1, E = g1² - 3 g2 g0 and
// P = 9 g3 g0 - g2 g1 (P and D as below): the same polynomial, from six
// products of g's degree and two of twice it instead of four and seven of
// higher degrees (measured: Δ's build took 8 % of the 2D degree-6 double
// pipeline; measured on the 2D cases of cases/generated, the coefficient
// error against the exact Δ is the same to two digits).
template <class Policy>
constexpr bool delta_from_hessian() {
  if constexpr (requires { Policy::delta_from_hessian; })
    return Policy::delta_from_hessian;
  else
    return false;
}
template <class T, PipelinePolicy<T> Policy>
auto discriminant_of(const std::vector<Poly<T>>& g, const Policy& pol) {
  if constexpr (delta_from_hessian<Policy>()) {
    auto delta = build_cubic(pol, g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
      auto d = double_root_denominator(g3, g2, g1);  // D = g2² - 3 g3 g1
      auto e = double_root_denominator(g0, g1, g2);  // E = g1² - 3 g2 g0
      auto p = double_root_numerator(g3, g2, g1, g0);
      auto de = d * e;
      auto pp = p * p;
      return 4 * de - pp;  // 3 Δ
    });
    const T third = scalar_traits<T>::from_rational(mpq_class(1, 3), like_of(delta.b));
    for (auto& x : delta.b) x = third * x;
    return delta;
  } else {
    return build_cubic(pol, g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
      return cubic_discriminant(g3, g2, g1, g0);
    });
  }
}

// Δ ≡ 0 (Corollary 7): the collision set is [0, 1]; touching where the double root P/(2D) is negative, decided in
// the cells between the roots of P·D.
template <class T, PipelinePolicy<T> Policy, class Rep>
void cd_disc_identically_zero(PipelineResult<T>& res, Policy& pol, const Rep& P, const Rep& D, const Instant& i0,
                              const Instant& i1) {
  Answer& ans = res.answer;
  res.projection_identically_zero = true;
  ans.collides = true;
  ans.intervals.push_back({i0, i1});
  ans.first_contact = i0;
  auto PD = build_cubic(pol, res.g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
    return double_root_numerator(g3, g2, g1, g0) * double_root_denominator(g3, g2, g1);
  });
  if (pol.identically_zero(PD)) return;
  auto rts = pol.roots(PD, false);
  for (std::size_t i = 0; i <= rts.size(); ++i) {
    T s = pol.sample_between(i ? &rts[i - 1] : nullptr, i < rts.size() ? &rts[i] : nullptr);
    Status st = status_at_multiple_root(pol.sign_at_value(P, s), pol.sign_at_value(D, s));
    res.cells.push_back({pol.instant_at(s), st});
    if (st == Status::touching)
      ans.contact_intervals.push_back({i ? pol.instant(rts[i - 1]) : i0, i < rts.size() ? pol.instant(rts[i]) : i1});
  }
}

// Variants 1 and 2 (003 VI-C) when the disks start separate: the first root of Δ is the first contact.
template <class T, PipelinePolicy<T> Policy>
void cd_disc_first_root(PipelineResult<T>& res, Policy& pol, const std::vector<typename Policy::Root>& rts) {
  Answer& ans = res.answer;
  if (!rts.empty() && policy_hooks::unresolved(rts.front())) {  // the first root is not known: undecided from there
    ans.collides = false;
    ans.undecided.push_back(pol.instant(rts.front()));
    res.critical.push_back({pol.instant(rts.front()), Status::uncertain, 0});
    return;
  }
  ans.collides = !rts.empty();
  if (!rts.empty()) ans.first_contact = pol.instant(rts.front());
  for (auto& r : rts) res.critical.push_back({pol.instant(r), Status::touching, 0});
}

// The timeline instant, cell, instant, ..., cell, instant over [0, 1] (kernel/collision_timeline.hpp) from the
// roots rts of Δ: the ends by the static test (touching at a root of Δ there that P and D call a touch), the cells
// by the static test at a sample (also into res.cells), the interior roots by P and D. node_root[k] is the root of
// node k, if any.
template <class T, PipelinePolicy<T> Policy, class Rep, class StatusAt>
void cd_disc_timeline(PipelineResult<T>& res, Policy& pol, const std::vector<typename Policy::Root>& rts, const Rep& P,
                      const Rep& D, const StatusAt& status_at, const T& zero, const T& one, const Instant& i0,
                      const Instant& i1, std::vector<TimelineNode>& seq,
                      std::vector<const typename Policy::Root*>& node_root) {
  using Root = typename Policy::Root;
  std::vector<const Root*> interior;
  const Root* root0 = nullptr;
  const Root* root1 = nullptr;
  for (auto& r : rts) {
    if (pol.at_zero(r))
      root0 = &r;
    else if (pol.at_one(r))
      root1 = &r;
    else
      interior.push_back(&r);
  }
  auto root_status = [&](const Root& r) { return status_at_multiple_root(pol.sign_at(P, r), pol.sign_at(D, r)); };
  auto endpoint_status = [&](const T& t, const Root* r) {
    Status s = status_at(t);
    if (r && root_status(*r) == Status::touching) s = Status::touching;
    return s;
  };
  auto push = [&](TimelineNode n, const Root* r) {
    seq.push_back(n);
    node_root.push_back(r);
  };
  push({i0, endpoint_status(zero, root0), false}, root0);
  for (std::size_t i = 0; i <= interior.size(); ++i) {
    const Root* l = i ? interior[i - 1] : nullptr;
    const Root* r = i < interior.size() ? interior[i] : nullptr;
    T s = pol.sample_between(l, r);
    Status cs = status_at(s);
    push({pol.instant_at(s), cs, true}, nullptr);
    res.cells.push_back({pol.instant_at(s), cs});
    if (r) push({pol.instant(*r), root_status(*r), false}, r);
  }
  push({i1, endpoint_status(one, root1), false}, root1);
}

// Marks the timeline's isolated instants undecided (check_isolated_instants); returns why plain T left instants
// undecided (collect_reasons).
inline PlainUndecided settle_isolated_instants(std::vector<TimelineNode>& seq, bool exact) {
  PlainUndecided plain = PlainUndecided::none;
  std::size_t before = 0, after = 0;
  for (const auto& n : seq) before += n.status == Status::uncertain;
  if (before > 0) plain = plain | PlainUndecided::own_sign;
  check_isolated_instants(seq, exact);
  for (const auto& n : seq) after += n.status == Status::uncertain;
  if (after > before) plain = plain | PlainUndecided::isolated;
  return plain;
}

template <class T, PipelinePolicy<T> Policy>
PipelineResult<T> cd_disc(const MovingPair2<T>& pair, Policy& pol, Variant variant = Variant::answer) {
  auto start = std::chrono::steady_clock::now();
  PipelineResult<T> res;
  res.variant = variant;
  const PolyMatrix<T, 3> A = moving_quadric<T, H_2D>(pair.qa, pair.na);
  const PolyMatrix<T, 3> B = moving_quadric<T, H_2D>(pair.qb, pair.nb);
  res.g = characteristic_coefficients<T, H_2D>(A, B);
  const std::pair<T, T> ends = start_run(res, pol, pair.qa[0][0]);
  const T &zero = ends.first, &one = ends.second;
  const auto& g = res.g;
  PlainUndecided plain = PlainUndecided::none;  // why plain T left instants undecided (collect_reasons)
  auto finish = [&]() { return finish_run(res, pol, start, plain); };
  if (undecided_on_trouble(res, pol, zero, one)) return finish();

  auto status_at = [&](const T& t) {
    return policy_hooks::settle_status(pol, t, cubic_contact_status(g[3](t), g[2](t), g[1](t), g[0](t)));
  };
  res.status_at_0 = status_at(zero);

  auto delta = discriminant_of(g, pol);
  auto P = build_cubic(pol, g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
    return double_root_numerator(g3, g2, g1, g0);
  });
  auto D = build_cubic(pol, g, [](const auto& g3, const auto& g2, const auto& g1, const auto&) {
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
    cd_disc_identically_zero(res, pol, P, D, i0, i1);
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
    cd_disc_first_root(res, pol, rts);
    return finish();
  }

  std::vector<TimelineNode> seq;
  std::vector<const typename Policy::Root*> node_root;
  cd_disc_timeline(res, pol, rts, P, D, status_at, zero, one, i0, i1, seq, node_root);
  plain = settle_isolated_instants(seq, scalar_traits<T>::is_exact);
  res.timeline = seq;
  for (std::size_t k = 0; k < seq.size(); ++k)
    if (!seq[k].is_cell && node_root[k])
      res.critical.push_back({seq[k].t, seq[k].status, pol.multiplicity(*node_root[k])});

  assemble_answer(seq, ans, [&](std::size_t k) {
    const T at = node_root[k] ? pol.value(*node_root[k]) : (k == 0 ? zero : one);
    if constexpr (std::is_same_v<T, mpq_class>)
      ans.contact_points.push_back(contact_point_integer(A, B, g, at));  // the same point over the integers
    else
      ans.contact_points.push_back(contact_point(A, B, g, at));
  });
  if (variant == Variant::all_contacts) ans.intervals.clear();
  return finish();
}

}  // namespace eccd
