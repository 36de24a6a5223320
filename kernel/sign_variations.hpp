#pragma once
// Sign variations of a sequence: the one count behind every Descartes-type
// rule of the workbench.
//
// Statement. V = the number of sign changes of a sequence s_0, ..., s_{n-1},
// zeros skipped. Descartes' rule of signs (power basis, and the Bernstein
// basis on [0, 1]: Lane and Riesenfeld 1981; Basu, Pollack and Roy 2006,
// ch. 10) bounds the real roots in the open interval by V, with the same
// parity; Sturm's theorem counts roots by the difference of V at two points.
// Users: Bernstein root isolation (floating/bernstein_roots.hpp, the certified
// policy), exact Descartes on an interval (exact/descartes.hpp), Sturm
// counting (kernel/sturm.hpp) and the inertia of a shape matrix
// (kernel/quadric_classification.hpp).
//
// Uncertainty. A rounded arithmetic with an error bound may leave a sign
// uncertain (number/scalar_traits.hpp). An uncertain sign is never skipped or
// guessed: the count is then unknown (`uncertain` set, `count` meaningless),
// and the caller decides what that means (subdivide further, escalate, or
// leave the place undecided). Exact arithmetic never sets it.
// Requirements: the signs (Sign, number/scalar_traits.hpp) of the elements,
// given by a callable or by eccd::sign.
#include "number/scalar_traits.hpp"

#include <cstddef>

namespace eccd {

struct SignVariations {
  int count = 0;           // sign changes among the certain signs (valid only when !uncertain)
  bool uncertain = false;  // some element's sign is uncertain: the true count is unknown
  // The count if it is known.
  bool is(int v) const { return !uncertain && count == v; }
};

// Sign changes of sign_of(0), ..., sign_of(n - 1); stops at the first uncertain sign.
// Capacity > 0: n <= Capacity is known at compile time (fixed-capacity storage,
// kernel/sturm.hpp), and the loop runs to it with a guard so that it unrolls.
template <int Capacity = 0, class SignOf>
SignVariations sign_variations_n(std::size_t n, SignOf&& sign_of) {
  SignVariations v;
  Sign last = Sign::zero;
  constexpr std::size_t cap = Capacity > 0 ? std::size_t(Capacity) : std::size_t(-1);
#pragma GCC unroll 8
  for (std::size_t k = 0; k < cap; ++k) {
    if (k >= n) break;
    const Sign s = sign_of(k);
    if (s == Sign::uncertain) {
      v.uncertain = true;
      return v;
    }
    if (s == Sign::zero) continue;
    if (last != Sign::zero && s != last) ++v.count;
    last = s;
  }
  return v;
}

// Sign changes of a sequence of scalars (any container with size() and []).
template <class Seq>
SignVariations sign_variations(const Seq& xs) {
  return sign_variations_n(std::size_t(xs.size()), [&](std::size_t k) { return eccd::sign(xs[k]); });
}

}  // namespace eccd
