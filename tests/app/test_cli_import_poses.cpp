// `eccd import-poses` (app/import_poses.cpp, docs/import-poses.md), run as
// the program ECCD_EXE on small CSVs:
//  - 3D: a header, comments, blank lines and lines in any order give an
//    animation (ellipse-ccd-animation/1) whose key times are the distinct
//    times in increasing order, bodies in the shapes file's order, numbers in
//    canonical form ("0.50" -> "0.5", "1.0" -> "1", fractions kept exact); the
//    file is one `eccd animate` reads, and its answer is the hand-computed
//    one: a unit ball moving from x = -3 to 0.5 touches a still ellipsoid of
//    x semi-axis 1/2 centred at x = 2 exactly at the end of the frame, at
//    (1.5, 0, 0);
//  - 2D: the angle θ becomes (w, z) = (cos θ/2, sin θ/2) within a few units
//    in the last place, written as decimals that read back as those doubles;
//  - standard input ("-"), --out written whole (and refused on a FIFO, a
//    directory, or the input itself, leaving nothing);
//  - errors of the docs' list: exit 2, the file, line, column and what is
//    wrong, nothing on standard output.
#include "cli_run.hpp"

#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <cmath>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;

namespace {
const char* kShapes3 = R"({"format": "eccd-shapes/1", "name": "two", "dim": 3,
 "bodies": [{"name": "mover", "shape": {"semi_axes": ["1", "1", "1"]}},
            {"name": "rest", "shape": {"semi_axes": ["0.5", "1/2", "2"]}}]})";
const char* kPoses3 = R"(time, body, x, y, z, qw, qx, qy, qz
# mover: from x = -3 to 0.5; rest: still at x = 2 (its quaternion scaled by 2 at time 1: the same rotation)

1, mover, 0.50, 0, 0, 1, 0, 0, 0
0, rest, 2, 0, 0, 1.0, 0, 0, 0
0, mover, -3, 1/3, 0, 1, 0, 0, 0
1, rest, 2, 0, 0, 2, 0, 0, 0
)";
const char* kShapes2 = R"({"dim": 2, "bodies": [{"name": "p", "shape": {"semi_axes": ["1", "2"]}},
 {"name": "q", "shape": {"semi_axes": ["1", "1"]}}], "pairs": "all"})";
}  // namespace

TEST_CASE("eccd import-poses: a 3D CSV becomes the animation, which animate answers as by hand",
          "[app][cli][cli-import-poses]") {
  TempDir d;
  spit(d.path / "shapes.json", kShapes3);
  spit(d.path / "poses.csv", kPoses3);
  Run r = run_eccd("import-poses " + q((d.path / "poses.csv").string()) + " --shapes " +
                   q((d.path / "shapes.json").string()));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const json a = json::parse(r.out);
  CHECK(a["format"] == "ellipse-ccd-animation/1");
  CHECK(a["name"] == "two");
  CHECK(a["dim"] == 3);
  CHECK(a["times"] == json::array({"0", "1"}));
  REQUIRE(a["bodies"].size() == 2);
  CHECK(a["bodies"][0]["name"] == "mover");
  CHECK(a["bodies"][1]["name"] == "rest");
  CHECK(a["bodies"][0]["poses"][0]["position"] == json::array({"-3", "1/3", "0"}));
  CHECK(a["bodies"][0]["poses"][1]["position"] == json::array({"0.5", "0", "0"}));        // "0.50"
  CHECK(a["bodies"][1]["poses"][0]["orientation"] == json::array({"1", "0", "0", "0"}));  // "1.0"
  CHECK(a["bodies"][1]["poses"][1]["orientation"] == json::array({"2", "0", "0", "0"}));
  CHECK(a["bodies"][1]["shape"]["semi_axes"] == json::array({"0.5", "1/2", "2"}));

  // The same from standard input, and into a file with --out (nothing on standard output then).
  Run s = run_eccd("import-poses - --shapes " + q((d.path / "shapes.json").string()) + " < " +
                   q((d.path / "poses.csv").string()));
  REQUIRE(s.code == 0);
  CHECK(json::parse(s.out) == a);
  Run o = run_eccd("import-poses " + q((d.path / "poses.csv").string()) + " --shapes " +
                   q((d.path / "shapes.json").string()) + " --out " + q((d.path / "anim.json").string()));
  REQUIRE(o.code == 0);
  CHECK(o.out.empty());
  CHECK(json::parse(slurp(d.path / "anim.json")) == a);

  // animate: the ball's right end reaches 0.5 + 1 = 1.5 = 2 - 0.5 at t = 1: one touch, at (1.5, 0, 0).
  Run an = run_eccd("animate " + q((d.path / "anim.json").string()) + " --json");
  INFO(an.err);
  REQUIRE(an.code == 0);
  const json ans = json::parse(an.out);
  REQUIRE(ans["events"].size() == 1);
  const json& e = ans["events"][0]["answer"];
  CHECK(e["collides"] == true);
  CHECK(e["first_contact"]["lo"] == "1");
  CHECK(e["first_contact"]["hi"] == "1");
  REQUIRE(e["contact_points"].size() == 1);
  CHECK(e["contact_points"][0] == json::array({"1.5", "0", "0"}));
}

TEST_CASE("eccd import-poses: 2D angles become (cos, sin) of the half angle", "[app][cli][cli-import-poses]") {
  TempDir d;
  spit(d.path / "shapes.json", kShapes2);
  spit(d.path / "poses.csv",
       "0, p, 0, 0, 0\n0, q, 5, 0, 1.5707963267948966\n2.5, p, 0, 1, 3.141592653589793\n2.5, q, 5, 0, -0.5\n");
  Run r = run_eccd("import-poses " + q((d.path / "poses.csv").string()) + " --shapes " +
                   q((d.path / "shapes.json").string()));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const json a = json::parse(r.out);
  CHECK(a["name"] == "animation");  // the default name
  CHECK(a["times"] == json::array({"0", "2.5"}));
  auto check_angle = [](const json& o, double theta) {
    REQUIRE(o.size() == 2);
    const double w = std::stod(o[0].get<std::string>()), z = std::stod(o[1].get<std::string>());
    CHECK(std::abs(w - std::cos(theta / 2)) <= 4e-16);
    CHECK(std::abs(z - std::sin(theta / 2)) <= 4e-16);
  };
  check_angle(a["bodies"][0]["poses"][0]["orientation"], 0);
  check_angle(a["bodies"][1]["poses"][0]["orientation"], 1.5707963267948966);
  check_angle(a["bodies"][0]["poses"][1]["orientation"], 3.141592653589793);
  check_angle(a["bodies"][1]["poses"][1]["orientation"], -0.5);
  CHECK(a["bodies"][0]["poses"][0]["orientation"] == json::array({"1", "0"}));  // θ = 0 exactly
}

TEST_CASE("eccd import-poses: bad CSVs, shapes and outputs are exit 2 with the place", "[app][cli][cli-import-poses]") {
  TempDir d;
  spit(d.path / "shapes.json", kShapes3);
  const std::string shapes = " --shapes " + q((d.path / "shapes.json").string());
  const std::string good_rest = "0, rest, 2,0,0,1,0,0,0\n1, mover, 0,0,0,1,0,0,0\n1, rest, 2,0,0,1,0,0,0\n";
  struct Bad {
    std::string line, message;
  };
  const std::vector<Bad> bad = {
      {"0, mover, 1, 2",
       "line 2: expected 9 columns (time, body, x, y, z, qw, qx, qy, qz) for a 3D shapes file, "
       "found 4"},
      {"0, ghost, 0,0,0,1,0,0,0",
       "line 2, column 2 (body): \"ghost\" is not a body of the shapes file (its bodies: mover, rest)"},
      {"0, mover, 0, 0, x, 1,0,0,0", "line 2, column 5 (z): \"x\""},
      {"0, mover, 0, 0, nan, 1,0,0,0", "line 2, column 5 (z): \"nan\""},
      {"0, mover, 0, 0, inf, 1,0,0,0", "line 2, column 5 (z): \"inf\""},
      {"0, mover, 0x1p3, 0, 0, 1,0,0,0", "line 2, column 3 (x)"},
      {"0, mover, 0,0,0, 0,0,0,0", "line 2, columns 6-9 (qw, qx, qy, qz): the quaternion is zero"},
      {"0, mover, 0,0,0,1,0,0,0", "line 2: body \"mover\" at time 0 again (its pose is on line 1)"},
  };
  for (const auto& b : bad) {
    INFO(b.line);
    spit(d.path / "b.csv", "0, mover, 0,0,0,1,0,0,0\n" + b.line + "\n" + good_rest);
    Run r = run_eccd("import-poses " + q((d.path / "b.csv").string()) + shapes + " --out " +
                     q((d.path / "never.json").string()));
    CHECK(r.code == 2);
    CHECK(r.err.find((d.path / "b.csv").string() + ": " + b.message) != std::string::npos);
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(d.path / "never.json"));
  }
  // A body without a pose at a time of the file; a single key time.
  spit(d.path / "m.csv", "0, mover, 0,0,0,1,0,0,0\n0, rest, 2,0,0,1,0,0,0\n1, mover, 0,0,0,1,0,0,0\n");
  Run m = run_eccd("import-poses " + q((d.path / "m.csv").string()) + shapes);
  CHECK(m.code == 2);
  CHECK(m.err.find("m.csv: body \"rest\" has no pose at time 1") != std::string::npos);
  spit(d.path / "one.csv", "0, mover, 0,0,0,1,0,0,0\n0, rest, 2,0,0,1,0,0,0\n");
  Run one = run_eccd("import-poses " + q((d.path / "one.csv").string()) + shapes);
  CHECK(one.code == 2);
  CHECK(one.err.find("one.csv") != std::string::npos);
  // A bad shapes file: the JSON place.
  spit(d.path / "bad-shapes.json", R"({"dim": 3, "bodies": [{"name": "mover", "shape": {"semi_axes": ["1", "-1", "1"]}},
    {"name": "rest", "shape": {"semi_axes": ["1", "1", "1"]}}]})");
  spit(d.path / "ok.csv", "0, mover, 0,0,0,1,0,0,0\n" + good_rest);
  Run s = run_eccd("import-poses " + q((d.path / "ok.csv").string()) + " --shapes " +
                   q((d.path / "bad-shapes.json").string()));
  CHECK(s.code == 2);
  CHECK(s.err.find("bad-shapes.json: /bodies/0/shape/semi_axes/1") != std::string::npos);
  // Outputs that are refused: a FIFO, a directory, the input itself (left as it was).
  REQUIRE(::mkfifo((d.path / "fifo").c_str(), 0600) == 0);
  std::filesystem::create_directories(d.path / "dir");
  for (const auto& out : {d.path / "fifo", d.path / "dir", d.path / "ok.csv"}) {
    INFO(out);
    Run o = run_eccd("import-poses " + q((d.path / "ok.csv").string()) + shapes + " --out " + q(out.string()), 20);
    CHECK(o.code == 2);
    CHECK_FALSE(o.timed_out);
    CHECK(o.err.find(out.string()) != std::string::npos);
  }
  CHECK(slurp(d.path / "ok.csv") == "0, mover, 0,0,0,1,0,0,0\n" + good_rest);
  // A missing CSV or shapes file.
  Run miss = run_eccd("import-poses " + q((d.path / "none.csv").string()) + shapes);
  CHECK(miss.code == 2);
  CHECK(miss.err.find("none.csv") != std::string::npos);
}

}  // namespace ECCD_UNITY_ID
