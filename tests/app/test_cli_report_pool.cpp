// The failure map of `eccd report` (app/report_pool.cpp: its scene and cells,
// run by the worker pool), on a report of the map alone (--count 0 --cases
// '', --map-size 3). Kettner et al. 2004's picture: a 2D touch-and-separate
// scene of degree 2 whose two translation inputs (the constant coefficients of
// B's m[0][2] and m[1][2]) are moved by ix - n/2 and iy - n/2 units in the last
// place of their nearest doubles.
//  - failure_map.csv: its header, n² cells for each of the five pipelines of
//    meta.json's failure_map, dx_ulps = ix - n/2 and dy_ulps = iy - n/2, an
//    answer class of {separate, touching, colliding, undecided, error};
//  - the exact column is the same for every pipeline at a cell, and is what
//    an independent exact solve (`eccd solve --json`) of the cell's scene says
//    (the centre row and column),
//    the scene built here from scenes/NAME.json with std::nextafter steps from
//    the nearest double (Python's float(Fraction) rounding, done with MPFR);
//  - meta.json: the map's size, scene, pipelines and row count; no scene rows.
#include "cli_run.hpp"

#include "compare/csv.hpp"

#include <gmpxx.h>
#include <mpfr.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {
double nearest(const std::string& rational) {
  mpq_class q(rational);
  q.canonicalize();
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDN);
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return d;
}
double step(double x, int ulps) {
  for (; ulps > 0; --ulps) x = std::nextafter(x, HUGE_VAL);
  for (; ulps < 0; ++ulps) x = std::nextafter(x, -HUGE_VAL);
  return x;
}
std::string exact_text(double x) {  // the double as an exact rational
  mpq_class q(x);
  return q.get_str();
}
// separate / touching / colliding from a solve --json answer.
std::string kind_of(const json& a) {
  if (!a["undecided"].empty()) return "undecided";
  if (a["collides"] != true) return "separate";
  for (const auto& iv : a["intervals"])
    if (iv[0]["approx"] != iv[1]["approx"]) return "colliding";
  return "touching";
}
}  // namespace

TEST_CASE("eccd report: the failure map's cells, and its exact column by independent solves",
          "[app][cli][cli-report-pool]") {
  TempDir d;
  const fs::path out = d.path / "FM";
  Run r =
      run_eccd("report --out-dir " + q(out.string()) + " --count 0 --cases '' --map-size 3 --no-figures --jobs 2", 300);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const json meta = json::parse(slurp(out / "meta.json"));
  const json& fm = meta["failure_map"];
  REQUIRE(fm.is_object());
  CHECK(fm["n"] == 3);
  REQUIRE(fm["pipelines"].size() == 5);
  CHECK(meta["map_rows"] == 45);
  CHECK(meta["scene_count"] == 0);
  CHECK(meta["result_rows"] == 0);

  std::istringstream csv(slurp(out / "failure_map.csv"));
  std::string line;
  REQUIRE(std::getline(csv, line));
  CHECK(line == "pipeline,ix,iy,dx_ulps,dy_ulps,answer,exact");
  std::map<std::pair<int, int>, std::string> exact;
  std::map<std::string, int> per_pipeline;
  int rows = 0;
  const std::set<std::string> classes = {"separate", "touching", "colliding", "undecided", "error"};
  while (std::getline(csv, line)) {
    const auto f = eccd::csv_split(line);
    REQUIRE(f.size() == 7);
    ++rows;
    ++per_pipeline[f[0]];
    const int ix = std::stoi(f[1]), iy = std::stoi(f[2]);
    CHECK((ix >= 0 && ix < 3 && iy >= 0 && iy < 3));
    CHECK(std::stoi(f[3]) == ix - 1);
    CHECK(std::stoi(f[4]) == iy - 1);
    CHECK(classes.count(f[5]) == 1);
    const auto [it, fresh] = exact.emplace(std::make_pair(ix, iy), f[6]);
    if (!fresh) CHECK(it->second == f[6]);  // one exact answer per cell
  }
  CHECK(rows == 45);
  for (const auto& p : fm["pipelines"]) CHECK(per_pipeline[p.get<std::string>()] == 9);
  REQUIRE(exact.size() == 9);

  // Each cell's scene, built here, solved exactly by `eccd solve`.
  const json base = json::parse(slurp(out / "scenes" / (fm["scene"].get<std::string>() + ".json")));
  const double x0 = nearest(base["b"]["motion"]["m"][0][2][0].get<std::string>());
  const double y0 = nearest(base["b"]["motion"]["m"][1][2][0].get<std::string>());
  std::set<std::string> seen;
  for (const auto& [cell, want] : exact) {
    if (cell.first != 1 && cell.second != 1) continue;  // the centre row and column: 5 of the 9 cells
    json s = base;
    s["b"]["motion"]["m"][0][2][0] = exact_text(step(x0, cell.first - 1));
    s["b"]["motion"]["m"][1][2][0] = exact_text(step(y0, cell.second - 1));
    s["name"] = "cell";
    spit(d.path / "cell.json", s.dump());
    Run sv = run_eccd("solve " + q((d.path / "cell.json").string()) + " --json", 120);
    REQUIRE(sv.code == 0);
    INFO("cell " << cell.first << "," << cell.second);
    CHECK(kind_of(json::parse(sv.out)) == want);
    seen.insert(want);
  }
  CHECK(seen.size() >= 2);  // the map crosses the touch: more than one class
}

}  // namespace ECCD_UNITY_ID
