// `eccd report --external NAME=DIR` (issue 19, point 2): a user's engine gets
// rows "ext:NAME" judged against the exact answer like eccd's own pipelines.
// The engine here is played by files: the exact answer itself (must come out
// correct), a hand-edited wrong one (must come out as the wrong `collides`),
// an unreadable one (an error row naming the file), and a scene without a file
// (no row; meta.json counts it missing). Bad specs exit 2 and write nothing.
#include "compare/csv.hpp"
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
namespace fs = std::filesystem;

namespace {

// results.csv as one map per row, keyed by column name.
std::vector<std::map<std::string, std::string>> read_results(const fs::path& p) {
  auto recs = eccd::csv_records(slurp(p), p.string());
  REQUIRE(!recs.empty());
  std::vector<std::map<std::string, std::string>> rows;
  for (std::size_t i = 1; i < recs.size(); ++i) {
    std::map<std::string, std::string> r;
    for (std::size_t k = 0; k < recs[0].fields.size(); ++k) r[recs[0].fields[k]] = recs[i].fields.at(k);
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST_CASE("eccd report --external judges an engine's answer files against the exact answers",
          "[app][cli][report][external]") {
  TempDir t;
  const fs::path scenes = t.path / "scenes", answers = t.path / "answers", out = t.path / "out";
  Run g = run_eccd("generate --out-dir " + q(scenes.string()) +
                   " --dims 2 --degrees 2 --families colliding,free,near-miss "
                   "--separations 3 --count 2 --seed 41 --json");
  REQUIRE(g.code == 0);
  std::vector<std::string> names;
  const nlohmann::json generated = nlohmann::json::parse(g.out);
  for (const auto& f : generated["files"]) names.push_back(fs::path(f.get<std::string>()).stem().string());
  REQUIRE(names.size() >= 4);
  fs::create_directories(answers);

  // names[0]: the exact answer, as `eccd solve --json` prints it (with its time_ms).
  Run s0 = run_eccd("solve " + q((scenes / (names[0] + ".json")).string()) + " --arith exact --json");
  REQUIRE(s0.code == 0);
  spit(answers / (names[0] + ".json"), s0.out);
  // names[1]: the exact answer with `collides` turned round, as a bare answer object.
  Run s1 = run_eccd("solve " + q((scenes / (names[1] + ".json")).string()) + " --arith exact --json");
  REQUIRE(s1.code == 0);
  const bool collides1 = nlohmann::json::parse(s1.out)["collides"].get<bool>();
  nlohmann::json wrong =
      collides1 ? nlohmann::json{{"collides", false},
                                 {"intervals", nlohmann::json::array()},
                                 {"first_contact", nullptr},
                                 {"contacts", nlohmann::json::array()}}
                : nlohmann::json::parse(R"({"collides": true, "intervals": [[{"approx": "0.25"}, {"approx": "0.5"}]],
                                  "first_contact": {"approx": "0.25"}, "contacts": []})");
  wrong["time_us"] = 12.5;
  spit(answers / (names[1] + ".json"), wrong.dump());
  // names[2]: a file that is not an answer.
  spit(answers / (names[2] + ".json"), R"({"collides": "maybe"})");
  // names[3..]: no file.

  Run r = run_eccd("report --scenes " + q(scenes.string()) +
                       " --cases '' --no-map --mpfr-bits 64 --input rounded --budget 2 "
                       "--external " +
                       q("mine=" + answers.string()) + " --out " + q(out.string()),
                   300);
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::map<std::string, std::map<std::string, std::string>> ext;  // scene -> row of ext:mine
  for (const auto& row : read_results(out / "results.csv"))
    if (row.at("pipeline") == "ext:mine") ext[row.at("scene")] = row;
  REQUIRE(ext.size() == 3);
  for (const auto& [scene, row] : ext) {
    CHECK(row.at("arith") == "external");
    CHECK(row.at("basis") == "none");
  }
  CHECK(ext[names[0]].at("outcome") == "correct");
  CHECK(ext[names[0]].at("structure_ok") == "1");
  CHECK(ext[names[1]].at("outcome") == (collides1 ? "false_negative" : "false_positive"));
  CHECK(ext[names[1]].at("time_us") == "12.5");
  CHECK(ext[names[2]].at("outcome") == "error");
  CHECK(ext[names[2]].at("reason").find(names[2] + ".json") != std::string::npos);  // names the file
  CHECK(ext[names[2]].at("reason").find("collides") != std::string::npos);          // and the place

  nlohmann::json meta = nlohmann::json::parse(slurp(out / "meta.json"));
  REQUIRE(meta["externals"].size() == 1);
  CHECK(meta["externals"][0]["name"] == "mine");
  CHECK(meta["externals"][0]["answers"] == 3);
  CHECK(meta["externals"][0]["missing"] == names.size() - 3);
  // The engine has its rows in the written report too.
  CHECK(slurp(out / "report.md").find("ext:mine") != std::string::npos);
}

TEST_CASE("eccd report --external: a bad NAME=DIR is exit 2 before any work", "[app][cli][report][external]") {
  TempDir t;
  const fs::path out = t.path / "out";
  for (const std::string& spec : std::vector<std::string>{
           "mine", "=" + t.path.string(), "mine=" + (t.path / "none").string(), "a b=" + t.path.string()}) {
    INFO(spec);
    Run r = run_eccd("report --dims 2 --degrees 2 --families free --count 1 --cases '' --no-map --external " + q(spec) +
                     " --out " + q(out.string()));
    CHECK(r.code == 2);
    CHECK(r.err.find("--external") != std::string::npos);
    CHECK(!fs::exists(out));
  }
  Run twice =
      run_eccd("report --dims 2 --degrees 2 --families free --count 1 --cases '' --no-map --external " +
               q("x=" + t.path.string()) + " --external " + q("x=" + t.path.string()) + " --out " + q(out.string()));
  CHECK(twice.code == 2);
  CHECK(twice.err.find("given twice") != std::string::npos);
  CHECK(!fs::exists(out));
}

}  // namespace ECCD_UNITY_ID
