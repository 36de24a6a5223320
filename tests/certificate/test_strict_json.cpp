// The certificate checker's strict JSON parse (certificate/check/strict_json.hpp):
//   - the same DOM as nlohmann's parser on ordinary documents;
//   - the first duplicate key is recorded with its JSON place (the first
//     value kept), nesting deeper than 64 levels is recorded, 64 levels are
//     not;
//   - an integer beyond 64 bits is kept exactly, as the string of its digits
//     (either sign); a number with a fraction or exponent becomes
//     "json-float:TEXT", so a rounded 1.8 cannot pass as 9/5;
//   - malformed text throws JsonTextError "LABEL: not valid JSON: byte N: ...";
//   - a duplicate key whose first value is a number and whose second is an
//     object or array: recorded as any duplicate.
#include "certificate/check/strict_json.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using eccd::check::JsonTextError;
using eccd::check::parse_strict;

TEST_CASE("check parse_strict builds the ordinary DOM", "[certificate][strict_json]") {
  const std::string text =
      R"({"a": [1, -2, {"b": null, "c": true}], "d": "x\u00e9", "e": {}, "f": [], "g": 18446744073709551615})";
  const auto d = parse_strict(text, "doc");
  CHECK(d.structure_problem.empty());
  CHECK(d.value == nlohmann::json::parse(text));
  CHECK(parse_strict("[]", "doc").value == nlohmann::json::array());
  CHECK(parse_strict("7", "doc").value == 7);
}

TEST_CASE("check parse_strict records duplicate keys and deep nesting with their place", "[certificate][strict_json]") {
  auto d = parse_strict(R"({"a": 1, "a": 2})", "doc");
  CHECK(d.value["a"] == 1);  // the first kept
  CHECK(d.structure_problem.find("/a: duplicate key \"a\"") != std::string::npos);
  d = parse_strict(R"({"timeline": [{"t": 0}, {"t": 1}, {"t": 2}, {"instant": 1, "instant": 2}]})", "doc");
  CHECK(d.structure_problem == "/timeline/3/instant: duplicate key \"instant\"");
  CHECK(d.value["timeline"][3]["instant"] == 1);
  // only the first problem is kept
  d = parse_strict(R"({"x": {"k": 1, "k": 2}, "y": {"m": 1, "m": 2}})", "doc");
  CHECK(d.structure_problem == "/x/k: duplicate key \"k\"");
  // the same key in different objects is no duplicate
  CHECK(parse_strict(R"({"x": {"k": 1}, "y": {"k": 2}})", "doc").structure_problem.empty());

  auto nested = [](int depth) { return std::string(std::size_t(depth), '[') + std::string(std::size_t(depth), ']'); };
  CHECK(parse_strict(nested(64), "doc").structure_problem.empty());
  d = parse_strict(nested(65), "doc");
  CHECK(d.structure_problem.find("nesting deeper than 64 levels") != std::string::npos);
}

TEST_CASE("check parse_strict keeps big integers exactly and marks floats", "[certificate][strict_json]") {
  const auto d = parse_strict(
      R"({"big": 123456789012345678901234567890, "neg": -98765432109876543210, "f": 1.8, "e": 1e3, "z": -0.0, "i": 42})",
      "doc");
  CHECK(d.structure_problem.empty());
  CHECK(d.value["big"] == "123456789012345678901234567890");
  CHECK(d.value["neg"] == "-98765432109876543210");
  CHECK(d.value["f"] == "json-float:1.8");
  CHECK(d.value["e"] == "json-float:1e3");
  CHECK(d.value["z"] == "json-float:-0.0");
  CHECK(d.value["i"] == 42);
}

TEST_CASE("check parse_strict refuses malformed text with the label and byte", "[certificate][strict_json]") {
  for (const char* bad : {"{", R"({"a": })", "[1, 2,]", "nul", R"({"a" 1})", ""}) {
    INFO(bad);
    try {
      parse_strict(bad, "cert.json");
      FAIL("accepted");
    } catch (const JsonTextError& e) {
      const std::string m = e.what();
      CHECK(m.rfind("cert.json: not valid JSON: ", 0) == 0);
      CHECK(m.find("byte ") != std::string::npos);
    }
  }
}

// A duplicate key whose first value is a scalar and whose second is an object or array: the second value (with
// its members) is set aside and the first kept, so the duplicate is recorded with its place like any other, and
// verdict.cpp rejects the certificate naming the key (not "unreadable" with the JSON library's message).
TEST_CASE("check parse_strict with a scalar then a container under one key", "[certificate][strict_json]") {
  for (const char* text : {R"({"a": 1, "a": {"b": 2}})", R"({"a": 1, "a": [2]})"}) {
    INFO(text);
    std::string problem;
    CHECK_NOTHROW(problem = parse_strict(text, "doc").structure_problem);
    CHECK(problem.find("duplicate key \"a\"") != std::string::npos);
  }
}

}  // namespace ECCD_UNITY_ID
