// The comparison harness (compare/harness.hpp): which pipelines run, how a
// run becomes a row, and the rows as results.csv. What tests/compare/
// test_metrics.cpp and test_fcl_engine.cpp check (coefficient errors, the
// count of input-mode rows, the kill of a run that does not stop, certified
// and FCL rows) is not repeated here.
//  - harness_pipelines: the exact pipeline first and once; in 2D double
//    power / bernstein / scaled-bernstein and MPFR power / bernstein per
//    precision, in 3D bezier, bezier-power, sampling:N and marching:N in
//    double and bezier (and with mpfr_power_3d bezier-power) per precision;
//    each floating one in every face asked for ("/published" before
//    "@prepared" for the as-published face), its CSV columns (arith, bits,
//    basis, method, input, guard) as the header says; an unknown input mode
//    or guard is refused; duplicate modes give no duplicate rows;
//  - in_faces puts the published suffix before any '@', drops duplicates;
//  - scene_info / scene_degree: a generator's note gives its spec (d only for
//    near-miss and overlap); a case gets the highest t-degree of the entries
//    of M_A, M_B, checked on hand-built motions (an euler motion with e of
//    degree 1 and v of degree 2 has entries E v of degree 4);
//  - run_bounded: in process or in a child, the same answer as solve(); a
//    pipeline that throws gives `error` (= reason) and no solution; a run over
//    its budget (1 µs of processor time) is timed out, "time budget ...";
//  - run_scene: coefficient errors on the prepared rows only;
//  - fill_row_from_run: a time-out is undecided with the wall time; an error
//    is outcome error; an answer's time and input are the solution's; a
//    guarded answer's second_look is its work counter (0 without one), the
//    CSV's last column, empty for as-published rows and time-outs;
//  - run_scene: rows of external engines last, judged against the exact
//    answer (a right answer file correct, a wrong one false_negative, a
//    broken one an error row, a missing one no row, no time NaN);
//  - results.csv: one field per header column, in its order, reasons on one
//    line and at most 200 characters, empty exact columns for a scene with
//    no ground truth; fcl_skipped counts scenes with an exact row and no
//    fcl/ccd row.
#include "compare/harness.hpp"

#include "compare/csv.hpp"
#include "compare/harness_families.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd;
namespace fs = std::filesystem;

namespace {
std::vector<std::string> labels_of(const std::vector<PipelineSpec>& v) {
  std::vector<std::string> out;
  for (const auto& p : v) out.push_back(p.label);
  return out;
}
const PipelineSpec& find(const std::vector<PipelineSpec>& v, const std::string& label) {
  for (const auto& p : v)
    if (p.label == label) return p;
  FAIL("no pipeline " << label);
  return v.front();
}
HarnessOptions light() {  // no peers, no isolation: the eccd pipelines alone
  HarnessOptions o;
  o.mpfr_bits = {};
  o.certified = false;
  o.fcl = false;
  o.isolate = false;
  o.inputs = {"prepared"};
  o.guards = {"bound"};
  o.budget_s = 30;
  return o;
}
std::string scene_doc(int dim, const std::string& motion_a, const std::string& motion_b) {
  const std::string axes = dim == 2 ? R"(["1", "2"])" : R"(["1", "2", "3"])";
  return R"({"format": "ellipse-ccd-scene/1", "name": "deg", "dim": )" + std::to_string(dim) +
         R"(, "a": {"shape": {"semi_axes": )" + axes + R"(}, "motion": )" + motion_a +
         R"(}, "b": {"shape": {"semi_axes": )" + axes + R"(}, "motion": )" + motion_b + "}}";
}
Scene colliding_2d() {
  GeneratorSpec sp;
  sp.dim = 2;
  sp.degree = 2;
  sp.family = "colliding";
  sp.seed = 7;
  const GeneratedScene g = generate_scene(sp);
  return parse_scene(g.doc.dump(), g.name);
}
}  // namespace

TEST_CASE("harness pipelines in 2D: exact first, every basis and precision in every face and mode",
          "[compare][harness]") {
  HarnessOptions o;
  o.mpfr_bits = {64, 128};
  o.inputs = {"rounded", "prepared", "rounded"};  // a repeated mode adds nothing
  o.guards = {"none", "bound"};
  o.certified = false;
  o.fcl = false;
  const auto v = harness_pipelines(2, o);
  REQUIRE(!v.empty());
  CHECK(v[0].label == "exact");
  CHECK(v[0].arith == "exact");
  CHECK(v[0].basis == "exact");
  CHECK(v[0].method == "cd-disc");
  CHECK(v[0].guard.empty());
  const auto labels = labels_of(v);
  CHECK(std::count(labels.begin(), labels.end(), "exact") == 1);
  CHECK(std::set<std::string>(labels.begin(), labels.end()).size() == labels.size());
  const bool modes = solver_has_input_modes();
  // (double x 3 bases + 2 precisions x 2 bases) x 2 faces x (2 modes or 1) + exact.
  CHECK(v.size() == std::size_t(1 + 7 * 2 * (modes ? 2 : 1)));
  const std::string at = modes ? "@prepared" : "";
  const PipelineSpec& pub = find(v, "double/scaled-bernstein/published" + at);
  CHECK(pub.guard == "none");
  CHECK(pub.opt.guard == Guard::none);
  CHECK(pub.arith == "double");
  CHECK(pub.bits == 53);
  CHECK(pub.basis == "scaled-bernstein");
  CHECK(pub.method == "cd-disc");
  CHECK(pub.input == "prepared");
  const PipelineSpec& g = find(v, "mpfr:128/power" + at);
  CHECK(g.guard == "bound");
  CHECK(g.opt.guard == Guard::bound);
  CHECK(g.arith == "mpfr");
  CHECK(g.bits == 128);
  CHECK(g.basis == "power");
  if (modes) {
    const PipelineSpec& r = find(v, "mpfr:64/bernstein/published");
    CHECK(r.input == "rounded");
    CHECK(r.guard == "none");
  }
  for (const auto& p : v) {
    INFO(p.label);
    if (p.arith == "double" || p.arith == "mpfr") {
      CHECK((p.guard == "none") == (p.label.find("/published") != std::string::npos));
      CHECK(p.engine == PipelineSpec::Engine::solve);
    }
  }
  // One mode only: no "@prepared" anywhere.
  o.inputs = {"prepared"};
  for (const auto& l : labels_of(harness_pipelines(2, o))) CHECK(l.find('@') == std::string::npos);
  // Refusals.
  o.inputs = {"exact"};
  CHECK_THROWS_AS(harness_pipelines(2, o), std::invalid_argument);
  o.inputs = {"prepared"};
  o.guards = {"maybe"};
  CHECK_THROWS_AS(harness_pipelines(2, o), std::invalid_argument);
  // The certified peer, when asked for: last of eccd's, no face.
  o.guards = {"bound"};
  o.certified = true;
  const auto c = harness_pipelines(2, o);
  CHECK(c.back().label == "certified");
  CHECK(c.back().method == "ladder");
  CHECK(c.back().basis == "none");
  CHECK(c.back().guard.empty());
  CHECK(c.back().bits == 0);
}

TEST_CASE("harness pipelines in 3D: the Bezier method, its power setup and the baselines at grid N",
          "[compare][harness]") {
  HarnessOptions o = light();
  o.grid = 16;
  o.mpfr_bits = {100};
  auto v = harness_pipelines(3, o);
  CHECK(labels_of(v) == std::vector<std::string>{"exact", "double/bezier", "double/bezier-power", "double/sampling:16",
                                                 "double/marching:16", "mpfr:100/bezier"});
  CHECK(v[0].method == "projection");
  CHECK(find(v, "double/bezier-power").basis == "power");
  CHECK(find(v, "double/bezier-power").method == "bezier");
  CHECK(find(v, "double/sampling:16").method == "sampling:16");
  CHECK(find(v, "mpfr:100/bezier").bits == 100);
  o.mpfr_power_3d = true;
  v = harness_pipelines(3, o);
  CHECK(find(v, "mpfr:100/bezier-power").basis == "power");
  CHECK(v.size() == 7);
}

TEST_CASE("harness: in_faces marks the as-published label before '@' and drops duplicates", "[compare][harness]") {
  PipelineSpec p;
  p.label = "double/bernstein@prepared";
  const auto f = in_faces(p, {"none", "bound", "none"});
  REQUIRE(f.size() == 2);
  CHECK(f[0].label == "double/bernstein/published@prepared");
  CHECK(f[0].guard == "none");
  CHECK(f[1].label == "double/bernstein@prepared");
  CHECK(f[1].guard == "bound");
  p.label = "mpfr:64/power";
  CHECK(in_faces(p, {"none"})[0].label == std::string("mpfr:64/power") + kPublishedSuffix);
  CHECK(in_faces(p, {}).empty());
  CHECK_THROWS_AS(in_faces(p, {"bounded"}), std::invalid_argument);
  SolveOptions so;
  CHECK_NOTHROW(apply_input_mode(so, "rounded"));
  CHECK_NOTHROW(apply_input_mode(so, "prepared"));
  CHECK_THROWS_AS(apply_input_mode(so, ""), std::invalid_argument);
  const auto modes = default_input_modes();
  CHECK(modes.back() == "prepared");
  CHECK(modes.size() == (solver_has_input_modes() ? 2u : 1u));
}

TEST_CASE("harness: scene_info from a generator's note, scene_degree from the motions", "[compare][harness]") {
  GeneratorSpec sp;
  sp.dim = 2;
  sp.degree = 3;
  sp.family = "near-miss";
  sp.d_exponent = 8;
  sp.seed = 4242;
  const GeneratedScene g = generate_scene(sp);
  const Scene s = parse_scene(g.doc.dump(), g.name);
  const SceneInfo i = scene_info(s, "generated");
  CHECK(i.name == g.name);
  CHECK(i.source == "generated");
  CHECK(i.family == "near-miss");
  CHECK(i.motion == "kinematic");
  CHECK(i.degree == 3);
  CHECK(i.degree == scene_degree(s));  // the generator checks the degree it states
  CHECK(i.d_exponent == 8);
  REQUIRE(i.seed);
  CHECK(*i.seed == g.spec.seed);
  sp.family = "touch";  // no separation: d stays 0
  const GeneratedScene t = generate_scene(sp);
  CHECK(scene_info(parse_scene(t.doc.dump(), t.name), "generated").d_exponent == 0);

  // Cases: no generator note; the degree is read from the motions.
  const std::string still = R"({"type": "static"})";
  const std::string cubic = R"({"type": "matrix", "m": [["1", "0", ["0", "0", "0", "1"]], ["0", "1", "0"],
                                                         ["0", "0", "1"]]})";
  const Scene c2 = parse_scene(scene_doc(2, still, cubic), "c2");
  const SceneInfo ci = scene_info(c2, "cases");
  CHECK(ci.family == "case");
  CHECK(ci.motion == "case");
  CHECK(ci.source == "cases");
  CHECK_FALSE(ci.seed);
  CHECK(ci.degree == 3);
  CHECK(scene_degree(parse_scene(scene_doc(2, still, still), "c0")) == 0);
  // euler: M = [[v3 R', E v], [0, E v3]] with e of degree 1 (R', E: degree 2) and v of degree 2: E v has degree 4.
  const std::string euler = R"({"type": "euler", "e": [["1", "1"], "0", "0", "0"],
       "translation": [["0", "0", "1"], "0", "0"], "translation_denominator": "1"})";
  CHECK(scene_degree(parse_scene(scene_doc(3, euler, still), "c3")) == 4);
}

TEST_CASE("harness: run_bounded gives solve()'s answer in process and from a child", "[compare][harness]") {
  const Scene s = colliding_2d();
  SolveOptions opt;
  opt.arith = parse_arithmetic("double");
  const Solution direct = solve(s, opt);
  for (bool isolate : {false, true}) {
    INFO("isolate " << isolate);
    BoundedRun r = run_bounded(s, opt, 30, isolate);
    CHECK_FALSE(r.timed_out);
    CHECK_FALSE(r.killed);
    CHECK(r.error.empty());
    REQUIRE(r.got.has_value());
    CHECK(r.got->answer.collides == direct.answer.collides);
    CHECK(answer_difference(r.got->answer, direct.answer, DifferenceOptions{0.0, "a", "b"}).agrees);
    CHECK(r.cpu_s >= 0);
    CHECK(r.wall_s >= 0);
  }
  // No budget: the run is not bounded and not isolated, and still answers.
  BoundedRun free_run = run_bounded(s, opt, 0, true);
  REQUIRE(free_run.got.has_value());
  CHECK_FALSE(free_run.timed_out);
  // A pipeline that throws: error and reason are its message, no solution.
  const Scene cyc = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example1.json");
  SolveOptions exact;  // exact arithmetic cannot represent a cycloidal motion
  for (bool isolate : {false, true}) {
    BoundedRun e = run_bounded(cyc, exact, 30, isolate);
    CHECK_FALSE(e.got.has_value());
    CHECK_FALSE(e.timed_out);
    CHECK(e.error.find("cycloidal") != std::string::npos);
    CHECK(e.reason == e.error);
  }
}

TEST_CASE("harness: fill_row_from_run turns time-outs, errors and answers into rows", "[compare][harness]") {
  const Scene s = colliding_2d();
  const Solution exact = solve(s);
  REQUIRE(exact.answer.collides);
  PipelineSpec ps;
  ps.label = "double/power";
  ps.arith = "double";
  ps.bits = 53;
  ps.basis = "power";
  ps.method = "cd-disc";
  ps.guard = "bound";
  const SceneInfo info = scene_info(s, "generated");
  ResultRow row = pipeline_row(info, ps);
  CHECK(row.pipeline == "double/power");
  CHECK(row.scene.name == info.name);
  CHECK(row.guard == "bound");
  SECTION("a time-out: undecided, the wall time, the reason") {
    BoundedRun br;
    br.timed_out = true;
    br.wall_s = 0.25;
    br.reason = "time budget: test";
    fill_row_from_run(row, std::move(br), exact.answer);
    CHECK(row.m.outcome == "undecided");
    CHECK(row.time_us == 250000);
    CHECK(row.reason == "time budget: test");
    CHECK(row.m.exact_collides);
    CHECK_FALSE(row.second_look);  // no answer: nothing known of a second look
  }
  SECTION("an error: outcome error, the message") {
    BoundedRun br;
    br.error = br.reason = "boom";
    fill_row_from_run(row, std::move(br), exact.answer);
    CHECK(row.m.outcome == "error");
    CHECK(row.error == "boom");
    CHECK(row.reason == "boom");
  }
  SECTION("an answer: its outcome against the truth, its time and input") {
    BoundedRun br;
    br.got = exact;
    br.got->time_ms = 1.5;
    br.got->input = InputMode::rounded;
    fill_row_from_run(row, std::move(br), exact.answer);
    CHECK(row.m.outcome == "correct");
    CHECK(row.m.structure_ok);
    CHECK(row.time_us == 1500);
    CHECK(row.input == "rounded");
    REQUIRE(row.second_look);  // a guarded row whose answer has no second_look counter: the bound decided alone
    CHECK(*row.second_look == 0);
  }
  SECTION("a guarded answer that took a second look: the answer's counter, in the CSV line's last column") {
    BoundedRun br;
    br.got = exact;
    br.got->work = {{"second_look", 2}, {"second_look_units", 301603}};
    fill_row_from_run(row, std::move(br), exact.answer);
    REQUIRE(row.second_look);
    CHECK(*row.second_look == 2);
    const std::string line = results_csv_line(row);
    CHECK(line.substr(line.rfind(',')) == ",2");
    CHECK(results_csv_header().substr(results_csv_header().rfind(',')) == ",second_look");
  }
  SECTION("an as-published answer: no second look column") {
    row.guard = "none";
    BoundedRun br;
    br.got = exact;
    fill_row_from_run(row, std::move(br), exact.answer);
    CHECK_FALSE(row.second_look);
    const std::string line = results_csv_line(row);
    CHECK(line.back() == ',');
  }
  SECTION("an undecided answer: the pipeline's reasons, once each") {
    BoundedRun br;
    br.got = exact;
    br.got->answer.undecided.push_back(rounded_instant(0.5));
    br.got->undecided_reasons = {"sign unsure", "", "sign unsure", "root cluster"};
    fill_row_from_run(row, std::move(br), exact.answer);
    CHECK(row.m.outcome == "undecided");
    CHECK(row.reason == "sign unsure; root cluster");
  }
  SECTION("an undecided answer without reasons: where") {
    BoundedRun br;
    br.got = exact;
    br.got->answer.undecided.push_back(rounded_instant(0.5));
    fill_row_from_run(row, std::move(br), exact.answer);
    CHECK(row.reason == "undecided near t = 0.5");
  }
  SECTION("a wrong answer: false_negative") {
    BoundedRun br;
    br.got = exact;
    br.got->answer = Answer{};
    fill_row_from_run(row, std::move(br), exact.answer);
    CHECK(row.m.outcome == "false_negative");
    CHECK_FALSE(row.m.structure_ok);
  }
}

TEST_CASE("harness: run_scene adds the external engines' rows last, judged against the exact answer",
          "[compare][harness]") {
  const Scene s = colliding_2d();
  const SceneInfo info = scene_info(s, "generated");
  const fs::path dir = fs::temp_directory_path() / ("eccd-harness-ext-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  for (const char* e : {"right", "wrong", "broken", "absent"}) fs::create_directories(dir / e);
  const Answer exact = solve(s).answer;
  {
    nlohmann::json a = answer_to_json(exact);
    a["time_us"] = 42;
    std::ofstream(dir / "right" / (info.name + ".json")) << a.dump();
    std::ofstream(dir / "wrong" / (info.name + ".json"))
        << R"({"collides": false, "intervals": [], "first_contact": null, "contacts": []})";
    std::ofstream(dir / "broken" / (info.name + ".json")) << "{";
  }
  HarnessOptions o = light();
  for (const char* e : {"right", "wrong", "broken", "absent"}) o.externals.push_back({e, (dir / e).string()});
  const auto rows = run_scene(s, info, o);
  fs::remove_all(dir);
  // exact, double power / bernstein / scaled-bernstein (guarded face, prepared), then right, wrong, broken.
  REQUIRE(rows.size() == 7);
  CHECK(rows[0].pipeline == "exact");
  CHECK(rows[0].m.outcome == "correct");
  CHECK(rows[0].m.structure_ok);
  CHECK(rows[1].pipeline == "double/power");
  CHECK(rows[3].pipeline == "double/scaled-bernstein");
  for (std::size_t k = 4; k < 7; ++k) {
    CHECK(rows[k].arith == "external");
    CHECK(rows[k].basis == "none");
    CHECK(rows[k].guard.empty());
  }
  CHECK(rows[4].pipeline == "ext:right");
  CHECK(rows[4].m.outcome == "correct");
  CHECK(rows[4].m.structure_ok);
  CHECK(rows[4].time_us == 42);
  CHECK(rows[5].pipeline == "ext:wrong");
  CHECK(rows[5].m.outcome == "false_negative");
  CHECK(std::isnan(rows[5].time_us));  // not measured
  CHECK(rows[6].pipeline == "ext:broken");
  CHECK(rows[6].m.outcome == "error");
  CHECK_FALSE(rows[6].error.empty());
  CHECK(rows[6].reason == rows[6].error);
}

TEST_CASE("harness: results.csv rows have the header's columns, in order", "[compare][harness]") {
  const std::vector<std::string> header = csv_split(results_csv_header());
  CHECK(header.size() == 33);
  std::map<std::string, std::size_t> col;
  for (std::size_t k = 0; k < header.size(); ++k) col[header[k]] = k;
  CHECK(col.size() == header.size());  // no column twice
  ResultRow r;
  r.scene.name = "s, with comma";
  r.scene.source = "generated";
  r.scene.dim = 3;
  r.scene.degree = 4;
  r.scene.family = "near-miss";
  r.scene.motion = "euler";
  r.scene.d_exponent = 8;
  r.scene.seed = 99;
  r.scene.digits = 0;
  r.pipeline = "mpfr:128/bezier@prepared";
  r.arith = "mpfr";
  r.bits = 128;
  r.basis = "bernstein";
  r.method = "bezier";
  r.coef_err = 1.25e-30;
  r.m.outcome = "undecided";
  r.m.collides = std::nullopt;
  r.m.exact_collides = true;
  r.m.intervals = 0;
  r.m.exact_intervals = 1;
  r.time_us = 12.34;
  r.input = "prepared";
  r.reason = "line one\nline two \"quoted\", " + std::string(300, 'x');
  r.guard = "bound";
  const std::vector<std::string> f = csv_split(results_csv_line(r));
  REQUIRE(f.size() == header.size());
  CHECK(f[col["scene"]] == "s, with comma");
  CHECK(f[col["dim"]] == "3");
  CHECK(f[col["degree"]] == "4");
  CHECK(f[col["d"]] == "1e-8");
  CHECK(f[col["seed"]] == "99");
  CHECK(f[col["pipeline"]] == "mpfr:128/bezier@prepared");
  CHECK(f[col["bits"]] == "128");
  CHECK(f[col["coef_err"]] == "1.25e-30");
  CHECK(f[col["delta_err"]].empty());
  CHECK(f[col["outcome"]] == "undecided");
  CHECK(f[col["collides"]].empty());  // no claim
  CHECK(f[col["exact_collides"]] == "1");
  CHECK(f[col["exact_intervals"]] == "1");
  CHECK(f[col["time_us"]] == "12.3");
  CHECK(f[col["structure_ok"]] == "0");
  CHECK(f[col["digits"]].empty());
  CHECK(f[col["guard"]] == "bound");
  CHECK(f[col["exact_touch"]] == "0");
  CHECK(f[col["second_look"]].empty());  // not filled from a run
  const std::string& why = f[col["reason"]];
  CHECK(why.size() == 200);
  CHECK(why.find('\n') == std::string::npos);
  CHECK(why.rfind("line one line two \"quoted\", ", 0) == 0);
  CHECK(why.substr(197) == "...");
  // No ground truth: the exact columns stay empty.
  r.m.outcome = kNoGroundTruthOutcome;
  r.scene.family = "touch";
  const std::vector<std::string> n = csv_split(results_csv_line(r));
  CHECK(n[col["exact_collides"]].empty());
  CHECK(n[col["exact_intervals"]].empty());
  CHECK(n[col["exact_touch"]].empty());
  CHECK(n[col["d"]].empty());  // a touch has no separation
}

TEST_CASE("harness: fcl_skipped counts the scenes with an exact row and no fcl/ccd row", "[compare][harness]") {
  auto row = [](const std::string& scene, const std::string& pipeline) {
    ResultRow r;
    r.scene.name = scene;
    r.pipeline = pipeline;
    r.m.outcome = "correct";
    return results_csv_line(r);
  };
  const std::vector<std::string> rows = {row("a", "exact"),      row("a", "fcl/ccd:10"),   row("a", "fcl/ccd:100"),
                                         row("b", "exact"),      row("b", "fcl/ccd:100"),  row("c", "exact"),
                                         row("d", "fcl/ccd:10"), row("b", "fcl/sample:10")};
  const auto sk = fcl_skipped({"exact", "fcl/sample:10", "fcl/ccd:10", "fcl/ccd:100"}, rows);
  // Only fcl/ccd labels are counted; d has no exact row, so it does not count.
  REQUIRE(sk.size() == 2);
  CHECK(sk[0] == std::make_pair(std::string("fcl/ccd:10"), 2));   // b and c
  CHECK(sk[1] == std::make_pair(std::string("fcl/ccd:100"), 1));  // c
  CHECK(fcl_skipped({"fcl/ccd:10"}, {}).at(0).second == 0);
}

TEST_CASE("harness: coefficient errors only on prepared rows, and a run over its budget is undecided",
          "[compare][harness]") {
  const Scene s = colliding_2d();
  HarnessOptions o = light();
  o.inputs = {"rounded", "prepared"};
  const auto rows = run_scene(s, scene_info(s, "generated"), o);
  int prepared = 0, rounded = 0;
  for (const auto& r : rows) {
    if (r.arith != "double" && r.arith != "mpfr") continue;
    INFO(r.pipeline);
    if (r.input == "prepared") {
      ++prepared;
      CHECK(r.coef_err.has_value());
      CHECK(r.coef_err_common.has_value());
    } else {
      ++rounded;
      CHECK_FALSE(r.coef_err.has_value());
      CHECK_FALSE(r.coef_err_common.has_value());
    }
  }
  CHECK(prepared == 3);
  CHECK(rounded == (solver_has_input_modes() ? 3 : 0));
  // A budget of a microsecond of processor time: whether the deadline stops the run or the run returns after
  // it, no answer is used and the reason says so.
  SolveOptions opt;
  opt.arith = parse_arithmetic("mpfr:256");
  for (bool isolate : {false, true}) {
    BoundedRun br = run_bounded(s, opt, 1e-6, isolate);
    INFO(br.reason);
    CHECK(br.timed_out);
    CHECK(br.reason.rfind("time budget", 0) == 0);
    CHECK(br.error.empty());
    ResultRow row;
    fill_row_from_run(row, std::move(br), solve(s).answer);
    CHECK(row.m.outcome == "undecided");
  }
}

}  // namespace ECCD_UNITY_ID
