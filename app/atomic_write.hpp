#pragma once
// Writing an output file so that a failure never leaves it half-written: the
// text goes to PATH.tmp, which is renamed to PATH only when complete.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace eccd {

inline void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream o(tmp, std::ios::binary);
    o << text;
    o.flush();
    if (!o) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace eccd
