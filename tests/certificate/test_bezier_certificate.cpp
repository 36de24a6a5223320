// The Bézier certificate (certificate/write/bezier_certificate.hpp): certify --arith
// certified's route for 3D scenes. Certificates of cases/spheres (known
// answers: the scene notes give the instants in closed form) are VALID, and
// one tampered copy per claim kind is REJECTED naming that claim; the CLI
// writes a VALID certificate, says its route, and writes nothing on error.
#include "api/certify.hpp"
#include "api/solve.hpp"
#include "certificate/write/bezier_certificate.hpp"
#include "io/scene_reader.hpp"
#include "tests/support/cli.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const std::string src = ECCD_SOURCE_DIR;

struct Case {
  Scene scene;
  json doc, cert;
};

Case certified_case(const std::string& rel) {
  Case c;
  c.scene = read_scene(src + "/" + rel);
  c.doc = parse_json_document(c.scene.source_text, c.scene.path);
  c.cert = make_bezier_certificate(c.scene, c.doc);
  return c;
}

void rejected(const Case& c, const json& t, const std::string& claim, const std::string& reason_part = "") {
  const CertificateCheck r = check_certificate(c.scene, t.dump());
  INFO("expected to fail: " << claim << "; got " << (r.valid ? "VALID" : r.failed_claim + ": " + r.reason));
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim.find(claim) != std::string::npos);
  if (!reason_part.empty()) CHECK(r.reason.find(reason_part) != std::string::npos);
}

std::size_t first(const json& cert, const std::string& kind) {
  for (std::size_t i = 0; i < cert["pieces"].size(); ++i)
    if (cert["pieces"][i]["kind"] == kind) return i;
  FAIL("no piece of kind " << kind);
  return 0;
}

mpq_class rq(const json& j) { return parse_rational(j.get<std::string>()); }

}  // namespace

TEST_CASE("bezier certificate: spheres-crossing is VALID and proves the closed-form instants", "[bezier-certificate]") {
  const Case c = certified_case("cases/spheres/spheres-crossing.json");
  REQUIRE(c.cert["format"] == kBezierCertificateFormat);
  const CertificateCheck ok = check_certificate(c.scene, c.cert.dump());
  INFO(ok.failed_claim << ": " << ok.reason);
  REQUIRE(ok.valid);
  // the scene note: 16 D(t) = 1024 t^2 - 1024 t + 117, roots 1/2 -+ sqrt(139)/32; both ends proved by Krawczyk
  const json& iv = c.cert["answer"]["intervals"];
  REQUIRE(iv.size() == 1);
  for (int e = 0; e < 2; ++e) {
    const mpq_class lo = rq(iv[0][e]["lo"]), hi = rq(iv[0][e]["hi"]);
    // r = 1/2 -+ sqrt(139)/32 in [lo, hi] iff (32 (x - 1/2))^2 - 139 changes sign over it (monotone on each side of
    // 1/2)
    auto p = [](const mpq_class& x) {
      mpq_class y = 32 * (x - mpq_class(1, 2));
      return mpq_class(y * y - 139);
    };
    INFO("end " << e << ": [" << lo.get_d() << ", " << hi.get_d() << "]");
    CHECK(sgn(p(lo)) * sgn(p(hi)) < 0);
    CHECK(hi - lo < mpq_class(1, 1000000000));
  }
  CHECK(c.cert["answer"]["contacts"].size() == 2);
  // the same certificate through the dispatching checker that `eccd check-certificate` uses
  CHECK(check_bezier_certificate(c.scene, c.doc, c.cert).valid);
}

TEST_CASE("bezier certificate: every kind of tampering is rejected naming the claim", "[bezier-certificate]") {
  const Case c = certified_case("cases/spheres/spheres-crossing.json");
  const json& cert = c.cert;
  const std::size_t out = first(cert, "out"), in = first(cert, "in"), end = first(cert, "end");
  {  // a box sign claim flipped: an out piece claimed in
    json t = cert;
    t["pieces"][out]["kind"] = "in";
    rejected(c, t, "piece " + std::to_string(out + 1) + " (in", "not all < 0");
  }
  {  // an in piece claimed out
    json t = cert;
    t["pieces"][in]["kind"] = "out";
    rejected(c, t, "piece " + std::to_string(in + 1) + " (out", "not all > 0");
  }
  {  // a box removed from an in piece: its u-ranges no longer cover [0, 1]
    json t = cert;
    auto& boxes = t["pieces"][in]["boxes"];
    REQUIRE(boxes.size() > 1);
    boxes.erase(boxes.begin());
    rejected(c, t, "piece " + std::to_string(in + 1), "do not cover");
  }
  {  // a moved bracket: shifted by its own width plus the run's, it leaves [lo, hi] ∩ Y_k
    json t = cert;
    json& e = t["pieces"][end];
    const mpq_class shift = rq(e["hi"]) - rq(e["lo"]);
    e["bracket"][0] = mpq_class(rq(e["bracket"][0]) + shift).get_str();
    e["bracket"][1] = mpq_class(rq(e["bracket"][1]) + shift).get_str();
    rejected(c, t, "piece " + std::to_string(end + 1) + " (end", "bracket");
  }
  {  // a bracket narrowed to one end point: it no longer holds the run ∩ the last chain box
    json t = cert;
    json& e = t["pieces"][end];
    e["bracket"][1] = e["bracket"][0];
    rejected(c, t, "piece " + std::to_string(end + 1) + " (end", "does not hold");
  }
  {  // a piece removed: a gap in the coverage of [0, 1]
    json t = cert;
    t["pieces"].erase(t["pieces"].begin() + std::ptrdiff_t(in));
    rejected(c, t, "coverage", "gap");
  }
  {  // the last piece removed: [0, 1] not covered to 1
    json t = cert;
    t["pieces"].erase(t["pieces"].end() - 1);
    rejected(c, t, "coverage");
  }
  {  // a Krawczyk box shrunk: X's u-range cut to its left twentieth, which misses the zero (Newton's point is X's
     // centre)
    json t = cert;
    json& X = t["pieces"][end]["boxes"][0];
    const mpq_class u0 = rq(X[0]), u1 = rq(X[1]);
    X[1] = mpq_class(u0 + (u1 - u0) / 20).get_str();
    rejected(c, t, "piece " + std::to_string(end + 1) + " (end", "Krawczyk's K(X) is not inside");
  }
  {  // a later chain box shrunk to its upper half: it no longer contains Y_0 ∩ K(Y_0)
    json t = cert;
    json& Y = t["pieces"][end]["boxes"];
    REQUIRE(Y.size() > 1);
    json& B = Y[1];
    B[0] = mpq_class((rq(B[0]) + rq(B[1])) / 2).get_str();
    rejected(c, t, "piece " + std::to_string(end + 1) + " (end", "does not contain Y_0");
  }
  {  // the Krawczyk box's t-range shrunk so that it no longer covers the run
    json t = cert;
    json& X = t["pieces"][end]["boxes"][0];
    X[2] =
        mpq_class(rq(t["pieces"][end]["lo"]) + (rq(t["pieces"][end]["hi"]) - rq(t["pieces"][end]["lo"])) / 2).get_str();
    rejected(c, t, "piece " + std::to_string(end + 1) + " (end", "does not cover the run");
  }
  {  // the answer changed: the second end's bracket replaced by the first's
    json t = cert;
    t["answer"]["intervals"][0][1] = t["answer"]["intervals"][0][0];
    rejected(c, t, "answer");
  }
  {  // the answer's decimal changed, its bracket kept: the approx must be the bracket's mid-point
    json t = cert;
    t["answer"]["first_contact"]["approx"] = "0.5";
    rejected(c, t, "answer");
  }
  {  // the answer changed: no collision
    json t = cert;
    t["answer"] = {
        {"collides", false}, {"intervals", json::array()}, {"first_contact", nullptr}, {"contacts", json::array()}};
    rejected(c, t, "answer", "collides");
  }
  {  // an oversized number (denial of service): refused before it is parsed
    json t = cert;
    t["pieces"][out]["lo"] = "1/" + std::string(3000, '7');
    rejected(c, t, "certificate format", "1024 bits");
  }
  {  // too many chain boxes
    json t = cert;
    json& b = t["pieces"][end]["boxes"];
    while (b.size() <= kBezierMaxChain) b.push_back(b.back());
    rejected(c, t, "certificate format", "chain");
  }
  {  // a certificate for another scene
    json t = cert;
    t["scene"]["b"]["shape"]["semi_axes"][0] = "3";
    rejected(c, t, "scene");
  }
  {  // format 2's own claims (eccd-check: certificate/check/bezier_certificate.cpp): the net changed by one in one
     // coefficient
    json t = cert;
    json& x = t["net"]["coefficients"][2][0];
    x = mpq_class(rq(x) + 1).get_str();
    rejected(c, t, "net", "differs");
  }
  {  // a stated shape that is not a positive multiple of the scene's
    json t = cert;
    for (auto& row : t["net"]["shape_a"])
      for (auto& x : row) x = mpq_class(-rq(x)).get_str();
    rejected(c, t, "net", "positive multiple");
  }
  {  // a stated inverse motion that is not one
    json t = cert;
    json& p = t["net"]["inverse_b"][0][0];
    p = json::array({"1", "1"});
    rejected(c, t, "net");
  }
  {  // the exclusion tree cut short, and its root claimed a leaf (the whole strip is not of one sign)
    json t = cert;
    std::string tree = t["pieces"][end]["exclusion"].get<std::string>();
    REQUIRE(tree.size() > 1);
    t["pieces"][end]["exclusion"] = tree.substr(0, tree.size() - 1);
    rejected(c, t, "piece " + std::to_string(end + 1) + " (end", "ends early");
    t["pieces"][end]["exclusion"] = "0";
    rejected(c, t, "piece " + std::to_string(end + 1) + " (end", "not excluded");
    t["pieces"][end]["exclusion"] = tree + "0";
    rejected(c, t, "certificate format", "after the end of the tree");
  }
  {  // the old format is refused, saying so
    json t = cert;
    t["format"] = "eccd-bezier-certificate/1";
    rejected(c, t, "certificate format", "older version");
  }
}

TEST_CASE("bezier certificate: a free and an overlapping-at-start scene", "[bezier-certificate]") {
  for (const char* rel : {"cases/spheres/spheres-free.json", "cases/spheres/spheres-overlap-start.json"}) {
    const Case c = certified_case(rel);
    const CertificateCheck ok = check_certificate(c.scene, c.cert.dump());
    INFO(rel << ": " << ok.failed_claim << ": " << ok.reason);
    REQUIRE(ok.valid);
    REQUIRE(c.scene.answer);
    CHECK(c.cert["answer"]["collides"] == c.scene.answer->collides);
    CHECK(c.cert["answer"]["intervals"].size() == c.scene.answer->intervals.size());
    CHECK(c.cert["answer"]["contacts"].size() == c.scene.answer->contacts.size());
  }
}

TEST_CASE(
    "bezier certificate: a touch is not decided by the proof, the certified route falls back to the exact certificate",
    "[bezier-certificate]") {
  const Scene s = read_scene(src + "/cases/spheres/spheres-touch.json");
  const json doc = parse_json_document(s.source_text, s.path);
  CHECK_THROWS_AS(make_bezier_certificate(s, doc), CertificationError);
  std::string route, why;
  const json cert = make_certified_mode_certificate(s, doc, route, why);
  CHECK(route == "exact");
  CHECK_FALSE(why.empty());
  CHECK(cert["format"] == "eccd-certificate/2");
  CHECK(check_certificate(s, cert.dump()).valid);
}

TEST_CASE("cli: certify --arith certified writes a VALID Bezier certificate, says its route, nothing written on error",
          "[bezier-certificate][cli]") {
  const std::string exe = ECCD_EXE;
  const fs::path dir = fs::temp_directory_path() / ("eccd-bezcert-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string scene = src + "/cases/spheres/spheres-crossing.json";
  const fs::path cert = dir / "c.json";
  std::string out;
  REQUIRE(eccd::test::run(exe + " certify " + scene + " --arith certified --no-floating --json --out " + cert.string(),
                          out) == 0);
  const json r = json::parse(out);
  CHECK(r["route"] == "bezier");
  CHECK(r["answer"]["intervals"].size() == 1);
  REQUIRE(eccd::test::run(exe + " check-certificate " + scene + " " + cert.string(), out) == 0);
  CHECK(out.find("VALID") != std::string::npos);
  {  // tampered: exit 1 naming the claim
    std::ifstream in(cert);
    json t = json::parse(in);
    t["answer"]["intervals"][0][1] = t["answer"]["intervals"][0][0];
    std::ofstream(dir / "t.json") << t.dump();
    CHECK(eccd::test::run(exe + " check-certificate " + scene + " " + (dir / "t.json").string(), out) == 1);
    CHECK(out.find("REJECTED: answer") != std::string::npos);
  }
  // text output names the route; a 2D scene takes the exact route
  const std::string scene2d = src + "/cases/paper003/example2-away-1e-12.json";
  REQUIRE(eccd::test::run(
              exe + " certify " + scene2d + " --arith certified --no-floating --out " + (dir / "d2.json").string(),
              out) == 0);
  CHECK(out.find("route: exact") != std::string::npos);
  // an unknown --arith: refused, nothing written
  const fs::path none = dir / "none.json";
  CHECK(eccd::test::run(exe + " certify " + scene + " --arith double --out " + none.string(), out) != 0);
  CHECK_FALSE(fs::exists(none));
  // an unreadable scene: exit 2, nothing written
  CHECK(eccd::test::run(
            exe + " certify " + (dir / "missing.json").string() + " --arith certified --out " + none.string(), out) ==
        2);
  CHECK_FALSE(fs::exists(none));
  fs::remove_all(dir);
}

TEST_CASE(
    "bezier certificate: generated colliding 3D cases and paper 002's example, end to end against their stored answers",
    "[bezier-certificate]") {
  for (const char* rel :
       {"cases/generated/3d-affine/3d-deg2-colliding-affine-2295206434708192.json",
        "cases/generated/3d-euler/3d-deg4-colliding-euler-4706106488671681.json", "cases/paper002/example.json"}) {
    const Scene s = read_scene(src + "/" + rel);
    const json doc = parse_json_document(s.source_text, s.path);
    std::string route, why;
    const json cert = make_certified_mode_certificate(s, doc, route, why);
    INFO(rel << ": route " << route << " " << why);
    REQUIRE(route == "bezier");
    const CertificateCheck ok = check_certificate(s, cert.dump());
    INFO(ok.failed_claim << ": " << ok.reason);
    REQUIRE(ok.valid);
    // the proved answer is the stored (exact pipeline's) one: same counts, every bracket overlapping the stored one
    REQUIRE(s.answer);
    const Answer got = answer_from_json(cert["answer"], rel, "/answer");
    CHECK(got.collides == s.answer->collides);
    REQUIRE(got.intervals.size() == s.answer->intervals.size());
    REQUIRE(got.contacts.size() == s.answer->contacts.size());
    auto overlaps = [](const Instant& a, const Instant& b) { return *a.lo <= *b.hi && *b.lo <= *a.hi; };
    for (std::size_t i = 0; i < got.intervals.size(); ++i) {
      CHECK(overlaps(got.intervals[i].first, s.answer->intervals[i].first));
      CHECK(overlaps(got.intervals[i].second, s.answer->intervals[i].second));
    }
    for (std::size_t i = 0; i < got.contacts.size(); ++i) CHECK(overlaps(got.contacts[i], s.answer->contacts[i]));
    // and a piece boundary moved (two neighbours overlapping) is a coverage failure on a real proof too
    json t = cert;
    REQUIRE(t["pieces"].size() >= 2);
    t["pieces"][1]["lo"] = mpq_class(rq(t["pieces"][1]["lo"]) - mpq_class(1, 1 << 20)).get_str();
    rejected(Case{s, doc, cert}, t, "coverage");
  }
}

TEST_CASE(
    "cli: regress --arith certified --certify certifies each scene by the certified route, every certificate VALID",
    "[bezier-certificate][cli]") {
  const std::string exe = ECCD_EXE;
  std::string out;
  REQUIRE(eccd::test::run(exe + " regress " + src + "/cases/spheres --arith certified --certify --json", out) == 0);
  const json r = json::parse(out);
  int bezier = 0, exact = 0;
  REQUIRE(r["scenes"].size() == 7);
  for (const auto& row : r["scenes"]) {
    INFO(row.dump());
    CHECK(row["result"] == "ok");
    CHECK(row["certificate"]["valid"] == true);
    bezier += row["certificate"]["route"] == "bezier";
    exact += row["certificate"]["route"] == "exact";
  }
  // the two touches (spheres-touch, spheres-touch-at-start) are not decided by intervals: exact route; the rest by the
  // proof
  CHECK(bezier == 5);
  CHECK(exact == 2);
}

}  // namespace ECCD_UNITY_ID
