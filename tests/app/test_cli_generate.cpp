// `eccd generate` (app/generate.cpp), run as ECCD_EXE on tiny plans. What
// test_cli_report (same seed, same files; no overwrite without --force;
// --degrees 9) and test_cli_generate_answer (--answer) check is not repeated.
//  - the plan's combinations: 3D touch at degree 2 in both motions (euler,
//    affine), near-miss in euler only (affine motions do not keep distances),
//    --count scenes per combination with distinct seeds; overlap is always of
//    degree 1; the --json listing (eccd-generate/1) names exactly the files
//    written;
//  - the scenes are what their family promises, by the exact pipeline
//    (`eccd solve --json`): touch collides at one instant, near-miss and free
//    never collide;
//  - decimal: every number of the scene is a decimal of at most --digits
//    significant digits;
//  - refusals: no --out-dir, touch at degree 1 (exit 2, nothing written; with
//    --json an eccd-error/1 object); --force rewrites the same files.
#include "cli_run.hpp"

#include <nlohmann/json.hpp>

#include <regex>
#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {
std::vector<std::string> files_of(const Run& r) {
  std::vector<std::string> v;
  const json j = json::parse(r.out);
  CHECK(j["format"] == "eccd-generate/1");
  for (const auto& f : j["files"]) v.push_back(f.get<std::string>());
  return v;
}
// Every string value under the shapes and motions of a scene.
void numbers(const json& j, std::vector<std::string>& out) {
  if (j.is_string()) out.push_back(j.get<std::string>());
  if (j.is_structured())
    for (const auto& x : j) numbers(x, out);
}
}  // namespace

TEST_CASE("eccd generate: the plan's combinations, each scene as its family promises", "[app][cli][cli-generate]") {
  TempDir d;
  const fs::path out = d.path / "g";
  Run r = run_eccd("generate --out-dir " + q(out.string()) +
                       " --dims 3 --degrees 2 --families touch,near-miss,free --separations 4 --count 2 --seed 77 "
                       "--json",
                   120);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto files = files_of(r);
  // touch: euler, affine; near-miss: euler; free: euler, affine; 2 of each.
  CHECK(files.size() == 10);
  std::set<std::string> on_disk;
  for (const auto& e : fs::directory_iterator(out)) on_disk.insert(e.path().string());
  CHECK(on_disk == std::set<std::string>(files.begin(), files.end()));
  std::map<std::string, int> per_kind;
  for (const auto& f : files) {
    const std::string name = fs::path(f).filename().string();
    INFO(name);
    const std::string family = name.find("-touch-") != std::string::npos            ? "touch"
                               : name.find("-near-miss-1e-4-") != std::string::npos ? "near-miss"
                               : name.find("-free-") != std::string::npos           ? "free"
                                                                                    : "?";
    const std::string motion = name.find("-euler-") != std::string::npos ? "euler" : "affine";
    ++per_kind[family + "/" + motion];
    CHECK(name.rfind("3d-deg2-", 0) == 0);
    Run s = run_eccd("solve " + q(f) + " --json", 120);
    REQUIRE(s.code == 0);
    const json a = json::parse(s.out);
    if (family == "touch") {
      CHECK(a["collides"] == true);
      REQUIRE(a["intervals"].size() == 1);
      CHECK(a["intervals"][0][0]["lo"] == a["intervals"][0][1]["lo"]);  // a single instant
      CHECK(a["contacts"].size() == 1);
    } else {
      CHECK(a["collides"] == false);
      CHECK(a["intervals"].empty());
    }
  }
  CHECK(per_kind ==
        std::map<std::string, int>{
            {"touch/euler", 2}, {"touch/affine", 2}, {"near-miss/euler", 2}, {"free/euler", 2}, {"free/affine", 2}});
  // --force rewrites the very same files.
  std::map<std::string, std::string> before;
  for (const auto& f : files) before[f] = slurp(f);
  Run again = run_eccd("generate --out-dir " + q(out.string()) +
                           " --dims 3 --degrees 2 --families touch,near-miss,free --separations 4 --count 2 --seed 77 "
                           "--force",
                       120);
  REQUIRE(again.code == 0);
  for (const auto& [f, text] : before) CHECK(slurp(f) == text);
}

TEST_CASE("eccd generate: overlap is of degree 1, decimal numbers have the digits asked for",
          "[app][cli][cli-generate]") {
  TempDir d;
  Run o = run_eccd("generate --out-dir " + q((d.path / "o").string()) +
                       " --dims 2 --degrees 2 --families overlap --depths 3,5 --json",
                   60);
  REQUIRE(o.code == 0);
  const auto of = files_of(o);
  REQUIRE(of.size() == 2);
  for (const auto& f : of) CHECK(fs::path(f).filename().string().rfind("2d-deg1-overlap-1e-", 0) == 0);

  Run r = run_eccd("generate --out-dir " + q((d.path / "dec").string()) +
                       " --dims 2,3 --degrees 2 --families decimal --digits 6 --json",
                   60);
  REQUIRE(r.code == 0);
  const auto files = files_of(r);
  CHECK(files.size() == 3);  // 2D kinematic, 3D euler and affine
  // A decimal: optional sign, digits with an optional point, optional exponent; at most 6 significant digits.
  const std::regex decimal(R"(^-?(\d+)(\.(\d+))?([eE][-+]?\d+)?$)");
  for (const auto& f : files) {
    INFO(f);
    const json scene = json::parse(slurp(f));
    std::vector<std::string> nums;
    for (const char* o2 : {"a", "b"}) {
      numbers(scene[o2]["shape"], nums);
      json motion = scene[o2]["motion"];
      motion.erase("type");
      numbers(motion, nums);
    }
    REQUIRE(!nums.empty());
    for (const auto& x : nums) {
      INFO(x);
      std::smatch m;
      REQUIRE(std::regex_match(x, m, decimal));
      std::string digits = m[1].str() + m[3].str();
      digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));  // leading zeros
      while (!digits.empty() && digits.back() == '0') digits.pop_back();        // trailing zeros
      CHECK(digits.size() <= 6);
    }
    CHECK(run_eccd("solve " + q(f), 120).code == 0);  // the reader takes it
  }
}

TEST_CASE("eccd generate: refusals are exit 2 and write nothing", "[app][cli][cli-generate]") {
  TempDir d;
  Run none = run_eccd("generate --dims 2", 30);
  CHECK(none.code == 2);
  CHECK(none.err.find("--out-dir DIR is required") != std::string::npos);
  const fs::path out = d.path / "t";
  Run touch1 = run_eccd("generate --out-dir " + q(out.string()) + " --dims 2 --degrees 1 --families touch", 30);
  CHECK(touch1.code == 2);
  CHECK(touch1.err.find("touch and near-miss scenes need motion degree >= 2") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  Run j = run_eccd("generate --out-dir " + q(out.string()) + " --dims 2 --degrees 1 --families near-miss --json", 30);
  CHECK(j.code == 2);
  const json e = json::parse(j.out);
  CHECK(e["format"] == "eccd-error/1");
  CHECK(e["exit_code"] == 2);
  CHECK(e["error"].get<std::string>().find("need motion degree >= 2") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

}  // namespace ECCD_UNITY_ID
