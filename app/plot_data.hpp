// The data of `eccd plot` (app/plot.cpp): what compare/plots/scene_figure.py
// draws, computed from a scene and the answer `eccd solve` gives for it.
//
// Statement. add_scene_data fills the "eccd-plot-data/1" object: 2D and 3D
// scenes get the objects' outlines at a few instants, their centres' paths
// and contact points ("objects") and the curve of the right panel ("curve":
// 2D the discriminant Δ(t) of f(λ; t), 003 eq. (2); 3D the values of
// F(u, t) = det((u-1)A(t) - uB(t)) on a (u, t) grid, 001 section 4);
// independent motions get the grid of the (s, t) square where A(s) meets
// B(t). The curves are built and evaluated exactly at rational instants and
// only then rounded to double (app/plot.cpp's opening comment says how each
// part is computed). Requirements: the exact kernel (GMP rationals).
#pragma once

#include "kernel/scene.hpp"
#include "solution/solution.hpp"

#include <nlohmann/json.hpp>

namespace eccd::plot_data {

// The scene's objects, curve (or (s, t) grid) and contacts into data; k
// snapshot instants of the objects.
void add_scene_data(nlohmann::json& data, const Scene& s, const Solution& rep, int k);

}  // namespace eccd::plot_data
