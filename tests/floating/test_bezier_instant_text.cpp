// The Bézier pipeline formats only the instants that reach its result
// (floating/bezier_ccd.hpp, BezierZeroSet::format_kept, issue 21): every
// instant that the answer, the cells or the critical instants carry must
// still have its text, the one rounded_instant gives for its value (the
// instants inside a run of one status, which appear nowhere, keep only their
// double value). Checked in double with a running bound (the `eccd solve`
// default) and in MPFR at 128 bits, on random Euler-parameter scenes.
#include "floating/bezier_ccd.hpp"
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "number/running_error.hpp"
#include "tests/support/arith.hpp"
#include "tests/support/scenes3d.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// exact: a double's text is its %.17g, which reads back to the same double;
// MPFR's 38-digit text reads back to within one rounding of the double nearest t.
template <class T>
int check_texts(const PipelineResult<T>& r, bool exact) {
  std::vector<const Instant*> all;
  for (const auto& iv : r.answer.intervals) {
    all.push_back(&iv.first);
    all.push_back(&iv.second);
  }
  for (const auto& iv : r.answer.contact_intervals) {
    all.push_back(&iv.first);
    all.push_back(&iv.second);
  }
  for (const auto& i : r.answer.contacts) all.push_back(&i);
  for (const auto& i : r.answer.undecided) all.push_back(&i);
  if (r.answer.first_contact) all.push_back(&*r.answer.first_contact);
  for (const auto& c : r.cells) all.push_back(&c.sample);
  for (const auto& c : r.critical) all.push_back(&c.t);
  for (const Instant* i : all) {
    INFO("instant with value " << i->value);
    REQUIRE_FALSE(i->approx.empty());
    const double back = std::stod(i->approx);
    if (exact)
      CHECK(back == i->value);
    else
      CHECK(std::fabs(back - i->value) <= 0x1p-52 * std::fmax(1.0, std::fabs(i->value)));
  }
  return int(all.size());
}

}  // namespace

TEST_CASE("the Bezier pipeline's answer, cells and critical instants all have their text",
          "[floating][bezier][speed21]") {
  std::uint64_t seed = test::seed_from_env(2111);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  int collided = 0, checked = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Scene s = test::random_euler_scene(rng, 1 + trial % 2);
    const auto rd = test::solve_bezier_3d(s, 53, Bounded<double>(1.0, 0));
    checked += check_texts(rd, true);
    collided += rd.answer.collides;
    if (trial % 4 == 0) {
      const Bounded<Mpfr> like(Mpfr(mpq_class(1), 128), 0);
      checked += check_texts(test::solve_bezier_3d(s, 128, like), false);
    }
  }
  CHECK(collided > 0);  // interval ends were among the instants checked
  CHECK(checked > 12 * 30);
}

}  // namespace ECCD_UNITY_ID
