// Fuzz: bytes that are not UTF-8 through the whole program.
// Each run takes one input of a reader (a scene, an animation, a certificate,
// an answer), puts bytes that are not UTF-8 into it (a stray 0x80-0xFF byte,
// a truncated sequence, an overlong form, a surrogate, all inside a string or
// in the open) and/or into the file's name, and runs the matching command
// with --json. Every run must end with an exit code of the table
// (docs/exit-codes.md: 0 to 5, never 70, never a signal) and print one valid
// JSON object (nlohmann refuses text that is not UTF-8).
// Settings: ECCD_FUZZ_SEED (default random, printed), ECCD_FUZZ_CLI_RUNS
// (default 48 runs: each is a process, a few tens of milliseconds).
#include "tests/app/cli_run.hpp"
#include "tests/support/mutate.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kBadBytes = {
    "\xff", "\xfe",     "\x80",        "\xc0\xaf", "\xe0\x80\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80",
    "\xc3", "\xe2\x82", "\xf0\x9f\x98"};

std::string insert_bad(std::mt19937_64& rng, std::string text) {
  const int k = 1 + int(rng() % 3);
  for (int i = 0; i < k; ++i) {
    const std::string& b = kBadBytes[rng() % kBadBytes.size()];
    std::size_t at;
    const std::size_t quote = text.find('"', rng() % (text.size() + 1));
    if (quote != std::string::npos && rng() % 2)
      at = quote + 1;  // inside a string (a key or a value)
    else
      at = rng() % (text.size() + 1);
    text.insert(at, b);
  }
  return text;
}

}  // namespace

TEST_CASE(
    "fuzz: bytes that are not UTF-8 in every reader's input and in file names give valid JSON and a table exit code",
    "[fuzz][cli][utf8]") {
  const std::uint64_t seed = eccd::test::fuzz_seed();
  long runs = 48;
  if (const char* s = std::getenv("ECCD_FUZZ_CLI_RUNS")) runs = std::strtol(s, nullptr, 10);
  std::fprintf(stderr, "fuzz cli bytes: seed %llu (ECCD_FUZZ_SEED=%llu to repeat), %ld runs (ECCD_FUZZ_CLI_RUNS)\n",
               (unsigned long long)seed, (unsigned long long)seed, runs);
  INFO("ECCD_FUZZ_SEED=" << seed);
  std::mt19937_64 rng(seed);
  TempDir w;
  const std::string scene = src("cases/spheres/spheres-crossing.json");
  // a certificate of that scene, made once
  const fs::path cert = w.path / "good.cert.json";
  Run c = run_eccd("certify " + q(scene) + " --no-floating --out " + q(cert.string()), 240);
  REQUIRE(c.code == 0);
  struct Reader {
    std::string what, text;
    std::string command(const std::string& scene_path, const std::string& file) const {
      if (what == "scene") return "solve " + q(file) + " --arith double --json";
      if (what == "animation") return "animate " + q(file) + " --arith double --json";
      if (what == "certificate") return "check-certificate " + q(scene_path) + " " + q(file) + " --json";
      return "judge " + q(scene_path) + " " + q(file) + " --json";
    }
  };
  const std::vector<Reader> readers = {{"scene", slurp(scene)},
                                       {"animation", slurp(src("cases/animations/swarm-2d.json"))},
                                       {"certificate", slurp(cert)},
                                       {"answer", slurp(src("tests/data/judge/correct.json"))}};
  for (long i = 0; i < runs; ++i) {
    const Reader& r = readers[std::size_t(i) % readers.size()];
    const int mode = int(rng() % 3);  // 0: bytes in the file, 1: in its name, 2: both
    std::string name = "in-" + std::to_string(i);
    if (mode >= 1) name += kBadBytes[rng() % kBadBytes.size()];
    name += ".json";
    const fs::path file = w.path / name;
    std::string text = mode == 1 ? r.text : insert_bad(rng, r.text);
    spit(file, text);
    const bool missing = rng() % 8 == 0;  // now and then a name that does not exist
    if (missing) fs::remove(file);
    const std::string cmd = r.command(scene, file.string());
    Run run = run_eccd(cmd, 240);
    INFO("run " << i << " (" << r.what << ", mode " << mode << (missing ? ", missing" : "") << "): " << cmd);
    INFO("stderr: " << run.err.substr(0, 600));
    INFO("stdout: " << run.out.substr(0, 600));
    CHECK(!run.timed_out);
    CHECK(run.code >= 0);
    CHECK(run.code <= 5);
    bool ok = false;
    try {
      ok = nlohmann::json::parse(run.out).is_object();
    } catch (const std::exception&) {}
    CHECK(ok);
    fs::remove(file);
  }
}

}  // namespace ECCD_UNITY_ID
