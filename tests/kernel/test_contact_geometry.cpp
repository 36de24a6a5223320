// kernel/contact_geometry.hpp: the contact point and common normal of two
// touching ellipses / ellipsoids (003 Lemma 5, the null vector of λ0 A - B).
// Checked on touching pairs built in the test so that the contact is known:
// an ellipse (semi-axes a, b, turned by θ, centred at c) and a point P on its
// boundary at parameter φ, with A's outward unit normal n there (∝ M (P - c));
// a circle of radius r centred at P + r n touches A externally at P, with A's
// normal n. In 3D an ellipsoid and a sphere the same way. In double (within
// 1e-9 of the construction) and MPFR at 200 bits (within 1e-40), over
// seeded random shapes, turns and points, with A and B in both orders (the
// normal then turns round); a pencil whose f has degree < 2 is refused.
#include "kernel/contact_geometry.hpp"

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
double tol() {
  return std::is_same_v<T, Mpfr> ? 1e-40 : 1e-9;
}
template <class T>
double dbl(const T& x) {
  return scalar_traits<T>::to_double(x);
}
// cos and sin of an angle in T (MPFR's at 200 bits for Mpfr).
template <class T>
void cos_sin(double angle, T& c, T& s) {
  if constexpr (std::is_same_v<T, Mpfr>) {
    c = val<T>(0);
    s = val<T>(0);
    Mpfr a = val<T>(angle);
    mpfr_sin_cos(s.get(), c.get(), a.get(), MPFR_RNDN);
  } else {
    c = std::cos(angle);
    s = std::sin(angle);
  }
}

// The world matrix of the solid (X - c)ᵀ M (X - c) <= 1 (H = dim + 1).
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

}  // namespace

TEMPLATE_TEST_CASE("contact_geometry finds the touching point and A's outward normal of an ellipse and a circle",
                   "[kernel][contact_geometry]", double, Mpfr) {
  using T = TestType;
  std::mt19937_64 rng(4328);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 40; ++trial) {
    const T a = val<T>(1 + 4 * u(rng)), b = val<T>(0.5 + 2 * u(rng)), r = val<T>(0.3 + 3 * u(rng));
    T ct, st, cp, sp;
    cos_sin<T>(6.283 * u(rng), ct, st);
    cos_sin<T>(6.283 * u(rng), cp, sp);
    EMatrix<T, 2> rot, dg;
    rot << ct, -st, st, ct;
    dg << val<T>(1) / (a * a), val<T>(0), val<T>(0), val<T>(1) / (b * b);
    const EMatrix<T, 2> m = rot * dg * rot.transpose();
    EVector<T, 2> c, pb;
    c << val<T>(10 * u(rng) - 5), val<T>(10 * u(rng) - 5);
    pb << a * cp, b * sp;
    const EVector<T, 2> p = c + rot * pb;
    EVector<T, 2> n = m * (p - c);
    n = n / sqrt_of(n.squaredNorm());
    EMatrix<T, 2> id;
    id << val<T>(1), val<T>(0), val<T>(0), val<T>(1);
    const Matrix<T, 3> A = solid<T, 3>(m, c), B = solid<T, 3>(EMatrix<T, 2>(id / (r * r)), EVector<T, 2>(p + r * n));
    const ContactGeometry<T, 3> g = contact_geometry<T, 3>(A, B);
    INFO("trial " << trial);
    REQUIRE(g.ok);
    for (int i = 0; i < 2; ++i) {
      CHECK(std::abs(dbl(T(g.point(i) - p(i)))) <= tol<T>() * 10);
      CHECK(std::abs(dbl(T(g.normal(i) - n(i)))) <= tol<T>());
    }
    // and with the roles exchanged: the same point, B's outward normal -n
    const ContactGeometry<T, 3> h = contact_geometry<T, 3>(B, A);
    REQUIRE(h.ok);
    for (int i = 0; i < 2; ++i) {
      CHECK(std::abs(dbl(T(h.point(i) - p(i)))) <= tol<T>() * 10);
      CHECK(std::abs(dbl(T(h.normal(i) + n(i)))) <= tol<T>());
    }
  }
}

TEMPLATE_TEST_CASE("contact_geometry of an ellipsoid and a sphere touching at a chosen point",
                   "[kernel][contact_geometry]", double, Mpfr) {
  using T = TestType;
  std::mt19937_64 rng(4329);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 30; ++trial) {
    const T ax[3] = {val<T>(1 + 3 * u(rng)), val<T>(1 + 3 * u(rng)), val<T>(0.5 + 3 * u(rng))};
    const T r = val<T>(0.5 + 2 * u(rng));
    EVector<T, 3> dir;
    dir << val<T>(u(rng) - 0.5), val<T>(u(rng) - 0.5), val<T>(u(rng) - 0.5);
    dir = dir / sqrt_of(dir.squaredNorm());
    EMatrix<T, 3> m = EMatrix<T, 3>::Zero(), id = EMatrix<T, 3>::Zero();
    EVector<T, 3> c, p, n;
    for (int i = 0; i < 3; ++i) {
      m(i, i) = val<T>(1) / (ax[i] * ax[i]);
      id(i, i) = val<T>(1) / (r * r);
      c(i) = val<T>(4 * u(rng) - 2);
    }
    for (int i = 0; i < 3; ++i) p(i) = c(i) + ax[i] * dir(i);
    n = m * (p - c);
    n = n / sqrt_of(n.squaredNorm());
    const Matrix<T, 4> A = solid<T, 4>(m, c), B = solid<T, 4>(id, EVector<T, 3>(p + r * n));
    const ContactGeometry<T, 4> g = contact_geometry<T, 4>(A, B);
    INFO("trial " << trial);
    REQUIRE(g.ok);
    for (int i = 0; i < 3; ++i) {
      CHECK(std::abs(dbl(T(g.point(i) - p(i)))) <= tol<T>() * 10);
      CHECK(std::abs(dbl(T(g.normal(i) - n(i)))) <= tol<T>());
    }
  }
}

TEST_CASE("contact_geometry refuses a pencil whose f has degree below 2", "[kernel][contact_geometry]") {
  // A = 0: f(λ) = det(-B), a constant.
  Matrix<double, 3> a{}, b{};
  b[0][0] = b[1][1] = 1;
  b[2][2] = -1;
  CHECK_FALSE((contact_geometry<double, 3>(a, b).ok));
}

}  // namespace ECCD_UNITY_ID
