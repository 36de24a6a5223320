// The typed API (api/solve.hpp, api/options.hpp, api/solution.hpp): the
// README's "C++ API" example as written, the Solution against the scene's
// stored exact answer, Instant::value, option names, errors, and the JSON
// writer (io/solution_json.hpp) over the typed Solution.
#include <eccd/eccd.hpp>

#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace ECCD_UNITY_ID {
namespace {

const std::string kCases = std::string(ECCD_SOURCE_DIR) + "/cases/";

// The README's example (section "C++ API"), with std::cout as a parameter.
void readme_example(std::ostream& out) {
  eccd::Scene scene = eccd::read_scene("cases/paper002/example.json");
  eccd::Solution r = eccd::solve(scene);  // exact by default
  out << "collides: " << std::boolalpha << r.answer.collides << "\n";
  for (const auto& [from, to] : r.answer.intervals)
    out << "[" << from.approx << ", " << to.approx << "], ends in [" << from.lo->get_str() << ", " << from.hi->get_str()
        << "] and [" << to.lo->get_str() << ", " << to.hi->get_str() << "]\n";
}

bool overlaps(const eccd::Instant& a, const eccd::Instant& b) { return *a.lo <= *b.hi && *b.lo <= *a.hi; }

}  // namespace

TEST_CASE("the README's C++ API example solves paper 002's example exactly: two collision intervals", "[api]") {
  struct Cwd {  // the example opens cases/... relative to the source tree, as the README runs it
    std::string old = std::filesystem::current_path().string();
    Cwd() { std::filesystem::current_path(ECCD_SOURCE_DIR); }
    ~Cwd() { std::filesystem::current_path(old); }
  } cwd;
  std::ostringstream out;
  readme_example(out);
  std::string text = out.str();
  CHECK(text.rfind("collides: true\n", 0) == 0);
  CHECK(std::count(text.begin(), text.end(), '\n') == 3);  // the line of collides and two intervals
  CHECK(text.find("[0.1698797168") != std::string::npos);  // 002's first interval starts near t = 0.1699
}

TEST_CASE("solve: exact Solution matches the stored answer, every instant has a bracket and a value inside it",
          "[api]") {
  for (const char* file : {"paper002/example.json", "paper003/example2.json", "rolling/circles-rolling.json"}) {
    INFO(file);
    eccd::Scene s = eccd::read_scene(kCases + file);
    REQUIRE(s.answer);
    eccd::Solution r = eccd::solve(s);
    CHECK(r.certified);
    CHECK(r.decided());
    CHECK(r.arith.name() == "exact");
    CHECK(r.answer.collides == s.answer->collides);
    REQUIRE(r.answer.intervals.size() == s.answer->intervals.size());
    for (std::size_t k = 0; k < r.answer.intervals.size(); ++k) {
      CHECK(overlaps(r.answer.intervals[k].first, s.answer->intervals[k].first));
      CHECK(overlaps(r.answer.intervals[k].second, s.answer->intervals[k].second));
    }
    CHECK(r.answer.contacts.size() == s.answer->contacts.size());
    auto check_value = [](const eccd::Instant& i) {
      REQUIRE(i.certified());
      REQUIRE(std::isfinite(i.value));
      // the double nearest the bracket's midpoint: within one rounding of the bracket
      CHECK(i.value >= i.lo->get_d() * (1 - 1e-15) - 1e-300);
      CHECK(i.value <= i.hi->get_d() * (1 + 1e-15) + 1e-300);
    };
    for (const auto& [a, b] : r.answer.intervals) {
      check_value(a);
      check_value(b);
    }
    for (const auto& c : r.answer.contacts) check_value(c);
    for (const auto& c : r.critical) check_value(c.t);
    // the stored answer's instants get their value from the approx text
    for (const auto& [a, b] : s.answer->intervals) CHECK(std::abs(a.value - std::stod(a.approx)) == 0);
  }
}

TEST_CASE("solve: double and certified runs of paper 002's example, typed", "[api]") {
  eccd::Scene s = eccd::read_scene(kCases + "paper002/example.json");
  eccd::Solution ex = eccd::solve(s);
  eccd::SolveOptions o;
  o.arith = eccd::Arithmetic::double_precision();
  eccd::Solution d = eccd::solve(s, o);
  CHECK(d.method == "bezier");
  CHECK(d.projection == "bezier");
  CHECK_FALSE(d.certified);
  CHECK(d.input == eccd::InputMode::rounded);
  CHECK(d.answer.collides);
  REQUIRE(d.answer.intervals.size() == ex.answer.intervals.size());
  for (std::size_t k = 0; k < d.answer.intervals.size(); ++k) {
    CHECK(std::isfinite(d.answer.intervals[k].first.value));
    CHECK(std::abs(d.answer.intervals[k].first.value - ex.answer.intervals[k].first.value) < 1e-6);
  }
  CHECK(eccd::summary_text(d).find("F(u,t) of degree") != std::string::npos);
  CHECK(eccd::summary_text(ex).find("discriminant degree") != std::string::npos);

  o.arith = eccd::Arithmetic::certified();
  eccd::Solution c = eccd::solve(s, o);
  CHECK(c.certified);
  // 002's example leaves the projection's interval rung (tests/certified) but is decided by the interval Bézier
  // proof, the first 3D rung (certified/bezier_proof.hpp), before any escalation.
  CHECK(c.decided_in == "bezier");
  CHECK(c.escalations.empty());
  CHECK(c.answer.intervals.size() == ex.answer.intervals.size());

  o.method = eccd::Method::sampling;  // a grid of 0 instants is refused
  o.arith = eccd::Arithmetic::double_precision();
  CHECK_THROWS_AS(eccd::solve(s, o), std::invalid_argument);
}

TEST_CASE("option names: arithmetic and method parse and print back", "[api]") {
  for (const char* a : {"double", "exact", "mpfr:128", "certified", "certified:none", "certified:128,1024"})
    CHECK(eccd::parse_arithmetic(a).name() == a);
  CHECK(eccd::parse_arithmetic("double").precision_bits() == 53);
  CHECK(eccd::parse_arithmetic("certified").precision_bits() == 53);
  CHECK(eccd::parse_arithmetic("mpfr:200").precision_bits() == 200);
  CHECK(eccd::parse_arithmetic("exact").precision_bits() == 0);
  CHECK(eccd::Arithmetic::mpfr(64).name() == "mpfr:64");
  CHECK(eccd::Arithmetic::certified({}).name() == "certified:none");
  CHECK_THROWS_AS(eccd::parse_arithmetic("mpfr:12"), std::invalid_argument);
  CHECK(eccd::parse_method("marching:40") == std::pair{eccd::Method::marching, 40});
  CHECK(eccd::parse_method("bezier").first == eccd::Method::bezier);
  CHECK_THROWS_WITH(eccd::parse_method("sampling:0"), Catch::Contains("--method sampling:0"));
  eccd::SolveOptions o;
  std::tie(o.method, o.grid) = eccd::parse_method("sampling:64");
  CHECK(o.method_name() == "sampling:64");
}

TEST_CASE("read_scene and scene_from_text: errors name the file and the place", "[api]") {
  CHECK_THROWS_WITH(eccd::read_scene(kCases + "no-such-file.json"), Catch::Contains("no-such-file.json"));
  CHECK_THROWS_WITH(eccd::scene_from_text("{\"format\": 1}", "mine"), Catch::StartsWith("mine: "));
  eccd::Scene s = eccd::read_scene(kCases + "paper003/example2.json");
  eccd::Scene t = eccd::scene_from_text(eccd::read_file_bytes(kCases + "paper003/example2.json"), "copy");
  CHECK(t.path == "copy");
  CHECK(eccd::solve(t).answer.intervals.size() == eccd::solve(s).answer.intervals.size());
}

TEST_CASE("solution_to_json writes the Solution's values under the solve --json keys", "[api]") {
  eccd::Scene s = eccd::read_scene(kCases + "paper003/example2.json");
  eccd::SolveOptions o;
  o.variant = eccd::Variant::first_contact;
  eccd::Solution r = eccd::solve(s, o);
  nlohmann::json j = eccd::solution_to_json(r);
  CHECK(j["arith"] == "exact");
  CHECK(j["variant"] == "first-contact");
  CHECK(j["intervals"].is_null());  // 2D variant 2 does not compute intervals
  CHECK(j["projection_degree"] == r.projection_degree);
  CHECK(j["critical_instants"].size() == r.critical.size());
  CHECK(j["method"] == "cd-disc");
  REQUIRE(r.answer.first_contact);
  CHECK(j["first_contact"]["lo"] == r.answer.first_contact->lo->get_str());
  nlohmann::ordered_json stored = eccd::stored_answer_of(r);
  CHECK(stored.begin().key() == "collides");
}

}  // namespace ECCD_UNITY_ID
