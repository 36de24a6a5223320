#pragma once
// The generator families cycloidal and independent: scenes whose motions
// are not the shared-parameter rational motions of the other families.
//
// Statement. Both families are seeded like the others (compare/
// scene_generator.hpp: scene_seed, the note's key=value facts) and every
// number is an exact rational; the kind of answer is known by construction
// and stated in the note (`kind=...`), but the harness never reads it: its
// ground truth is the certified (cycloidal) or the exact (independent)
// answer, and a test checks the construction against the pipelines.
//
//   cycloidal   (2D, 003 section V; motion "cycloidal", reported as degree 1:
//               the translation is linear, the rotation transcendental) A
//               turns at constant angular speed π·θ1 about its centre and
//               translates linearly; B is static or cycloidal (eccd combines
//               only these two). The seed picks the kind:
//                 colliding  both centres pass through one point at a rational
//                            t1 in [1/16, 15/16]: the solids overlap there;
//                 free       A's centre path keeps x <= -(R_A + gap) and B's
//                            x >= R_B + gap (R = the larger semi-axis, a
//                            bound under any rotation; a static B sits at the
//                            origin and A keeps x <= -(R_A + R_B + gap)):
//                            the line x = 0 (or x = -R_B - gap/2) separates them;
//                 touch      two circles (turning, which changes nothing
//                            geometric but everything numeric): the relative
//                            centre path c_A - c_B = (r_A + r_B) n + (t - t0) v τ
//                            with τ ⊥ n, so the distance of the centres is
//                            >= r_A + r_B with equality at t0 only: an
//                            isolated touch (Δ has a double root there; the
//                            certified pipeline says "touch or near miss within ε");
//                 near-miss  the same at distance r_A + r_B + d, d = 10^-e,
//                            e in {2, 4, 6}: never colliding.
//   independent (2D and 3D, "parameters": "independent", 001 section 4; motion
//               "translation", degree 1) A(s) and B(t) move on straight lines
//               (matrix motions: a constant rational rotation, a linear
//               translation). The seed picks the kind:
//                 balls-colliding    two balls whose segments cross: the
//                                    centres coincide at rational (s1, t1);
//                 balls-free         the plane x = 0 separates the two swept volumes;
//                 balls-touch        the segments lie in parallel planes at
//                                    distance r_A + r_B, their projections
//                                    crossing at interior (s*, t*): the swept
//                                    volumes touch at one point only, so
//                                    s_intervals = [[s*, s*]], t_intervals =
//                                    [[t*, t*]] (rotated by a rational rotation);
//                 balls-near-miss    the same at distance r_A + r_B + 10^-6;
//                 ellipsoids-colliding, ellipsoids-free   the same constructions
//                                    for two ellipsoids (exact answers them once
//                                    branch indepx extends it; until then the
//                                    report marks them "no ground truth").
//               Exact arithmetic answers the ball kinds (exact/independent_balls.hpp).
//               In 2D (named 2d-independent-KIND-SEED) the same for discs and
//               ellipses (a constant rational rotation of the plane):
//               discs-colliding, discs-free (the line x = 0 separates the
//               swept areas), ellipses-colliding, ellipses-free, and
//                 discs-touch        two segments of the plane that do not
//                                    cross are nearest at an end of one: A's
//                                    path ends (s = 1) at distance r_A + r_B
//                                    from B's line, coming from the far side,
//                                    where B's centre passes at interior t*:
//                                    s_intervals [[1, 1]], t_intervals [[t*, t*]];
//                 discs-near-miss    the same at distance r_A + r_B + 10^-6.
// Requirements: exact rationals only (a kind is a construction, not a float test).
#include "compare/scene_generator.hpp"

#include <optional>
#include <string>
#include <vector>

namespace eccd {

// Is `family` one of these (cycloidal, independent)?
bool motion_family(const std::string& family);
// The dimensions a motion family is generated in (cycloidal: 2; independent: 2 and 3)
// and the motion name of its scenes.
std::vector<int> motion_family_dims(const std::string& family);
std::string motion_family_motion(const std::string& family);
// The scene of a motion family (nullopt for any other family, which
// generate_scene builds). Throws std::invalid_argument for a spec it cannot
// build (wrong dimension or motion).
std::optional<GeneratedScene> generate_motion_family(const GeneratorSpec& spec);

}  // namespace eccd
