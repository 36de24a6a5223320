// Certificates (certificate/write/exact_certificate.hpp) and their checker
// (certificate/check_certificate.hpp): Descartes' rule on intervals, certificates
// of the shipped cases accepted, and tampered ones rejected with the claim named.
#include "certificate/write/exact_certificate.hpp"
#include "exact/certificate_algebra.hpp"
#include "certificate/check_certificate.hpp"
#include "exact/descartes.hpp"
#include "io/scene_reader.hpp"
#include "tests/support/scenes.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {
Rational q(long n, long d) {
  Rational r(n, d);
  r.canonicalize();
  return r;
}
json doc_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return json::parse(ss.str());
}
struct Certified {
  Scene s;
  json doc, cert;
};
Certified certify(const std::string& rel) {
  Certified c;
  std::string path = eccd::test::case_path(rel);
  c.s = read_scene_file(path);
  c.doc = doc_of(path);
  c.cert = make_certificate(c.s, c.doc);
  return c;
}
// Index in the timeline of the first instant that is an irrational root.
std::size_t first_irrational_root(const json& cert) {
  const json& tl = cert["timeline"];
  for (std::size_t k = 0; k < tl.size(); k += 2)
    if (!tl[k]["root_of_factor"].is_null() && tl[k]["instant"]["lo"] != tl[k]["instant"]["hi"]) return k;
  return 0;
}
}  // namespace

TEST_CASE("Descartes' rule on an interval: 0 proves no root, 1 proves exactly one", "[certificate][descartes]") {
  // p = (t - 1/3)(t - 2/3)(t^2 + 1)
  Poly<Rational> a({q(-1, 3), Rational(1)}), b({q(-2, 3), Rational(1)}), c({Rational(1), Rational(0), Rational(1)});
  Poly<Rational> p = a * b * c;
  CHECK(descartes_variations(p, q(2, 5), q(3, 5)) == 0);
  CHECK(descartes_variations(p, q(1, 5), q(1, 2)) == 1);
  CHECK(descartes_variations(p, q(1, 2), Rational(1)) == 1);
  CHECK(descartes_variations(p, Rational(0), Rational(1)) >= 2);
  // a double root counts twice: V is never 1 for it
  Poly<Rational> d = a * a;
  CHECK(descartes_variations(d, Rational(0), Rational(1)) == 2);
  // no real root, but complex roots close to the interval: V may be 2, never 1
  Poly<Rational> e({q(1, 4) + q(1, 10000), Rational(-1), Rational(1)});  // (t - 1/2)^2 + 1e-4
  CHECK(descartes_variations(e, Rational(0), Rational(1)) % 2 == 0);
  CHECK(descartes_variations(e, q(1, 2), Rational(1)) == 0);
}

TEST_CASE("Certificates of the shipped 2D and 3D cases pass the checker", "[certificate]") {
  for (const char* rel :
       {"paper003/example2.json", "paper003/example2-towards-1e-9.json", "paper003/example2-away-1e-12.json",
        "spheres/spheres-crossing.json", "spheres/spheres-touch.json", "touch3d/touch-and-separate.json",
        "touch3d/overlap-on-axis.json"}) {
    INFO(rel);
    Certified c = certify(rel);
    CertificateCheck r = check_certificate(c.s, c.doc, c.cert);
    INFO(r.failed_claim << ": " << r.reason);
    CHECK(r.valid);
    CHECK(r.checked.size() >= 3);
    // The certified answer is the stored one.
    std::vector<std::string> dummy;
    Answer a = answer_from_json(c.cert["answer"], "certificate", "answer");
    REQUIRE(c.s.answer);
    CHECK(a.collides == c.s.answer->collides);
    CHECK(a.intervals.size() == c.s.answer->intervals.size());
  }
}

TEST_CASE("The spheres' certificate names its projection psc_1 and proves the discriminant vanishes", "[certificate]") {
  Certified c = certify("spheres/spheres-crossing.json");
  CHECK(c.cert["projection"]["name"] == "psc_1");
  CHECK(c.cert["projection"]["vanishing"] == json::array({"discriminant"}));
  json t = c.cert;
  t["projection"]["name"] = "discriminant";
  t["projection"]["vanishing"] = json::array();
  CertificateCheck r = check_certificate(c.s, c.doc, t);
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim == "projection");
}

TEST_CASE("A tampered 2D certificate is rejected and the failing claim is named", "[certificate]") {
  Certified c = certify("paper003/example2-towards-1e-9.json");
  REQUIRE(check_certificate(c.s, c.doc, c.cert).valid);
  std::size_t k = first_irrational_root(c.cert);
  REQUIRE(k > 0);

  SECTION("a bracket moved off its root, into the gap before it") {
    json t = c.cert;
    Rational lo = parse_rational(t["timeline"][k]["instant"]["lo"].get<std::string>());
    Rational prev = parse_rational(t["timeline"][k - 1]["cell_sample"].get<std::string>());
    Rational w = parse_rational(t["timeline"][k]["instant"]["hi"].get<std::string>()) - lo;
    Rational nlo = (prev + lo) / 2, nhi = nlo + w;  // same width, between the sample and the old bracket
    t["timeline"][k]["instant"]["lo"] = nlo.get_str();
    t["timeline"][k]["instant"]["hi"] = nhi.get_str();
    t["timeline"][k]["instant"]["approx"] =
        approx_in_bracket(nlo, nhi);  // a consistent forgery: approx in the new bracket
    CertificateCheck r = check_certificate(c.s, c.doc, t);
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim.rfind("instant 1 ", 0) == 0);
    CHECK(r.reason.find("same sign at both ends of the bracket") != std::string::npos);  // no root of its factor in it
  }
  SECTION("a cell's status flipped") {
    json t = c.cert;
    t["timeline"][k + 1]["status"] = t["timeline"][k + 1]["status"] == "separate" ? "overlapping" : "separate";
    CertificateCheck r = check_certificate(c.s, c.doc, t);
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim.rfind("cell 1 ", 0) == 0);
    CHECK(r.reason.find("static test") != std::string::npos);
  }
  SECTION("one coefficient of the projection changed") {
    json t = c.cert;
    mpz_class x(t["projection"]["coefficients"][3].get<std::string>());
    t["projection"]["coefficients"][3] = mpz_class(x + 1).get_str();
    CertificateCheck r = check_certificate(c.s, c.doc, t);
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim == "projection");
    CHECK(r.reason.find("not a constant multiple") !=
          std::string::npos);  // compared by values at integers (certificate/check/)
  }
  SECTION("an evidence sign flipped") {
    json t = c.cert;
    json& e = t["timeline"][k]["evidence"][0];
    e["sign"] = e["sign"] == "positive" ? "negative" : "positive";
    CertificateCheck r = check_certificate(c.s, c.doc, t);
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim.rfind("instant 1 ", 0) == 0);
  }
  SECTION("a root dropped from the timeline") {
    json t = c.cert;
    t["timeline"].erase(t["timeline"].begin() + long(k), t["timeline"].begin() + long(k) + 2);
    CertificateCheck r = check_certificate(c.s, c.doc, t);
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim == "gaps");
  }
  SECTION("the answer's first interval widened to a neighbouring bracket") {
    json t = c.cert;
    t["answer"]["intervals"][0][1] = t["answer"]["intervals"][0][0];
    CertificateCheck r = check_certificate(c.s, c.doc, t);
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim == "answer");
  }
  SECTION("a certificate of another scene") {
    Certified other = certify("paper003/example2-away-1e-12.json");
    CertificateCheck r = check_certificate(c.s, c.doc, other.cert);
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim == "scene");
  }
  SECTION("a malformed rational") {
    json t = c.cert;
    t["timeline"][1]["cell_sample"] = "one half";
    CertificateCheck r = check_certificate(c.s, c.doc, t);
    CHECK_FALSE(r.valid);
    CHECK(r.failed_claim == "certificate format");
    CHECK(r.reason.find("timeline[1].cell_sample") != std::string::npos);
  }
}

}  // namespace ECCD_UNITY_ID
