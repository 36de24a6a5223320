// `eccd plot` from the command line: a 2D scene (003 Example 2) and a 3D scene
// (002's example) drawn into a temporary folder, and failures that write
// nothing. Checks the PNG signature, and that the --data file holds the very
// critical instants `eccd solve --json` reports. Needs python3 with numpy and
// matplotlib (scripts/bootstrap.sh installs python3-matplotlib).
//
// ECCD_EXE (the eccd binary) and ECCD_SOURCE_DIR are defined by CMake.
#include "tests/support/cli.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace ECCD_UNITY_ID {
namespace {

namespace fs = std::filesystem;

std::string quote(const std::string& s) {
  std::string r = "'";
  for (char c : s) r += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return r + "'";
}

using eccd::test::run;

std::string exe() { return quote(ECCD_EXE); }
std::string source(const std::string& rel) { return std::string(ECCD_SOURCE_DIR) + "/" + rel; }

struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "eccd-plot-test-XXXXXX").string();
    REQUIRE(mkdtemp(tmpl.data()) != nullptr);
    path = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::vector<std::string> files() const {
    std::vector<std::string> v;
    for (auto& e : fs::directory_iterator(path)) v.push_back(e.path().filename().string());
    std::sort(v.begin(), v.end());
    return v;
  }
};

bool is_png(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::string head(8, '\0');
  f.read(head.data(), 8);
  return f && head == std::string("\x89PNG\r\n\x1a\n", 8);
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream f(p);
  return nlohmann::json::parse(f);
}

nlohmann::json solve_json(const std::string& scene) {
  std::string out;
  REQUIRE(run(exe() + " solve " + quote(scene) + " --arith exact --json", out) == 0);
  return nlohmann::json::parse(out);
}

}  // namespace

TEST_CASE("eccd plot draws a 2D scene: default output name, PNG, data with solve's critical instants",
          "[plot][app][cli]") {
  TempDir dir;
  const std::string scene = source("cases/paper003/example2.json");
  std::string out;
  REQUIRE(run("cd " + quote(dir.path.string()) + " && " + exe() + " plot " + quote(scene) + " --data data.json", out) ==
          0);
  CHECK(out.find("wrote example2.png") != std::string::npos);
  CHECK(dir.files() == std::vector<std::string>{"data.json", "example2.png"});  // no temporary left behind
  CHECK(is_png(dir.path / "example2.png"));

  nlohmann::json data = read_json(dir.path / "data.json");
  nlohmann::json solved = solve_json(scene);
  REQUIRE(!solved["critical_instants"].empty());
  CHECK(data["solve"]["critical_instants"] == solved["critical_instants"]);
  CHECK(data["solve"]["intervals"] == solved["intervals"]);
  CHECK(data["arith"] == "exact");
  CHECK(data["curve"]["kind"] == "discriminant");
  CHECK(data["curve"]["degree"] == 96);
  CHECK(data["curve"]["t"].size() == data["curve"]["value"].size());
  CHECK(data["curve"]["t"].size() >= 2001);
  // 5 evenly spaced instants; the contact t = 1/2 is one of them and is marked.
  REQUIRE(data["snapshots"].size() == 5);
  CHECK(data["snapshots"][2]["t"] == 0.5);
  CHECK(data["snapshots"][2]["contact"] == true);
  REQUIRE(data["contacts"].size() == 1);
  CHECK(data["contacts"][0]["point"][0].get<double>() == Approx(0).margin(1e-9));
  CHECK(data["contacts"][0]["point"][1].get<double>() == Approx(0).margin(1e-9));
}

TEST_CASE("eccd plot - reads the scene from standard input and names the PNG after the scene",
          "[plot][app][cli][conventions]") {
  TempDir dir;
  const std::string scene = source("cases/paper003/example2.json");
  const std::string name = read_json(scene)["name"].get<std::string>();
  std::string out;
  REQUIRE(run("cd " + quote(dir.path.string()) + " && " + exe() + " plot - --data data.json < " + quote(scene), out) ==
          0);
  CHECK(out.find("wrote " + name + ".png") != std::string::npos);
  CHECK(dir.files() == std::vector<std::string>{"data.json", name + ".png"});
  CHECK(is_png(dir.path / (name + ".png")));
  nlohmann::json data = read_json(dir.path / "data.json");
  CHECK(data["file"] == "<stdin>");
  CHECK(data["solve"]["critical_instants"] == solve_json(scene)["critical_instants"]);
  // A bad scene on stdin is named "<stdin>", exit 2, nothing written.
  TempDir bad;
  CHECK(run("cd " + quote(bad.path.string()) + " && (echo '{' | " + exe() + " plot - 2>&1)", out) == 2);
  CHECK(out.find("<stdin>") != std::string::npos);
  CHECK(bad.files().empty());
}

TEST_CASE("eccd plot draws a 3D scene: the zero set of F(u,t), with solve's critical instants",
          "[plot][app][cli][ccd3]") {
  TempDir dir;
  const std::string scene = source("cases/paper002/example.json");
  const fs::path png = dir.path / "example3d.png", data_file = dir.path / "d.json";
  std::string out;
  REQUIRE(run(exe() + " plot " + quote(scene) + " -o " + quote(png.string()) + " --data " + quote(data_file.string()) +
                  " --instants 3",
              out) == 0);
  CHECK(dir.files() == std::vector<std::string>{"d.json", "example3d.png"});
  CHECK(is_png(png));

  nlohmann::json data = read_json(data_file);
  nlohmann::json solved = solve_json(scene);
  REQUIRE(solved["critical_instants"].size() == 4);
  CHECK(data["solve"]["critical_instants"] == solved["critical_instants"]);
  CHECK(data["dim"] == 3);
  CHECK(data["curve"]["kind"] == "F");
  CHECK(data["curve"]["value"].size() == data["curve"]["t"].size());
  CHECK(data["curve"]["value"][0].size() == data["curve"]["u"].size());
  // 3 evenly spaced instants plus the 4 contacts, each with its u0 = argmax F(., t0) and a 3D point.
  CHECK(data["snapshots"].size() == 7);
  REQUIRE(data["contacts"].size() == 4);
  for (const auto& c : data["contacts"]) {
    CHECK(c["u"].get<double>() > 0);
    CHECK(c["u"].get<double>() < 1);
    CHECK(c["point"].size() == 3);
  }
}

TEST_CASE("eccd plot fails cleanly and writes nothing", "[plot][app][cli]") {
  TempDir dir;
  const fs::path png = dir.path / "out.png";
  std::string out;
  // A bad scene: the scene reader's error, exit 2.
  CHECK(run(exe() + " plot " + quote(source("tests/data/bad/hyperbola.json")) + " -o " + quote(png.string()) +
                " --data " + quote((dir.path / "d.json").string()),
            out) == 2);
  CHECK(out.empty());
  // A bad option: exit 2.
  CHECK(run(exe() + " plot " + quote(source("cases/paper003/example2.json")) + " -o " + quote(png.string()) +
                " --instants 99",
            out) == 2);
  CHECK(run(exe() + " plot " + quote(source("cases/paper003/example2.json")) + " -o " + quote(png.string()) +
                " --arith quad",
            out) == 2);
  // A cycloidal motion in exact arithmetic: a refusal (exit 3).
  CHECK(run(exe() + " plot " + quote(source("tests/data/bad/cycloidal_exact.json")) + " -o " + quote(png.string()) +
                " --arith exact",
            out) == 3);
  CHECK(out.empty());
  CHECK(dir.files().empty());
}

TEST_CASE("eccd plot draws a cycloidal scene (003 Example 1): Δ(t) from enclosures, solve's critical instants",
          "[plot][app][cli][cycloidal]") {
  TempDir dir;
  const std::string scene = source("cases/paper003/example1.json");
  std::string out;
  REQUIRE(run(exe() + " plot " + quote(scene) + " -o " + quote((dir.path / "e1.png").string()) + " --data " +
                  quote((dir.path / "d.json").string()) + " --arith certified",
              out) == 0);
  CHECK(is_png(dir.path / "e1.png"));
  nlohmann::json data = read_json(dir.path / "d.json");
  CHECK(data["solve"]["critical_instants"].size() == 4);
  CHECK(data["curve"]["kind"] == "discriminant");
  CHECK(data["curve"]["t"].size() == data["curve"]["value"].size());
  // Δ changes sign across each of the paper's roots 0.226, 0.393, 0.600, 0.731 (and nowhere else on the grid).
  int changes = 0;
  const auto& v = data["curve"]["value"];
  for (std::size_t i = 1; i < v.size(); ++i)
    if ((v[i - 1].get<double>() < 0) != (v[i].get<double>() < 0) && v[i].get<double>() != 0) ++changes;
  CHECK(changes == 4);
  CHECK(data["contacts"].size() == 2);
}

}  // namespace ECCD_UNITY_ID
