#pragma once
// The static test for two ellipsoids from signs only: the characteristic
// quartic's discriminant and Descartes' rule, the 3D analogue of 003
// Theorem 6's cubic rule (kernel/contact_status.hpp), without the Sturm
// sequence's divisions (kernel/quartic_status.hpp).
//
// Statement. 002 Theorem 1 / 001 section 3: with f(λ) = det(λA - B) =
// g4 λ⁴ + ... + g0 the ellipsoids are separate iff f has two distinct
// negative roots, touch iff a negative double root, overlap otherwise; f
// always has at least two positive roots (so at most two negative ones).
// With Δ the quartic's discriminant (kernel/discriminant.hpp):
//   Δ < 0   exactly two real roots: the two positive ones -> overlapping
//   Δ > 0   four distinct real roots (none of the two-complex-pairs kind,
//           since two are real): Descartes' rule counts the negative ones
//           exactly, as the sign changes of f(-λ)'s coefficients
//           g4, -g3, g2, -g1, g0 (g0 = det(-B) ≠ 0): 2 -> separate,
//           0 -> overlapping
//   Δ = 0   a multiple root: a negative double root (touching) or a positive
//           one (overlapping); decided by the Sturm count
//           (quartic_contact_status) with exact T, `uncertain` otherwise.
// With rounded T (ForwardBound, Bounded) a sign that is not certain gives
// `uncertain`, as does a pattern the theory forbids (1, 3 or 4 changes).
// With T = ForwardBound the sign of Δ is taken with the coefficients as
// fresh leaves (magnitudes restart at |ĝ_i|, which is much tighter than the
// magnitude of the whole program from the poses): if every |ĝ_i| > e_i (their
// bounds) and ρ = max e_i / |ĝ_i| <= 2^-20, then, Δ having degree <= 6 in the
// g_i, |Δ(g) - Δ(ĝ)| <= P(|ĝ|) ((1 + ρ)^6 - 1) <= 6.1 ρ P(|ĝ|), where P is Δ
// with its coefficients' absolute values (each monomial's factors move by at
// most a relative ρ), and the rounding of Δ(ĝ) adds γ_d P(|ĝ|)
// (number/forward_bound.hpp). With m >= P(|ĝ|)(1 - d u) the computed
// magnitude, err = m (2 d u + 7 ρ) bounds |computed Δ - Δ(g)|.
// Cost: Δ is about 60 products; no division, no branch before the signs.
// Requirements on T: ring operations, int * T, scalar_traits<T>::sign.
#include "kernel/contact_status.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/quartic_status.hpp"
#include "number/forward_bound.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace eccd {

template <class T>
Sign quartic_discriminant_sign(const std::array<T, 5>& g) {
  return sign(quartic_discriminant(g[4], g[3], g[2], g[1], g[0]));
}
inline Sign quartic_discriminant_sign(const std::array<ForwardBound, 5>& g) {
  std::array<ForwardBound, 5> leaf;
  double rho = 0;
  for (int i = 0; i < 5; ++i) {
    const double v = std::fabs(g[i].value()), e = g[i].bound();
    if (!(v > e) || !(g[i].magnitude() <= std::numeric_limits<double>::max())) return Sign::uncertain;
    rho = std::max(rho, e / v);  // rounded: the factor 7 (not 6.1) covers it
    leaf[i] = ForwardBound::exact(g[i].value());
  }
  if (!(rho <= 0x1p-20)) return Sign::uncertain;
  ForwardBound d = quartic_discriminant(leaf[4], leaf[3], leaf[2], leaf[1], leaf[0]);
  const double m = d.magnitude(), err = m * (2 * d.depth() * 0x1p-53 + 7 * rho);
  if (!(m <= std::numeric_limits<double>::max()) || !(std::fabs(d.value()) > err)) return Sign::uncertain;
  return d.value() > 0 ? Sign::positive : Sign::negative;
}

template <class T>
Status quartic_sign_status(const std::array<T, 5>& g) {
  Sign s = quartic_discriminant_sign(g);
  if (s == Sign::uncertain) return Status::uncertain;
  if (s == Sign::negative) return Status::overlapping;
  if (s == Sign::zero) {
    if constexpr (scalar_traits<T>::is_exact)
      return quartic_contact_status(g);
    else
      return Status::uncertain;
  }
  const Sign seq[5] = {sign(g[4]), sign(g[3]) * Sign::negative, sign(g[2]), sign(g[1]) * Sign::negative, sign(g[0])};
  const SignVariations v = sign_variations_n<5>(5, [&](std::size_t k) { return seq[k]; });
  if (v.uncertain) return Status::uncertain;
  const int changes = v.count;
  if (changes == 2) return Status::separate;
  if (changes == 0) return Status::overlapping;
  if constexpr (scalar_traits<T>::is_exact)
    throw std::logic_error("internal error: the characteristic quartic's coefficients change sign " +
                           std::to_string(changes) + " times with Δ > 0 (0 or 2 for two ellipsoids)");
  return Status::uncertain;
}

}  // namespace eccd
