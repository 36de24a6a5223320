// Phases: the targets' pipelines split into their public steps.
#include "bench/groups.hpp"

namespace eccd_bench::groups {

// P = 9g3g0 - g2g1 and D = g2² - 3g3g1 (003 section VI-B) built by the policy, as cd_disc builds them.
template <class Policy, class G>
auto build_P_D(Policy& pol, const G& g) {
  auto P = build_cubic(pol, g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) {
    return double_root_numerator(g3, g2, g1, g0);
  });
  auto D = build_cubic(pol, g, [](const auto& g3, const auto& g2, const auto& g1, const auto&) {
    return double_root_denominator(g3, g2, g1);
  });
  return std::make_pair(std::move(P), std::move(D));
}

template <class T, class Policy>
void add_phases_2d(const std::string& grp, Lazy<Scene2D>* sc, Variant var, std::function<Policy()> make_pol,
                   std::function<T()> make_like) {
  struct In {
    MovingPair<T, 3> m;
    std::vector<Poly<T>> g;
    typename Policy::Rep delta, P, D;
    std::vector<typename Policy::Root> roots;
  };
  auto in = std::make_shared<Lazy<In>>([sc, make_pol, make_like] {
    const Scene2D& s = sc->get();
    Policy pol = make_pol();
    In x{to_arithmetic<T, 3>(s.p, make_like()), {}, {}, {}, {}, {}};
    x.g = characteristic_coefficients<T, 3>(moving_quadric<T, 3>(x.m.qa, x.m.na), moving_quadric<T, 3>(x.m.qb, x.m.nb));
    x.delta = discriminant_of(x.g, pol);
    std::tie(x.P, x.D) = build_P_D(pol, x.g);
    x.roots = pol.roots(x.delta, false);
    return x;
  });
  auto none = [](const auto&) { return json(); };
  row(grp, "total pipeline", true, Cost::slow, "to_arithmetic + cd_disc", [=](benchmark::State& st) {
    const Scene2D& s = sc->get();
    T like = make_like();
    timed(
        st, grp + "/total pipeline",
        [&] {
          Policy pol = make_pol();
          MovingPair<T, 3> m = to_arithmetic<T, 3>(s.p, like);
          return cd_disc(m, pol, var);
        },
        [](const auto& r) { return summarise_ccd(r); });
  });
  row(grp, "1 to_arithmetic", false, Cost::slow, "the exact scene rounded to the arithmetic",
      [=](benchmark::State& st) {
        const Scene2D& s = sc->get();
        T like = make_like();
        timed(
            st, grp + "/1 to_arithmetic", [&] { return to_arithmetic<T, 3>(s.p, like); }, none);
      });
  row(grp, "2 g = det(λA - B)", false, Cost::slow, "moving_quadric x 2 + characteristic_coefficients (power form)",
      [=](benchmark::State& st) {
        const In& x = in->get();
        timed(
            st, grp + "/2 g = det(λA - B)",
            [&] {
              return characteristic_coefficients<T, 3>(moving_quadric<T, 3>(x.m.qa, x.m.na),
                                                       moving_quadric<T, 3>(x.m.qb, x.m.nb));
            },
            none);
      });
  row(grp, "3 Δ build", false, Cost::slow, "discriminant_of(g, policy)", [=](benchmark::State& st) {
    const In& x = in->get();
    Policy pol = make_pol();
    timed(
        st, grp + "/3 Δ build", [&] { return discriminant_of(x.g, pol); }, none);
  });
  row(grp, "4 P, D build", false, Cost::slow, "policy.build of P = 9g3g0 - g2g1 and D = g2² - 3g3g1",
      [=](benchmark::State& st) {
        const In& x = in->get();
        Policy pol = make_pol();
        timed(
            st, grp + "/4 P, D build", [&] { return build_P_D(pol, x.g); }, none);
      });
  row(grp, "5 roots of Δ", false, Cost::slow, "policy.roots(Δ)", [=](benchmark::State& st) {
    const In& x = in->get();
    Policy pol = make_pol();
    timed(
        st, grp + "/5 roots of Δ", [&] { return pol.roots(x.delta, false); },
        [](const auto& r) {
          return json{{"roots", r.size()}};
        });
  });
  row(grp, "6 signs of P, D at the roots", false, Cost::slow,
      "policy.sign_at(P, r), policy.sign_at(D, r) for every root", [=](benchmark::State& st) {
        const In& x = in->get();
        Policy pol = make_pol();
        timed(
            st, grp + "/6 signs of P, D at the roots",
            [&] {
              int n = 0;
              for (const auto& r : x.roots) n += int(pol.sign_at(x.P, r)) + int(pol.sign_at(x.D, r));
              return n;
            },
            none);
      });
}

// The 2D groups: cd_disc in double (Variant 3) and exact (full answer), step by step.
void register_phases_2d() {
  group("phases-2d-deg6-double-v3", "Where the time goes: 2D degree 6, Variant 3, double",
        "The steps of cd_disc timed one by one on the same inputs; the remainder (static tests at the samples, "
        "contact points, answer assembly) is the total minus the steps.",
        "speed target for the total: at most 50 µs");
  add_phases_2d<double, FloatingPolicy<double>>(
      "phases-2d-deg6-double-v3", &s2d_deg6, Variant::all_contacts,
      [] { return FloatingPolicy<double>(Basis::bernstein, 53, 1.0); }, [] { return 1.0; });
  group("phases-2d-deg6-guarded-v3", "Where the time goes: 2D degree 6, Variant 3, double guarded",
        "The same steps in Bounded<double> (the guarded face: the same values with a running error bound), "
        "from the same exactly prepared pair: beside the rows above they break the guard's cost down by step.",
        "none (phase rows; the guard's cost target is the product rows' ratio)");
  add_phases_2d<Bounded<double>, FloatingPolicy<Bounded<double>>>(
      "phases-2d-deg6-guarded-v3", &s2d_deg6, Variant::all_contacts,
      [] { return FloatingPolicy<Bounded<double>>(Basis::bernstein, 53, Bounded<double>(1.0, 0)); },
      [] { return Bounded<double>(1.0, 0); });
  group("phases-2d-deg6-exact-v0", "Where the time goes: 2D degree 6, full answer, exact",
        "The steps of cd_disc with ExactPolicy timed one by one on the same inputs (roots: the square-free "
        "part by FLINT, CGAL's isolation and refinement; signs: exact signs at algebraic numbers).",
        "speed target for the total: at most 5 ms");
  add_phases_2d<Rational, ExactPolicy>(
      "phases-2d-deg6-exact-v0", &s2d_deg6, Variant::answer, [] { return ExactPolicy(); }, [] { return Rational(1); });
}

// Paper 002's example in double, Bézier method, step by step.
void register_phases_paper002_double() {
  // 3D paper 002, double Bézier: setup of g, F(u, t), the zero-set analysis.
  std::string grp = "phases-paper002-double-bezier";
  group(grp, "Where the time goes: paper 002's example, double Bézier",
        "characteristic_bernstein (g_0..g_4 in Bernstein form from N(t) converted exactly to Bernstein form), "
        "F(u, t) = det((u-1)A - uB) as a bivariate Bernstein polynomial (BezierZeroSet's constructor), and the "
        "analysis (static tests at 33 samples, shooting, subdivision, Gaussian-circle tests); the remainder is "
        "ccd_bezier's answer assembly.",
        "speed target for the total: at most 0.3 ms");
  auto g002 = std::make_shared<Lazy<std::vector<Bern<double>>>>(
      [] { return characteristic_bernstein<double, 4>(s3d_paper002.get().p, false, 1.0); });
  row(grp, "total pipeline", true, Cost::slow, "characteristic_bernstein + ccd_bezier", [grp](benchmark::State& st) {
    const Scene3D& s = s3d_paper002.get();
    timed(
        st, grp + "/total pipeline",
        [&] { return run3d_floating<double>(s.p, "bezier", Basis::bernstein, 53, 1.0, false); },
        [](const auto& r) { return summarise_ccd(r); });
  });
  row(grp, "1 setup g (characteristic_bernstein)", false, Cost::slow, "", [grp](benchmark::State& st) {
    const Scene3D& s = s3d_paper002.get();
    timed(
        st, grp + "/1 setup g (characteristic_bernstein)",
        [&] { return characteristic_bernstein<double, 4>(s.p, false, 1.0); }, [](const auto&) { return json(); });
  });
  row(grp, "1a to_arithmetic_bernstein (part of 1)", false, Cost::slow,
      "N(t) converted to Bernstein form exactly, then rounded", [grp](benchmark::State& st) {
        const Scene3D& s = s3d_paper002.get();
        timed(
            st, grp + "/1a to_arithmetic_bernstein (part of 1)",
            [&] { return to_arithmetic_bernstein<double, 4>(s.p, 1.0); }, [](const auto&) { return json(); });
      });
  row(grp, "2 zero-set analysis (BezierZeroSet: F build + run)", false, Cost::slow,
      "BezierZeroSet<double>(g, ...).run(): static tests at the samples, shooting, subdivision, Gaussian-circle tests",
      [grp, g002](benchmark::State& st) {
        const auto& g = g002->get();
        timed(
            st, grp + "/2 zero-set analysis (BezierZeroSet: F build + run)",
            [&] {
              BezierZeroSet<double> z(g, 1.0, 53, BezierOptions{});
              return z.run().size();
            },
            [](std::size_t n) {
              return json{{"timeline_nodes", n}};
            });
      });
  row(grp, "2a F(u,t) build (part of 2)", false, Cost::slow, "BezierZeroSet constructor (ellipsoid_function)",
      [grp, g002](benchmark::State& st) {
        const auto& g = g002->get();
        timed(
            st, grp + "/2a F(u,t) build (part of 2)",
            [&] { return BezierZeroSet<double>(g, 1.0, 53, BezierOptions{}).F().degree_t(); },
            [](int d) {
              return json{{"degree_t", d}};
            });
      });
}

// Paper 002's example, exact projection, step by step.
// Paper 002, exact projection: the rest of ccd_projection. At every interior root the touch rule
// (negative_multiple_root) asks for signs of subresultant coefficients s(j, i) there, and every cell is decided by
// the exact static test at its sample. The plan (which s(j, i), which samples) is recorded once.
struct ExactTouchPlan {
  std::vector<AlgebraicRoot> roots;  // interior roots
  std::vector<std::pair<int, int>> needed;
  std::vector<std::tuple<std::size_t, int, int>> calls;  // (root, j, i)
  std::map<std::pair<int, int>, Poly<Rational>> s;
  std::vector<Rational> samples;  // 0, the cell samples, 1
};

ExactTouchPlan exact_touch_plan(const std::vector<Poly<Rational>>& g, const Poly<Rational>& projection) {
  ExactPolicy pol;
  ExactTouchPlan pl;
  for (auto& r : pol.roots(projection, false))
    if (!pol.at_zero(r) && !pol.at_one(r)) pl.roots.push_back(r);
  for (std::size_t n = 0; n < pl.roots.size(); ++n)
    negative_multiple_root(0, [&](int j, int i) {
      auto key = std::make_pair(j, i);
      if (!pl.s.count(key)) {
        pl.s[key] = subresultant_evidence(g, j, i);
        pl.needed.push_back(key);
      }
      pl.calls.emplace_back(n, j, i);
      return pol.sign_at(pl.s[key], pl.roots[n]);
    });
  pl.samples.push_back(Rational(0));
  for (std::size_t i = 0; i <= pl.roots.size(); ++i)
    pl.samples.push_back(
        pol.sample_between(i ? &pl.roots[i - 1] : nullptr, i < pl.roots.size() ? &pl.roots[i] : nullptr));
  pl.samples.push_back(Rational(1));
  return pl;
}

// The rows of the touch rule's and the static tests' work (the plan's).
void add_exact_touch_rows(const std::string& grp, std::shared_ptr<Lazy<std::vector<Poly<Rational>>>> gx,
                          std::shared_ptr<Lazy<ExactTouchPlan>> plan) {
  row(grp, "4 s(j,i) build (those the touch rule asks for)", false, Cost::slow,
      "ExactPolicy::build of subresultant_evidence(g, j, i) (FLINT, as the pipeline), for each distinct (j, i) asked "
      "at the roots",
      [grp, gx, plan](benchmark::State& st) {
        const auto& g = gx->get();
        const ExactTouchPlan& pl = plan->get();
        timed(
            st, grp + "/4 s(j,i) build (those the touch rule asks for)",
            [&] {
              std::vector<Poly<Rational>> out;
              for (auto [j, i] : pl.needed)
                out.push_back(ExactPolicy().build(g, [j, i](const auto& G) { return subresultant_evidence(G, j, i); }));
              return out;
            },
            [&](const auto&) {
              json j = json::array();
              for (auto [a, b] : pl.needed)
                j.push_back(subresultant_evidence_name(a, b) + " of degree " +
                            std::to_string(pl.s.at({a, b}).degree()));
              return json{{"built", j}, {"interior_roots", pl.roots.size()}};
            });
      });
  row(grp, "5 signs of s(j,i) at the roots", false, Cost::slow,
      "ExactPolicy::sign_at (CGAL sign at an algebraic number)", [grp, plan](benchmark::State& st) {
        const ExactTouchPlan& pl = plan->get();
        ExactPolicy pol;
        timed(
            st, grp + "/5 signs of s(j,i) at the roots",
            [&] {
              int n = 0;
              for (auto [r, j, i] : pl.calls) n += int(pol.sign_at(pl.s.at({j, i}), pl.roots[r]));
              return n;
            },
            [&](int) {
              return json{{"sign_evaluations", pl.calls.size()}};
            });
      });
  row(grp, "6 static tests at 0, the cell samples and 1", false, Cost::slow, "quartic_status_at (exact Sturm count)",
      [grp, gx, plan](benchmark::State& st) {
        const auto& g = gx->get();
        const ExactTouchPlan& pl = plan->get();
        timed(
            st, grp + "/6 static tests at 0, the cell samples and 1",
            [&] {
              int n = 0;
              for (const auto& t : pl.samples) n += int(quartic_status_at(g, t));
              return n;
            },
            [&](int) {
              return json{{"static_tests", pl.samples.size()}};
            });
      });
}

void register_phases_paper002_exact() {
  // 3D paper 002, exact projection.
  std::string grp = "phases-paper002-exact";
  group(grp, "Where the time goes: paper 002's example, exact projection",
        "ccd_projection with ExactPolicy split: the exact g_k, the discriminant of the quartic (degree 216, built in "
        "FLINT), its isolation on [0, 1] (square-free factors by FLINT, isolation by CGAL), and the rest (exact Sturm "
        "counts in the cells, subresultant signs at the roots).",
        "speed target for the total: at most 25 ms");
  auto gx = std::make_shared<Lazy<std::vector<Poly<Rational>>>>(
      [] { return characteristic_of(to_arithmetic<Rational, 4>(s3d_paper002.get().p, Rational(1))); });
  auto projx = std::make_shared<Lazy<Poly<Rational>>>([gx] {
    const auto& g = gx->get();
    return quartic_discriminant(g[4], g[3], g[2], g[1], g[0]);
  });
  row(grp, "total pipeline", true, Cost::very_slow, "to_arithmetic + ccd_projection, ExactPolicy",
      [grp](benchmark::State& st) {
        const Scene3D& s = s3d_paper002.get();
        timed(
            st, grp + "/total pipeline", [&] { return run3d_exact(s.p); },
            [](const auto& r) { return summarise_ccd(r); });
      });
  row(grp, "1 g = det(λA - B)", false, Cost::slow, "to_arithmetic<Rational,4> + characteristic_of",
      [grp](benchmark::State& st) {
        const Scene3D& s = s3d_paper002.get();
        timed(
            st, grp + "/1 g = det(λA - B)",
            [&] { return characteristic_of(to_arithmetic<Rational, 4>(s.p, Rational(1))); },
            [](const auto&) { return json(); });
      });
  row(grp, "2 projection build", false, Cost::slow,
      "ExactPolicy::build of quartic_discriminant (FLINT, as the pipeline)", [grp, gx](benchmark::State& st) {
        const auto& g = gx->get();
        timed(
            st, grp + "/2 projection build",
            [&] {
              return ExactPolicy().build(
                  g, [](const auto& G) { return quartic_discriminant(G[4], G[3], G[2], G[1], G[0]); });
            },
            [](const Poly<Rational>& p) {
              return json{{"degree", p.degree()}};
            });
      });
  row(grp, "3 roots of the projection", false, Cost::slow, "ExactPolicy::roots (real_roots on [0, 1] + refinement)",
      [grp, projx](benchmark::State& st) {
        const auto& p = projx->get();
        ExactPolicy pol;
        timed(
            st, grp + "/3 roots of the projection", [&] { return pol.roots(p, false); },
            [](const auto& r) {
              return json{{"roots", r.size()}};
            });
      });
  auto plan = std::make_shared<Lazy<ExactTouchPlan>>([gx, projx] { return exact_touch_plan(gx->get(), projx->get()); });
  add_exact_touch_rows(grp, gx, plan);
}

void register_phases() {
  register_phases_2d();
  register_phases_paper002_double();
  register_phases_paper002_exact();
}

}  // namespace eccd_bench::groups
