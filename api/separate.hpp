#pragma once
// Separating planes (paper 000, sections 3 and 4) for a scene's two objects:
// the plane at one instant, and whether a kept plane still separates them over
// the whole frame t in [0, 1] (frame coherence).
//
// Statement.
//  - separate_at(scene, t, o): the status at t by the static test
//    (api/static_status.hpp). When separate: 000's construction
//    (kernel/separating_plane.hpp: eigenvectors of the pencil, the polar line
//    V0V1, the tangent points P_R^A, P_L^B) and a plane n·x + o = 0 with a on
//    the negative side, b on the positive side.
//      exact: the construction at 128, 256, ... 4096 bits of MPFR
//      from the exact A(t), B(t); the plane rounded to short rationals (the
//      simplest rational within 2^-16, 2^-32, ... of each entry, then the
//      MPFR value itself) and each candidate checked by exact inequalities
//      (below) until one holds: the plane is proved. Not separate: the exact
//      statement "touching" or "overlapping".
//      certified: first the double construction below, its plane proved by
//      the same inequalities with running error bounds (bounds that hold
//      against the exact scene numbers, so a certain sign is the exact one:
//      `bits` 53, each check's error_bound given); when the double static
//      test or a bounded check cannot decide, the exact path above.
//      double / mpfr:BITS: the construction in that arithmetic from the
//      scene's numbers rounded to it; the plane (exact rationals of the
//      floating values) is checked by the same inequalities evaluated with a
//      running error bound (number/running_error.hpp). "undecided" with why
//      when the static test or a check is within its error bound.
//    The inequalities (checks), with q = M(t)ᵀ(n, o) the plane in the object's
//    own frame (M the scene's motion matrix, Q the scene's shape matrix):
//      qᵀ adj(Q) q > 0   (the plane misses the object; kernel/plane_frame_check.hpp)
//      n·c + o < 0 for a, > 0 for b   (c the object's centre at t).
//    Anyone can recompute them from the scene file and the plane.
//  - plane_separates_on_frame(scene, plane, o): for all t in [0, 1] (000
//    section 4): h_a(t) = q_a(t)ᵀ adj(Q_a) q_a(t) > 0 and h_b(t) > 0 on
//    [0, 1] and the centres on their sides at t = 0 (kernel/plane_frame_check.hpp
//    derives it). Exact: Bernstein signs, else a Sturm count (a proof).
//    double / mpfr: Bernstein signs with error bounds and subdivision,
//    `unknown` where the bound cannot decide. Certified: double first, exact
//    when unknown. An independent-motions scene is accepted (the conditions
//    are per object: a(s) and b(t) for all s and t).
// Errors: std::invalid_argument for t outside [0, 1], a plane of the wrong
// size or with a zero normal, an independent scene (separate_at: one shared t),
// and NotRationalMotion (kernel/prepared_scene.hpp) for a cycloidal motion
// (its motion has no polynomial matrix; not supported by either function).
#include "api/options.hpp"
#include "kernel/scene.hpp"

#include <gmpxx.h>

#include <optional>
#include <string>
#include <vector>

namespace eccd {

struct SeparatingPlane {          // the plane (2D: line) n·x + o = 0, in world coordinates
  std::vector<mpq_class> normal;  // dim entries; a double is an exact rational, so every arithmetic fits
  mpq_class offset;               // object a lies in n·x + o < 0, object b in n·x + o > 0
};

// One inequality of the separation proof (exact), or the same value computed
// with its error bound (double / MPFR).
struct PlaneInequality {
  std::string object;             // "a" or "b"
  std::string quantity;           // e.g. "q^T adj(Q) q, q = M(t)^T (n, o)" or "n.c + o"
  std::string relation;           // "> 0" or "< 0"
  mpq_class value;                // exact value (exact arithmetic) or the computed one
  double error_bound = 0;         // 0 in exact arithmetic
  std::vector<mpq_class> centre;  // the object's centre at t, for "n.c + o"
};

struct Separation {
  std::string status;                                  // "separate" | "touching" | "overlapping" | "undecided"
  std::optional<SeparatingPlane> plane;                // when "separate"
  std::vector<std::vector<mpq_class>> tangent_points;  // 000 section 3: the points of a and b (when separate)
  std::string why;                                     // when "undecided": where and why
  // Beyond the contract: the inequalities that prove the plane (when separate).
  std::vector<PlaneInequality> checks;
  int bits = 0;  // MPFR bits of the construction (exact), or of the arithmetic
};
// The two objects of `scene` at the instant t (rational, in [0, 1]) in the arithmetic of o.
Separation separate_at(const Scene& scene, const mpq_class& t, const SolveOptions& o);
enum class PlaneCheck { separates, fails, unknown };
// Does `plane` separate a(t) and b(t) (a strictly on the negative side, b strictly on the positive side) for
// EVERY t in [0, 1] of the scene's motions? Decided in the arithmetic of o (exact: proved; certified: proved;
// double/MPFR: "unknown" where the error bound cannot decide). 000 section 4 (frame coherence).
PlaneCheck plane_separates_on_frame(const Scene& scene, const SeparatingPlane& plane, const SolveOptions& o);
const char* to_string(PlaneCheck c);

}  // namespace eccd
