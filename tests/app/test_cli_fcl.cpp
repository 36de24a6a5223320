// `eccd fcl` (app/fcl.cpp, docs/fcl.md), run as ECCD_EXE on cases/spheres.
// What tests/compare/test_fcl_engine.cpp and test_fcl_gjk_tolerance.cpp check
// (bad options and scenes, the pipe into `eccd judge`, the GJK tolerance) and
// test_cli_names (format and version) is not repeated.
//  - --samples N is fcl::collide at t = k/N merged into intervals: on two
//    spheres crossing, whose exact collision interval [a, b] comes from
//    `eccd solve --json`, the one interval is [ceil(aN)/N, floor(bN)/N] for
//    N = 10, 37, 1000 (no sample lies within 1e-6 of a or b), the first contact
//    is its start, nothing is certified (lo, hi null) and no contact is claimed;
//    a free pair: no collision;
//  - --ccd N (linear translations only): collides, and a first contact no
//    earlier than the exact one; no intervals claimed; a rotating scene is
//    refused with exit 3 and the reason;
//  - the same object with and without --json, and from standard input.
#include "cli_run.hpp"

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;

namespace {
bool fcl_missing(const Run& r) { return r.code == 3 && r.err.find("not built") != std::string::npos; }
}  // namespace

TEST_CASE("eccd fcl --samples: the sampled interval is the exact one rounded inwards to k/N", "[app][cli][cli-fcl]") {
  const std::string crossing = src("cases/spheres/spheres-crossing.json");
  Run ex = run_eccd("solve " + q(crossing) + " --json", 120);
  REQUIRE(ex.code == 0);
  const json exact = json::parse(ex.out);
  REQUIRE(exact["intervals"].size() == 1);
  const double a = std::stod(exact["intervals"][0][0]["approx"].get<std::string>());
  const double b = std::stod(exact["intervals"][0][1]["approx"].get<std::string>());
  for (int n : {10, 37, 1000}) {
    INFO("N = " << n);
    Run r = run_eccd("fcl " + q(crossing) + " --samples " + std::to_string(n), 120);
    if (fcl_missing(r)) {
      WARN("FCL is not built in: " << r.err);
      return;
    }
    REQUIRE(r.code == 0);
    const json j = json::parse(r.out);
    CHECK(j["format"] == "eccd-fcl-answer/1");
    CHECK(j["engine"] == "fcl/sample:" + std::to_string(n));
    const json& ans = j["answer"];
    CHECK(ans["collides"] == true);
    CHECK(ans["contacts"].empty());
    REQUIRE(ans["intervals"].size() == 1);
    const double ka = std::ceil(a * n), kb = std::floor(b * n);
    REQUIRE(std::abs(a * n - std::round(a * n)) > 1e-6 * n);  // no sample on the boundary
    REQUIRE(std::abs(b * n - std::round(b * n)) > 1e-6 * n);
    const json& iv = ans["intervals"][0];
    CHECK(std::abs(std::stod(iv[0]["approx"].get<std::string>()) - ka / n) < 1e-12);
    CHECK(std::abs(std::stod(iv[1]["approx"].get<std::string>()) - kb / n) < 1e-12);
    CHECK(iv[0]["lo"].is_null());
    CHECK(iv[0]["hi"].is_null());
    CHECK(ans["first_contact"]["approx"] == iv[0]["approx"]);
  }
  Run free = run_eccd("fcl " + q(src("cases/spheres/spheres-free.json")) + " --samples 100", 120);
  REQUIRE(free.code == 0);
  const json f = json::parse(free.out)["answer"];
  CHECK(f["collides"] == false);
  CHECK(f["intervals"].empty());
  CHECK(f["first_contact"].is_null());
}

TEST_CASE("eccd fcl --ccd, --json and standard input", "[app][cli][cli-fcl]") {
  const std::string crossing = src("cases/spheres/spheres-crossing.json");
  Run r = run_eccd("fcl " + q(crossing) + " --ccd 50", 120);
  if (fcl_missing(r)) {
    WARN("FCL is not built in: " << r.err);
    return;
  }
  REQUIRE(r.code == 0);
  const json j = json::parse(r.out);
  CHECK(j["engine"] == "fcl/ccd:50");
  CHECK(j["answer"]["collides"] == true);
  CHECK_FALSE(j["answer"].contains("intervals"));  // collides and first contact only
  // The exact first contact: 0.13156793367026... (its bracket from solve); the naive CCD never reports earlier.
  CHECK(std::stod(j["answer"]["first_contact"]["approx"].get<std::string>()) >= 0.1315679336702626 - 1e-6);
  Run rot = run_eccd("fcl " + q(src("cases/paper002/example.json")) + " --ccd 10", 120);
  CHECK(rot.code == 3);
  CHECK(rot.out.empty());
  CHECK(rot.err.find("not expressible by FCL's translation motion") != std::string::npos);

  Run plain = run_eccd("fcl " + q(crossing) + " --samples 20", 120);
  Run with_json = run_eccd("fcl " + q(crossing) + " --samples 20 --json", 120);
  Run in = run_eccd("fcl - --samples 20 < " + q(crossing), 120);
  REQUIRE(plain.code == 0);
  REQUIRE(with_json.code == 0);
  REQUIRE(in.code == 0);
  CHECK(json::parse(plain.out) == json::parse(with_json.out));
  json a = json::parse(plain.out), b = json::parse(in.out);
  CHECK(a["answer"] == b["answer"]);
  CHECK(a["scene"] == b["scene"]);
}

}  // namespace ECCD_UNITY_ID
