// CSV with RFC 4180 quoting (compare/csv.hpp, issue 19 point 5): the writer
// quotes what needs quoting, the reader is its inverse, and a scene whose name
// holds commas and quotes goes through `eccd report` and comes out intact in
// results.csv as Python's csv module reads it. The report step's failure
// message says what failed (issue 19: it used to blame matplotlib for any
// failure of the script).
#include "compare/csv.hpp"
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
namespace fs = std::filesystem;
using namespace eccd::clitest;

TEST_CASE("csv_field quotes a field with a comma, quote or line break and doubles its quotes", "[csv]") {
  CHECK(eccd::csv_field("plain") == "plain");
  CHECK(eccd::csv_field("") == "");
  CHECK(eccd::csv_field("1.5e-07") == "1.5e-07");
  CHECK(eccd::csv_field("a,b") == "\"a,b\"");
  CHECK(eccd::csv_field("a,\"b\"") == "\"a,\"\"b\"\"\"");
  CHECK(eccd::csv_field("two\nlines") == "\"two\nlines\"");
  CHECK(eccd::csv_field(" padded ") == "\" padded \"");
  CHECK(eccd::csv_line({"x", "a,\"b\"", "", "y"}) == "x,\"a,\"\"b\"\"\",,y");
}

TEST_CASE("csv_records reads what csv_line writes, line breaks inside quotes included", "[csv]") {
  const std::vector<std::vector<std::string>> rows{{"scene", "reason"},
                                                   {"a,\"b\"", "time budget: 2 s, then killed"},
                                                   {"two\nlines", ""},
                                                   {"", "\"quoted\""},
                                                   {"last", "x"}};
  std::string text;
  for (const auto& r : rows) text += eccd::csv_line(r) + "\n";
  auto recs = eccd::csv_records(text, "t.csv");
  REQUIRE(recs.size() == rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) CHECK(recs[k].fields == rows[k]);
  CHECK(recs[2].line == 3);  // the record with a quoted line break takes lines 3 and 4
  CHECK(recs[3].line == 5);
  CHECK(recs[4].line == 6);
  // CRLF line ends and a last record without a line break
  auto crlf = eccd::csv_records("a,b\r\n\"c,d\",e", "t.csv");
  REQUIRE(crlf.size() == 2);
  CHECK(crlf[1].fields == std::vector<std::string>{"c,d", "e"});
  CHECK(eccd::csv_split("x,,\"y\"") == std::vector<std::string>{"x", "", "y"});
}

TEST_CASE("csv_records names the file and line of malformed quoting", "[csv]") {
  auto message = [](const std::string& text) {
    try {
      eccd::csv_records(text, "parts/results.csv");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message("h\nok\n\"open,never closed\n") ==
        "parts/results.csv: line 3: a quoted field is not closed (truncated?)");
  CHECK(message("h\n\"a\"b,c\n").find("parts/results.csv: line 2: text after the closing quote") == 0);
  CHECK(message("h\na\"b,c\n").find("parts/results.csv: line 2: a quote inside an unquoted field") == 0);
}

namespace {
// The scene of 003 (example 2) renamed.
void write_named_scene(const fs::path& file, const std::string& name) {
  std::ifstream in(src("cases/paper003/example2.json"));
  nlohmann::ordered_json d = nlohmann::ordered_json::parse(in);
  d["name"] = name;
  fs::create_directories(file.parent_path());
  spit(file, d.dump(2) + "\n");
}
}  // namespace

TEST_CASE("a scene named with commas and quotes goes through eccd report intact", "[csv][cli][report]") {
  TempDir t;
  const std::string name = "a,\"b\"";
  write_named_scene(t.path / "scenes" / "s.json", name);
  const std::string out = (t.path / "out").string();
  // the whole report, report_figures.py included (it reads results.csv with the csv module)
  Run r = run_eccd("report --scenes " + q((t.path / "scenes").string()) +
                       " --cases '' --no-map --mpfr 64 --budget 2 --jobs 1 --out " + q(out),
                   300);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string csv = slurp(t.path / "out" / "results.csv");
  CHECK(csv.find("\"a,\"\"b\"\"\",") != std::string::npos);  // written quoted, quotes doubled
  // the C++ reader: every row has the header's field count and the name intact
  auto recs = eccd::csv_records(csv, "results.csv");
  REQUIRE(recs.size() > 2);
  for (std::size_t k = 1; k < recs.size(); ++k) {
    CHECK(recs[k].fields.size() == recs[0].fields.size());
    CHECK(recs[k].fields[0] == name);
  }
  // Python's csv module (the reader of compare/plots/report_figures.py)
  const std::string py =
      "import csv, json, sys; r = list(csv.reader(open(sys.argv[1], newline=''))); "
      "print(json.dumps({'names': sorted({x[0] for x in r[1:]}), 'widths': sorted({len(x) for x in r})}))";
  FILE* p = popen(("python3 -c " + q(py) + " " + q(out + "/results.csv")).c_str(), "r");
  REQUIRE(p != nullptr);
  std::string text;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) text.append(buf, n);
  REQUIRE(pclose(p) == 0);
  auto seen = nlohmann::json::parse(text);
  CHECK(seen["names"] == nlohmann::json::array({name}));
  CHECK(seen["widths"] == nlohmann::json::array({recs[0].fields.size()}));
  CHECK(fs::exists(t.path / "out" / "report.md"));
}

namespace {
// ECCD_PLOTS_DIR set for the scope (the eccd binary looks for report_figures.py there).
struct PlotsDir {
  explicit PlotsDir(const std::string& dir) { setenv("ECCD_PLOTS_DIR", dir.c_str(), 1); }
  ~PlotsDir() { unsetenv("ECCD_PLOTS_DIR"); }
};
}  // namespace

TEST_CASE("the report step's failure says what failed, matplotlib only when its import failed", "[csv][cli][report]") {
  TempDir t;
  write_named_scene(t.path / "scenes" / "s.json", "plain");
  fs::create_directories(t.path / "plots");
  PlotsDir plots((t.path / "plots").string());
  const std::string args = "report --scenes " + q((t.path / "scenes").string()) +
                           " --cases '' --no-map --mpfr 64 --budget 2 --jobs 1 --out " + q((t.path / "out").string());
  SECTION("a script that fails for another reason: its stderr, no word of matplotlib") {
    spit(t.path / "plots" / "report_figures.py",
         "import sys\nprint('report_figures.py: results.csv line 7: something else is wrong', "
         "file=sys.stderr)\nsys.exit(2)\n");
    Run r = run_eccd(args, 300);
    INFO(r.err);
    CHECK(r.code != 0);
    CHECK(r.err.find("the report step failed") != std::string::npos);
    CHECK(r.err.find("exit status 2") != std::string::npos);
    CHECK(r.err.find("stderr ends with:\nreport_figures.py: results.csv line 7: something else is wrong") !=
          std::string::npos);
    CHECK(r.err.find("matplotlib") == std::string::npos);
  }
  SECTION("a script whose import of matplotlib fails") {
    spit(t.path / "plots" / "report_figures.py",
         "raise ModuleNotFoundError(\"No module named 'matplotlib'\", name='matplotlib')\n");
    Run r = run_eccd(args, 300);
    INFO(r.err);
    CHECK(r.code != 0);
    CHECK(r.err.find("matplotlib is missing: apt-get install python3-matplotlib") != std::string::npos);
    CHECK(r.err.find("ModuleNotFoundError: No module named 'matplotlib'") != std::string::npos);
  }
}

namespace {
// tests/data/report (the hand-computed fixture of report_figures.py) copied to a temp folder.
int run_report_figures(const fs::path& dir, std::string& log) {
  const std::string cmd = "python3 " + q(src("compare/plots/report_figures.py")) + " " + q(dir.string()) + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) log.append(buf, n);
  int st = pclose(p);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}
}  // namespace

TEST_CASE("report_figures.py reads quoted fields with the csv module and names the line of a broken quote",
          "[csv][report-figures]") {
  TempDir t;
  for (const char* f : {"results.csv", "meta.json", "failure_map.csv"})
    fs::copy_file(src("tests/data/report/") + f, t.path / f);
  const std::string text = slurp(t.path / "results.csv");
  auto recs = eccd::csv_records(text, "results.csv");
  REQUIRE(recs.size() > 3);
  REQUIRE(recs[1].fields[0] == "s2-col");
  std::string renamed;
  for (auto& r : recs) {
    if (r.fields[0] == "s2-col") r.fields[0] = "s2,\"col\"";
    renamed += eccd::csv_line(r.fields) + "\n";
  }
  REQUIRE(renamed.find("\"s2,\"\"col\"\"\",") != std::string::npos);
  SECTION("a name with commas and quotes: the same report as with the plain name") {
    std::string log;
    REQUIRE(run_report_figures(t.path, log) == 0);  // the fixture as it is
    const std::string plain = slurp(t.path / "report.md");
    spit(t.path / "results.csv", renamed);
    REQUIRE(run_report_figures(t.path, log) == 0);
    INFO(log);
    CHECK(slurp(t.path / "report.md") == plain);  // report.md names no scene: every count and table is unchanged
  }
  SECTION("an unclosed quote: exit 2, the line where the record starts") {
    // line 3 starts a quoted field that never closes
    std::string broken = text;
    std::size_t line3 = broken.find('\n', broken.find('\n') + 1) + 1;
    broken.insert(line3, "\"");
    spit(t.path / "results.csv", broken);
    std::string log;
    CHECK(run_report_figures(t.path, log) == 2);
    CHECK(log.find("results.csv line 3: malformed CSV") != std::string::npos);
    CHECK_FALSE(fs::exists(t.path / "report.md"));
  }
}

}  // namespace ECCD_UNITY_ID
