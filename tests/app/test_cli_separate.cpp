// `eccd separate` (app/separate.cpp), tags [separate][cli]: the JSON plane is
// re-checked by hand (exact rationals, support function of the test's own
// ellipsoids; no code shared with the construction), the text mode, and the
// exit codes of docs/exit-codes.md.
#include "cli_run.hpp"

#include <gmpxx.h>
#include <nlohmann/json.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;

namespace {

// a: ellipsoid semi-axes (3, 2, 1) at the origin, static; b: unit ball at (5, 1, 0) + t (1, 0, 0).
const char* kScene = R"({"format": "ellipse-ccd-scene/1", "name": "cli-separate", "dim": 3,
 "a": {"shape": {"semi_axes": ["3", "2", "1"]}, "motion": {"type": "static"}},
 "b": {"shape": {"semi_axes": ["1", "1", "1"]}, "motion": {"type": "matrix", "m": [["1", "0", "0", ["5", "1"]],
   ["0", "1", "0", "1"], ["0", "0", "1", "0"], ["0", "0", "0", "1"]]}}})";

// n·c + o and nᵀ diag(axes²) n: the plane separates strictly iff the signs are right and (n·c + o)² exceeds it.
bool strictly(const std::vector<mpq_class>& n, const mpq_class& o, const std::vector<mpq_class>& c,
              const std::vector<mpq_class>& axes, int want_sign) {
  mpq_class side = o, spread = 0;
  for (int i = 0; i < 3; ++i) {
    side += n[i] * c[i];
    spread += axes[i] * axes[i] * n[i] * n[i];
  }
  return sgn(side) == want_sign && side * side > spread;
}

}  // namespace

TEST_CASE("eccd separate --json: an exact rational plane that a hand check proves", "[separate][cli]") {
  TempDir d;
  spit(d.path / "s.json", kScene);
  for (const char* at : {"0", "1/3", "0.75", "1"}) {
    INFO(at);
    Run r = run_eccd("separate " + q((d.path / "s.json").string()) + " --at " + at + " --json");
    REQUIRE(r.code == 0);
    auto j = nlohmann::json::parse(r.out);
    CHECK(j["format"] == "eccd-separate/1");
    CHECK(j["status"] == "separate");
    CHECK(j["t"] == mpq_class(std::string(at) == "0.75" ? "3/4" : at).get_str());
    std::vector<mpq_class> n;
    for (const auto& x : j["plane"]["normal"]) n.emplace_back(x.get<std::string>());  // exact rational strings
    REQUIRE(n.size() == 3);
    for (auto& x : n) x.canonicalize();
    mpq_class o(j["plane"]["offset"].get<std::string>());
    o.canonicalize();
    mpq_class t(std::string(at) == "0.75" ? "3/4" : at);
    CHECK(strictly(n, o, {0, 0, 0}, {3, 2, 1}, -1));
    CHECK(strictly(n, o, {mpq_class(5) + t, 1, 0}, {1, 1, 1}, 1));
    CHECK(j["tangent_points"].size() == 2);
    REQUIRE(j["checks"].size() == 4);
    for (const auto& c : j["checks"]) {  // each stated inequality holds for its stated exact value
      mpq_class v(c["value"].get<std::string>());
      v.canonicalize();
      CHECK(sgn(v) == (c["relation"] == "> 0" ? 1 : -1));
    }
  }
}

TEST_CASE("eccd separate: text, touching, double, and exit codes", "[separate][cli]") {
  Run r = run_eccd("separate " + q(src("cases/paper003/example2.json")) + " --at 1/2");
  CHECK(r.code == 0);
  CHECK(r.out.find("touching") != std::string::npos);  // 003 Example 2 touches at t = 1/2
  r = run_eccd("separate " + q(src("cases/paper003/example2.json")) + " --at 0");
  CHECK(r.code == 0);
  CHECK(r.out.find("separating line") != std::string::npos);
  CHECK(r.out.find("proof (exact") != std::string::npos);
  r = run_eccd("separate " + q(src("cases/paper002/example.json")) + " --at 0 --arith double --json");
  CHECK(r.code == 0);
  auto j = nlohmann::json::parse(r.out);
  CHECK((j["status"] == "separate" || j["status"] == "undecided"));
  CHECK(j["arith"] == "double");
  r = run_eccd("separate " + q(src("cases/paper002/example.json")) + " --at 1/3 --json");
  CHECK(r.code == 0);
  CHECK(nlohmann::json::parse(r.out)["status"] == "overlapping");
  // T outside [0, 1] or not a rational: exit 2, named.
  r = run_eccd("separate " + q(src("cases/paper002/example.json")) + " --at 3/2");
  CHECK(r.code == 2);
  CHECK(r.err.find("--at 3/2") != std::string::npos);
  r = run_eccd("separate " + q(src("cases/paper002/example.json")) + " --at x --json");
  CHECK(r.code == 2);
  CHECK(nlohmann::json::parse(r.out)["format"] == "eccd-error/1");
  r = run_eccd("separate " + q(src("cases/paper002/example.json")));
  CHECK(r.code == 2);  // --at is required
  // A cycloidal scene: refused (exit 3), with the reason.
  r = run_eccd("separate " + q(src("cases/paper003/example1.json")) + " --at 1/2");
  CHECK(r.code == 3);
  CHECK(r.err.find("cycloidal") != std::string::npos);
}

}  // namespace ECCD_UNITY_ID
