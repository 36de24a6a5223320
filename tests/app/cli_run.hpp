#pragma once
// Test support: the built `eccd` run through the shell under `timeout`, with
// stdout, stderr, the exit status, the wall time and the processor time
// (issue 15's tests: exit code, clear message, bounded time). A test bounds
// `cpu_seconds`, the work the run did, and never `seconds`, which grows with
// whatever else the machine runs. ECCD_EXE and ECCD_SOURCE_DIR come from CMake.
#include <catch2/catch.hpp>

#include <unistd.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace eccd::clitest {

inline std::string q(const std::string& s) {
  std::string r = "'";
  for (char c : s) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return r + "'";
}

inline std::string exe() { return q(ECCD_EXE); }
inline std::string src(const std::string& rel) { return std::string(ECCD_SOURCE_DIR) + "/" + rel; }
inline std::string bad(const std::string& file) { return src("tests/data/bad/" + file); }

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
inline void spit(const std::filesystem::path& p, const std::string& text) {
  std::ofstream o(p, std::ios::binary);
  o << text;
}

struct Run {
  int code = -1;  // exit status; 124/137: killed by timeout; -1: no normal exit
  bool timed_out = false;
  std::string out, err;  // stderr cut at 1 MB (a flood would be seen by its size)
  std::size_t err_bytes = 0;
  double seconds = 0;      // wall-clock: for messages only
  double cpu_seconds = 0;  // user + system time of the shell, `timeout` and eccd (all waited for)
};

// User + system time of the waited-for children of this process so far.
inline double children_cpu_seconds() {
  rusage ru{};
  getrusage(RUSAGE_CHILDREN, &ru);
  return double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

// Runs `args` (after the eccd binary) in folder `cwd` under `timeout SECONDS`.
inline Run run_eccd(const std::string& args, double seconds = 60, const std::string& cwd = "") {
  Run r;
  auto tmp = std::filesystem::temp_directory_path() /
             ("eccd_cli_err_" + std::to_string(getpid()) + "_" + std::to_string(std::random_device{}()));
  std::string cmd = (cwd.empty() ? "" : "cd " + q(cwd) + " && ") + "timeout -k 5 " + std::to_string(int(seconds)) +
                    " " + exe() + " " + args + " 2>" + q(tmp.string());
  auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = children_cpu_seconds();
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  int st = pclose(p);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu_seconds = children_cpu_seconds() - cpu0;
  std::error_code ec;
  r.err_bytes = std::size_t(std::filesystem::file_size(tmp, ec));
  {
    std::ifstream in(tmp, std::ios::binary);
    std::string e(std::min<std::size_t>(r.err_bytes, 1 << 20), '\0');
    in.read(e.data(), std::streamsize(e.size()));
    r.err = e;
  }
  std::filesystem::remove(tmp, ec);
  if (WIFEXITED(st)) r.code = WEXITSTATUS(st);
  r.timed_out = r.code == 124 || r.code == 137;
  return r;
}

// A fresh empty folder, removed with its contents at the end of the scope.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string t = (std::filesystem::temp_directory_path() / "eccd_test_XXXXXX").string();
    REQUIRE(mkdtemp(t.data()) != nullptr);
    path = t;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::permissions(path, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
    for (auto& e : std::filesystem::recursive_directory_iterator(path, ec))
      if (e.is_directory(ec))
        std::filesystem::permissions(e.path(), std::filesystem::perms::owner_all, std::filesystem::perm_options::add,
                                     ec);
    std::filesystem::remove_all(path, ec);
  }
  std::string str() const { return path.string(); }
};

}  // namespace eccd::clitest
