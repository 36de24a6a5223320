#pragma once
// The kinds of certificate eccd-check covers, one checker each, and the table
// the dispatcher (certificate/check/verdict.cpp) reads them from.
//
// Statement. Each kind's checker re-proves every claim of a certificate of its
// format against the scene as the checker reads it (certificate/check/scene.hpp)
// and throws Rejected (certificate/check/claims.hpp) naming the first claim that
// fails; it returns normally only when every claim holds, with one line per
// checked claim in `checked`. A new kind is one function here and one row of
// kKinds in verdict.cpp (its format, the older formats it replaces, the function).
// Requirements: nlohmann json; the scene as read by read_check_scene.
#include "certificate/check/scene.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace eccd::check {

using KindChecker = void (*)(const CheckScene& scene, const nlohmann::json& cert, std::vector<std::string>& checked);

// "eccd-certificate/2": rational scenes, 2D and 3D (certificate/check/exact_certificate.cpp).
void check_exact_certificate(const CheckScene& scene, const nlohmann::json& cert, std::vector<std::string>& checked);
// "eccd-bezier-certificate/2": 3D, shared parameter, the interval Bézier proof
// (certificate/check/bezier_certificate.cpp).
void check_bezier_certificate(const CheckScene& scene, const nlohmann::json& cert, std::vector<std::string>& checked);
// "eccd-cycloidal-certificate/2": 2D, static and cycloidal motions, MPFI enclosures
// (certificate/check/cycloidal_certificate.cpp).
void check_cycloidal_certificate(const CheckScene& scene, const nlohmann::json& cert,
                                 std::vector<std::string>& checked);
// "eccd-independent-certificate/3": 2D and 3D, independent parameters (certificate/check/independent_certificate.cpp).
void check_independent_certificate(const CheckScene& scene, const nlohmann::json& cert,
                                   std::vector<std::string>& checked);

}  // namespace eccd::check
