// `eccd report --resume` and the lock on NAME.partial (app/report_resume.cpp),
// on a run of two scenes given by --scenes, killed (SIGKILL) as soon as its
// plan file exists (the shell waits for the file, not for a time). What
// test_cli_report checks (a resumed run's table equals an uninterrupted one's;
// another seed or precision, nothing to resume, another plan format) is not
// repeated.
//  - the plan file (eccd-report-plan/1): the options, the number of tasks and
//    their digest, the build, the command;
//  - while another process holds the lock on NAME.partial/plan.json, neither
//    --resume nor a fresh run of the same name touches the folder (exit 2,
//    "in use");
//  - a changed --scenes folder is "started on other scenes"; a partial folder
//    without report's marker, or without a plan file, is refused;
//  - the same options resume and finish: the report holds both scenes, the
//    partial folder is gone, meta.json counts the reused tasks.
#include "cli_run.hpp"

#include <nlohmann/json.hpp>

#include <sys/file.h>
#include <unistd.h>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {
const std::string kOptions = " --cases '' --no-map --no-figures --mpfr-bits 64 --no-fcl --no-certified --jobs 1";
}

TEST_CASE("eccd report --resume: the plan file, the lock, other scenes, and finishing",
          "[app][cli][cli-report-resume]") {
  TempDir d;
  const fs::path scenes = d.path / "S";
  fs::create_directories(scenes);
  fs::copy_file(src("cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json"), scenes / "a.json");
  fs::copy_file(src("cases/generated/2d/2d-deg2-free-kinematic-2054184850131159.json"), scenes / "b.json");
  const std::string run = "report --out-dir R --scenes S" + kOptions;
  // Started, then killed once its plan file is written (or when it ends by itself, which the REQUIRE below catches).
  spit(d.path / "start.sh",
       std::string(ECCD_EXE) + " " + run +
           " 2>/dev/null &\np=$!\nwhile kill -0 $p 2>/dev/null && [ ! -f R.partial/plan.json ]; do "
           "sleep 0.01; done\nkill -9 $p 2>/dev/null\nwait $p\n");
  const std::string cmd = "cd " + q(d.str()) + " && sh start.sh >/dev/null 2>&1";
  std::system(cmd.c_str());
  const fs::path partial = d.path / "R.partial";
  REQUIRE(fs::is_regular_file(partial / "plan.json"));
  // The killed run's worker holds the lock on plan.json (inherited) until the kernel delivers its parent-death
  // signal (app/report_pool.cpp, PR_SET_PDEATHSIG): wait until the lock is free (a bounded number of tries), so that
  // the sections below see no run still going.
  {
    const int fd = ::open((partial / "plan.json").c_str(), O_RDONLY);
    REQUIRE(fd >= 0);
    bool free_now = false;
    for (int i = 0; i < 6000 && !(free_now = ::flock(fd, LOCK_EX | LOCK_NB) == 0); ++i) ::usleep(10000);
    REQUIRE(free_now);
    ::close(fd);  // releases it
  }
  REQUIRE_FALSE(fs::exists(d.path / "R"));
  const json plan = json::parse(slurp(partial / "plan.json"));
  CHECK(plan["format"] == "eccd-report-plan/1");
  CHECK(plan["tasks"] == 2);
  CHECK(plan["tasks_digest"].is_string());
  CHECK(plan["options"]["mpfr_bits"] == json::array({64}));
  CHECK(plan["command"].get<std::string>().find("--scenes S") != std::string::npos);
  CHECK(plan.contains("revision"));
  const std::string plan_text = slurp(partial / "plan.json");

  SECTION("the lock: another process holds plan.json") {
    const int fd = ::open((partial / "plan.json").c_str(), O_RDONLY);
    REQUIRE(fd >= 0);
    REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
    for (const std::string& args : {run + " --resume", run}) {
      INFO(args);
      Run r = run_eccd(args, 120, d.str());
      CHECK(r.code == 2);
      CHECK(r.err.find("in use by an eccd report still running") != std::string::npos);
      CHECK(slurp(partial / "plan.json") == plan_text);
      CHECK_FALSE(fs::exists(d.path / "R"));
    }
    ::close(fd);
  }
  SECTION("other scenes under --scenes") {
    fs::copy_file(src("cases/generated/2d/2d-deg2-touch-kinematic-6164051338131805.json"), scenes / "c.json");
    Run r = run_eccd(run + " --resume", 120, d.str());
    CHECK(r.code == 2);
    CHECK(r.err.find("was started on other scenes (2 task(s)") != std::string::npos);
    CHECK(r.err.find("did the files under --cases or --scenes change?") != std::string::npos);
    CHECK(slurp(partial / "plan.json") == plan_text);
  }
  SECTION("a partial folder without the marker, or without a plan file") {
    fs::create_directories(d.path / "X.partial");
    fs::copy_file(partial / "plan.json", d.path / "X.partial" / "plan.json");
    Run r = run_eccd("report --out-dir X --scenes S" + kOptions + " --resume", 120, d.str());
    CHECK(r.code == 2);
    CHECK(r.err.find("X.partial: exists and was not written by this command (no .eccd-report marker)") !=
          std::string::npos);
    fs::create_directories(d.path / "Y.partial");
    fs::copy_file(partial / ".eccd-report", d.path / "Y.partial" / ".eccd-report");
    Run y = run_eccd("report --out-dir Y --scenes S" + kOptions + " --resume", 120, d.str());
    CHECK(y.code == 2);
    CHECK(y.err.find("cannot be resumed: it has no plan.json") != std::string::npos);
    CHECK(fs::exists(d.path / "X.partial" / "plan.json"));
  }
  SECTION("the same options resume and finish") {
    Run r = run_eccd(run + " --resume", 300, d.str());
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK_FALSE(fs::exists(partial));
    CHECK_FALSE(fs::exists(d.path / "R" / "plan.json"));
    const std::string csv = slurp(d.path / "R" / "results.csv");
    CHECK(csv.find("2d-deg2-colliding-kinematic-4575131933740715,") != std::string::npos);
    CHECK(csv.find("2d-deg2-free-kinematic-2054184850131159,") != std::string::npos);
    const json meta = json::parse(slurp(d.path / "R" / "meta.json"));
    CHECK(meta["scene_count"] == 2);
    CHECK(meta["resumed_tasks"].get<int>() >= 0);
    CHECK(meta["resumed_tasks"].get<int>() <= 2);
  }
}

}  // namespace ECCD_UNITY_ID
