// The generators of the paper reproductions (cases/animations/make_repro.py,
// scripts/run-animation-report.sh; issue 17 point 5) at a tiny size, through
// `eccd animate`: the files are valid animations of the stated shape (000
// Table 1: 2 bodies, 1 pair; 000 Table 2: sphere and ellipsoid; 001 boxers:
// 48 bodies, 576 pairs "between-groups"), the stages add up, and the
// certified run gives exactly the events of the exact run (same pair-frames,
// same collides, same number of intervals) while double classifies no
// pair-frame differently. --no-planes settles nothing by planes and changes
// no event.
#include "tests/app/cli_run.hpp"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;

namespace {

using Key = std::tuple<int, std::string, std::string>;

json animate(const std::string& file, const std::string& arith, const std::string& extra = "") {
  Run r = run_eccd("animate " + q(file) + " --arith " + arith + " --json --quiet " + extra, 120);
  INFO(arith << " " << extra << ": " << r.err);
  REQUIRE(r.code == 0);
  return json::parse(r.out);
}

std::map<Key, json> events(const json& j) {
  std::map<Key, json> m;
  for (const auto& e : j["events"])
    m[{e["frame"].get<int>(), e["pair"][0].get<std::string>(), e["pair"][1].get<std::string>()}] = e["answer"];
  return m;
}

void generate(const TempDir& d, const std::string& args) {
  const std::string cmd = "python3 " + q(src("cases/animations/make_repro.py")) + " " + args + " >/dev/null";
  INFO(cmd);
  REQUIRE(std::system(cmd.c_str()) == 0);
  (void)d;
}

void check(const std::string& file, int frames, int pairs, bool no_planes_too) {
  const json ex = animate(file, "exact"), ce = animate(file, "certified"), db = animate(file, "double");
  for (const json* j : {&ex, &ce, &db}) {
    REQUIRE((*j)["format"] == "ellipse-ccd-animation-answer/1");
    REQUIRE((*j)["frames"] == frames);
    REQUIRE((*j)["pairs_per_frame"] == pairs);
    REQUIRE((*j)["per_frame"].size() == std::size_t(frames));
    const json& st = (*j)["stages"];
    REQUIRE(st["bounding_volumes"].get<int>() + st["separating_plane"].get<int>() + st["continuous_test"].get<int>() ==
            frames * pairs);
  }
  REQUIRE(ex["undecided"].empty());
  REQUIRE(ce["undecided"].empty());
  const auto e = events(ex), c = events(ce), d = events(db);
  REQUIRE(e.size() == c.size());
  for (const auto& [k, a] : e) {
    INFO("frame " << std::get<0>(k) << " " << std::get<1>(k) << " -- " << std::get<2>(k));
    REQUIRE(c.count(k) == 1);
    REQUIRE(c.at(k)["collides"] == a["collides"]);
    REQUIRE(c.at(k)["intervals"].size() == a["intervals"].size());
    REQUIRE(c.at(k)["first_contact"]["lo"].is_string());
  }
  // double: every decided pair-frame classified as exact does
  std::set<Key> und;
  for (const auto& u : db["undecided"])
    und.insert({u["frame"].get<int>(), u["pair"][0].get<std::string>(), u["pair"][1].get<std::string>()});
  for (const auto& [k, a] : d) REQUIRE(e.count(k) == 1);
  for (const auto& [k, a] : e) REQUIRE((d.count(k) == 1 || und.count(k) == 1));
  if (!no_planes_too) return;
  // without planes: no plane stage, the same events
  const json np = animate(file, "certified", "--no-planes");
  REQUIRE(np["separating_plane_stage"] == "off");
  REQUIRE(np["stages"]["separating_plane"] == 0);
  const auto n = events(np);
  REQUIRE(n.size() == c.size());
  for (const auto& [k, a] : c) REQUIRE(n.count(k) == 1);
}

}  // namespace

TEST_CASE("paper reproductions: the 000 Table 1 generator through eccd animate", "[app][cli][animation]") {
  TempDir d;
  const std::string f = d.str() + "/t1.json";
  generate(d, "table1 --rate 1 --frames 4 --seed 1 " + q(f));
  check(f, 4, 1, true);
  // the rate-1 set-up collides in some of its first frames (seed 1): an event exists to compare
  REQUIRE_FALSE(animate(f, "exact")["events"].empty());
}

TEST_CASE("paper reproductions: the 000 Table 2 generator through eccd animate", "[app][cli][animation]") {
  TempDir d;
  const std::string f = d.str() + "/t2.json";
  generate(d, "table2 --frames 6 --radius 5.49 --scenes " + q(d.str() + "/scenes") + " " + q(f));
  check(f, 6, 1, true);
  // at angle 0 the sphere (r = 1, centre 5.49 from the origin) reaches into the 4.5 end: every one of these frames
  // collides
  REQUIRE(animate(f, "exact")["events"].size() == 6);
  // the per-frame scenes for eccd fcl are the animation's pair-frames: eccd solve agrees on frame 0
  Run s = run_eccd("solve " + q(d.str() + "/scenes/frame-0.json") + " --arith exact --json", 60);
  INFO(s.err);
  REQUIRE(s.code == 0);
  REQUIRE(json::parse(s.out)["collides"] == true);
}

TEST_CASE("paper reproductions: the 001 boxers generator through eccd animate", "[app][cli][animation]") {
  TempDir d;
  const std::string f = d.str() + "/bx.json";
  generate(d, "boxers --frames 1 " + q(f));
  check(f, 1, 576, false);  // (--no-planes is checked on the two above: 3 s per certified boxers frame)
}

}  // namespace ECCD_UNITY_ID
