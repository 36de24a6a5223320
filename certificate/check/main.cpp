// eccd-check SCENE CERT [--json]: the independent certificate checker as a
// program (certificate/check/verdict.hpp). Exit 0 VALID, 1 REJECTED (the
// claim and why), 2 unreadable input, an uncovered format or bad arguments.
#include "certificate/check/verdict.hpp"

#include <nlohmann/json.hpp>

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  std::vector<std::string> files;
  bool as_json = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--json") == 0)
      as_json = true;
    else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      std::cout << "usage: eccd-check SCENE CERT [--json]\n"
                   "Checks an eccd certificate against its scene with its own exact algebra (no solver code).\n"
                   "Exit 0 VALID, 1 REJECTED, 2 unreadable input or a format it does not cover.\n";
      return 0;
    } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
      std::cerr << "eccd-check: unknown option " << argv[i] << " (usage: eccd-check SCENE CERT [--json])\n";
      return 2;
    } else {
      files.push_back(argv[i]);
    }
  }
  if (files.size() != 2) {
    std::cerr << "eccd-check: expected a scene file and a certificate file (usage: eccd-check SCENE CERT [--json])\n";
    return 2;
  }
  using eccd::check::Outcome;
  const eccd::check::Verdict v = eccd::check::check_certificate_files(files[0], files[1]);
  const char* word = v.outcome == Outcome::valid ? "VALID" : v.outcome == Outcome::rejected ? "REJECTED" : "UNREADABLE";
  if (as_json) {
    nlohmann::json j;
    j["verdict"] = word;
    j["claims"] = v.checked;
    if (v.outcome != Outcome::valid) {
      j["failed_claim"] = v.claim;
      j["reason"] = v.reason;
    }
    std::cout << j.dump(2) << "\n";
  } else {
    for (const auto& line : v.checked) std::cout << "ok  " << line << "\n";
    if (v.outcome == Outcome::valid)
      std::cout << "VALID\n";
    else if (v.outcome == Outcome::rejected)
      std::cout << "REJECTED: " << v.claim << ": " << v.reason << "\n";
    else
      std::cerr << "eccd-check: " << v.reason << "\n";
  }
  return v.outcome == Outcome::valid ? 0 : v.outcome == Outcome::rejected ? 1 : 2;
}
