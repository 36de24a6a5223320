// One name per option across the commands (docs/cli/README.md): the current
// names work without a warning, the old spellings still work as hidden aliases
// that warn on stderr, --help lists only the current names, every error starts
// with "eccd:", `-` reads judge's scene, and the JSON keys agree (arith; format
// and version on eccd fcl's output).
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
namespace fs = std::filesystem;

namespace {
const std::string kScene2d = src("cases/paper003/example2.json");

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

std::vector<nlohmann::json> json_lines(const std::string& out) {
  std::istringstream in(out);
  std::string line;
  std::vector<nlohmann::json> v;
  while (std::getline(in, line))
    if (!line.empty()) v.push_back(nlohmann::json::parse(line));
  return v;
}
}  // namespace

TEST_CASE("a parser error starts with eccd: like every other error", "[cli][names]") {
  for (const std::string& args :
       std::vector<std::string>{"solve " + q(kScene2d) + " --bogus", "table --mpfr-bits 12", "report --no-such-option",
                                "generate --out-dir", "nosuchcommand"}) {
    INFO(args);
    Run r = run_eccd(args);
    CHECK(r.code == 2);
    CHECK(r.err.rfind("eccd: ", 0) == 0);
    CHECK(r.out.empty());
  }
}

TEST_CASE("table: --mpfr-bits, and --mpfr as an alias that warns", "[cli][names]") {
  TempDir t;
  fs::copy_file(kScene2d, t.path / "example2.json");
  Run now = run_eccd("table " + q(t.str()) + " --mpfr-bits 64 --json -q", 120);
  Run old = run_eccd("table " + q(t.str()) + " --mpfr 64 --json", 120);
  REQUIRE(now.code == 0);
  REQUIRE(old.code == 0);
  CHECK_FALSE(has(now.err, "warning"));
  CHECK(has(old.err, "eccd table: warning: --mpfr is renamed --mpfr-bits"));
  auto a = json_lines(now.out), b = json_lines(old.out);
  REQUIRE(a.size() == 1);
  REQUIRE(b.size() == 1);
  CHECK(a[0].contains("mpfr:64"));
  CHECK(b[0].contains("mpfr:64"));
  CHECK_FALSE(b[0].contains("mpfr:128"));  // the alias replaced the default, as the new name does
  // --quiet silences the alias's warning too
  Run quiet = run_eccd("table " + q(t.str()) + " --mpfr 64 --json --quiet", 120);
  CHECK(quiet.code == 0);
  CHECK_FALSE(has(quiet.err, "warning"));
}

TEST_CASE("each command's --help lists the current names only", "[cli][names]") {
  struct Want {
    std::string command;
    std::vector<std::string> listed, hidden;
  };
  for (const Want& w :
       {Want{"report", {"--mpfr-bits", "--out-dir", "--jobs", "--shard"}, {"--mpfr ", "--out ", "--threads"}},
        Want{"table", {"--mpfr-bits"}, {"--mpfr "}}, Want{"generate", {"--out-dir"}, {"--out "}},
        Want{"animate", {"--jobs", "--frame-block", "--out"}, {"--threads", "--shard"}},
        Want{"plot", {"--out"}, {"--output", "-o,"}}}) {
    INFO(w.command);
    Run r = run_eccd(w.command + " --help");
    CHECK(r.code == 0);
    for (const auto& s : w.listed) CHECK(has(r.out, s));
    for (const auto& s : w.hidden) CHECK_FALSE(has(r.out, s));
  }
}

TEST_CASE("generate: --out-dir, and --out as an alias that warns", "[cli][names]") {
  TempDir t;
  const std::string plan = " --dims 2 --degrees 2 --families free --count 1 --seed 5 --json";
  Run now = run_eccd("generate --out-dir " + q((t.path / "a").string()) + plan);
  Run old = run_eccd("generate --out " + q((t.path / "b").string()) + plan);
  REQUIRE(now.code == 0);
  REQUIRE(old.code == 0);
  CHECK_FALSE(has(now.err, "warning"));
  CHECK(has(old.err, "--out is renamed --out-dir"));
  auto a = nlohmann::json::parse(now.out), b = nlohmann::json::parse(old.out);
  REQUIRE(a["files"].size() == 1);
  REQUIRE(b["files"].size() == 1);
  CHECK(slurp(a["files"][0].get<std::string>()) == slurp(b["files"][0].get<std::string>()));  // the same scene
  Run none = run_eccd("generate" + plan);                                                     // no folder at all
  CHECK(none.code == 2);
  CHECK(has(none.err, "eccd: generate: --out-dir DIR is required"));
}

TEST_CASE("animate: --jobs and --frame-block, --threads and --shard as aliases that warn, and arith as in solve",
          "[cli][names]") {
  const std::string swarm = q(src("cases/animations/swarm-2d.json"));
  Run now = run_eccd("animate " + swarm + " --arith double --json --jobs 1 --frame-block 0/2", 120);
  Run old = run_eccd("animate " + swarm + " --arith double --json --threads 1 --shard 0/2", 120);
  REQUIRE(now.code == 0);
  REQUIRE(old.code == 0);
  CHECK_FALSE(has(now.err, "warning"));
  CHECK(has(old.err, "--threads is renamed --jobs"));
  CHECK(has(old.err, "--shard is renamed --frame-block"));
  auto a = nlohmann::json::parse(now.out), b = nlohmann::json::parse(old.out);
  CHECK(a["arith"] == "double");
  CHECK(a["arithmetic"] == a["arith"]);  // the key the animation answer format names
  CHECK(a["frames"] == b["frames"]);
  CHECK(a["events"] == b["events"]);
  Run bad = run_eccd("animate " + swarm + " --frame-block 2/2");
  CHECK(bad.code == 2);
  CHECK(has(bad.err, "eccd: --frame-block 2/2: expected i/n with 0 <= i < n"));
}

TEST_CASE("judge reads its scene from standard input with -", "[cli][names]") {
  Run piped = run_eccd("judge - " + q(kScene2d) + " --json < " + q(kScene2d), 120);
  REQUIRE(piped.code == 0);
  auto j = nlohmann::json::parse(piped.out);
  CHECK(j["scene_file"] == "<stdin>");
  CHECK(j["agrees"] == true);  // the scene's own stored answer against its certified one
  Run both = run_eccd("judge - - < " + q(kScene2d));
  CHECK(both.code == 2);
  CHECK(has(both.err, "eccd: judge: SCENE and ANSWER are both -"));
}

TEST_CASE("eccd fcl prints format and version with or without --json", "[cli][names]") {
  const std::string crossing = q(src("cases/spheres/spheres-crossing.json"));
  Run plain = run_eccd("fcl " + crossing + " --samples 10");
  if (plain.code == 3) {  // FCL not built in: refused, and said so
    CHECK(has(plain.err, "eccd: fcl: "));
    return;
  }
  REQUIRE(plain.code == 0);
  auto j = nlohmann::json::parse(plain.out);
  CHECK(j["format"] == "eccd-fcl-answer/1");
  CHECK(j.contains("version"));
  CHECK(j["answer"].contains("collides"));
  Run json = run_eccd("fcl " + crossing + " --samples 10 --json");
  REQUIRE(json.code == 0);
  CHECK(nlohmann::json::parse(json.out) == j);
}

TEST_CASE("solve's words: undecided is not collides no, and a sampled method has no polynomial", "[cli][names]") {
  Run d = run_eccd("solve " + q(kScene2d) + " --arith double");  // double cannot prove the touch at t = 1/2
  REQUIRE(d.code == 0);
  CHECK(has(d.out, "undecided near"));
  CHECK(has(d.out, "collides: unknown (no collision proved;"));
  CHECK_FALSE(has(d.out, "collides: no"));
  Run e = run_eccd("solve " + q(kScene2d) + " --arith exact");
  REQUIRE(e.code == 0);
  CHECK(has(e.out, "collides: yes"));
  Run m = run_eccd("solve " + q(src("cases/paper002/example.json")) + " --arith double --method marching:20");
  REQUIRE(m.code == 0);
  CHECK_FALSE(has(m.out, "degree -1"));
  CHECK(has(m.out, "no polynomial in t (method marching:20"));
}

}  // namespace ECCD_UNITY_ID
