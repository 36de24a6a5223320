// eccd-check's verdict as a library call (certificate/check/verdict.hpp);
// tests/certificate/test_eccd_check.cpp runs the executable's exit codes.
// The three outcomes from the header's statement:
//   - VALID on a shipped genuine certificate (tests/data/cert, its scene in
//     cases/), one line per checked claim;
//   - REJECTED naming the first claim that fails: a duplicate key (with its
//     JSON place), a certificate that is not an object, an older format
//     (named as such), a changed answer;
//   - UNREADABLE: malformed certificate or scene JSON, a missing file, a
//     format the checker does not cover (naming the ones it covers);
//   - covers_format.
#include "certificate/check/verdict.hpp"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>

namespace ECCD_UNITY_ID {
using eccd::check::check_certificate_files;
using eccd::check::check_certificate_text;
using eccd::check::covers_format;
using eccd::check::Outcome;

namespace {

const std::string src = ECCD_SOURCE_DIR;

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("check verdict: valid, rejected and unreadable certificates", "[certificate][check_verdict]") {
  const std::string scene_path = src + "/cases/paper003/example2-towards-1e-9.json";
  const std::string cert_path = src + "/tests/data/cert/valid-2d.cert.json";
  const std::string scene = slurp(scene_path), cert = slurp(cert_path);
  REQUIRE_FALSE(scene.empty());
  REQUIRE_FALSE(cert.empty());

  auto v = check_certificate_text(scene, "scene.json", cert, "cert.json");
  INFO(v.claim << ": " << v.reason);
  CHECK(v.outcome == Outcome::valid);
  CHECK_FALSE(v.checked.empty());
  CHECK(check_certificate_files(scene_path, cert_path).outcome == Outcome::valid);

  nlohmann::json doc = nlohmann::json::parse(cert);
  // a duplicate key: rejected with its place
  std::string dup = cert;
  dup.insert(dup.find('{') + 1, "\"format\": \"x\",");
  v = check_certificate_text(scene, "scene.json", dup, "cert.json");
  CHECK(v.outcome == Outcome::rejected);
  CHECK(v.claim == "certificate format");
  CHECK(v.reason.find("duplicate key \"format\"") != std::string::npos);
  // not an object
  v = check_certificate_text(scene, "scene.json", "[1, 2]", "cert.json");
  CHECK(v.outcome == Outcome::rejected);
  CHECK(v.reason.find("top level: expected an object") != std::string::npos);
  // a changed answer
  nlohmann::json changed = doc;
  changed["answer"]["collides"] = !changed["answer"]["collides"].get<bool>();
  v = check_certificate_text(scene, "scene.json", changed.dump(), "cert.json");
  CHECK(v.outcome == Outcome::rejected);
  CHECK_FALSE(v.claim.empty());
  // an older format: rejected, named
  nlohmann::json old = doc;
  old["format"] = "eccd-certificate/1";
  v = check_certificate_text(scene, "scene.json", old.dump(), "cert.json");
  CHECK(v.outcome == Outcome::rejected);
  CHECK(v.reason.find("older version") != std::string::npos);
  // a format nobody covers: unreadable, naming the covered ones
  nlohmann::json other = doc;
  other["format"] = "someone-else/7";
  v = check_certificate_text(scene, "scene.json", other.dump(), "cert.json");
  CHECK(v.outcome == Outcome::unreadable);
  CHECK(v.reason.find("eccd-certificate/2") != std::string::npos);
  // malformed JSON, either file; a missing file
  v = check_certificate_text(scene, "scene.json", "{\"format\": ", "cert.json");
  CHECK(v.outcome == Outcome::unreadable);
  CHECK(v.reason.find("cert.json") != std::string::npos);
  v = check_certificate_text("{", "scene.json", cert, "cert.json");
  CHECK(v.outcome == Outcome::unreadable);
  CHECK(v.reason.find("scene.json") != std::string::npos);
  CHECK(check_certificate_files(scene_path, src + "/no/such/file.json").outcome == Outcome::unreadable);

  CHECK(covers_format("eccd-certificate/2"));
  CHECK_FALSE(covers_format("eccd-certificate/1"));
  CHECK_FALSE(covers_format(""));
}

}  // namespace ECCD_UNITY_ID
