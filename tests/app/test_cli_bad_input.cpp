// Bad scene files at the command line: `eccd solve FILE --arith exact --json`
// on each file under tests/data/bad/ must fail cleanly: a normal non-zero exit
// (no crash), a message on stderr that names the file and says what is wrong,
// and nothing on stdout (no half-written JSON). cycloidal_exact.json is a
// valid scene whose motion the exact pipeline must refuse.
//
// ECCD_EXE (the eccd binary) and ECCD_SOURCE_DIR are defined by CMake.
#include "io/scene_reader.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace ECCD_UNITY_ID {
#ifndef ECCD_EXE
#error "ECCD_EXE (path of the eccd binary) must be defined by the build"
#endif
#ifndef ECCD_SOURCE_DIR
#error "ECCD_SOURCE_DIR (the source tree) must be defined by the build"
#endif

namespace {

struct BadCase {
  const char* file;    // under tests/data/bad/
  const char* place;   // JSON pointer or "line L, column C" the message must name ("" = any)
  const char* phrase;  // what the message must say
};

const BadCase kCases[] = {
    {"json_syntax.json", "line 7, column 1", "malformed JSON"},
    {"float_number.json", "/a/shape/semi_axes/1", "write it as a string \"1.8\""},
    {"unknown_key.json", "/a/colour", "unknown key \"colour\""},
    {"unknown_motion.json", "/b/motion/type", "unknown motion type \"spline\""},
    {"bad_dim.json", "/dim", "dim must be 2"},
    {"matrix_size.json", "/a/shape/matrix", "4x4"},
    {"hyperbola.json", "/b/shape/matrix", "is a hyperbola"},
    {"imaginary_ellipse.json", "/a/shape/matrix", "is an imaginary ellipse"},
    {"w_vanishes.json", "/b/motion/m/2/2", "w(t) vanishes on [0, 1]"},
    {"kinematic_denominator.json", "/b/motion/d", "d2(t)^2 + d3(t)^2 vanishes on [0, 1]"},
    {"singular_affine.json", "/b/motion/m", "singular affine block at t = 1/2"},
    {"euler_in_2d.json", "/b/motion/type", "\"euler\" is for dim 3 only"},
    {"cycloidal_exact.json", "", "cycloidal"},
};

std::string bad_path(const char* file) { return std::string(ECCD_SOURCE_DIR) + "/tests/data/bad/" + file; }

std::string shell_quote(const std::string& s) {
  std::string r = "'";
  for (char c : s) {
    if (c == '\'')
      r += "'\\''";
    else
      r += c;
  }
  return r + "'";
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct RunResult {
  bool exited = false;  // terminated normally (not by a signal)
  int code = -1;        // exit status when exited
  std::string out, err;
};

// Runs `command` through the shell; stdout via the pipe, stderr via a temp file.
RunResult run(const std::string& command) {
  RunResult r;
  std::string tmpl = (std::filesystem::temp_directory_path() / "eccd_cli_stderr_XXXXXX").string();
  int fd = mkstemp(tmpl.data());
  REQUIRE(fd >= 0);
  close(fd);
  const std::string full = command + " 2>" + shell_quote(tmpl);
  FILE* pipe = popen(full.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
  const int status = pclose(pipe);
  r.err = slurp(tmpl);
  std::remove(tmpl.c_str());
  // The shell reports a child killed by signal N as exit status 128 + N.
  if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) < 128) {
    r.exited = true;
    r.code = WEXITSTATUS(status);
  }
  return r;
}

}  // namespace

TEST_CASE("eccd solve rejects bad scene files cleanly", "[cli]") {
  for (const BadCase& c : kCases) {
    const std::string path = bad_path(c.file);
    SECTION(c.file) {
      REQUIRE(std::filesystem::exists(path));
      const RunResult r = run(shell_quote(ECCD_EXE) + " solve " + shell_quote(path) + " --arith exact --json");
      INFO("file: " << path);
      INFO("exit code: " << r.code);
      INFO("stderr: " << r.err);
      INFO("stdout: " << r.out);
      CHECK(r.exited);  // no crash
      CHECK(r.code != 0);
      CHECK(r.err.find(path) != std::string::npos);
      CHECK(r.err.find(c.place) != std::string::npos);
      CHECK(r.err.find(c.phrase) != std::string::npos);
      // Under --json the error is also one JSON object on stdout (issue 19: README "Exit codes"), nothing else.
      const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
      CHECK(j.is_object());
      CHECK(j.value("format", "") == "eccd-error/1");
      CHECK(j.value("exit_code", -1) == r.code);
    }
  }
}

// The data files say what the tests above expect of them (the reader alone,
// no binary needed): each bad file fails with its place and phrase, and
// cycloidal_exact.json is a valid scene.
TEST_CASE("bad scene files fail in the reader as expected", "[scene_reader][cli]") {
  for (const BadCase& c : kCases) {
    const std::string path = bad_path(c.file);
    INFO("file: " << path);
    if (std::string(c.file) == "cycloidal_exact.json") {
      eccd::Scene s = eccd::read_scene_file(path);
      CHECK(std::holds_alternative<eccd::CycloidalMotion>(s.b.motion));
      continue;
    }
    std::string msg = "(no error)";
    try {
      eccd::read_scene_file(path);
    } catch (const eccd::SceneError& e) {
      msg = e.what();
    }
    INFO("message: " << msg);
    CHECK(msg.rfind(path + ": " + c.place + ": ", 0) == 0);
    CHECK(msg.find(c.phrase) != std::string::npos);
  }
}

}  // namespace ECCD_UNITY_ID
