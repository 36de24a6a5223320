// The prover's door to the independent checker (certificate/check_certificate.hpp):
//   - a genuine certificate of the shipped data is VALID through the door,
//     from a Scene read from its file (its own text is what the checker
//     sees) and from a Scene built in memory (the scene document's dump);
//     the checked claims are the checker's;
//   - a changed claim fails with the checker's claim name; an unreadable
//     certificate (the checker's "input") is reported as "certificate
//     format";
//   - a cycloidal scene accepts only the cycloidal format, and the verdict
//     names the format expected;
//   - check_certificate_text: a duplicate key is REJECTED naming its place,
//     malformed JSON throws SceneError with the label.
#include "certificate/check_certificate.hpp"
#include "certificate/check/verdict.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {
const std::string src = ECCD_SOURCE_DIR;
const std::string data = src + "/tests/data/cert/";
}  // namespace

TEST_CASE("check_certificate passes the independent checker's verdict through", "[certificate][check_certificate]") {
  const std::string path = src + "/cases/paper003/example2-towards-1e-9.json";
  const Scene s = read_scene_file(path);
  const json doc = parse_json_document(read_file_bytes(path), path);
  const json cert = json::parse(read_file_bytes(data + "valid-2d.cert.json"));
  CertificateCheck r = check_certificate(s, doc, cert);
  INFO(r.failed_claim << ": " << r.reason);
  REQUIRE(r.valid);
  const auto direct = check::check_certificate_text(read_file_bytes(path), path, cert.dump(), "certificate");
  CHECK(r.checked == direct.checked);
  // a Scene without its source text: the document is what the checker reads
  Scene mem = s;
  mem.source_text.clear();
  mem.path.clear();
  CHECK(check_certificate(mem, doc, cert).valid);

  json changed = cert;
  changed["answer"]["collides"] = !changed["answer"]["collides"].get<bool>();
  r = check_certificate(s, doc, changed);
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim == check::check_certificate_text(read_file_bytes(path), path, changed.dump(), "c").claim);
  r = check_certificate(s, doc, json::array());
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim == "certificate format");

  // duplicate key and malformed text
  std::string text = cert.dump();
  text.insert(1, "\"format\": \"x\", ");
  r = check_certificate_text(s, doc, text, "c.json");
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim == "certificate format");
  CHECK(r.reason.find("duplicate key") != std::string::npos);
  CHECK_THROWS_AS(check_certificate_text(s, doc, "{\"format\": ", "c.json"), SceneError);
}

TEST_CASE("check_certificate: a cycloidal scene takes only a cycloidal certificate",
          "[certificate][check_certificate]") {
  const std::string path = src + "/cases/paper003/example1.json";
  const Scene s = read_scene_file(path);
  const json doc = parse_json_document(read_file_bytes(path), path);
  const json cert = json::parse(read_file_bytes(data + "valid-2d.cert.json"));  // an exact certificate
  const CertificateCheck r = check_certificate(s, doc, cert);
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim == "certificate format");
  CHECK(r.reason.find("for a cycloidal scene, got \"eccd-certificate/2\"") != std::string::npos);
  CHECK(r.reason.find("format: expected \"eccd-cycloidal-certificate/") == 0);
}

}  // namespace ECCD_UNITY_ID
