// FCL's GJK tolerance as an option (issue 17 point 2; compare/fcl_engine.hpp
// FclOptions, `eccd fcl --gjk-tolerance X`): the value reaches fcl::collide,
// shown by a pose whose answer changes with it. The pose: a unit sphere whose
// centre is at distance 5.4999999 from the origin, at angle 0.0004 rad from
// the x axis in the x-y plane, and a static ellipsoid with semi-axes 4.5, 4, 2
// at the origin (paper 000 Table 2's set-up, the grazing orbit of
// reports/animation/: the sphere is less than 1e-7 deep). The exact static
// test says the two overlap; FCL with its default gjk_tolerance (1e-6)
// reports no collision there, with 1e-12 a collision (measured with FCL 0.7.0,
// libccd's MPR; another FCL may differ, and then this test says so).
#include "api/static_status.hpp"
#include "compare/fcl_engine.hpp"
#include "io/scene_reader.hpp"
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::clitest;

namespace {

const char* kGraze = R"({"format": "ellipse-ccd-scene/1", "name": "fcl-gjk-graze", "dim": 3,
  "a": {"shape": {"semi_axes": ["1", "1", "1"]},
        "motion": {"type": "matrix", "m": [["1", "0", "0", "5.499999460000013"], ["0", "1", "0", "0.0021999999013333346"],
                                           ["0", "0", "1", "0"], ["0", "0", "0", "1"]]}},
  "b": {"shape": {"semi_axes": ["4.5", "4", "2"]}, "motion": {"type": "static"}}})";

}  // namespace

TEST_CASE("fcl gjk_tolerance: the option is what FCL's request carries", "[fcl]") {
  CHECK(fcl_gjk_tolerance() == 1e-6);  // FCL's own default, read from its CollisionRequest
  FclOptions tight;
  tight.gjk_tolerance = 1e-12;
  CHECK(fcl_gjk_tolerance(tight) == 1e-12);
  CHECK(fcl_tolerances(tight).find("gjk_tolerance 1e-12") != std::string::npos);
  CHECK(fcl_tolerances().find("gjk_tolerance 1e-06") != std::string::npos);
  FclOptions bad;
  bad.gjk_tolerance = -1;
  CHECK_THROWS_AS(fcl_gjk_tolerance(bad), std::invalid_argument);
  const Scene s = parse_scene(kGraze, "graze");
  CHECK_THROWS_AS(fcl_sample(s, 1, bad), std::invalid_argument);
  // FCL's naive continuous collision makes its own default request: a tolerance cannot reach it
  CHECK_THROWS_AS(fcl_ccd(s, 10, tight), std::invalid_argument);
}

TEST_CASE("fcl gjk_tolerance reaches fcl::collide: a shallow overlap FCL misses at 1e-6 and finds at 1e-12", "[fcl]") {
  const Scene s = parse_scene(kGraze, "graze");
  REQUIRE(status_at(s, mpq_class(0), Arithmetic::exact()) == Status::overlapping);  // the exact answer
  FclOptions tight;
  tight.gjk_tolerance = 1e-12;
  CHECK_FALSE(fcl_collides_at(s, 0));   // default tolerance: missed
  CHECK(fcl_collides_at(s, 0, tight));  // tight: found, as the exact test says
  CHECK_FALSE(fcl_sample(s, 1).collides);
  CHECK(fcl_sample(s, 1, tight).collides);
}

TEST_CASE("eccd fcl --gjk-tolerance: reaches FCL, reported in the JSON, bad values refused", "[fcl][cli]") {
  const auto dir = std::filesystem::temp_directory_path() / ("eccd-fcl-gjk-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string scene = (dir / "graze.json").string();
  spit(scene, kGraze);
  Run d = run_eccd("fcl " + q(scene) + " --samples 1 --json");
  Run t = run_eccd("fcl " + q(scene) + " --samples 1 --gjk-tolerance 1e-12 --json");
  REQUIRE(d.code == 0);
  REQUIRE(t.code == 0);
  const auto jd = nlohmann::json::parse(d.out), jt = nlohmann::json::parse(t.out);
  CHECK(jd["gjk_tolerance"].get<double>() == 1e-6);
  CHECK(jt["gjk_tolerance"].get<double>() == 1e-12);
  CHECK(jd["answer"]["collides"] == false);
  CHECK(jt["answer"]["collides"] == true);
  for (const std::string args : {"--samples 1 --gjk-tolerance 0", "--samples 1 --gjk-tolerance -1e-9",
                                 "--samples 1 --gjk-tolerance abc", "--ccd 10 --gjk-tolerance 1e-12"}) {
    INFO(args);
    Run r = run_eccd("fcl " + q(scene) + " " + args);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(r.err.empty());
  }
  std::filesystem::remove_all(dir);
}

}  // namespace ECCD_UNITY_ID
