// The independent-motion certificate (certificate/write/independent_certificate.hpp, checked
// by eccd-check: certificate/check/independent_certificate.cpp): cases
// certified in 2D and 3D (bodies that stop, stand still or turn in place),
// their certificates VALID, and tampered copies (a moved bracket, a flipped
// strip, a dropped strip, a changed scene number, a forged reduction, an
// exclusion tree cut short) REJECTED naming the claim.
#include "api/certify.hpp"
#include "api/solve.hpp"
#include "certificate/write/independent_certificate.hpp"
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {

CertificateCheck check(const Scene& s, const json& cert) { return check_certificate(s, cert.dump()); }

void rejected(const Scene& s, const json& t, const std::string& claim) {
  const CertificateCheck r = check(s, t);
  INFO("expected to fail: " << claim << "; got " << (r.valid ? "VALID" : r.failed_claim + ": " + r.reason));
  CHECK_FALSE(r.valid);
  CHECK(r.failed_claim.find(claim) != std::string::npos);
}

}  // namespace

TEST_CASE("independent certificate: spheres-end round trip and tampering", "[independent][certificate]") {
  const Scene s = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/independent/spheres-end.json");
  const Certificate c = certify(s);
  const json cert = json::parse(c.text);
  REQUIRE(cert["format"] == kIndependentCertificateFormat);
  const CertificateCheck ok = check(s, cert);
  INFO(ok.failed_claim << ": " << ok.reason);
  REQUIRE(ok.valid);
  // the answer: the paths meet, one s-interval and one t-interval, their brackets containing the stored answer's
  REQUIRE(cert["answer"]["collides"] == true);
  REQUIRE(s.answer);
  REQUIRE(cert["answer"]["s_intervals"].size() == s.answer->s_intervals.size());
  REQUIRE(cert["answer"]["t_intervals"].size() == s.answer->t_intervals.size());
  for (const char* k : {"s_intervals", "t_intervals"}) {
    const auto& stored = std::string(k) == "s_intervals" ? s.answer->s_intervals : s.answer->t_intervals;
    for (std::size_t i = 0; i < stored.size(); ++i)
      for (int e = 0; e < 2; ++e) {
        const Instant& want = e ? stored[i].second : stored[i].first;
        const json& got = cert["answer"][k][i][e];
        const mpq_class lo = parse_rational(got["lo"].get<std::string>()),
                        hi = parse_rational(got["hi"].get<std::string>());
        INFO(k << " " << i << " end " << e << ": stored " << want.approx << ", certified [" << lo.get_d() << ", "
               << hi.get_d() << "]");
        CHECK(hi - lo < mpq_class(1, 1000000));
        CHECK(std::abs(want.value - lo.get_d()) < 1e-6);
      }
  }
  // find an end and a strip of each kind in the s-proof
  std::size_t end = 0, in = 0, out = 0;
  const json& items = cert["s_proof"];
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i]["kind"] == "end" && !end) end = i;
    if (items[i]["kind"] == "in" && !in) in = i;
    if (items[i]["kind"] == "out" && !out) out = i;
  }
  REQUIRE(end > 0);
  REQUIRE(in > 0);
  {  // a moved bracket: shifted by its run's width, it leaves the run
    json t = cert;
    json& e = t["s_proof"][end];
    const mpq_class lo = parse_rational(e["bracket"][0].get<std::string>()),
                    hi = parse_rational(e["bracket"][1].get<std::string>());
    const mpq_class w = parse_rational(e["hi"].get<std::string>()) - parse_rational(e["lo"].get<std::string>());
    e["bracket"] = {mpq_class(lo + w).get_str(), mpq_class(hi + w).get_str()};
    rejected(s, t, "s_proof item " + std::to_string(end + 1) + " (");
  }
  {  // a moved bracket in the answer only: no longer what the proofs give
    json t = cert;
    json& a = t["answer"]["s_intervals"][0][0];
    a["lo"] = mpq_class(parse_rational(a["lo"].get<std::string>()) - mpq_class(1, 1024)).get_str();
    rejected(s, t, "answer");
  }
  {  // a flipped strip: an in-strip claimed out (its boxes are negative, not positive)
    json t = cert;
    t["s_proof"][in]["kind"] = "out";
    rejected(s, t, "s_proof item " + std::to_string(in + 1) + " (");
  }
  {  // a flipped strip: an out-strip claimed in
    json t = cert;
    t["s_proof"][out]["kind"] = "in";
    rejected(s, t, "s_proof item " + std::to_string(out + 1) + " (");
  }
  {  // a dropped strip: the coverage of [0, 1] has a gap
    json t = cert;
    t["s_proof"].erase(t["s_proof"].begin() + long(out));
    rejected(s, t, "coverage");
  }
  {  // a dropped box of an in-strip with more than one: its u-ranges no longer cover [0, 1]
    json t = cert;
    std::size_t k = 0;
    while (k < items.size() && !(items[k]["kind"] == "in" && items[k]["boxes"].size() > 1)) ++k;
    REQUIRE(k < items.size());
    t["s_proof"][k]["boxes"].erase(t["s_proof"][k]["boxes"].begin());
    rejected(s, t, "s_proof item " + std::to_string(k + 1) + " (");
  }
  {  // a changed scene number: a certificate for another scene
    json t = cert;
    t["scene"]["b"]["shape"]["semi_axes"][0] = "3/5";
    rejected(s, t, "scene");
  }
  {  // the scene file changed (B larger): F differs, so the claims about its net fail
    std::ifstream file(std::string(ECCD_SOURCE_DIR) + "/cases/independent/spheres-end.json");
    json doc = json::parse(file);
    doc["b"]["shape"]["semi_axes"] = {"3/5", "3/5", "3/5"};
    doc.erase("answer");
    json t = cert;
    t["scene"]["b"] = doc["b"];
    const Scene s3 = parse_scene(doc.dump(), "changed.json");
    const CertificateCheck r = check(s3, t);
    CHECK_FALSE(r.valid);
  }
}

TEST_CASE("independent certificate: ellipsoids-apart (no meeting) round trip", "[independent][certificate]") {
  const Scene s = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/independent/ellipsoids-apart.json");
  const Certificate c = certify(s);
  const json cert = json::parse(c.text);
  REQUIRE(cert["format"] == kIndependentCertificateFormat);
  const CertificateCheck ok = check(s, cert);
  INFO(ok.failed_claim << ": " << ok.reason);
  REQUIRE(ok.valid);
  CHECK(cert["answer"]["collides"] == false);
  CHECK(cert["answer"]["s_intervals"].empty());
  {  // an out-strip claimed in: its boxes are positive, not negative
    json t = cert;
    t["s_proof"][0]["kind"] = "in";
    rejected(s, t, "s_proof item 1 (");
  }
  {  // a changed scene number
    json t = cert;
    t["scene"]["a"]["shape"]["semi_axes"][0] = "7";
    rejected(s, t, "scene");
  }
}

TEST_CASE("independent certificate: 2D scenes (discs-end, ellipse-static) round trip, the free system and the format",
          "[independent][certificate]") {
  // discs-end: two discs on lines whose meeting ends where B's path stops (edge systems "0", "1");
  // ellipse-static: B does not move, so the ends of P_s are proved on F = F_u = 0 in (u, s) (system "free").
  for (const char* name : {"discs-end", "ellipse-static"}) {
    INFO(name);
    const Scene s = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/independent/" + name + ".json");
    REQUIRE(s.dim == 2);
    const Certificate c = certify(s);
    const json cert = json::parse(c.text);
    REQUIRE(cert["format"] == kIndependentCertificateFormat);
    const CertificateCheck ok = check(s, cert);
    INFO(ok.failed_claim << ": " << ok.reason);
    REQUIRE(ok.valid);
    CHECK(cert["reduced"] == json::array());
    // the certified brackets hold the stored answer's ends (the case's note gives them analytically)
    REQUIRE(s.answer);
    REQUIRE(cert["answer"]["collides"] == true);
    for (const char* k : {"s_intervals", "t_intervals"}) {
      const auto& stored = std::string(k) == "s_intervals" ? s.answer->s_intervals : s.answer->t_intervals;
      REQUIRE(cert["answer"][k].size() == stored.size());
      for (std::size_t i = 0; i < stored.size(); ++i)
        for (int e = 0; e < 2; ++e) {
          const json& got = cert["answer"][k][i][e];
          const mpq_class lo = parse_rational(got["lo"].get<std::string>()),
                          hi = parse_rational(got["hi"].get<std::string>());
          CHECK(lo <= hi);
          CHECK(hi - lo < mpq_class(1, 1000000));
          CHECK(std::abs((e ? stored[i].second : stored[i].first).value - lo.get_d()) < 1e-6);
        }
    }
    std::size_t end = 0;
    const json& items = cert["s_proof"];
    while (end < items.size() && items[end]["kind"] != "end") ++end;
    REQUIRE(end < items.size());
    const std::string sys = items[end]["system"].get<std::string>();
    CHECK(sys == (std::string(name) == "ellipse-static" ? "free" : "0"));
    {  // the end's system changed: its chain has the wrong unknowns or its conditions fail
      json t = cert;
      t["s_proof"][end]["system"] = sys == "free" ? "fold" : "free";
      const CertificateCheck r = check(s, t);
      INFO(r.failed_claim << ": " << r.reason);
      CHECK_FALSE(r.valid);
      CHECK((r.failed_claim + ": " + r.reason).find("s_proof item " + std::to_string(end + 1)) != std::string::npos);
    }
    {  // a claimed reduction that F's net does not have
      json t = cert;
      t["reduced"] = {"s"};
      rejected(s, t, "reduced");
    }
    {  // the older format is refused by name
      json t = cert;
      t["format"] = "eccd-independent-certificate/2";
      const CertificateCheck r = check(s, t);
      CHECK_FALSE(r.valid);
      CHECK(r.reason.find("an older version, no longer accepted") != std::string::npos);
    }
    {  // a flipped out-strip
      json t = cert;
      std::size_t out = 0;
      while (out < items.size() && items[out]["kind"] != "out") ++out;
      REQUIRE(out < items.size());
      t["s_proof"][out]["kind"] = "in";
      rejected(s, t, "s_proof item " + std::to_string(out + 1) + " (");
    }
  }
}

TEST_CASE("independent certificate: a body turning in place (disc-turning 2D, ball-turning 3D) round trip",
          "[independent][certificate]") {
  // A turns about its fixed centre: A(s) = c(s) A(0), so the net holds A at s = 0 (reduced ["s"]), P_s = [0, 1] and
  // the ends of P_t are proved on F = F_u = 0 in (u, t) (system "free" in the t-proof); analytic t-ends:
  // disc-turning 144 t^2 - 144 t + 31 = 0, ball-turning 36 t^2 - 42 t + 11 = 0
  const std::pair<const char*, std::vector<int>> cases[] = {{"disc-turning", {31, -144, 144}},
                                                            {"ball-turning", {11, -42, 36}}};
  for (const auto& [name, p] : cases) {
    INFO(name);
    const Scene s = read_scene(std::string(ECCD_SOURCE_DIR) + "/cases/independent/" + name + ".json");
    const Certificate c = certify(s);
    const json cert = json::parse(c.text);
    REQUIRE(cert["format"] == kIndependentCertificateFormat);
    const CertificateCheck ok = check(s, cert);
    INFO(ok.failed_claim << ": " << ok.reason);
    REQUIRE(ok.valid);
    CHECK(cert["reduced"] == json::array({"s"}));
    CHECK(cert["net"]["degrees"][1] == 0);
    REQUIRE(cert["answer"]["s_intervals"].size() == 1);
    CHECK(cert["answer"]["s_intervals"][0][0]["lo"] == "0");
    CHECK(cert["answer"]["s_intervals"][0][1]["hi"] == "1");
    REQUIRE(cert["answer"]["t_intervals"].size() == 1);
    for (int e = 0; e < 2; ++e) {  // each bracket holds a sign change of the quadratic
      const json& got = cert["answer"]["t_intervals"][0][e];
      const mpq_class lo = parse_rational(got["lo"].get<std::string>()),
                      hi = parse_rational(got["hi"].get<std::string>());
      auto f = [&](const mpq_class& x) { return sgn(mpq_class(p[0] + p[1] * x + p[2] * x * x)); };
      CHECK(f(lo) * f(hi) <= 0);
      CHECK(hi - lo < mpq_class(1, 1000000));
    }
    bool free_end = false;
    for (const auto& it : cert["t_proof"]) free_end = free_end || (it["kind"] == "end" && it["system"] == "free");
    CHECK(free_end);
    {  // the reduction dropped: the net (degree 0 in s) is not F of the turning body
      json t = cert;
      t["reduced"] = json::array();
      rejected(s, t, "net");
    }
    {  // an exclusion tree cut short
      json t = cert;
      for (auto& it : t["t_proof"])
        if (it["kind"] == "end") {
          it["exclusion"] = "1";
          break;
        }
      const CertificateCheck r = check(s, t);
      CHECK_FALSE(r.valid);
      CHECK(r.reason.find("exclusion tree ends early") != std::string::npos);
    }
  }
}

}  // namespace ECCD_UNITY_ID
