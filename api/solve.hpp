#pragma once
// The API's entry points (namespace eccd; `#include <eccd/eccd.hpp>`):
// read a scene, solve it in a chosen arithmetic, get a typed Solution.
//
//   eccd::Scene s = eccd::read_scene("cases/paper002/example.json");
//   eccd::SolveOptions o;                       // exact by default
//   eccd::Solution r = eccd::solve(s, o);
//   r.answer.collides, r.answer.intervals, r.answer.first_contact, ...
//
// Arithmetic (api/options.hpp): double, MPFR at a chosen precision, exact,
// or certified (intervals of doubles, escalating where a sign is uncertain to
// MPFI intervals, 256 bits by default, then to exact: certified/ladder.hpp;
// Solution::decided_in says where it was decided).
// Errors: SceneError (io/scene_reader.hpp) "FILE: PLACE: what is wrong" for a
// bad scene; std::invalid_argument for a request the pipelines refuse (a
// cycloidal motion in exact arithmetic or with --guard none: double, MPFR and certified solve it;
// scaled-bernstein outside the 3D projection, a bad grid, ...). A floating run never throws for lack of time or
// precision: what it cannot decide is in answer.undecided with the reasons.
#include "api/options.hpp"
#include "api/solution.hpp"
#include "io/scene_error.hpp"  // SceneError
#include "kernel/scene.hpp"

#include <string>

namespace eccd {

// A scene from a file or from text (the scene-format.md contract; throws SceneError).
Scene read_scene(const std::string& path);
Scene scene_from_text(const std::string& json_text, const std::string& label = "<string>");

Solution solve(const Scene& scene, const SolveOptions& options = {});

}  // namespace eccd
