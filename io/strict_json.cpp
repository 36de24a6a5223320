// Strict JSON parsing for every reader of eccd's formats (declared in
// io/scene_reader.hpp, choice 6 there): a SAX handler builds the DOM,
// refusing duplicate keys and nesting deeper than 64 levels, and keeps the raw
// text of every JSON number that is not an integer (so that the reader can
// say what was written, and refuse it at its place); empty files, NUL bytes
// and syntax errors become SceneError "FILE: line L, column C: malformed
// JSON: ...". Requirements: nlohmann json 3.11.
#include "io/json_messages.hpp"
#include "io/scene_reader.hpp"

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace eccd {

using json = nlohmann::json;

namespace {

using json_messages::escape_token;
using json_messages::json_error_text;
using json_messages::place_text;
using json_messages::quote;

constexpr std::size_t kMaxDepth = 64;

// SAX handler building the DOM, with duplicate-key detection, a depth limit,
// and the raw text of every JSON number that is not an integer.
class DomBuilder {
 public:
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  json root;
  std::unordered_map<std::string, std::string> float_text;  // pointer -> raw token
  std::string error_place, error_what;                      // our own error (duplicate key, depth)
  bool json_error = false;
  std::size_t error_byte = 0;
  std::string json_error_what;

  bool null() {
    put(json(nullptr));
    return true;
  }
  bool boolean(bool v) {
    put(json(v));
    return true;
  }
  bool number_integer(number_integer_t v) {
    put(json(v));
    return true;
  }
  bool number_unsigned(number_unsigned_t v) {
    put(json(v));
    return true;
  }
  bool number_float(number_float_t v, const string_t& s) {
    float_text[current_pointer()] = s;
    put(json(v));
    return true;
  }
  bool string(string_t& s) {
    put(json(std::move(s)));
    return true;
  }
  bool binary(binary_t& b) {
    put(json::binary(std::move(b)));
    return true;
  }
  bool start_object(std::size_t) { return open(json::object()); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_object() {
    close();
    return true;
  }
  bool end_array() {
    close();
    return true;
  }
  bool key(string_t& k) {
    if (stack_.back()->contains(k)) {
      error_place = pointer_of(tokens_.size()) + "/" + escape_token(k);
      error_what = "duplicate key " + quote(k) + " (each key may appear only once in an object)";
      return false;
    }
    keys_.back() = k;
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    json_error = true;
    error_byte = position;
    json_error_what = ex.what();
    return false;
  }

 private:
  std::vector<json*> stack_;
  std::vector<std::string> keys_;    // pending key per open container (objects)
  std::vector<std::string> tokens_;  // token of each open container in its parent

  std::string pointer_of(std::size_t n) const {
    std::string r;
    for (std::size_t i = 1; i < n; ++i) r += "/" + tokens_[i];
    return r;
  }
  std::string current_token() const {
    if (stack_.empty()) return "";
    const json& top = *stack_.back();
    return top.is_array() ? std::to_string(top.size()) : escape_token(keys_.back());
  }
  std::string current_pointer() const {
    if (stack_.empty()) return "";
    return pointer_of(tokens_.size()) + "/" + current_token();
  }
  json* put(json&& v) {
    if (stack_.empty()) {
      root = std::move(v);
      return &root;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(std::move(v));
      return &top.back();
    }
    json& slot = top[keys_.back()];
    slot = std::move(v);
    return &slot;
  }
  bool open(json&& v) {
    if (stack_.size() >= kMaxDepth) {
      error_place = current_pointer();
      error_what = "nesting deeper than " + std::to_string(kMaxDepth) + " levels";
      return false;
    }
    std::string tok = current_token();
    json* p = put(std::move(v));
    stack_.push_back(p);
    keys_.emplace_back();
    tokens_.push_back(std::move(tok));
    return true;
  }
  void close() {
    stack_.pop_back();
    keys_.pop_back();
    tokens_.pop_back();
  }
};

// One strict parse: the DOM with duplicate keys and over-deep nesting refused.
// Syntax errors always throw; structure errors (duplicate key, depth) throw
// unless `structure_error` is given, which then receives "PLACE: what".
void parse_dom(const std::string& json_text, const std::string& file_label, DomBuilder& b,
               std::string* structure_error) {
  if (json_text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw SceneError(file_label +
                     ": line 1, column 1: malformed JSON: the file is empty or blank (expected a JSON object)");
  if (auto nul = json_text.find('\0'); nul != std::string::npos) {
    std::size_t line = 1 + std::size_t(std::count(json_text.begin(), json_text.begin() + long(nul), '\n'));
    throw SceneError(file_label + ": line " + std::to_string(line) + ", byte " + std::to_string(nul + 1) +
                     ": malformed JSON: a NUL byte: this is a binary file, not a JSON text");
  }
  bool ok = false;
  try {
    ok = json::sax_parse(json_text, &b);
  } catch (const std::exception& e) {
    throw SceneError(file_label + ": " + json_error_text(json_text, json_text.size(), e.what()));
  }
  if (!b.error_what.empty()) {
    const std::string what = place_text(b.error_place) + ": " + b.error_what;
    if (!structure_error) throw SceneError(file_label + ": " + what);
    *structure_error = what;
    return;
  }
  if (b.json_error || !ok)
    throw SceneError(file_label + ": " + json_error_text(json_text, b.error_byte, b.json_error_what));
}

}  // namespace

nlohmann::json parse_json_document(const std::string& json_text, const std::string& file_label,
                                   std::string* structure_error) {
  DomBuilder b;
  parse_dom(json_text, file_label, b, structure_error);
  return structure_error && !structure_error->empty() ? json() : std::move(b.root);
}

StrictJson parse_strict_json(const std::string& json_text, const std::string& file_label) {
  if (json_text.size() > input_limits().max_file_bytes)
    throw SceneError(file_label + ": " + std::to_string(json_text.size()) + " bytes, beyond the input limit of " +
                     std::to_string(input_limits().max_file_bytes) + " bytes (--max-file-bytes)");
  DomBuilder b;
  parse_dom(json_text, file_label, b, nullptr);
  return StrictJson{std::move(b.root), std::move(b.float_text)};
}

}  // namespace eccd
