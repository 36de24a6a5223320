// The recipes for sweeps that outgrow a machine (issue 19 point 6,
// docs/sweeps.md): scripts/report-parallel.sh (GNU parallel runs
// `eccd report --shard i/N`, then `--merge`) run locally on a tiny plan gives
// the rows of one unsharded run; scripts/report-slurm.sh is checked with
// `bash -n` and its task and merge modes run here as Slurm would run them.
// GNU parallel (Debian `parallel`, in scripts/bootstrap.sh) is required: the
// test fails, not skips, without it.
#include "compare/csv.hpp"
#include "compare/fcl_engine.hpp"
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
namespace fs = std::filesystem;
using namespace eccd::clitest;

namespace {

// Runs a shell command with stdout and stderr in `out`; the exit status (-1: no normal exit).
int shell(const std::string& cmd, std::string& out) {
  out.clear();
  FILE* p = popen(("timeout -k 5 600 bash -c " + q(cmd) + " 2>&1").c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  int st = pclose(p);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

// The rows of a report's results.csv without the time column, sorted (order-independent).
std::vector<std::vector<std::string>> rows_without_time(const fs::path& file) {
  auto recs = eccd::csv_records(slurp(file), file.string());
  REQUIRE(!recs.empty());
  auto& head = recs[0].fields;
  auto col = std::size_t(std::find(head.begin(), head.end(), "time_us") - head.begin());
  REQUIRE(col < head.size());
  std::vector<std::vector<std::string>> rows;
  for (std::size_t k = 1; k < recs.size(); ++k) {
    REQUIRE(recs[k].fields.size() == head.size());
    auto f = recs[k].fields;
    f.erase(f.begin() + long(col));
    rows.push_back(f);
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

std::vector<std::string> sorted_lines(const fs::path& file) {
  std::vector<std::string> v;
  for (auto& r : eccd::csv_records(slurp(file), file.string())) v.push_back(eccd::csv_line(r.fields));
  std::sort(v.begin(), v.end());
  return v;
}

// A tiny plan: 2D degree 2, one touch and one free scene, MPFR 64, a 2 x 2 failure map, and the
// scene of 003 example 2 renamed with a comma and quotes (a case), so that quoting goes through the merge.
std::string tiny_plan(const fs::path& cases) {
  return "--dims 2 --degrees 2 --families touch,free --count 1 --mpfr-bits 64 --map-size 2 --seed 9 --budget 2 "
         "--no-figures --cases " +
         q(cases.string());
}

void write_cases(const fs::path& dir) {
  std::ifstream in(src("cases/paper003/example2.json"));
  nlohmann::ordered_json d = nlohmann::ordered_json::parse(in);
  d["name"] = "sweep,\"quoted\"";
  fs::create_directories(dir);
  spit(dir / "renamed.json", d.dump(2) + "\n");
}

}  // namespace

TEST_CASE("the GNU parallel recipe (2 shards, then --merge) gives the rows of one unsharded run", "[cli][parallel]") {
  std::string out;
  if (shell("command -v parallel", out) != 0)
    FAIL(
        "GNU parallel is not installed: the recipe scripts/report-parallel.sh needs it (Debian: apt-get install "
        "parallel; "
        "scripts/bootstrap.sh installs it)");
  TempDir t;
  write_cases(t.path / "my cases");  // a space: the arguments must reach eccd as given
  const std::string plan = tiny_plan(t.path / "my cases");
  Run whole = run_eccd("report --jobs 2 --out-dir " + q((t.path / "whole").string()) + " " + plan, 600);
  INFO(whole.err);
  REQUIRE(whole.code == 0);

  const std::string env = "ECCD=" + q(ECCD_EXE) + " ";
  int rc =
      shell(env + q(src("scripts/report-parallel.sh")) + " 2 " + q((t.path / "joined").string()) + " " + plan, out);
  INFO(out);
  REQUIRE(rc == 0);
  CHECK(fs::exists(t.path / "joined.parts" / "shard-0" / "results.csv"));
  CHECK(fs::exists(t.path / "joined.parts" / "shard-1" / "results.csv"));
  auto rows = rows_without_time(t.path / "whole" / "results.csv");
  // 3 scenes x (exact + (3 double + 2 mpfr:64) x 2 input modes x 2 faces (as published, guarded) + certified +
  // fcl/sample:10,100,1000 where FCL is built in; no fcl/ccd row: these scenes rotate, compare/fcl_engine.hpp)
  CHECK(rows.size() == std::size_t(3 * (1 + 5 * 2 * 2 + 1 + (eccd::fcl_availability().available ? 3 : 0))));
  CHECK(rows == rows_without_time(t.path / "joined" / "results.csv"));
  CHECK(sorted_lines(t.path / "whole" / "failure_map.csv") == sorted_lines(t.path / "joined" / "failure_map.csv"));
  CHECK(nlohmann::json::parse(slurp(t.path / "joined" / "meta.json"))["shards"] == 2);
  CHECK(std::any_of(rows.begin(), rows.end(), [](const auto& r) { return r[0] == "sweep,\"quoted\""; }));

  // bad usage is refused with exit 2 before any work
  CHECK(shell(env + q(src("scripts/report-parallel.sh")) + " 0 " + q((t.path / "x").string()), out) == 2);
  CHECK(!fs::exists(t.path / "x"));
}

TEST_CASE("the Slurm job-array script parses, and its task and merge modes run as Slurm would run them",
          "[cli][parallel]") {
  std::string out;
  const std::string script = q(src("scripts/report-slurm.sh"));
  REQUIRE(shell("bash -n " + script, out) == 0);
  TempDir t;
  write_cases(t.path / "my cases");  // a space: the arguments must reach eccd as given
  const std::string plan = tiny_plan(t.path / "my cases");
  const std::string env = "ECCD=" + q(ECCD_EXE) + " ";
  const std::string dest = q((t.path / "slurm").string());
  for (int i : {0, 1}) {
    int rc = shell(env + "SLURM_ARRAY_TASK_ID=" + std::to_string(i) + " SLURM_CPUS_PER_TASK=1 " + script + " task 2 " +
                       dest + " " + plan,
                   out);
    INFO(out);
    REQUIRE(rc == 0);
  }
  int rc = shell(env + script + " merge 2 " + dest + " " + plan, out);
  INFO(out);
  REQUIRE(rc == 0);
  Run whole = run_eccd("report --jobs 2 --out-dir " + q((t.path / "whole").string()) + " " + plan, 600);
  REQUIRE(whole.code == 0);
  CHECK(rows_without_time(t.path / "whole" / "results.csv") == rows_without_time(t.path / "slurm" / "results.csv"));
  // outside a Slurm task, task mode says so; submit without sbatch says so (exit 2)
  CHECK(shell("unset SLURM_ARRAY_TASK_ID; " + env + script + " task 2 " + dest, out) != 0);
  CHECK(out.find("SLURM_ARRAY_TASK_ID") != std::string::npos);
  if (shell("command -v sbatch", out) != 0) {  // here: no Slurm
    CHECK(shell(env + script + " submit 2 " + dest, out) == 2);
    CHECK(out.find("sbatch not found") != std::string::npos);
  }
}

}  // namespace ECCD_UNITY_ID
