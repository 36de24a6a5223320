#pragma once
// Test support: rigid poses in double as the static-test API takes them
// (api/static_status.hpp): a 2D rotation by an angle plus a translation, and a
// 3D rotation from a (normalised) quaternion plus a translation. The rotation
// matrix is rounded to doubles, so not exactly orthogonal: any affine pose is
// allowed by the API, and the exact pipeline reads these doubles exactly.
#include <array>
#include <cmath>

namespace eccd::test {

inline std::array<std::array<double, 3>, 3> pose2(double angle, double x, double y) {
  double c = std::cos(angle), s = std::sin(angle);
  return {{{c, -s, x}, {s, c, y}, {0, 0, 1}}};
}

inline std::array<std::array<double, 4>, 4> pose3(std::array<double, 4> q, double x, double y, double z) {
  double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& v : q) v /= n;
  auto [w, a, b, c] = q;
  return {{{1 - 2 * (b * b + c * c), 2 * (a * b - w * c), 2 * (a * c + w * b), x},
           {2 * (a * b + w * c), 1 - 2 * (a * a + c * c), 2 * (b * c - w * a), y},
           {2 * (a * c - w * b), 2 * (b * c + w * a), 1 - 2 * (a * a + b * b), z},
           {0, 0, 0, 1}}};
}

}  // namespace eccd::test
