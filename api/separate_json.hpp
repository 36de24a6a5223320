#pragma once
// The JSON form of a separation (format eccd-separate/1): what
// `eccd separate --json` prints and the Python module's eccd.separate returns,
// built in one place so that the two cannot drift apart.
//
// Statement. separation_to_json(scene, file, t, arith, sep) gives, in this
// order: "scene" (the scene's name), "file" (the label it was read from),
// "dim", "arith" (the arithmetic's name), "t" (the exact rational), "status"
// ("separate", "touching", "overlapping" or, floating only, "undecided");
// when separate "plane" {"normal": [...], "offset": o, "meaning"} (each an
// exact rational string: n·x + o = 0, a on the negative side), the tangent
// points of paper 000 section 3 (decimals, irrational in general) and
// "checks": the inequalities that prove the plane (exact: rational strings;
// floating: decimals with "error_bound"); "why" when there is a reason. The
// caller adds "format" and "version" (the command line's stamp_format).
// Paper: 000 section 3 (the construction), api/separate.hpp (the statement).
// Requirements: `sep` is separate_at(scene, t, o) with o.arith == arith.
#include "api/options.hpp"
#include "api/separate.hpp"
#include "kernel/scene.hpp"

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <string>

namespace eccd {

inline constexpr const char* kSeparateFormat = "eccd-separate/1";

nlohmann::ordered_json separation_to_json(const Scene& scene, const std::string& file, const mpq_class& t,
                                          const Arithmetic& arith, const Separation& sep);

}  // namespace eccd
