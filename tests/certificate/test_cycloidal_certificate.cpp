// The cycloidal certificate (certificate/write/cycloidal_certificate.hpp): 003 Example 1
// certified, its certificate VALID, and tampered copies REJECTED naming the
// claim; a touch scene gives an incomplete certificate whose ε is checked.
#include "api/certify.hpp"
#include "api/solve.hpp"
#include "certificate/write/cycloidal_certificate.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {

CertificateCheck check(const Scene& s, const json& cert) { return check_certificate(s, cert.dump()); }

}  // namespace

TEST_CASE("cycloidal certificate: 003 Example 1 round trip and tampering", "[cycloidal][certify]") {
  const Scene s = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/paper003/example1.json");
  const Certificate c = certify(s);
  const json cert = json::parse(c.text);
  REQUIRE(cert["format"] == kCycloidalCertificateFormat);
  CHECK(cert["complete"] == true);
  CHECK(c.solution.arith.kind == Arithmetic::Certified);
  CertificateCheck ok = check(s, cert);
  INFO(ok.failed_claim << ": " << ok.reason);
  REQUIRE(ok.valid);
  // the paper's four roots of Δ (003 Example 1: 0.226, 0.393, 0.600, 0.731), each a proved simple root
  std::vector<double> roots;
  for (const auto& n : cert["timeline"])
    if (n.contains("kind") && n["kind"] == "simple_root")
      roots.push_back(parse_rational(n["instant"]["lo"].get<std::string>()).get_d());
  REQUIRE(roots.size() == 4);
  const double paper[] = {0.226, 0.393, 0.600, 0.731};
  for (int i = 0; i < 4; ++i) CHECK(std::abs(roots[i] - paper[i]) < 5e-4);
  // the answer agrees with the stored (certified) one
  REQUIRE(s.answer);
  CHECK(cert["answer"]["intervals"].size() == 1);
  CHECK(cert["answer"]["contacts"].size() == 2);

  auto rejected = [&](json t, const std::string& claim) {
    CertificateCheck r = check(s, t);
    INFO("expected to fail: " << claim << "; got " << (r.valid ? "VALID" : r.failed_claim + ": " + r.reason));
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim.find(claim) != std::string::npos);
  };
  std::size_t root = 0;  // the timeline index of the first simple root
  while (!cert["timeline"][root].contains("kind") || cert["timeline"][root]["kind"] != "simple_root") ++root;
  {  // a bracket moved off its root: the signs of Δ at its ends are no longer opposite
    json t = cert;
    const mpq_class old_lo = parse_rational(t["timeline"][root]["instant"]["lo"].get<std::string>());
    const mpq_class sample = parse_rational(t["timeline"][root - 1]["cell_sample"].get<std::string>());
    t["timeline"][root]["instant"]["hi"] = old_lo.get_str();
    t["timeline"][root]["instant"]["lo"] = mpq_class((old_lo + sample) / 2).get_str();
    rejected(t, "instant");
  }
  {  // a cell's status flipped
    json t = cert;
    t["timeline"][1]["status"] = t["timeline"][1]["status"] == "separate" ? "overlapping" : "separate";
    rejected(t, "cell");
  }
  {  // a root dropped (its instant and a cell): the gap then holds a root
    json t = cert;
    t["timeline"].erase(root);
    t["timeline"].erase(root);
    t["gap_points"] = json::array();
    CertificateCheck r = check(s, t);
    CHECK_FALSE(r.valid);
  }
  {  // the gap points removed: the long gaps are not proved root-free in one piece
    json t = cert;
    if (!t["gap_points"].empty()) {
      t["gap_points"] = json::array();
      rejected(t, "gaps");
    }
  }
  {  // the answer drops a contact
    json t = cert;
    t["answer"]["contacts"].erase(1);
    rejected(t, "answer");
  }
  {  // an approx outside its bracket
    json t = cert;
    t["timeline"][root]["instant"]["approx"] = "0.5";
    rejected(t, "instant");
  }
  {  // a precision too high to check cheaply
    json t = cert;
    t["delta"]["precision_bits"] = 100000;
    rejected(t, "certificate format");
  }
  {  // another scene's certificate
    json t = cert;
    t["scene"]["a"]["shape"]["semi_axes"][0] = "7";
    rejected(t, "scene");
  }
}

TEST_CASE("cycloidal certificate: a touch is stated as 'touch or near miss within epsilon', and epsilon is checked",
          "[cycloidal][certify]") {
  // Two circles, B static, A passing at distance r_A + r_B at t = 1/2 (compare/motion_families.hpp, kind touch)
  const std::string text = R"({"format": "ellipse-ccd-scene/1", "name": "cyc-touch", "dim": 2,
    "a": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "cycloidal", "angle_over_pi": ["0", "1"], "translation": [["-2", "4"], ["2", "0"]]}},
    "b": {"shape": {"semi_axes": ["1", "1"]}, "motion": {"type": "static"}}})";
  const Scene s = scene_from_text(text, "cyc-touch");
  const json cert = json::parse(certify(s).text);
  CHECK(cert["complete"] == false);
  CertificateCheck ok = check(s, cert);
  INFO(ok.failed_claim << ": " << ok.reason);
  REQUIRE(ok.valid);
  std::size_t k = 0;
  while (!cert["timeline"][k].contains("kind") || cert["timeline"][k]["kind"] != "undecided") ++k;
  const json& n = cert["timeline"][k];
  CHECK(n["status"] == "uncertain");
  const mpq_class lo = parse_rational(n["instant"]["lo"].get<std::string>()),
                  hi = parse_rational(n["instant"]["hi"].get<std::string>());
  CHECK(lo <= mpq_class(1, 2));
  CHECK(mpq_class(1, 2) <= hi);
  CHECK(cert["answer"]["undecided"].size() == 1);
  json t = cert;
  t["timeline"][k]["epsilon"] = "0";  // |Δ| <= 0 on the stretch: not provable
  CertificateCheck r = check(s, t);
  CHECK_FALSE(r.valid);
  t = cert;
  t["timeline"][k]["status"] = "touching";  // claiming the touch
  CHECK_FALSE(check(s, t).valid);
  t = cert;
  t["complete"] = true;
  CHECK_FALSE(check(s, t).valid);
}

TEST_CASE("cycloidal certificate: a touch at t = 0 makes the first instant an undecided stretch from 0",
          "[cycloidal][certify]") {
  // as in tests/certified/test_cycloidal.cpp: A slides off B, touching at t = 0 only
  const std::string text = R"({"format": "ellipse-ccd-scene/1", "name": "touch0", "dim": 2,
    "a": {"shape": {"semi_axes": ["2", "1"]},
          "motion": {"type": "cycloidal", "angle_over_pi": ["0", "0"], "translation": [["0", "2"], ["3", "0"]]}},
    "b": {"shape": {"semi_axes": ["1", "2"]}, "motion": {"type": "static"}}})";
  const Scene s = scene_from_text(text, "touch0");
  const json cert = json::parse(certify(s).text);
  CertificateCheck ok = check(s, cert);
  INFO(ok.failed_claim << ": " << ok.reason);
  REQUIRE(ok.valid);
  const json& first = cert["timeline"][0];
  CHECK(first["kind"] == "undecided");
  CHECK(first["instant"]["lo"] == "0");
  CHECK(parse_rational(first["instant"]["hi"].get<std::string>()) > 0);
  CHECK(cert["complete"] == false);
  // Separate outside the stretch, proved; a touch at t = 0 is not excluded, so
  // the certificate claims no collision only as unknown (null), never false.
  CHECK(cert["answer"]["collides"].is_null());
  json forged = cert;
  forged["answer"]["collides"] = false;
  CertificateCheck r = check(s, forged);
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim == "answer");
}

}  // namespace ECCD_UNITY_ID
