#pragma once
// The small JSON helpers of the prover-side certificate code
// (certificate/write/prover_self_check.cpp, the writers of
// certificate/write/): fail a claim with a reason, read a key, read a
// bounded rational, and run a checker into a CertificateCheck verdict.
//
// Statement. A checker is a sequence of claims; the first that does not hold
// is thrown as Reject{claim, reason} and becomes the verdict's failed_claim and
// reason; any other exception (a malformed part no check foresaw) is reported
// as a "certificate format" failure, never as a crash and never as VALID.
// Rationals are size-bounded before they are parsed (denial of service,
// docs/certificate-format.md): a forged 10^6-digit number costs nothing.
// Requirements: nlohmann::json documents; rationals are number/rational_traits.hpp's.
#include "solution/solution.hpp"
#include "certificate/certificate_result.hpp"
#include "io/scene_reader.hpp"
#include "number/rational_traits.hpp"

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace eccd::certificate_json {

using json = nlohmann::json;

struct Reject {
  std::string claim, reason;
};

[[noreturn]] inline void reject(const std::string& claim, const std::string& reason) { throw Reject{claim, reason}; }

// j[key]; `name_non_object`: a value that is not an object is named as such (the exact checker's message),
// otherwise it is reported as the key missing.
inline const json& at(const json& j, const std::string& key, const std::string& place, bool name_non_object = true) {
  if (!j.is_object()) {
    if (name_non_object)
      reject("certificate format",
             place + ": expected an object with the key \"" + key + "\", got " + j.dump().substr(0, 40));
    reject("certificate format", place + ": missing \"" + key + "\"");
  }
  if (!j.contains(key)) reject("certificate format", place + ": missing \"" + key + "\"");
  return j.at(key);
}

// A rational of at most max_bits bits in numerator and denominator (the exact certificate's messages).
inline Rational read_rational(const json& j, const std::string& place, std::size_t max_bits) {
  if (!j.is_string()) reject("certificate format", place + ": expected a rational written as a string \"p/q\"");
  const std::string& text = j.get_ref<const std::string&>();
  const std::size_t max_chars = 2 * (max_bits * 30103 / 100000 + 2) + 8;
  auto too_big = [&]() {
    reject("certificate format", place + ": a rational of more than " + std::to_string(max_bits) +
                                     " bits, beyond what any certificate of this scene needs (" +
                                     std::to_string(text.size()) + " characters)");
  };
  if (text.size() > max_chars) too_big();
  Rational q;
  try {
    q = parse_rational(text);
  } catch (const std::exception& e) {
    reject("certificate format", place + ": " + e.what());
  }
  if (mpz_sizeinbase(q.get_num_mpz_t(), 2) > max_bits || mpz_sizeinbase(q.get_den_mpz_t(), 2) > max_bits) too_big();
  return q;
}

// The same bound with the short messages of the interval certificates (cycloidal, independent, Bézier).
inline mpq_class read_short_rational(const json& j, const std::string& place, std::size_t max_bits) {
  if (!j.is_string() || j.get_ref<const std::string&>().size() > 2 * max_bits)
    reject("certificate format",
           place + ": expected a rational \"p/q\" of at most " + std::to_string(max_bits) + " bits");
  mpq_class q;
  try {
    q = parse_rational(j.get<std::string>());
  } catch (const std::exception& e) {
    reject("certificate format", place + ": " + e.what());
  }
  if (mpz_sizeinbase(q.get_num_mpz_t(), 2) > max_bits || mpz_sizeinbase(q.get_den_mpz_t(), 2) > max_bits)
    reject("certificate format", place + ": a rational of more than " + std::to_string(max_bits) + " bits");
  return q;
}

// n rationals (a JSON array of exactly n).
inline std::vector<mpq_class> read_short_rationals(const json& j, std::size_t n, const std::string& place,
                                                   std::size_t max_bits) {
  if (!j.is_array() || j.size() != n)
    reject("certificate format", place + ": expected " + std::to_string(n) + " rationals");
  std::vector<mpq_class> r;
  for (std::size_t i = 0; i < n; ++i) r.push_back(read_short_rational(j[i], place, max_bits));
  return r;
}

// Runs check() (which appends to `checked`) into a verdict: VALID when it returns, the first failed claim when it
// throws.
template <class Check>
CertificateCheck run_checker(Check&& check, std::vector<std::string>& checked) {
  CertificateCheck out;
  try {
    check();
    out.valid = true;
  } catch (const Reject& r) {
    out.failed_claim = r.claim;
    out.reason = r.reason;
  } catch (const std::exception& e) {  // safety net: a malformed part the checks did not foresee
    out.failed_claim = "certificate format";
    out.reason = std::string("malformed certificate after the claims checked so far: ") + e.what();
  }
  out.checked = checked;
  return out;
}

// Equal brackets and the same decimal (a derived instant's approx is its bracket's mid-point, as
// bracketed_instant writes it): an answer instant of a certificate against the one its claims give.
inline bool same_instant(const Instant& a, const Instant& b) {
  return a.certified() && b.certified() && *a.lo == *b.lo && *a.hi == *b.hi && a.approx == b.approx;
}

// The certificate's list of intervals `y` must be `x`, the one its claims give, instant for instant; else an
// "answer" rejection. `source` says what gave x ("the pieces", "the proofs").
inline void require_same_intervals(const std::vector<std::pair<Instant, Instant>>& x,
                                   const std::vector<std::pair<Instant, Instant>>& y, const std::string& what,
                                   const std::string& source) {
  if (x.size() != y.size())
    reject("answer",
           source + " give " + std::to_string(x.size()) + " " + what + ", the certificate " + std::to_string(y.size()));
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!same_instant(x[i].first, y[i].first) || !same_instant(x[i].second, y[i].second))
      reject("answer", what + " " + std::to_string(i + 1) + " differs from the one " + source + " give");
}

// The end of a proof certificate's writer (certificate/write/bezier_certificate.cpp,
// certificate/write/independent_certificate.cpp): the writer has run its own checker on the
// certificate (`self`) and never writes a claim it cannot re-prove; it stamps
// the seconds taken and fills the proved run's Solution with what both proofs
// share (the caller adds its own counters and details).
inline void finish_proof_certificate(nlohmann::json& c, const CertificateCheck& self, const std::string& format,
                                     int bits, const Answer& answer, const std::string& method,
                                     std::chrono::steady_clock::time_point start, Solution* solved) {
  if (!self.valid)
    throw CertificationError("internal: the " + format +
                             " certificate does not pass its own check: " + self.failed_claim + ": " + self.reason);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  c["seconds"] = seconds;
  if (!solved) return;
  Solution& o = *solved;
  o.dim = 3;
  o.answer = answer;
  o.certified = true;
  o.basis = "interval+mpfi:" + std::to_string(bits);
  o.method = method;
  o.projection = "krawczyk";
  o.decided_in = "interval proofs about the exact F (certificate " + format + ")";
  o.time_ms = seconds * 1e3;
}

}  // namespace eccd::certificate_json
