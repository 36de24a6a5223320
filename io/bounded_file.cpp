// Reading a file's bytes once, bounded (io/scene_reader.hpp, choice 14):
// opened without blocking, only a regular file (or "/dev/stdin", what a
// command's `-` reads) is read, and at most limit + 1 bytes of it, so a huge
// file or an endless stream is refused without being read whole. Every
// failure is a SceneError "PATH: ...".
#include "io/scene_reader.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace eccd {

std::string read_file_bytes(const std::string& path) {
  return read_bounded_file(path, input_limits().max_file_bytes, "the input limit", "--max-file-bytes");
}

std::string read_bounded_file(const std::string& path, std::size_t limit, const std::string& limit_text,
                              const std::string& option) {
  // Opened without blocking (a FIFO with no writer would wait for one), then
  // only a regular file is read; "/dev/stdin" (what `-` reads) may be a pipe or
  // a terminal and is read blocking, as the user asked.
  const bool stdin_path = path == "/dev/stdin";
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | (stdin_path ? 0 : O_NONBLOCK));
  if (fd < 0) throw SceneError(path + ": cannot read the file: " + std::strerror(errno));
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw SceneError(path + ": cannot read the file: " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw SceneError(path + ": cannot read the file: it is a directory");
  if (!stdin_path && !S_ISREG(st.st_mode)) {
    const char* what = S_ISFIFO(st.st_mode)   ? "a FIFO (named pipe)"
                       : S_ISCHR(st.st_mode)  ? "a character device"
                       : S_ISBLK(st.st_mode)  ? "a block device"
                       : S_ISSOCK(st.st_mode) ? "a socket"
                                              : "not a regular file";
    throw SceneError(path + ": cannot read the file: it is " + std::string(what) +
                     ", not a regular file (to read a stream, give - and pipe it to standard input)");
  }
  if (!stdin_path) {
    int fl = ::fcntl(fd, F_GETFL);
    if (fl >= 0) ::fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
  }
  // At most limit + 1 bytes are read: a huge file or a stream such as a pipe
  // from /dev/zero is refused without reading it whole.
  const std::string too_large = path + ": larger than " + limit_text + " of " + std::to_string(limit) + " bytes" +
                                (option.empty() ? "" : " (" + option + ")");
  if (S_ISREG(st.st_mode) && std::uint64_t(st.st_size) > limit) throw SceneError(too_large);
  std::string text;
  std::vector<char> buf(1 << 16);
  while (text.size() <= limit) {
    ssize_t n = ::read(fd, buf.data(), buf.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw SceneError(path + ": cannot read the file: " + std::strerror(errno));
    }
    if (n == 0) break;
    text.append(buf.data(), std::size_t(n));
  }
  if (text.size() > limit) throw SceneError(too_large);
  return text;
}

}  // namespace eccd
