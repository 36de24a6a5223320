#pragma once
// Sweep-and-prune: the pairs of boxes whose intervals on one axis overlap,
// found by sorting the intervals by their low end and sweeping, so that the
// work grows with n log n plus the pairs the sweep looks at, not with n².
//
// Statement (the broad phase of 001 section 5's animations in its usual
// form: Baraff 1992, "sort and sweep"). Box i is the closed interval
// [lo_i, hi_i] (lo_i <= hi_i). After sorting by lo, box i is compared only
// with the boxes j after it in that order whose lo_j <= hi_i; every pair whose
// intervals intersect is one of them, and each is looked at once. The number
// of pairs looked at is returned in `examined` (the work count the tests
// assert on, tests/api), and equals the number of overlapping pairs.
// Output: the pairs (i, j), i < j, in the sweep's order (a function of the
// intervals only; callers sort what survives their own tests).
// Requirements: finite doubles (callers round outwards, so an interval that
// encloses an exact one keeps every exact overlap).
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace eccd {

struct SweepInterval {
  double lo = 0, hi = 0;
};

inline std::vector<std::pair<std::size_t, std::size_t>> sweep_and_prune(const std::vector<SweepInterval>& box,
                                                                        std::size_t& examined) {
  const std::size_t n = box.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return box[x].lo < box[y].lo || (box[x].lo == box[y].lo && x < y); });
  std::vector<std::pair<std::size_t, std::size_t>> out;
  examined = 0;
  for (std::size_t u = 0; u < n; ++u) {
    const std::size_t x = order[u];
    for (std::size_t v = u + 1; v < n && box[order[v]].lo <= box[x].hi; ++v) {
      ++examined;
      const std::size_t y = order[v];
      out.emplace_back(std::min(x, y), std::max(x, y));
    }
  }
  return out;
}

}  // namespace eccd
