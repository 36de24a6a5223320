// eccd-check, the independent checker (certificate/check/verdict.hpp): VALID
// on genuine certificates (2D, 3D, continuous touching), REJECTED naming the
// claim on forgeries, exit 2 on unreadable input or a format it does not
// cover; and the forgeries of incomplete cycloidal certificates that claim
// "collides": false (tests/data/cert/) are REJECTED by eccd check-certificate.
#include "certificate/check/verdict.hpp"
#include "certificate/write/exact_certificate.hpp"
#include "certificate/check_certificate.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"
#include "tests/support/cli.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;
namespace fs = std::filesystem;
using eccd::test::run;

namespace {
const std::string src = ECCD_SOURCE_DIR;
const std::string checker = ECCD_CHECK_EXE;
const std::string exe = ECCD_EXE;
const std::string data = src + "/tests/data/cert/";

std::string q(const std::string& s) { return "'" + s + "'"; }

fs::path temp_dir(const std::string& tag) {
  fs::path d = fs::temp_directory_path() / ("eccd-" + tag + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
}  // namespace

TEST_CASE("eccd-check: VALID (exit 0) on genuine certificates, 2D, 3D and continuous touching",
          "[eccd-check][certificate]") {
  const json manifest = json::parse(read_file_bytes(data + "forgeries.json"));
  for (const auto& v : manifest["valid"]) {
    const std::string scene = src + "/cases/" + v["scene"].get<std::string>(),
                      cert = data + v["file"].get<std::string>();
    INFO(cert);
    std::string out;
    CHECK(run(q(checker) + " " + q(scene) + " " + q(cert), out) == 0);
    CHECK(out.find("\nVALID\n") != std::string::npos);
    CHECK(out.find("ok  f: ") != std::string::npos);
    CHECK(run(q(checker) + " " + q(scene) + " " + q(cert) + " --json", out) == 0);
    CHECK(json::parse(out)["verdict"] == "VALID");
  }
}

TEST_CASE("eccd-check: REJECTED (exit 1) names the claim, and every shipped forgery of eccd-certificate/2 is rejected",
          "[eccd-check][certificate][forgery]") {
  const json manifest = json::parse(read_file_bytes(data + "forgeries.json"));
  for (const auto& f : manifest["forgeries"]) {
    const std::string scene = src + "/cases/" + f["scene"].get<std::string>(),
                      cert = data + f["file"].get<std::string>();
    INFO(cert);
    std::string out;
    CHECK(run(q(checker) + " " + q(scene) + " " + q(cert) + " --json", out) == 1);
    const json j = json::parse(out);
    CHECK(j["verdict"] == "REJECTED");
    CHECK(j["failed_claim"].get<std::string>().rfind(f["claim"].get<std::string>(), 0) == 0);
    CHECK((j["failed_claim"].get<std::string>() + ": " + j["reason"].get<std::string>())
              .find(f["place"].get<std::string>()) != std::string::npos);
  }
  // A certificate checked against another scene.
  std::string out;
  CHECK(run(q(checker) + " " + q(src + "/cases/paper003/example2.json") + " " + q(data + "valid-3d.cert.json"), out) ==
        1);
  CHECK(out.find("REJECTED: scene:") != std::string::npos);
}

TEST_CASE("eccd-check: a changed claim is rejected by name (f, projection, a cell status, the answer)",
          "[eccd-check][certificate]") {
  const std::string scene_path = src + "/cases/paper003/example2-towards-1e-9.json";
  const std::string scene = read_file_bytes(scene_path);
  const json cert = json::parse(read_file_bytes(data + "valid-2d.cert.json"));
  auto verdict = [&](const json& c) { return check::check_certificate_text(scene, scene_path, c.dump(), "c.json"); };
  REQUIRE(verdict(cert).outcome == check::Outcome::valid);
  json c = cert;
  c["f"]["g"][1][0] = "12345";
  CHECK(verdict(c).claim == "f");
  c = cert;  // f scaled by -1: the roots lambda keep their values, but the claim is about f as written
  for (auto& gk : c["f"]["g"])
    for (auto& x : gk) {
      mpq_class v(x.get<std::string>());
      v.canonicalize();
      x = mpq_class(-v).get_str();
    }
  CHECK(verdict(c).claim == "f");
  c = cert;
  c["projection"]["coefficients"][0] = "1";
  CHECK(verdict(c).claim == "projection");
  c = cert;
  c["timeline"][1]["status"] = c["timeline"][1]["status"] == "separate" ? "overlapping" : "separate";
  CHECK(verdict(c).outcome == check::Outcome::rejected);
  c = cert;
  c["answer"]["collides"] = !c["answer"]["collides"].get<bool>();
  const check::Verdict v = verdict(c);
  CHECK(v.claim == "answer");
  CHECK(v.reason.find("collides") != std::string::npos);
}

TEST_CASE("eccd-check: exit 2 for an unreadable file, malformed JSON, bad arguments or a format it does not cover",
          "[eccd-check][certificate]") {
  const fs::path d = temp_dir("eccd-check");
  const std::string scene = src + "/cases/paper003/example2-towards-1e-9.json";
  std::ofstream(d / "broken.json") << "{\"format\": ";
  std::ofstream(d / "cycloidal.json") << "{\"format\": \"eccd-unknown-certificate/1\"}";
  std::ofstream(d / "cycloidal-1.json") << "{\"format\": \"eccd-cycloidal-certificate/1\"}";
  std::string out;
  CHECK(run(q(checker) + " " + q(scene) + " " + q((d / "missing.json").string()), out) == 2);
  CHECK(run(q(checker) + " " + q(scene) + " " + q((d / "broken.json").string()), out) == 2);
  CHECK(run(q(checker) + " " + q(scene) + " " + q((d / "cycloidal.json").string()), out) == 2);
  CHECK(run(q(checker) + " " + q(scene) + " " + q((d / "cycloidal-1.json").string()), out) ==
        1);  // an older version: refused, saying so
  CHECK(out.find("older version") != std::string::npos);
  CHECK(run(q(checker) + " " + q(scene), out) == 2);
  CHECK(run(q(checker) + " --bogus " + q(scene) + " " + q(data + "valid-2d.cert.json"), out) == 2);
  CHECK(check::covers_format("eccd-certificate/2"));
  CHECK_FALSE(check::covers_format("eccd-bezier-certificate/1"));
  CHECK(check::covers_format("eccd-bezier-certificate/2"));
  CHECK(check::covers_format("eccd-independent-certificate/3"));
  CHECK_FALSE(check::covers_format("eccd-independent-certificate/2"));
  {  // the independent kind's older version: refused by name
    std::ofstream(d / "independent-2.json") << "{\"format\": \"eccd-independent-certificate/2\"}";
    CHECK(run(q(checker) + " " + q(src + "/cases/independent/discs-end.json") + " " +
                  q((d / "independent-2.json").string()),
              out) == 1);
    CHECK(out.find("older version") != std::string::npos);
  }
  fs::remove_all(d);
}

TEST_CASE("An incomplete cycloidal certificate never claims collides: false (the two forgeries of 003 Example 1)",
          "[eccd-check][certificate][cycloidal][forgery]") {
  const std::string path = src + "/cases/paper003/example1.json";
  for (const char* file : {"cycloidal-incomplete-collides-false-epsilon-1e300.cert.json",
                           "cycloidal-collision-hidden-in-undecided-stretch.cert.json"}) {
    INFO(file);
    std::string out;
    CHECK(run(q(exe) + " check-certificate " + q(path) + " " + q(data + file), out) == 1);
    CHECK(out.find("REJECTED: answer: answer.collides is false but 1 stretch(es) of the timeline are undecided") !=
          std::string::npos);
    // With collides null (unknown) the claim about the stretch must still be proved: epsilon is bounded.
    json c = json::parse(read_file_bytes(data + file));
    c["answer"]["collides"] = nullptr;
    const std::string text = read_file_bytes(path);
    const Scene s = parse_scene(text, path);
    const CertificateCheck r = check_certificate(s, parse_json_document(text, path), c);
    INFO(r.failed_claim << ": " << r.reason);
    CHECK_FALSE(r.valid);
    CHECK(r.reason.find("epsilon") != std::string::npos);
  }
}

TEST_CASE(
    "collides_claim: true where a collision is proved, null where a stretch is undecided and none is, false only when "
    "complete",
    "[certificate][answer]") {
  Answer a;
  CHECK(collides_claim(a) == std::optional<bool>(false));
  a.undecided.push_back(Instant{"0.5", std::nullopt, std::nullopt, 0.5});
  CHECK_FALSE(collides_claim(a).has_value());
  a.collides = true;
  CHECK(collides_claim(a) == std::optional<bool>(true));
}

TEST_CASE("The solver's JSON says collides null when nothing is proved and a stretch is undecided, and reads it back",
          "[certificate][answer]") {
  Solution s;
  s.answer.undecided.push_back(Instant{"0.25", std::nullopt, std::nullopt, 0.25});
  json j = solution_to_json(s);
  CHECK(j["collides"].is_null());
  Solution back = solution_from_json(j, "report");
  CHECK_FALSE(back.answer.collides);
  CHECK_FALSE(collides_claim(back.answer).has_value());
  CHECK(summary_text(s).find("collides: unknown") != std::string::npos);
  s.answer.undecided.clear();
  CHECK(solution_to_json(s)["collides"] == false);
  j["undecided"] = json::array();  // null without anything undecided is refused
  CHECK_THROWS_AS(solution_from_json(j, "report"), SceneError);
}

}  // namespace ECCD_UNITY_ID
