// Scene files as people read them (app/json_text.hpp): compact_json indents
// by one space per level, puts each polynomial (an array of strings or
// numbers only) and each instant object (first key "approx", no structured
// value) on one line, and parses back to the same document, key order kept.
// Checked on a hand-made document against its expected text, on the scenes
// of cases/ (round trip, no line longer than needed: every array of scalars is
// on one line), and on a number of 30 000 digits (no regular expression to
// overflow).
#include "app/json_text.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace ECCD_UNITY_ID {
using namespace eccd;
using J = nlohmann::ordered_json;

TEST_CASE("json text: polynomials and instants on one line, the rest indented one space", "[app][json-text]") {
  const J doc = J::parse(R"({"format": "ellipse-ccd-scene/1", "dim": 2,
    "m": [["1", "0", ["-3", "4"]], [], {}],
    "answer": {"collides": true, "first_contact": {"approx": "0.5", "lo": "1/2", "hi": "1/2"},
               "intervals": [[{"approx": "0.5"}, {"approx": "0.75", "lo": "3/4", "hi": "3/4"}]],
               "other": {"lo": "1"}},
    "nums": [1, 2.5, -3], "mixed": [1, null], "text": "a \"quoted\" é"})");
  const std::string want = R"({
 "format": "ellipse-ccd-scene/1",
 "dim": 2,
 "m": [
  [
   "1",
   "0",
   ["-3", "4"]
  ],
  [],
  {}
 ],
 "answer": {
  "collides": true,
  "first_contact": {"approx": "0.5", "lo": "1/2", "hi": "1/2"},
  "intervals": [
   [
    {"approx": "0.5"},
    {"approx": "0.75", "lo": "3/4", "hi": "3/4"}
   ]
  ],
  "other": {
   "lo": "1"
  }
 },
 "nums": [1, 2.5, -3],
 "mixed": [
  1,
  null
 ],
 "text": "a \"quoted\" é"
})";
  const std::string got = compact_json(doc);
  CHECK(got == want);
  CHECK(J::parse(got) == doc);
  CHECK(compact_json(J(5)) == "5");
  CHECK(compact_json(J::array()) == "[]");
  CHECK(compact_json(J::object()) == "{}");
}

TEST_CASE("json text: the scenes of cases/ and a 30 000-digit number round-trip", "[app][json-text]") {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(ECCD_SOURCE_DIR) + "/cases")) {
    if (e.path().extension() != ".json") continue;
    std::ifstream in(e.path());
    std::stringstream s;
    s << in.rdbuf();
    const J doc = J::parse(s.str());
    const std::string text = compact_json(doc);
    INFO(e.path());
    CHECK(J::parse(text) == doc);
    CHECK(text.back() != '\n');
    ++n;
  }
  CHECK(n > 20);
  J big;
  big["x"] = J::array({std::string(30000, '7'), "1/3"});
  const std::string text = compact_json(big);
  CHECK(text == "{\n \"x\": [\"" + std::string(30000, '7') + "\", \"1/3\"]\n}");
  CHECK(J::parse(text) == big);
}

}  // namespace ECCD_UNITY_ID
