#pragma once
// FCL as a peer engine: what a robotics user gets from FCL 0.7 (the Flexible
// Collision Library, Debian libfcl-dev) on a scene, as an answer in the scene
// format, so that the harness and `eccd judge` can hold it against the
// certified answer.
//
// Statement. FCL is used as a user's program uses it, in double:
//  * The pose at an instant t (a double). Each body's world quadric
//    A(t) = M(t)^-T Q M(t)^-1 is formed in double from the scene's numbers
//    rounded to double, by the code of the floating pipelines' rounded input
//    mode (floating/rounded_input.hpp round_pair: N(t) with M N = c I, then
//    kernel/quadric.hpp quadric_at: N(t)^T Q N(t), a positive multiple of
//    A(t)). Written A = [[S, b], [b^T, c]], the body is
//    (x - x0)^T S (x - x0) <= k with centre x0 = -S^-1 b and k = x0^T S x0 - c;
//    Eigen's SelfAdjointEigenSolver gives S / k = R diag(1/r_i^2) R^T, so the
//    body is fcl::Ellipsoidd(r) posed by the Transform3d (R, x0) (R's columns
//    the body's axes, flipped to det R = +1). A quadric that is not an
//    ellipse/ellipsoid in double at t (S not positive definite, k <= 0)
//    throws std::invalid_argument.
//  * 2D scenes: each ellipse becomes an ellipsoid with the SAME third
//    semi-axis h along z for both bodies (h: the largest semi-axis of the two
//    at t). This is exact, not an approximation: the section of either
//    ellipsoid at height z is its z = 0 ellipse shrunk about its own centre
//    by sqrt(1 - z^2/h^2), which lies inside the unshrunk ellipse (an
//    ellipse is convex and contains its centre), so the ellipsoids meet iff
//    they meet at z = 0, i.e. iff the ellipses meet.
//  * `fcl/sample:N`: fcl::collide with the default fcl::CollisionRequestd
//    (GJK solver libccd, gjk_tolerance 1e-6, at most 500 GJK iterations:
//    fcl_tolerances() reads them from FCL's own objects; FclOptions sets
//    gjk_tolerance, e.g. the tight 1e-12 of the animation report) at t = k/N,
//    k = 0..N. Runs of colliding samples k..m become intervals [k/N, m/N]
//    (decimals, no brackets), collides = some sample collides, first_contact
//    = the first interval's start; no contacts (FCL reports none). Any
//    rational motion can be sampled.
//  * `fcl/ccd:N`: fcl::continuousCollide with ContinuousCollisionRequestd
//    {num_max_iterations N, solver CCDC_NAIVE, motion CCDM_TRANS}: FCL's
//    naive continuous collision samples t = i/(n-1), i = 0..n-1 with
//    n = min(N, ceil(1/toc_err)), and stops at the first collision, so its
//    answer is collides and first_contact (time_of_contact) only.
//    CCDM_TRANS keeps the start's orientation and moves the translation
//    linearly from the start to the end pose; it expresses a scene exactly
//    only when both bodies have a constant shape and orientation and a
//    translation linear in t with a constant denominator: M(t) = [[L, v(t)],
//    [0, w]] with L and w constant and deg v <= 1 (fcl_ccd_inexpressible
//    checks the exact motion matrix and gives the reason otherwise).
//    Why not FCL's other motions: conservative advancement (CCDC_CONSERVATIVE_
//    ADVANCEMENT) is not implemented for ellipsoids; CCDM_LINEAR (InterpMotion)
//    was measured to give different answers from run to run on the same
//    input, and CCDM_SCREW moves a pure translation by |dT| dT instead of dT
//    (found by the harness); they would measure FCL's bugs, not its arithmetic.
// Availability: FCL is optional at build time (CMake package fcl, defining
// ECCD_HAVE_FCL for this layer); without it fcl_availability() says why and
// fcl_sample / fcl_ccd throw FclUnavailable. No FCL or Eigen header is
// included here.
// Requirements: a scene with rational motions (cycloidal motions throw
// std::invalid_argument, like the floating pipelines).
#include "kernel/answer.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

struct FclAvailability {
  bool available = false;
  std::string version;  // FCL's version ("0.7.0") when available
  std::string reason;   // why not, when not
};
FclAvailability fcl_availability();

// What a caller may change in FCL's collision request.
// gjk_tolerance: fcl::CollisionRequestd::gjk_tolerance, which fcl::collide
// passes to the libccd solver as its collision_tolerance (the MPR/GJK
// termination tolerance; fcl/narrowphase/collision-inl.h); 0 keeps FCL's
// default (1e-6). It reaches fcl::collide (fcl/sample:N and
// fcl_collides_at) only: FCL's naive continuous collision builds its own
// default CollisionRequest inside, so fcl_ccd refuses a non-zero one.
struct FclOptions {
  double gjk_tolerance = 0;  // > 0, or 0 for FCL's default
};

// FCL's settings these pipelines use, read from FCL's request and solver
// objects after `options` are applied ("GJK solver libccd, gjk_tolerance
// 1e-06, ..."); "" without FCL.
std::string fcl_tolerances(const FclOptions& options = {});
// The gjk_tolerance fcl::collide receives with `options` (FCL's default for
// 0), read back from FCL's request object; 0 without FCL.
double fcl_gjk_tolerance(const FclOptions& options = {});

// A call that needs FCL in a build without it.
struct FclUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One body as FCL receives it.
struct FclPose {
  std::array<double, 3> radii{};                    // the semi-axes (2D: the third is the common h)
  std::array<std::array<double, 3>, 3> rotation{};  // columns: the body's axes in the world, det +1
  std::array<double, 3> centre{};                   // 2D: z = 0
};
struct FclScenePose {
  FclPose a, b;
  // The quadrics A(t), B(t) in double that were decomposed ((dim+1) x (dim+1),
  // each a positive multiple of M^-T Q M^-1), for checking the pose.
  std::vector<std::vector<double>> qa, qb;
};
// Both bodies at instant t, computed in double as above.
FclScenePose fcl_pose_at(const Scene& scene, double t);

// "" when fcl/ccd expresses the scene's motions exactly, else why not.
std::string fcl_ccd_inexpressible(const Scene& scene);

// FCL's static test at instant t: fcl::collide with the default request on
// the poses above (throws like fcl_sample).
bool fcl_collides_at(const Scene& scene, double t, const FclOptions& options = {});

// The pipelines (throw FclUnavailable without FCL; std::invalid_argument for
// n < 1, an inexpressible scene (ccd) or a pose that is not an ellipsoid, a
// gjk_tolerance that is negative or not finite, or non-zero for fcl_ccd).
Answer fcl_sample(const Scene& scene, int n, const FclOptions& options = {});
Answer fcl_ccd(const Scene& scene, int n, const FclOptions& options = {});

// An answer as a first-contact-only engine (fcl/ccd) sees it: collides and
// first_contact kept, no intervals, contacts or contact intervals; the
// harness compares fcl/ccd answers with the exact answer's view, so a
// pipeline is not charged for intervals it never claims.
Answer first_contact_view(const Answer& answer);

}  // namespace eccd
