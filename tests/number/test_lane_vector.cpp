// Lane vectors (number/lane_vector.hpp): LaneDouble<W> is W independent
// doubles, each operation rounding each lane exactly as the scalar operation
// does (compared bit for bit with scalar double on random values, zeros,
// infinities and NaN); the comparison flags are 1.0 / 0.0 per lane, false
// for a NaN operand, as the scalar forms; LaneMagnitude<W> adds the
// magnitudes for both + and -, multiplies them for *, and a leaf is |x|.
#pragma GCC diagnostic ignored "-Wpsabi"  // the W = 4 lanes below, compiled without AVX (number/lane_vector.hpp)
#include "number/lane_vector.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

bool same_bits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

std::vector<double> sample_values(std::mt19937_64& rng, std::size_t n) {
  std::vector<double> v{0.0, -0.0, 1.0, -3.5, std::numeric_limits<double>::infinity(), std::nan(""), 1e-310, 1e300};
  std::uniform_real_distribution<double> m(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-60, 60);
  while (v.size() < n) v.push_back(std::ldexp(m(rng), e(rng)));
  return v;
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("LaneDouble<W> rounds each lane as scalar double does", "[number][lane_vector]", ((int W), W), 2,
                       4) {
  std::mt19937_64 rng(375);
  const std::vector<double> xs = sample_values(rng, 64), ys = sample_values(rng, 64);
  std::vector<double> ysh(ys.rbegin(), ys.rend());  // pair every special value with others
  for (std::size_t i = 0; i + W <= xs.size(); i += W) {
    const auto a = LaneDouble<W>::load(&xs[i]), b = LaneDouble<W>::load(&ysh[i]);
    double out[8];
    for (int l = 0; l < W; ++l) {
      const double x = xs[i + l], y = ysh[i + l];
      INFO(x << " op " << y);
      CHECK(same_bits((a + b)[l], x + y));
      CHECK(same_bits((a - b)[l], x - y));
      CHECK(same_bits((a * b)[l], x * y));
      CHECK(same_bits((a / b)[l], x / y));
      CHECK(same_bits((-a)[l], -x));
      CHECK(same_bits((3 * b)[l], 3.0 * y));
      CHECK(same_bits(lane_abs(a)[l], lane_abs(x)));
      CHECK(lane_gt(a, b)[l] == lane_gt(x, y));
      CHECK(lane_ge(a, b)[l] == lane_ge(x, y));
      CHECK(lane_le(a, b)[l] == lane_le(x, y));
      CHECK(lane_eq(a, b)[l] == lane_eq(x, y));
      CHECK(lane_not_gt(a, b)[l] == lane_not_gt(x, y));
    }
    (a * b).store(out);
    for (int l = 0; l < W; ++l) CHECK(same_bits(out[l], xs[i + l] * ysh[i + l]));
  }
  // the scalar flags: NaN compares false, and "not greater" is its negation
  const double not_a_number = std::nan("");
  CHECK(lane_gt(not_a_number, 1.0) == 0.0);
  CHECK(lane_le(not_a_number, 1.0) == 0.0);
  CHECK(lane_not_gt(not_a_number, 1.0) == 1.0);
  CHECK(lane_eq(2.0, 2.0) == 1.0);
  CHECK(std::signbit((-LaneDouble<W>(0.0))[0]));  // negation flips the sign bit, also of 0
}

TEMPLATE_TEST_CASE_SIG("LaneMagnitude<W> bounds magnitudes lane by lane", "[number][lane_vector]", ((int W), W), 2, 4) {
  double xs[8] = {1.5, -2.0, 0.0, -0.25, 3.0, -1.0, 8.0, -0.5};
  double ys[8] = {-4.0, 0.5, -1.0, 2.0, -3.0, 1.0, 0.125, -64.0};
  using M = LaneMagnitude<W>;
  const M a = M::leaf(LaneDouble<W>::load(xs)), b = M::leaf(LaneDouble<W>::load(ys));
  for (int l = 0; l < W; ++l) {
    const double ax = std::fabs(xs[l]), ay = std::fabs(ys[l]);
    CHECK(a.value()[l] == ax);
    CHECK((a + b).value()[l] == ax + ay);
    CHECK((a - b).value()[l] == ax + ay);  // a difference's magnitude bound is the sum
    CHECK((a * b).value()[l] == ax * ay);
    CHECK((-a).value()[l] == ax);
    CHECK((3 * a).value()[l] == 3 * ax);
    CHECK(M(-2).value()[l] == 2.0);
  }
}

}  // namespace ECCD_UNITY_ID
