#pragma once
// Discriminant of the cubic f(λ) = g3 λ³ + g2 λ² + g1 λ + g0 in λ.
//
// Statement. 003 section III eq. (2):
//   Δ = 18 g3 g2 g1 g0 - 4 g2³ g0 + g2² g1² - 4 g3 g1³ - 27 g3² g0².
// f has a multiple root iff Δ = 0; three simple real roots iff Δ > 0; one real
// and two complex conjugate roots iff Δ < 0. Written once for any ring R in
// which the g_i live: scalars T (Δ at one instant), Poly<T> (power form),
// Bern<T> (Bernstein form) and ScaledBern<T> (scaled Bernstein form), the
// three constructions of 003 section VI-C.
// Requirements on R: R * R, R + R, R - R, int * R.
namespace eccd {

template <class R>
R cubic_discriminant(const R& g3, const R& g2, const R& g1, const R& g0) {
  R g22 = g2 * g2, g11 = g1 * g1, g30 = g3 * g0;
  R t1 = 18 * (g30 * (g2 * g1));
  R t2 = 4 * ((g22 * g2) * g0);
  R t3 = g22 * g11;
  R t4 = 4 * (g3 * (g11 * g1));
  R t5 = 27 * (g30 * g30);
  return t1 - t2 + t3 - t4 - t5;
}

// The double root of a cubic with Δ = 0 and D ≠ 0 is λ0 = P / (2 D), with
//   P = 9 g3 g0 - g2 g1,   D = g2² - 3 g3 g1;
// D = 0 and Δ = 0 means a triple root -g2 / (3 g3).
template <class R>
R double_root_numerator(const R& g3, const R& g2, const R& g1, const R& g0) {
  R a = 9 * (g3 * g0);
  R b = g2 * g1;
  return a - b;
}
template <class R>
R double_root_denominator(const R& g3, const R& g2, const R& g1) {
  R a = g2 * g2;
  R b = 3 * (g3 * g1);
  return a - b;
}

}  // namespace eccd

namespace eccd {

// Discriminant of the quartic f(λ) = a λ⁴ + b λ³ + c λ² + d λ + e (the 3D
// projection, 002 section III / 001 section 4):
//   Δ = 256a³e³ - 192a²bde² - 128a²c²e² + 144a²cd²e - 27a²d⁴ + 144ab²ce²
//     - 6ab²d²e - 80abc²de + 18abcd³ + 16ac⁴e - 4ac³d² - 27b⁴e² + 18b³cde
//     - 4b³d³ - 4b²c³e + b²c²d²,
// which equals Res(f, f') / a (kernel/subresultants.hpp; checked in the tests).
// f has a multiple root iff Δ = 0. Same ring requirements as above.
template <class R>
R quartic_discriminant(const R& a, const R& b, const R& c, const R& d, const R& e) {
  R aa = a * a, bb = b * b, cc = c * c, dd = d * d, ee = e * e;
  R bd = b * d;
  // grouped by powers of a to share products
  R t_a3 = 256 * ((aa * a) * (ee * e));
  R t_a2 = aa * (-192 * (bd * ee) - 128 * (cc * ee) + 144 * (c * (dd * e)) - 27 * (dd * dd));
  R t_a1 = a * (144 * (bb * (c * ee)) - 6 * (bb * (dd * e)) - 80 * (bd * (cc * e)) + 18 * (bd * (c * dd)) +
                16 * ((cc * cc) * e) - 4 * ((cc * c) * dd));
  R t_a0 = -27 * ((bb * bb) * ee) + 18 * ((bb * b) * (c * (d * e))) - 4 * ((bb * b) * (dd * d)) -
           4 * (bb * ((cc * c) * e)) + (bb * cc) * dd;
  return t_a3 + t_a2 + t_a1 + t_a0;
}

}  // namespace eccd
