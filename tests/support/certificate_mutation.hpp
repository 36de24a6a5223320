#pragma once
// Test support for the certificate mutation campaigns
// (tests/certificate/test_mutation_campaign*.cpp): what a mutant is, where in
// a certificate's JSON a mutation can land (every JSON pointer whose value a
// predicate picks), and which values are rational numbers written as text
// ("-3/4", "12"), the values an "integer changed by one" mutation edits.
// The campaigns differ in their bases and their mutations; these pieces are
// the same for all of them.
#include <nlohmann/json.hpp>

#include <cctype>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace eccd::test {

// One mutated certificate: what was changed, the certificate's text and the
// scene text it is checked against (a swapped scene changes the latter).
struct Mutant {
  std::string what, text, scene_text;
  bool may_stay_valid = false;  // the answer and scene are unchanged: a VALID verdict is allowed
};

// Every path (JSON pointer) below `at` to a value for which pick(value) holds.
inline void collect(const nlohmann::json& j, const nlohmann::json::json_pointer& at,
                    const std::function<bool(const nlohmann::json&)>& pick,
                    std::vector<nlohmann::json::json_pointer>& out) {
  if (pick(j)) out.push_back(at);
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) collect(it.value(), at / it.key(), pick, out);
  else if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i) collect(j[i], at / i, pick, out);
}

// A string that reads as a rational: an optional '-', digits, at most one '/'
// with digits on both sides (at most 4000 characters).
inline bool is_rational_text(const nlohmann::json& j) {
  if (!j.is_string()) return false;
  const std::string& s = j.get_ref<const std::string&>();
  if (s.empty() || s.size() > 4000) return false;
  std::size_t slash = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '/') {
      if (slash || i == 0) return false;
      slash = i;
      continue;
    }
    if (!(std::isdigit(static_cast<unsigned char>(s[i])) || (i == 0 && s[i] == '-'))) return false;
  }
  return true;
}

}  // namespace eccd::test
