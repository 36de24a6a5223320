// Fuzz: the certificate checker (certificate/check_certificate.hpp) on mutated
// certificates of a few corpus scenes (one of them a Bézier certificate from --arith certified). The certificate text
// is mutated, then parsed (a text that is not JSON is an unreadable file: exit 2 at the command line, not the checker's
// business) and checked. Every mutant must give a verdict (VALID or REJECTED with the claim named), never an exception
// that the command line would call an internal error (json exceptions, std::logic_error, ...), never take long; and a
// VALID verdict must certify the genuine answer (a mutant cannot forge another one). Runs ECCD_FUZZ_SECONDS (default
// 10) from ECCD_FUZZ_SEED (default random; printed).
#include "compare/regress.hpp"
#include "certificate/write/bezier_certificate.hpp"
#include "certificate/write/exact_certificate.hpp"
#include "certificate/check_certificate.hpp"
#include "io/scene_reader.hpp"
#include "tests/support/mutate.hpp"

#include <catch2/catch.hpp>

#include <chrono>

#include "kernel/budget.hpp"
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace ECCD_UNITY_ID {
namespace {

struct Genuine {
  eccd::Scene scene;
  nlohmann::json doc, cert;
  std::string text;
};

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("fuzz: the certificate checker gives a verdict on mutated certificates", "[fuzz][certificate]") {
  const std::uint64_t seed = eccd::test::fuzz_seed();
  const double budget = eccd::test::fuzz_seconds();
  std::fprintf(stderr,
               "fuzz certificate checker: seed %llu (ECCD_FUZZ_SEED=%llu to repeat), %.0f s (ECCD_FUZZ_SECONDS)\n",
               (unsigned long long)seed, (unsigned long long)seed, budget);
  INFO("ECCD_FUZZ_SEED=" << seed);
  std::vector<Genuine> genuine;
  for (const char* rel : {"cases/paper003/example2.json", "cases/spheres/spheres-touch.json",
                          "cases/generated/2d/2d-deg2-colliding-kinematic-4575131933740715.json"}) {
    Genuine g;
    std::string path = std::string(ECCD_SOURCE_DIR) + "/" + rel;
    g.scene = eccd::read_scene_file(path);
    g.doc = nlohmann::json::parse(slurp(path));
    g.cert = eccd::make_certificate(g.scene, g.doc);
    g.text = g.cert.dump(1);
    REQUIRE(eccd::check_certificate(g.scene, g.doc, g.cert).valid);
    genuine.push_back(std::move(g));
  }
  {  // a Bézier certificate (certify --arith certified: certificate/write/bezier_certificate.hpp)
    Genuine g;
    std::string path = std::string(ECCD_SOURCE_DIR) + "/cases/spheres/spheres-crossing.json";
    g.scene = eccd::read_scene_file(path);
    g.doc = nlohmann::json::parse(slurp(path));
    g.cert = eccd::make_bezier_certificate(g.scene, g.doc);
    g.text = g.cert.dump(1);
    REQUIRE(eccd::check_certificate(g.scene, g.doc, g.cert).valid);
    genuine.push_back(std::move(g));
  }
  std::vector<std::string> texts;
  for (const auto& g : genuine) texts.push_back(g.text);
  eccd::test::Mutator m(seed, texts, 300);
  auto start = std::chrono::steady_clock::now();
  long runs = 0, valid = 0, rejected = 0, unparsable = 0;
  std::map<std::string, std::pair<long, std::string>> problems;  // kind -> count, first example
  double slowest = 0;
  while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < budget) {
    const Genuine& g = genuine[m.pick(genuine.size())];
    std::string how;
    std::string text = m.pick(3) == 0 ? m.mutate(g.text, how) : m.mutate_value(g.text, how);
    nlohmann::json cert = nlohmann::json::parse(text, nullptr, false);
    if (cert.is_discarded()) {
      ++unparsable;
      continue;
    }
    ++runs;
    const double t0 = eccd::thread_cpu_seconds();  // processor time: a busy machine does not make an input slow
    std::string problem;
    try {
      eccd::CertificateCheck r = eccd::check_certificate(g.scene, g.doc, cert);
      if (r.valid) {
        ++valid;
        // VALID: the answer it certifies is the genuine one
        try {
          eccd::Answer a = eccd::answer_from_json(cert.at("answer"), "mutant", "/answer");
          eccd::Answer b = eccd::answer_from_json(g.cert.at("answer"), "genuine", "/answer");
          auto d = eccd::regress_differences(b, a);
          if (!d.empty()) problem = "VALID for a different answer: " + d[0];
        } catch (const std::exception& e) {
          problem = std::string("VALID, but its answer does not read as an answer: ") + e.what();
        }
      } else {
        ++rejected;
        if (r.failed_claim.empty()) problem = "REJECTED without naming the claim";
      }
    } catch (const std::invalid_argument& e) {  // a usage error (exit 2), e.g. a certificate of another format
      ++rejected;
    } catch (const std::exception& e) {
      problem = std::string("exception (an internal error at the command line): ") + e.what();
    }
    double s = eccd::thread_cpu_seconds() - t0;
    slowest = std::max(slowest, s);
    if (problem.empty() && s > 20) problem = "one check took more than 20 s";
    if (!problem.empty()) {  // collected: the summary names each kind once, with an example
      std::string kind = problem.substr(0, 90);
      auto& [n, example] = problems[kind];
      if (n++ == 0) example = "scene " + g.scene.path + ", mutations " + how + ": " + problem.substr(0, 400);
    }
  }
  for (const auto& [kind, p] : problems)
    std::fprintf(stderr, "fuzz certificate checker: PROBLEM x%ld: %s\n", p.first, p.second.c_str());
  for (const auto& [kind, p] : problems) {
    INFO(p.first << " time(s): " << p.second);
    CHECK(false);
  }
  std::fprintf(stderr,
               "fuzz certificate checker: %ld checked (%ld VALID, %ld REJECTED), %ld not JSON, slowest %.3f s\n", runs,
               valid, rejected, unparsable, slowest);
  CHECK(runs > 0);
}

}  // namespace ECCD_UNITY_ID
