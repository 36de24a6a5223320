// Tests for the scene reader (io/scene_reader.hpp): exact numbers, valid
// 2D and 3D scenes, one test per kind of bad input (message names the file,
// the JSON pointer and what is wrong), answers to and from JSON, and a
// robustness sweep (truncated / mangled files give SceneError, never a crash).
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <variant>

namespace ECCD_UNITY_ID {
using eccd::Rational;
using eccd::RPoly;
using eccd::SceneError;
using nlohmann::json;

namespace {

const std::string kLabel = "cases/test-scene.json";

json base2d() {
  return json::parse(R"({
    "format": "ellipse-ccd-scene/1",
    "name": "two-ellipses",
    "dim": 2,
    "a": {"shape": {"semi_axes": ["5", "10"]}, "motion": {"type": "static"}},
    "b": {"shape": {"semi_axes_squared": ["4", "9/4"]},
          "motion": {"type": "kinematic", "d": [["0", "1"], "-3", {"bernstein": ["1", "1"]}, "0"]}},
    "note": "a test"
  })");
}

json base3d() {
  return json::parse(R"({
    "format": "ellipse-ccd-scene/1",
    "name": "two-ellipsoids",
    "dim": 3,
    "a": {"shape": {"semi_axes_squared": ["5", "8", "10"]}, "motion": {"type": "static"}},
    "b": {"shape": {"matrix": [["1/4", "0", "0", "0"], ["0", "1", "0", "0"], ["0", "0", "1", "-1"], ["0", "0", "-1", "0"]]},
          "motion": {"type": "euler", "e": ["1", ["0", "1"], "0", "0"], "translation": [["1", "2"], "0", "-1.5"],
                     "translation_denominator": ["2"]}}
  })");
}

std::string error_of(const std::string& text) {
  try {
    eccd::parse_scene(text, kLabel);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// parse_scene(text) must throw SceneError "LABEL: PLACE: ... PHRASE ...".
void expect_error(const std::string& text, const std::string& place, const std::string& phrase) {
  std::string msg = error_of(text);
  INFO("message: " << msg);
  CHECK(msg.rfind(kLabel + ": " + place + ": ", 0) == 0);
  CHECK(msg.find(phrase) != std::string::npos);
}
void expect_error(const json& j, const std::string& place, const std::string& phrase) {
  expect_error(j.dump(2), place, phrase);
}

RPoly P(std::initializer_list<const char*> cs) {
  std::vector<Rational> v;
  for (const char* c : cs) v.push_back(Rational(c));
  return RPoly(v);
}

json matrix_shape(std::initializer_list<std::initializer_list<const char*>> rows) {
  json m = json::array();
  for (auto r : rows) {
    json row = json::array();
    for (const char* x : r) row.push_back(x);
    m.push_back(row);
  }
  return json{{"matrix", m}};
}

}  // namespace

// ---------------------------------------------------------------------------
TEST_CASE("parse_rational reads exact values", "[scene_reader]") {
  CHECK(eccd::parse_rational("-63") == Rational(-63));
  CHECK(eccd::parse_rational("+5") == Rational(5));
  CHECK(eccd::parse_rational("007") == Rational(7));
  CHECK(eccd::parse_rational("-3/7") == Rational(-3, 7));
  CHECK(eccd::parse_rational("6/4") == Rational(3, 2));
  CHECK(eccd::parse_rational("1.8") == Rational(9, 5));
  CHECK(eccd::parse_rational("2.5e-3") == Rational(1, 400));
  CHECK(eccd::parse_rational("2.5E+3") == Rational(2500));
  CHECK(eccd::parse_rational("-.5") == Rational(-1, 2));
  CHECK(eccd::parse_rational("5.") == Rational(5));
  CHECK(eccd::parse_rational("0.1") == Rational(1, 10));
  CHECK(eccd::parse_rational("-0") == Rational(0));
  CHECK(eccd::parse_rational("123456789012345678901234567890") == Rational("123456789012345678901234567890"));
  CHECK(eccd::parse_rational("1e-30") == Rational(mpz_class(1), mpz_class("1000000000000000000000000000000")));
}

TEST_CASE("parse_rational rejects bad text with a reason", "[scene_reader]") {
  for (const char* bad : {"1/0", "abc", "1.2.3", "",     " 1",  "1 ",  "1/-2", "1.5/2",    "/3",  "3/",
                          ".",   "e5",  "1e",    "0x10", "inf", "nan", "--1",  "1e100000", "1,5", "½"}) {
    INFO("text: \"" << bad << "\"");
    CHECK_THROWS_AS(eccd::parse_rational(bad), std::invalid_argument);
  }
  CHECK_THROWS_WITH(eccd::parse_rational("1/0"), Catch::Contains("zero denominator"));
  CHECK_THROWS_WITH(eccd::parse_rational("1.2.3"), Catch::Contains("unexpected '.'"));
  CHECK_THROWS_WITH(eccd::parse_rational("abc"), Catch::Contains("no digits"));
}

// ---------------------------------------------------------------------------
TEST_CASE("a valid 2D scene is read into exact data", "[scene_reader]") {
  eccd::Scene s = eccd::parse_scene(base2d().dump(), kLabel);
  CHECK(s.path == kLabel);
  CHECK(s.name == "two-ellipses");
  CHECK(s.note == "a test");
  CHECK(s.dim == 2);
  CHECK_FALSE(s.answer.has_value());
  using Row = std::vector<Rational>;
  CHECK(s.a.Q == std::vector<Row>{{Rational(1, 25), 0, 0}, {0, Rational(1, 100), 0}, {0, 0, -1}});
  CHECK(s.b.Q == std::vector<Row>{{Rational(1, 4), 0, 0}, {0, Rational(4, 9), 0}, {0, 0, -1}});
  CHECK(std::holds_alternative<eccd::StaticMotion>(s.a.motion));
  REQUIRE(std::holds_alternative<eccd::KinematicMotion>(s.b.motion));
  const auto& d = std::get<eccd::KinematicMotion>(s.b.motion).d;
  CHECK(d[0] == P({"0", "1"}));
  CHECK(d[1] == P({"-3"}));
  CHECK(d[2] == P({"1"}));  // bernstein ["1", "1"] is the constant 1
  CHECK(d[3].is_zero());
}

TEST_CASE("Bernstein coefficients are converted exactly to power form", "[scene_reader]") {
  json j = base2d();
  j["b"]["motion"] = json::parse(R"({"type": "matrix", "m": [
      [{"bernstein": ["1", "1"]}, "0", {"bernstein": ["0", "1"]}],
      ["0", {"bernstein": ["1", "1/2", "1"]}, {"bernstein": ["0", "0", "1"]}],
      ["0", "0", ["1"]]]})");
  eccd::Scene s = eccd::parse_scene(j.dump(), kLabel);
  REQUIRE(std::holds_alternative<eccd::MatrixMotion>(s.b.motion));
  const auto& m = std::get<eccd::MatrixMotion>(s.b.motion).m;
  CHECK(m[0][0] == P({"1"}));
  CHECK(m[0][2] == P({"0", "1"}));        // t
  CHECK(m[1][1] == P({"1", "-1", "1"}));  // (1-t)^2 + t(1-t) + t^2 = 1 - t + t^2
  CHECK(m[1][2] == P({"0", "0", "1"}));   // t^2
  CHECK(m[2][2] == P({"1"}));
}

TEST_CASE("a valid 3D scene is read into exact data", "[scene_reader]") {
  json j = base3d();
  j["answer"] = json::parse(R"({"collides": true,
      "intervals": [[{"approx": "0.25", "lo": "1/4", "hi": "1/4"}, {"approx": "1", "lo": "1", "hi": "1"}]],
      "first_contact": {"approx": "0.25", "lo": "1/4", "hi": "1/4"},
      "contacts": [{"approx": "0.25", "lo": "0.2", "hi": "3/10"}]})");
  eccd::Scene s = eccd::parse_scene(j.dump(), kLabel);
  CHECK(s.dim == 3);
  CHECK(s.note.empty());
  using Row = std::vector<Rational>;
  CHECK(s.a.Q == std::vector<Row>{
                     {Rational(1, 5), 0, 0, 0}, {0, Rational(1, 8), 0, 0}, {0, 0, Rational(1, 10), 0}, {0, 0, 0, -1}});
  CHECK(s.b.Q == std::vector<Row>{{Rational(1, 4), 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, -1}, {0, 0, -1, 0}});
  REQUIRE(std::holds_alternative<eccd::EulerMotion>(s.b.motion));
  const auto& em = std::get<eccd::EulerMotion>(s.b.motion);
  CHECK(em.e[0] == P({"1"}));
  CHECK(em.e[1] == P({"0", "1"}));
  CHECK(em.e[2].is_zero());
  CHECK(em.v[0] == P({"1", "2"}));
  CHECK(em.v[2] == P({"-3/2"}));
  CHECK(em.v3 == P({"2"}));
  REQUIRE(s.answer.has_value());
  CHECK(s.answer->collides);
  REQUIRE(s.answer->intervals.size() == 1);
  CHECK(*s.answer->intervals[0].first.lo == Rational(1, 4));
  CHECK(*s.answer->intervals[0].second.hi == Rational(1));
  REQUIRE(s.answer->first_contact.has_value());
  REQUIRE(s.answer->contacts.size() == 1);
  CHECK(*s.answer->contacts[0].lo == Rational(1, 5));

  // translation_denominator defaults to 1; JSON integers and big integers are exact.
  j["b"]["motion"].erase("translation_denominator");
  j["b"]["motion"]["translation"] = json::array({17, "0", 0});
  std::string text = j.dump();
  const std::string big = "123456789012345678901234567890";
  text.replace(text.find("17"), 2, big);
  s = eccd::parse_scene(text, kLabel);
  const auto& em2 = std::get<eccd::EulerMotion>(s.b.motion);
  CHECK(em2.v3 == P({"1"}));
  CHECK(em2.v[0] == RPoly::constant(Rational(big)));
}

TEST_CASE("other valid forms: general matrix shape, cycloidal, string dim, null answer", "[scene_reader]") {
  json j = base2d();
  // Rotated, shifted ellipse: 2x^2 + 2xy + 2y^2 - 2x - 1 <= 0 (scaled arbitrarily).
  j["a"]["shape"] = matrix_shape({{"4", "2", "-2"}, {"2", "4", "0"}, {"-2", "0", "-2"}});
  j["b"]["motion"] =
      json::parse(R"({"type": "cycloidal", "angle_over_pi": ["0", "1/2"], "translation": [["1", "-2"], ["0.5", 3]]})");
  j["dim"] = "2";
  j["answer"] = nullptr;
  eccd::Scene s = eccd::parse_scene(j.dump(), kLabel);
  CHECK(s.a.Q[0][1] == Rational(2));
  REQUIRE(std::holds_alternative<eccd::CycloidalMotion>(s.b.motion));
  const auto& c = std::get<eccd::CycloidalMotion>(s.b.motion);
  CHECK(c.theta1 == Rational(1, 2));
  CHECK(c.x[1] == Rational(-2));
  CHECK(c.y[0] == Rational(1, 2));
  CHECK(c.y[1] == Rational(3));
  CHECK_FALSE(s.answer.has_value());
}

// ---------------------------------------------------------------------------
// Bad input: one check per kind of error.

TEST_CASE("malformed JSON gives line and column", "[scene_reader]") {
  expect_error(std::string("{\n  \"format\": \"ellipse-ccd-scene/1\",\n  \"name\": \"x\",,\n}"), "line 3, column 15",
               "malformed JSON");
  expect_error(std::string(""), "line 1, column 1", "malformed JSON");
  expect_error(std::string("{\"a\": 1} trailing"), "line 1, column 12", "malformed JSON");
  expect_error(std::string("{\"a\": 1e400}"), "line 1, column 11", "number overflow");
}

TEST_CASE("top level must be an object with the right format", "[scene_reader]") {
  expect_error(std::string("[1, 2]"), "top level", "must be a JSON object");
  expect_error(std::string("\"scene\""), "top level", "must be a JSON object");
  json j = base2d();
  j.erase("format");
  expect_error(j, "top level", "missing required key \"format\"");
  j["format"] = "ellipse-ccd-scene/2";
  expect_error(j, "/format", "unsupported format \"ellipse-ccd-scene/2\"");
  j["format"] = 1;
  expect_error(j, "/format", "unsupported format");
}

TEST_CASE("missing required keys are named", "[scene_reader]") {
  for (const char* key : {"name", "dim", "a", "b"}) {
    json j = base2d();
    j.erase(key);
    expect_error(j, "top level", std::string("missing required key \"") + key + "\"");
  }
  json j = base2d();
  j["a"].erase("motion");
  expect_error(j, "/a", "missing required key \"motion\"");
  j = base2d();
  j["b"].erase("shape");
  expect_error(j, "/b", "missing required key \"shape\"");
  j = base2d();
  j["b"]["motion"].erase("type");
  expect_error(j, "/b/motion", "missing required key \"type\"");
  j = base2d();
  j["b"]["motion"].erase("d");
  expect_error(j, "/b/motion", "missing required key \"d\"");
  j = base2d();
  j["name"] = "";
  expect_error(j, "/name", "non-empty string");
  j = base2d();
  j["note"] = 5;
  expect_error(j, "/note", "note must be a string");
}

TEST_CASE("unknown keys are named, with the allowed ones", "[scene_reader]") {
  json j = base2d();
  j["colour"] = "red";
  expect_error(
      j, "/colour",
      "unknown key \"colour\" in a scene; allowed keys: format, name, dim, a, b, note, parameters, answer");  // parameters:
                                                                                                              // issue
                                                                                                              // 20
                                                                                                              // (scene-format.md,
                                                                                                              // independent
                                                                                                              // motions)
  j = base2d();
  j["a"]["velocity"] = "1";
  expect_error(j, "/a/velocity", "unknown key \"velocity\" in object a; allowed keys: shape, motion");
  j = base2d();
  j["a"]["shape"]["radius"] = "1";
  expect_error(j, "/a/shape/radius", "allowed keys: semi_axes, semi_axes_squared, matrix");
  j = base2d();
  j["b"]["motion"]["e"] = json::array();
  expect_error(j, "/b/motion/e", "unknown key \"e\" in a kinematic motion; allowed keys: type, d");
  j = base2d();
  j["a"]["motion"]["m"] = "1";
  expect_error(j, "/a/motion/m", "unknown key \"m\" in a static motion; allowed keys: type");
  j = base2d();
  j["b"]["motion"]["d"][2] = json{{"bernstein", {"1"}}, {"power", {"1"}}};
  expect_error(j, "/b/motion/d/2/power", "allowed keys: bernstein");
  j = base2d();
  j["answer"] = json{{"collides", false}, {"verdict", "free"}};
  expect_error(j, "/answer/verdict", "allowed keys: collides, intervals, first_contact, contacts");
  j = base2d();
  j["answer"] = json::parse(R"({"collides": true, "intervals": [[{"approx": "0", "lo": "0", "hi": "0", "eps": "1"},
                                 {"approx": "1", "lo": "1", "hi": "1"}]]})");
  expect_error(j, "/answer/intervals/0/0/eps", "allowed keys: approx, lo, hi");
  // Key with '/' and '~' is escaped in the pointer.
  j = base2d();
  j["a/b~c"] = 1;
  expect_error(j, "/a~1b~0c", "unknown key \"a/b~c\"");
}

TEST_CASE("duplicate keys are errors", "[scene_reader]") {
  std::string text = base2d().dump();
  text.insert(1, "\"name\": \"first\", ");
  expect_error(text, "/name", "duplicate key \"name\"");
}

TEST_CASE("JSON numbers with a fraction part or exponent are rejected", "[scene_reader]") {
  json j = base2d();
  j["a"]["shape"]["semi_axes"][1] = 1.8;
  expect_error(j, "/a/shape/semi_axes/1", "write it as a string \"1.8\"");
  std::string text = base2d().dump();
  text.replace(text.find("\"-3\""), 4, "-3e0");
  expect_error(text, "/b/motion/d/1", "write it as a string \"-3e0\"");
  j = base2d();
  j["dim"] = 2.0;
  expect_error(j, "/dim", "fraction part or exponent");
}

TEST_CASE("bad number strings and wrong types name their place", "[scene_reader]") {
  json j = base2d();
  j["a"]["shape"]["semi_axes"][0] = "abc";
  expect_error(j, "/a/shape/semi_axes/0", "\"abc\" is not an exact number");
  j["a"]["shape"]["semi_axes"][0] = "1/0";
  expect_error(j, "/a/shape/semi_axes/0", "zero denominator");
  j["a"]["shape"]["semi_axes"][0] = true;
  expect_error(j, "/a/shape/semi_axes/0", "expected a number");
  j = base2d();
  j["b"]["motion"]["d"][0] = json::array();
  expect_error(j, "/b/motion/d/0", "empty coefficient array");
  j["b"]["motion"]["d"][0] = json{{"bernstein", json::array()}};
  expect_error(j, "/b/motion/d/0/bernstein", "empty Bernstein coefficient array");
  j["b"]["motion"]["d"][0] = nullptr;
  expect_error(j, "/b/motion/d/0", "expected a polynomial");
  j["b"]["motion"]["d"] = json::array({"1", "2", "3"});
  expect_error(j, "/b/motion/d", "must have 4 entries");
}

TEST_CASE("dim must be 2 or 3", "[scene_reader]") {
  json j = base2d();
  j["dim"] = 4;
  expect_error(j, "/dim", "dim must be 2 (ellipses) or 3 (ellipsoids), got 4");
  j["dim"] = "5/2";
  expect_error(j, "/dim", "got 5/2");
}

TEST_CASE("shapes: exactly one kind, right size, positive", "[scene_reader]") {
  json j = base2d();
  j["a"]["shape"] = json::object();
  expect_error(j, "/a/shape", "needs exactly one of");
  j["a"]["shape"] = json{{"semi_axes", {"1", "2"}}, {"semi_axes_squared", {"1", "4"}}};
  expect_error(j, "/a/shape", "this one has semi_axes and semi_axes_squared");
  j["a"]["shape"] = json{{"semi_axes", {"1", "2", "3"}}};
  expect_error(j, "/a/shape/semi_axes", "must have 2 entries (dim 2), got 3");
  j["a"]["shape"] = json{{"semi_axes", {"1", "-2"}}};
  expect_error(j, "/a/shape/semi_axes/1", "must be positive, got -2");
  j["a"]["shape"] = json{{"semi_axes_squared", {"0", "2"}}};
  expect_error(j, "/a/shape/semi_axes_squared/0", "must be positive, got 0");
  j["a"]["shape"] = "circle";
  expect_error(j, "/a/shape", "must be a JSON object");
}

TEST_CASE("matrix shapes: size and symmetry", "[scene_reader]") {
  json j = base2d();
  j["a"]["shape"] = matrix_shape({{"1", "0"}, {"0", "1"}});
  expect_error(j, "/a/shape/matrix", "symmetric 3x3");
  j["a"]["shape"] = matrix_shape({{"1", "0", "0"}, {"0", "1"}, {"0", "0", "-1"}});
  expect_error(j, "/a/shape/matrix/1", "must have 3 entries (dim 2), got 2");
  j["a"]["shape"] = matrix_shape({{"1", "1/2", "0"}, {"1/3", "1", "0"}, {"0", "0", "-1"}});
  expect_error(j, "/a/shape/matrix/1/0", "not symmetric");
}

TEST_CASE("matrix shapes: conics that are not real ellipses are named", "[scene_reader]") {
  struct Case {
    std::initializer_list<std::initializer_list<const char*>> m;
    const char* phrase;
  };
  const Case cases[] = {
      {{{"1", "0", "0"}, {"0", "1", "0"}, {"0", "0", "1"}}, "is an imaginary ellipse"},
      {{{"1", "0", "0"}, {"0", "2", "0"}, {"0", "0", "0"}}, "is a single point"},
      {{{"1", "0", "0"}, {"0", "-1", "0"}, {"0", "0", "-1"}}, "is a hyperbola"},
      {{{"1", "0", "0"}, {"0", "0", "-1"}, {"0", "-1", "0"}}, "is a parabola"},
      {{{"1", "0", "0"}, {"0", "-1", "0"}, {"0", "0", "0"}}, "is degenerate (det Q = 0)"},
      {{{"1", "0", "0"}, {"0", "0", "0"}, {"0", "0", "-1"}}, "is degenerate (det Q = 0)"},
      {{{"0", "0", "1"}, {"0", "0", "0"}, {"1", "0", "-1"}}, "is degenerate (det Q = 0)"},
      {{{"-1", "0", "0"}, {"0", "-1", "0"}, {"0", "0", "1"}},
       "has the wrong sign: X^T Q X > 0 inside; negate the matrix"},
      {{{"-1", "0", "0"}, {"0", "-1", "0"}, {"0", "0", "-1"}}, "is an imaginary ellipse"},
      // Rotated: 2x^2 + 2xy + 2y^2 + 1 has no real point.
      {{{"2", "1", "0"}, {"1", "2", "0"}, {"0", "0", "1"}}, "is an imaginary ellipse"},
      // Rotated hyperbola with zero diagonal: xy - 1.
      {{{"0", "1/2", "0"}, {"1/2", "0", "0"}, {"0", "0", "-1"}}, "is a hyperbola"},
  };
  for (const auto& c : cases) {
    json j = base2d();
    j["a"]["shape"] = matrix_shape(c.m);
    INFO("expected: " << c.phrase);
    expect_error(j, "/a/shape/matrix", c.phrase);
  }
}

TEST_CASE("matrix shapes: quadrics that are not real ellipsoids are named", "[scene_reader]") {
  struct Case {
    std::initializer_list<std::initializer_list<const char*>> m;
    const char* phrase;
  };
  const Case cases[] = {
      {{{"1", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "1", "0"}, {"0", "0", "0", "1"}},
       "is an imaginary ellipsoid"},
      {{{"1", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "1", "0"}, {"0", "0", "0", "0"}}, "is a single point"},
      {{{"1", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "-1", "0"}, {"0", "0", "0", "-1"}},
       "hyperboloid of one sheet"},
      {{{"1", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "-1", "0"}, {"0", "0", "0", "1"}},
       "hyperboloid of two sheets"},
      {{{"1", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "-1", "0"}, {"0", "0", "0", "0"}}, "a cone"},
      {{{"1", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "0", "-1"}, {"0", "0", "-1", "0"}},
       "elliptic paraboloid"},
      {{{"1", "0", "0", "0"}, {"0", "-1", "0", "0"}, {"0", "0", "0", "-1"}, {"0", "0", "-1", "0"}},
       "hyperbolic paraboloid"},
      {{{"1", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "0", "0"}, {"0", "0", "0", "-1"}},
       "is degenerate (det Q = 0)"},
      {{{"-1", "0", "0", "0"}, {"0", "-1", "0", "0"}, {"0", "0", "-1", "0"}, {"0", "0", "0", "1"}},
       "negate the matrix"},
  };
  for (const auto& c : cases) {
    json j = base3d();
    j["b"]["shape"] = matrix_shape(c.m);
    INFO("expected: " << c.phrase);
    expect_error(j, "/b/shape/matrix", c.phrase);
  }
}

TEST_CASE("motion types: unknown, missing, wrong dimension", "[scene_reader]") {
  json j = base2d();
  j["a"]["motion"]["type"] = "spline";
  expect_error(j, "/a/motion/type",
               "unknown motion type \"spline\"; allowed types: static, matrix, kinematic, euler, cycloidal");
  j["a"]["motion"]["type"] = 3;
  expect_error(j, "/a/motion/type", "must be a string");
  j["a"]["motion"] = json::parse(R"({"type": "euler", "e": ["1", "0", "0", "0"], "translation": ["0", "0", "0"]})");
  expect_error(j, "/a/motion/type", "motion type \"euler\" is for dim 3 only, but this scene has dim 2");
  j = base3d();
  j["a"]["motion"] = json::parse(R"({"type": "kinematic", "d": ["0", "0", "1", "0"]})");
  expect_error(j, "/a/motion/type", "motion type \"kinematic\" is for dim 2 only, but this scene has dim 3");
  j["a"]["motion"] =
      json::parse(R"({"type": "cycloidal", "angle_over_pi": ["0", "1"], "translation": [["0", "0"], ["0", "0"]]})");
  expect_error(j, "/a/motion/type", "motion type \"cycloidal\" is for dim 2 only");
}

TEST_CASE("matrix motions: size, last row, w(t), affine block", "[scene_reader]") {
  json j = base2d();
  auto set_m = [&](const char* m) {
    j["b"]["motion"] = json::parse(std::string(R"({"type": "matrix", "m": )") + m + "}");
  };
  set_m(R"([["1", "0"], ["0", "1"]])");
  expect_error(j, "/b/motion/m", "must be a 3x3 array");
  set_m(R"([["1", "0", "0"], ["0", "1", "0"], ["0", "0"]])");
  expect_error(j, "/b/motion/m/2", "must have 3 polynomials");
  set_m(R"([["1", "0", "0"], ["0", "1", "0"], ["0", ["0", "1"], "1"]])");
  expect_error(j, "/b/motion/m/2/1", "the last row of the motion matrix must be (0, 0, w(t))");
  set_m(R"([["1", "0", "0"], ["0", "1", "0"], [["0", "0"], "0", ["-1", "3"]]])");
  expect_error(j, "/b/motion/m/2/2", "w(t) vanishes on [0, 1]: w(t) = 0 at t = 1/3");
  set_m(R"([["1", "0", "0"], ["0", "1", "0"], ["0", "0", ["-1/2", "0", "1"]]])");  // root sqrt(1/2)
  expect_error(j, "/b/motion/m/2/2", "w(t) vanishes on [0, 1]: w(t) = 0 at t in [");
  set_m(R"([["1", "0", "0"], ["0", "1", "0"], ["0", "0", ["1", "-1"]]])");
  expect_error(j, "/b/motion/m/2/2", "w(t) = 0 at t = 1");
  set_m(R"([["1", "0", "0"], ["0", "1", "0"], ["0", "0", "0"]])");
  expect_error(j, "/b/motion/m/2/2", "w(t) is identically zero");
  set_m(R"([[["-1/2", "1"], "0", "0"], ["0", "1", "0"], ["0", "0", "1"]])");
  expect_error(j, "/b/motion/m", "singular affine block at t = 1/2");
  set_m(R"([["1", "2", "0"], ["1/2", "1", "0"], ["0", "0", "1"]])");
  expect_error(j, "/b/motion/m", "singular affine block for every t");
  // Roots outside [0, 1] are fine; shear is allowed.
  set_m(R"([[["2", "1"], ["0", "3"], "5"], ["0", "1", "0"], ["0", "0", ["2", "-1"]]])");
  CHECK_NOTHROW(eccd::parse_scene(j.dump(), kLabel));
  // 3D: the upper-left block is 3x3.
  j = base3d();
  j["a"]["motion"] = json::parse(R"({"type": "matrix", "m": [["1","0","0","0"],["0","1","0","0"],
                                      ["0","0",["-1","4"],"0"],["0","0","0","1"]]})");
  expect_error(j, "/a/motion/m", "singular affine block at t = 1/4");
}

TEST_CASE("kinematic and euler denominators must not vanish", "[scene_reader]") {
  json j = base2d();
  j["b"]["motion"]["d"] = json::parse(R"(["0", "0", ["-1/2", "1"], ["-1", "2"]])");
  expect_error(j, "/b/motion/d", "d2(t)^2 + d3(t)^2 vanishes on [0, 1]: d2(t)^2 + d3(t)^2 = 0 at t = 1/2");
  j["b"]["motion"]["d"] = json::parse(R"(["1", "0", "0", "0"])");
  expect_error(j, "/b/motion/d", "is identically zero");
  j["b"]["motion"]["d"] = json::parse(R"(["1", "0", ["-1/2", "1"], "1"])");  // d3 != 0: fine
  CHECK_NOTHROW(eccd::parse_scene(j.dump(), kLabel));

  j = base3d();
  j["b"]["motion"]["e"] = json::parse(R"([["-1", "1"], "0", "0", ["-1", "1"]])");
  expect_error(j, "/b/motion/e", "E(t) = e0^2 + e1^2 + e2^2 + e3^2 vanishes on [0, 1]");
  j = base3d();
  j["b"]["motion"]["translation_denominator"] = json::parse(R"(["-1", "0", "4"])");
  expect_error(j, "/b/motion/translation_denominator", "the translation denominator v3(t) vanishes on [0, 1]");
  j["b"]["motion"]["translation_denominator"] = "0";
  expect_error(j, "/b/motion/translation_denominator", "is identically zero");
  j = base3d();
  j["b"]["motion"]["translation"] = json::array({"0", "0"});
  expect_error(j, "/b/motion/translation", "must have 3 entries");
}

TEST_CASE("cycloidal motions: sizes", "[scene_reader]") {
  json j = base2d();
  j["b"]["motion"] =
      json::parse(R"({"type": "cycloidal", "angle_over_pi": ["0"], "translation": [["0", "0"], ["0", "0"]]})");
  expect_error(j, "/b/motion/angle_over_pi", "must have 2 entries");
  j["b"]["motion"] =
      json::parse(R"({"type": "cycloidal", "angle_over_pi": ["0", "1"], "translation": [["0", "0"], ["0"]]})");
  expect_error(j, "/b/motion/translation/1", "must have 2 entries");
  j["b"]["motion"] = json::parse(R"({"type": "cycloidal", "angle_over_pi": ["0", "1"]})");
  expect_error(j, "/b/motion", "missing required key \"translation\"");
}

TEST_CASE("stored answers are validated", "[scene_reader]") {
  json j = base2d();
  j["answer"] = json::parse(R"({"collides": "yes"})");
  expect_error(j, "/answer/collides", "must be true or false");
  j["answer"] = json::parse(R"({"intervals": []})");
  expect_error(j, "/answer", "missing required key \"collides\"");
  j["answer"] = json::parse(R"({"collides": true, "first_contact": {"approx": "0.5", "lo": "3/5", "hi": "1/2"}})");
  expect_error(j, "/answer/first_contact", "lo > hi");
  j["answer"] = json::parse(R"({"collides": true, "first_contact": {"approx": "0.5", "lo": "1/2"}})");
  expect_error(j, "/answer/first_contact", "both null");
  j["answer"] = json::parse(R"({"collides": true, "contacts": [{"lo": null, "hi": null}]})");
  expect_error(j, "/answer/contacts/0", "missing required key \"approx\"");
  j["answer"] = json::parse(R"({"collides": true, "intervals": [[{"approx": "0.5"}]]})");
  expect_error(j, "/answer/intervals/0", "array of 2 instants");
  j["answer"] = json::parse(R"({"collides": false, "intervals": [[{"approx": "0.5"}, {"approx": "0.6"}]]})");
  expect_error(j, "/answer/intervals", "collides is false but intervals is not empty");
  j["answer"] = json::parse(R"({"collides": true, "intervals": []})");
  expect_error(j, "/answer/intervals", "collides is true but intervals is empty");
  j["answer"] = json::parse(R"({"collides": true, "contacts": [{"approx": "0.5", "lo": 0.4, "hi": "1/2"}]})");
  expect_error(j, "/answer/contacts/0/lo", "write it as a string \"0.4\"");
  j["answer"] = json::parse(R"({"collides": false})");
  eccd::Scene s = eccd::parse_scene(j.dump(), kLabel);
  REQUIRE(s.answer.has_value());
  CHECK_FALSE(s.answer->collides);
  CHECK(s.answer->intervals.empty());
  CHECK_FALSE(s.answer->first_contact.has_value());
}

TEST_CASE("answer_to_json / answer_from_json round trip", "[scene_reader]") {
  eccd::Answer a;
  a.collides = true;
  eccd::Instant t0{"0.1699", Rational(1, 6), Rational(171, 1000)};
  eccd::Instant t1{"1", Rational(1), Rational(1)};
  eccd::Instant u{"0.5", std::nullopt, std::nullopt};
  a.intervals = {{t0, t1}, {u, u}};
  a.first_contact = t0;
  a.contacts = {t0, u};
  json j = eccd::answer_to_json(a);
  CHECK(j["intervals"][0][0]["lo"] == "1/6");
  CHECK(j["intervals"][0][1]["hi"] == "1");
  CHECK(j["intervals"][1][0]["lo"].is_null());
  CHECK(j.size() == 4);  // no extras when empty
  eccd::Answer b = eccd::answer_from_json(json::parse(j.dump()), kLabel, "/answer");
  CHECK(b.collides);
  REQUIRE(b.intervals.size() == 2);
  CHECK(b.intervals[0].first.approx == "0.1699");
  CHECK(*b.intervals[0].first.lo == Rational(1, 6));
  CHECK(*b.intervals[0].first.hi == Rational(171, 1000));
  CHECK(*b.intervals[0].second.lo == Rational(1));
  CHECK_FALSE(b.intervals[1].first.certified());
  REQUIRE(b.first_contact.has_value());
  CHECK(*b.first_contact->hi == Rational(171, 1000));
  REQUIRE(b.contacts.size() == 2);
  CHECK_FALSE(b.contacts[1].certified());
  CHECK(eccd::answer_to_json(b) == j);

  eccd::Answer none;
  json jn = eccd::answer_to_json(none);
  CHECK(jn["first_contact"].is_null());
  CHECK(jn["intervals"].empty());
  CHECK_FALSE(eccd::answer_from_json(jn, kLabel, "/answer").collides);

  // Extras are written only when present, and are not part of a stored answer.
  a.undecided = {u};
  json je = eccd::answer_to_json(a);
  CHECK(je.contains("undecided"));
  CHECK_THROWS_WITH(eccd::answer_from_json(je, kLabel, "/answer"),
                    Catch::Contains(kLabel + ": /answer/undecided: unknown key \"undecided\""));
}

TEST_CASE("read_scene_file reports unreadable files", "[scene_reader]") {
  CHECK_THROWS_WITH(eccd::read_scene_file("/nonexistent/scene.json"),
                    Catch::StartsWith("/nonexistent/scene.json: cannot read the file"));
}

TEST_CASE("truncated or mangled files give SceneError, never anything else", "[scene_reader]") {
  json j = base3d();
  j["answer"] = json::parse(R"({"collides": true,
      "intervals": [[{"approx": "0.25", "lo": "1/4", "hi": "1/4"}, {"approx": "1", "lo": "1", "hi": "1"}]],
      "first_contact": {"approx": "0.25", "lo": "1/4", "hi": "1/4"}, "contacts": []})");
  const std::string text = j.dump();
  REQUIRE_NOTHROW(eccd::parse_scene(text, kLabel));
  int errors = 0;
  auto attempt = [&](const std::string& t) {
    try {
      eccd::parse_scene(t, kLabel);
    } catch (const SceneError& e) {
      ++errors;
      CHECK(std::string(e.what()).rfind(kLabel + ": ", 0) == 0);
    }
  };
  for (std::size_t n = 0; n < text.size(); ++n) attempt(text.substr(0, n));  // every prefix
  for (std::size_t i = 0; i < text.size(); ++i) {                            // every one-character change
    std::string t = text;
    t.erase(i, 1);
    attempt(t);
    for (char c : {'0', '-', '"', '[', '{', '/', '.', 'e'}) {
      t = text;
      t[i] = c;
      attempt(t);
    }
  }
  CHECK(errors > int(text.size()));
  attempt(std::string(200, '[') + std::string(200, ']'));  // deep nesting
  attempt(std::string("\xff\xfe{}", 4));                   // not UTF-8
}

}  // namespace ECCD_UNITY_ID
