// Fuzz: the animation reader (io/animation_reader.hpp) on mutated copies of
// the shipped animations (cases/animations/). Every mutant must either read
// or fail with SceneError whose message starts with the file label; nothing
// else may escape (no json exception, no crash), no single input may take
// long, no message may echo a huge input. Runs half of ECCD_FUZZ_SECONDS
// (default 10) from seed ECCD_FUZZ_SEED (default random; printed).
#include "io/animation_reader.hpp"
#include "tests/support/mutate.hpp"

#include <catch2/catch.hpp>

#include <chrono>

#include "kernel/budget.hpp"
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ECCD_UNITY_ID {
TEST_CASE("fuzz: the animation reader gives an animation or a clear SceneError on mutated files", "[fuzz][animation]") {
  const std::uint64_t seed = eccd::test::fuzz_seed();
  const double budget = eccd::test::fuzz_seconds() / 2;
  std::fprintf(stderr, "fuzz animation reader: seed %llu (ECCD_FUZZ_SEED=%llu to repeat), %.0f s\n",
               (unsigned long long)seed, (unsigned long long)seed, budget);
  INFO("ECCD_FUZZ_SEED=" << seed);
  std::vector<std::string> corpus;
  for (auto& e : std::filesystem::directory_iterator(std::filesystem::path(ECCD_SOURCE_DIR) / "cases/animations")) {
    if (e.path().extension() != ".json") continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    corpus.push_back(ss.str());
  }
  REQUIRE(corpus.size() >= 2);
  eccd::test::Mutator m(seed, corpus);
  const std::string label = "fuzz.json";
  auto start = std::chrono::steady_clock::now();
  long runs = 0, accepted = 0, rejected = 0;
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < budget) {
    std::string how;
    std::string text = m.mutate(m.any_corpus(), how);
    ++runs;
    const double t0 = eccd::thread_cpu_seconds();  // processor time: a busy machine does not make an input slow
    std::string unexpected;
    try {
      eccd::animation_from_text(text, label);
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
    if (!unexpected.empty() || s > 10) {
      INFO("mutations: " << how);
      INFO("seconds: " << s);
      FAIL((unexpected.empty() ? std::string("one input took more than 10 s") : unexpected));
    }
  }
  std::fprintf(stderr, "fuzz animation reader: %ld inputs (%ld accepted, %ld rejected)\n", runs, accepted, rejected);
  CHECK(runs > 0);
  CHECK(rejected > 0);
}

}  // namespace ECCD_UNITY_ID
