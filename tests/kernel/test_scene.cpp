// kernel/scene.hpp: the in-memory scene. Its one function, motion_type_name,
// must give the spec's "type" string (scene-format.md, "Motion") of every
// alternative of Motion: checked by reading one scene per motion type and
// comparing the name with the type written in the file; H_2D and H_3D are
// dim + 1.
#include "io/scene_reader.hpp"
#include "kernel/scene.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("motion_type_name is the scene file's motion type", "[kernel][scene]") {
  static_assert(H_2D == 3 && H_3D == 4);
  const std::string obj2 = R"({"shape": {"semi_axes": ["1", "2"]}, "motion": )";
  const std::string obj3 = R"({"shape": {"semi_axes": ["1", "2", "3"]}, "motion": )";
  struct Case {
    int dim;
    std::string motion, type;
  };
  const Case cases[] = {
      {2, R"({"type": "static"})", "static"},
      {2, R"({"type": "matrix", "m": [["1", "0", ["0", "1"]], ["0", "1", "0"], ["0", "0", "1"]]})", "matrix"},
      {2, R"({"type": "kinematic", "d": ["0", "1", "1", ["0", "1"]]})", "kinematic"},
      {3, R"({"type": "euler", "e": ["1", "0", "0", ["0", "1"]], "translation": ["0", "1", "2"]})", "euler"},
      {2, R"({"type": "cycloidal", "angle_over_pi": ["0", "1"], "translation": [["0", "1"], ["0", "0"]]})",
       "cycloidal"},
  };
  for (const Case& c : cases) {
    const std::string o = (c.dim == 2 ? obj2 : obj3) + c.motion + "}";
    const std::string text = R"({"format": "ellipse-ccd-scene/1", "name": "t", "dim": )" + std::to_string(c.dim) +
                             R"(, "a": )" + o + R"(, "b": )" + (c.dim == 2 ? obj2 : obj3) + R"({"type": "static"}})" +
                             "}";
    INFO(c.type);
    const Scene s = parse_scene(text, "test");
    CHECK(std::string(motion_type_name(s.a.motion)) == c.type);
    CHECK(std::string(motion_type_name(s.b.motion)) == "static");
    CHECK(s.dim == c.dim);
    CHECK(s.a.Q.size() == std::size_t(c.dim + 1));
  }
  CHECK(std::string(motion_type_name(Motion(CycloidalMotion{}))) == "cycloidal");
}

}  // namespace ECCD_UNITY_ID
