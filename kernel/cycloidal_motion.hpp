#pragma once
// Cycloidal motions (003 section V): A(t), B(t), the coefficients g_i(t) of
// f(λ;t) = det(λA(t) - B(t)) and the discriminant Δ(t), evaluated at an
// instant (or over a whole interval of t, in an enclosing type).
//
// Statement. docs/scene-format.md: an object with a `cycloidal` motion is
// rotated by the angle π(θ0 + θ1 t) about its centre c, then translated by
// V(t) = (x0 + x1 t, y0 + y1 t): X = c + R(t)(X_body - c) + V(t). Its solid at
// t is X^T A(t) X <= 0 with A(t) = N(t)^T Q N(t), N(t) the inverse motion:
//   X_body = R^T X + c - R^T (c + V).
// A `static` object is the same with θ = 0, V = 0. g_3 = det A and g_0 =
// -det B are constant (003 section V: the shapes do not change), g_2 and g_1
// are trigonometric in t; Δ(t) = cubic_discriminant(g) (kernel/discriminant.hpp).
// Δ is not a polynomial in t, so the pipeline evaluates it pointwise (the
// paper's "any suitable numerical solver"); every evaluation here is in the
// scalar R, so with R an enclosing type (Bounded<U>, MpfiInterval; Dual of one
// for Δ') the result encloses the exact value at every t of the argument.
// Requirements on T: ring operations, scalar_traits<T>::from_rational, and
// sin_cos_pi (number/enclosure.hpp) for R = T or Dual<T>.
#include "kernel/discriminant.hpp"
#include "kernel/poly_matrix.hpp"
#include "kernel/scene.hpp"
#include "number/enclosure.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <variant>

namespace eccd {

template <class T>
struct CycloidalObject {
  Matrix<T, 3> q;
  T cx, cy;          // centre (about which it turns)
  T th0, th1;        // angle / π = th0 + th1 t
  T x0, x1, y0, y1;  // translation
};

template <class T>
struct CycloidalPair {
  CycloidalObject<T> a, b;
};

inline bool has_cycloidal_motion(const Scene& s) {
  return std::holds_alternative<CycloidalMotion>(s.a.motion) || std::holds_alternative<CycloidalMotion>(s.b.motion);
}

// The scene's objects as T (rationals rounded or enclosed by from_rational).
// Throws std::invalid_argument if an object's motion is neither static nor
// cycloidal (a rational motion paired with a cycloidal one is not supported).
template <class T>
CycloidalPair<T> cycloidal_pair(const Scene& s, const T& like) {
  auto conv = [&](const Rational& r) { return scalar_traits<T>::from_rational(r, like); };
  auto one = [&](const SceneObject& o, const char* which) {
    CycloidalObject<T> c;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c.q[i][j] = conv(o.Q[i][j]);
    // centre: Q[0:2,0:2] c = -Q[0:2,2] (exactly, in rationals)
    const auto& Q = o.Q;
    Rational det = Q[0][0] * Q[1][1] - Q[0][1] * Q[1][0];
    if (det == 0)
      throw std::invalid_argument(std::string("object ") + which + ": not an ellipse (singular quadratic part)");
    Rational cx = (-Q[0][2] * Q[1][1] + Q[1][2] * Q[0][1]) / det;
    Rational cy = (-Q[1][2] * Q[0][0] + Q[0][2] * Q[1][0]) / det;
    c.cx = conv(cx);
    c.cy = conv(cy);
    Rational z(0);
    if (auto* m = std::get_if<CycloidalMotion>(&o.motion)) {
      c.th0 = conv(m->theta0);
      c.th1 = conv(m->theta1);
      c.x0 = conv(m->x[0]);
      c.x1 = conv(m->x[1]);
      c.y0 = conv(m->y[0]);
      c.y1 = conv(m->y[1]);
    } else if (std::holds_alternative<StaticMotion>(o.motion)) {
      c.th0 = c.th1 = c.x0 = c.x1 = c.y0 = c.y1 = conv(z);
    } else {
      throw std::invalid_argument(std::string("object ") + which + " has a " + motion_type_name(o.motion) +
                                  " motion beside a cycloidal one: only static and cycloidal motions can be combined");
    }
    return c;
  };
  return {one(s.a, "a"), one(s.b, "b")};
}

// A(t) for one object, at t in R (T, or Dual<T> for derivatives).
template <class R, class T>
Matrix<R, 3> cycloidal_quadric_at(const CycloidalObject<T>& o, const R& t) {
  auto lift = [](const T& x) {
    if constexpr (std::is_same_v<R, T>)
      return x;
    else
      return R(x, T(0) * x);
  };
  R s, c;
  sin_cos_pi(R(lift(o.th0) + lift(o.th1) * t), s, c);
  R wx = lift(o.cx) + lift(o.x0) + lift(o.x1) * t, wy = lift(o.cy) + lift(o.y0) + lift(o.y1) * t;
  Matrix<R, 3> n;
  n[0][0] = c;
  n[0][1] = s;
  n[0][2] = lift(o.cx) - (c * wx + s * wy);
  n[1][0] = -s;
  n[1][1] = c;
  n[1][2] = lift(o.cy) - (c * wy - s * wx);
  n[2][0] = R(0);
  n[2][1] = R(0);
  n[2][2] = R(1);
  Matrix<R, 3> qn, a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      qn[i][j] = lift(o.q[i][0]) * n[0][j] + lift(o.q[i][1]) * n[1][j] + lift(o.q[i][2]) * n[2][j];
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      a[i][j] = n[0][i] * qn[0][j] + n[1][i] * qn[1][j] + n[2][i] * qn[2][j];
      a[j][i] = a[i][j];
    }
  return a;
}

// g_0..g_3 of det(λA - B) from the columns of A and B (multilinearity of det).
template <class R>
std::array<R, 4> pencil_coefficients(const Matrix<R, 3>& A, const Matrix<R, 3>& B) {
  auto det = [](const Matrix<R, 3>& x, const Matrix<R, 3>& y, const Matrix<R, 3>& z) {  // columns 0,1,2 from x,y,z
    return x[0][0] * (y[1][1] * z[2][2] - z[1][2] * y[2][1]) - y[0][1] * (x[1][0] * z[2][2] - z[1][2] * x[2][0]) +
           z[0][2] * (x[1][0] * y[2][1] - y[1][1] * x[2][0]);
  };
  std::array<R, 4> g;
  g[3] = det(A, A, A);
  g[2] = -(det(B, A, A) + det(A, B, A) + det(A, A, B));
  g[1] = det(A, B, B) + det(B, A, B) + det(B, B, A);
  g[0] = -det(B, B, B);
  return g;
}

template <class R, class T>
std::array<R, 4> cycloidal_g(const CycloidalPair<T>& p, const R& t) {
  return pencil_coefficients<R>(cycloidal_quadric_at<R>(p.a, t), cycloidal_quadric_at<R>(p.b, t));
}

template <class R, class T>
R cycloidal_delta(const CycloidalPair<T>& p, const R& t) {
  auto g = cycloidal_g<R>(p, t);
  return cubic_discriminant(g[3], g[2], g[1], g[0]);
}

}  // namespace eccd
