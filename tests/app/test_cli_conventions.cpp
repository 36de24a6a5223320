// The command line by convention (issue 19, point 4): --version with the git
// revision, --quiet, one exit-code table (README "Exit codes": 2 for every bad
// option or option value, 3 for a request refused on a valid scene), a warning
// for every ignored option, comma lists, "-" for standard input, "format" and
// "version" keys in JSON output, and errors as a JSON object under --json.
#include "tests/app/cli_run.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
namespace fs = std::filesystem;

namespace {
const std::string kScene2d =
    src("cases/paper003/example2.json");  // 003 Example 2: exact touch at t = 1/2, stored answer
const std::string kScene3d = src("cases/paper002/example.json");
}  // namespace

TEST_CASE("eccd --version prints the project version and the git revision", "[cli][conventions]") {
  Run r = run_eccd("--version");
  CHECK(r.code == 0);
  CHECK(r.out.find(std::string("eccd ") + ECCD_PROJECT_VERSION) != std::string::npos);
  CHECK(r.out.find("(git ") != std::string::npos);
  CHECK(r.err.empty());
}

TEST_CASE("eccd --quiet keeps warnings off stderr but not errors", "[cli][conventions]") {
  // --basis with exact arithmetic is ignored: a warning without --quiet ...
  Run loud = run_eccd("solve " + q(kScene2d) + " --arith exact --basis power");
  CHECK(loud.code == 0);
  CHECK(loud.err.find("warning: --basis") != std::string::npos);
  // ... none with --quiet, at the top level or after the sub-command, and the same answer.
  for (const char* where : {"--quiet solve ", "solve --quiet "}) {
    INFO(where);
    Run quiet = run_eccd(std::string(where) + q(kScene2d) + " --arith exact --basis power");
    CHECK(quiet.code == 0);
    CHECK(quiet.err.empty());
    CHECK(quiet.out.find("collides: yes") != std::string::npos);
  }
  // An error is still printed.
  Run bad = run_eccd("--quiet solve " + q(kScene2d) + " --variant 7");
  CHECK(bad.code == 2);
  CHECK(bad.err.find("--variant 7") != std::string::npos);
}

TEST_CASE("every command exits 2 for a bad option or a bad option value", "[cli][conventions]") {
  TempDir t;
  const std::string cert = (t.path / "c.json").string();
  for (const std::string& args :
       {"solve " + q(kScene2d) + " --basis quartic", "solve " + q(kScene2d) + " --variant 7",
        "solve " + q(kScene2d) + " --arith quad", "solve " + q(kScene2d) + " --method marching:x",
        "solve " + q(kScene2d) + " --input cooked", "solve " + q(kScene2d) + " --bogus",
        "solve " + q(kScene3d) + " --arith double --basis scaled-bernstein",  // a combination no 3D method takes: a bad
                                                                              // option, not a refusal
        "table " + q(t.str()) + " --mpfr 12", "certify " + q(kScene2d) + " --out " + q(cert) + " --mpfr-bits 10",
        "check-certificate " + q(kScene2d) + " " + q(cert) + " --bogus", "regress " + q(t.str()) + " --tol -1",
        "generate --out " + q(t.str()) + " --degrees 9", std::string("report --mpfr 7"),
        "plot " + q(kScene2d) + " --instants 51", "plot " + q(kScene2d) + " --arith quad",
        "--time-limit -3 solve " + q(kScene2d)}) {
    INFO(args);
    Run r = run_eccd(args);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(!r.err.empty());
  }
  // 3: valid options on a valid scene that the pipeline refuses (a cycloidal motion in exact arithmetic).
  Run refused = run_eccd("solve " + q(bad("cycloidal_exact.json")) + " --arith exact");
  CHECK(refused.code == 3);
  CHECK(refused.err.find("cycloidal_exact.json") != std::string::npos);
  // ... and points to what does solve it (issue 20).
  CHECK(refused.err.find("double, mpfr:BITS or certified") != std::string::npos);
}

TEST_CASE("eccd solve warns about options the combination ignores", "[cli][conventions]") {
  // --method chooses among the 3D floating methods: ignored on a 2D scene, with the answer unchanged.
  Run with = run_eccd("solve " + q(kScene2d) + " --arith double --method marching:10 --json");
  Run without = run_eccd("solve " + q(kScene2d) + " --arith double --json");
  REQUIRE(with.code == 0);
  REQUIRE(without.code == 0);
  CHECK(with.err.find("warning: --method is ignored") != std::string::npos);
  CHECK(without.err.empty());
  auto a = nlohmann::json::parse(with.out), b = nlohmann::json::parse(without.out);
  CHECK(a["collides"] == b["collides"]);
  CHECK(a["intervals"] == b["intervals"]);
  // --basis with exact arithmetic.
  Run exact = run_eccd("solve " + q(kScene2d) + " --arith exact --basis scaled-bernstein");
  CHECK(exact.code == 0);
  CHECK(exact.err.find("warning: --basis applies to double and mpfr only") != std::string::npos);
  // --first-contact in 2D (003's Variant 2 is --variant 2).
  Run fc = run_eccd("solve " + q(kScene2d) + " --arith double --first-contact");
  CHECK(fc.code == 0);
  CHECK(fc.err.find("warning: --first-contact is ignored in 2D") != std::string::npos);
}

TEST_CASE("eccd table --mpfr-bits takes a comma list", "[cli][conventions]") {
  TempDir t;
  fs::copy_file(kScene2d, t.path / "example2.json");
  Run r = run_eccd("table " + q(t.str()) + " --mpfr-bits 64,128 --json", 120);
  REQUIRE(r.code == 0);
  // JSON Lines: one object per scene, printed when the scene is done
  std::istringstream lines(r.out);
  std::string line;
  std::vector<nlohmann::json> rows;
  while (std::getline(lines, line))
    if (!line.empty()) rows.push_back(nlohmann::json::parse(line));
  REQUIRE(rows.size() == 1);
  CHECK(rows[0]["format"] == "eccd-table-row/1");
  CHECK(rows[0].contains("version"));
  CHECK(rows[0].contains("mpfr:64"));
  CHECK(rows[0].contains("mpfr:128"));
  CHECK(rows[0]["mpfr:64"]["arith"] == "mpfr:64");
  CHECK(rows[0]["mpfr:128"]["precision_bits"] == 128);
}

TEST_CASE("eccd solve - reads the scene from standard input", "[cli][conventions]") {
  Run piped = run_eccd("solve - --arith exact --json < " + q(kScene2d));
  Run file = run_eccd("solve " + q(kScene2d) + " --arith exact --json");
  REQUIRE(piped.code == 0);
  REQUIRE(file.code == 0);
  auto a = nlohmann::json::parse(piped.out), b = nlohmann::json::parse(file.out);
  CHECK(a["file"] == "<stdin>");
  CHECK(a["collides"] == true);
  CHECK(a["intervals"] == b["intervals"]);  // the same exact brackets (1/2, 1/2)
  CHECK(a["intervals"][0][0]["lo"] == "1/2");
  // A malformed scene on stdin is named <stdin>.
  Run bad_in = run_eccd("solve - < " + q(bad("json_syntax.json")));
  CHECK(bad_in.code == 2);
  CHECK(bad_in.err.find("<stdin>") != std::string::npos);
}

TEST_CASE("JSON outputs carry format and version keys", "[cli][conventions]") {
  TempDir t;
  Run s = run_eccd("solve " + q(kScene2d) + " --arith double --json");
  REQUIRE(s.code == 0);
  auto j = nlohmann::json::parse(s.out);
  CHECK(j["format"] == "eccd-solution/1");
  CHECK(j["version"] == ECCD_PROJECT_VERSION);
  CHECK(j.contains("collides"));  // the keys stay

  fs::copy_file(kScene2d, t.path / "example2.json");
  Run r = run_eccd("regress " + q(t.str()) + " --json", 120);
  REQUIRE(r.code == 0);
  auto rj = nlohmann::json::parse(r.out);
  CHECK(rj["format"] == "eccd-regress/1");
  CHECK(rj["version"] == ECCD_PROJECT_VERSION);
  CHECK(rj["passed"] == true);

  const std::string cert = (t.path / "e.cert.json").string();
  Run c = run_eccd("certify " + q(kScene2d) + " --out " + q(cert) + " --no-floating --json", 120);
  REQUIRE(c.code == 0);
  auto cj = nlohmann::json::parse(c.out);
  CHECK(cj["format"] == "eccd-certify/1");
  CHECK(cj["version"] == ECCD_PROJECT_VERSION);
  Run k = run_eccd("check-certificate " + q(kScene2d) + " " + q(cert) + " --json", 120);
  REQUIRE(k.code == 0);
  auto kj = nlohmann::json::parse(k.out);
  CHECK(kj["format"] == "eccd-certificate-check/1");
  CHECK(kj["valid"] == true);
}

TEST_CASE("under --json an error is also a JSON object on stdout", "[cli][conventions]") {
  Run r = run_eccd("solve " + q(bad("json_syntax.json")) + " --json");
  CHECK(r.code == 2);
  auto j = nlohmann::json::parse(r.out);  // exactly one JSON value
  CHECK(j["format"] == "eccd-error/1");
  CHECK(j["exit_code"] == 2);
  CHECK(j["error"].get<std::string>().find("json_syntax.json") != std::string::npos);
  CHECK(r.err.find("json_syntax.json") != std::string::npos);  // still on stderr
  // A refusal keeps its own exit status in the object.
  Run refused = run_eccd("solve " + q(bad("cycloidal_exact.json")) + " --json");
  CHECK(refused.code == 3);
  CHECK(nlohmann::json::parse(refused.out)["exit_code"] == 3);
  // Without --json nothing is written to stdout.
  Run plain = run_eccd("solve " + q(bad("json_syntax.json")));
  CHECK(plain.code == 2);
  CHECK(plain.out.empty());
}

namespace {
// Significant digits of a decimal text such as "0.00123400" or "1.5e-05" (trailing zeros count: they were printed).
int significant_digits(const std::string& a) {
  std::string m = a.substr(0, a.find_first_of("eE"));
  std::string d;
  for (char c : m)
    if (c >= '0' && c <= '9') d += c;
  const auto first = d.find_first_not_of('0');
  return first == std::string::npos ? 1 : int(d.size() - first);
}
// The exact rational value of a decimal text such as "0.00123400", "-1.5e-05".
mpq_class decimal_value(const std::string& a) {
  const auto e = a.find_first_of("eE");
  const std::string m = a.substr(0, e);
  std::string digits;
  int frac = 0;
  bool after_point = false;
  for (char c : m) {
    if (c == '.')
      after_point = true;
    else if (c >= '0' && c <= '9') {
      digits += c;
      frac += after_point;
    }
  }
  int exp10 = (e == std::string::npos ? 0 : std::stoi(a.substr(e + 1))) - frac;
  mpz_class ten_k;
  mpz_ui_pow_ui(ten_k.get_mpz_t(), 10, unsigned(std::abs(exp10)));
  mpq_class v(mpz_class(digits.empty() ? "0" : digits, 10));  // base 10: leading zeros are not octal
  v = exp10 >= 0 ? mpq_class(v * ten_k) : mpq_class(v / ten_k);
  return m.find('-') != std::string::npos ? mpq_class(-v) : v;
}
}  // namespace

TEST_CASE("an instant's approx carries the digits its bracket or precision supports", "[cli][conventions]") {
  // Certified: the ladder's brackets of 002's example (about 1e-9 wide from an MPFI rung, 5e-20 from the exact
  // rung, where the ladder decides it since issue 18's budgets): floor(-log10 w) + 1 digits, inside the bracket.
  Run c = run_eccd("solve " + q(kScene3d) + " --arith certified --json", 120);
  REQUIRE(c.code == 0);
  auto cj = nlohmann::json::parse(c.out);
  REQUIRE(!cj["intervals"].empty());
  int checked = 0, full = 0;
  for (const auto& iv : cj["intervals"])
    for (const auto& i : iv) {
      if (i["lo"] == i["hi"]) continue;
      const mpq_class lo(i["lo"].get<std::string>()), hi(i["hi"].get<std::string>());
      const double w = mpq_class(hi - lo).get_d();
      const int want = std::clamp(int(std::floor(-std::log10(w))) + 1, 3, 20);
      INFO(i.dump() << " width " << w);
      CHECK(significant_digits(i["approx"].get<std::string>()) <= want);
      full += significant_digits(i["approx"].get<std::string>()) == want;  // less only where %g dropped trailing zeros
      // Compared exactly: an exact bracket (narrower than a double's spacing) holds its approx, but
      // mpq_class::get_d() truncates, so hi.get_d() may lie below the double nearest to the approx.
      const mpq_class a = decimal_value(i["approx"].get<std::string>());
      CHECK(a >= lo);
      CHECK(a <= hi);
      ++checked;
    }
  CHECK(checked > 0);
  CHECK(full > 0);
  // Floating at 512 bits: at most 40 digits, more than a double's 17 somewhere.
  Run m = run_eccd("solve " + q(kScene3d) + " --arith mpfr:512 --json", 120);
  REQUIRE(m.code == 0);
  auto mj = nlohmann::json::parse(m.out);
  int longest = 0;
  for (const auto& instant : mj["critical_instants"])
    longest = std::max(longest, significant_digits(instant["t"]["approx"].get<std::string>()));
  for (const auto& iv : mj["intervals"])
    for (const auto& i : iv) longest = std::max(longest, significant_digits(i["approx"].get<std::string>()));
  CHECK(longest <= 40);
  CHECK(longest > 17);
}

}  // namespace ECCD_UNITY_ID
