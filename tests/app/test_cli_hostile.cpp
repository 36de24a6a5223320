// The command line against hostile input and output paths: bytes that are not UTF-8 give a clear error and valid JSON,
// never an abort; an output path that is a special file, a symbolic link, an input or an existing file without --force
// is refused (exit 2) and its bytes do not change; a FIFO or device given as an input is refused at once instead of
// blocking; judge checks its numbers; regress walks past loops and dangling
// links. Every run is bounded by `timeout` (minutes, a busy machine's margin).
#include "tests/app/cli_run.hpp"

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& s, const std::string& sub) { return s.find(sub) != std::string::npos; }

// stdout is one JSON object (nlohmann refuses text that is not UTF-8).
bool valid_json(const std::string& out, nlohmann::json* j = nullptr) {
  try {
    nlohmann::json v = nlohmann::json::parse(out);
    if (j) *j = v;
    return v.is_object();
  } catch (const std::exception&) {
    return false;
  }
}

const std::string kScene = src("cases/spheres/spheres-crossing.json");

}  // namespace

TEST_CASE("bytes that are not UTF-8 give exit 2 and valid JSON under --json, never an abort", "[cli][hostile][utf8]") {
  TempDir w;
  const std::string ff = (w.path / "ff.json").string();
  spit(ff, std::string("{\xff", 2));
  const std::string cert = (w.path / "c.json").string();
  spit(cert, std::string("{\"format\": \"\xfe\"}", 16));
  for (const std::string& cmd :
       {"solve " + q(ff) + " --json", "animate " + q(ff) + " --json",
        "check-certificate " + q(kScene) + " " + q(ff) + " --json",
        "check-certificate " + q(kScene) + " " + q(cert) + " --json", "judge " + q(kScene) + " " + q(ff) + " --json"}) {
    INFO(cmd);
    Run r = run_eccd(cmd, 240);
    INFO("stderr: " << r.err << "\nstdout: " << r.out);
    nlohmann::json j;
    REQUIRE(valid_json(r.out, &j));
    if (cmd.rfind("check-certificate", 0) == 0 && r.code == 1) {  // a malformed certificate is REJECTED
      CHECK(j["valid"] == false);
      continue;
    }
    CHECK(r.code == 2);
    CHECK(j["exit_code"] == 2);
    CHECK(contains(j["error"].get<std::string>(),
                   cmd.rfind("check-certificate", 0) == 0 && contains(cmd, "c.json") ? "c.json" : "ff.json"));
  }
  // standard input of two bytes that are not UTF-8
  {
    Run r = run_eccd("solve - --json < " + q(ff), 240);
    INFO("stderr: " << r.err);
    CHECK(r.code == 2);
    CHECK(valid_json(r.out));
  }
  // a missing file whose name holds the byte 0xfe: the name is shown escaped
  {
    Run r = run_eccd("solve " + q((w.path / "x\xfe.json").string()) + " --json", 240);
    INFO("stderr: " << r.err);
    CHECK(r.code == 2);
    nlohmann::json j;
    REQUIRE(valid_json(r.out, &j));
    CHECK(contains(j["error"].get<std::string>(), "x\\xFE.json"));
  }
  // a valid scene at such a path: the answer, with the name's byte replaced (valid JSON)
  {
    const fs::path odd = w.path / "scene\xfe.json";
    fs::copy_file(kScene, odd);
    Run r = run_eccd("solve " + q(odd.string()) + " --json", 240);
    INFO("stderr: " << r.err);
    CHECK(r.code == 0);
    nlohmann::json j;
    REQUIRE(valid_json(r.out, &j));
    CHECK(j["collides"] == true);
  }
}

TEST_CASE("an output path that is not a new name or a regular file is refused and left as it was",
          "[cli][hostile][outputs]") {
  TempDir w;
  const std::string decoy_text = "decoy: these bytes must not change\n";
  const fs::path decoy = w.path / "decoy.txt";
  spit(decoy, decoy_text);
  const fs::path link = w.path / "link.json";
  fs::create_symlink(decoy, link);
  const fs::path fifo = w.path / "fifo";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  const fs::path dir = w.path / "dir";
  fs::create_directory(dir);
  const fs::path scene = w.path / "scene.json";
  fs::copy_file(kScene, scene);
  const std::string scene_text = slurp(scene);
  const fs::path anim = w.path / "anim.json";
  fs::copy_file(src("cases/animations/swarm-2d.json"), anim);
  const std::string anim_text = slurp(anim);
  const fs::path existing = w.path / "existing.json";
  spit(existing, decoy_text);

  for (const fs::path& out : {link, fifo, dir, scene, existing}) {
    INFO("--out " << out);
    Run c = run_eccd("certify " + q(scene.string()) + " --no-floating --out " + q(out.string()), 240);
    INFO("stderr: " << c.err);
    CHECK(c.code == 2);
    CHECK(contains(c.err, out.string()));
    Run a = run_eccd("animate " + q(anim.string()) + " --arith double --out " + q(out.string()), 240);
    INFO("stderr: " << a.err);
    CHECK(a.code == 2);
  }
  Run ai = run_eccd("animate " + q(anim.string()) + " --arith double --force --out " + q(anim.string()), 240);
  CHECK(ai.code == 2);  // an input, even with --force
  CHECK(contains(ai.err, "input"));
  CHECK(slurp(decoy) == decoy_text);
  CHECK(slurp(existing) == decoy_text);
  CHECK(slurp(scene) == scene_text);
  CHECK(slurp(anim) == anim_text);
  CHECK(fs::is_symlink(link));
  CHECK(fs::is_fifo(fifo));
  CHECK(fs::is_directory(dir));
  // --force replaces an existing regular file (and only that)
  Run f = run_eccd("certify " + q(scene.string()) + " --no-floating --force --out " + q(existing.string()), 240);
  INFO("stderr: " << f.err);
  CHECK(f.code == 0);
  CHECK(slurp(existing) != decoy_text);
  // nothing left beside the targets
  for (const auto& e : fs::directory_iterator(w.path)) CHECK(!contains(e.path().filename().string(), ".tmp-"));
}

TEST_CASE("a file size limit (SIGXFSZ) leaves no temporary file and exits 2", "[cli][hostile][outputs]") {
  TempDir w;
  // ulimit -f 1: at most 1024 bytes per file; the certificate is larger
  Run r = run_eccd("certify " + q(kScene) + " --no-floating --out " + q((w.path / "c.json").string()), 240, w.str());
  REQUIRE(r.code == 0);  // without the limit: fine
  fs::remove(w.path / "c.json");
  std::string cmd =
      "cd " + q(w.str()) + " && (ulimit -f 1; " + exe() + " certify " + q(kScene) + " --no-floating --out c.json) 2>&1";
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  int st = pclose(p);
  INFO(out);
  CHECK(WIFEXITED(st));
  CHECK(WEXITSTATUS(st) == 2);
  CHECK(contains(out, "c.json"));
  for (const auto& e : fs::directory_iterator(w.path)) CHECK(!contains(e.path().filename().string(), ".tmp-"));
  CHECK(!fs::exists(w.path / "c.json"));
}

TEST_CASE("solve --write-answer refuses to write a scene the reader would refuse", "[cli][hostile][outputs]") {
  TempDir w;
  const fs::path scene = w.path / "s.json";
  const std::string text = slurp(src("cases/spheres/spheres-free.json"));
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(text);
  doc.erase("answer");
  const std::string bare = doc.dump() + "\n";
  // the size of the file with its answer, as --write-answer writes it (on a copy, no limit)
  const fs::path copy = w.path / "copy.json";
  spit(copy, bare);
  REQUIRE(run_eccd("solve " + q(copy.string()) + " --write-answer", 240).code == 0);
  const std::size_t answered = slurp(copy).size();
  REQUIRE(bare.size() < answered);
  spit(scene, bare);
  // a limit the scene meets and the scene with its answer does not
  const std::string limit = std::to_string(answered - 1);
  Run r = run_eccd("solve " + q(scene.string()) + " --write-answer --max-file-bytes " + limit, 240);
  INFO("stderr: " << r.err);
  CHECK(r.code == 2);
  CHECK(contains(r.err, "--max-file-bytes"));
  CHECK(contains(r.err, "unchanged"));
  CHECK(slurp(scene) == bare);
}

TEST_CASE("a FIFO or a device as an input is refused at once, never waited on", "[cli][hostile][inputs]") {
  TempDir w;
  const fs::path fifo = w.path / "f";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  for (const std::string& cmd :
       {"solve " + q(fifo.string()), "judge " + q(kScene) + " " + q(fifo.string()), "animate " + q(fifo.string()),
        "check-certificate " + q(kScene) + " " + q(fifo.string()), std::string("solve /dev/zero")}) {
    INFO(cmd);
    Run r = run_eccd(cmd, 240);
    INFO("stderr: " << r.err << "\nprocessor " << r.cpu_seconds << " s");
    CHECK(!r.timed_out);
    CHECK(r.code == 2);
    CHECK(contains(r.err, "not a regular file"));
  }
  // standard input may be a pipe
  Run r = run_eccd("solve - < " + q(kScene), 240);
  CHECK(r.code == 0);
}

TEST_CASE("judge checks the numbers of an answer as the scene reader does", "[cli][hostile][judge]") {
  TempDir w;
  for (const std::string approx : {"NaN", "2", "0x1p-1", "-0.5", "inf"}) {
    const fs::path a = w.path / "a.json";
    spit(a, "{\"collides\": true, \"intervals\": [[{\"approx\": \"0.1\"}, {\"approx\": \"" + approx +
                "\"}]], \"first_contact\": {\"approx\": \"0.1\"}, \"contacts\": []}");
    Run r = run_eccd("judge " + q(kScene) + " " + q(a.string()), 240);
    INFO(approx << ": " << r.err);
    CHECK(r.code == 2);
    CHECK(contains(r.err, "/intervals/0/1"));
  }
}

TEST_CASE("regress reports symbolic link loops, dangling links and skipped names, and checks the rest",
          "[cli][hostile][regress]") {
  TempDir w;
  fs::copy_file(src("cases/spheres/spheres-free.json"), w.path / "good.json");
  fs::create_symlink(w.path / "loop-a.json", w.path / "loop-b.json");
  fs::create_symlink(w.path / "loop-b.json", w.path / "loop-a.json");
  fs::create_symlink(w.path / "missing.json", w.path / "dangling.json");
  fs::create_symlink("/dev/zero", w.path / "zero.json");
  fs::copy_file(src("cases/spheres/spheres-free.json"), w.path / "upper.JSON");
  Run r = run_eccd("regress " + q(w.str()), 240);
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.code == 1);  // the broken entries fail; the good scene is still checked
  CHECK(contains(r.out, "good.json"));
  CHECK(contains(r.out + r.err, "loop"));
  CHECK(contains(r.out + r.err, "dangling"));
  CHECK(contains(r.out + r.err, "zero.json"));
  CHECK(contains(r.err, "upper.JSON"));
}

}  // namespace ECCD_UNITY_ID
