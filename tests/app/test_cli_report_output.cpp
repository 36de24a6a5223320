// The output folder of `eccd report` (app/report_output.cpp, with the worker
// pool of app/report_pool.cpp), on the cheapest run that has every part: three
// 2D scenes given by --scenes (a generated colliding and a generated free one
// of degree 2, and cases/paper003/example2-away-1e-3.json, 003 Example 2
// moved 1e-3 apart), no failure map, no figures, one face, one input mode,
// two workers. (test_cli_report checks shards, --merge, --resume and SIGINT;
// test_cli_reliability the folder replacement rules.)
//  - results.csv: the harness's header (compare/harness.hpp), every row with
//    one field per column; the scenes in the plan's order whatever their file
//    names and whichever worker ran them (colliding, free, then cases), each
//    scene's rows in the harness's pipeline order, exact first;
//  - the exact rows say what the scenes are by construction: colliding
//    collides, free and the moved-apart example do not;
//  - meta.json (eccd-report-meta/1): counts, options and pipelines as run,
//    no failure map, why FCL did not run;
//  - scenes/index.json links every scene to its file, relative to the report;
//  - the folder carries report's marker.
#include "cli_run.hpp"

#include "compare/csv.hpp"
#include "compare/harness.hpp"

#include <nlohmann/json.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;
namespace fs = std::filesystem;

TEST_CASE("eccd report: results.csv, meta.json and the scene index of a three-scene run",
          "[app][cli][cli-report-output]") {
  TempDir d;
  const fs::path in = d.path / "S";
  fs::create_directories(in);
  // File names in the reverse of the plan's order.
  fs::copy_file(src("cases/paper003/example2-away-1e-3.json"), in / "a-case.json");
  fs::copy_file(src("cases/generated/2d/2d-deg2-free-kinematic-2054184850131159.json"), in / "m-free.json");
  fs::copy_file(src("cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json"), in / "z-coll.json");
  const fs::path out = d.path / "R";
  Run r = run_eccd("report --out-dir " + q(out.string()) + " --scenes " + q(in.string()) +
                       " --cases '' --no-map --no-figures --mpfr-bits 64 --input prepared --guard bound --no-fcl "
                       "--no-certified --jobs 2",
                   300);
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_FALSE(fs::exists(d.path / "R.partial"));
  CHECK(slurp(out / ".eccd-report").rfind("written by eccd report", 0) == 0);

  // The pipelines as the harness lists them for these options.
  eccd::HarnessOptions h;
  h.mpfr_bits = {64};
  h.inputs = {"prepared"};
  h.guards = {"bound"};
  h.certified = false;
  h.fcl = false;
  std::vector<std::string> labels;
  for (const auto& p : eccd::harness_pipelines(2, h)) labels.push_back(p.label);
  REQUIRE(labels.size() == 6);

  std::istringstream csv(slurp(out / "results.csv"));
  std::string line;
  REQUIRE(std::getline(csv, line));
  CHECK(line == eccd::results_csv_header());
  const auto header = eccd::csv_split(line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) rows.push_back(eccd::csv_split(line));
  REQUIRE(rows.size() == 18);
  const std::vector<std::pair<std::string, std::string>> scenes = {
      {"2d-deg2-colliding-kinematic-4575131933740715", "1"},
      {"2d-deg2-free-kinematic-2054184850131159", "0"},
      {"example2-away-1e-3", "0"}};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& f = rows[k];
    INFO("row " << k);
    REQUIRE(f.size() == header.size());
    CHECK(f[0] == scenes[k / 6].first);
    CHECK(f[8] == labels[k % 6]);  // pipeline
    CHECK(f[2] == "2");
    CHECK(f[30] == (k % 6 == 0 ? "" : "bound"));  // guard
    if (k % 6 == 0) {
      CHECK(f[15] == "correct");  // the exact row is the ground truth
      CHECK(f[17] == scenes[k / 6].second);
    }
  }
  CHECK(rows[0][4] == "colliding");
  CHECK(rows[6][4] == "free");
  CHECK(rows[12][4] == "case");

  const json meta = json::parse(slurp(out / "meta.json"));
  CHECK(meta["format"] == "eccd-report-meta/1");
  CHECK(meta["scene_count"] == 3);
  CHECK(meta["result_rows"] == 18);
  CHECK(meta["mpfr_bits"] == json::array({64}));
  CHECK(meta["guards"] == json::array({"bound"}));
  CHECK(meta["inputs"] == json::array({"prepared"}));
  CHECK(meta["failure_map"].is_null());
  CHECK(meta["map_rows"] == 0);
  CHECK(meta["shards"] == 1);
  CHECK(meta["failed"].empty());
  CHECK(meta["no_ground_truth"]["scenes"] == 0);
  CHECK(meta["fcl"]["reason"].get<std::string>().find("--no-fcl") != std::string::npos);
  REQUIRE(meta["pipelines"].size() >= 6);
  for (std::size_t k = 0; k < 6; ++k) CHECK(meta["pipelines"][k] == labels[k]);

  const json index = json::parse(slurp(out / "scenes" / "index.json"));
  CHECK(index["format"] == "eccd-report-scenes/1");
  REQUIRE(index["scenes"].size() == 3);
  const std::map<std::string, std::string> file_of = {
      {scenes[0].first, "z-coll.json"}, {scenes[1].first, "m-free.json"}, {scenes[2].first, "a-case.json"}};
  for (const auto& [name, rel] : index["scenes"].items()) {
    INFO(name);
    REQUIRE(file_of.count(name) == 1);
    const fs::path target = (out / rel.get<std::string>()).lexically_normal();
    CHECK(target == (in / file_of.at(name)).lexically_normal());
    CHECK(fs::is_regular_file(target));
  }
}

}  // namespace ECCD_UNITY_ID
