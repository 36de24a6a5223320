#pragma once
// Scene files as people read them: indented JSON (one space per level) with
// each polynomial (an array of strings or numbers only) and each instant
// object ({"approx": ..., "lo": ..., "hi": ...}) on one line. The JSON library
// formats every value (strings, numbers); this only chooses the line breaks,
// walking the document (no regular expressions: a regex over
// a 30 000-digit number overflows the stack). The output parses back to the
// same document. Requirements: nlohmann::ordered_json (key order kept).
#include <nlohmann/json.hpp>

#include <string>

namespace eccd {

namespace detail {

inline std::string json_scalar(const nlohmann::ordered_json& j) {
  return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

inline bool one_line(const nlohmann::ordered_json& j) {
  if (j.is_array()) {
    if (j.empty()) return true;
    for (const auto& x : j)
      if (!x.is_string() && !x.is_number()) return false;
    return true;
  }
  if (j.is_object()) {
    if (j.empty()) return true;
    if (j.begin().key() != "approx") return false;
    for (const auto& x : j)
      if (x.is_structured()) return false;
    return true;
  }
  return true;
}

inline void write_json(const nlohmann::ordered_json& j, int depth, std::string& out) {
  if (!j.is_structured()) {
    out += json_scalar(j);
    return;
  }
  const bool arr = j.is_array();
  if (one_line(j)) {
    out += arr ? '[' : '{';
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!first) out += ", ";
      first = false;
      if (!arr) out += json_scalar(it.key()) + ": ";
      out += json_scalar(*it);
    }
    out += arr ? ']' : '}';
    return;
  }
  out += arr ? "[\n" : "{\n";
  bool first = true;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out.append(std::size_t(depth + 1), ' ');
    if (!arr) out += json_scalar(it.key()) + ": ";
    write_json(*it, depth + 1, out);
  }
  out += '\n';
  out.append(std::size_t(depth), ' ');
  out += arr ? ']' : '}';
}

}  // namespace detail

// The document as text (no trailing newline).
inline std::string compact_json(const nlohmann::ordered_json& doc) {
  std::string out;
  detail::write_json(doc, 0, out);
  return out;
}

}  // namespace eccd
