#pragma once
// Arithmetic: which numbers a run computes with — double (IEEE 754, 53 bits),
// MPFR at a chosen precision, exact rationals, or certified (interval
// arithmetic climbing a ladder of MPFI precisions, then exact:
// certified/ladder.hpp). Names as the command line writes them: "double",
// "mpfr:BITS" (53 <= BITS <= 65536), "exact", "certified" (MPFI rung 256),
// "certified:B1,B2,..." (increasing, each 54..65536), "certified:none";
// parse_arithmetic and Arithmetic::name are inverse.
// It sits in solution/, below floating/, exact/ and certified/, because a
// Solution (solution/solution.hpp) names its arithmetic and every layer
// above writes or returns Solutions; api/options.hpp includes it.
#include <string>
#include <vector>

namespace eccd {

struct Arithmetic {
  enum Kind { Double, Mpfr, Exact, Certified } kind = Exact;
  int mpfr_bits = 0;            // Mpfr: the precision (53..65536); unused otherwise
  std::vector<int> mpfi_rungs;  // Certified: the MPFI precisions tried after intervals of doubles, before exact
  // The precision of the floating numbers the run starts computing with:
  // 53 for double and certified (intervals of doubles first), mpfr_bits for
  // MPFR, 0 for exact. This is the JSON's "precision_bits".
  int precision_bits() const;
  std::string name() const;

  static Arithmetic exact();
  static Arithmetic double_precision();
  static Arithmetic mpfr(int bits);
  static Arithmetic certified(std::vector<int> rungs = {256});
  bool floating() const { return kind == Double || kind == Mpfr; }
};
// "double", "mpfr:BITS", "exact", "certified[:B1,B2,...|:none]"; std::invalid_argument
// ("--arith TEXT: what is wrong") otherwise.
Arithmetic parse_arithmetic(const std::string& text);

}  // namespace eccd
