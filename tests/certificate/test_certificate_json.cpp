// The prover-side certificate helpers (certificate/write/certificate_json.hpp):
//   - at: a missing key or a non-object is a "certificate format" rejection
//     naming the place (the non-object named as such, or as the key missing);
//   - read_rational / read_short_rational(s): rationals within the bit bound,
//     in lowest terms; a rational over the bound (numerator or denominator),
//     a text too long to parse at all, a non-string, a malformed text are
//     rejections, never exceptions of another kind;
//   - run_checker: VALID when the check returns; the first Reject becomes
//     failed_claim and reason; any other exception becomes a "certificate
//     format" failure (never a crash, never VALID); the claims checked so
//     far are kept;
//   - same_instant and require_same_intervals compare brackets and
//     decimals; finish_proof_certificate refuses an invalid self-check and
//     stamps a valid one.
#include "certificate/write/certificate_json.hpp"

#include <catch2/catch.hpp>

#include <functional>
#include <stdexcept>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::certificate_json;

namespace {

Reject rejection(const std::function<void()>& f) {
  try {
    f();
  } catch (const Reject& r) {
    return r;
  }
  return Reject{"", ""};
}

Instant inst(const std::string& approx, const mpq_class& lo, const mpq_class& hi) {
  Instant i;
  i.approx = approx;
  i.lo = lo;
  i.hi = hi;
  return i;
}

}  // namespace

TEST_CASE("certificate_json at and the rational readers", "[certificate][certificate_json]") {
  const json j = {{"a", 1}};
  CHECK(at(j, "a", "root") == 1);
  Reject r = rejection([&] { at(j, "b", "root"); });
  CHECK(r.claim == "certificate format");
  CHECK(r.reason == "root: missing \"b\"");
  r = rejection([&] { at(json::array(), "b", "root"); });
  CHECK(r.reason.rfind("root: expected an object with the key \"b\"", 0) == 0);
  CHECK(rejection([&] { at(json(3), "b", "root", false); }).reason == "root: missing \"b\"");

  CHECK(read_rational(json("6/4"), "p", 64) == mpq_class(3, 2));
  CHECK(read_rational(json("-7"), "p", 64) == -7);
  const std::string two70 = mpz_class(mpz_class(1) << 70).get_str();
  CHECK(rejection([&] { read_rational(json(two70), "p", 64); }).reason.find("more than 64 bits") != std::string::npos);
  CHECK(rejection([&] { read_rational(json("1/" + two70), "p", 64); }).reason.find("more than 64 bits") !=
        std::string::npos);
  CHECK(rejection([&] { read_rational(json(std::string(100000, '9')), "p", 64); }).reason.find("characters") !=
        std::string::npos);
  CHECK(rejection([&] { read_rational(json(3), "p", 64); }).reason.find("written as a string") != std::string::npos);
  for (const char* bad : {"1/0", "abc", "1//2", ""}) {
    INFO(bad);
    const Reject b = rejection([&] { read_rational(json(bad), "p", 64); });
    CHECK(b.claim == "certificate format");
    CHECK(b.reason.rfind("p: ", 0) == 0);
  }
  CHECK(read_short_rational(json("10/4"), "p", 16) == mpq_class(5, 2));
  CHECK(rejection([&] { read_short_rational(json("123456789/2"), "p", 16); }).reason.find("more than 16 bits") !=
        std::string::npos);
  CHECK(rejection([&] { read_short_rational(json(std::string(40, '1')), "p", 16); }).reason.find("at most 16 bits") !=
        std::string::npos);
  CHECK(read_short_rationals(json::array({"1/2", "3"}), 2, "p", 16) == std::vector<mpq_class>{mpq_class(1, 2), 3});
  CHECK(rejection([&] { read_short_rationals(json::array({"1/2"}), 2, "p", 16); }).reason == "p: expected 2 rationals");
}

TEST_CASE("certificate_json run_checker turns every outcome into a verdict", "[certificate][certificate_json]") {
  std::vector<std::string> checked;
  CertificateCheck v = run_checker([&] { checked.push_back("scene: ok"); }, checked);
  CHECK(v.valid);
  CHECK(v.checked == std::vector<std::string>{"scene: ok"});
  checked.clear();
  v = run_checker(
      [&] {
        checked.push_back("scene: ok");
        reject("f", "g_2 differs");
      },
      checked);
  CHECK_FALSE(v.valid);
  CHECK(v.failed_claim == "f");
  CHECK(v.reason == "g_2 differs");
  CHECK(v.checked.size() == 1);
  checked.clear();
  v = run_checker([&] { (void)json::array().at(5); }, checked);  // nlohmann's out_of_range: unforeseen
  CHECK_FALSE(v.valid);
  CHECK(v.failed_claim == "certificate format");
  CHECK(v.reason.rfind("malformed certificate after the claims checked so far: ", 0) == 0);
}

TEST_CASE("certificate_json instants, intervals and the end of a proof certificate",
          "[certificate][certificate_json]") {
  const Instant a = inst("0.25", mpq_class(1, 4), mpq_class(1, 4)), b = inst("0.4", mpq_class(1, 3), mpq_class(1, 2));
  CHECK(same_instant(a, a));
  CHECK_FALSE(same_instant(a, b));
  CHECK_FALSE(same_instant(a, inst("0.250", mpq_class(1, 4), mpq_class(1, 4))));  // the same bracket, another decimal
  CHECK_FALSE(same_instant(Instant{}, Instant{}));                                // not certified
  const std::vector<std::pair<Instant, Instant>> x{{a, b}};
  CHECK_NOTHROW(require_same_intervals(x, x, "intervals", "the proofs"));
  CHECK(rejection([&] { require_same_intervals(x, {}, "intervals", "the proofs"); }).reason ==
        "the proofs give 1 intervals, the certificate 0");
  CHECK(rejection([&] {
          require_same_intervals(x, {{a, a}}, "intervals", "the pieces");
        }).reason == "intervals 1 differs from the one the pieces give");

  json c = json::object();
  CertificateCheck bad;
  bad.failed_claim = "f";
  bad.reason = "why";
  CHECK_THROWS_AS(
      finish_proof_certificate(c, bad, "fmt/1", 128, Answer{}, "m", std::chrono::steady_clock::now(), nullptr),
      CertificationError);
  CertificateCheck good;
  good.valid = true;
  Solution sol;
  Answer ans;
  ans.collides = true;
  finish_proof_certificate(c, good, "fmt/1", 128, ans, "bezier", std::chrono::steady_clock::now(), &sol);
  CHECK(c.contains("seconds"));
  CHECK(c["seconds"].get<double>() >= 0);
  CHECK(sol.certified);
  CHECK(sol.answer.collides);
  CHECK(sol.basis == "interval+mpfi:128");
  CHECK(sol.method == "bezier");
  CHECK(sol.decided_in.find("fmt/1") != std::string::npos);
}

}  // namespace ECCD_UNITY_ID
