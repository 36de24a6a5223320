#pragma once
// The claims every kind of certificate shares, read and checked the same way
// by each of the checker's kinds (certificate/check/verdict.hpp): a rejection
// (the claim and why), the reading of the certificate's rationals, whole
// numbers, statuses and decimal approximations (each bounded in size), and
// the answer assembled from a checked timeline.
//
// Statement. A timeline is instant, cell, instant, ..., instant over [0, 1]
// (docs/certificate-format.md), each node a bracket [lo, hi] (a cell: its
// sample) with a proved status. The collision set is the union of the runs of
// nodes in collision (touching or overlapping); a touching cell between two
// touching instants is continuous touching (contact_intervals); a touching
// instant between cells that are not touching is a contact. answer_claim
// assembles these from the checked nodes and compare_answer requires the
// certificate's answer to be exactly that (collides, every bracket, the first
// contact), its approximations inside their brackets.
// Requirements: GMP; nlohmann json. N (answer_claim): lo, hi, cell, status, name.
#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace eccd::check {

using json = nlohmann::json;

struct Rejected {
  std::string claim, reason;
};
[[noreturn]] inline void reject(const std::string& claim, const std::string& reason) { throw Rejected{claim, reason}; }

inline const json& at(const json& j, const char* key, const std::string& place) {
  if (!j.is_object()) reject("certificate format", place + ": expected an object");
  if (!j.contains(key)) reject("certificate format", place + ": missing key \"" + key + "\"");
  return j.at(key);
}

inline std::string shown(const json& j) {
  std::string s = j.dump();
  return s.size() > 40 ? s.substr(0, 40) + "..." : s;
}

// A certificate rational "[-]digits" or "[-]digits/digits" of at most max_bits bits (checked on the text first).
inline mpq_class rational(const json& j, const std::string& place, std::size_t max_bits) {
  if (!j.is_string()) reject("certificate format", place + ": expected a rational \"p/q\", got " + shown(j));
  const std::string& s = j.get_ref<const std::string&>();
  const std::size_t max_chars = 2 * (max_bits * 30103 / 100000 + 2) + 2;
  if (s.size() > max_chars)
    reject("certificate format", place + ": a rational of more than " + std::to_string(max_bits) + " bits");
  std::size_t i = s.size() && s[0] == '-' ? 1 : 0;
  const std::size_t slash = s.find('/');
  auto digits = [&](std::size_t a, std::size_t b) {
    if (a >= b) return false;
    for (std::size_t k = a; k < b; ++k)
      if (!std::isdigit(static_cast<unsigned char>(s[k]))) return false;
    return true;
  };
  const bool ok = slash == std::string::npos ? digits(i, s.size()) : digits(i, slash) && digits(slash + 1, s.size());
  if (!ok) reject("certificate format", place + ": expected a rational \"p/q\", got " + shown(j));
  mpq_class q;
  if (slash == std::string::npos) {
    q = mpq_class(mpz_class(s, 10));
  } else {
    mpz_class n(s.substr(0, slash), 10), d(s.substr(slash + 1), 10);
    if (d == 0) reject("certificate format", place + ": zero denominator");
    q = mpq_class(n, d);
    q.canonicalize();
  }
  if (mpz_sizeinbase(q.get_num_mpz_t(), 2) > max_bits || mpz_sizeinbase(q.get_den_mpz_t(), 2) > max_bits)
    reject("certificate format", place + ": a rational of more than " + std::to_string(max_bits) + " bits");
  return q;
}

inline long long whole(const json& j, const std::string& place, long long lo, long long hi) {
  long long v = 0;
  bool ok = j.is_number_integer();
  if (ok && j.is_number_unsigned())
    ok = j.get<std::uint64_t>() <= std::uint64_t(std::max(hi, 0LL)), v = ok ? (long long)j.get<std::uint64_t>() : 0;
  else if (ok)
    v = j.get<std::int64_t>();
  if (!ok || v < lo || v > hi)
    reject("certificate format", place + ": expected a whole number from " + std::to_string(lo) + " to " +
                                     std::to_string(hi) + ", got " + shown(j));
  return v;
}

enum class St { separate, touching, overlapping };
inline const char* name(St s) {
  return s == St::separate ? "separate" : s == St::touching ? "touching" : "overlapping";
}
inline St status_named(const json& j, const std::string& place) {
  for (St s : {St::separate, St::touching, St::overlapping})
    if (j.is_string() && j.get<std::string>() == name(s)) return s;
  reject("certificate format", place + ": expected \"separate\", \"touching\" or \"overlapping\", got " + shown(j));
}
inline int sign_named(const json& j, const std::string& place) {
  if (j == "negative") return -1;
  if (j == "zero") return 0;
  if (j == "positive") return 1;
  reject("certificate format", place + ": expected \"negative\", \"zero\" or \"positive\", got " + shown(j));
}

// "[lo]" when lo == hi, else "[lo, hi]". Appended piece by piece: GCC 12 reports a false -Wrestrict in
// `"[" + std::string` once inlined (GCC bug 105329).
inline std::string bracket_text(const mpq_class& lo, const mpq_class& hi) {
  std::string text = "[";
  text += lo.get_str();
  if (lo != hi) text.append(", ").append(hi.get_str());
  text += ']';
  return text;
}

// A plain decimal "[-]digits[.digits][e[-]digits]": its value and the unit of its last digit.
inline bool read_decimal(const std::string& s, std::size_t max_chars, mpq_class& value, mpq_class& unit) {
  if (s.empty() || s.size() > max_chars) return false;
  std::size_t i = 0;
  bool neg = false;
  if (s[0] == '-' || s[0] == '+') neg = s[i++] == '-';
  std::string digits;
  long places = 0;
  bool dot = false;
  for (; i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || (s[i] == '.' && !dot)); ++i) {
    if (s[i] == '.') {
      dot = true;
      continue;
    }
    digits += s[i];
    if (dot) ++places;
  }
  if (digits.empty()) return false;
  long ex = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) eneg = s[i++] == '-';
    const std::size_t start = i;
    for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i)
      if (ex <= 100000) ex = ex * 10 + (s[i] - '0');
    if (i == start || ex > 100000) return false;
    if (eneg) ex = -ex;
  }
  if (i != s.size()) return false;
  const long e = ex - places;
  mpz_class p10, m(digits, 10);
  mpz_ui_pow_ui(p10.get_mpz_t(), 10, (unsigned long)(e < 0 ? -e : e));
  if (neg) m = -m;
  value = e < 0 ? mpq_class(m, p10) : mpq_class(m * p10);
  unit = e < 0 ? mpq_class(mpz_class(1), p10) : mpq_class(p10);
  value.canonicalize();
  unit.canonicalize();
  return true;
}

// An approx lies in its bracket; for a point [r, r], r rounded to its own last digit.
inline void check_approx(const json& a, const mpq_class& lo, const mpq_class& hi, const std::string& claim,
                         const std::string& place, std::size_t max_chars) {
  mpq_class v, u;
  if (!a.is_string() || !read_decimal(a.get<std::string>(), max_chars, v, u))
    reject(claim, place + ": approx must be a decimal string, got " + shown(a));
  const bool ok = lo == hi ? abs(mpq_class(v - lo)) * 2 <= u : (lo <= v && v <= hi);
  if (!ok) reject(claim, place + ": approx " + shown(a) + " lies outside its bracket " + bracket_text(lo, hi));
}

inline void compare_answer(
    const json& cert,
    const std::vector<std::pair<std::pair<mpq_class, mpq_class>, std::pair<mpq_class, mpq_class>>>& intervals,
    const std::vector<std::pair<mpq_class, mpq_class>>& contacts,
    const std::vector<std::pair<std::pair<mpq_class, mpq_class>, std::pair<mpq_class, mpq_class>>>& contact_intervals,
    std::size_t max_bits, std::size_t approx_chars, std::vector<std::string>& checked) {
  const json& a = at(cert, "answer", "certificate");
  if (!a.is_object()) reject("certificate format", "answer: expected an object");
  for (auto it = a.begin(); it != a.end(); ++it)
    if (it.key() != "collides" && it.key() != "intervals" && it.key() != "first_contact" && it.key() != "contacts" &&
        it.key() != "contact_intervals")
      reject("certificate format", "answer." + it.key() + ": not a key of the answer");
  const std::size_t chars = approx_chars;
  auto inst = [&](const json& j, const std::string& place, const std::pair<mpq_class, mpq_class>& want) {
    if (!j.is_object()) reject("certificate format", place + ": expected an instant {approx, lo, hi}");
    for (auto it = j.begin(); it != j.end(); ++it)  // the answer is read back as an answer: nothing else may ride along
      if (it.key() != "approx" && it.key() != "lo" && it.key() != "hi")
        reject("certificate format", place + "." + it.key() + ": not a key of an instant (approx, lo, hi)");
    const mpq_class lo = rational(at(j, "lo", place), place + ".lo", max_bits),
                    hi = rational(at(j, "hi", place), place + ".hi", max_bits);
    if (lo != want.first || hi != want.second)
      reject("answer", place + ": the instant " + bracket_text(lo, hi) + " differs from the checked timeline's " +
                           bracket_text(want.first, want.second));
    check_approx(at(j, "approx", place), lo, hi, "answer", place + ".approx", chars);
  };
  const json& col = at(a, "collides", "answer");
  const bool collides = !intervals.empty();
  if (col != json(collides))
    reject("answer", std::string("answer.collides is ") + shown(col) + " but the checked timeline proves " +
                         (collides ? "a collision" : "there is none"));
  auto pairs = [&](const char* key,
                   const std::vector<std::pair<std::pair<mpq_class, mpq_class>, std::pair<mpq_class, mpq_class>>>& want,
                   bool optional) {
    const std::string place = std::string("answer.") + key;
    if (optional && !a.contains(key)) {
      if (!want.empty())
        reject("answer", place + " is missing but the checked timeline has " + std::to_string(want.size()) +
                             " (continuous touching): it would pass a continuous touch off as an overlap");
      return;
    }
    const json& l = at(a, key, "answer");
    if (!l.is_array()) reject("certificate format", place + ": expected an array");
    if (l.size() != want.size())
      reject("answer", "the checked timeline gives " + std::to_string(want.size()) + " " + key + ", the certificate " +
                           std::to_string(l.size()) +
                           (std::string(key) == "contact_intervals" && l.size() < want.size()
                                ? ": it would pass a continuous touch off as an overlap"
                                : ""));
    for (std::size_t i = 0; i < l.size(); ++i) {
      const std::string p = place + "[" + std::to_string(i) + "]";
      if (!l[i].is_array() || l[i].size() != 2) reject("certificate format", p + ": expected [start, end]");
      inst(l[i][0], p + "[0]", want[i].first);
      inst(l[i][1], p + "[1]", want[i].second);
    }
  };
  pairs("intervals", intervals, false);
  pairs("contact_intervals", contact_intervals, true);
  const json& fc = at(a, "first_contact", "answer");
  if (intervals.empty() != fc.is_null())
    reject("answer",
           "first_contact must be " + std::string(intervals.empty() ? "null" : "the start of the first interval"));
  if (!intervals.empty()) inst(fc, "answer.first_contact", intervals.front().first);
  const json& cs = at(a, "contacts", "answer");
  if (!cs.is_array()) reject("certificate format", "answer.contacts: expected an array");
  if (cs.size() != contacts.size())
    reject("answer", "the checked timeline gives " + std::to_string(contacts.size()) + " contact(s), the certificate " +
                         std::to_string(cs.size()));
  for (std::size_t i = 0; i < cs.size(); ++i) inst(cs[i], "answer.contacts[" + std::to_string(i) + "]", contacts[i]);
  checked.push_back("answer: assembled by the checker from the checked timeline, equal to the certificate's");
}

template <class N>
void answer_claim(const json& cert, const std::vector<N>& seq, std::size_t max_bits, std::size_t approx_chars,
                  std::vector<std::string>& checked) {
  // Assemble: runs of nodes in collision (touching, overlapping), contacts, contact intervals.
  auto in_c = [&](std::size_t k) { return seq[k].status != St::separate; };
  auto touching_cell = [&](std::size_t k) { return k < seq.size() && seq[k].cell && seq[k].status == St::touching; };
  for (std::size_t k = 1; k < seq.size(); k += 2)
    if (in_c(k) && (!in_c(k - 1) || !in_c(k + 1)))
      reject("timeline",
             seq[k].name +
                 " is in collision but a neighbouring instant is separate: the collision set would not be closed");
  using Br = std::pair<mpq_class, mpq_class>;
  std::vector<std::pair<Br, Br>> intervals, contact_intervals;
  std::vector<Br> contacts;
  for (std::size_t k = 0; k < seq.size(); ++k) {
    if (!touching_cell(k)) continue;
    std::size_t e = k;
    while (touching_cell(e + 2) && seq[e + 1].status == St::touching) e += 2;
    contact_intervals.push_back({{seq[k - 1].lo, seq[k - 1].hi}, {seq[e + 1].lo, seq[e + 1].hi}});
    k = e;
  }
  for (std::size_t k = 0; k < seq.size(); k += 2)
    if (seq[k].status == St::touching && !touching_cell(k + 1) && !(k > 0 && touching_cell(k - 1)))
      contacts.push_back({seq[k].lo, seq[k].hi});
  for (std::size_t k = 0; k < seq.size(); ++k) {
    if (!in_c(k)) continue;
    std::size_t e = k;
    while (e + 1 < seq.size() && in_c(e + 1)) ++e;
    intervals.push_back({{seq[k].lo, seq[k].hi}, {seq[e].lo, seq[e].hi}});
    k = e;
  }
  compare_answer(cert, intervals, contacts, contact_intervals, max_bits, approx_chars, checked);
}

}  // namespace eccd::check
