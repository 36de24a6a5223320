// make_repro.py boxers --subdivide S (cases/animations/make_repro.py; the
// report's finer sampling of the same motion, reports/animation "The kept
// plane's share"): key k of the subdivided file is the pose of the motion at
// k/S, so key S·m equals key m of the default file, body by body, and the
// keys in between differ; S < 1 is refused with a message and no file.
#include "tests/app/cli_run.hpp"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;

namespace {

int make_repro(const std::string& args) {
  const std::string cmd = "python3 " + q(src("cases/animations/make_repro.py")) + " " + args + " >/dev/null 2>&1";
  return std::system(cmd.c_str());
}

}  // namespace

TEST_CASE("make_repro.py boxers --subdivide samples the same motion more finely", "[app][cli][animation]") {
  TempDir d;
  const std::string plain = d.str() + "/plain.json", fine = d.str() + "/fine.json", bad = d.str() + "/bad.json";
  REQUIRE(make_repro("boxers --frames 3 " + q(plain)) == 0);
  REQUIRE(make_repro("boxers --frames 12 --subdivide 4 " + q(fine)) == 0);
  const json a = json::parse(slurp(plain)), b = json::parse(slurp(fine));
  REQUIRE(a["bodies"].size() == 48);
  REQUIRE(b["bodies"].size() == 48);
  REQUIRE(b["times"].size() == 13);
  int differ = 0;
  for (std::size_t i = 0; i < 48; ++i) {
    INFO(a["bodies"][i]["name"]);
    REQUIRE(a["bodies"][i]["name"] == b["bodies"][i]["name"]);
    for (int m = 0; m <= 3; ++m) CHECK(b["bodies"][i]["poses"][4 * m] == a["bodies"][i]["poses"][m]);
    differ += b["bodies"][i]["poses"][1] != a["bodies"][i]["poses"][0] &&
              b["bodies"][i]["poses"][1] != a["bodies"][i]["poses"][1];
  }
  CHECK(differ > 20);  // the limbs move: key 1/4 is neither key 0 nor key 1
  CHECK(make_repro("boxers --frames 3 --subdivide 0 " + q(bad)) != 0);
  CHECK_FALSE(std::filesystem::exists(bad));
}

}  // namespace ECCD_UNITY_ID
