// Message text for the strict JSON readers (see io/json_messages.hpp).
#include "io/json_messages.hpp"

#include "io/scene_reader.hpp"

#include <cstdio>

namespace eccd {

namespace json_messages {

using json = nlohmann::json;

std::string escape_token(const std::string& k) {
  std::string r;
  for (char ch : k) {
    if (ch == '~')
      r += "~0";
    else if (ch == '/')
      r += "~1";
    else
      r += ch;
  }
  return r;
}
std::string child(const std::string& ptr, const std::string& key) { return ptr + "/" + escape_token(key); }
std::string child(const std::string& ptr, std::size_t i) { return ptr + "/" + std::to_string(i); }
// A JSON pointer for a message: each token cut to 80 characters.
std::string place_text(const std::string& ptr) {
  if (ptr.empty()) return "top level";
  if (ptr.size() <= 200) return ptr;
  std::string r;
  std::size_t i = 0;
  while (i < ptr.size()) {
    std::size_t j = ptr.find('/', i + 1);
    if (j == std::string::npos) j = ptr.size();
    std::string tok = ptr.substr(i, j - i);
    r += tok.size() > 81 ? tok.substr(0, 81) + "..." : tok;
    i = j;
  }
  return r.size() > 2000 ? r.substr(0, 2000) + "..." : r;
}

// A message with each run of more than 40 digits shortened to its first 20
// and last 8 digits and the count (a 1000-digit number is not echoed whole).
std::string shorten_digits(const std::string& m) {
  std::string r;
  std::size_t i = 0;
  while (i < m.size()) {
    if (m[i] < '0' || m[i] > '9') {
      r += m[i++];
      continue;
    }
    std::size_t j = i;
    while (j < m.size() && m[j] >= '0' && m[j] <= '9') ++j;
    if (j - i > 40)
      r += m.substr(i, 20) + "...(" + std::to_string(j - i) + " digits)..." + m.substr(j - 8, 8);
    else
      r += m.substr(i, j - i);
    i = j;
  }
  return r;
}

// A user string in a message: JSON-quoted, shortened.
std::string quote(const std::string& s) {
  std::string t = s.size() > 80 ? s.substr(0, 80) + "..." : s;
  return json(t).dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string type_name(const json& j) {
  switch (j.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::string:
      return "a string";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
      return "an integer";
    case json::value_t::number_float:
      return "a number with a fraction part";
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array";
    default:
      return "an unexpected value";
  }
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string r;
  for (std::size_t i = 0; i < v.size(); ++i) r += (i ? sep : "") + v[i];
  return r;
}

// "line L, column C: reason" for an error the JSON parser reported at byte `pos`.
std::string json_error_text(const std::string& text, std::size_t pos, const std::string& what) {
  if (pos > text.size()) pos = text.size();
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < pos; ++i)
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  std::size_t column = pos - line_start;
  if (column == 0) column = 1;
  // Prefer the parser's own "at line L, column C" when its message has one.
  if (auto k = what.find(" at line "); k != std::string::npos) {
    unsigned long l = 0, c = 0;
    if (std::sscanf(what.c_str() + k, " at line %lu, column %lu", &l, &c) == 2) {
      line = l;
      column = c;
    }
  }
  std::string reason = what;
  if (auto k = reason.find("] "); k != std::string::npos && reason.rfind("[json.exception.", 0) == 0)
    reason = reason.substr(k + 2);
  if (reason.rfind("parse error", 0) == 0)
    if (auto k = reason.find(": "); k != std::string::npos) reason = reason.substr(k + 2);
  reason = shorten_digits(reason);
  if (reason.size() > 300) reason = reason.substr(0, 300) + "...";
  if (reason.find("number overflow") != std::string::npos)
    reason += " (write large numbers as strings, e.g. \"1e400\")";
  return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": malformed JSON: " + reason;
}

}  // namespace json_messages

std::string json_place(const std::string& pointer) { return json_messages::place_text(pointer); }
std::string json_quote(const std::string& text) { return json_messages::quote(text); }
std::string json_type_name(const nlohmann::json& j) { return json_messages::type_name(j); }

}  // namespace eccd
