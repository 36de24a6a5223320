// Sweep-and-prune (api/sweep_and_prune.hpp), against brute force over all
// pairs: the pairs (i, j), i < j, whose closed intervals [lo, hi] intersect,
// each exactly once, and `examined` equal to their number.
//  - random boxes with integer ends (many equal lo's, touching ends
//    hi_i = lo_j, point intervals), random real boxes over a wide range and
//    with negative values, nested boxes, all-overlapping and disjoint sets;
//  - edges: no boxes, one box, `examined` reset on entry;
//  - the order: a function of the intervals alone (sorted by lo, ties by
//    index), the same for a permuted input up to the renaming of boxes.
#include "api/sweep_and_prune.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <set>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {
using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;
Pairs brute_force(const std::vector<SweepInterval>& box) {
  Pairs all;
  for (std::size_t i = 0; i < box.size(); ++i)
    for (std::size_t j = i + 1; j < box.size(); ++j)
      if (box[i].lo <= box[j].hi && box[j].lo <= box[i].hi) all.emplace_back(i, j);
  return all;
}
// The pairs, sorted, with checks that each is (i < j) and appears once.
Pairs checked(const std::vector<SweepInterval>& box, std::size_t& examined) {
  examined = 12345;  // reset by the call
  Pairs got = sweep_and_prune(box, examined);
  CHECK(std::all_of(got.begin(), got.end(), [](const auto& p) { return p.first < p.second; }));
  CHECK(examined == got.size());
  std::sort(got.begin(), got.end());
  CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
  return got;
}
}  // namespace

TEST_CASE("sweep and prune: ties, touching ends and points, as brute force finds them", "[api][sweep-and-prune]") {
  std::mt19937_64 rng(49);
  std::uniform_int_distribution<int> lo(0, 30), w(0, 4);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<SweepInterval> box(1 + trial % 60);
    for (auto& b : box) {
      b.lo = lo(rng);
      b.hi = b.lo + w(rng);  // width 0: a point
    }
    std::size_t examined = 0;
    const Pairs got = checked(box, examined);
    CHECK(got == brute_force(box));
  }
}

TEST_CASE("sweep and prune: real boxes over wide ranges, nested, all overlapping or none", "[api][sweep-and-prune]") {
  std::mt19937_64 rng(50);
  std::uniform_real_distribution<double> u(-1e6, 1e6), e(-8, 6);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<SweepInterval> box(200);
    for (auto& b : box) {
      b.lo = u(rng);
      b.hi = b.lo + std::pow(10.0, e(rng)) * 1e3;  // widths from 1e-5 to 1e9
    }
    std::size_t examined = 0;
    CHECK(checked(box, examined) == brute_force(box));
  }
  // Nested: [-k, k] for k = 1..30: every pair meets.
  std::vector<SweepInterval> nested;
  for (int k = 1; k <= 30; ++k) nested.push_back({double(-k), double(k)});
  std::size_t examined = 0;
  CHECK(checked(nested, examined).size() == 30 * 29 / 2);
  // Disjoint, in reverse order: nothing meets and nothing is looked at.
  std::vector<SweepInterval> apart;
  for (int k = 30; k >= 1; --k) apart.push_back({3.0 * k, 3.0 * k + 2});
  CHECK(checked(apart, examined).empty());
  CHECK(examined == 0);
  // A chain where neighbours touch at one point only: [k, k + 1].
  std::vector<SweepInterval> chain;
  for (int k = 0; k < 10; ++k) chain.push_back({double(k), double(k + 1)});
  const Pairs c = checked(chain, examined);
  REQUIRE(c.size() == 9);
  for (std::size_t k = 0; k < 9; ++k) CHECK(c[k] == std::make_pair(k, k + 1));
}

TEST_CASE("sweep and prune: empty and single inputs, and the sweep's order", "[api][sweep-and-prune]") {
  std::size_t examined = 7;
  CHECK(sweep_and_prune({}, examined).empty());
  CHECK(examined == 0);
  examined = 7;
  CHECK(sweep_and_prune({{1, 2}}, examined).empty());
  CHECK(examined == 0);
  // Sorted by lo, ties by index: box 2 [0, 5] first, then 0 [1, 3] and 3 [1, 1], then 1 [4, 6].
  const std::vector<SweepInterval> box{{1, 3}, {4, 6}, {0, 5}, {1, 1}};
  const Pairs got = sweep_and_prune(box, examined);
  const Pairs want{{0, 2}, {2, 3}, {1, 2}, {0, 3}};
  CHECK(got == want);
  CHECK(examined == 4);
  // A permuted input gives the same pairs under the renaming.
  std::mt19937_64 rng(51);
  std::uniform_int_distribution<int> lo(0, 20), w(0, 3);
  std::vector<SweepInterval> b(40);
  for (auto& x : b) {
    x.lo = lo(rng);
    x.hi = x.lo + w(rng);
  }
  std::vector<std::size_t> perm(b.size());
  std::iota(perm.begin(), perm.end(), std::size_t(0));
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<SweepInterval> pb(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) pb[perm[k]] = b[k];  // box k is called perm[k]
  std::set<std::pair<std::size_t, std::size_t>> a, renamed;
  for (auto [i, j] : sweep_and_prune(b, examined)) a.insert({perm[i], perm[j]});
  for (auto [i, j] : a) renamed.insert({std::min(i, j), std::max(i, j)});
  const Pairs pg = sweep_and_prune(pb, examined);
  CHECK(renamed == std::set<std::pair<std::size_t, std::size_t>>(pg.begin(), pg.end()));
}

}  // namespace ECCD_UNITY_ID
