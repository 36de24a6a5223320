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
#include "floating/cd_disc_floating.hpp"  // Basis, to_string(Basis), parse_basis
#include "kernel/cd_disc.hpp"              // Variant
#include "kernel/prepared_scene.hpp"       // InputMode

#include <string>
#include <vector>

namespace eccd {

struct Arithmetic {
  enum Kind { Double, Mpfr, Exact, Certified } kind = Exact;
  int mpfr_bits = 0;            // Mpfr: the precision (53..65536); unused otherwise
  std::vector<int> mpfi_rungs;  // Certified: the MPFI precisions tried after intervals of doubles, before exact
  // The precision of the floating numbers the run starts computing with:
  // 53 for double and certified (intervals of doubles first), mpfr_bits for
  // MPFR, 0 for exact. This is the JSON's "precision_bits".
  int precision_bits() const;
  std::string name() const;

  static Arithmetic exact();
  static Arithmetic double_precision();
  static Arithmetic mpfr(int bits);
  static Arithmetic certified(std::vector<int> rungs = {256});
  bool floating() const { return kind == Double || kind == Mpfr; }
};
// "double", "mpfr:BITS", "exact", "certified[:B1,B2,...|:none]"; std::invalid_argument otherwise.
Arithmetic parse_arithmetic(const std::string& text);

// 3D floating methods (001 section 4 Bézier zero-set; the projection in
// floating point; the sampled baselines of 002 IV on a grid of N instants).
enum class Method { bezier, projection, sampling, marching };
const char* to_string(Method m);
// "bezier", "projection", "sampling:N", "marching:N" -> method and N (0 for the first two).
std::pair<Method, int> parse_method(const std::string& text);

struct SolveOptions {
  Arithmetic arith = Arithmetic::exact();
  Basis basis = Basis::bernstein;  // floating only
  Variant variant = Variant::answer;  // 2D: answer, collides, first contact, all contacts (003 VI-C)
  Method method = Method::bezier;  // 3D floating only
  int grid = 0;                    // sampling / marching: N instants (>= 1)
  bool first_contact = false;      // 3D: stop after the first collision interval (001 section 4)
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
