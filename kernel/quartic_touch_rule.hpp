#pragma once
// Does the characteristic quartic have a negative multiple root at a root t*
// of the 3D projection polynomial? Decided from signs of subresultant
// coefficients at t* only.
//
// Statement (002 section III, 001 section 4; kernel/subresultants.hpp for the
// facts on subresultants). Let the projection be psc_k(t) (k = 0: the
// discriminant, which is psc_0 up to a non-zero factor), so that
// psc_0 .. psc_{k-1} vanish identically. At a root t* of psc_k, gcd(f, f') has
// degree j = the least j > k with psc_j(t*) ≠ 0 and equals S_j(λ; t*); its real
// roots are the multiple roots of f(.; t*). The pair touches externally at t*
// iff one of them is negative:
//   j = 1: the double root -s10/s11 is negative iff s10·s11 > 0;
//   j = 3: the quadruple root -s32/(3 s33) is negative iff s32·s33 > 0;
//   j = 2: S_2 = s22 λ² + s21 λ + s20 has a negative real root, decided by the
//          signs of s22, s21, s20 and of the discriminant s21² - 4 s22 s20.
// The rule asks for the signs it needs through sign_of(j, i) (i = -1 stands
// for the discriminant of S_2), so that the exact pipeline, the floating
// pipelines and the certificate checker apply one and the same rule: the
// exact pipeline answers with exact signs at the algebraic number t*, the
// checker with signs it has verified from a certificate.
// Requirements: sign_of returns Sign (uncertain propagates to the answer).
#include "number/scalar_traits.hpp"
#include "kernel/subresultants.hpp"

#include <string>
#include <vector>

namespace eccd {

// The polynomial behind sign_of(j, i) for f with coefficients G (increasing
// powers of λ, entries in any ring): s_{j,i} of S_j(f, ∂f/∂λ), or for
// (2, -1) the discriminant s21² - 4 s22 s20 of S_2.
template <class R>
R subresultant_evidence(const std::vector<R>& G, int j, int i) {
  R z = G[0] - G[0];
  std::vector<R> fp = lambda_derivative(G);
  if (i >= 0) return subresultant_coefficient(G, fp, j, i, z);
  R a = subresultant_coefficient(G, fp, 2, 2, z);
  R b = subresultant_coefficient(G, fp, 2, 1, z);
  R c = subresultant_coefficient(G, fp, 2, 0, z);
  return b * b - 4 * (a * c);
}

// The name a certificate uses for that polynomial: "s(2,1)", "disc(S_2)".
inline std::string subresultant_evidence_name(int j, int i) {
  if (i < 0) return "disc(S_2)";
  return "s(" + std::to_string(j) + "," + std::to_string(i) + ")";
}

// positive = a negative multiple root exists (external touch), zero = it does
// not, uncertain = a sign needed was uncertain.
template <class SignOf>
Sign negative_multiple_root(int k, SignOf sign_of) {
  for (int j = k + 1; j <= 3; ++j) {
    Sign lead = sign_of(j, j);
    if (lead == Sign::uncertain) return Sign::uncertain;
    if (lead == Sign::zero) continue;
    if (j == 1 || j == 3) {
      Sign next = sign_of(j, j - 1);
      if (next == Sign::uncertain) return Sign::uncertain;
      return (next * lead) == Sign::positive ? Sign::positive : Sign::zero;
    }
    Sign sb = sign_of(2, 1), sc = sign_of(2, 0), sd = sign_of(2, -1);
    if (sb == Sign::uncertain || sc == Sign::uncertain || sd == Sign::uncertain) return Sign::uncertain;
    if (sd == Sign::negative) return Sign::zero;                                    // complex pair of double roots
    bool neg = (lead * sc) == Sign::negative ||                                     // roots of opposite signs
               ((lead * sc) == Sign::positive && (lead * sb) == Sign::positive) ||  // both negative
               (sc == Sign::zero && (lead * sb) == Sign::positive);                 // 0 and -b/a < 0
    return neg ? Sign::positive : Sign::zero;
  }
  return Sign::uncertain;  // psc_j(t*) = 0 for every j <= 3: impossible since g4 ≠ 0
}

}  // namespace eccd
