// The pipeline policy concept (kernel/pipeline_policy.hpp) and one contract
// checked on every model of it, the way CGAL runs one test over every model
// of a concept: the same TEMPLATE_TEST_CASE over the exact policy
// (exact/cd_disc_exact.hpp), the floating policy in double and MPFR as
// published and with a running error bound (floating/cd_disc_floating.hpp,
// the guard) and the certified policy over double and MPFI intervals
// (certified/certified_policy.hpp).
//
// The contract:
//   - on polynomials with known rational roots: the roots in [0, 1], sorted,
//     near the exact ones; a sign a policy decides at a root or at an instant
//     is the exact sign there (uncertain is allowed, a wrong sign is not); a
//     sample between two roots lies strictly between them; a root at t = 0 is
//     at_zero (or, for the certified policy, which takes no root at an end,
//     an Escalate that says so; for the guard, a root whose place it does
//     not claim); identically_zero never calls a non-zero polynomial zero,
//     and never calls an exact zero non-zero (all but the guard: a running
//     error bound after a product is never 0; an interval policy may say it
//     cannot tell).
//   - on scenes of cases/ through the one pipeline entry
//     (projection_pipeline: CD-DISC in 2D, the projection CCD in 3D): an
//     undecided answer carries a reason (an escalation carries its message);
//     what a policy that proves its decisions (exact, guard, certified)
//     claims about `collides` is the stored exact answer's, so a touching
//     scene is never called separate, and a complete answer of such a
//     policy agrees with the stored one; on the well-separated and clearly
//     colliding scenes every complete answer, the plain rounded policies'
//     too, is the stored answer (and those are complete). The stored answers
//     are the exact pipeline's
//     (`eccd regress cases/` checks them).
// Plain double and MPFR decide signs at rounded values without a bound
// (003 as published): near a touch they may give a wrong answer, which the
// reports count, so the touching contract is not asked of them.
#include "api/answer_difference.hpp"
#include "certified/certified_policy.hpp"
#include "exact/cd_disc_exact.hpp"
#include "floating/cd_disc_floating.hpp"
#include "io/scene_reader.hpp"
#include "kernel/ccd_projection.hpp"
#include "kernel/pipeline_policy.hpp"
#include "kernel/prepared_scene.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"
#include "number/mpfr_real.hpp"
#include "number/running_error.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

const std::string kCases = std::string(ECCD_SOURCE_DIR) + "/cases/";

// The models: a scalar type, its policy as the solver builds it, and whether
// every decision of the policy is proved (`proves`).
struct ExactModel {
  using T = Rational;
  using Policy = ExactPolicy;
  static constexpr bool proves = true;
  static T like() { return Rational(1); }
  static Policy make() { return ExactPolicy{}; }
};
template <class S, bool Proves>
struct FloatingModel {
  using T = S;
  using Policy = FloatingPolicy<S>;
  static constexpr bool proves = Proves;
  static T like() {
    if constexpr (std::is_same_v<S, double>)
      return 1.0;
    else if constexpr (std::is_same_v<S, Mpfr>)
      return Mpfr(mpq_class(1), 200);
    else if constexpr (std::is_same_v<S, Bounded<double>>)
      return Bounded<double>(1.0, 0);
    else
      return Bounded<Mpfr>(Mpfr(mpq_class(1), 200), 0);
  }
  static Policy make() { return Policy(Basis::bernstein, scalar_traits<S>::precision(like()), like()); }
};
using DoubleModel = FloatingModel<double, false>;
using MpfrModel = FloatingModel<Mpfr, false>;
using GuardDoubleModel = FloatingModel<Bounded<double>, true>;
using GuardMpfrModel = FloatingModel<Bounded<Mpfr>, true>;
template <class I>
struct CertifiedModel {
  using T = I;
  using Policy = CertifiedPolicy<I>;
  static constexpr bool proves = true;
  static T like() {
    if constexpr (std::is_same_v<I, Interval>)
      return Interval(0);
    else
      return MpfiInterval(Rational(0), 128);
  }
  static Policy make() { return Policy(like()); }
};
using IntervalModel = CertifiedModel<Interval>;
using MpfiModel = CertifiedModel<MpfiInterval>;

template <class M>
using Sc = typename M::T;

template <class M>
Poly<Sc<M>> in(const Poly<Rational>& p) {
  return map_coeffs<Sc<M>>(p, [](const Rational& q) { return scalar_traits<Sc<M>>::from_rational(q, M::like()); });
}
template <class M>
auto rep_of(const typename M::Policy& pol, const Poly<Rational>& p) {
  return pol.build(std::vector<Poly<Sc<M>>>{in<M>(p)}, policy_detail::FirstOf{});
}
Poly<Rational> product(const std::vector<Poly<Rational>>& fs) {
  Poly<Rational> p({Rational(1)});
  for (const auto& f : fs) p = p * f;
  return p;
}
Poly<Rational> linear(long a, long b) { return Poly<Rational>({Rational(b), Rational(a)}); }  // a t + b
Sign exact_sign(const Poly<Rational>& p, const Rational& t) {
  const int s = sgn(p(t));
  return s > 0 ? Sign::positive : s < 0 ? Sign::negative : Sign::zero;
}

// One pipeline run: the answer and its reasons, or the escalation's message.
struct Run {
  std::optional<Answer> answer;
  std::vector<std::string> reasons;
  Status status_at_0 = Status::uncertain;
  std::string escalated;
};
template <class M, int H>
Run run(const Scene& s) {
  Run out;
  const PreparedPair<H> p = prepare_pair<H>(s);
  auto pol = M::make();
  try {
    const auto r = projection_pipeline(to_arithmetic<Sc<M>, H>(p, M::like()), pol);
    out.answer = r.answer;
    out.reasons = r.undecided_reasons;
    out.status_at_0 = r.status_at_0;
  } catch (const Escalate& e) {
    out.escalated = e.what();
  }
  return out;
}
template <class M>
Run run_scene(const Scene& s) {
  return s.dim == 2 ? run<M, H_2D>(s) : run<M, H_3D>(s);
}

// The exact pipeline's status at t = 0 (once per scene).
Status exact_status_at_0(const std::string& file, const Scene& s) {
  static std::map<std::string, Status> known;
  auto it = known.find(file);
  if (it == known.end()) it = known.emplace(file, run_scene<ExactModel>(s).status_at_0).first;
  return it->second;
}

// Scenes of cases/ with stored answers: touching ones, and ones far from any
// touch (well separated, clearly colliding) on which rounding cannot matter.
const std::vector<std::string> kTouching = {
    "paper003/example2.json",
    "generated/2d/2d-deg2-touch-kinematic-6164051338131805.json",
    "generated/2d/2d-deg3-touch-kinematic-370301508307387.json",
    "touch3d/touch-and-separate.json",
    "generated/3d-euler/3d-deg2-touch-euler-6438416085184312.json",
};
const std::vector<std::string> kClear = {
    "generated/2d/2d-deg2-free-kinematic-2054184850131159.json",
    "generated/2d/2d-deg3-colliding-kinematic-2972849163640120.json",
    "generated/2d/2d-deg4-free-kinematic-6960435196246194.json",
    "generated/3d-euler/3d-deg2-colliding-euler-3526122894755803.json",
    "generated/3d-euler/3d-deg2-free-euler-311914328102894.json",
};

// What every model must satisfy on a scene; `clear`: far from any touch.
template <class M>
void check_scene(const std::string& file, bool clear) {
  INFO(file);
  const Scene s = read_scene_file(kCases + file);
  REQUIRE(s.answer);
  const Answer& want = *s.answer;
  const Run r = run_scene<M>(s);
  if (!r.answer) {  // the certified policy escalated (the ladder's next rung decides): it says why
    CHECK_FALSE(r.escalated.empty());
    return;
  }
  const Answer& a = *r.answer;
  INFO("undecided instants: " << a.undecided.size());
  if (!a.undecided.empty()) CHECK_FALSE(r.reasons.empty());  // an undecided answer carries a reason
  DifferenceOptions o;
  o.tol = 1e-6;
  const AnswerDifference d = answer_difference(a, want, o);
  for (const auto& w : d.differences) UNSCOPED_INFO(w);
  if (M::proves) {
    const std::optional<bool> claim = collides_claim(a);
    if (claim) CHECK(*claim == want.collides);  // a touching scene is never called separate
    if (a.undecided.empty()) CHECK(d.agrees);
    if (r.status_at_0 != Status::uncertain) CHECK(r.status_at_0 == exact_status_at_0(file, s));
  }
  if (clear) {
    if (!M::proves) CHECK(a.undecided.empty());  // plain rounding decides everything, and far from a touch
    if (a.undecided.empty()) CHECK(d.agrees);    // it decides right
  }
}

}  // namespace

TEST_CASE("the pipeline policies satisfy the concept, other types do not", "[kernel][policy]") {
  struct NotAPolicy {
    using Rep = Poly<Rational>;
    using Root = int;
  };
  STATIC_REQUIRE(PipelinePolicy<ExactPolicy, Rational>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<double>, double>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<Mpfr>, Mpfr>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<Bounded<double>>, Bounded<double>>);
  STATIC_REQUIRE(PipelinePolicy<FloatingPolicy<Bounded<Mpfr>>, Bounded<Mpfr>>);
  STATIC_REQUIRE(PipelinePolicy<CertifiedPolicy<Interval>, Interval>);
  STATIC_REQUIRE(PipelinePolicy<CertifiedPolicy<MpfiInterval>, MpfiInterval>);
  STATIC_REQUIRE_FALSE(PipelinePolicy<NotAPolicy, Rational>);
  STATIC_REQUIRE_FALSE(PipelinePolicy<ExactPolicy, double>);  // an exact policy takes rational instants
  // the optional hooks: rounded policies have them, exact and interval ones do not
  STATIC_REQUIRE(ReportsTrouble<FloatingPolicy<double>>);
  STATIC_REQUIRE(KeepsNotes<FloatingPolicy<double>>);
  STATIC_REQUIRE(NormalisesG<FloatingPolicy<double>, std::vector<Poly<double>>>);
  STATIC_REQUIRE(MayBeUnresolved<FloatRoot<double>>);
  STATIC_REQUIRE(SettlesStatus<CertifiedPolicy<Interval>, Interval>);
  STATIC_REQUIRE_FALSE(ReportsTrouble<ExactPolicy>);
  STATIC_REQUIRE_FALSE(NormalisesG<ExactPolicy, std::vector<Poly<Rational>>>);
  STATIC_REQUIRE_FALSE(MayBeUnresolved<AlgebraicRoot>);
  STATIC_REQUIRE_FALSE(SettlesStatus<FloatingPolicy<double>, double>);
}

TEMPLATE_TEST_CASE("every pipeline policy finds known roots and decides signs as exact arithmetic does",
                   "[kernel][policy][conformance]", ExactModel, DoubleModel, MpfrModel, GuardDoubleModel,
                   GuardMpfrModel, IntervalModel, MpfiModel) {
  using M = TestType;
  using T = Sc<M>;
  auto pol = M::make();
  // q = (3t - 1)(5t - 3)(7t - 5): simple roots 1/3 < 3/5 < 5/7, none dyadic (no
  // root at a split point of the certified policy's bisection).
  const Poly<Rational> q = product({linear(3, -1), linear(5, -3), linear(7, -5)});
  const std::vector<Rational> want{Rational(1, 3), Rational(3, 5), Rational(5, 7)};
  const auto rq = rep_of<M>(pol, q);
  CHECK_FALSE(pol.identically_zero(rq));
  // 0 · q: every coefficient an exact 0. No model calls it non-zero, except
  // the guard: a running error bound is never 0 after a product, so it cannot
  // tell this zero (the pipeline then leaves the stretch undecided). An
  // interval policy may say that it cannot tell (Escalate, kernel/pipeline_policy.hpp).
  const auto zero = pol.build(std::vector<Poly<T>>{in<M>(q)}, [](const auto& G) { return 0 * G[0]; });
  if constexpr (!has_error_bound_v<T>) {
    std::optional<bool> said;
    try {
      said = pol.identically_zero(zero);
    } catch (const Escalate& e) {
      CHECK(std::string(e.what()).find("identically") != std::string::npos);
    }
    if (said) CHECK(*said);
  }
  const auto roots = pol.roots(rq, false);
  REQUIRE(roots.size() == want.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    INFO("root " << i);
    const double v = to_double(pol.value(roots[i]));
    CHECK(v == Approx(want[i].get_d()).margin(1e-8));
    CHECK(pol.multiplicity(roots[i]) == 1);
    CHECK_FALSE(pol.at_zero(roots[i]));
    CHECK_FALSE(pol.at_one(roots[i]));
    const Instant at = pol.instant(roots[i]);
    CHECK(at.value == Approx(want[i].get_d()).margin(1e-8));
    if (at.certified()) CHECK((*at.lo <= want[i] && want[i] <= *at.hi));
    // p = (2t - 1)(10t - 7) changes sign at 1/2 and 7/10, between the roots of q:
    // positive at 1/3, negative at 3/5, positive at 5/7.
    const Poly<Rational> p = product({linear(2, -1), linear(10, -7)});
    const Sign s = pol.sign_at(rep_of<M>(pol, p), roots[i]);
    if (s != Sign::uncertain) CHECK(s == exact_sign(p, want[i]));
    if (M::proves) CHECK(s != Sign::zero);  // p does not vanish at a root of q
  }
  // the leftmost root comes first when it is the only one asked for
  const auto first = pol.roots(rq, true);
  REQUIRE_FALSE(first.empty());
  CHECK(to_double(pol.value(first.front())) == Approx(1.0 / 3).margin(1e-8));
  // samples lie strictly between consecutive roots, and inside [0, 1] at the ends
  for (std::size_t i = 0; i <= roots.size(); ++i) {
    const auto* l = i == 0 ? nullptr : &roots[i - 1];
    const auto* r = i == roots.size() ? nullptr : &roots[i];
    const double x = to_double(T(pol.sample_between(l, r)));
    const double lo = i == 0 ? 0.0 : want[i - 1].get_d(), hi = i == roots.size() ? 1.0 : want[i].get_d();
    INFO("cell " << i << ": " << x);
    CHECK((lo < x && x < hi));
    CHECK(exact_sign(q, Rational(x)) != Sign::zero);
  }
  // signs at dyadic instants (exact in every arithmetic)
  for (const Rational& t : {Rational(1, 8), Rational(1, 2), Rational(5, 8), Rational(7, 8)}) {
    const Sign s = pol.sign_at_value(rq, scalar_traits<T>::from_rational(t, M::like()));
    INFO("t = " << t.get_str());
    if (s != Sign::uncertain) CHECK(s == exact_sign(q, t));
    if constexpr (std::is_same_v<T, Rational>) CHECK(s != Sign::uncertain);  // exact: always decided
  }
  // the instant of a point is that point
  CHECK(pol.instant_at(scalar_traits<T>::from_rational(Rational(1, 4), M::like())).value == 0.25);
}

TEMPLATE_TEST_CASE("every pipeline policy places a root at t = 0 there or says it cannot",
                   "[kernel][policy][conformance]", ExactModel, DoubleModel, MpfrModel, GuardDoubleModel,
                   GuardMpfrModel, IntervalModel, MpfiModel) {
  using M = TestType;
  auto pol = M::make();
  const Poly<Rational> q = product({linear(1, 0), linear(3, -1)});  // t (3t - 1): roots 0 and 1/3
  try {
    const auto roots = pol.roots(rep_of<M>(pol, q), false);
    REQUIRE_FALSE(roots.empty());
    if constexpr (has_error_bound_v<Sc<M>>) {
      // the guard may not place a root at an end: it then claims nothing
      // there, not even the sign of t + 1 (positive on [0, 1]) at that root
      if (!pol.at_zero(roots.front()))
        CHECK(pol.sign_at(rep_of<M>(pol, linear(1, 1)), roots.front()) == Sign::uncertain);
    } else {
      CHECK(pol.at_zero(roots.front()));
    }
    CHECK_FALSE(pol.at_one(roots.front()));
    CHECK(to_double(pol.value(roots.back())) == Approx(1.0 / 3).margin(1e-8));
  } catch (const Escalate& e) {
    // the certified policy takes no root at an end: it hands the scene on, saying where
    CHECK(std::string(e.what()).find("t = 0") != std::string::npos);
  }
}

TEMPLATE_TEST_CASE("every pipeline policy keeps the contract on scenes of cases/", "[kernel][policy][conformance]",
                   ExactModel, DoubleModel, MpfrModel, GuardDoubleModel, GuardMpfrModel, IntervalModel, MpfiModel) {
  for (const auto& f : kTouching) check_scene<TestType>(f, false);
  for (const auto& f : kClear) check_scene<TestType>(f, true);
}

}  // namespace ECCD_UNITY_ID
