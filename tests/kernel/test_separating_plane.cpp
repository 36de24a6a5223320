// kernel/separating_plane.hpp: a separating line / plane of two disjoint
// ellipses / ellipsoids from the pencil's eigenvectors (000 section 3,
// Theorems 1 and 2). Checked on disjoint pairs built in the test (a turned
// ellipse or an ellipsoid, and a circle or sphere at a chosen gap along the
// outward normal of a boundary point), against the support function of each
// solid: for (X - c)ᵀ M (X - c) <= 1 the largest value of pᵀ(x, 1) over it is
// p_h + p_xᵀ c + sqrt(p_xᵀ M⁻¹ p_x) (M⁻¹ written from the semi-axes), the
// smallest p_h + p_xᵀ c - sqrt(...). So the plane separates iff A's largest
// value is < 0 < B's smallest, as the header orients it; p is scaled to
// max |p_i| = 1; the tangent points lie on the boundaries of A and B. In
// double and MPFR (200 bits), gaps from 1e-3 to 3. Overlapping pairs (f with
// no negative root) are refused with the reason.
#include "kernel/separating_plane.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

template <class T>
T val(double x) {
  if constexpr (std::is_same_v<T, Mpfr>)
    return Mpfr(x, 200);
  else
    return x;
}
template <class T>
double dbl(const T& x) {
  return scalar_traits<T>::to_double(x);
}
template <class T, int H>
Matrix<T, H> solid(const EMatrix<T, H - 1>& m, const EVector<T, H - 1>& c) {
  constexpr int d = H - 1;
  Matrix<T, H> q;
  const EVector<T, d> mc = m * c;
  for (int i = 0; i < d; ++i) {
    for (int j = 0; j < d; ++j) q[i][j] = m(i, j);
    q[i][d] = q[d][i] = -mc(i);
  }
  q[d][d] = c.dot(mc) - val<T>(1);
  return q;
}
// The extreme values of pᵀ(x, 1) over (x - c)ᵀ M (x - c) <= 1, M⁻¹ = minv.
template <class T, int H>
std::pair<double, double> range(const EVector<T, H>& p, const EMatrix<T, H - 1>& minv, const EVector<T, H - 1>& c) {
  constexpr int d = H - 1;
  const EVector<T, d> px = p.head(d);
  const T mid = p(d) + px.dot(c), half = sqrt_of(T(px.dot(minv * px)));
  return {dbl(T(mid - half)), dbl(T(mid + half))};
}

template <class T, int H>
void check_pairs(std::mt19937_64& rng, int trials) {
  constexpr int d = H - 1;
  std::uniform_real_distribution<double> u(0, 1);
  int separated = 0;
  for (int trial = 0; trial < trials; ++trial) {
    // A: axis-aligned semi-axes, turned (2D) by an angle, centred at c. B: a ball of radius r.
    EMatrix<T, d> rot = EMatrix<T, d>::Identity();
    if constexpr (d == 2) {
      const double th = 6.283 * u(rng);
      rot << val<T>(std::cos(th)), val<T>(-std::sin(th)), val<T>(std::sin(th)), val<T>(std::cos(th));
      // (cos, sin rounded to double: rot is a rotation to 1e-16, which only changes the shape by as much)
    }
    EMatrix<T, d> dg = EMatrix<T, d>::Zero(), dginv = EMatrix<T, d>::Zero();
    EVector<T, d> c, dir;
    for (int i = 0; i < d; ++i) {
      const T ax = val<T>(0.5 + 3 * u(rng));
      dg(i, i) = val<T>(1) / (ax * ax);
      dginv(i, i) = ax * ax;
      c(i) = val<T>(6 * u(rng) - 3);
      dir(i) = val<T>(u(rng) - 0.5);
    }
    const EMatrix<T, d> m = rot * dg * rot.transpose(), minv = rot * dginv * rot.transpose();
    // a boundary point: c + x with xᵀ M x = 1
    EVector<T, d> x = rot * dir;
    x = x / sqrt_of(T(x.dot(m * x)));
    const EVector<T, d> p = c + x;
    EVector<T, d> n = m * x;
    n = n / sqrt_of(n.squaredNorm());
    const T r = val<T>(0.3 + 2 * u(rng)), gap = val<T>(trial % 3 == 0 ? 1e-3 : 3 * u(rng) + 1e-3);
    const EVector<T, d> cb = p + (r + gap) * n;
    const EMatrix<T, d> mb = EMatrix<T, d>::Identity() / (r * r), mbinv = EMatrix<T, d>::Identity() * (r * r);
    const auto pc = separating_plane<T, H>(solid<T, H>(m, c), solid<T, H>(mb, cb));
    INFO("H = " << H << " trial " << trial << " gap " << dbl(gap) << ": " << pc.why);
    REQUIRE(pc.ok);
    const auto [alo, ahi] = range<T, H>(pc.p, minv, c);
    const auto [blo, bhi] = range<T, H>(pc.p, mbinv, cb);
    CHECK(ahi < 0);  // A on the negative side
    CHECK(blo > 0);  // B on the positive side
    (void)alo;
    (void)bhi;
    double mx = 0;
    for (int i = 0; i < H; ++i) mx = std::max(mx, std::abs(dbl(pc.p(i))));
    CHECK(mx == Approx(1).epsilon(1e-15));
    // the tangent points on the boundaries
    const EVector<T, d> ta = pc.tangent_a - c, tb = pc.tangent_b - cb;
    CHECK(dbl(T(ta.dot(m * ta))) == Approx(1).epsilon(1e-9));
    CHECK(dbl(T(tb.dot(mb * tb))) == Approx(1).epsilon(1e-9));
    ++separated;
  }
  CHECK(separated == trials);
}

}  // namespace

TEMPLATE_TEST_CASE("separating_plane separates disjoint ellipses and ellipsoids from balls",
                   "[kernel][separating_plane]", double, Mpfr) {
  std::mt19937_64 rng(4330);
  check_pairs<TestType, 3>(rng, 30);
  check_pairs<TestType, 4>(rng, 20);
}

TEMPLATE_TEST_CASE("separating_plane refuses overlapping pairs and says why", "[kernel][separating_plane]", double,
                   Mpfr) {
  using T = TestType;
  // Unit circles at distance 1 (overlapping): f = -(λ - 1)(λ² - λ + 1) has no negative root.
  EMatrix<T, 2> id = EMatrix<T, 2>::Identity();
  EVector<T, 2> c0 = EVector<T, 2>::Zero(), c1;
  c1 << val<T>(1), val<T>(0);
  const auto pc = separating_plane<T, 3>(solid<T, 3>(id, c0), solid<T, 3>(id, c1));
  CHECK_FALSE(pc.ok);
  CHECK(pc.why.find("fewer than two distinct negative roots") != std::string::npos);
  // Spheres inside one another: the same.
  EMatrix<T, 3> i3 = EMatrix<T, 3>::Identity();
  const auto p3 = separating_plane<T, 4>(solid<T, 4>(i3, EVector<T, 3>::Zero()),
                                         solid<T, 4>(EMatrix<T, 3>(i3 * val<T>(4)), EVector<T, 3>::Zero()));
  CHECK_FALSE(p3.ok);
  CHECK_FALSE(p3.why.empty());
}

}  // namespace ECCD_UNITY_ID
