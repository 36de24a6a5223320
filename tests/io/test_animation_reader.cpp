// The animation reader (io/animation_reader.hpp; docs/animation-format.md):
// a valid file is read exactly, and each kind of bad file is refused with
// "FILE: PLACE: what is wrong" (one test per kind).
#include "io/animation_reader.hpp"
#include "kernel/keyframe_motion.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {

// Three bodies, three key times, 3D.
json good3d() {
  json pose0 = {{"position", {"0", "0", "0"}}, {"orientation", {"1", "0", "0", "0"}}};
  json pose1 = {{"position", {"1/2", "0", "0"}}, {"orientation", {"0.9", "0.1", "0", "0"}}};
  json pose2 = {{"position", {"1", "0", "0"}},
                {"orientation", {"0.8", "0.2", "0", "0"}},
                {"deformation", {{"1.1", "0", "0"}, {"0", "1", "0"}, {"0", "0", "1"}}}};
  json body = {{"name", "a"},
               {"group", "g1"},
               {"shape", {{"semi_axes", {"1", "0.5", "0.5"}}}},
               {"poses", {pose0, pose1, pose2}}};
  json b2 = body;
  b2["name"] = "b";
  b2["group"] = "g2";
  json b3 = body;
  b3["name"] = "c";
  b3["group"] = "g2";
  return {{"format", "ellipse-ccd-animation/1"},
          {"name", "t"},
          {"dim", 3},
          {"times", {"0", "1/30", "2/30"}},
          {"bodies", {body, b2, b3}},
          {"pairs", "between-groups"}};
}

// The message of reading `j` (dumped), or "" if it reads.
std::string error_of(const std::string& text) {
  try {
    animation_from_text(text, "anim.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}
std::string error_of(const json& j) { return error_of(j.dump()); }

void require_error(const json& j, const std::string& place, const std::string& what) {
  const std::string m = error_of(j);
  INFO(m);
  REQUIRE(m.rfind("anim.json: " + place + ": ", 0) == 0);
  REQUIRE(m.find(what) != std::string::npos);
}

}  // namespace

TEST_CASE("animation reader: a valid file is read exactly", "[animation]") {
  Animation a = animation_from_text(good3d().dump(), "anim.json");
  REQUIRE(a.dim == 3);
  REQUIRE(a.frames() == 2);
  REQUIRE(a.times[2] == Rational(1, 15));
  REQUIRE(a.bodies.size() == 3);
  REQUIRE(a.bodies[1].poses[2].deformation.has_value());
  REQUIRE((*a.bodies[1].poses[2].deformation)[0][0] == Rational(11, 10));
  REQUIRE(a.bodies[0].poses[1].orientation[0] == Rational(9, 10));
  REQUIRE(a.bodies[0].Q[0][0] == 1);
  REQUIRE(a.bodies[0].Q[1][1] == 4);
  // between-groups: a-b, a-c (b and c share g2), in the order of bodies
  REQUIRE(a.pairs == std::vector<std::pair<std::size_t, std::size_t>>{{0, 1}, {0, 2}});
  json all = good3d();
  all.erase("pairs");
  REQUIRE(animation_from_text(all.dump()).pairs.size() == 3);
  json list = good3d();
  list["pairs"] = json::array({json::array({"c", "a"}), json::array({"b", "c"})});
  REQUIRE(animation_from_text(list.dump()).pairs == std::vector<std::pair<std::size_t, std::size_t>>{{0, 2}, {1, 2}});
}

TEST_CASE("animation reader: format, malformed JSON, unknown keys", "[animation]") {
  json j = good3d();
  j["format"] = "ellipse-ccd-scene/1";
  require_error(j, "/format", "unsupported format");
  j = good3d();
  j["speed"] = "1";
  require_error(j, "/speed", "unknown key \"speed\" in an animation");
  j = good3d();
  j["bodies"][1]["colour"] = "red";
  require_error(j, "/bodies/1/colour", "unknown key \"colour\" in a body");
  j = good3d();
  j["bodies"][0]["poses"][1]["velocity"] = {"0", "0", "0"};
  require_error(j, "/bodies/0/poses/1/velocity", "unknown key \"velocity\" in a pose");
  REQUIRE(error_of(std::string("{\"format\": ")).find("anim.json: line 1") == 0);
  // duplicate keys, as in scenes
  REQUIRE(error_of(std::string("{\"format\": \"ellipse-ccd-animation/1\", \"name\": \"x\", \"name\": \"y\"}"))
              .find("duplicate key") != std::string::npos);
}

TEST_CASE("animation reader: a JSON number with a fraction part", "[animation]") {
  json j = good3d();
  std::string text = j.dump();
  const std::string from = "\"1/2\"";
  text.replace(text.find(from), from.size(), "0.5");
  const std::string m = error_of(text);
  INFO(m);
  REQUIRE(m.rfind("anim.json: /bodies/0/poses/1/position/0: ", 0) == 0);
  REQUIRE(m.find("fraction part") != std::string::npos);
}

TEST_CASE("animation reader: a zero orientation", "[animation]") {
  json j = good3d();
  j["bodies"][2]["poses"][0]["orientation"] = {"0", "0", "0", "0"};
  require_error(j, "/bodies/2/poses/0/orientation", "the orientation is zero");
  j = good3d();
  j["bodies"][0]["poses"][0]["orientation"] = {"1", "0"};
  require_error(j, "/bodies/0/poses/0/orientation", "must have 4 entries");
}

TEST_CASE("animation reader: a half-turn flip never makes q(tau) vanish", "[animation]") {
  // q_1 = -q_0 (the same rotation) and q_1 = -2 q_0: the shorter-way rule
  // flips them, so q(tau) stays away from 0 and the file is valid; without
  // the rule, q(tau) = (1 - tau) q_0 + tau q_1 would vanish at tau = 1/2 and 1/3.
  json j = good3d();
  j["bodies"][0]["poses"][1]["orientation"] = {"-1", "0", "0", "0"};
  j["bodies"][1]["poses"][1]["orientation"] = {"-2", "0", "0", "0"};
  REQUIRE(error_of(j).empty());
  const std::vector<Rational> q0{1, 0, 0, 0}, q1{-2, 0, 0, 0};
  const RPoly unflipped = keyframe_weight(q0, q1);  // (1 - 3 tau)^2
  REQUIRE(unflipped(Rational(1, 3)) == 0);
  const RPoly w = keyframe_weight(q0, shorter_way(q0, q1));  // (1 + tau)^2
  REQUIRE(w(Rational(0)) == 1);
  REQUIRE(w(Rational(1)) == 4);
  REQUIRE(w.degree() == 2);
  REQUIRE(w.c[1] == 2);
  // 2D: [w, z] = [1, 0] and [0, 1] (a half turn apart, q0 . q1 = 0): q(tau) = (1 - tau, tau) != 0
  const std::vector<Rational> p0{1, 0}, p1{0, 1};
  REQUIRE(keyframe_weight(p0, shorter_way(p0, p1)) == RPoly(std::vector<Rational>{1, -2, 2}));
}

TEST_CASE("animation reader: a singular deformation on a frame", "[animation]") {
  // det D at the keys: 1 and 1, but D(tau) = (1 - tau) I + tau diag(-1, -1, 1) is singular at tau = 1/2.
  json j = good3d();
  j["bodies"][1]["poses"][2]["deformation"] = {{"-1", "0", "0"}, {"0", "-1", "0"}, {"0", "0", "1"}};
  require_error(j, "/bodies/1/poses/2/deformation", "body \"b\", frame 1");
  require_error(j, "/bodies/1/poses/2/deformation", "det D(τ) = 0 at τ = 1/2");
  // det D <= 0 at a key
  j = good3d();
  j["bodies"][0]["poses"][2]["deformation"] = {{"1", "0", "0"}, {"0", "1", "0"}, {"0", "0", "-2"}};
  require_error(j, "/bodies/0/poses/2/deformation", "det D > 0, got det D = -2 (a reflection)");
  j["bodies"][0]["poses"][2]["deformation"] = {{"1", "1", "0"}, {"1", "1", "0"}, {"0", "0", "1"}};
  require_error(j, "/bodies/0/poses/2/deformation", "got det D = 0 (singular");
  // a shear with det D = -1 at a key
  j = good3d();
  j["bodies"][0]["poses"][1]["deformation"] = {{"1", "0", "0"}, {"0", "1", "0"}, {"0", "0", "1"}};
  j["bodies"][0]["poses"][2]["deformation"] = {{"1", "2", "0"}, {"1", "1", "0"}, {"0", "0", "1"}};  // det -1
  require_error(j, "/bodies/0/poses/2/deformation", "det D > 0");
}

TEST_CASE("animation reader: wrong number of poses", "[animation]") {
  json j = good3d();
  j["bodies"][1]["poses"].erase(1);
  require_error(j, "/bodies/1/poses", "exactly one entry per key time: 3 key times, got 2 poses");
}

TEST_CASE("animation reader: times not strictly increasing", "[animation]") {
  json j = good3d();
  j["times"] = {"0", "1/30", "1/30"};
  require_error(j, "/times/2", "strictly increasing");
  j["times"] = {"0"};
  require_error(j, "/times", "at least two key times");
}

TEST_CASE("animation reader: duplicate names and too few bodies", "[animation]") {
  json j = good3d();
  j["bodies"][2]["name"] = "a";
  require_error(j, "/bodies/2/name", "duplicate body name \"a\" (also /bodies/0)");
  j = good3d();
  j["bodies"].erase(1);
  j["bodies"].erase(1);
  require_error(j, "/bodies", "at least two bodies");
}

TEST_CASE("animation reader: pairs naming unknown bodies, repeated, or empty", "[animation]") {
  json j = good3d();
  j["pairs"] = json::array({json::array({"a", "zz"})});
  require_error(j, "/pairs/0/1", "unknown body name \"zz\"");
  j["pairs"] = json::array({json::array({"a", "b"}), json::array({"b", "a"})});
  require_error(j, "/pairs/1", "listed twice (also at /pairs/0)");
  j["pairs"] = json::array({json::array({"a", "a"})});
  require_error(j, "/pairs/0", "a pair of a body with itself");
  j["pairs"] = "some";
  require_error(j, "/pairs", "pairs must be \"all\", \"between-groups\"");
  j = good3d();
  j["bodies"][1].erase("group");
  require_error(j, "/bodies/1/name", "has no group");
  j = good3d();
  for (auto& b : j["bodies"]) b["group"] = "same";
  require_error(j, "/pairs", "no pair to check");
}

TEST_CASE("animation reader: shapes and positions as in scenes", "[animation]") {
  json j = good3d();
  j["bodies"][0]["shape"] = {{"semi_axes", {"1", "-1", "1"}}};
  require_error(j, "/bodies/0/shape/semi_axes/1", "must be positive");
  j = good3d();
  j["bodies"][0]["poses"][0]["position"] = {"0", "0"};
  require_error(j, "/bodies/0/poses/0/position", "must have 3 entries");
  j = good3d();
  j["dim"] = 2;
  require_error(j, "/bodies/0/shape/semi_axes", "must have 2 entries");
}

}  // namespace ECCD_UNITY_ID
