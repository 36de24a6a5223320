#pragma once
// UTF-8 text for JSON: any byte string made into valid UTF-8 before it reaches
// a JSON document, with the bytes that were not UTF-8 still visible.
//
// Statement. JSON text is Unicode (RFC 8259, section 8.1: UTF-8), and the
// JSON library (nlohmann::json) throws type_error 316 when it is asked to
// write a string that is not valid UTF-8. Text that comes from outside can be
// anything: a file name (a POSIX path is bytes), a scene file's bytes quoted
// in an error message, the text of a shell argument. escape_invalid_utf8
// keeps every well-formed UTF-8 sequence (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF) and writes every other byte as the four
// characters \xNN (NN its value in upper-case hexadecimal), so that a person
// can still tell which byte it was; a backslash in the input is kept as it is.
// utf8_for_json does the same and says so: it appends the note
// kInvalidUtf8Note when it changed anything. Where a whole document is written
// (the commands' --json output), json dumps use
// nlohmann's error_handler_t::replace as well (U+FFFD for a bad byte) as the
// last line of defence.
// No paper section. Requirements: none.
#include <string>
#include <string_view>

namespace eccd {

inline constexpr const char* kInvalidUtf8Note = " (bytes that are not UTF-8 are shown as \\xNN)";

// The length of the well-formed UTF-8 sequence starting at s[i], or 0.
inline std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF)
    n = 2;
  else if (c == 0xE0) {
    n = 3;
    lo = 0xA0;
  } else if (c >= 0xE1 && c <= 0xEC)
    n = 3;
  else if (c == 0xED) {
    n = 3;
    hi = 0x9F;
  }  // no surrogates
  else if (c >= 0xEE && c <= 0xEF)
    n = 3;
  else if (c == 0xF0) {
    n = 4;
    lo = 0x90;
  } else if (c >= 0xF1 && c <= 0xF3)
    n = 4;
  else if (c == 0xF4) {
    n = 4;
    hi = 0x8F;
  }  // nothing above U+10FFFF
  else
    return 0;
  if (i + n > s.size()) return 0;
  if (b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  return n;
}

inline bool valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    std::size_t n = utf8_sequence_length(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

// s with every byte that does not start a well-formed sequence written as \xNN.
inline std::string escape_invalid_utf8(std::string_view s) {
  static const char hex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    std::size_t n = utf8_sequence_length(s, i);
    if (n == 0) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
      ++i;
    } else {
      out.append(s.substr(i, n));
      i += n;
    }
  }
  return out;
}

// s itself if it is valid UTF-8; else escaped, with the note that says so.
inline std::string utf8_for_json(std::string_view s) {
  if (valid_utf8(s)) return std::string(s);
  return escape_invalid_utf8(s) + kInvalidUtf8Note;
}

}  // namespace eccd
