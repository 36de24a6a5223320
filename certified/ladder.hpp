#pragma once
// The certified ladder (`--arith certified`): the 2D or 3D projection
// pipeline (kernel/cd_disc.hpp, kernel/ccd_projection.hpp) in interval
// arithmetic, up a ladder of rungs — intervals of doubles, then MPFI
// intervals at each precision of `mpfi_rungs` (increasing) — and, where every
// rung leaves a sign uncertain (Escalate, certified/certified_policy.hpp, or
// an undecided instant), the exact pipeline (exact/cd_disc_exact.hpp). A
// multiple root (every touch scene) skips the remaining MPFI rungs: no
// precision separates it. The Solution is certified whichever rung decided;
// decided_in names that rung, escalations why each lower rung gave up.
// Requirements: a prepared pair (kernel/prepared_scene.hpp), N = 3 (2D) or 4 (3D).
#include "certified/solution.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace eccd {

template <int N>
Solution run_certified(const PreparedPair<N>& p, const std::vector<int>& mpfi_rungs, Variant variant,
                       bool first_contact);

// A cycloidal scene (2D, not rational: kernel/cycloidal_cd_disc.hpp) in MPFI
// interval arithmetic at each precision of mpfi_rungs (128 if none) until
// nothing is undecided: every simple root of Δ enclosed in a proved bracket,
// every cell proved; what stays undecided (a possible double root: a touch or
// a near miss) is reported with the proved bound on |Δ| there, never as a
// touch. There is no exact rung (exact arithmetic cannot represent it).
Solution run_certified_cycloidal(const Scene& scene, const std::vector<int>& mpfi_rungs, Variant variant);

// The exact pipeline on a prepared pair: a certified Solution (basis "exact").
template <int N>
Solution run_exact(const PreparedPair<N>& p, Variant variant, bool first_contact);

}  // namespace eccd
