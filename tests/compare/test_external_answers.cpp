// External engines' answers (compare/external_answers.hpp), on answer files
// written to a temporary folder:
//  - parse_external accepts NAME=DIR with a name of letters, digits, '_',
//    '-', '.' of at most 40 characters and an existing folder, and refuses
//    everything else with std::invalid_argument saying what is wrong;
//  - read_external_answer reads DIR/<scene name>.json: nullopt when there is
//    no such regular file (or the name cannot be a file name); the answer in
//    each form `eccd judge` reads (a bare answer, a scene file's "answer", the
//    report of `eccd solve --json`, which gives back the solved answer);
//    "time_us" or "time_ms" (converted to µs; time_us first when both) as the
//    engine's time, -1 without; a negative or non-numeric time, malformed
//    JSON or a bad answer give an error row naming the file, never an answer.
#include "compare/external_answers.hpp"

#include "api/solve.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace ECCD_UNITY_ID {
using namespace eccd;
namespace fs = std::filesystem;

namespace {
struct TempDir {
  fs::path p;
  explicit TempDir(const std::string& tag)
      : p(fs::temp_directory_path() / ("eccd-ext-" + tag + "-" + std::to_string(::getpid()))) {
    fs::remove_all(p);
    fs::create_directories(p);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(p, ec);
  }
  void write(const std::string& file, const std::string& text) const {
    std::ofstream o(p / file, std::ios::binary);
    o << text;
  }
};
std::string refusal(const std::string& spec) {
  try {
    parse_external(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
bool has(const std::string& s, const std::string& w) { return s.find(w) != std::string::npos; }

const char* kBare = R"({"collides": true,
  "intervals": [[{"approx": "0.25"}, {"approx": "0.5", "lo": "1/2", "hi": "1/2"}]],
  "first_contact": {"approx": "0.25"}, "contacts": [{"approx": "0.25"}]})";
}  // namespace

TEST_CASE("external answers: NAME=DIR is parsed and checked", "[compare][external-answers]") {
  TempDir d("parse");
  const std::string dir = d.p.string();
  const ExternalEngine e = parse_external("my-fcl_2.0=" + dir);
  CHECK(e.name == "my-fcl_2.0");
  CHECK(e.dir == dir);
  CHECK(parse_external(std::string(40, 'x') + "=" + dir).name.size() == 40);
  // The first '=' splits: a folder may hold '=' in its name.
  fs::create_directories(d.p / "a=b");
  CHECK(parse_external("e=" + (d.p / "a=b").string()).dir == (d.p / "a=b").string());

  CHECK(has(refusal("fcl"), "expected NAME=DIR"));
  CHECK(has(refusal("=" + dir), "expected NAME=DIR"));
  CHECK(has(refusal("fcl="), "expected NAME=DIR"));
  CHECK(has(refusal(std::string(41, 'x') + "=" + dir), "longer than 40 characters"));
  CHECK(has(refusal("my engine=" + dir), "may hold only letters, digits"));
  CHECK(has(refusal("a/b=" + dir), "may hold only letters, digits"));
  CHECK(has(refusal("fcl=" + dir + "/missing"), "is not a folder"));
  d.write("file.txt", "x");
  CHECK(has(refusal("fcl=" + (d.p / "file.txt").string()), "is not a folder"));
  CHECK(has(refusal("fcl=" + dir + "/missing"), "--external fcl="));  // the message quotes the option
}

TEST_CASE("external answers: answer files are read with the engine's time", "[compare][external-answers]") {
  TempDir d("read");
  const ExternalEngine e{"eng", d.p.string()};
  SECTION("no file, or a name that cannot be a file's: nullopt") {
    CHECK_FALSE(read_external_answer(e, "absent").has_value());
    CHECK_FALSE(read_external_answer(e, "").has_value());
    fs::create_directories(d.p / "sub");
    d.write("sub/x.json", kBare);
    CHECK_FALSE(read_external_answer(e, "sub/x").has_value());  // no path into sub-folders
    fs::create_directories(d.p / "folder.json");
    CHECK_FALSE(read_external_answer(e, "folder").has_value());  // not a regular file
  }
  SECTION("a bare answer without a time") {
    d.write("s1.json", kBare);
    const auto a = read_external_answer(e, "s1");
    REQUIRE(a.has_value());
    CHECK(a->error.empty());
    CHECK(a->path == (d.p / "s1.json").string());
    CHECK(a->time_us < 0);
    REQUIRE(a->answer.has_value());
    CHECK(a->answer->collides);
    REQUIRE(a->answer->intervals.size() == 1);
    CHECK(a->answer->intervals[0].first.approx == "0.25");
    CHECK_FALSE(a->answer->intervals[0].first.certified());
    CHECK(a->answer->intervals[0].second.certified());
    CHECK(*a->answer->intervals[0].second.lo == Rational(1, 2));
    REQUIRE(a->answer->contacts.size() == 1);
  }
  SECTION("time_us, time_ms (in microseconds), and time_us first when both are given") {
    std::string body = std::string(kBare);
    body.pop_back();  // the closing brace
    d.write("us.json", body + R"(, "time_us": 12.5})");
    d.write("ms.json", body + R"(, "time_ms": 2.5})");
    d.write("both.json", body + R"(, "time_ms": 7, "time_us": 3})");
    d.write("zero.json", body + R"(, "time_us": 0})");
    const auto us = read_external_answer(e, "us"), ms = read_external_answer(e, "ms"),
               both = read_external_answer(e, "both"), zero = read_external_answer(e, "zero");
    REQUIRE((us && ms && both && zero));
    CHECK(us->time_us == 12.5);
    CHECK(ms->time_us == 2500);
    CHECK(both->time_us == 3);
    CHECK(zero->time_us == 0);
    for (const auto* x : {&us, &ms, &both, &zero}) {
      CHECK((*x)->error.empty());
      CHECK((*x)->answer.has_value());
    }
  }
  SECTION("a scene file with an answer key") {
    d.write("scene.json", std::string(R"({"format": "ellipse-ccd-scene/1", "name": "scene", "dim": 2,
      "a": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "static"}},
      "b": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "static"}},
      "answer": )") + kBare + "}");
    const auto a = read_external_answer(e, "scene");
    REQUIRE(a.has_value());
    INFO(a->error);
    REQUIRE(a->answer.has_value());
    CHECK(a->answer->intervals.size() == 1);
  }
  SECTION("the report of eccd solve --json, with a time") {
    const Scene sc = read_scene_file(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example2.json");
    const Solution sol = solve(sc);
    nlohmann::json j = solution_to_json(sol);
    j["time_ms"] = 0.5;
    d.write("solved.json", j.dump());
    const auto a = read_external_answer(e, "solved");
    REQUIRE(a.has_value());
    INFO(a->error);
    REQUIRE(a->answer.has_value());
    CHECK(a->time_us == 500);
    CHECK(a->answer->collides == sol.answer.collides);
    REQUIRE(a->answer->intervals.size() == sol.answer.intervals.size());
    CHECK(*a->answer->intervals[0].first.lo == *sol.answer.intervals[0].first.lo);
    CHECK(*a->answer->intervals[0].second.hi == *sol.answer.intervals[0].second.hi);
    CHECK(a->answer->contacts.size() == sol.answer.contacts.size());
  }
  SECTION("bad times, malformed JSON and bad answers give an error naming the file, no answer") {
    std::string body = std::string(kBare);
    body.pop_back();
    d.write("neg.json", body + R"(, "time_us": -1})");
    d.write("str.json", body + R"(, "time_ms": "5"})");
    d.write("broken.json", R"({"collides": true, "intervals": [)");
    d.write("late.json", R"({"collides": true, "intervals": [[{"approx": "0.5"}, {"approx": "1.5"}]],
      "first_contact": {"approx": "0.5"}, "contacts": []})");
    d.write("nan.json",
            R"({"collides": false, "intervals": [], "first_contact": null, "contacts": [{"approx": "nan"}]})");
    const auto neg = read_external_answer(e, "neg");
    REQUIRE(neg.has_value());
    CHECK_FALSE(neg->answer.has_value());
    CHECK(neg->error == neg->path + ": /time_us: expected a non-negative number (the engine's time for the query)");
    const auto str = read_external_answer(e, "str");
    REQUIRE(str.has_value());
    CHECK_FALSE(str->answer.has_value());
    CHECK(has(str->error, "/time_ms: expected a non-negative number"));
    for (const char* name : {"broken", "late", "nan"}) {
      const auto x = read_external_answer(e, name);
      INFO(name);
      REQUIRE(x.has_value());
      CHECK_FALSE(x->answer.has_value());
      CHECK(has(x->error, x->path));  // the reader's message names the file
    }
  }
}

}  // namespace ECCD_UNITY_ID
