// Exact numbers of the scene format (io/scene_reader.hpp, choices 1 and 14):
// parse_rational reads an integer, a fraction or a decimal with exponent into
// its exact rational value, refusing what the format does not allow and any
// number beyond the process-wide input limits (input_limits(), digits per
// numerator and denominator). Requirements: GMP rationals.
#include "io/scene_reader.hpp"

#include <cstdint>
#include <string>

namespace eccd {

namespace {

bool all_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char ch : s)
    if (ch < '0' || ch > '9') return false;
  return true;
}

const char* const kNumberForms =
    "expected an integer (\"-63\"), a fraction (\"-3/7\") or a decimal (\"1.8\", \"2.5e-3\")";

[[noreturn]] void bad_number(const std::string& why) { throw std::invalid_argument(why); }

}  // namespace

InputLimits& input_limits() {
  static InputLimits limits;
  return limits;
}

namespace {
[[noreturn]] void beyond_digits(const char* part, std::size_t digits, bool at_least = false) {
  bad_number(std::string(part) + " has " + (at_least ? "at least " : "") + std::to_string(digits) +
             " digits, beyond the input limit of " + std::to_string(input_limits().max_digits) +
             " digits per number (--max-digits)");
}
void check_digits(const mpq_class& q) {
  const std::size_t lim = input_limits().max_digits;
  // mpz_sizeinbase(.,10) may be one too large: confirm with the exact count only near the limit
  auto digits = [](const mpz_class& z) {
    std::size_t d = mpz_sizeinbase(z.get_mpz_t(), 10);
    if (d > 1) {
      mpz_class p;
      mpz_ui_pow_ui(p.get_mpz_t(), 10, d - 1);
      if (abs(z) < p) --d;
    }
    return d;
  };
  if (mpz_sizeinbase(q.get_num_mpz_t(), 10) > lim) {
    std::size_t d = digits(q.get_num());
    if (d > lim) beyond_digits(q.get_den() == 1 ? "the number" : "its numerator", d);
  }
  if (mpz_sizeinbase(q.get_den_mpz_t(), 10) > lim) {
    std::size_t d = digits(q.get_den());
    if (d > lim) beyond_digits("its denominator (in lowest terms)", d);
  }
}
}  // namespace

Rational parse_rational(const std::string& text) {
  if (text.empty()) bad_number(std::string("empty string; ") + kNumberForms);
  if (text.size() > 100 * input_limits().max_digits + 16)
    bad_number("a number text of " + std::to_string(text.size()) + " characters, beyond the input limit of " +
               std::to_string(100 * input_limits().max_digits + 16) + " characters (100 x --max-digits)");
  for (char ch : text)
    if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\f' || ch == '\v')
      bad_number("contains whitespace");
  std::size_t i = 0;
  bool negative = false;
  if (text[0] == '+' || text[0] == '-') {
    negative = text[0] == '-';
    i = 1;
  }
  const std::size_t slash = text.find('/');
  if (slash != std::string::npos) {
    const std::string num = text.substr(i, slash - i), den = text.substr(slash + 1);
    if (!all_digits(num)) bad_number("the numerator of a fraction must be an integer (an optional sign, then digits)");
    if (!all_digits(den)) bad_number("the denominator of a fraction must be a positive integer (digits only)");
    mpz_class n(num, 10), d(den, 10);
    if (d == 0) bad_number("zero denominator");
    mpq_class q(n, d);
    q.canonicalize();
    check_digits(q);
    if (negative) q = -q;
    return q;
  }
  // Decimal: digits [ '.' digits ] [ (e|E) [sign] digits ], at least one mantissa digit.
  std::string mantissa;
  long frac_len = 0;
  std::size_t j = i;
  while (j < text.size() && text[j] >= '0' && text[j] <= '9') mantissa += text[j++];
  if (j < text.size() && text[j] == '.') {
    ++j;
    while (j < text.size() && text[j] >= '0' && text[j] <= '9') {
      mantissa += text[j++];
      ++frac_len;
    }
  }
  if (mantissa.empty()) bad_number(std::string("no digits; ") + kNumberForms);
  long exponent = 0;
  if (j < text.size() && (text[j] == 'e' || text[j] == 'E')) {
    ++j;
    bool eneg = false;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) {
      eneg = text[j] == '-';
      ++j;
    }
    std::string ed;
    while (j < text.size() && text[j] >= '0' && text[j] <= '9') ed += text[j++];
    if (ed.empty()) bad_number("the exponent has no digits");
    std::size_t nz = ed.find_first_not_of('0');
    ed = nz == std::string::npos ? std::string("0") : ed.substr(nz);
    if (ed.size() > 5 || std::stol(ed) > 10000) bad_number("exponent too large (at most 10000 in magnitude)");
    exponent = std::stol(ed);
    if (eneg) exponent = -exponent;
  }
  if (j != text.size())
    bad_number("unexpected '" + std::string(1, text[j]) + "' at character " + std::to_string(j + 1) + "; " +
               kNumberForms);
  {  // the value's size before building it: significant digits + exponent
    std::size_t nz = mantissa.find_first_not_of('0');
    if (nz == std::string::npos) return Rational(0);
    std::size_t sig = mantissa.size() - nz;
    std::size_t last = mantissa.find_last_not_of('0');
    long trailing = long(mantissa.size() - 1 - last);
    long e0 = exponent - frac_len + trailing;  // value = (significant digits) * 10^e0
    std::size_t core = sig - std::size_t(trailing);
    std::size_t lim = input_limits().max_digits;
    if (e0 >= 0 && core + std::size_t(e0) > lim + 1) beyond_digits("the number", core + std::size_t(e0));
    // the denominator in lowest terms is at least 10^-e0 / core: more than -e0 - core digits
    if (e0 < 0 && std::size_t(-e0) > core + lim + 1)
      beyond_digits("its denominator (in lowest terms)", std::size_t(-e0) - core, true);
  }
  mpz_class m(mantissa, 10);
  const long e = exponent - frac_len;
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(e < 0 ? -e : e));
  mpq_class q = e >= 0 ? mpq_class(mpz_class(m * p)) : mpq_class(m, p);
  q.canonicalize();
  check_digits(q);
  if (negative) q = -q;
  return q;
}

}  // namespace eccd
