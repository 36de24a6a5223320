#pragma once
// The exclusion step of an end's proof of independent motions
// (certified/independent_proof.hpp, EndProver; the certificate records it as
// a tree that eccd-check replays): a bounded subdivision of a region of two axes
// of F's tensor net until every box either lies in the box kept for the
// Krawczyk zero or is excluded by a sign condition on the restricted nets.
//
// Statement. Paper 001, section 4 (the lemma in certified/independent_proof.hpp
// step 3 and certified/bezier_proof.hpp): the zeros of the end's system that
// could be ends lie where F = F_u = 0 (and, for independent motions, unless
// F_t and F_uu are of one sign). For each box of the subdivision the caller's
// predicate reads the signs of the nets restricted to the box (MPFI enclosures,
// de Casteljau at 1/2 in intervals: the convex hull property makes "every
// control point of one sign" a proof about the exact F there). The region is
// split at mid-points along axis `ax_u` every level and along `ax_t` every
// `t_every` levels; coordinates are tracked exactly (rationals). The result is
// "every box excluded or kept", or the first box that could not be (at
// `max_depth`), or the box count passing `max_boxes`, or the deadline.
// Requirements: nets TriBern<T> already restricted to the region, T an interval type whose operations
// round outwards (MpfiInterval, Interval).
#include "kernel/budget.hpp"
#include "kernel/trivariate_bernstein.hpp"

#include <gmpxx.h>

#include <array>
#include <tuple>
#include <vector>

namespace eccd {

struct ExclusionRegion {
  mpq_class u0, u1, t0, t1;  // along ax_u and ax_t
};

struct ExclusionResult {
  enum Status { ok, too_many_boxes, stuck, deadline } status = ok;
  mpq_class u0, t0;  // stuck: the corner of the box that could not be excluded
  long boxes = 0;    // boxes visited
};

// excluded(nets of the box, box) -> true when the box holds no zero that matters.
// T: MpfiInterval or Interval (number/interval.hpp, outward rounding); half: 1/2 in T (exact in both).
template <class T, std::size_t N, class Excluded>
ExclusionResult exclude_region(std::array<TriBern<T>, N> nets, int ax_u, int ax_t, const ExclusionRegion& region,
                               const ExclusionRegion& keep, Excluded&& excluded, long max_boxes, int max_depth,
                               int t_every, const T& half) {
  using I = T;
  struct Ex {
    std::array<TriBern<I>, N> f;
    ExclusionRegion r;
    int depth;
  };
  ExclusionResult res;
  std::vector<Ex> stack;
  stack.push_back(Ex{std::move(nets), region, 0});
  while (!stack.empty()) {
    Ex b = std::move(stack.back());
    stack.pop_back();
    if (++res.boxes > max_boxes) {
      res.status = ExclusionResult::too_many_boxes;
      return res;
    }
    if (deadline_passed()) {
      res.status = ExclusionResult::deadline;
      return res;
    }
    if (b.r.u0 >= keep.u0 && b.r.u1 <= keep.u1 && b.r.t0 >= keep.t0 && b.r.t1 <= keep.t1) continue;
    if (excluded(std::as_const(b.f), std::as_const(b.r))) continue;
    if (b.depth >= max_depth) {
      res.status = ExclusionResult::stuck;
      res.u0 = b.r.u0;
      res.t0 = b.r.t0;
      return res;
    }
    const mpq_class um = (b.r.u0 + b.r.u1) / 2, tm = (b.r.t0 + b.r.t1) / 2;
    const bool split_t = (b.depth % t_every) == t_every - 1;
    std::array<TriBern<I>, N> lu, hu;
    for (std::size_t i = 0; i < N; ++i) std::tie(lu[i], hu[i]) = b.f[i].split_half(ax_u, half);
    for (int side = 0; side < 2; ++side) {
      auto& g = side ? hu : lu;
      const mpq_class a0 = side ? um : b.r.u0, a1 = side ? b.r.u1 : um;
      if (!split_t) {
        stack.push_back(Ex{std::move(g), {a0, a1, b.r.t0, b.r.t1}, b.depth + 1});
        continue;
      }
      std::array<TriBern<I>, N> lt, ht;
      for (std::size_t i = 0; i < N; ++i) std::tie(lt[i], ht[i]) = g[i].split_half(ax_t, half);
      stack.push_back(Ex{std::move(ht), {a0, a1, tm, b.r.t1}, b.depth + 1});
      stack.push_back(Ex{std::move(lt), {a0, a1, b.r.t0, tm}, b.depth + 1});
    }
  }
  return res;
}

}  // namespace eccd
