// Fuzz: the scene reader on mutated corpus files (cases/ and tests/data/bad/).
// Every mutant must either read as a scene or fail with SceneError whose
// message starts with the file label and names a place; nothing else may
// escape (no json exception, no std::logic_error, no crash), no single input
// may take long (a hang), and no message may echo a huge input (cut at a few
// hundred characters per value). Runs ECCD_FUZZ_SECONDS (default 10) from
// seed ECCD_FUZZ_SEED (default random; printed).
#include "io/scene_reader.hpp"
#include "tests/support/mutate.hpp"

#include <catch2/catch.hpp>

#include <chrono>

#include "kernel/budget.hpp"
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ECCD_UNITY_ID {
namespace {

std::vector<std::string> scene_corpus() {
  std::vector<std::string> texts;
  for (const char* dir : {"cases", "tests/data/bad"}) {
    std::filesystem::path root = std::filesystem::path(ECCD_SOURCE_DIR) / dir;
    for (auto& e : std::filesystem::recursive_directory_iterator(root)) {
      if (!e.is_regular_file() || e.path().extension() != ".json" || e.file_size() > 200000) continue;
      std::ifstream in(e.path(), std::ios::binary);
      std::ostringstream ss;
      ss << in.rdbuf();
      texts.push_back(ss.str());
    }
  }
  return texts;
}

}  // namespace

TEST_CASE("fuzz: the scene reader gives a scene or a clear SceneError on mutated files", "[fuzz][scene_reader]") {
  const std::uint64_t seed = eccd::test::fuzz_seed();
  const double budget = eccd::test::fuzz_seconds();
  std::fprintf(stderr, "fuzz scene reader: seed %llu (ECCD_FUZZ_SEED=%llu to repeat), %.0f s (ECCD_FUZZ_SECONDS)\n",
               (unsigned long long)seed, (unsigned long long)seed, budget);
  INFO("ECCD_FUZZ_SEED=" << seed);
  auto corpus = scene_corpus();
  REQUIRE(corpus.size() > 20);
  eccd::test::Mutator m(seed, corpus);
  const std::string label = "fuzz.json";
  auto start = std::chrono::steady_clock::now();
  long runs = 0, accepted = 0, rejected = 0;
  double slowest = 0;
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < budget) {
    std::string how;
    std::string text = m.mutate(m.any_corpus(), how);
    ++runs;
    const double t0 = eccd::thread_cpu_seconds();  // processor time: a busy machine does not make an input slow
    std::string unexpected;
    try {
      eccd::parse_scene(text, label);
      ++accepted;
    } catch (const eccd::SceneError& e) {
      ++rejected;
      const std::string msg = e.what();
      if (msg.rfind(label + ": ", 0) != 0)
        unexpected = "SceneError without the file label: " + msg.substr(0, 300);
      else if (msg.size() > 4000)
        unexpected = "a message of " + std::to_string(msg.size()) + " characters";
      else if (msg.find("internal error") != std::string::npos)
        unexpected = "internal error: " + msg.substr(0, 300);
    } catch (const std::exception& e) {
      unexpected = std::string("an exception other than SceneError: ") + e.what();
    }
    double s = eccd::thread_cpu_seconds() - t0;
    slowest = std::max(slowest, s);
    if (!unexpected.empty() || s > 10) {
      INFO("mutations: " << how);
      INFO("input (first 300 bytes): " << text.substr(0, 300));
      INFO("seconds: " << s);
      FAIL((unexpected.empty() ? std::string("one input took more than 10 s") : unexpected));
    }
  }
  std::fprintf(stderr, "fuzz scene reader: %ld inputs (%ld accepted, %ld rejected), slowest %.3f s\n", runs, accepted,
               rejected, slowest);
  CHECK(runs > 0);
  CHECK(rejected > 0);
}

}  // namespace ECCD_UNITY_ID
