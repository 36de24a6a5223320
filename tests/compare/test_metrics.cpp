// The report's metrics (compare/metrics.hpp) on hand-made inputs whose error
// is known, and the harness rows (compare/harness.hpp) on one scene.
#include "compare/harness.hpp"
#include "compare/metrics.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
Poly<mpq_class> qpoly(std::vector<mpq_class> c) { return Poly<mpq_class>(std::move(c)); }
}  // namespace

TEST_CASE("normwise relative error of one perturbed coefficient is the perturbation over the largest coefficient",
          "[metrics]") {
  std::vector<mpq_class> exact{1, -2, 8, 3};
  std::vector<mpq_class> approx = exact;
  approx[1] += mpq_class(1, 1024);                                        // one coefficient off by 2^-10
  CHECK(normwise_relative_error(approx, exact) == std::ldexp(1.0, -13));  // 2^-10 / 8
  CHECK(normwise_relative_error(exact, exact) == 0.0);
  // An all-zero exact list: the absolute error.
  CHECK(normwise_relative_error({mpq_class(1, 4)}, {mpq_class(0)}) == 0.25);
}

TEST_CASE("coefficient error of g in power form: one double coefficient perturbed by a known amount", "[metrics]") {
  std::vector<Poly<mpq_class>> g{qpoly({3, 0, -5}), qpoly({1, 2}), qpoly({0, 0, 0, 10})};
  std::vector<Poly<double>> gd{Poly<double>({3.0, 0.0, -5.0}), Poly<double>({1.0, 2.0}),
                               Poly<double>({0.0, 0.0, 0.0, 10.0})};
  CHECK(coefficient_error(gd, g) == 0.0);
  gd[1].c[0] = 1.0 + std::ldexp(1.0, -20);
  CHECK(coefficient_error(gd, g) == Approx(std::ldexp(1.0, -20) / 10.0).epsilon(1e-15));
  // A leading coefficient that exact arithmetic cancels but rounding left behind counts too.
  gd[1].c[0] = 1.0;
  gd[0].c.push_back(1e-12);
  CHECK(coefficient_error(gd, g) == Approx(1e-13).epsilon(1e-12));
}

TEST_CASE("coefficient error in Bernstein form compares after exact degree elevation", "[metrics]") {
  Bern<mpq_class> e(std::vector<mpq_class>{mpq_class(1), mpq_class(-3), mpq_class(2)});
  Bern<mpq_class> up = elevate(e, 2);  // the same polynomial in degree 4
  Bern<double> d;
  for (const auto& x : up.b) d.b.push_back(x.get_d());
  REQUIRE(d.b.size() == 5);
  CHECK(coefficient_error(d, e) == 0.0);
  double big = 0;
  for (const auto& x : up.b) big = std::max(big, std::abs(x.get_d()));
  d.b[2] += 0.25;  // exactly representable: error 0.25 / max |coefficient of degree 4|
  CHECK(coefficient_error(d, e) == Approx(0.25 / big).epsilon(1e-15));
  // MPFR values enter exactly.
  Bern<Mpfr> m;
  for (const auto& x : up.b) m.b.push_back(Mpfr(x, 200));
  CHECK(coefficient_error(m, e) == 0.0);
}

// The answer comparison itself: tests/api/test_answer_difference.cpp.

TEST_CASE("harness rows for one generated 2D scene: every pipeline, exact first, errors ordered by precision",
          "[metrics][harness]") {
  GeneratorSpec sp;
  sp.dim = 2;
  sp.degree = 3;
  sp.family = "colliding";
  sp.seed = 7;
  GeneratedScene g = generate_scene(sp);
  Scene s = parse_scene(g.doc.dump(), g.name);
  HarnessOptions o;
  o.mpfr_bits = {64, 256};
  o.inputs = {"prepared"};  // coefficient errors are measured for this mode; one mode: labels without suffix
  o.fcl = false;            // fcl/ccd has no row for this rotating scene (tests/compare/test_fcl_engine.cpp)
  auto rows = run_scene(s, scene_info(s, "generated"), o);
  REQUIRE(rows.size() == harness_pipelines(2, o).size());
  CHECK(rows[0].pipeline == "exact");
  CHECK(rows[0].m.outcome == "correct");
  CHECK(rows[0].m.structure_ok);
  CHECK(rows[0].scene.family == "colliding");
  CHECK(rows[0].scene.degree == 3);
  std::map<std::string, const ResultRow*> by;
  for (const auto& r : rows) by[r.pipeline] = &r;
  // Rounding errors shrink with the precision (the same code, more bits).
  REQUIRE(by.count("double/bernstein"));
  REQUIRE(by.count("mpfr:256/bernstein"));
  CHECK(*by["double/bernstein"]->coef_err < 1e-12);
  CHECK(*by["mpfr:256/bernstein"]->coef_err < 1e-70);
  CHECK(*by["mpfr:256/power"]->delta_err < *by["mpfr:64/power"]->delta_err);
  CHECK(*by["mpfr:64/power"]->delta_err < *by["double/power"]->delta_err);
  for (const auto& r : rows) CHECK(r.input == "prepared");
  // The common-basis error: a Bernstein pipeline's is its coef_err; a power pipeline's is measured on the same
  // Bernstein coefficients as the Bernstein pipelines' (and shrinks with the precision like them).
  for (const auto& r : rows) {
    if (r.pipeline == "exact") continue;
    INFO(r.pipeline);
    if (r.arith ==
        "certified") {  // the certified ladder holds intervals or rationals: no floating coefficients to measure
      CHECK(!r.coef_err);
      CHECK(!r.coef_err_common);
      continue;
    }
    REQUIRE(r.coef_err_common);
    if (r.basis != "power") CHECK(*r.coef_err_common == *r.coef_err);
  }
  CHECK(*by["mpfr:256/power"]->coef_err_common <= *by["mpfr:64/power"]->coef_err_common);
  CHECK(*by["mpfr:64/power"]->coef_err_common <= *by["double/power"]->coef_err_common);
  // The change of basis is exact and one to one: exact power coefficients iff exact Bernstein coefficients.
  for (const char* p : {"double/power", "mpfr:64/power", "mpfr:256/power"})
    CHECK((*by[p]->coef_err == 0) == (*by[p]->coef_err_common == 0));
  // Both faces of every floating pipeline: the guarded row keeps the label, its as-published twin is marked.
  for (const auto& r : rows) {
    if (r.arith != "double" && r.arith != "mpfr") {
      CHECK(r.guard.empty());
      continue;
    }
    INFO(r.pipeline);
    const bool published = r.pipeline.find("/published") != std::string::npos;
    CHECK(r.guard == (published ? "none" : "bound"));
    if (!published) CHECK(by.count(r.pipeline + "/published"));
  }
  // One CSV line per row, 33 fields each (coef_err_common, issue 19; guard, exact_touch and second_look, issue 30).
  for (const auto& r : rows) {
    const std::string line = results_csv_line(r);
    CHECK(std::count(line.begin(), line.end(), ',') == 32);
  }
  const std::string head = results_csv_header();
  CHECK(std::count(head.begin(), head.end(), ',') == 32);
  CHECK(head.substr(head.size() - std::string(",reason,coef_err_common,guard,exact_touch,second_look").size()) ==
        ",reason,coef_err_common,guard,exact_touch,second_look");
}

TEST_CASE("exact_touch: the truth touches without overlapping (an interval of one instant, or continuous touching)",
          "[metrics]") {
  auto at = [](long p, long q) {
    const mpq_class t(p, q);
    return Instant{std::to_string(t.get_d()), t, t, t.get_d()};
  };
  Answer overlap;  // a collision interval of positive length: the guard can bracket both ends
  overlap.collides = true;
  overlap.intervals = {{at(1, 4), at(3, 4)}};
  CHECK_FALSE(answer_metrics(nullptr, overlap).exact_touch);
  Answer touch = overlap;  // an isolated touch at 1/2 beside the overlap
  touch.intervals.push_back({at(1, 2), at(1, 2)});
  CHECK(answer_metrics(nullptr, touch).exact_touch);
  Answer rolling;  // continuous touching on [0, 1] (cases/rolling/circles-rolling.json)
  rolling.collides = true;
  rolling.intervals = {{at(0, 1), at(1, 1)}};
  rolling.contact_intervals = rolling.intervals;
  CHECK(answer_metrics(nullptr, rolling).exact_touch);
  Answer free;
  CHECK_FALSE(answer_metrics(&free, free).exact_touch);
  // Brackets, not approximations, decide: two certified ends with the same double but different brackets are an
  // interval of positive length.
  Answer narrow = overlap;
  narrow.intervals = {
      {Instant{"0.5", mpq_class(1, 2), mpq_class(1, 2), 0.5},
       Instant{"0.5", mpq_class(1, 2) + mpq_class(1, 1L << 62), mpq_class(1, 2) + mpq_class(1, 1L << 62), 0.5}}};
  CHECK_FALSE(answer_metrics(nullptr, narrow).exact_touch);
}

TEST_CASE("coefficient error in the common basis: power coefficients changed exactly to Bernstein form", "[metrics]") {
  // p(t) = 1 + t: power [1, 1], Bernstein [1, 2]. The approximation 1 + (1 + 2^-52) t is [1, 2 + 2^-52] in
  // Bernstein form: normwise relative error 2^-52 / 2 = 2^-53 in the common basis, 2^-52 / 1 in power form.
  const double u = std::ldexp(1.0, -52);
  std::vector<Poly<double>> approx{Poly<double>(std::vector<double>{1.0, 1.0 + u})};
  std::vector<Poly<mpq_class>> exact{Poly<mpq_class>(std::vector<mpq_class>{1, 1})};
  std::vector<Bern<mpq_class>> exact_bern{to_bernstein(exact[0])};
  CHECK(coefficient_error(approx, exact) == u);
  CHECK(coefficient_error_common(approx, exact_bern) == std::ldexp(1.0, -53));
  // Exact input: no error in either basis; a degree that differs is elevated exactly (p = 1 against [1, 1]).
  std::vector<Poly<double>> one{Poly<double>(std::vector<double>{1.0})};
  Bern<mpq_class> flat;
  flat.b = {1, 1};
  CHECK(coefficient_error_common(one, {flat}) == 0.0);
  // A non-finite coefficient has no exact value: the error is +inf.
  std::vector<Poly<double>> bad{Poly<double>(std::vector<double>{1.0, std::numeric_limits<double>::infinity()})};
  CHECK(std::isinf(coefficient_error_common(bad, exact_bern)));
}

TEST_CASE("harness: both input modes are rows of their own where the solver has them", "[metrics][harness]") {
  HarnessOptions o;
  o.mpfr_bits = {64};
  o.inputs = {"rounded", "prepared"};
  auto pipes = harness_pipelines(2, o);
  int prepared = 0, rounded = 0;
  for (const auto& p : pipes) {
    if (p.arith != "double" && p.arith != "mpfr")
      continue;  // exact, and the peers certified and fcl have one input each
    (p.input == "prepared" ? prepared : rounded)++;
    if (solver_has_input_modes()) CHECK((p.input == "prepared") == (p.label.find("@prepared") != std::string::npos));
  }
  CHECK(prepared == 10);  // (double x 3 bases, mpfr:64 x 2) x 2 faces
  CHECK(rounded == (solver_has_input_modes() ? 10 : 0));
  // One face only: half the rows.
  o.guards = {"bound"};
  int guarded = 0;
  for (const auto& p : harness_pipelines(2, o)) guarded += p.arith == "double" || p.arith == "mpfr";
  CHECK(guarded == 10);
  SolveOptions so;
  CHECK_THROWS_AS(apply_input_mode(so, "rounding"), std::invalid_argument);
}

TEST_CASE("harness: a run that does not stop is killed and recorded as a time-out", "[metrics][harness][budget]") {
  // A 2D decimal scene whose double run took minutes before issue 14 (or, after it, ends well within the budget):
  // either way run_bounded returns within 2 x budget + 1 s of the run's processor time (the budget is processor
  // time: kernel/budget.hpp); its wall time only within the minutes of run_bounded's backstop.
  GeneratorSpec sp;
  sp.dim = 2;
  sp.degree = 2;
  sp.family = "decimal";
  sp.digits = 6;
  sp.seed = 132530586833523ULL;
  GeneratedScene g = generate_scene(sp);
  Scene s = parse_scene(g.doc.dump(), g.name);
  SolveOptions opt;
  opt.arith = parse_arithmetic("double");
  BoundedRun r = run_bounded(s, opt, 0.2, true);
  INFO("processor " << r.cpu_s << " s, wall " << r.wall_s << " s, " << r.reason);
  CHECK(r.cpu_s < 2 * 0.2 + 1 + 0.1);
  CHECK(r.wall_s < 10 * (2 * 0.2 + 1) + 120);
  if (r.timed_out)
    CHECK(r.reason.rfind("time budget", 0) == 0);
  else
    CHECK(r.got.has_value());
}

}  // namespace ECCD_UNITY_ID
