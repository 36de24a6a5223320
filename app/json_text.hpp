#pragma once
// Scene files as people read them: indented JSON with each polynomial (array
// of number strings) and each instant object on one line.
#include <regex>
#include <string>

namespace eccd {

// Indented JSON with each polynomial (array of number strings) and each
// instant object on one line, so that scene files stay readable.
inline std::string compact_json(const std::string& text) {
  static const std::regex strings_array(R"(\[\s*("[^"]*"(?:,\s*"[^"]*")*)\s*\])");
  static const std::regex instant(R"(\{\s*("approx"[^{}\[\]]*?)\s*\})");
  static const std::regex spaces(R"(,\s+)");
  auto collapse = [](const std::string& in, const std::regex& re, const char* open, const char* close) {
    std::string out;
    auto it = std::sregex_iterator(in.begin(), in.end(), re);
    std::size_t last = 0;
    for (; it != std::sregex_iterator(); ++it) {
      out.append(in, last, it->position() - last);
      out += open + std::regex_replace(it->str(1), spaces, ", ") + close;
      last = it->position() + it->length();
    }
    out.append(in, last, std::string::npos);
    return out;
  };
  std::string s = collapse(text, strings_array, "[", "]");
  return collapse(s, instant, "{", "}");
}

}  // namespace eccd
