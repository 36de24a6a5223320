// Every scene under cases/ with a stored answer: the exact pipeline recomputes
// it and must agree (same collides, same numbers of intervals and contacts,
// each recomputed bracket overlapping the stored one).
#include "tests/support/scenes.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace eccd;
using namespace eccd::test;

namespace {
bool overlaps(const Instant& a, const Instant& b) {
  if (!a.certified() || !b.certified()) return false;
  return !(*a.hi < *b.lo) && !(*b.hi < *a.lo);
}
}  // namespace

TEST_CASE("stored exact answers under cases/ are reproduced by the exact pipeline", "[exact][cases]") {
  int checked = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(ECCD_SOURCE_DIR) + "/cases")) {
    if (e.path().extension() != ".json") continue;
    Scene s = read_scene_file(e.path().string());
    if (!s.answer || s.dim != 2) continue;
    INFO(e.path().string());
    auto r = solve_exact(s);
    const Answer& want = *s.answer;
    const Answer& got = r.answer;
    CHECK(got.collides == want.collides);
    REQUIRE(got.intervals.size() == want.intervals.size());
    for (std::size_t i = 0; i < got.intervals.size(); ++i) {
      CHECK(overlaps(got.intervals[i].first, want.intervals[i].first));
      CHECK(overlaps(got.intervals[i].second, want.intervals[i].second));
    }
    REQUIRE(got.contacts.size() == want.contacts.size());
    for (std::size_t i = 0; i < got.contacts.size(); ++i) CHECK(overlaps(got.contacts[i], want.contacts[i]));
    ++checked;
  }
  CHECK(checked >= 11);
}
