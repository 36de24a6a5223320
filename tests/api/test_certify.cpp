// Certify and check a certificate through the typed API (api/certify.hpp):
// the certified Solution is the stored exact answer, the certificate passes
// the checker, a forged bracket fails it, and a scene without its JSON text
// is refused with the reason.
#include <eccd/eccd.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace ECCD_UNITY_ID {
namespace {
const std::string kCases = std::string(ECCD_SOURCE_DIR) + "/cases/";
bool overlaps(const eccd::Instant& a, const eccd::Instant& b) { return *a.lo <= *b.hi && *b.lo <= *a.hi; }
}  // namespace

TEST_CASE(
    "certify returns the certificate and the certified Solution, and check_certificate accepts it and rejects a "
    "forgery",
    "[api][certify]") {
  for (const char* file : {"paper003/example2.json", "spheres/spheres-touch.json"}) {
    INFO(file);
    eccd::Scene s = eccd::read_scene(kCases + file);
    REQUIRE(s.answer);
    eccd::Certificate c = eccd::certify(s);
    CHECK(c.solution.certified);
    CHECK(c.solution.arith.name() == "exact");
    CHECK(c.solution.answer.collides == s.answer->collides);
    REQUIRE(c.solution.answer.intervals.size() == s.answer->intervals.size());
    for (std::size_t k = 0; k < s.answer->intervals.size(); ++k) {
      CHECK(overlaps(c.solution.answer.intervals[k].first, s.answer->intervals[k].first));
      CHECK(overlaps(c.solution.answer.intervals[k].second, s.answer->intervals[k].second));
    }
    eccd::CertificateCheck ok = eccd::check_certificate(s, c.text);
    CHECK(ok.valid);
    CHECK_FALSE(ok.checked.empty());
    // Forge the certificate: its f's first coefficient changes sign.
    nlohmann::json j = nlohmann::json::parse(c.text);
    std::string g00 = j["f"]["g"][0][0];
    j["f"]["g"][0][0] = g00 == "0" ? std::string("1") : g00[0] == '-' ? g00.substr(1) : "-" + g00;
    std::string forged = j.dump();
    eccd::CertificateCheck bad = eccd::check_certificate(s, forged);
    CHECK_FALSE(bad.valid);
    CHECK_FALSE(bad.failed_claim.empty());
  }
}

TEST_CASE("certify refuses a scene without its JSON text, naming the reason", "[api][certify]") {
  eccd::Scene s = eccd::read_scene(kCases + "paper003/example2.json");
  s.source_text.clear();
  CHECK_THROWS_WITH(eccd::certify(s), Catch::Contains("has no JSON text"));
}

}  // namespace ECCD_UNITY_ID
