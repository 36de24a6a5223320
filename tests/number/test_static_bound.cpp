// number/static_bound.hpp: one straight-line program run three times —
// double (the value), Magnitude (absolute leaves, subtractions as additions)
// and StaticDepth (the rounding depth, at compile time). Checked against the
// statement: err = 2 d u M̂ bounds |v̂ - v| for the exact v of the program on
// the given doubles (computed in mpq), over a program of the size the static
// filter uses (a 3x3 determinant and products: d known at compile time, a
// static_assert) and seeded random inputs of mixed signs and scales; the
// Magnitude run equals the exact program on |leaves| up to its own rounding
// (within (1 + u)^d); StaticDepth follows the stated rules; ValueMagnitude's
// lanes are the two separate runs bit for bit.
#include "number/static_bound.hpp"

#include <gmpxx.h>

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

// det [[x0 x1 x2] [x3 x4 x5] [x6 x7 x8]] · (x0 - x4) + 2 · x8 · x8: any scalar type with the leaf rule.
template <class T>
constexpr T program(const double (&x)[9]) {
  T l[9];
  for (int i = 0; i < 9; ++i) {
    if constexpr (std::is_same_v<T, StaticDepth>)
      l[i] = StaticDepth::leaf(x[i]);  // constexpr (static_leaf is not: it is the same leaf)
    else
      l[i] = static_leaf<T>(x[i]);
  }
  const T det =
      l[0] * (l[4] * l[8] - l[5] * l[7]) - l[1] * (l[3] * l[8] - l[5] * l[6]) + l[2] * (l[3] * l[7] - l[4] * l[6]);
  return det * (l[0] - l[4]) + 2 * (l[8] * l[8]);
}
mpq_class exact_program(const double (&x)[9], bool absolute) {
  mpq_class l[9];
  for (int i = 0; i < 9; ++i) l[i] = absolute ? abs(mpq_class(x[i])) : mpq_class(x[i]);
  if (!absolute) {
    const mpq_class det =
        l[0] * (l[4] * l[8] - l[5] * l[7]) - l[1] * (l[3] * l[8] - l[5] * l[6]) + l[2] * (l[3] * l[7] - l[4] * l[6]);
    return det * (l[0] - l[4]) + 2 * (l[8] * l[8]);
  }
  const mpq_class det =
      l[0] * (l[4] * l[8] + l[5] * l[7]) + l[1] * (l[3] * l[8] + l[5] * l[6]) + l[2] * (l[3] * l[7] + l[4] * l[6]);
  return det * (l[0] + l[4]) + 2 * (l[8] * l[8]);
}

// depth by the rules: l4 l8 is 1, the 2x2 minor 2, times a leaf 3 (2 + 0 + 1), the three terms summed 5 (two
// additions), times (l0 - l4) (depth 1): 5 + 1 + 1 = 7; 2 · (l8 l8): 2 (a product by an int is a product);
// the final sum max(7, 2) + 1 = 8.
constexpr double kX[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
static_assert(program<StaticDepth>(kX).value() == 8, "the depth of the program by the stated rules");

}  // namespace

TEST_CASE("static bound: 2 d u M bounds the error of the double run", "[number][static_bound]") {
  std::mt19937_64 rng(4343);
  std::uniform_real_distribution<double> u(-1, 1);
  constexpr int d = program<StaticDepth>(kX).value();
  for (int trial = 0; trial < 2000; ++trial) {
    double x[9];
    const double scale = trial % 2 ? 1.0 : 1e3;
    for (double& v : x) v = u(rng) * scale;
    if (trial % 7 == 0) x[4] = x[0];  // a cancelling factor: the exact value is 2 x8²
    const double v = program<double>(x);
    const double m = program<Magnitude>(x).value();
    const mpq_class exact = exact_program(x, false), mag = exact_program(x, true);
    INFO("trial " << trial);
    CHECK(abs(mpq_class(v) - exact) <= mpq_class(2.0 * d * 0x1p-53 * m));
    // the magnitude run is the exact magnitude up to (1 + u)^d
    CHECK(abs(mpq_class(m) - mag) <= mag * mpq_class(2.0 * d * 0x1p-53));
    const ValueMagnitude vm = program<ValueMagnitude>(x);
    CHECK(vm.value() == v);
    CHECK(vm.magnitude() == m);
  }
}

TEST_CASE("static bound: the scalar types' rules", "[number][static_bound]") {
  const Magnitude a = Magnitude::leaf(-3.0), b = Magnitude::leaf(2.0);
  CHECK(a.value() == 3.0);
  CHECK((a - b).value() == 5.0);  // a subtraction adds
  CHECK((-a).value() == 3.0);
  CHECK((a * b).value() == 6.0);
  CHECK((2 * b).value() == 4.0);
  CHECK(Magnitude(-7).value() == 7.0);
  CHECK(static_leaf<Magnitude>(-2.5).value() == 2.5);
  CHECK(static_leaf<double>(-2.5) == -2.5);
  constexpr StaticDepth l = StaticDepth::leaf(1.0);
  static_assert(l.value() == 0);
  static_assert((l + l).value() == 1 && (l * l).value() == 1 && ((l * l) * (l * l)).value() == 3);
  static_assert((-(l * l)).value() == 1 && (3 * l).value() == 1 && StaticDepth(5).value() == 0);
  const ValueMagnitude v = ValueMagnitude::leaf(-3.0) - ValueMagnitude::leaf(2.0);
  CHECK(v.value() == -5.0);
  CHECK(v.magnitude() == 5.0);
  CHECK((-ValueMagnitude::leaf(4.0)).value() == -4.0);
  CHECK((-ValueMagnitude::leaf(4.0)).magnitude() == 4.0);
}

}  // namespace ECCD_UNITY_ID
