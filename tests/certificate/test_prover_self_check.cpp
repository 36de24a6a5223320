// The prover-side self-check of eccd-certificate/2
// (certificate/write/prover_self_check.hpp), on the shipped certificates of
// tests/data/cert (forgeries.json lists them with their scenes):
//   - every genuine certificate (2D, 3D, continuous touching in 2D and 3D) is
//     VALID, its checked claims in the order the header states (scene, f,
//     projection, ..., answer last);
//   - every shipped forgery is rejected, as the independent checker
//     (certificate/check/verdict.hpp) rejects it: the two share no code, so
//     agreeing on all of them is evidence for both; forgeries of the answer
//     are rejected as "answer" claims by the self-check too;
//   - a certificate of one scene offered for another is rejected at the
//     scene claim; a malformed part is REJECTED, never an exception.
#include "certificate/check/verdict.hpp"
#include "certificate/write/prover_self_check.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {

const std::string src = ECCD_SOURCE_DIR;
const std::string data = src + "/tests/data/cert/";

struct Pair {
  Scene scene;
  json doc;
  std::string scene_text;
};

Pair scene_of(const std::string& rel) {
  Pair p;
  p.scene_text = read_file_bytes(src + "/cases/" + rel);
  p.scene = parse_scene(p.scene_text, rel);
  p.doc = parse_json_document(p.scene_text, rel);
  return p;
}

}  // namespace

TEST_CASE("prover_self_check accepts the genuine certificates, claims in order", "[certificate][prover_self_check]") {
  const json manifest = json::parse(read_file_bytes(data + "forgeries.json"));
  REQUIRE(manifest["valid"].size() >= 4);
  for (const auto& v : manifest["valid"]) {
    const std::string rel = v["scene"].get<std::string>();
    INFO(rel);
    const Pair p = scene_of(rel);
    const json cert = json::parse(read_file_bytes(data + v["file"].get<std::string>()));
    const CertificateCheck r = prover_self_check(p.scene, p.doc, cert);
    INFO(r.failed_claim << ": " << r.reason);
    REQUIRE(r.valid);
    REQUIRE(r.checked.size() >= 3);
    CHECK(r.checked.front().rfind("scene", 0) == 0);
    CHECK(r.checked[1].rfind("f", 0) == 0);
    CHECK(r.checked.back().rfind("answer", 0) == 0);
  }
}

TEST_CASE("prover_self_check rejects every shipped forgery, as the independent checker does",
          "[certificate][prover_self_check]") {
  const json manifest = json::parse(read_file_bytes(data + "forgeries.json"));
  int answers = 0;
  for (const auto& f : manifest["forgeries"]) {
    const std::string rel = f["scene"].get<std::string>(), file = f["file"].get<std::string>();
    INFO(file << ": " << f.value("what", ""));
    const Pair p = scene_of(rel);
    const std::string text = read_file_bytes(data + file);
    const check::Verdict independent = check::check_certificate_text(p.scene_text, rel, text, file);
    CHECK(independent.outcome != check::Outcome::valid);
    std::string structure;
    json cert;
    try {
      cert = parse_json_document(text, file, &structure);
    } catch (const SceneError&) {
      continue;  // not JSON: nothing for the self-check to read
    }
    if (!structure.empty()) continue;  // a duplicate key: refused before any claim
    CertificateCheck r;
    REQUIRE_NOTHROW(r = prover_self_check(p.scene, p.doc, cert));
    CHECK_FALSE(r.valid);
    CHECK_FALSE(r.failed_claim.empty());
    if (f["claim"] == "answer" && r.failed_claim == "answer") ++answers;
  }
  CHECK(answers >= 1);
}

TEST_CASE("prover_self_check rejects a certificate offered for another scene", "[certificate][prover_self_check]") {
  const Pair x = scene_of("paper003/example2-towards-1e-9.json");
  const Pair y = scene_of("paper003/example2-away-1e-12.json");
  const json cert = json::parse(read_file_bytes(data + "valid-2d.cert.json"));
  REQUIRE(prover_self_check(x.scene, x.doc, cert).valid);
  const CertificateCheck r = prover_self_check(y.scene, y.doc, cert);
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim == "scene");
  json broken = cert;
  broken["timeline"] = 7;
  const CertificateCheck b = prover_self_check(x.scene, x.doc, broken);
  CHECK_FALSE(b.valid);
  CHECK_FALSE(b.failed_claim.empty());
}

}  // namespace ECCD_UNITY_ID
