// `eccd report --merge` (app/report_merge.cpp) on two real shard parts of the
// cheapest plan (2D, degree 2, one free and one colliding scene, one MPFR
// precision, one face, one input mode, no map, no peers), and on copies of
// them edited one way each. What test_cli_report (the merged table equals one
// run's) and test_cli_reliability (bad shard texts, a shard given twice, a
// truncated meta.json or results.csv, a missing part) check is not repeated.
//  - the merge takes the parts in any order and gives the same results.csv:
//    the header, then every row of both parts, in the plan's order; meta.json
//    says 2 shards; scenes/index.json lists the scenes of both parts;
//  - each refusal is exit 2, names the file or option and what is wrong, and
//    writes nothing: a part run with another seed or other MPFR precisions, a
//    row count that does not match meta.json's, /shards not a positive
//    integer, /shard disagreeing with /shards, no /command, a results.csv with
//    another header, a path that is not a folder, --resume with --merge, and
//    an output folder that is one of the parts.
#include "cli_run.hpp"

#include "compare/harness.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {
const std::string kPlan =
    " --dims 2 --degrees 2 --families free,colliding --count 1 --cases '' --no-map --no-figures --mpfr-bits 64 "
    "--input prepared --guard bound --no-fcl --no-certified --jobs 1";
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}
}  // namespace

TEST_CASE("eccd report --merge: parts in any order, and each bad part refused", "[app][cli][cli-report-merge]") {
  TempDir d;
  for (const char* i : {"0", "1"}) {
    const std::string part = (d.path / (std::string("p") + i)).string();
    std::string args = "report --out-dir " + q(part);
    args += kPlan;
    args += std::string(" --shard ") + i + "/2";
    Run r = run_eccd(args, 300);
    INFO(r.err);
    REQUIRE(r.code == 0);
  }
  const std::string p0 = (d.path / "p0").string(), p1 = (d.path / "p1").string();
  Run a = run_eccd("report --out-dir " + q((d.path / "m01").string()) + " --no-figures --merge " + q(p0) + " " + q(p1));
  Run b = run_eccd("report --out-dir " + q((d.path / "m10").string()) + " --no-figures --merge " + q(p1) + " " + q(p0));
  INFO(a.err << b.err);
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  const std::string merged = slurp(d.path / "m01" / "results.csv");
  CHECK(merged == slurp(d.path / "m10" / "results.csv"));
  const auto m = lines(merged), r0 = lines(slurp(d.path / "p0" / "results.csv")),
             r1 = lines(slurp(d.path / "p1" / "results.csv"));
  REQUIRE(!m.empty());
  CHECK(m[0] == eccd::results_csv_header());
  CHECK(m.size() == r0.size() + r1.size() - 1);
  std::multiset<std::string> want(r0.begin() + 1, r0.end()), got(m.begin() + 1, m.end());
  want.insert(r1.begin() + 1, r1.end());
  CHECK(got == want);                                    // every row of both parts, nothing else
  CHECK(m[1].find(",colliding,") != std::string::npos);  // the plan's order: colliding before free
  CHECK(m.back().find(",free,") != std::string::npos);
  const json meta = json::parse(slurp(d.path / "m01" / "meta.json"));
  CHECK(meta["shards"] == 2);
  CHECK(json::parse(slurp(d.path / "m01" / "scenes" / "index.json"))["scenes"].size() == 2);

  // Refusals, each on a fresh copy of part 1 edited one way.
  const fs::path bad = d.path / "bad";
  auto edit_meta = [&](const std::function<void(json&)>& f) {
    json j = json::parse(slurp(bad / "meta.json"));
    f(j);
    spit(bad / "meta.json", j.dump());
  };
  struct Case {
    std::string what;
    std::function<void()> make;
    std::string phrase;
  };
  const std::vector<Case> cases{
      {"another seed", [&] { edit_meta([](json& j) { j["seed"] = 99; }); }, "was run with a different seed than"},
      {"other precisions", [&] { edit_meta([](json& j) { j["mpfr_bits"] = {128}; }); },
       "was run with a different mpfr_bits than"},
      {"row count", [&] { edit_meta([](json& j) { j["result_rows"] = j["result_rows"].get<int>() + 1; }); },
       "(truncated?)"},
      {"shards zero", [&] { edit_meta([](json& j) { j["shards"] = 0; }); }, "/shards: expected a positive integer"},
      {"shard of 3", [&] { edit_meta([](json& j) { j["shard"] = "1/3"; }); }, "/shard says 3 shards but /shards is 2"},
      {"no command", [&] { edit_meta([](json& j) { j.erase("command"); }); }, "/command: expected a string"},
      {"another header",
       [&] {
         auto l = lines(slurp(bad / "results.csv"));
         l[0] += ",extra";
         std::string t;
         for (const auto& x : l) t += x + "\n";
         spit(bad / "results.csv", t);
       },
       "line 1: not the expected header"},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    fs::remove_all(bad);
    fs::copy(d.path / "p1", bad, fs::copy_options::recursive);
    c.make();
    Run r = run_eccd("report --out-dir " + q((d.path / "out").string()) + " --no-figures --merge " + q(p0) + " " +
                     q(bad.string()));
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find(c.phrase) != std::string::npos);
    CHECK_FALSE(fs::exists(d.path / "out"));
    CHECK_FALSE(fs::exists(d.path / "out.partial"));
  }
  spit(d.path / "file", "x");
  Run nf = run_eccd("report --out-dir " + q((d.path / "out").string()) + " --no-figures --merge " + q(p0) + " " +
                    q((d.path / "file").string()));
  CHECK(nf.code == 2);
  CHECK(nf.err.find("not a folder (an `eccd report --shard` part)") != std::string::npos);
  Run res = run_eccd("report --out-dir " + q((d.path / "out").string()) + " --no-figures --resume --merge " + q(p0) +
                     " " + q(p1));
  CHECK(res.code == 2);
  CHECK(res.err.find("--resume: not with --merge") != std::string::npos);
  Run onto = run_eccd("report --out-dir " + q(p0) + " --no-figures --merge " + q(p0) + " " + q(p1));
  CHECK(onto.code == 2);
  CHECK(onto.err.find("it is the part") != std::string::npos);
  CHECK(lines(slurp(d.path / "p0" / "results.csv")) == r0);  // the part is untouched
  CHECK_FALSE(fs::exists(d.path / "out"));
}

}  // namespace ECCD_UNITY_ID
