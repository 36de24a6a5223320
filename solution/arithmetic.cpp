// Arithmetic names (solution/arithmetic.hpp).
#include "solution/arithmetic.hpp"

#include <stdexcept>

namespace eccd {

int Arithmetic::precision_bits() const {
  switch (kind) {
    case Double:
    case Certified:
      return 53;
    case Mpfr:
      return mpfr_bits;
    default:
      return 0;
  }
}

std::string Arithmetic::name() const {
  switch (kind) {
    case Double:
      return "double";
    case Mpfr:
      return "mpfr:" + std::to_string(mpfr_bits);
    case Certified: {
      if (mpfi_rungs == std::vector<int>{256}) return "certified";
      std::string n = "certified:";
      for (std::size_t i = 0; i < mpfi_rungs.size(); ++i)
        n.append(i ? "," : "")
            .append(std::to_string(mpfi_rungs[i]));  // no const char* + string: GCC 12's false -Wrestrict
      return mpfi_rungs.empty() ? n + "none" : n;
    }
    default:
      return "exact";
  }
}

Arithmetic Arithmetic::exact() { return Arithmetic{}; }
Arithmetic Arithmetic::double_precision() {
  Arithmetic a;
  a.kind = Double;
  return a;
}
Arithmetic Arithmetic::mpfr(int bits) { return parse_arithmetic("mpfr:" + std::to_string(bits)); }
Arithmetic Arithmetic::certified(std::vector<int> rungs) {
  std::string n = "certified:";
  for (std::size_t i = 0; i < rungs.size(); ++i) n.append(i ? "," : "").append(std::to_string(rungs[i]));  // (as above)
  return parse_arithmetic(rungs.empty() ? n + "none" : n);
}

Arithmetic parse_arithmetic(const std::string& text) {
  Arithmetic a;
  if (text == "double") {
    a.kind = Arithmetic::Double;
    return a;
  }
  if (text == "exact") {
    a.kind = Arithmetic::Exact;
    return a;
  }
  if (text == "certified") {
    a.kind = Arithmetic::Certified;
    a.mpfi_rungs = {256};
    return a;
  }
  if (text.rfind("certified:", 0) == 0) {
    a.kind = Arithmetic::Certified;
    std::string list = text.substr(10);
    if (list == "none") return a;
    std::size_t at = 0;
    while (true) {
      std::size_t comma = list.find(',', at);
      std::string b = list.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
      if (b.empty() || b.find_first_not_of("0123456789") != std::string::npos || b.size() > 6)
        throw std::invalid_argument("--arith " + text +
                                    ": expected certified:BITS[,BITS...] (MPFI rungs) or certified:none");
      int bits = std::stoi(b);
      if (bits < 54 || bits > 65536 || (!a.mpfi_rungs.empty() && bits <= a.mpfi_rungs.back()))
        throw std::invalid_argument("--arith " + text + ": MPFI rungs must increase, each between 54 and 65536 bits");
      a.mpfi_rungs.push_back(bits);
      if (comma == std::string::npos) break;
      at = comma + 1;
    }
    return a;
  }
  if (text.rfind("mpfr:", 0) == 0) {
    std::string b = text.substr(5);
    if (b.empty() || b.find_first_not_of("0123456789") != std::string::npos || b.size() > 6)
      throw std::invalid_argument("--arith " + text + ": expected mpfr:BITS with BITS a whole number");
    a.kind = Arithmetic::Mpfr;
    a.mpfr_bits = std::stoi(b);
    if (a.mpfr_bits < 53 || a.mpfr_bits > 65536)
      throw std::invalid_argument("--arith " + text + ": MPFR precision must be between 53 and 65536 bits");
    return a;
  }
  throw std::invalid_argument("--arith " + text + ": expected double, mpfr:BITS, exact or certified");
}

}  // namespace eccd
