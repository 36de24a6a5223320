#pragma once
// Contact status of two elliptic disks from the root pattern of their
// characteristic cubic f(λ) = det(λA - B) (003 section II).
//
// Statement. 003 Theorem 6: separate iff f has two distinct negative roots;
// touching externally iff f has a negative double root; otherwise
// overlapping (Lemma 1: f always has a positive root, and the other two are
// both positive, both negative or complex). Decided from signs only:
//   Δ < 0                       -> one real root (positive)     -> overlapping
//   Δ > 0, f(-λ) has 2 sign changes in its coefficients -> separate
//          (Descartes' rule is exact when all roots are real)
//   Δ > 0, 0 sign changes       -> three positive roots         -> overlapping
//   Δ = 0, D ≠ 0: double root λ0 = P / (2D) -> touching iff sign(P) sign(D) < 0
//   Δ = 0, D = 0: triple root (positive by Lemma 1)             -> overlapping
// with P, D from kernel/discriminant.hpp. With exact T the answer is proved;
// with rounded T the signs are those of the computed values, and a pattern
// that Lemma 1 forbids (1 or 3 sign changes) is reported as `uncertain`.
// Requirements on T: ring operations, scalar_traits<T>::sign.
#include "kernel/discriminant.hpp"
#include "kernel/sign_variations.hpp"
#include "number/scalar_traits.hpp"

namespace eccd {

enum class Status { separate, touching, overlapping, uncertain };

inline const char* to_string(Status s) {
  switch (s) {
    case Status::separate:
      return "separate";
    case Status::touching:
      return "touching";
    case Status::overlapping:
      return "overlapping";
    default:
      return "uncertain";
  }
}
inline bool in_collision(Status s) { return s == Status::touching || s == Status::overlapping; }

// Status when f is known to have a multiple root (Δ = 0), from sign(P), sign(D).
inline Status status_at_multiple_root(Sign sP, Sign sD) {
  if (sD == Sign::uncertain || sP == Sign::uncertain) return Status::uncertain;
  if (sD == Sign::zero) return Status::overlapping;  // triple root, positive
  return (sP * sD) == Sign::negative ? Status::touching : Status::overlapping;
}

template <class T>
Status cubic_contact_status(const T& g3, const T& g2, const T& g1, const T& g0) {
  T disc = cubic_discriminant(g3, g2, g1, g0);
  Sign s = sign(disc);
  if (s == Sign::uncertain) return Status::uncertain;
  if (s == Sign::negative) return Status::overlapping;
  if (s == Sign::zero)
    return status_at_multiple_root(sign(double_root_numerator(g3, g2, g1, g0)),
                                   sign(double_root_denominator(g3, g2, g1)));
  // Δ > 0: count sign changes of f(-λ) = -g3 λ³ + g2 λ² - g1 λ + g0.
  const Sign seq[4] = {sign(g3) * Sign::negative, sign(g2), sign(g1) * Sign::negative, sign(g0)};
  const SignVariations v = sign_variations_n<4>(4, [&](std::size_t k) { return seq[k]; });
  if (v.uncertain) return Status::uncertain;
  const int changes = v.count;
  if (changes == 2) return Status::separate;
  if (changes == 0) return Status::overlapping;
  return Status::uncertain;
}

}  // namespace eccd
