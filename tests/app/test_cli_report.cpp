// `eccd generate` and `eccd report` from the command line: seeded output,
// shards that join into the same table as one run, and clear refusals.
#include "compare/csv.hpp"
#include "tests/support/cli.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {
using eccd::test::run;
std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
// results.csv without the time column (timings differ between runs); the
// column is found by its name in the header.
std::string without_time(const std::string& csv) {
  auto recs = eccd::csv_records(csv, "results.csv");  // RFC 4180 quoting (compare/csv.hpp)
  REQUIRE(!recs.empty());
  const auto& head = recs[0].fields;
  const std::size_t time_col = std::size_t(std::find(head.begin(), head.end(), "time_us") - head.begin());
  REQUIRE(time_col < head.size());
  std::string out;
  for (auto r : recs) {
    REQUIRE(r.fields.size() == head.size());
    r.fields.erase(r.fields.begin() + long(time_col));
    out += eccd::csv_line(r.fields) + "\n";
  }
  return out;
}
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("eccd-report-test-" + std::to_string(getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};
}  // namespace

TEST_CASE("eccd generate writes the same scenes for the same seed and refuses to overwrite", "[app][cli][generator]") {
  TempDir t;
  const std::string exe = ECCD_EXE;
  std::string out;
  const std::string args = " --dims 2 --degrees 3 --families touch,near-miss --separations 6 --seed 5 --json";
  REQUIRE(run(exe + " generate --out " + (t.path / "a").string() + args, out) == 0);
  auto files = nlohmann::json::parse(out)["files"];  // eccd-generate/1
  REQUIRE(files.size() == 2);
  REQUIRE(run(exe + " generate --out " + (t.path / "b").string() + args, out) == 0);
  for (const auto& f : files) {
    fs::path p(f.get<std::string>());
    CHECK(slurp(p) == slurp(t.path / "b" / p.filename()));
    REQUIRE(run(exe + " solve " + p.string() + " --arith exact --json", out) == 0);  // the reader accepts it
  }
  CHECK(run(exe + " generate --out " + (t.path / "a").string() + args, out) == 2);  // exists: no --force
  CHECK(run(exe + " generate --out " + (t.path / "c").string() + " --degrees 9", out) == 2);
}

TEST_CASE("eccd report: two shards joined by --merge give the table of one run", "[app][cli][report]") {
  TempDir t;
  const std::string exe = ECCD_EXE;
  const std::string plan = " --dims 2,3 --degrees 2 --families touch,free --count 1 --mpfr 64 --grid 16 --cases '' "
                           "--map-size 2 --seed 9 --no-figures";
  std::string out;
  REQUIRE(run(exe + " report --out " + (t.path / "whole").string() + plan, out) == 0);
  REQUIRE(run(exe + " report --out " + (t.path / "p0").string() + plan + " --shard 0/2 --jobs 1", out) == 0);
  REQUIRE(run(exe + " report --out " + (t.path / "p1").string() + plan + " --shard 1/2 --jobs 1", out) == 0);
  REQUIRE(run(exe + " report --out " + (t.path / "joined").string() + " --no-figures --merge " + (t.path / "p0").string() +
                  " " + (t.path / "p1").string(),
              out) == 0);
  std::string whole = slurp(t.path / "whole" / "results.csv");
  CHECK(without_time(whole) == without_time(slurp(t.path / "joined" / "results.csv")));
  CHECK(slurp(t.path / "whole" / "failure_map.csv") == slurp(t.path / "joined" / "failure_map.csv"));
  // 2D: 2 scenes x (exact + (3 double + 2 mpfr:64) x 2 input modes); 3D: 4 scenes (euler touch, euler free,
  // affine touch, affine free) x (exact + (4 double + 1 mpfr) x 2 input modes) -> header + 2*11 + 4*11 lines.
  CHECK(std::count(whole.begin(), whole.end(), '\n') == 1 + 2 * 11 + 4 * 11);
  auto meta = nlohmann::json::parse(slurp(t.path / "joined" / "meta.json"));
  CHECK(meta["shards"] == 2);
  CHECK(meta["seed"] == 9);
  CHECK(!fs::exists(t.path / "joined.partial"));
  // A missing part, a bad shard and a part from another run are refused, and nothing is written.
  CHECK(run(exe + " report --out " + (t.path / "bad").string() + " --no-figures --merge " + (t.path / "p0").string(), out) == 2);
  CHECK(run(exe + " report --out " + (t.path / "bad").string() + plan + " --shard 2/2", out) == 2);
  CHECK(run(exe + " report --out " + (t.path / "bad").string() + plan + " --shard x", out) == 2);
  CHECK(!fs::exists(t.path / "bad"));
}
