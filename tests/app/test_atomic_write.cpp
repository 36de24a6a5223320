// Output files and folders (app/atomic_write.hpp), on real files in a
// temporary folder:
//  - write_text_atomically writes the whole text to a new name or over a
//    regular file (keeping its mode; a new file gets 0666 & ~umask) and leaves
//    no temporary sibling; it refuses, and leaves untouched, a directory, a
//    FIFO, a character device (/dev/null), a socket and a symbolic link
//    (to a file, or dangling); when the write fails (a file size limit: EFBIG,
//    with SIGXFSZ ignored rather than ending the process; a missing parent
//    folder) the old file is intact, no temporary is left, and OutputError
//    names the path and the system's reason;
//  - check_output_file: a new name passes; an existing regular file only with
//    --force and only when it is none of the inputs (the same inode, also
//    through a hard link); the refusals say what the path is;
//  - check_output_name / check_output_path: the names and paths refused;
//  - output folders: replaced only when missing or carrying the marker (or
//    accepted by written_by_us), swapped into place, the old one removed; a
//    folder without the marker, a symbolic link or a file is refused and the
//    finished output stays where it is.
#include "app/atomic_write.hpp"

#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>

#include <fstream>
#include <sstream>

namespace ECCD_UNITY_ID {
using namespace eccd;
namespace fs = std::filesystem;

namespace {
struct Tmp {
  fs::path p;
  explicit Tmp(const std::string& tag)
      : p(fs::temp_directory_path() / ("eccd-atomic-" + tag + "-" + std::to_string(::getpid()))) {
    fs::remove_all(p);
    fs::create_directories(p);
  }
  ~Tmp() {
    std::error_code ec;
    fs::remove_all(p, ec);
  }
};
std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
void spit(const fs::path& p, const std::string& t) { std::ofstream(p, std::ios::binary) << t; }
// Entries of `dir` whose name holds ".tmp-": temporaries left behind.
int temporaries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    n += e.path().filename().string().find(".tmp-") != std::string::npos;
  return n;
}
std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const OutputError& e) {
    return e.what();
  }
  return "";
}
bool has(const std::string& s, const std::string& w) { return s.find(w) != std::string::npos; }
mode_t mode_of(const fs::path& p) {
  struct stat st {};
  ::stat(p.c_str(), &st);
  return st.st_mode & 07777;
}
}  // namespace

TEST_CASE("atomic write: new files and replaced regular files, whole, no temporaries, mode kept",
          "[app][atomic-write]") {
  Tmp t("write");
  const fs::path f = t.p / "out.json";
  std::string big(1 << 20, 'x');
  for (std::size_t i = 0; i < big.size(); i += 97) big[i] = char('a' + i % 26);
  write_text_atomically(f, big);
  CHECK(slurp(f) == big);
  const mode_t u = ::umask(0);
  ::umask(u);
  CHECK(mode_of(f) == (0666 & ~u));
  ::chmod(f.c_str(), 0640);
  write_text_atomically(f, "short");
  CHECK(slurp(f) == "short");
  CHECK(mode_of(f) == 0640);
  write_text_atomically(f, "");
  CHECK(slurp(f).empty());
  CHECK(temporaries(t.p) == 0);
  // A user's file that looks like a temporary is never touched.
  spit(t.p / "out.json.tmp-AAAAAA", "mine");
  write_text_atomically(f, "again");
  CHECK(slurp(t.p / "out.json.tmp-AAAAAA") == "mine");
  CHECK(has(refusal([] { write_text_atomically("", "x"); }), "empty output path"));
}

TEST_CASE("atomic write: directories, FIFOs, devices, sockets and symbolic links are refused, not replaced",
          "[app][atomic-write]") {
  Tmp t("refuse");
  fs::create_directories(t.p / "dir");
  REQUIRE(::mkfifo((t.p / "fifo").c_str(), 0600) == 0);
  spit(t.p / "target", "keep me");
  fs::create_symlink(t.p / "target", t.p / "link");
  fs::create_symlink(t.p / "nowhere", t.p / "dangling");
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string sp = (t.p / "sock").string();
  REQUIRE(sp.size() < sizeof addr.sun_path);
  std::strcpy(addr.sun_path, sp.c_str());
  REQUIRE(::bind(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
  const std::vector<std::pair<fs::path, std::string>> cases = {
      {t.p / "dir", "it is a directory, not a regular file"},
      {t.p / "fifo", "it is a FIFO (named pipe), not a regular file"},
      {"/dev/null", "it is a character device, not a regular file"},
      {t.p / "sock", "it is a socket, not a regular file"},
      {t.p / "link", "it is a symbolic link to a regular file"},
      {t.p / "dangling", "it is a symbolic link (dangling)"}};
  for (const auto& [path, words] : cases) {
    INFO(path);
    const std::string w = refusal([&] { write_text_atomically(path, "text"); });
    CHECK(has(w, path.string() + ": cannot write the file: " + words));
    const std::string c = refusal([&] { check_output_file("--out", path, true); });
    CHECK(has(c, "--out " + path.string() + ": refusing to write there: " + words));
  }
  ::close(sock);
  CHECK(slurp(t.p / "target") == "keep me");
  CHECK(fs::is_symlink(t.p / "link"));
  CHECK(fs::is_symlink(t.p / "dangling"));
  CHECK_FALSE(fs::exists(t.p / "nowhere"));
  CHECK(fs::is_empty(t.p / "dir"));
  CHECK(fs::is_fifo(t.p / "fifo"));
  CHECK(temporaries(t.p) == 0);
}

TEST_CASE("atomic write: a failed write leaves the old file whole and no temporary", "[app][atomic-write]") {
  Tmp t("fail");
  const fs::path f = t.p / "result.csv";
  spit(f, "old contents\n");
  // A file size limit of 4 KiB in a child process: the 64 KiB write fails with EFBIG (SIGXFSZ ignored meanwhile).
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    rlimit lim{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &lim);
    int code = 10;
    try {
      write_text_atomically(f, std::string(65536, 'y'));
      code = 11;  // no error: wrong
    } catch (const OutputError& e) {
      const std::string w = e.what();
      code = has(w, f.string() + ": cannot write the file: ") && has(w, std::strerror(EFBIG)) ? 0 : 12;
    }
    ::_exit(code);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));  // not ended by SIGXFSZ
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(slurp(f) == "old contents\n");
  CHECK(temporaries(t.p) == 0);
  // A missing folder: the system's reason.
  const std::string w = refusal([&] { write_text_atomically(t.p / "missing" / "x.json", "x"); });
  CHECK(has(w, "missing/x.json: cannot write the file: " + std::string(std::strerror(ENOENT))));
  CHECK_FALSE(fs::exists(t.p / "missing"));
  remove_pending_output();  // nothing pending: does nothing
  CHECK(slurp(f) == "old contents\n");
}

TEST_CASE("atomic write: check_output_file allows new names, and existing files only with --force, not inputs",
          "[app][atomic-write]") {
  Tmp t("check");
  const fs::path in = t.p / "scene.json", out = t.p / "answer.json";
  spit(in, "{}");
  CHECK_NOTHROW(check_output_file("--out", out, false, {in.string()}));
  spit(out, "old");
  CHECK(refusal([&] { check_output_file("--out", out, false); }) ==
        "--out " + out.string() + ": exists; refusing to replace it (give --force to replace it)");
  CHECK_NOTHROW(check_output_file("--out", out, true, {in.string(), "-", ""}));
  CHECK(refusal([&] { check_output_file("--out", in, true, {in.string()}); }) ==
        "--out " + in.string() + ": refusing to write there: it is the input " + in.string() + " of this command");
  // The same file under another name (a hard link) is still the input.
  fs::create_hard_link(in, t.p / "alias.json");
  CHECK(has(refusal([&] { check_output_file("", t.p / "alias.json", true, {in.string()}); }),
            "it is the input " + in.string()));
  CHECK(refusal([&] { check_output_file("--out", "", true); }) == "--out: an empty path");
  CHECK(slurp(in) == "{}");
}

TEST_CASE("atomic write: output names and paths", "[app][atomic-write]") {
  auto name = [](const std::string& n) { return refusal([&] { check_output_name("--name", n); }); };
  CHECK(name("nightly").empty());
  CHECK(name("run-2026_12.v2").empty());
  CHECK(has(name(""), "an empty name"));
  CHECK(has(name("."), "are not names"));
  CHECK(has(name(".."), "are not names"));
  CHECK(has(name("a/b"), "path separator"));
  CHECK(has(name("a\\b"), "path separator"));
  CHECK(has(name(".hidden"), "may not start with '.'"));
  CHECK(has(name("tab\there"), "control characters"));
  CHECK(has(name(std::string("del") + char(0x7f)), "control characters"));
  CHECK(has(name(std::string(201, 'n')), "longer than 200 characters"));
  CHECK(name(std::string(200, 'n')).empty());
  CHECK(has(name(std::string(201, 'n')), std::string(80, 'n') + "...:"));  // long names shown cut
  auto path = [](const std::string& p) { return refusal([&] { check_output_path("--out", p); }); };
  CHECK(path("reports/nightly").empty());
  CHECK(path("/tmp/x.json").empty());
  CHECK(path("./x").empty());
  CHECK(has(path(""), "an empty path"));
  CHECK(has(path("a/../b"), "\"..\" is not allowed"));
  CHECK(has(path(".."), "\"..\" is not allowed"));
  CHECK(has(path("/"), "must be a named file or folder"));
  CHECK(has(path("."), "must be a named file or folder"));
  CHECK(has(path("reports/"), "must be a named file or folder"));
}

TEST_CASE("atomic write: output folders are replaced only when they are ours", "[app][atomic-write]") {
  Tmp t("folders");
  const std::string marker = ".eccd-test-output";
  auto partial = [&](const std::string& content) {
    const fs::path p = t.p / "partial";
    fs::remove_all(p);
    fs::create_directories(p);
    spit(p / marker, "test");
    spit(p / "result.txt", content);
    return p;
  };
  const fs::path out = t.p / "out";
  // Missing: moved into place.
  replace_output_folder(partial("one"), out, marker);
  CHECK(slurp(out / "result.txt") == "one");
  CHECK_FALSE(fs::exists(t.p / "partial"));
  CHECK(has_marker(out, marker));
  // Ours: swapped, the old one removed.
  spit(out / "stale.txt", "old run");
  replace_output_folder(partial("two"), out, marker);
  CHECK(slurp(out / "result.txt") == "two");
  CHECK_FALSE(fs::exists(out / "stale.txt"));
  CHECK_FALSE(fs::exists(t.p / "partial"));
  // Not ours: refused, both left as they are.
  const fs::path theirs = t.p / "theirs";
  fs::create_directories(theirs);
  spit(theirs / "thesis.tex", "precious");
  const fs::path p3 = partial("three");
  CHECK(has(refusal([&] { replace_output_folder(p3, theirs, marker); }),
            "was not written by this command (no " + marker));
  CHECK(slurp(theirs / "thesis.tex") == "precious");
  CHECK(slurp(p3 / "result.txt") == "three");
  CHECK_FALSE(refusal([&] { check_replaceable(theirs, marker); }).empty());
  CHECK_FALSE(refusal([&] { remove_our_folder(theirs, marker); }).empty());
  CHECK(fs::exists(theirs / "thesis.tex"));
  // ... unless the caller's test accepts it.
  auto accept = [](const fs::path& d) { return fs::exists(d / "thesis.tex"); };
  CHECK_NOTHROW(check_replaceable(theirs, marker, accept));
  // A symbolic link to a folder of ours, and a regular file, are refused.
  fs::create_directory_symlink(out, t.p / "link");
  CHECK_FALSE(has_marker(t.p / "link", marker));
  CHECK_FALSE(refusal([&] { replace_output_folder(p3, t.p / "link", marker); }).empty());
  CHECK(slurp(out / "result.txt") == "two");
  spit(t.p / "file", "x");
  CHECK_FALSE(refusal([&] { check_replaceable(t.p / "file", marker); }).empty());
  // remove_our_folder: a missing folder is nothing to do; ours is removed.
  CHECK_NOTHROW(remove_our_folder(t.p / "absent", marker));
  remove_our_folder(out, marker);
  CHECK_FALSE(fs::exists(out));
  CHECK(slurp(p3 / "result.txt") == "three");
}

}  // namespace ECCD_UNITY_ID
