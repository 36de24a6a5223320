// `eccd table` (app/table.cpp, docs/cli/table.md) on a folder of three files:
// a generated 2D colliding scene, 3D spheres crossing (cases/spheres) and a
// file that claims the scene format but lacks a required key. What
// test_cli_conventions and test_progress check (the comma list of
// --mpfr-bits, rows printed as scenes finish) is not repeated.
//  - --json: one eccd-table-row/1 line per file in file order, with folder
//    and file; the exact column is `eccd solve FILE --json`'s solution (the
//    same collides and interval brackets, from a separate run); a floating
//    column per basis and precision in each face (labels .../published for
//    the as-published face); the 3D scaled-Bernstein column is an
//    {"error"} saying why; an unreadable scene has "error" at the top level;
//  - --guard none / bound: only that face's columns;
//  - the text table: a header of the column labels, one row per file (the
//    bad one says "bad scene" and why), the legend; exit 0;
//  - a folder that does not exist: exit 2.
#include "cli_run.hpp"

#include <nlohmann/json.hpp>

#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {
std::vector<json> lines_of(const std::string& out) {
  std::vector<json> v;
  std::istringstream in(out);
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) v.push_back(json::parse(l));
  return v;
}
void folder(const TempDir& d) {
  fs::copy_file(src("cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json"), d.path / "a.json");
  fs::copy_file(src("cases/spheres/spheres-crossing.json"), d.path / "b.json");
  spit(d.path / "c.json", R"({"format": "ellipse-ccd-scene/1", "dim": 2})");
}
std::set<std::string> columns(const json& row) {
  std::set<std::string> c;
  for (const auto& [k, v] : row.items())
    if (v.is_object()) c.insert(k);
  return c;
}
}  // namespace

TEST_CASE("eccd table --json: a line per file, the exact column is solve's, every face and basis",
          "[app][cli][cli-table]") {
  TempDir d;
  folder(d);
  Run r = run_eccd("table " + q(d.str()) + " --mpfr-bits 64 --json", 240);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto rows = lines_of(r.out);
  REQUIRE(rows.size() == 3);
  const char* files[] = {"a.json", "b.json", "c.json"};
  for (int k = 0; k < 3; ++k) {
    CHECK(rows[k]["format"] == "eccd-table-row/1");
    CHECK(rows[k]["folder"] == d.str());
    CHECK(rows[k]["file"] == (d.path / files[k]).string());
  }
  const std::set<std::string> want = {"exact",
                                      "double/power",
                                      "double/power/published",
                                      "double/bernstein",
                                      "double/bernstein/published",
                                      "double/scaled",
                                      "double/scaled/published",
                                      "mpfr:64",
                                      "mpfr:64/published"};
  for (int k = 0; k < 2; ++k) {
    INFO(files[k]);
    CHECK(columns(rows[k]) == want);
    Run s = run_eccd("solve " + q((d.path / files[k]).string()) + " --json", 120);
    REQUIRE(s.code == 0);
    const json solo = json::parse(s.out);
    const json& ex = rows[k]["exact"];
    CHECK(ex["format"] == "eccd-solution/1");
    CHECK(ex["collides"] == solo["collides"]);
    CHECK(ex["intervals"] == solo["intervals"]);  // the same certified brackets
    CHECK(ex["contacts"] == solo["contacts"]);
    CHECK(ex["collides"] == true);
    // These clear crossings: every floating column that answers says collides, one interval.
    for (const auto& c : want) {
      const json& col = rows[k][c];
      if (col.contains("error")) continue;
      INFO(c);
      CHECK(col["collides"] == true);
      CHECK(col["intervals"].size() == 1);
    }
  }
  CHECK_FALSE(rows[0]["double/scaled"].contains("error"));  // 2D: a discriminant construction
  REQUIRE(rows[1]["double/scaled"].contains("error"));      // 3D: none
  CHECK(rows[1]["double/scaled"]["error"].get<std::string>().find("scaled-bernstein") != std::string::npos);
  REQUIRE(rows[2].contains("error"));
  CHECK(rows[2]["error"].get<std::string>().find("missing required key \"name\"") != std::string::npos);
  CHECK(columns(rows[2]).empty());
}

TEST_CASE("eccd table: one face at a time, the text table, and a missing folder", "[app][cli][cli-table]") {
  TempDir d;
  folder(d);
  for (const char* face : {"none", "bound"}) {
    INFO(face);
    Run r = run_eccd("table " + q(d.str()) + " --mpfr-bits 64 --guard " + face + " --json", 240);
    REQUIRE(r.code == 0);
    const auto rows = lines_of(r.out);
    REQUIRE(rows.size() == 3);
    for (const auto& c : columns(rows[0])) {
      if (c == "exact") continue;
      INFO(c);
      CHECK((c.find("/published") != std::string::npos) == (std::string(face) == "none"));
    }
    CHECK(columns(rows[0]).size() == 5);  // exact and 4 floating columns
  }
  Run t = run_eccd("table " + q(d.str()) + " --mpfr-bits 64", 240);
  REQUIRE(t.code == 0);
  std::istringstream in(t.out);
  std::string header;
  std::getline(in, header);
  for (const char* label : {"scene", "exact", "double/power/published", "double/scaled", "mpfr:64/published"})
    CHECK(header.find(label) != std::string::npos);
  CHECK(t.out.find("\na.json ") != std::string::npos);
  CHECK(t.out.find("\nb.json ") != std::string::npos);
  CHECK(t.out.find("\nc.json  bad scene: ") != std::string::npos);
  CHECK(t.out.find("'!' marks a floating answer that differs from the exact one") != std::string::npos);
  Run none = run_eccd("table " + q((d.path / "missing").string()), 30);
  CHECK(none.code == 2);
  CHECK(none.err.find("not a directory") != std::string::npos);
}

}  // namespace ECCD_UNITY_ID
