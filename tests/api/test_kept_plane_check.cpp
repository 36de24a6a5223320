// Stage 2's interval check of a kept plane (api/animate.hpp KeptPlaneCheck,
// kernel/plane_frame_check.hpp keyframe_plane_check) against the exact check
// of the same plane on the pair-frame's scene (api/separate.hpp
// plane_separates_on_frame, exact arithmetic): on 000 Table 1's animations
// and on the boxers, with the plane animate keeps (the exact separating plane
// at the end of the frame before) and with that plane moved off (its offset
// shifted, so that it cuts a body), every `separates` and every `fails` of the
// interval check is the exact check's answer. The test also asserts that the
// interval check settles most kept planes, so that it is not passing by
// answering `unknown`.
#include "api/animate.hpp"
#include "api/separate.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

struct Tally {
  int separates = 0, fails = 0, unknown = 0, exact_separates = 0;
};

void compare(const Animation& anim, std::size_t i, std::size_t j, std::size_t k, const SeparatingPlane& plane,
             const KeptPlaneCheck& check, Tally& t) {
  SolveOptions ex;
  ex.arith = Arithmetic::exact();
  const PlaneCheck exact = plane_separates_on_frame(pair_frame_scene(anim, i, j, k), plane, ex);
  const FrameSides f = check.check(check.prepare(plane.normal, plane.offset), i, j, k);
  INFO(anim.name << " bodies " << i << ", " << j << " frame " << k << ": interval " << int(f) << ", exact "
                 << int(exact));
  t.exact_separates += exact == PlaneCheck::separates;
  if (f == FrameSides::separates) {
    ++t.separates;
    CHECK(exact == PlaneCheck::separates);
  } else if (f == FrameSides::fails) {
    ++t.fails;
    CHECK(exact == PlaneCheck::fails);
  } else {
    ++t.unknown;
  }
}

void run(const std::string& rel, std::size_t frames, std::size_t pairs, Tally& kept, Tally& moved) {
  const Animation anim = read_animation(std::string(ECCD_SOURCE_DIR) + "/" + rel);
  const KeptPlaneCheck check(anim);
  SolveOptions ex;
  ex.arith = Arithmetic::exact();
  for (std::size_t n = 0; n < pairs && n < anim.pairs.size(); ++n)
    for (std::size_t k = 1; k <= frames && k < anim.frames(); ++k) {
      const auto [i, j] = anim.pairs[n * (anim.pairs.size() / std::min(pairs, anim.pairs.size()))];
      const Separation sep = separate_at(pair_frame_scene(anim, i, j, k - 1), 1, ex);
      if (!sep.plane) continue;
      compare(anim, i, j, k, *sep.plane, check, kept);
      SeparatingPlane off = *sep.plane;
      off.offset += Rational(k % 2 ? 1 : -1, 2);  // half a unit towards one body (normals are scaled to max |n_i| = 1)
      compare(anim, i, j, k, off, check, moved);
    }
}

}  // namespace

TEST_CASE("kept-plane check in intervals agrees with the exact check where it decides", "[animate][planes]") {
  Tally kept, moved;
  run("bench/data/table1-0.1-1000.anim.json", 40, 1, kept, moved);
  run("bench/data/table1-1-1000.anim.json", 40, 1, kept, moved);
  run("bench/data/boxers-10.anim.json", 3, 24, kept, moved);
  INFO("kept: " << kept.separates << " separate, " << kept.fails << " fail, " << kept.unknown
                << " unknown (exact separates " << kept.exact_separates << "); moved: " << moved.separates << "/"
                << moved.fails << "/" << moved.unknown);
  CHECK(kept.separates >= kept.exact_separates * 9 / 10);
  CHECK(kept.separates > 0);
  CHECK(moved.separates + moved.fails + moved.unknown > 0);
}

}  // namespace ECCD_UNITY_ID
