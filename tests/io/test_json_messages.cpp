// Message text for the strict JSON readers (io/json_messages.hpp), against
// the rules its prose states:
//   - escape_token follows RFC 6901 ('~' -> "~0", '/' -> "~1", in that
//     order: "~1" in a key stays distinguishable from '/'); child builds
//     pointers; place_text says "top level" for "", keeps short pointers and
//     cuts each token of a long one to 80 characters;
//   - shorten_digits: runs of more than 40 digits become the first 20, the
//     count and the last 8 (40 digits stay whole);
//   - quote: JSON-quoted, cut to 80 characters, invalid UTF-8 replaced;
//   - type_name in words; join;
//   - json_error_text: "line L, column C: malformed JSON: reason", from the
//     parser's own line and column when its message has them (checked
//     against a line count of the text here), else from the byte offset; the
//     "[json.exception...]" and "parse error ...: " prefixes dropped; the hint
//     for a number overflow.
#include "io/json_messages.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd::json_messages;

namespace {
// a + b + c by append: GCC 12 reports a false -Wrestrict for "literal" + std::string at -O3 (bug 105329)
std::string cat(const std::string& a, const std::string& b, const std::string& c = "") {
  std::string r = a;
  return r.append(b).append(c);
}
}  // namespace

TEST_CASE("json_messages pointers: escape, child, place_text", "[io][json_messages]") {
  CHECK(escape_token("a/b~c") == "a~1b~0c");
  CHECK(escape_token("~1") == "~01");  // the key "~1" is not the key "/"
  CHECK(escape_token("") == "");
  CHECK(child("", "a") == "/a");
  CHECK(child("/a", "x/y") == "/a/x~1y");
  CHECK(child("/a", std::size_t(3)) == "/a/3");
  CHECK(place_text("") == "top level");
  CHECK(place_text("/a/0/b") == "/a/0/b");
  const std::string long_key(300, 'k');
  const std::string p = place_text(cat("/x/", long_key, "/7"));
  CHECK(p == cat("/x/", std::string(80, 'k'), ".../7"));
}

TEST_CASE("json_messages digits, quotes, type names, join", "[io][json_messages]") {
  const std::string d40(40, '7'), d41 = "1234567890123456789012345678901234567890X";
  CHECK(shorten_digits(cat("n = ", d40)) == cat("n = ", d40));
  std::string run;
  for (int i = 0; i < 100; ++i) run += char('0' + i % 10);
  CHECK(shorten_digits(cat("x", run, "y")) ==
        cat(cat("x", run.substr(0, 20), "...(100 digits)..."), run.substr(92), "y"));
  CHECK(shorten_digits(d41) == d41);  // 40 digits and a letter
  CHECK(quote("a\"b") == "\"a\\\"b\"");
  CHECK(quote(std::string(100, 'z')) == cat("\"", std::string(80, 'z'), "...\""));
  const std::string bad = quote(std::string("\xff", 1));  // not UTF-8: replaced, still a JSON string
  CHECK(nlohmann::json::parse(bad).is_string());
  CHECK(type_name(nlohmann::json(nullptr)) == "null");
  CHECK(type_name(nlohmann::json(true)) == "a boolean");
  CHECK(type_name(nlohmann::json(3)) == "an integer");
  CHECK(type_name(nlohmann::json(3u)) == "an integer");
  CHECK(type_name(nlohmann::json(1.5)) == "a number with a fraction part");
  CHECK(type_name(nlohmann::json("s")) == "a string");
  CHECK(type_name(nlohmann::json::object()) == "an object");
  CHECK(type_name(nlohmann::json::array()) == "an array");
  CHECK(join({"a", "b", "c"}) == "a, b, c");
  CHECK(join({"a", "b"}, " | ") == "a | b");
  CHECK(join({}) == "");
}

TEST_CASE("json_messages json_error_text places a parse error", "[io][json_messages]") {
  // the parser's own message: line and column of the bad token
  const std::string text = "{\n  \"a\": 1,\n  \"b\": ]\n}";
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    (void)j;
    FAIL("parsed");
  } catch (const nlohmann::json::parse_error& e) {
    const std::string m = json_error_text(text, e.byte, e.what());
    INFO(m);
    CHECK(m.rfind("line 3, column ", 0) == 0);  // the ']' is on line 3
    CHECK(m.find(": malformed JSON: ") != std::string::npos);
    CHECK(m.find("[json.exception") == std::string::npos);
  }
  // no line in the message: from the byte offset (column counted from the line start, at least 1)
  CHECK(json_error_text("ab\ncd", 4, "oops") == "line 2, column 1: malformed JSON: oops");
  CHECK(json_error_text("ab\ncd", 5, "oops") == "line 2, column 2: malformed JSON: oops");
  CHECK(json_error_text("ab\ncd", 3, "oops") == "line 2, column 1: malformed JSON: oops");
  CHECK(json_error_text("ab", 99, "oops") == "line 1, column 2: malformed JSON: oops");  // clamped to the end
  const std::string o = json_error_text("[1e999]", 6, "number overflow parsing '1e999'");
  CHECK(o.find("(write large numbers as strings") != std::string::npos);
  const std::string long_digits = json_error_text("x", 1, cat("bad ", std::string(60, '9')));
  CHECK(long_digits.find("(60 digits)") != std::string::npos);
}

}  // namespace ECCD_UNITY_ID
