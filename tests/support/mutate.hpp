#pragma once
// Test support: seeded mutations of JSON texts for the fuzz tests
// (tests/fuzz/*.cpp, issue 15). Each call to mutate() applies one to three of:
// byte flips, truncation, splicing (a piece of another corpus text), digit
// blow-up (a run of digits repeated up to max_blowup times), duplicate keys
// (a key of the text inserted again in an object), huge numbers ("1e9999",
// thousands of digits, "1/0"), deep nesting ([[[...]]] a thousand levels),
// and structural changes through the JSON library (a random value replaced by
// null, "", [], {}, a huge integer, a string, or deleted). Everything derives
// from one std::mt19937_64, so a seed reproduces a run.
//
// Fuzz settings from the environment: ECCD_FUZZ_SEED (default: random, always
// printed), ECCD_FUZZ_SECONDS (default 10 per fuzz test).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <iterator>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace eccd::test {

inline std::uint64_t fuzz_seed() {
  if (const char* s = std::getenv("ECCD_FUZZ_SEED")) return std::strtoull(s, nullptr, 10);
  return (std::uint64_t(std::random_device{}()) << 32) ^ std::uint64_t(std::random_device{}());
}
inline double fuzz_seconds() {
  if (const char* s = std::getenv("ECCD_FUZZ_SECONDS")) return std::strtod(s, nullptr);
  return 10;
}

class Mutator {
 public:
  Mutator(std::uint64_t seed, std::vector<std::string> corpus, std::size_t max_blowup = 5000)
      : rng_(seed), corpus_(std::move(corpus)), max_blowup_(max_blowup) {}

  std::size_t pick(std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
  const std::string& any_corpus() { return corpus_[pick(corpus_.size())]; }

  // A mutant that stays JSON (for readers behind a JSON parser, e.g. the
  // certificate checker): values replaced, deleted, duplicated or made huge.
  std::string mutate_value(std::string text, std::string& how) {
    how.clear();
    int rounds = 1 + int(pick(3));
    for (int r = 0; r < rounds; ++r) {
      switch (pick(3)) {
        case 0:
          huge_number(text, how);
          break;
        default:
          structural(text, how);
          break;
      }
    }
    return text;
  }

  // One mutant of `text` and a short description of what was done (for failure messages).
  std::string mutate(std::string text, std::string& how) {
    how.clear();
    int rounds = 1 + int(pick(3));
    for (int r = 0; r < rounds; ++r) {
      switch (pick(9)) {
        case 0:
          flip(text, how);
          break;
        case 1:
          truncate(text, how);
          break;
        case 2:
          splice(text, how);
          break;
        case 3:
          blowup(text, how);
          break;
        case 4:
          duplicate_key(text, how);
          break;
        case 5:
          huge_number(text, how);
          break;
        case 6:
          deep_nesting(text, how);
          break;
        default:
          structural(text, how);
          break;
      }
    }
    return text;
  }

 private:
  std::mt19937_64 rng_;
  std::vector<std::string> corpus_;
  std::size_t max_blowup_;

  void flip(std::string& t, std::string& how) {
    if (t.empty()) return;
    int n = 1 + int(pick(4));
    for (int i = 0; i < n; ++i) {
      std::size_t at = pick(t.size());
      static const char interesting[] = "{}[],:\"\\0-./eE \x01\xff";
      t[at] = pick(2) ? interesting[pick(sizeof interesting - 1)] : char(pick(256));
    }
    how += "flip;";
  }
  void truncate(std::string& t, std::string& how) {
    t.resize(pick(t.size() + 1));
    how += "truncate;";
  }
  void splice(std::string& t, std::string& how) {
    const std::string& o = any_corpus();
    if (o.empty() || t.empty()) return;
    std::size_t a = pick(o.size()), len = 1 + pick(std::min<std::size_t>(o.size() - a, 400));
    std::size_t at = pick(t.size()), cut = pick(std::min<std::size_t>(t.size() - at, 400) + 1);
    t.replace(at, cut, o.substr(a, len));
    how += "splice;";
  }
  void blowup(std::string& t, std::string& how) {
    std::vector<std::size_t> digits;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= '0' && t[i] <= '9') digits.push_back(i);
    if (digits.empty()) return;
    std::size_t at = digits[pick(digits.size())];
    std::size_t k = 1 + pick(max_blowup_);
    t.insert(at, std::string(k, t[at]));
    how += "blowup(" + std::to_string(k) + ");";
  }
  void duplicate_key(std::string& t, std::string& how) {
    // keys: "name" followed by optional spaces and ':'
    std::vector<std::pair<std::size_t, std::size_t>> keys;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] != '"') continue;
      std::size_t j = t.find('"', i + 1);
      if (j == std::string::npos) break;
      std::size_t k = j + 1;
      while (k < t.size() && t[k] == ' ') ++k;
      if (k < t.size() && t[k] == ':') keys.push_back({i, j + 1 - i});
      i = j;
    }
    std::vector<std::size_t> opens;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] == '{') opens.push_back(i);
    if (keys.empty() || opens.empty()) return;
    auto [ks, kl] = keys[pick(keys.size())];
    std::string key = t.substr(ks, kl);
    std::size_t at = opens[pick(opens.size())] + 1;
    static const char* values[] = {"1", "\"0\"", "null", "[]", "{}", "\"x\"", "true"};
    t.insert(at, key + ": " + values[pick(7)] + ", ");
    how += "dupkey(" + key.substr(0, 20) + ");";
  }
  void huge_number(std::string& t, std::string& how) {
    // replace a quoted number-looking string by a huge or odd one
    std::vector<std::pair<std::size_t, std::size_t>> strs;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] != '"') continue;
      std::size_t j = t.find('"', i + 1);
      if (j == std::string::npos) break;
      if (j > i + 1 && (std::isdigit(static_cast<unsigned char>(t[i + 1])) || t[i + 1] == '-'))
        strs.push_back({i, j + 1 - i});
      i = j;
    }
    static const std::vector<std::string> odd = {"\"1e9999\"",
                                                 "\"-1e-9999\"",
                                                 "\"1/0\"",
                                                 "\"1e100000\"",
                                                 "\"0/0\"",
                                                 "\"-0\"",
                                                 "\"1e-10000\"",
                                                 "\"4294967296\"",
                                                 "\"18446744073709551617\"",
                                                 "99999999999999999999999999",
                                                 "-1",
                                                 "1.5e308",
                                                 "\"nan\"",
                                                 "\"inf\""};
    std::string rep = pick(3) == 0 ? "\"" + std::string(1 + pick(max_blowup_), char('1' + pick(9))) + "/" +
                                         std::string(1 + pick(max_blowup_), char('1' + pick(9))) + "\""
                                   : odd[pick(odd.size())];
    if (strs.empty()) return;
    auto [s, l] = strs[pick(strs.size())];
    t.replace(s, l, rep);
    how += "huge(" + rep.substr(0, 20) + ");";
  }
  void deep_nesting(std::string& t, std::string& how) {
    std::size_t depth = 1 + pick(2000);
    std::string v = pick(2) ? std::string(depth, '[') + std::string(depth, ']') : std::string(depth, '[');
    std::size_t colon = t.find(':', pick(t.size() + 1));
    if (colon == std::string::npos) colon = t.find(':');
    if (colon == std::string::npos) {
      t += v;
      return;
    }
    t.insert(colon + 1, v + (pick(2) ? "," : ""));
    how += "deep(" + std::to_string(depth) + ");";
  }
  void structural(std::string& t, std::string& how) {
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(t, nullptr, false);
    if (j.is_discarded()) return flip(t, how);
    std::vector<nlohmann::ordered_json*> nodes;
    collect(j, nodes);
    if (nodes.empty()) return;
    nlohmann::ordered_json& n = *nodes[pick(nodes.size())];
    switch (pick(9)) {
      case 8:  // a copy of another value of the document in its place (wrong type or wrong number)
        n = nlohmann::ordered_json(*nodes[pick(nodes.size())]);
        break;
      case 0:
        n = nullptr;
        break;
      case 1:
        n = "";
        break;
      case 2:
        n = nlohmann::ordered_json::array();
        break;
      case 3:
        n = nlohmann::ordered_json::object();
        break;
      case 4:
        n = std::uint64_t(1) << 63;
        break;
      case 5:
        n = "not a number";
        break;
      case 6:
        n = pick(2) ? nlohmann::ordered_json(-1) : nlohmann::ordered_json(4294967297ull);
        break;
      default:
        if (n.is_array() && !n.empty())
          n.erase(n.begin() + long(pick(n.size())));
        else if (n.is_object() && !n.empty())
          n.erase(std::next(n.begin(), long(pick(n.size()))));
        else if (n.is_array())
          n.push_back(n.is_array() ? nlohmann::ordered_json(1) : nlohmann::ordered_json());
        break;
    }
    t = j.dump(pick(2) ? 1 : -1);
    how += "structural;";
  }
  static void collect(nlohmann::ordered_json& j, std::vector<nlohmann::ordered_json*>& out) {
    out.push_back(&j);
    if (j.is_structured())
      for (auto& x : j) collect(x, out);
  }
};

}  // namespace eccd::test
