#pragma once
// Strict JSON for the certificate checker: one parse that keeps what a
// checker must not lose, written for certificate/check/ alone.
//
// Statement. nlohmann's DOM parser silently keeps one of two equal keys and
// rounds integers beyond 64 bits to doubles. This SAX handler builds the same
// DOM but
//   - records the first duplicate key, or nesting deeper than 64 levels, with
//     its JSON place (e.g. /timeline/3/instant): a structure problem the
//     caller reports (a certificate with one is REJECTED, a scene unreadable);
//   - keeps an integer too large for 64 bits as the string of its digits
//     (exact, and equal to the same integer written as a string);
//   - keeps a number with a fraction part or exponent as a string that no
//     exact-number reader accepts ("json-float:" and its text), so that a
//     rounded 1.8 can never pass as 9/5.
// Malformed JSON throws JsonTextError "LABEL: byte N: ...".
// Requirements: nlohmann json 3.11 (its SAX interface).
#include <nlohmann/json.hpp>

#include <cctype>
#include <cstddef>
#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd::check {

struct JsonTextError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct StrictDocument {
  nlohmann::json value;
  std::string structure_problem;  // "" or "PLACE: what"
};

namespace strict_json_impl {
class Builder {
 public:
  using json = nlohmann::json;
  explicit Builder(json& root) : root_(root) {}
  std::string problem;

  bool null() { return put(json(nullptr)); }
  bool boolean(bool b) { return put(json(b)); }
  bool number_integer(json::number_integer_t v) { return put(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return put(json(v)); }
  bool number_float(json::number_float_t, const std::string& text) {
    bool digits = !text.empty();
    for (std::size_t i = 0; i < text.size(); ++i)
      if (!(std::isdigit(static_cast<unsigned char>(text[i])) || (i == 0 && text[i] == '-' && text.size() > 1)))
        digits = false;
    return put(json(digits ? text : "json-float:" + text));
  }
  bool string(std::string& s) { return put(json(s)); }
  bool binary(json::binary_t&) { return put(json(nullptr)); }
  bool start_object(std::size_t) {
    if (!open(json::object())) return false;
    keys_.emplace_back();
    return true;
  }
  bool key(std::string& k) {
    json& obj = *stack_.back();
    if (obj.contains(k) && problem.empty()) problem = place() + "/" + k + ": duplicate key \"" + k + "\"";
    key_ = k;
    have_key_ = true;
    return true;
  }
  bool end_object() {
    stack_.pop_back();
    path_.pop_back();
    keys_.pop_back();
    return true;
  }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_array() {
    stack_.pop_back();
    path_.pop_back();
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    error_ = "byte " + std::to_string(position) + ": " + ex.what();
    return false;
  }
  const std::string& error() const { return error_; }

 private:
  json& root_;
  std::vector<json*> stack_;
  std::deque<json> discarded_;  // the values of duplicate keys after the first
  std::vector<std::string> path_;
  std::vector<int> keys_;
  std::string key_, error_;
  bool have_key_ = false, started_ = false;

  std::string place() const {
    std::string p;
    for (const auto& s : path_) p += s;
    return p.empty() ? "top level" : p;
  }
  json* insert(json v, std::string& where) {
    if (!started_) {
      started_ = true;
      root_ = std::move(v);
      where = "";
      return &root_;
    }
    json& parent = *stack_.back();
    if (parent.is_array()) {
      where = "/" + std::to_string(parent.size());
      parent.push_back(std::move(v));
      return &parent.back();
    }
    where = "/" + key_;
    have_key_ = false;
    if (parent.contains(key_)) {  // duplicate: keep the first (the problem is recorded); the second goes aside,
      discarded_.push_back(std::move(v));  // whatever its type, with its own members (a deque keeps their places)
      return &discarded_.back();
    }
    parent[key_] = std::move(v);
    return &parent[key_];
  }
  bool put(json v) {
    std::string where;
    insert(std::move(v), where);
    return true;
  }
  bool open(json v) {
    if (stack_.size() >= 64 && problem.empty()) problem = place() + ": nesting deeper than 64 levels";
    std::string where;
    json* p = insert(std::move(v), where);
    stack_.push_back(p);
    path_.push_back(where);
    return true;
  }
};
}  // namespace strict_json_impl

inline StrictDocument parse_strict(const std::string& text, const std::string& label) {
  StrictDocument d;
  strict_json_impl::Builder b(d.value);
  const bool ok = nlohmann::json::sax_parse(text, &b);
  if (!ok)
    throw JsonTextError(label + ": not valid JSON: " + (b.error().empty() ? std::string("parse error") : b.error()));
  d.structure_problem = b.problem;
  return d;
}

}  // namespace eccd::check
