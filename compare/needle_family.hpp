#pragma once
// The needle family: a static unit circle or sphere and a needle, an ellipse
// or ellipsoid of semi-axes (1, R) or (1, R, 1) with R from 1 to 1e300, whose
// centre moves along the x axis past it. The guard of the floating pipelines
// (number/running_error.hpp) must never be confidently wrong on it: every
// guarded answer agrees with the exact one or says undecided where it differs.
//
// Construction (exact, checked against the exact pipeline by the tests). The
// needle's axis of length R points along y, so along x it is as thin as the
// circle/sphere (semi-axis 1), and the two meet iff |x(t)| <= 2 (both
// symmetric about y = 0 (and z = 0), so they meet iff they meet on the x axis).
//   kind "miss"      x(t) = -(3 + g) + 4t - 4t², g = 10^-gap_exponent
//                    (1e-3 ... 1e-12): closest at t = 1/2, a gap g; free.
//   kind "touch-end" x(t) = -3 + t: one external touch at t = 1.
//   kind "touch-mid" x(t) = -3 + 4t - 4t²: one tangential touch at t = 1/2.
// The hard cases: the 3D miss with g = 1e-3 and R = 1e20, where a guard that
// trusts a negative value at the peak found would answer "collides" on
// [0.4826, 0.5174] in double (R = 1e100: in mpfr:128 and mpfr:256), and the
// touch at the end with R = 1e20 (an interval [0.99994, 1] in double).
// Motions: 3D `euler` with e = (1, 0, 0, 0) and the translation above; 2D a
// `matrix` motion [[1, 0, x(t)], [0, 1, 0], [0, 0, 1]].
// Requirements: none (exact decimals written as text).
#include "compare/scene_generator.hpp"

#include <string>
#include <vector>

namespace eccd {

struct NeedleSpec {
  int dim = 3;
  int r_exponent = 20;        // R = 10^r_exponent (0 .. 300)
  std::string kind = "miss";  // miss | touch-end | touch-mid
  int gap_exponent = 3;       // miss: g = 10^-gap_exponent (>= 1)
};

// The scene (GeneratedScene::spec.family is "needle"; t0 the touch or closest instant).
GeneratedScene needle_scene(const NeedleSpec& spec);

// The family's grid: dims {2, 3} x R in {1, 1e5, 1e20, 1e50, 1e100, 1e200,
// 1e300} x {miss 1e-3, 1e-6, 1e-9, 1e-12, touch-end, touch-mid}.
std::vector<NeedleSpec> needle_family_plan();

}  // namespace eccd
