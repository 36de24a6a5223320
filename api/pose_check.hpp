#pragma once
// The papers' per-pose mode (000 section 5, 001 section 5): every checked pair of an
// animation at every key pose, by the static test, keeping the separating
// plane from pose to pose (paper 000 section 4; docs/animation-format.md,
// "The per-pose mode").
//
// Statement. Pose k is the bodies at the key time t_k (k = 0..K), each body
// the solid XᵀA_kX <= 0 with A_k a positive multiple of M_k^-T Q M_k^-1,
// M_k = [[R_k D_k, c_k], [0, 1]] the key pose (kernel/keyframe_motion.hpp at
// τ = 0 of frame k, or τ = 1 of frame K − 1 for the last pose). Written without
// division: M'_k = W·M_k = [[W R D, W c], [0, W]] (W R the quaternion's
// polynomial matrix, W = |q|² > 0), A_k = adj(M'_k)ᵀ Q adj(M'_k) and the dual
// C_k = M'_k adj(Q) M'_kᵀ (= a positive multiple of adj(A_k)). Per pose:
//  1. bounding spheres: body b lies in the ball of centre c_k and radius
//     r_b·‖D_k‖ (api/animate.hpp body_shape_radius, key_deformation_bound);
//     candidates by sweep-and-prune on x (api/sweep_and_prune.hpp), then the
//     sphere test |c_a − c_b| > r_a + r_b in intervals of doubles enclosing
//     the exact numbers: a pair is dropped only when that is proved.
//  2. the plane kept from the pose before (000 section 4: check the kept
//     plane first): p = (n, o) separates a and b iff pᵀC_a p > 0 and
//     pᵀC_b p > 0 (the plane misses each solid: kernel/plane_frame_check.hpp
//     derives the form in the body's frame, qᵀ adj(Q) q > 0 with q = Mᵀp) and
//     (C_a p)_d < 0 < (C_b p)_d (the centres' sides: C e_d is a positive
//     multiple of the homogeneous centre), computed as q = M'ᵀp,
//     qᵀ adj(Q) q and W (adj(Q) q)_d without forming C. double and certified:
//     in intervals of doubles around the exact values (a proof; an uncertain
//     sign is a miss); exact: in rationals. A plane is trusted for the pose it
//     was checked on.
//  3. otherwise the static test (f(λ) = det(λA − B), 002 Theorem 1 / 003
//     Theorem 6: api/static_status.hpp's rules): double: api/static_status.hpp's
//     static_status from the semi-axes and the pose rounded to doubles (as
//     `eccd solve --arith double` rounds a scene) when the shape is
//     axis-aligned and centred, otherwise f's coefficients in intervals (in
//     a's body frame: det(μ Q_a - Rᵀ Q_b R), R = adj(M'_b) M'_a, whose roots
//     are positive multiples of f's, so the same status; for a diagonal Q_a
//     by 001 Appendix A's closed form, kernel/fast_quartic.hpp); a
//     status only where the error bound decides it, else the pair-pose is
//     undecided. certified: those coefficients in intervals of doubles
//     enclosing the exact values, the exact expansion where a sign is
//     uncertain (the exact status of the animation). exact: rationals (in a's
//     frame too).
//     When separate, a new plane is built by 000 section 3
//     (kernel/separating_plane.hpp) in double from the world matrices and
//     kept for the next pose, unchecked until then (the check is the proof).
// A pair not checked at a pose (dropped by stage 1) forgets its plane. A
// pair-pose that is touching or overlapping is an event; one the double test
// cannot decide goes to `undecided`, never to the events. Stage 1 runs for all
// poses first, the poses shared among `threads` threads; then stages 2-3 run
// pose by pose in order, each pose's bodies (M'_k, A_k, computed only
// where a pair needs them) and then its pairs shared among the threads;
// results are stored by position, so nothing depends on the schedule.
// Requirements: the animation is exact (rationals); arithmetic double, exact
// or certified (std::invalid_argument otherwise, and for shards or
// all_intervals, which have no meaning here).
#include "api/animate.hpp"
#include "kernel/contact_status.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace eccd {

struct PoseSummary {
  std::size_t pose = 0;
  std::size_t pairs = 0;             // checked pairs
  std::size_t bounding_volumes = 0;  // settled by stage 1
  std::size_t separating_plane = 0;  // settled by the kept plane (stage 2)
  std::size_t static_test = 0;       // settled or left undecided by the static test (stage 3)
  std::size_t planes_built = 0;      // new planes built at this pose
  std::size_t sweep_examined = 0;    // pairs the sweep looked at (x intervals overlap)
  std::size_t events = 0, undecided = 0;
  double seconds = 0;  // stage 1's time on its thread plus stages 2-3's wall time
};
struct PairPoseStatus {
  std::size_t pose = 0, body_a = 0, body_b = 0;  // body_a < body_b
  Status status = Status::uncertain;
  bool by_plane = false;  // settled by the kept plane
};
struct PairPoseUndecided {
  std::size_t pose = 0, body_a = 0, body_b = 0;
  std::string why;
};

struct PosesResult {
  std::string animation, file, arithmetic;
  int dim = 3;
  std::size_t poses = 0, frames = 0, pairs_per_pose = 0;
  std::vector<std::string> body_names;
  std::vector<Rational> times;
  std::vector<PoseSummary> per_pose;
  std::vector<PairPoseStatus> events;  // touching or overlapping, by pose then pair
  std::vector<PairPoseUndecided> undecided;
  std::vector<PairPoseStatus> tested;  // with AnimateOptions::keep_tested: every pair-pose past stage 1
  std::size_t bounding_volumes = 0, separating_plane = 0, static_test = 0;
  std::size_t plane_checks = 0;  // kept planes checked (hits: separating_plane)
  std::size_t planes_built = 0, plane_build_failed = 0;
  std::size_t sweep_examined = 0;
  bool planes_disabled = false;
  double seconds = 0;
};

// Uses AnimateOptions' solve.arith (double, exact, certified), threads, planes and keep_tested.
PosesResult animate_poses(const Animation& anim, const AnimateOptions& options = {});

// The animation answer object with "mode": "poses" (docs/animation-format.md, "The per-pose mode").
nlohmann::ordered_json poses_result_to_json(const PosesResult& result);

}  // namespace eccd
