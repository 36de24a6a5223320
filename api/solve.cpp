// The API's entry points (api/solve.hpp): dispatch to the one templated
// pipeline in the chosen arithmetic and return its typed Solution.
#include "api/solve.hpp"
#include "api/contact_points.hpp"

#include "certified/independent_proof.hpp"
#include "certified/ladder.hpp"
#include "exact/cd_disc_exact.hpp"
#include "exact/independent_balls.hpp"
#include "floating/bezier_ccd.hpp"
#include "floating/ccd3_baselines.hpp"
#include "floating/cd_disc_floating.hpp"
#include "floating/independent_ccd.hpp"
#include "floating/rounded_input.hpp"
#include "floating/translation_ccd.hpp"
#include "io/scene_reader.hpp"
#include "kernel/budget.hpp"
#include "kernel/ccd_projection.hpp"
#include "kernel/cycloidal_cd_disc.hpp"
#include "kernel/trivariate_bernstein.hpp"
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "number/running_error.hpp"

#include <chrono>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace eccd {

Scene read_scene(const std::string& path) { return read_scene_file(path); }
Scene scene_from_text(const std::string& json_text, const std::string& label) { return parse_scene(json_text, label); }

const char* to_string(Method m) {
  switch (m) {
    case Method::projection:
      return "projection";
    case Method::sampling:
      return "sampling";
    case Method::marching:
      return "marching";
    default:
      return "bezier";
  }
}

std::pair<Method, int> parse_method(const std::string& text) {
  if (text == "bezier") return {Method::bezier, 0};
  if (text == "projection") return {Method::projection, 0};
  for (Method m : {Method::sampling, Method::marching}) {
    std::string name = to_string(m);
    if (text.rfind(name + ":", 0) != 0) continue;
    std::string n = text.substr(name.size() + 1);
    if (n.empty() || n.size() > 6 || n.find_first_not_of("0123456789") != std::string::npos || std::stoi(n) < 1)
      throw std::invalid_argument("--method " + text + ": expected " + name +
                                  ":N with N a whole number from 1 to 999999");
    return {m, std::stoi(n)};
  }
  throw std::invalid_argument("--method " + text + ": expected bezier, projection, sampling:N or marching:N");
}

const char* to_string(Guard g) { return g == Guard::none ? "none" : "bound"; }

Guard parse_guard(const std::string& text) {
  if (text == "none") return Guard::none;
  if (text == "bound") return Guard::bound;
  throw std::invalid_argument("--guard " + text + ": expected none (the algorithm as published) or bound (guarded)");
}

std::string SolveOptions::method_name() const {
  if (method == Method::sampling || method == Method::marching)
    return std::string(to_string(method)) + ":" + std::to_string(grid);
  return to_string(method);
}

namespace {

// A run where nothing could be decided: [0, 1] undecided, with the reason
// (a value that is not finite, or a deadline that passed inside a stage that
// cannot stop half-way: kernel/polynomial.hpp throws BudgetExhausted).
template <class T>
Solution undecided_run(const std::string& reason, int dim, Variant v) {
  PipelineResult<T> r;
  r.variant = v;
  Instant zero{"0", std::nullopt, std::nullopt, 0.0}, one{"1", std::nullopt, std::nullopt, 1.0};
  undecided_everywhere(r, zero, one, reason);
  return solution_of(r, dim);
}

// The pair a floating run starts from: the scene's numbers rounded to T and
// prepared in T (input mode rounded, floating/rounded_input.hpp), or the
// exactly prepared pair rounded (input mode prepared). trouble: "" or why a
// value is not finite.
template <class T, int N>
MovingPair<T, N> floating_pair(const Scene& scene, const SolveOptions& opt, const T& like, std::string& trouble) {
  trouble.clear();
  if (opt.input == InputMode::prepared) return to_arithmetic<T, N>(prepare_pair<N>(scene), like);
  return round_pair<T, N>(scene, like, trouble);
}

template <class T>
Solution run_floating_2d(const Scene& scene, const SolveOptions& opt, const T& like) {
  Solution s;
  try {
    FloatingPolicy<T> pol(opt.basis, opt.arith.precision_bits(), like);
    std::string trouble;
    MovingPair<T, 3> m = floating_pair<T, 3>(scene, opt, like, trouble);
    if (!trouble.empty()) {
      PipelineResult<T> r;
      r.variant = opt.variant;
      undecided_everywhere(r, pol.instant_at(scalar_traits<T>::from_rational(0, like)),
                           pol.instant_at(scalar_traits<T>::from_rational(1, like)), trouble);
      s = solution_of(r, 2);
    } else {
      s = solution_of(cd_disc(m, pol, opt.variant), 2);
    }
  } catch (const BudgetExhausted& e) {
    s = undecided_run<T>(e.what(), 2, opt.variant);
  }
  s.basis = to_string(opt.basis);
  return s;
}

template <class T>
Solution run_floating_3d_stages(const Scene& scene, const SolveOptions& opt, const T& like) {
  auto start = std::chrono::steady_clock::now();
  std::string trouble;
  std::optional<PreparedPair<4>> p;
  if (opt.input == InputMode::prepared) p = prepare_pair<4>(scene);
  MovingPair<T, 4> m = p ? to_arithmetic<T, 4>(*p, like) : round_pair<T, 4>(scene, like, trouble);
  const bool power = opt.basis == Basis::power;
  // g_0..g_4: products in Bernstein form from N(t) in Bernstein form, or in power form.
  std::vector<Bern<T>> g;
  if (trouble.empty() && opt.method != Method::projection)
    g = p ? characteristic_bernstein<T, 4>(*p, power, like) : characteristic_bernstein_of<T, 4>(m, power);
  double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Solution s;
  if (!trouble.empty()) {
    s = undecided_run<T>(trouble, 3, Variant::answer);
  } else if (opt.method == Method::projection) {
    FloatingPolicy<T> pol(opt.basis, opt.arith.precision_bits(), like);
    s = solution_of(ccd_projection(m, pol, opt.first_contact), 3);
    setup = 0;  // ccd_projection builds its own coefficients and times them
  } else if (opt.method == Method::bezier) {
    BezierOptions bo;
    bo.first_contact_only = opt.first_contact;
    if (opt.arith.kind == Arithmetic::Mpfr) bo.max_subdivisions = 2000;  // MPFR steps cost 10-100x double's
    s = solution_of(ccd_bezier(g, like, opt.arith.precision_bits(), bo), 3);
    s.projection = "bezier";  // no univariate projection: the degree is F(u,t)'s in t
  } else if (opt.method == Method::sampling) {
    s = solution_of(ccd_sampling(g, like, opt.grid, opt.first_contact), 3);
    s.sampled = true;  // a grid of instants: nothing is claimed about the gaps between them
  } else {
    s = solution_of(ccd_marching(g, like, opt.grid, opt.first_contact), 3);
    s.sampled = true;
  }
  s.setup_ms = setup * 1e3;
  s.time_ms += setup * 1e3;
  return s;
}

// The guarded face's shortcut for a pair in straight-line relative
// translation (floating/translation_ccd.hpp), in double from the scene's
// numbers rounded: its answer when every claim is proved, else nothing and the
// Bézier method runs. Only the guarded face takes it: the as-published face is
// 001's Bézier method as the paper states it, whose errors the reports count.
template <class T>
std::optional<Solution> translation_shortcut(const Scene& scene, const SolveOptions& opt, const T& like) {
  if constexpr (!std::is_same_v<T, Bounded<double>>)
    return std::nullopt;
  else {
    if (opt.method != Method::bezier || opt.input != InputMode::rounded || opt.basis == Basis::scaled_bernstein)
      return std::nullopt;
    const auto start = std::chrono::steady_clock::now();
    const auto pair = translating_pair<T>(scene, like);
    if (!pair) return std::nullopt;
    const auto r = translation_ccd(*pair);
    if (!r) return std::nullopt;
    Solution s;
    s.dim = 3;
    s.answer = r->answer;
    s.projection = "contact-function";
    s.projection_degree = 2;
    s.work = {{"newton_steps", r->newton_steps}, {"proofs", r->proofs}};
    s.time_ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
    s.basis = to_string(opt.basis);
    s.method = "translation";
    return s;
  }
}

template <class T>
Solution run_floating_3d(const Scene& scene, const SolveOptions& opt, const T& like) {
  if (opt.basis == Basis::scaled_bernstein && opt.method != Method::projection)
    throw std::invalid_argument("--basis scaled-bernstein applies to --method projection only in 3D");
  if ((opt.method == Method::sampling || opt.method == Method::marching) && (opt.grid < 1 || opt.grid > 999999))
    throw std::invalid_argument("--method " + opt.method_name() + ": expected " + to_string(opt.method) +
                                ":N with N a whole number from 1 to 999999");
  Solution s;
  try {
    if (auto t = deadline_passed() ? std::nullopt : translation_shortcut(scene, opt, like)) return *t;
    s = run_floating_3d_stages(scene, opt, like);
  } catch (const BudgetExhausted& e) {
    s = undecided_run<T>(e.what(), 3, Variant::answer);
  }
  s.basis = to_string(opt.basis);
  s.method = opt.method_name();
  return s;
}

// A cycloidal scene (003 section V): Δ(t) is not a polynomial, so no basis
// applies; its roots are isolated by validated subdivision in T read as an
// enclosure (kernel/cycloidal_cd_disc.hpp).
template <class T>
Solution run_floating_cycloidal(const Scene& scene, const SolveOptions& opt, const T& like) {
  if (opt.input == InputMode::prepared)
    throw std::invalid_argument(
        "--input prepared needs rational motions: a cycloidal scene is read with --input rounded");
  Solution s;
  try {
    CycloidalOptions co;
    const int bits = opt.arith.precision_bits();
    co.max_depth = std::clamp(bits / 2, 20, 200);
    co.refine_bits = std::clamp(bits + 8, 60, 4000);
    s = solution_of(cycloidal_cd_disc(cycloidal_pair<T>(scene, like), like, co, opt.variant), 2);
  } catch (const BudgetExhausted& e) {
    s = undecided_run<T>(e.what(), 2, opt.variant);
  }
  s.basis = "pointwise";
  s.method = "cd-disc-cycloidal";
  return s;
}

// The guarded face's second look (2D and 3D). Where the guarded double run
// leaves instants undecided, the reason is mostly its bound, not the
// algorithm: at a near miss the smallest values (Δ's in 2D, F(u, t)'s in 3D)
// lie below what double resolves, and the errors are already in the
// coefficients, so no evaluation of those coefficients can decide there. The
// same pipeline (same method, basis, input mode and variant) then runs once
// more with a running error bound in MPFR of kSecondLookBits bits, from the
// scene's numbers rounded to that precision: its claims, like the double
// run's, are proved about the scene's exact numbers
// (number/running_error.hpp). Its answer replaces the double one only if it
// decides everything; otherwise, or if the run's deadline passes, the double
// answer stands. Both runs' times count in time_ms, and the work counter
// second_look says that it ran (1) and decided (2).
// Only where every reason is a sign the double bound could not read: an
// overflow, a work bound or the time budget stays the double run's answer.
// The second look has a budget of its own inside the run's deadline, in work
// units (kernel/budget.hpp ScopedWorkBudget: the deadline checks, the
// polynomial products' coefficient products and the de Casteljau and Horner
// steps the run does), so that where it
// stops, and so the answer, is the same on every machine and under any load
// (a budget of processor time made a near miss decided on a quiet machine and
// undecided on a busy one): kSecondLookUnits units (measured: 128-bit MPFR
// runs about 5 million units a second in 3D and 2 to 5 million in 2D on the
// machine of reports/performance.md, so the budget is under a second there, as
// the 0.5 s of processor time it replaces was; no share of the double run's
// units, as that budget had a share of its time: double does a unit a hundred
// times faster than MPFR, vectorised, so its units say little of what the
// MPFR run needs), so that a near miss
// costs a double run its fraction of a second, not the MPFR run's seconds; a
// second look that meets it leaves the double answer standing (second_look 1;
// second_look_units says how many it used). A processor-time backstop of
// kSecondLookBackstop seconds stays in case a loop counts less work than it
// does; no run of cases/ or of the report's scenes reaches it.
constexpr int kSecondLookBits = 128;
constexpr unsigned long long kSecondLookUnits = 4'000'000;
constexpr double kSecondLookBackstop = 10;

bool only_arithmetic_limits(const Solution& s) {
  if (s.undecided_reasons.empty()) return false;
  for (const auto& r : s.undecided_reasons)
    if (r.find("too close to zero") == std::string::npos &&
        r.find("could not resolve in this arithmetic") == std::string::npos)
      return false;
  return true;
}

template <class Run>
Solution second_look(const SolveOptions& opt, Solution first, Run&& run) {
  if (deadline_passed()) return first;
  SolveOptions wide = opt;
  wide.arith = Arithmetic::mpfr(kSecondLookBits);
  const auto start = std::chrono::steady_clock::now();
  ScopedDeadline backstop(kSecondLookBackstop, DeadlineClock::thread_cpu);
  const unsigned long long before = work_units_done();
  Solution s;
  {
    ScopedWorkBudget cap(kSecondLookUnits);
    s = run(wide, Bounded<Mpfr>(Mpfr(mpq_class(1), kSecondLookBits), 0));
  }
  const unsigned long long used = work_units_done() - before;
  const double ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
  const bool decided = s.decided();
  Solution& out = decided ? s : first;
  out.time_ms = first.time_ms + ms;
  out.work.emplace_back("second_look", decided ? 2 : 1);
  out.work.emplace_back("second_look_units", long(std::min<unsigned long long>(used, 1ULL << 62)));
  return std::move(out);
}

template <class T>
Solution run_floating(const Scene& scene, const SolveOptions& opt, const T& like) {
  constexpr bool guarded_double = std::is_same_v<T, Bounded<double>>;
  if (scene.dim == 3) {
    Solution s = run_floating_3d(scene, opt, like);
    if constexpr (guarded_double)
      if (!s.decided() && !s.sampled && only_arithmetic_limits(s))
        s = second_look(opt, std::move(s),
                        [&](const SolveOptions& w, const auto& l) { return run_floating_3d(scene, w, l); });
    return s;
  }
  if (has_cycloidal_motion(scene)) {
    // The cycloidal pipeline isolates the roots of a transcendental Δ by
    // subdivision that reads T as an enclosure (number/enclosure.hpp): it
    // exists in the guarded face only.
    if constexpr (has_error_bound_v<T>)
      return run_floating_cycloidal(scene, opt, like);
    else
      throw std::invalid_argument(
          "--guard none: a cycloidal scene has no as-published floating pipeline "
          "(its roots of Δ are isolated by validated subdivision): use --guard bound");
  }
  Solution s = run_floating_2d(scene, opt, like);
  if constexpr (guarded_double)
    if (!s.decided() && only_arithmetic_limits(s))
      s = second_look(opt, std::move(s),
                      [&](const SolveOptions& w, const auto& l) { return run_floating_2d(scene, w, l); });
  s.method = "cd-disc";
  return s;
}

// Independent motions ("parameters": "independent", scene-format.md; 001
// section 4): F(u, s, t) (kernel/trivariate_bernstein.hpp, H = 3 for ellipses,
// 4 for ellipsoids) from the exactly prepared pair rounded to T (the input
// mode is always `prepared` here), then floating/independent_ccd.hpp. T is
// plain double / Mpfr (as published) or Bounded<...> (guarded); MPFR gets a
// smaller work bound (a box test costs 10-100x double's), and both the
// run's deadline (kernel/budget.hpp).
template <class T, int H>
IndependentResult independent_floating_result(const Scene& scene, const SolveOptions& opt, const T& like) {
  Scene shared = scene;
  shared.independent = false;  // prepare_pair refuses independent scenes for the shared-parameter pipelines
  PreparedPair<H> p = prepare_pair<H>(shared);
  hold_still_pair(p);  // a body that does not move as a set: held at 0, decided exactly before any rounding
  IndependentOptions io;
  if (opt.arith.kind == Arithmetic::Mpfr) io.max_tests = 2000000;
  try {
    const TriBern<T> F = independent_ellipsoid_function<T, H>(to_arithmetic_bernstein<T, H>(p, like));
    return ccd_independent(F, like, io);
  } catch (const BudgetExhausted& e) {
    IndependentResult r;
    r.answer.independent = true;
    r.answer.undecided.push_back(Instant{"0", std::nullopt, std::nullopt, 0.0});
    r.undecided_reasons.push_back(std::string("s and t in [0, 1]: ") + e.what());
    return r;
  }
}

template <class T>
Solution run_independent_floating(const Scene& scene, const SolveOptions& opt, const T& like) {
  if (has_cycloidal_motion(scene))
    throw IndependentMotionsRefused(
        "independent motions with cycloidal (non-rational) motions are not solved: F(u, s, t) needs rational motions");
  const auto start = std::chrono::steady_clock::now();
  const IndependentResult r = scene.dim == 3 ? independent_floating_result<T, 4>(scene, opt, like)
                                             : independent_floating_result<T, 3>(scene, opt, like);
  Solution s;
  s.dim = scene.dim;
  s.answer = r.answer;
  s.undecided_reasons = r.undecided_reasons;
  s.work = r.counters;
  s.projection = "bezier";
  s.projection_degree = r.degree_s;
  s.time_ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
  s.basis = "bernstein";
  s.method = "bezier-independent";
  s.input = InputMode::prepared;
  return s;
}

// F's exact net of an independent scene, ellipses or ellipsoids.
TriBern<Rational> independent_exact_net(const Scene& scene) {
  if (has_cycloidal_motion(scene))
    throw IndependentMotionsRefused(
        "independent motions with cycloidal (non-rational) motions are not solved: F(u, s, t) needs rational motions");
  Scene shared = scene;
  shared.independent = false;
  if (scene.dim == 3)
    return independent_ellipsoid_function<Rational, 4>(
        to_arithmetic_bernstein<Rational, 4>(prepare_pair<4>(shared), Rational(1)));
  return independent_ellipsoid_function<Rational, 3>(
      to_arithmetic_bernstein<Rational, 3>(prepare_pair<3>(shared), Rational(1)));
}

// Proved answers for any rational motions (certified/independent_proof.hpp):
// F's net built exactly, then interval proofs (strip signs; at each end
// Krawczyk's test and the exclusion of other extreme points). The answer says
// so: method "bezier-independent-proved", basis "interval+mpfi:BITS",
// decided_in, and one line per proved end in `proofs`.
Solution run_independent_proved(const Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const TriBern<Rational> F = independent_exact_net(scene);
  const IndependentProofOptions po;
  const IndependentProofResult r = prove_independent(F, po);
  Solution s;
  s.dim = scene.dim;
  s.answer = r.answer;
  s.undecided_reasons = r.undecided_reasons;
  s.work = r.counters;
  s.certified = r.answer.undecided.empty();
  s.basis = "interval+mpfi:" + std::to_string(po.bits);
  s.method = "bezier-independent-proved";
  s.projection = "krawczyk";
  s.projection_degree = r.degree_s;
  s.decided_in = "interval proofs about the exact F (cells: intervals of doubles; ends: Krawczyk in MPFI " +
                 std::to_string(po.bits) + " bits)";
  s.proofs = r.proofs;
  s.time_ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
  return s;
}

// Exact: two balls (discs in 2D) on straight paths (exact/independent_balls.hpp),
// each cell decided by the exact shared-parameter pipeline on the scene with
// one object fixed at the cell's rational sample; any other pair by the
// proved route above.
Solution run_independent_exact(const Scene& scene) {
  const auto a = ball_path(scene.a), b = ball_path(scene.b);
  if (!a || !b) return run_independent_proved(scene);
  const auto start = std::chrono::steady_clock::now();
  auto fixed = [](const SceneObject& o, const Rational& x) {
    SceneObject f = o;
    if (auto* m = std::get_if<MatrixMotion>(&f.motion))
      for (auto& row : m->m)
        for (auto& e : row) e = RPoly::constant(e(x));
    return f;
  };
  long runs = 0;
  auto meets = [&](bool fix_a, const Rational& x) {
    Scene sh = scene;
    sh.independent = false;
    sh.answer.reset();
    (fix_a ? sh.a : sh.b) = fixed(fix_a ? scene.a : scene.b, x);
    ++runs;
    return scene.dim == 3 ? run_exact<4>(prepare_pair<4>(sh), Variant::answer, false).answer.collides
                          : run_exact<3>(prepare_pair<3>(sh), Variant::answer, false).answer.collides;
  };
  Solution s;
  s.dim = scene.dim;
  s.answer.independent = true;
  s.answer.s_intervals = ball_projection(*a, *b, [&](const Rational& x) { return meets(true, x); });
  s.answer.t_intervals = ball_projection(*b, *a, [&](const Rational& x) { return meets(false, x); });
  s.answer.collides = !s.answer.s_intervals.empty();
  if (s.answer.s_intervals.empty() != s.answer.t_intervals.empty())
    throw std::logic_error("independent balls: one projection is empty and the other is not");
  s.certified = true;
  s.basis = "exact";
  s.method = "balls-exact";
  s.projection = "explicit";
  s.work = {{"shared_exact_runs", runs}};
  s.time_ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
  return s;
}

// A floating run in the face opt.guard asks for: `run(like)` with like a 1 in
// plain T (as published) or in Bounded<T> (guarded), T = double or Mpfr at
// the arithmetic's precision. The Solution says which face ran.
template <class Run>
Solution in_face(const SolveOptions& opt, Run&& run) {
  const bool bound = opt.guard == Guard::bound;
  Solution s;
  if (opt.arith.kind == Arithmetic::Double) {
    s = bound ? run(Bounded<double>(1.0, 0)) : run(1.0);
  } else {
    const Mpfr one(mpq_class(1), opt.arith.mpfr_bits);
    s = bound ? run(Bounded<Mpfr>(one, 0)) : run(one);
  }
  s.guard = to_string(opt.guard);
  return s;
}

Solution solve_independent(const Scene& scene, const SolveOptions& opt) {
  switch (opt.arith.kind) {
    case Arithmetic::Double:
    case Arithmetic::Mpfr:
      return in_face(opt, [&](const auto& like) {
        return run_independent_floating<std::decay_t<decltype(like)>>(scene, opt, like);
      });
    case Arithmetic::Exact:
      return run_independent_exact(scene);
    case Arithmetic::Certified:
      return run_independent_proved(scene);
  }
  throw IndependentMotionsRefused("independent motions (\"parameters\": \"independent\") are not solved in " +
                                  opt.arith.name() + " arithmetic");
}

}  // namespace

Solution solve(const Scene& scene, const SolveOptions& opt) {
  if (scene.dim == 2 && (int(opt.variant) < 0 || int(opt.variant) > 3))
    throw std::invalid_argument("--variant must be 0, 1, 2 or 3");
  // Floating runs always end: each method has work bounds, and a run that the
  // caller did not bound otherwise gets the default deadline (the earlier of
  // two deadlines counts, kernel/budget.hpp); what is left then is undecided.
  const bool floating = opt.arith.floating();
  ScopedDeadline budget(opt.time_limit_s > 0 ? opt.time_limit_s : floating ? kDefaultFloatingSeconds : 0);
  Solution s;
  if (scene.independent) {
    s = solve_independent(scene, opt);
    s.scene = scene.name;
    s.file = scene.path;
    s.arith = opt.arith;
    return s;
  }
  std::optional<PreparedPair<4>> prepared3;  // an exact or certified 3D run's pair, shared with its contact points
  switch (opt.arith.kind) {                  // prepare_pair refuses cycloidal motions for exact arithmetic
    case Arithmetic::Double:
    case Arithmetic::Mpfr:
      s = in_face(opt, [&](const auto& like) { return run_floating<std::decay_t<decltype(like)>>(scene, opt, like); });
      break;
    case Arithmetic::Exact:
      if (scene.dim == 3) prepared3 = prepare_pair<4>(scene);
      s = scene.dim == 3 ? run_exact<4>(*prepared3, opt.variant, opt.first_contact)
                         : run_exact<3>(prepare_pair<3>(scene), opt.variant, opt.first_contact);
      break;
    case Arithmetic::Certified:
      if (scene.dim == 2 && has_cycloidal_motion(scene)) {
        s = run_certified_cycloidal(scene, opt.arith.mpfi_rungs, opt.variant);
        break;
      }
      if (scene.dim == 3) prepared3 = prepare_pair<4>(scene);
      s = scene.dim == 3
              ? run_certified<4>(*prepared3, opt.arith.mpfi_rungs, opt.variant, opt.first_contact)
              : run_certified<3>(prepare_pair<3>(scene), opt.arith.mpfi_rungs, opt.variant, opt.first_contact);
      break;
  }
  s.scene = scene.name;
  s.file = scene.path;
  s.dim = scene.dim;
  s.arith = opt.arith;
  s.input = floating ? opt.input : InputMode::prepared;
  add_contact_points_3d(scene, s,
                        prepared3 ? &*prepared3 : nullptr);  // 3D contact points and normals (api/contact_points.hpp)
  return s;
}

}  // namespace eccd
