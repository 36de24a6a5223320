// `eccd regress` (app/regress.cpp) on small folders (cases/paper003/
// example2.json: a touch at t = 1/2, and edited copies), run as ECCD_EXE.
// What test_cli_reliability, test_cli_hostile and test_cli_certify check
// (no scene skipped silently, links, cases/ with --certify) is not repeated.
//  - agreeing scenes: exit 0, "ok" lines and the summary; --json
//    (eccd-regress/1) with per-scene results and counts;
//  - a stored answer with an end moved from 1/2 to 0.6: exit 1, FAIL with the
//    difference in words (stored 0.6, recomputed 0.5, off by 0.1); a scene
//    without a stored answer is skipped and said so; --json passed false;
//  - a folder without scenes: exit 2 with the reason;
//  - --floating (on a generated 2D colliding scene): one row per floating pipeline (each face, each input mode,
//    each --mpfr-bits), and a row with a counted difference (wrong collides,
//    missed, false, ends off, undecided, error) never agrees;
//  - --arith certified: every scene is decided somewhere (decided_in);
//  - --certify --keep-certificates: an index of the certificates written, each
//    of which `eccd check-certificate` accepts for its scene.
#include "cli_run.hpp"

#include <nlohmann/json.hpp>

#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {
// example2.json, under another name, its stored answer's first interval ending at `end` instead of 1/2 (or no
// stored answer when end is empty).
void edited_copy(const fs::path& to, const std::string& name, const std::string& end) {
  json d = json::parse(slurp(src("cases/paper003/example2.json")));
  d["name"] = name;
  if (end.empty())
    d.erase("answer");
  else
    d["answer"]["intervals"][0][1] = {{"approx", end}};
  spit(to, d.dump());
}
}  // namespace

TEST_CASE("eccd regress: agreeing, differing and answerless scenes, text and JSON", "[app][cli][cli-regress]") {
  TempDir d;
  fs::create_directories(d.path / "good");
  fs::copy_file(src("cases/paper003/example2.json"), d.path / "good" / "example2.json");
  Run ok = run_eccd("regress " + q((d.path / "good").string()), 120);
  INFO(ok.out << ok.err);
  CHECK(ok.code == 0);
  CHECK(ok.out.find("ok    example2.json  2D  collides, 1 interval(s), 1 contact(s)") != std::string::npos);
  CHECK(ok.out.find("1 scene(s) checked, 1 agree, 0 differ, 0 failed, 0 without a stored answer") != std::string::npos);
  Run okj = run_eccd("regress " + q((d.path / "good").string()) + " --json", 120);
  REQUIRE(okj.code == 0);
  const json j = json::parse(okj.out);
  CHECK(j["format"] == "eccd-regress/1");
  CHECK(j["passed"] == true);
  CHECK(j["agree"] == 1);
  CHECK(j["differ"] == 0);
  CHECK(j["arith"] == "exact");
  REQUIRE(j["scenes"].size() == 1);
  CHECK(j["scenes"][0]["result"] == "ok");
  CHECK(j["scenes"][0]["scene"] == "example2.json");

  fs::create_directories(d.path / "bad");
  edited_copy(d.path / "bad" / "edited.json", "edited", "0.6");
  edited_copy(d.path / "bad" / "bare.json", "bare", "");
  Run bad = run_eccd("regress " + q((d.path / "bad").string()), 120);
  INFO(bad.out << bad.err);
  CHECK(bad.code == 1);
  CHECK(bad.out.find("skip  bare.json: no stored answer") != std::string::npos);
  CHECK(bad.out.find("FAIL  edited.json") != std::string::npos);
  // Recomputed end 1/2 (a touch: [1/2, 1/2]), stored 0.6: off by 0.1.
  CHECK(bad.out.find("collision interval 1 end off by 0.1 (stored 0.6, recomputed 0.5)") != std::string::npos);
  CHECK(bad.out.find("1 differ") != std::string::npos);
  CHECK(bad.out.find("1 without a stored answer") != std::string::npos);
  Run badj = run_eccd("regress " + q((d.path / "bad").string()) + " --json", 120);
  CHECK(badj.code == 1);
  const json b = json::parse(badj.out);
  CHECK(b["passed"] == false);
  CHECK(b["differ"] == 1);
  CHECK(b["skipped"] == 1);
  for (const auto& s : b["scenes"]) {
    if (s["scene"] == "bare.json") {
      CHECK(s["result"] == "skipped");
      CHECK(s["reason"] == "no stored answer");
    } else {
      CHECK(s["result"] == "differs");
      REQUIRE(s["differences"].size() == 1);
      CHECK(s["differences"][0] == "collision interval 1 end off by 0.1 (stored 0.6, recomputed 0.5)");
    }
  }
  // A stored end within 1e-12 of the recomputed one agrees.
  fs::create_directories(d.path / "close");
  edited_copy(d.path / "close" / "close.json", "close", "0.5000000000001");
  CHECK(run_eccd("regress " + q((d.path / "close").string()), 120).code == 0);

  fs::create_directories(d.path / "empty");
  spit(d.path / "empty" / "notes.json", R"({"format": "something-else/1"})");
  Run none = run_eccd("regress " + q((d.path / "empty").string()), 60);
  CHECK(none.code == 2);
  CHECK(none.err.find("no scene found") != std::string::npos);
}

TEST_CASE("eccd regress --floating: a row per pipeline, never agreeing with a difference counted",
          "[app][cli][cli-regress]") {
  TempDir d;
  const std::string scene = "cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json";
  fs::copy_file(src(scene), d.path / "scene.json");
  Run r = run_eccd("regress " + q(d.str()) + " --floating --mpfr-bits 64 --json", 240);
  INFO(r.err);
  REQUIRE(r.code == 0);  // the floating table reports; the stored answers still agree
  const json j = json::parse(r.out);
  REQUIRE(j.contains("floating"));
  std::set<std::string> labels;
  for (const auto& p : j["floating"]["pipelines"]) {
    const std::string label = p["pipeline"];
    INFO(label);
    labels.insert(label);
    CHECK(p["scenes"] == 1);
    const int differences = p["wrong_collides"].get<int>() + p["missed"].get<int>() + p["false"].get<int>() +
                            p["endpoints_off"].get<int>() + p["undecided"].get<int>() + p["errors"].get<int>();
    // A counted difference means no agreement (a first contact off alone is a difference no counter shows).
    if (differences > 0) CHECK(p["agree"] == 0);
    CHECK(p["agree"].get<int>() + p["errors"].get<int>() <= 1);
  }
  // Every 2D floating pipeline: three double bases and two MPFR bases at 64 bits, each as published and guarded.
  for (const char* base :
       {"double/power", "double/bernstein", "double/scaled-bernstein", "mpfr:64/power", "mpfr:64/bernstein"}) {
    CHECK(labels.count(base) == 1);
    CHECK(labels.count(std::string(base) + "/published") == 1);
  }
  CHECK(labels.size() % 10 == 0);  // 10 per input mode
}

TEST_CASE("eccd regress --arith certified --certify --keep-certificates: decided and checkable",
          "[app][cli][cli-regress]") {
  TempDir d;
  fs::create_directories(d.path / "in" / "sub");
  fs::copy_file(src("cases/paper003/example2.json"), d.path / "in" / "example2.json");
  fs::copy_file(src("cases/touch3d/touch-and-separate.json"), d.path / "in" / "sub" / "t3.json");
  const fs::path kc = d.path / "certs";
  Run r = run_eccd("regress " + q((d.path / "in").string()) + " --arith certified --certify --keep-certificates " +
                       q(kc.string()) + " --json",
                   240);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const json j = json::parse(r.out);
  CHECK(j["arith"] == "certified");
  CHECK(j["agree"] == 2);
  int decided = 0;
  for (const auto& [where, n] : j["decided_in"].items()) decided += n.get<int>();
  CHECK(decided == 2);
  for (const auto& s : j["scenes"]) CHECK(s["certificate"]["valid"] == true);
  const json index = json::parse(slurp(kc / "index.json"));
  REQUIRE(index["certificates"].size() == 2);
  std::set<std::string> names;
  for (const auto& c : index["certificates"]) {
    const std::string cert = c["certificate"];
    names.insert(cert);
    INFO(cert);
    REQUIRE(fs::exists(kc / cert));
    Run chk = run_eccd("check-certificate " + q(c["scene"].get<std::string>()) + " " + q((kc / cert).string()), 120);
    CHECK(chk.code == 0);
  }
  CHECK(names == std::set<std::string>{"example2.cert.json", "sub__t3.cert.json"});  // path under DIR, '/' -> "__"
}

}  // namespace ECCD_UNITY_ID
