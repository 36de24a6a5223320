// The claims every certificate kind shares (certificate/check/claims.hpp):
//   - the readers: rational ("p/q" in lowest terms after reading, size
//     bounded in bits and characters), whole (range, unsigned JSON integers),
//     status_named, sign_named, read_decimal and bracket_text; each refusal
//     is a Rejected with the claim "certificate format" and the place;
//   - check_approx: inside a bracket, or for a point [r, r] r rounded to the
//     approx's own last digit (within half a unit);
//   - answer_claim on a timeline worked out by hand from the statement
//     (docs/certificate-format.md): instants I0..I5 and cells C0..C4 with
//       I0 [0] separate, C0 separate, I1 [1/4] touching, C1 separate,
//       I2 [1/3, 1/2] touching, C2 overlapping, I3 [2/3, 3/4] touching,
//       C3 touching, I4 [7/8] touching, C4 separate, I5 [1] separate,
//     whose answer is: collides; intervals [I1, I1] and [I2, I4]; contacts I1
//     and I2 (touching instants not next to a touching cell); contact
//     intervals [I3, I4] (the touching cell C3); first contact I1. That
//     answer is accepted; each single change of it (collides, a bracket, an
//     approx outside its bracket, a missing contact interval, an extra key, a
//     wrong first contact, a lost contact) is rejected, and a cell in
//     collision next to a separate instant is rejected as a timeline that
//     is not closed.
#include "certificate/check/claims.hpp"

#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::check;

namespace {

Rejected rejection(const std::function<void()>& f) {
  try {
    f();
  } catch (const Rejected& r) {
    return r;
  }
  return Rejected{"", ""};
}

struct Node {
  mpq_class lo, hi;
  bool cell = false;
  St status = St::separate;
  std::string name;
};

mpq_class q(long n, long d = 1) {
  mpq_class r(n, d);
  r.canonicalize();
  return r;
}

std::vector<Node> timeline() {
  std::vector<Node> s;
  auto inst = [&](mpq_class lo, mpq_class hi, St st, std::string n) { s.push_back({lo, hi, false, st, n}); };
  auto cell = [&](mpq_class x, St st, std::string n) { s.push_back({x, x, true, st, n}); };
  inst(q(0), q(0), St::separate, "I0");
  cell(q(1, 8), St::separate, "C0");
  inst(q(1, 4), q(1, 4), St::touching, "I1");
  cell(q(3, 10), St::separate, "C1");
  inst(q(1, 3), q(1, 2), St::touching, "I2");
  cell(q(3, 5), St::overlapping, "C2");
  inst(q(2, 3), q(3, 4), St::touching, "I3");
  cell(q(4, 5), St::touching, "C3");
  inst(q(7, 8), q(7, 8), St::touching, "I4");
  cell(q(15, 16), St::separate, "C4");
  inst(q(1), q(1), St::separate, "I5");
  return s;
}

json instant(const std::string& approx, const std::string& lo, const std::string& hi) {
  return json{{"approx", approx}, {"lo", lo}, {"hi", hi}};
}

json good_certificate() {
  const json i1 = instant("0.25", "1/4", "1/4"), i2 = instant("0.4", "1/3", "1/2"), i3 = instant("0.7", "2/3", "3/4"),
             i4 = instant("0.875", "7/8", "7/8");
  return json{{"answer",
               {{"collides", true},
                {"intervals", json::array({json::array({i1, i1}), json::array({i2, i4})})},
                {"first_contact", i1},
                {"contacts", json::array({i1, i2})},
                {"contact_intervals", json::array({json::array({i3, i4})})}}}};
}

}  // namespace

TEST_CASE("check claims readers accept the format and reject the rest", "[certificate][check_claims]") {
  CHECK(rational(json("3/7"), "p", 64) == q(3, 7));
  CHECK(rational(json("-6/4"), "p", 64) == q(-3, 2));
  CHECK(rational(json("12"), "p", 64) == 12);
  for (const json& bad :
       {json("3/-7"), json("1.5"), json(""), json("/3"), json("3/"), json("+3"), json(3), json(nullptr)}) {
    INFO(bad.dump());
    const Rejected r = rejection([&] { rational(bad, "answer.x", 64); });
    CHECK(r.claim == "certificate format");
    CHECK(r.reason.rfind("answer.x: expected a rational", 0) == 0);
  }
  CHECK(rejection([] { rational(json("1/0"), "p", 64); }).reason == "p: zero denominator");
  const std::string big = mpz_class(mpz_class(1) << 70).get_str();
  CHECK(rejection([&] { rational(json(big), "p", 64); }).reason.find("more than 64 bits") != std::string::npos);
  CHECK(rational(json(big), "p", 71) == mpq_class(mpz_class(1) << 70));
  CHECK(rejection([] { rational(json(std::string(500, '1')), "p", 64); }).reason.find("more than 64 bits") !=
        std::string::npos);

  CHECK(whole(json(5), "w", 0, 10) == 5);
  CHECK(whole(json(-3), "w", -5, 10) == -3);
  CHECK(whole(json(std::uint64_t(7)), "w", 0, 10) == 7);
  for (const json& bad : {json(11), json(-6), json(2.5), json("3"), json(std::uint64_t(1) << 63)})
    CHECK(rejection([&] { whole(bad, "w", -5, 10); }).reason.find("w: expected a whole number from -5 to 10") == 0);

  CHECK(status_named(json("touching"), "s") == St::touching);
  CHECK(rejection([] { status_named(json("Touching"), "s"); }).claim == "certificate format");
  CHECK(sign_named(json("negative"), "s") == -1);
  CHECK(sign_named(json("zero"), "s") == 0);
  CHECK(sign_named(json("positive"), "s") == 1);
  CHECK(rejection([] { sign_named(json(1), "s"); }).reason.find("s: expected \"negative\"") == 0);
  CHECK(bracket_text(q(1, 3), q(1, 3)) == "[1/3]");
  CHECK(bracket_text(q(1, 3), q(1, 2)) == "[1/3, 1/2]");

  mpq_class v, u;
  REQUIRE(read_decimal("-1.25e-1", 20, v, u));
  CHECK(v == q(-1, 8));
  CHECK(u == q(1, 1000));
  CHECK_FALSE(read_decimal("1.25", 3, v, u));  // too long
  CHECK_FALSE(read_decimal("1e", 20, v, u));
}

TEST_CASE("check claims check_approx: in the bracket, or a point rounded to its last digit",
          "[certificate][check_claims]") {
  CHECK_NOTHROW(check_approx(json("0.4"), q(1, 3), q(1, 2), "answer", "p", 50));
  CHECK_NOTHROW(check_approx(json("0.3333"), q(1, 3), q(1, 3), "answer", "p", 50));  // |1/3 - 0.3333| <= 0.00005
  CHECK_NOTHROW(check_approx(json("0.25"), q(1, 4), q(1, 4), "answer", "p", 50));
  const Rejected r = rejection([] { check_approx(json("0.6"), q(1, 3), q(1, 2), "answer", "p", 50); });
  CHECK(r.claim == "answer");
  CHECK(r.reason == "p: approx \"0.6\" lies outside its bracket [1/3, 1/2]");
  CHECK(rejection([] { check_approx(json("0.3334"), q(1, 3), q(1, 3), "answer", "p", 50); }).claim == "answer");
  CHECK(rejection([] { check_approx(json(0.4), q(1, 3), q(1, 2), "answer", "p", 50); }).reason.find("decimal string") !=
        std::string::npos);
}

TEST_CASE("check claims answer_claim assembles the hand-worked answer and rejects every change",
          "[certificate][check_claims]") {
  const std::vector<Node> seq = timeline();
  std::vector<std::string> checked;
  REQUIRE_NOTHROW(answer_claim(good_certificate(), seq, 64, 50, checked));
  CHECK(checked.size() == 1);

  auto rejected = [&](const std::function<void(json&)>& change) {
    json c = good_certificate();
    change(c);
    std::vector<std::string> ch;
    return rejection([&] { answer_claim(c, seq, 64, 50, ch); });
  };
  CHECK(rejected([](json& c) { c["answer"]["collides"] = false; }).claim == "answer");
  CHECK(rejected([](json& c) { c["answer"]["intervals"][1][1]["hi"] = "8/9"; }).claim == "answer");
  CHECK(rejected([](json& c) { c["answer"]["intervals"][1][0]["approx"] = "0.6"; }).claim == "answer");
  CHECK(rejected([](json& c) { c["answer"].erase("contact_intervals"); }).reason.find("continuous touch") !=
        std::string::npos);
  CHECK(rejected([](json& c) { c["answer"]["contact_intervals"] = json::array(); }).reason.find("continuous touch") !=
        std::string::npos);
  CHECK(rejected([](json& c) { c["answer"]["first_contact"] = c["answer"]["contacts"][1]; }).claim == "answer");
  CHECK(rejected([](json& c) { c["answer"]["first_contact"] = nullptr; }).claim == "answer");
  CHECK(rejected([](json& c) { c["answer"]["contacts"].erase(1); }).claim == "answer");
  CHECK(rejected([](json& c) { c["answer"]["intervals"][0][0]["note"] = "x"; }).claim == "certificate format");
  CHECK(rejected([](json& c) { c["answer"]["extra"] = 1; }).claim == "certificate format");
  CHECK(rejected([](json& c) { c["answer"]["intervals"].erase(0); }).claim == "answer");

  // a cell in collision next to a separate instant: the collision set would not be closed
  std::vector<Node> open = seq;
  open[3].status = St::overlapping;  // C1 between I1 (touching) and I2 (touching): fine
  open[9].status = St::overlapping;  // C4 between I4 (touching) and I5 (separate): not closed
  const Rejected r = rejection([&] {
    std::vector<std::string> ch;
    answer_claim(good_certificate(), open, 64, 50, ch);
  });
  CHECK(r.claim == "timeline");
  CHECK(r.reason.rfind("C4 is in collision", 0) == 0);

  // no collision at all: collides false, no intervals, first_contact null
  std::vector<Node> apart = seq;
  for (auto& n : apart) n.status = St::separate;
  const json none = {
      {"answer",
       {{"collides", false}, {"intervals", json::array()}, {"first_contact", nullptr}, {"contacts", json::array()}}}};
  std::vector<std::string> ch;
  CHECK_NOTHROW(answer_claim(none, apart, 64, 50, ch));
}

}  // namespace ECCD_UNITY_ID
