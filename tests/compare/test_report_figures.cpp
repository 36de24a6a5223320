// compare/plots/report_figures.py on the hand-made fixture tests/data/report: the report's numbers are the
// ones worked out by hand from the fixture's 10 scenes (2D, degrees 2 and 4; double/power, double/bernstein,
// mpfr:64/power, mpfr:128/power, exact) and its 3 x 3 failure map; a malformed input fails cleanly.
//
// Hand computation (see tests/data/report/results.csv):
//   degree 2, 4 scenes: double/power 1 FP of 4 -> 25.0%; double/bernstein 0 of 4, 1 undecided.
//   degree 4, 6 scenes: double/power FP + FN = 2 of 6 -> 33.3%, 1 undecided, 1 error; structure wrong 4 of
//     its 5 rows without error -> 80.0%; coef_err {1,3,3,5,8}e-12 -> median 3e-12, max 8e-12; delta_err
//     {1..5}e-10 -> median 3e-10; time {30..38 step 2} -> median 34 µs (the error row's 0.0 is left out).
//   near-miss d = 1e-04, 1e-06, 1e-08 pooled over degrees: double/power fails first at 1e-06 -> smallest
//     correct d 1e-04; double/bernstein fails first at 1e-08 -> 1e-06; mpfr:64/power fails at degree 4 already
//     at 1e-04 -> "none" for degree 4.
//   MPFR, power: degree 2 -> mpfr:64 has a FP, mpfr:128 is clean -> 128 bits; degree 4 -> mpfr:128 has an
//     undecided -> none of the tested.
//   time over all 2D rows without error: double/power median of {10,12,14,16,30,...,38} = 30 µs (fastest);
//     exact median of {1000, ..., 10000} = 5500 µs (slowest).
//   failure map: double/power differs from exact in 3 of 9 cells (1 undecided), double/bernstein in 1.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

const char* const kFigures[] = {"coef_error_vs_degree.png", "coef_error_hist.png", "misclassification_vs_d.png",
                                "min_mpfr_bits_vs_degree.png", "time_vs_degree.png", "failure_map.png"};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh copy of the fixture, removed again at the end of the test.
struct FixtureCopy {
  fs::path dir;
  explicit FixtureCopy(const std::string& tag) {
    dir = fs::temp_directory_path() / ("eccd-report-figures-" + std::to_string(::getpid()) + "-" + tag);
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path src = fs::path(ECCD_SOURCE_DIR) / "tests" / "data" / "report";
    for (const char* f : {"results.csv", "meta.json", "failure_map.csv"}) fs::copy_file(src / f, dir / f);
  }
  ~FixtureCopy() {
    std::error_code ec;
    fs::remove_all(dir, ec);
    fs::remove(fs::path(dir.string() + ".log"), ec);
  }
};

// Runs the script on `dir`; its stdout and stderr go to dir + ".log" (outside the directory).
int run_script(const fs::path& dir, std::string& log) {
  const std::string logfile = dir.string() + ".log";
  const std::string cmd = "python3 '" + std::string(ECCD_SOURCE_DIR) + "/compare/plots/report_figures.py' '" +
                          dir.string() + "' >'" + logfile + "' 2>&1";
  const int st = std::system(cmd.c_str());
  log = slurp(logfile);
  return (st != -1 && WIFEXITED(st)) ? WEXITSTATUS(st) : -1;
}

bool leftover_temp(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(".report_figures-", 0) == 0) return true;
  return false;
}

}  // namespace

TEST_CASE("report_figures.py writes report.md and every figure with the hand-computed numbers", "[report-figures]") {
  FixtureCopy fx("ok");
  std::string log;
  REQUIRE(run_script(fx.dir, log) == 0);
  INFO(log);

  for (const char* fig : kFigures) {
    INFO(fig);
    const fs::path p = fx.dir / fig;
    REQUIRE(fs::exists(p));
    const std::string bytes = slurp(p);
    REQUIRE(bytes.size() > 8);
    CHECK(bytes.compare(0, 8, std::string("\x89PNG\r\n\x1a\n", 8)) == 0);
  }
  CHECK_FALSE(leftover_temp(fx.dir));

  const std::string md = slurp(fx.dir / "report.md");
  const char* expected[] = {
      "# Robustness report: fixture",
      "- Command: `eccd report --out tests/data/report --seed 42",
      "- MPFR precisions (bits): 64, 128",
      // scenes per dim x degree x family: colliding, free, touch, near-miss, case, total
      "| 2D | 2 | 1 | 1 | 0 | 2 | 0 | 4 |",
      "| 2D | 4 | 1 | 0 | 1 | 3 | 1 | 6 |",
      // findings
      "2D, degree 2 (4 scenes, too few for a firm claim)",
      "double/power 25.0% (1 of 4; 0 undecided)",
      "double/bernstein 0.0% (0 of 4; 1 undecided)",
      "double/power 33.3% (2 of 6; 1 undecided, 1 error)",
      "double/bernstein 16.7% (1 of 6; 0 undecided)",
      "double/power 1e-04; double/bernstein 1e-06",
      "power — degree 2: 128 bits (4 scenes, too few), degree 4: none of the tested (at 128 bits 1 near-miss scene "
      "still fails)",
      "fastest double/power (median 30 µs per query), slowest exact (median 5500 µs",
      "1 run ended in an error: double/power on s4-case",
      // per dim x degree tables
      "| double/power | 4 | 1 | 0 | 0 | 0 | 25.0% | 25.0% | 1.5e-16 | 4e-16 | 2.5e-15 | 2e-09 | 3e-09 | 13 |",
      "| double/power | 6 | 1 | 1 | 1 | 1 | 33.3% | 80.0% | 3e-12 | 8e-12 | 3e-10 | 2e-06 | 3e-06 | 34 |",
      "| double/bernstein | 6 | 1 | 0 | 0 | 0 | 16.7% | 16.7% | 3e-15 | 9e-15 | 3.5e-13 | 2e-11 | 7e-11 | 55 |",
      "| exact | 6 | 0 | 0 | 0 | 0 | 0.0% | 0.0% | — | — | — | 0 | 0 | 7500 |",
      // near-miss: misclassified / scenes per d; smallest correct d per degree
      "| 1e-04 | 0/2 | 0/2 | 1/2 | 0/2 |",
      "| 1e-06 | 1/1 | 0/1 | 0/1 (1 undecided) | 0/1 |",
      "| 1e-08 | 1/2 (1 undecided) | 1/2 (1 undecided) | 2/2 | 0/2 (1 undecided) |",
      "| 2 | 1e-04 | 1e-04 | 1e-04 | 1e-08 |",
      "| 4 | 1e-04 | 1e-06 | none | 1e-06 |",
      // smallest MPFR precision with no misclassification
      "| 2D | 2 | 4 | 128 bits |",
      "| 2D | 4 | 6 | none of the tested |",
      // failure map: cells, differ from exact, share, undecided, error, where exact is touching
      "| double/power | 9 | 3 | 33.3% | 1 | 0 | 3 |",
      "| double/bernstein | 9 | 1 | 11.1% | 0 | 0 | 1 |",
      "[results.csv](results.csv)",
  };
  for (const char* s : expected) {
    INFO(s);
    CHECK(md.find(s) != std::string::npos);
  }
  for (const char* fig : kFigures) {
    INFO(fig);
    CHECK(md.find("![" + std::string(fig) + "](" + fig + ")") != std::string::npos);
  }
  CHECK(md.find("skipped") == std::string::npos);  // the fixture has data for every section
}

TEST_CASE("report_figures.py rejects a malformed results.csv, names the place and writes nothing", "[report-figures]") {
  FixtureCopy fx("bad");
  std::string csv = slurp(fx.dir / "results.csv");
  // Line 4 is s2-col on mpfr:64/power; its coef_err (column 14) becomes text.
  const std::string good = "mpfr:64/power,mpfr,64,power,cd-disc,1e-19,";
  const auto at = csv.find(good);
  REQUIRE(at != std::string::npos);
  csv.replace(at, good.size(), "mpfr:64/power,mpfr,64,power,cd-disc,abc,");
  std::ofstream(fx.dir / "results.csv", std::ios::binary | std::ios::trunc) << csv;

  std::string log;
  CHECK(run_script(fx.dir, log) != 0);
  INFO(log);
  CHECK(log.find("results.csv line 4, column 'coef_err'") != std::string::npos);
  CHECK_FALSE(fs::exists(fx.dir / "report.md"));
  for (const char* fig : kFigures) CHECK_FALSE(fs::exists(fx.dir / fig));
  CHECK_FALSE(leftover_temp(fx.dir));
}

TEST_CASE("report_figures.py rejects a meta.json that is not JSON, with its line", "[report-figures]") {
  FixtureCopy fx("badmeta");
  std::ofstream(fx.dir / "meta.json", std::ios::trunc) << "{\n  \"name\": \"x\",\n  oops\n}\n";
  std::string log;
  CHECK(run_script(fx.dir, log) != 0);
  INFO(log);
  CHECK(log.find("meta.json line 3") != std::string::npos);
  CHECK_FALSE(fs::exists(fx.dir / "report.md"));
}
