// `eccd animate` (app/animate.cpp): the answer object of
// docs/animation-format.md, the summary table, exit codes (docs/exit-codes.md)
// and nothing written on error.
#include "tests/app/cli_run.hpp"

#include <gmpxx.h>
#include <nlohmann/json.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;

namespace {
std::string swarm() { return q(src("cases/animations/swarm-2d.json")); }
}  // namespace

TEST_CASE("eccd animate --json prints the animation answer object", "[app][cli][animation]") {
  Run r = run_eccd("animate " + swarm() + " --arith exact --json --quiet");
  INFO(r.err);
  REQUIRE(r.code == 0);
  REQUIRE(r.err.empty());  // --quiet: no progress
  json j = json::parse(r.out);
  REQUIRE(j["format"] == "ellipse-ccd-animation-answer/1");
  REQUIRE(j["animation"] == "swarm-2d");
  REQUIRE(j["arithmetic"] == "exact");
  REQUIRE(j["frames"] == 20);
  REQUIRE(j["pairs_per_frame"] == 10);
  REQUIRE(j["events"].size() > 0);
  REQUIRE(j["undecided"].empty());
  const json& st = j["stages"];
  REQUIRE(st["bounding_volumes"].get<int>() + st["separating_plane"].get<int>() + st["continuous_test"].get<int>() ==
          200);
  REQUIRE(j["separating_plane_stage"] == "built");  // api/separate.hpp is part of the build (000 section 4)
  std::size_t last_frame = 0;
  for (const auto& e : j["events"]) {
    REQUIRE(e["pair"].size() == 2);
    REQUIRE(e["answer"]["collides"] == true);
    REQUIRE(e["answer"]["first_contact"]["lo"].is_string());  // exact: certified brackets
    // global t = t_k + tau (t_{k+1} - t_k) with t_k = k/20 here: the local bracket maps exactly
    const std::size_t k = e["frame"].get<std::size_t>();
    mpq_class lo_t(e["answer"]["first_contact"]["lo"].get<std::string>()),
        lo_tau(e["local_answer"]["first_contact"]["lo"].get<std::string>());
    lo_t.canonicalize();
    lo_tau.canonicalize();
    mpq_class t_k(long(k), 20);
    t_k.canonicalize();
    REQUIRE(lo_t == t_k + lo_tau / 20);
    REQUIRE(e["frame"].get<std::size_t>() >= last_frame);  // ordered by frame
    last_frame = e["frame"].get<std::size_t>();
  }
  // double: no brackets
  Run d = run_eccd("animate " + swarm() + " --arith double --json --quiet --jobs 1");
  REQUIRE(d.code == 0);
  json dj = json::parse(d.out);
  REQUIRE(dj["arithmetic"] == "double");
  for (const auto& e : dj["events"]) REQUIRE_FALSE(e["answer"]["first_contact"].contains("lo"));
}

TEST_CASE("eccd animate prints a summary table and progress on stderr", "[app][cli][animation]") {
  Run r = run_eccd("animate " + swarm() + " --arith certified --all-intervals");
  INFO(r.err);
  REQUIRE(r.code == 0);
  REQUIRE(r.out.find("frame   pairs  bounding  plane  continuous  events  undecided") != std::string::npos);
  REQUIRE(r.out.find("stages: bounding volumes") != std::string::npos);
  REQUIRE(r.err.find("eccd animate: pair-frames 30/30 past the bounding volumes") != std::string::npos);
}

TEST_CASE("eccd animate: bad file, bad options, and nothing written on error", "[app][cli][animation]") {
  TempDir dir;
  const std::string out = dir.str() + "/answer.json";
  // a bad animation: exit 2, the file and place named, no output file
  spit(dir.path / "bad.json",
       R"({"format": "ellipse-ccd-animation/1", "name": "x", "dim": 2, "times": ["0", "0"], "bodies": []})");
  Run r = run_eccd("animate " + q(dir.str() + "/bad.json") + " --out " + q(out));
  REQUIRE(r.code == 2);
  REQUIRE(r.err.find("bad.json: /times/1: times must be strictly increasing") != std::string::npos);
  REQUIRE(r.out.empty());
  REQUIRE_FALSE(std::filesystem::exists(out));
  // --json failure: one error object on stdout
  r = run_eccd("animate " + q(dir.str() + "/bad.json") + " --json");
  REQUIRE(r.code == 2);
  REQUIRE(json::parse(r.out)["format"] == "eccd-error/1");
  // bad options: exit 2 before any work
  for (const std::string opt : {"--arith quad", "--threads 0", "--shard 2/2", "--shard x"}) {
    r = run_eccd("animate " + swarm() + " " + opt + " --out " + q(out));
    INFO(opt << ": " << r.err);
    REQUIRE(r.code == 2);
    REQUIRE_FALSE(std::filesystem::exists(out));
  }
  REQUIRE(run_eccd("animate " + q(dir.str() + "/missing.json")).code == 2);
  // success with --out: the file holds the answer, stdout is empty
  r = run_eccd("animate " + swarm() + " --json --quiet --out " + q(out));
  REQUIRE(r.code == 0);
  REQUIRE(r.out.empty());
  REQUIRE(json::parse(slurp(out))["format"] == "ellipse-ccd-animation-answer/1");
}

}  // namespace ECCD_UNITY_ID
