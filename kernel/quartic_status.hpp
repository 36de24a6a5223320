#pragma once
// The static test for two ellipsoids: contact status from the negative roots
// of the characteristic quartic f(λ) = det(λA - B) = g4 λ⁴ + ... + g0.
//
// Statement. 002 Theorem 1 (from Wang-Wang-Kim 2001), 001 section 3: the
// ellipsoids are separate iff f has two distinct negative roots, touch
// externally iff f has a negative double root, and overlap otherwise (f has
// no negative root; it always has at least two positive roots, so there are
// never more than two negative roots counted with multiplicity). The distinct
// negative roots are counted by Sturm's theorem (kernel/sturm.hpp) over
// (-∞, 0] (g0 = det(-B) ≠ 0, so 0 is not a root):
//   2 -> separate,  1 -> touching (it must be the double root),  0 -> overlapping.
// With exact T the count is a proof (the Sturm sequence is divided by
// gcd(f, f'), so it counts distinct roots even with a double root). With
// rounded T it is the count the arithmetic computes; a count the theory
// forbids (3, 4) gives `uncertain`. With a running error bound (the guarded
// face) an uncertain count is followed by the negative-axis test
// (kernel/negative_axis_status.hpp), a proof from values of f on (-∞, 0) that
// decides the pairs whose f has a positive double root (two spheres).
// Cost. As in 001 section 3, the Sturm sequence of the quartic has a fixed
// size (at most 5 polynomials of degree <= 4): it is held in fixed-capacity
// storage (count_roots_inline, kernel/sturm.hpp), so the static test
// allocates nothing in double and runs fully unrolled (the hot path of the
// sampling pipeline and of the static benchmark); the count is the one the
// Poly<T> version of the same Sturm code gives.
// Requirements on T: a field, scalar_traits<T>.
#include "kernel/bernstein.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/negative_axis_status.hpp"
#include "kernel/polynomial.hpp"
#include "kernel/sturm.hpp"
#include "number/running_error.hpp"

#include <array>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

// Distinct negative roots of the quartic with coefficients g[0..4] (increasing
// powers; at most 5 values, zero leading ones allowed).
template <class T>
int negative_root_count(std::span<const T> g) {
  return count_roots_inline<5, T>(g, std::optional<T>(), std::optional<T>(g[0] - g[0]));
}

template <class T>
Status quartic_contact_status(std::span<const T> g) {
  int n = negative_root_count(g);
  if (n == 2) return Status::separate;
  if (n == 1) return Status::touching;
  if (n == 0) return Status::overlapping;
  if constexpr (scalar_traits<T>::is_exact)
    throw std::logic_error("internal error: the characteristic quartic has " + std::to_string(n) +
                           " distinct negative roots (at most 2 for two ellipsoids)");
  if constexpr (has_error_bound_v<T>) return negative_axis_status(g);
  return Status::uncertain;
}
template <class T>
Status quartic_contact_status(const std::array<T, 5>& g) {
  return quartic_contact_status(std::span<const T>(g));
}
template <class T>
Status quartic_contact_status(const std::vector<T>& g) {
  return quartic_contact_status(std::span<const T>(g));
}

// The status at instant t from the coefficient polynomials g_i(t) (at most 5).
template <class T>
Status quartic_status_at(const std::vector<Poly<T>>& g, const T& t) {
  if (g.size() > 5) throw std::invalid_argument("quartic_status_at: more than 5 coefficients");
  std::array<T, 5> v;
  for (std::size_t i = 0; i < g.size(); ++i) v[i] = g[i].is_zero() ? t - t : g[i](t);
  return quartic_contact_status(std::span<const T>(v.data(), g.size()));
}

// The same from g_i(t) in Bernstein form (the floating 3D pipelines' setup).
template <class T>
Status quartic_status_at(const std::vector<Bern<T>>& g, const T& t) {
  if (g.size() > 5) throw std::invalid_argument("quartic_status_at: more than 5 coefficients");
  std::array<T, 5> v;
  for (std::size_t i = 0; i < g.size(); ++i) v[i] = g[i](t);
  return quartic_contact_status(std::span<const T>(v.data(), g.size()));
}

}  // namespace eccd
