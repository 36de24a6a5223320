#pragma once
// A separating plane of two disjoint ellipsoids (a separating line of two
// disjoint ellipses) from the eigenvectors of the pencil: paper 000, section 3
// (Theorems 1 and 2 and the computational procedure after them).
//
// Statement (in this workbench's convention f(μ) = det(μA - B); 000 writes
// det(λA + B), so its λ is -μ). A, B: the two solids XᵀAX <= 0, XᵀBX <= 0 in
// homogeneous world coordinates (any positive multiples). When they are
// disjoint, f has two distinct negative roots μ1 < μ2 < 0 (000's λ3 > λ2 > 0).
// Va, a null vector of μ1 A - B (000's V3), lies inside A, and Vb, a null
// vector of μ2 A - B (000's V2), inside B (Theorem 1); Va and Vb are
// conjugate for both quadrics, and their polar planes A·Va, A·Vb both contain
// the line V0V1 of 000 (in 2D: the point V0). On the line P(s) = Va + s·Vb:
// PᵀAP = aa + s² ab with aa = VaᵀAVa < 0 < ab = VbᵀAVb, PᵀBP = ba + s² bb
// with ba > 0 > bb, so A's tangent points are s = ±sA, sA = sqrt(-aa/ab),
// B's are s = ±sB, sB = sqrt(-ba/bb), and sA < sB since A and B are
// disjoint. A plane through V0V1 and a point S = P(s) with sA < |s| < sB
// misses both (Theorem 2); p = s·ab·(A Va) - aa·(A Vb) is that plane
// (pᵀS = 0). Of the two gaps (s > 0 and s < 0) the one whose plane has the
// centres on opposite sides is taken (the other plane has both on one side),
// with s = ±sqrt(sA sB). The tangent points reported are 000's P_R^A = P(±sA)
// and P_L^B = P(±sB) on the same side, as affine points. p is oriented so
// that pᵀVa·Va_d < 0 (A on the negative side) and scaled to max |p_i| = 1.
// Nothing here is trusted: the plane is checked afterwards (exact inequalities
// or error-bounded ones, api/separate.cpp), and `why` says where a rounded
// construction gave up.
// Requirements on T: double or Mpfr (Eigen scalars, kernel/eigen_scalar.hpp).
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/eigen_scalar.hpp"
#include "kernel/pencil_geometry.hpp"

#include <string>
#include <utility>

namespace eccd {

template <class T, int H>
struct PlaneConstruction {
  bool ok = false;
  std::string why;                         // when !ok: where the construction gave up
  EVector<T, H> p;                         // the plane pᵀX = 0, A on the negative side
  EVector<T, H - 1> tangent_a, tangent_b;  // 000's P_R^A and P_L^B (affine)
};

template <class T, int H>
PlaneConstruction<T, H> separating_plane(const Matrix<T, H>& a, const Matrix<T, H>& b) {
  PlaneConstruction<T, H> out;
  const T zero = a[0][0] - a[0][0];
  std::vector<T> g = characteristic_coefficients_in<T, H>(a, b, zero);
  std::vector<T> neg;
  for (const T& r : small_real_roots(Poly<T>(g)))
    if (sign(r) == Sign::negative) neg.push_back(r);
  if (neg.size() < 2) {
    out.why = "f(λ) = det(λA - B) has fewer than two distinct negative roots in this arithmetic";
    return out;
  }
  const EMatrix<T, H> A = to_eigen<T, H>(a), B = to_eigen<T, H>(b);
  EVector<T, H> va = null_vector<T, H>(EMatrix<T, H>(neg.front() * A - B));
  EVector<T, H> vb = null_vector<T, H>(EMatrix<T, H>(neg[1] * A - B));
  T aa = va.dot(A * va), ab = vb.dot(A * vb), ba = va.dot(B * va), bb = vb.dot(B * vb);
  if (sign(aa) == Sign::positive && sign(bb) == Sign::positive) {  // the roles came out swapped
    std::swap(va, vb);
    aa = va.dot(A * va);
    ab = vb.dot(A * vb);
    ba = va.dot(B * va);
    bb = vb.dot(B * vb);
  }
  if (!(sign(aa) == Sign::negative && sign(ab) == Sign::positive && sign(ba) == Sign::positive &&
        sign(bb) == Sign::negative)) {
    out.why = "the eigenvectors of the two negative roots are not inside A and B in this arithmetic";
    return out;
  }
  const T sa = sqrt_of(T(-aa / ab)), sb = sqrt_of(T(-ba / bb));
  if (!(sa < sb)) {
    out.why = "the tangent points of A and B on the line of the eigenvectors are not disjoint in this arithmetic";
    return out;
  }
  const T s0 = sqrt_of(T(sa * sb));
  const EVector<T, H> pa = A * va, pb = A * vb;
  const int d = H - 1;
  for (int sg : {1, -1}) {
    const T s = sg > 0 ? s0 : T(-s0);
    EVector<T, H> p = (s * ab) * pa - aa * pb;
    T side_a = p.dot(va) * va(d), side_b = p.dot(vb) * vb(d);
    if (sign(T(side_a * side_b)) != Sign::negative) continue;
    if (sign(side_a) == Sign::positive) p = -p;
    T m = abs_of(p(0));
    for (int i = 1; i < H; ++i) m = std::max(m, abs_of(p(i)));
    out.p = p / m;
    const T ta = sg > 0 ? sa : T(-sa), tb = sg > 0 ? sb : T(-sb);
    EVector<T, H> xa = va + ta * vb, xb = va + tb * vb;
    out.tangent_a = xa.head(d) / xa(d);
    out.tangent_b = xb.head(d) / xb(d);
    out.ok = true;
    return out;
  }
  out.why = "neither plane through the polar line has the centres on opposite sides in this arithmetic";
  return out;
}

}  // namespace eccd
