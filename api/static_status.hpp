#pragma once
// Static tests: the contact status (separate, touching, overlapping:
// kernel/contact_status.hpp Status) of two ellipses or ellipsoids at one
// instant, from a scene at an instant t or from two shapes at two poses.
//
// Statement. 003 Theorem 6 (2D) and 002 Theorem 1 / 001 section 3 (3D): with
// f(λ) = det(λA - B) the objects are separate iff f has two distinct negative
// roots, touch externally iff a negative double root, overlap otherwise.
// From two poses the objects are x^T diag(1/a², 1/b²[, 1/c²], -1) x <= 0 in
// their own frames, moved by a homogeneous affine pose M (last row 0 ... 0 1,
// det ≠ 0) that maps the object's frame to the world.
//  - exact: the world matrices A = adj(M_a)^T Q_a adj(M_a), B likewise (a
//    positive multiple of M^-T Q M^-1, docs/architecture.md "Use the adjugate"), f by the generic
//    determinant expansion (kernel/characteristic_polynomial.hpp), then the
//    exact static test (kernel/contact_status.hpp 2D, kernel/quartic_status.hpp
//    3D): a proof about the doubles given.
//  - double: a in standard position (001 section 3), b = Rᵀ Q_b R with R =
//    adj(M_b) M_a; in 3D f by 001 Appendix A (kernel/fast_quartic.hpp), in 2D
//    by the same closed form for a 3x3 diagonal A. Fast path: in
//    3D both shapes as unit balls under their poses scaled by the semi-axes
//    (no division), the relative pose by the adjugate, 001 Appendix A with
//    A = diag(1, 1, 1, -1), in plain double with static bounds: the same
//    program run for its magnitude beside the value (two doubles in one SSE2
//    register) and a rounding depth fixed at compile time, then Descartes
//    and the discriminant's sign (kernel/static_filter3d.hpp, each bound
//    derived there; number/static_bound.hpp); in 2D all of it with an
//    a-priori bound carried as a magnitude and a depth (number/forward_bound.hpp),
//    status by 003 Theorem 6's rule. Where a sign is within its bound
//    (Δ ≈ 0: touching, near-touching, or a positive double root of symmetric
//    shapes such as two spheres) the running-bound test follows: the same
//    computation in Bounded<double> (number/running_error.hpp) with the Sturm
//    count in 3D. A status only where an error bound makes every sign it
//    needs certain, uncertain otherwise. It allocates nothing.
// Scene at t: the scene's motions at t (kernel/prepared_scene.hpp for exact;
// the scene's numbers rounded for double and MPFR, as `eccd solve` does);
// Certified (the arithmetic, not Solution::certified) is a filtered predicate that gives the exact
// status: first the double test — from two poses the Bounded<double> test
// above (its running error bound makes a status a proof about the doubles
// given), at a scene's instant the same rules in intervals of doubles that
// enclose the exact motions (number/interval.hpp, to_arithmetic) — and the
// exact test only where that is uncertain (every touching pair, pairs within
// the error bound of touching). One instant: no ladder to climb.
// Errors: std::invalid_argument for a non-positive or non-finite semi-axis, a
// pose that is not affine or is singular, an arithmetic a test has not (the
// poses: double, exact and certified), a cycloidal motion in exact arithmetic.
#include "api/options.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/scene.hpp"

#include <gmpxx.h>

#include <array>
#include <span>

namespace eccd {

struct Ellipse {
  std::array<double, 2> semi_axes;            // a, b > 0 along the object's x and y
  std::array<std::array<double, 3>, 3> pose;  // object frame -> world, homogeneous (last row 0 0 1)
};
struct Ellipsoid {
  std::array<double, 3> semi_axes;            // a, b, c > 0
  std::array<std::array<double, 4>, 4> pose;  // last row 0 0 0 1
};

// The status of the scene's two objects at instant t (0 <= t <= 1) in the arithmetic.
Status status_at(const Scene& scene, const mpq_class& t, const Arithmetic& arith = Arithmetic::exact());

// The status of two shapes at two poses: arith double (default), exact or certified (double filter, then exact).
Status static_status(const Ellipse& a, const Ellipse& b, const Arithmetic& arith = Arithmetic::double_precision());
Status static_status(const Ellipsoid& a, const Ellipsoid& b, const Arithmetic& arith = Arithmetic::double_precision());

// Batched static test from two poses: out[i] = static_status(a[i], b[i], arith) for every i, the same
// answer pair by pair (arith double, exact or certified). In double (and as certified's filter): in 3D each pair
// through the single pair's plain-double program (kernel/static_filter3d.hpp; its lane form over structure-of-
// arrays blocks vectorises only for AVX, which the default build does not target, and was slower in SSE2); in
// 2D blocks of kStaticBatchLanes: the relative pose and f's coefficients with their a-priori bounds
// (ForwardBound) for the whole block in one loop over the pairs' lanes, then the sign rule per pair. A pair the
// fast path cannot decide takes the running-bound path (then exact for certified). Errors: std::invalid_argument
// as static_status (naming the pair's index), or when the spans' sizes differ; out is written only when every
// pair is valid.
inline constexpr int kStaticBatchLanes = 8;
void static_status_batch(std::span<const Ellipsoid> a, std::span<const Ellipsoid> b, std::span<Status> out,
                         const Arithmetic& arith = Arithmetic::double_precision());
void static_status_batch(std::span<const Ellipse> a, std::span<const Ellipse> b, std::span<Status> out,
                         const Arithmetic& arith = Arithmetic::double_precision());

}  // namespace eccd
