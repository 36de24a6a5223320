// Keyframes -> animation files (io/pose_import.hpp; docs/import-poses.md):
// canonical numbers, the CSV of poses with a shapes file, and the errors that
// name the line and the column. The Python side (tests/python/test_package.py)
// checks that the CSV, the keyframe builder and `eccd import-poses` write the
// same bytes and that `eccd animate` answers them.
#include "io/animation_reader.hpp"
#include "io/pose_import.hpp"
#include "io/scene_error.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

const char* kShapes = R"({"name": "pair", "dim": 3, "bodies": [
  {"name": "mover", "group": "g1", "shape": {"semi_axes": ["1", "1", "1"]}},
  {"name": "rest", "group": "g2", "shape": {"semi_axes": ["1", "1", "1"]}}], "pairs": "between-groups"})";

std::string csv_error(const std::string& csv) {
  try {
    pose_keyframes_from_csv(csv, "p.csv", shapes_from_text(kShapes, "s.json"));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("canonical numbers: one text per exact value", "[pose_import]") {
  CHECK(canonical_number_text("1.0") == "1");
  CHECK(canonical_number_text("0.50") == "0.5");
  CHECK(canonical_number_text("6/4") == "1.5");
  CHECK(canonical_number_text("1/3") == "1/3");
  CHECK(canonical_number_text("-2.5e-3") == "-0.0025");
  CHECK(canonical_number_text("1e-30") == "1e-30");
  CHECK(canonical_number_text("-12.5e-40") == "-1.25e-39");
  CHECK(number_from_double(0.1) == "0.1");  // the shortest round-trip text, not the binary value
  CHECK(number_from_double(2.0) == "2");
  CHECK(number_from_double(1e-30) == "1e-30");
  CHECK_THROWS_AS(number_from_double(1.0 / 0.0), std::invalid_argument);
  const auto wz = orientation_of_angle(0);
  CHECK(wz == std::vector<std::string>{"1", "0"});
}

TEST_CASE("a CSV of poses becomes a valid animation, times in order", "[pose_import]") {
  const std::string csv =
      "time, body, x, y, z, qw, qx, qy, qz\n"
      "# a comment\n"
      "1.0,mover,3,0,0,1,0,0,0\n"
      "0,mover,-3,0,0,1,0,0,0\n"
      "0,rest,0,0,0,1,0,0,0\n"
      "0.5,rest,0,0,0,1,0,0,0\n"
      "0.5,mover,0,0,0,0.9,0.1,0.2,0.3\n"
      "\n"
      "1,rest,0,0,0,1,0,0,0\n";
  const Keyframes k = pose_keyframes_from_csv(csv, "p.csv", shapes_from_text(kShapes, "s.json"));
  CHECK(k.times == std::vector<std::string>{"0", "0.5", "1"});
  REQUIRE(k.bodies.size() == 2);
  CHECK(k.bodies[0].poses[1].orientation == std::vector<std::string>{"0.9", "0.1", "0.2", "0.3"});
  CHECK(k.bodies[0].poses[2].position == std::vector<std::string>{"3", "0", "0"});
  const auto j = animation_json(k, "p.csv");
  const Animation a = animation_from_text(animation_text(j), "p.csv");
  CHECK(a.name == "pair");
  CHECK(a.frames() == 2);
  CHECK(a.pairs_rule == "between-groups");
}

TEST_CASE("CSV errors name the file, the line and the column", "[pose_import]") {
  CHECK(csv_error("0,mover,0,0,0,1,0,0,0\n0,rest,0,0,0,1,0,0,0\n1,mover,0,0,x,1,0,0,0\n")
            .rfind("p.csv: line 3, column 5 (z): ", 0) == 0);
  CHECK(csv_error("0,mover,0,0,0,1,0,0,0\n0,rest,0,0\n").rfind("p.csv: line 2: expected 9 columns", 0) == 0);
  CHECK(csv_error("0,ghost,0,0,0,1,0,0,0\n").rfind("p.csv: line 1, column 2 (body): \"ghost\"", 0) == 0);
  CHECK(csv_error("0,mover,0,0,0,1,0,0,0\n0,mover,0,0,0,1,0,0,0\n") ==
        "p.csv: line 2: body \"mover\" at time 0 again (its pose is on line 1)");
  CHECK(csv_error("0,mover,0,0,0,1,0,0,0\n0,rest,0,0,0,1,0,0,0\n1,mover,0,0,0,1,0,0,0\n") ==
        "p.csv: body \"rest\" has no pose at time 1 (every body needs one pose at every time of the file)");
  CHECK(csv_error("0,mover,0,0,0,0,0,0,0\n").rfind("p.csv: line 1, columns 6-9", 0) == 0);
  CHECK(csv_error(std::string("0,mover,0,0,0,1,0,0,0\n0,rest\0,0,0,0,1,0,0,0\n", 44))
            .rfind("p.csv: line 2: a NUL byte", 0) == 0);
  CHECK_THROWS_WITH(shapes_from_text(R"({"dim": 4, "bodies": []})", "s.json"), Catch::StartsWith("s.json: /dim: "));
}

}  // namespace ECCD_UNITY_ID
