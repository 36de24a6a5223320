#pragma once
// What a solve asks for: the arithmetic and the typed options of a run.
//
// Arithmetic: double (IEEE 754, 53 bits), MPFR at a chosen precision, exact
// rationals, or certified (interval arithmetic climbing a ladder of MPFI
// precisions, then exact: certified/). Names as the command line writes them:
// "double", "mpfr:BITS", "exact", "certified", "certified:B1,B2,...",
// "certified:none" (parse_arithmetic / Arithmetic::name are inverse).
// Options are enums, not strings; the command line and the JSON use the
// to_string / parse_* names below.
#include "solution/arithmetic.hpp"        // Arithmetic, parse_arithmetic
#include "floating/cd_disc_floating.hpp"  // Basis, to_string(Basis), parse_basis
#include "kernel/cd_disc.hpp"             // Variant
#include "kernel/prepared_scene.hpp"      // InputMode

#include <string>
#include <utility>
#include <vector>

namespace eccd {

// 3D floating methods (001 section 4 Bézier zero-set; the projection in
// floating point; the sampled baselines of 002 IV on a grid of N instants).
enum class Method { bezier, projection, sampling, marching };

// The two faces of a floating run (docs/architecture.md, "Two faces"): `none` runs the
// published algorithm in plain T (double or MPFR), nothing added, so its
// errors are the algorithm's; `bound` runs the same templates in Bounded<T>
// (number/running_error.hpp), where a sign the error bound cannot decide
// makes that place "undecided". Exact and certified runs have no face.
enum class Guard { none, bound };
const char* to_string(Guard g);
// "none" / "bound" -> Guard; std::invalid_argument ("--guard TEXT: expected none or bound") otherwise.
Guard parse_guard(const std::string& text);
const char* to_string(Method m);
// "bezier", "projection", "sampling:N", "marching:N" -> method and N (0 for the first two).
// std::invalid_argument ("--method TEXT: expected ...") otherwise.
std::pair<Method, int> parse_method(const std::string& text);

struct SolveOptions {
  Arithmetic arith = Arithmetic::exact();
  Basis basis = Basis::bernstein;     // floating only
  Variant variant = Variant::answer;  // 2D: answer, collides, first contact, all contacts (003 VI-C)
  Method method = Method::bezier;     // 3D floating only
  int grid = 0;                       // sampling / marching: N instants (>= 1)
  bool first_contact = false;         // 3D: stop after the first collision interval (001 section 4)
  Guard guard = Guard::bound;         // floating only: as published (none) or guarded (bound)
  // Floating only: start from the scene's numbers rounded to the arithmetic
  // (default, what a user's program does) or from the exactly prepared scene.
  InputMode input = InputMode::rounded;
  // Wall-clock budget of the run in seconds; 0 = the default: 30 s for a
  // floating run (what is left then is undecided, reason "time budget"),
  // none for exact and certified runs.
  double time_limit_s = 0;
  // The method's name as the JSON writes it ("bezier", "sampling:64", ...).
  std::string method_name() const;
};

inline constexpr double kDefaultFloatingSeconds = 30.0;

}  // namespace eccd
