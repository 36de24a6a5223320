// The harness on the motion families (compare/harness_families.hpp): which
// scenes it takes, which pipelines it runs, and meta.json's count of scenes
// without ground truth. (The rows of whole runs are checked in
// tests/compare/test_motion_families.cpp.)
//  - motion_family_scene: a 2D scene with a cycloidal motion, or any scene
//    with "parameters": "independent"; not a rational shared-parameter scene;
//  - motion_family_pipelines: cycloidal: the certified ground truth first
//    (bits 0, basis none, method ladder), then double and each MPFR precision
//    labelled ARITH/cycloidal (basis pointwise, method cd-disc-cycloidal,
//    input rounded) in the guarded face only, whatever faces are asked for;
//    independent: exact first (balls-exact), then ARITH/independent (basis
//    bernstein, method bezier-independent, input prepared) in every face;
//  - no_ground_truth_meta: one entry per scene whose rows have outcome
//    no_ground_truth, with the reason of its first row; other rows ignored.
#include "compare/harness_families.hpp"

#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
Scene case_scene(const std::string& rel) { return read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/" + rel); }
}  // namespace

TEST_CASE("harness families: which scenes the motion families' harness takes", "[compare][harness-families]") {
  CHECK(motion_family_scene(case_scene("paper003/example1.json")));          // cycloidal
  CHECK(motion_family_scene(case_scene("independent/spheres-cross.json")));  // 3D independent
  CHECK(motion_family_scene(case_scene("independent/discs-end.json")));      // 2D independent
  CHECK_FALSE(motion_family_scene(case_scene("paper003/example2.json")));    // rational, shared
  CHECK_FALSE(motion_family_scene(case_scene("touch3d/touch-and-separate.json")));
}

TEST_CASE("harness families: cycloidal pipelines, the certified ground truth first, guarded face only",
          "[compare][harness-families]") {
  HarnessOptions o;
  o.mpfr_bits = {64, 256};
  o.guards = {"none", "bound"};
  const auto v = motion_family_pipelines(case_scene("paper003/example1.json"), o);
  REQUIRE(v.size() == 4);
  CHECK(v[0].label == "certified");
  CHECK(v[0].arith == "certified");
  CHECK(v[0].bits == 0);
  CHECK(v[0].basis == "none");
  CHECK(v[0].method == "ladder");
  CHECK(v[0].guard.empty());
  const std::vector<std::pair<std::string, int>> want = {
      {"double/cycloidal", 53}, {"mpfr:64/cycloidal", 64}, {"mpfr:256/cycloidal", 256}};
  for (std::size_t k = 0; k < want.size(); ++k) {
    const PipelineSpec& p = v[k + 1];
    INFO(p.label);
    CHECK(p.label == want[k].first);
    CHECK(p.bits == want[k].second);
    CHECK(p.arith == (k == 0 ? "double" : "mpfr"));
    CHECK(p.guard == "bound");
    CHECK(p.opt.guard == Guard::bound);
    CHECK(p.basis == "pointwise");
    CHECK(p.method == "cd-disc-cycloidal");
    CHECK(p.input == "rounded");
  }
  // The as-published face alone still gives the guarded rows (the only ones cycloidal pipelines have).
  o.guards = {"none"};
  const auto g = motion_family_pipelines(case_scene("paper003/example1.json"), o);
  REQUIRE(g.size() == 4);
  CHECK(g[1].guard == "bound");
}

TEST_CASE("harness families: independent pipelines, exact first, every face", "[compare][harness-families]") {
  HarnessOptions o;
  o.mpfr_bits = {128};
  o.guards = {"none", "bound"};
  const auto v = motion_family_pipelines(case_scene("independent/spheres-cross.json"), o);
  REQUIRE(v.size() == 5);
  CHECK(v[0].label == "exact");
  CHECK(v[0].arith == "exact");
  CHECK(v[0].method == "balls-exact");
  CHECK(v[0].bits == 0);
  CHECK(v[0].guard.empty());
  const std::vector<std::string> labels = {"double/independent/published", "double/independent",
                                           "mpfr:128/independent/published", "mpfr:128/independent"};
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const PipelineSpec& p = v[k + 1];
    INFO(p.label);
    CHECK(p.label == labels[k]);
    CHECK(p.guard == (k % 2 ? "bound" : "none"));
    CHECK(p.basis == "bernstein");
    CHECK(p.method == "bezier-independent");
    CHECK(p.input == "prepared");
    CHECK(p.bits == (k < 2 ? 53 : 128));
  }
  o.guards = {"bound"};
  o.mpfr_bits = {};
  CHECK(motion_family_pipelines(case_scene("independent/discs-end.json"), o).size() == 2);
}

TEST_CASE("harness families: meta.json counts the scenes without ground truth once each",
          "[compare][harness-families]") {
  auto row = [](const std::string& scene, const std::string& pipeline, const std::string& outcome,
                const std::string& reason) {
    ResultRow r;
    r.scene.name = scene;
    r.pipeline = pipeline;
    r.m.outcome = outcome;
    r.reason = reason;
    return results_csv_line(r);
  };
  const std::string why = std::string(kNoGroundTruthReason) + "exact refuses the scene: ellipsoids, for now";
  const std::vector<std::string> rows = {
      row("a", "exact", "correct", ""),
      row("b", "exact", kNoGroundTruthOutcome, why),
      row("b", "double/independent", kNoGroundTruthOutcome, why + "; the run: undecided"),
      row("c", "certified", "correct", "ground truth: ..."),
      row("d", "certified", kNoGroundTruthOutcome, "no ground truth: 2 instant(s) undecided"),
  };
  const nlohmann::json m = no_ground_truth_meta(rows);
  CHECK(m["scenes"] == 2);
  REQUIRE(m["list"].size() == 2);
  CHECK(m["list"][0]["scene"] == "b");
  CHECK(m["list"][0]["reason"] == why);  // the first row's reason (commas kept through the CSV)
  CHECK(m["list"][1]["scene"] == "d");
  CHECK(m["list"][1]["reason"] == "no ground truth: 2 instant(s) undecided");
  const nlohmann::json none = no_ground_truth_meta({row("a", "exact", "correct", "")});
  CHECK(none["scenes"] == 0);
  CHECK(none["list"].is_array());
  CHECK(none["list"].empty());
  CHECK(no_ground_truth_meta({})["scenes"] == 0);
}

}  // namespace ECCD_UNITY_ID
