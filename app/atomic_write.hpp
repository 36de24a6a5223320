#pragma once
// Output files and folders that a failure never leaves half-written, and that
// never replace anything the command did not write itself.
//
//  - write_text_atomically(PATH, text): the text goes to a fresh temporary
//    sibling PATH.tmp-XXXXXX (created exclusively, so a user's file of that
//    name is never touched), which is renamed onto PATH only when complete; on
//    any failure the temporary is removed and OutputError names PATH and the
//    operating system's reason. PATH must be a new name or a regular file
//    (never a directory, device, FIFO, socket or symbolic link: those are
//    refused, never replaced). While the temporary exists, SIGXFSZ (a file
//    size limit) is ignored, so the write fails with EFBIG and is cleaned up
//    like any other failure, and SIGINT, SIGTERM, SIGHUP and SIGQUIT remove it
//    before the process ends (a handler of the program's own, e.g. report's,
//    is called instead, and the write then ends normally);
//    remove_pending_output() does the same for other signal handlers (the
//    time limit's backstop).
//  - check_output_file(OPTION, PATH, force, inputs): before any work, what a
//    command's output file may be: a new name, or (with --force) an existing
//    regular file that is none of the command's inputs (the same device and
//    inode); everything else is refused with OutputError saying what it is.
//  - check_output_name(NAME): a name that becomes one folder inside a chosen
//    folder (`report --name`): not empty, no path separator, not "." or "..",
//    no leading '.', printable characters only.
//  - check_output_path(PATH): a user-chosen output path: not empty, no ".."
//    component, and its last component is a real name (not "/", ".", "..").
//  - Output folders written by a command carry a marker file (MARKER, holding
//    the command's name); replace_output_folder(partial, out, marker) replaces
//    OUT by PARTIAL only if OUT is missing or carries that marker (or the
//    caller's `written_by_us` test accepts it), and swaps the two atomically
//    (renameat2 RENAME_EXCHANGE) before removing the old folder.
// OutputError is a bad-output-path error: exit code 2 at the command line.
// No paper section. Requirements: Linux (renameat2, mkstemp).
#include <fcntl.h>
#include <sys/stat.h>
#include <stdio.h>
#include <unistd.h>

#include <csignal>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

// A path the command cannot write, or may not replace: exit 2 (bad input).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline std::string errno_text(int e) { return std::strerror(e); }

// What a file system entry is, in words ("a directory", "a FIFO", ...).
inline std::string file_type_text(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISSOCK(m)) return "a socket";
  if (S_ISLNK(m)) return "a symbolic link";
  if (S_ISREG(m)) return "a regular file";
  return "not a regular file";
}

// "" if PATH is missing or a regular file (not a symbolic link); else why it may not be an output.
inline std::string not_a_plain_output(const std::filesystem::path& path) {
  struct stat ls {};
  if (::lstat(path.c_str(), &ls) != 0) return "";
  if (S_ISREG(ls.st_mode)) return "";
  if (S_ISLNK(ls.st_mode)) {
    struct stat ts {};
    std::string to = ::stat(path.c_str(), &ts) == 0 ? " to " + file_type_text(ts.st_mode) : " (dangling)";
    return "it is a symbolic link" + to +
           "; an output is written only to a new name or a regular file (give the target's own path)";
  }
  return "it is " + file_type_text(ls.st_mode) + ", not a regular file";
}

inline void check_output_file(const std::string& option, const std::filesystem::path& path, bool force,
                              const std::vector<std::string>& inputs = {}) {
  const std::string shown = (option.empty() ? "" : option + " ") + path.string();
  if (path.empty()) throw OutputError(option + ": an empty path");
  if (std::string why = not_a_plain_output(path); !why.empty())
    throw OutputError(shown + ": refusing to write there: " + why);
  struct stat os {};
  if (::stat(path.c_str(), &os) != 0) return;  // a new name
  for (const auto& in : inputs) {
    struct stat is {};
    if (in.empty() || in == "-" || ::stat(in.c_str(), &is) != 0) continue;
    if (is.st_dev == os.st_dev && is.st_ino == os.st_ino)
      throw OutputError(shown + ": refusing to write there: it is the input " + in + " of this command");
  }
  if (!force) throw OutputError(shown + ": exists; refusing to replace it (give --force to replace it)");
}

namespace detail {
// The temporary being written, for the signal handlers (async-signal-safe: a fixed buffer).
inline char g_pending_tmp[4096];
inline volatile sig_atomic_t g_pending = 0;
inline struct sigaction g_old_actions[65];
inline constexpr int kCleanSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
inline void on_signal_while_writing(int sig) {
  const struct sigaction& old = g_old_actions[sig];
  if (old.sa_handler != SIG_DFL && old.sa_handler != SIG_IGN) {  // the program's own handler decides
    if (old.sa_flags & SA_SIGINFO) return;
    old.sa_handler(sig);
    return;
  }
  if (old.sa_handler == SIG_IGN) return;
  if (g_pending) ::unlink(g_pending_tmp);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}
// Registers `tmp` and the handlers for the lifetime of the guard.
class PendingOutput {
 public:
  explicit PendingOutput(const std::string& tmp) {
    if (tmp.size() >= sizeof g_pending_tmp) return;
    std::memcpy(g_pending_tmp, tmp.c_str(), tmp.size() + 1);
    g_pending = 1;
    struct sigaction sa {};
    sa.sa_handler = on_signal_while_writing;
    sigemptyset(&sa.sa_mask);
    for (int sig : kCleanSignals) ::sigaction(sig, &sa, &g_old_actions[sig]);
    struct sigaction ign {};
    ign.sa_handler = SIG_IGN;
    sigemptyset(&ign.sa_mask);
    ::sigaction(SIGXFSZ, &ign, &old_xfsz_);
    active_ = true;
  }
  ~PendingOutput() {
    if (!active_) return;
    for (int sig : kCleanSignals) ::sigaction(sig, &g_old_actions[sig], nullptr);
    ::sigaction(SIGXFSZ, &old_xfsz_, nullptr);
    g_pending = 0;
  }
  PendingOutput(const PendingOutput&) = delete;
  PendingOutput& operator=(const PendingOutput&) = delete;

 private:
  struct sigaction old_xfsz_ {};
  bool active_ = false;
};
}  // namespace detail

// Removes the temporary of a write in progress (async-signal-safe; for handlers that end the process).
inline void remove_pending_output() {
  if (detail::g_pending) ::unlink(detail::g_pending_tmp);
}

inline void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
  namespace fs = std::filesystem;
  if (path.empty()) throw OutputError("empty output path");
  if (std::string why = not_a_plain_output(path); !why.empty())
    throw OutputError(path.string() + ": cannot write the file: " + why);
  std::string tmpl = path.string() + ".tmp-XXXXXX";
  int fd = mkstemp(tmpl.data());
  if (fd < 0) throw OutputError(path.string() + ": cannot write the file: " + errno_text(errno));
  detail::PendingOutput pending(tmpl);
  auto fail = [&](int e) {
    ::close(fd);
    ::unlink(tmpl.c_str());
    throw OutputError(path.string() + ": cannot write the file: " + errno_text(e));
  };
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(errno);
    }
    p += n;
    left -= std::size_t(n);
  }
  {  // mkstemp gives 0600: keep the mode of the file replaced, or the usual 0666 & ~umask
    struct stat st {};
    mode_t mode;
    if (::stat(path.c_str(), &st) == 0) {
      mode = st.st_mode & 07777;
    } else {
      mode_t u = ::umask(0);
      ::umask(u);
      mode = 0666 & ~u;
    }
    if (::fchmod(fd, mode) != 0) fail(errno);
  }
  if (::fsync(fd) != 0 && errno != EINVAL) fail(errno);
  if (::close(fd) != 0) {
    int e = errno;
    ::unlink(tmpl.c_str());
    throw OutputError(path.string() + ": cannot write the file: " + errno_text(e));
  }
  if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
    int e = errno;
    ::unlink(tmpl.c_str());
    throw OutputError(path.string() + ": cannot write the file: " + errno_text(e));
  }
}

// A name for one folder inside a chosen folder (e.g. reports/NAME).
inline void check_output_name(const std::string& option, const std::string& name) {
  auto bad = [&](const std::string& why) {
    throw OutputError(option + " " + (name.size() > 80 ? name.substr(0, 80) + "..." : name) + ": " + why);
  };
  if (name.empty()) bad("an empty name (give a folder name such as \"nightly\")");
  if (name.size() > 200) bad("longer than 200 characters");
  if (name == "." || name == "..") bad("\".\" and \"..\" are not names");
  if (name.find('/') != std::string::npos || name.find('\\') != std::string::npos)
    bad("a name may not contain a path separator ('/' or '\\'); use --out for a path");
  if (name[0] == '.') bad("a name may not start with '.'");
  for (unsigned char c : name)
    if (c < 0x20 || c == 0x7f) bad("a name may not contain control characters");
}

// A user-chosen output path (file or folder).
inline void check_output_path(const std::string& option, const std::string& path) {
  auto shown = path.size() > 200 ? path.substr(0, 200) + "..." : path;
  if (path.empty()) throw OutputError(option + ": an empty path");
  std::filesystem::path p(path);
  for (const auto& part : p)
    if (part == "..") throw OutputError(option + " " + shown + ": \"..\" is not allowed in an output path");
  auto last = p.lexically_normal().filename();
  if (last.empty() || last == "." || last == "..")
    throw OutputError(option + " " + shown +
                      ": the output must be a named file or folder (not \"/\", \".\" or a path ending in '/')");
}

// Does folder `dir` carry the marker file `marker` (written by the command that made it)?
inline bool has_marker(const std::filesystem::path& dir, const std::string& marker) {
  std::error_code ec;
  return std::filesystem::is_regular_file(dir / marker, ec) && !std::filesystem::is_symlink(dir, ec);
}

// Removes a leftover folder of ours (PATH missing: nothing to do); refuses anything else.
inline void remove_our_folder(const std::filesystem::path& dir, const std::string& marker,
                              const std::function<bool(const std::filesystem::path&)>& written_by_us = {}) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(dir, ec))) return;
  if (fs::is_symlink(dir, ec) || !fs::is_directory(dir, ec) ||
      !(has_marker(dir, marker) || (written_by_us && written_by_us(dir))))
    throw OutputError(dir.string() + ": exists and was not written by this command (no " + marker +
                      " marker): refusing to replace it; remove it yourself or choose another name");
  fs::remove_all(dir, ec);
  if (ec) throw OutputError(dir.string() + ": cannot remove the old folder: " + ec.message());
}

// Checks, before any work, that `out` may be replaced later (missing, or ours).
inline void check_replaceable(const std::filesystem::path& out, const std::string& marker,
                              const std::function<bool(const std::filesystem::path&)>& written_by_us = {}) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(out, ec))) return;
  if (fs::is_symlink(out, ec) || !fs::is_directory(out, ec) ||
      !(has_marker(out, marker) || (written_by_us && written_by_us(out))))
    throw OutputError(out.string() + ": exists and was not written by this command (no " + marker +
                      " marker): refusing to replace it; remove it yourself or choose another name");
}

// Puts the finished folder `partial` at `out`, replacing an old `out` of ours atomically.
inline void replace_output_folder(const std::filesystem::path& partial, const std::filesystem::path& out,
                                  const std::string& marker,
                                  const std::function<bool(const std::filesystem::path&)>& written_by_us = {}) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(out, ec))) {
    if (std::rename(partial.c_str(), out.c_str()) != 0)
      throw OutputError(out.string() + ": cannot move the finished output into place: " + errno_text(errno) +
                        " (it is in " + partial.string() + ")");
    return;
  }
  check_replaceable(out, marker, written_by_us);
  if (::renameat2(AT_FDCWD, partial.c_str(), AT_FDCWD, out.c_str(), RENAME_EXCHANGE) != 0)
    throw OutputError(out.string() + ": cannot replace it: " + errno_text(errno) + " (the new output is in " +
                      partial.string() + ")");
  fs::remove_all(partial, ec);  // now the old output
  if (ec) throw OutputError(partial.string() + ": cannot remove the replaced output: " + ec.message());
}

}  // namespace eccd
