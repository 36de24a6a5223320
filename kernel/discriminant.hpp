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
