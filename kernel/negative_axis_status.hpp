#pragma once
// The static test for two ellipsoids on the negative λ-axis alone: a proof
// of separation or of overlap from certified signs of f's values, where the
// Sturm count cannot be read (a running error bound leaves one of its signs
// open).
//
// Statement. 002 Theorem 1 / 001 section 3 (kernel/quartic_status.hpp): the
// ellipsoids are separate iff f(λ) = det(λA - B) = g4 λ⁴ + ... + g0 has two
// distinct negative roots, and f has at most two negative roots counted
// with multiplicity. With λ = -s / (1 - s), s in [0, 1) runs over (-∞, 0]
// (s = 0 is λ = 0, s -> 1 is λ -> -∞), and
//   h(s) = (1 - s)⁴ f(-s / (1 - s)) = Σ_k g_k (-s)^k (1 - s)^(4-k)
//        = Σ_k (-1)^k g_k / C(4, k) B_k(s)   (Bernstein basis of degree 4),
// whose roots in (0, 1) are f's negative roots, multiplicities kept;
// h(0) = g0 = det(-B), h(1) = g4 = det(A), both non-zero and of one sign
// (an even number of negative roots). Here 12 h, with coefficients
// 12 g0, -3 g1, 2 g2, -3 g3, 12 g4 (small integer multiples: no division).
//   separate    a point s* in (0, 1) where h has the sign opposite to h(0)
//               and h(1): a root in (0, s*) and one in (s*, 1), two
//               distinct negative roots.
//   overlapping every piece of a subdivision of [0, 1] has Bernstein
//               coefficients all of h(0)'s strict sign (convex hull
//               property): h has no root, f no negative root.
//   uncertain   neither within the work bound (a negative double root, as
//               at a touch, or two negative roots closer than the
//               arithmetic can separate).
// Only certified signs are read (scalar_traits<T>::sign; an uncertain sign
// never decides), so with a running error bound (number/running_error.hpp)
// each answer is a proof about the exact g, not about the rounded ones.
// Where it is used: after the Sturm count in the guarded face only
// (kernel/quartic_status.hpp). It decides the pairs whose f has a positive
// double root by symmetry, two spheres above all (every f of two spheres
// has one: the two directions across the line of centres), where the Sturm
// sequence's last remainder is rounding noise; the published algorithm
// (the Sturm count in plain T) is left as it is.
// Work: depth-first bisection, at most `max_pieces` pieces of degree 4
// (about 20 products each), pieces no narrower than 2^-max_depth.
// Requirements on T: ring operations, int * T, scalar_traits<T> (sign,
// from_rational), kernel/bernstein.hpp's split.
#include "kernel/bernstein.hpp"
#include "kernel/contact_status.hpp"

#include <span>
#include <utility>
#include <vector>

namespace eccd {

template <class T>
Status negative_axis_status(std::span<const T> g, int max_pieces = 160, int max_depth = 48) {
  if (g.size() != 5) return Status::uncertain;
  const Sign s0 = sign(g[0]);
  if (s0 == Sign::uncertain || s0 == Sign::zero || sign(g[4]) != s0) return Status::uncertain;
  const Sign opposite = s0 * Sign::negative;
  Bern<T> h;
  h.b = {T(12 * g[0]), T(-3 * g[1]), T(2 * g[2]), T(-3 * g[3]), T(12 * g[4])};
  const T half = scalar_traits<T>::from_rational(mpq_class(1, 2), g[0]);
  std::vector<std::pair<Bern<T>, int>> stack;  // piece, depth
  stack.push_back({std::move(h), 0});
  bool open = false;
  int pieces = 0;
  while (!stack.empty()) {
    if (++pieces > max_pieces) return Status::uncertain;
    auto [q, depth] = std::move(stack.back());
    stack.pop_back();
    // An end value of the opposite sign: an interior point of [0, 1] (the outer ends have s0's sign).
    if (sign(q.b.front()) == opposite || sign(q.b.back()) == opposite) return Status::separate;
    bool all_s0 = true;
    for (const T& x : q.b) all_s0 = all_s0 && sign(x) == s0;
    if (all_s0) continue;
    if (depth >= max_depth) {
      open = true;
      continue;
    }
    auto [l, r] = split(q, half);
    stack.push_back({std::move(r), depth + 1});
    stack.push_back({std::move(l), depth + 1});
  }
  return open ? Status::uncertain : Status::overlapping;
}

}  // namespace eccd
