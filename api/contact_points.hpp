#pragma once
// Contact points and normals of a solved 3D scene.
//
// Statement. For each external contact of the answer (an isolated instant
// t* of external tangency) the contact point is the null vector of
// λ0 A(t) - B(t) at the negative double root λ0, and the common normal the
// gradient of a's quadric there (kernel/contact_geometry.hpp). t is the
// instant as the run knows it: the midpoint of its bracket (exact, certified)
// or its floating value. Computed in the run's arithmetic: double, MPFR at the
// run's bits, and for exact and certified runs from the exact A(t), B(t) at
// the rational t in MPFR at 256 bits (the point is irrational in general).
// Display only: nothing is decided from them. 2D points come from the
// pipelines themselves (003 Lemma 5, kernel/cd_disc.hpp), with their normals.
// Requirements: a shared-parameter 3D scene with rational motions; anything
// else is left as it is.
#include "api/solution.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/scene.hpp"

namespace eccd {

// Fills solution.answer.contact_points (one per contact) for a 3D scene whose run left them out.
// prepared: the scene's exactly prepared pair when the caller has it already (an exact or certified run), so
// that it is not prepared a second time (that costs a tenth of a certified 3D query); null: prepared here if needed.
void add_contact_points_3d(const Scene& scene, Solution& solution, const PreparedPair<4>* prepared = nullptr);

}  // namespace eccd
