#pragma once
// The contact point and the common normal of two ellipses / ellipsoids that
// touch externally (reported with every contact instant: api/contact_points.hpp).
//
// Statement. At an external contact f(λ) = det(λA - B) has a negative double
// root λ0 (003 Theorem 6 in 2D; 002 Theorem 1 in 3D), λ0·A - B has rank
// H - 1, and its null vector X is the contact point (003 Lemma 5 in 2D; the
// same argument in 3D: (λ0 A - B)X = 0 gives XᵀAX = XᵀBX/λ0, and the touching
// point is the one point on both boundaries). Since B·X = λ0·A·X with λ0 < 0,
// the gradients of the two quadrics at X, (A X) and (B X) restricted to the
// first dim coordinates, are opposite: the common normal. `normal` is the unit
// outward normal of A at X (pointing from A towards B); B's outward normal is
// its negative.
// At an instant t that only approximates the contact (a floating root, or a
// rational point of an exact bracket) f has two close negative roots instead
// of a double one; λ0 is taken as the negative critical point of f (root of
// f') where |f| is smallest, which is the double root at the contact itself.
// Display only: nothing is decided from these values.
// Requirements on T: double or Mpfr (kernel/eigen_scalar.hpp).
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/eigen_scalar.hpp"
#include "kernel/pencil_geometry.hpp"

namespace eccd {

template <class T, int H>
struct ContactGeometry {
  bool ok = false;
  EVector<T, H - 1> point, normal;  // the contact point; A's unit outward normal there
};

template <class T, int H>
ContactGeometry<T, H> contact_geometry(const Matrix<T, H>& a, const Matrix<T, H>& b) {
  ContactGeometry<T, H> out;
  const T zero = a[0][0] - a[0][0];
  const Poly<T> f(characteristic_coefficients_in<T, H>(a, b, zero));
  if (f.degree() < 2) return out;
  bool have = false;
  T lam = zero, best = zero;
  for (const T& c : small_real_roots(derivative(f))) {
    if (sign(c) != Sign::negative) continue;
    T v = abs_of(f(c));
    if (!have || v < best) {
      have = true;
      lam = c;
      best = v;
    }
  }
  if (!have) return out;
  const EMatrix<T, H> A = to_eigen<T, H>(a), B = to_eigen<T, H>(b);
  const EVector<T, H> x = null_vector<T, H>(EMatrix<T, H>(lam * A - B));
  constexpr int d = H - 1;
  if (sign(x(d)) == Sign::zero) return out;
  const EVector<T, H> X = x / x(d);
  const EVector<T, H> grad = A * X;
  const EVector<T, d> n = grad.head(d);
  const T len = sqrt_of(n.squaredNorm());
  if (sign(len) == Sign::zero) return out;
  out.point = X.head(d);
  out.normal = n / len;
  out.ok = true;
  return out;
}

}  // namespace eccd
