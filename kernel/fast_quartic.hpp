#pragma once
// The five coefficients of the characteristic quartic in 40 multiplications
// (001 Appendix A, "Generate-Characteristic-Polynomial").
//
// Statement. 001 section 3: bring ellipsoid A to standard position, so that
// A = diag(ea, eb, ec, -1) (ea = 1/a², ...), and B to the symmetric matrix
// b = M_Aᵀ M_B⁻ᵀ B M_B⁻¹ M_A. Then f(λ) = det(λA - b) = A4 λ⁴ + A3 λ³ + A2 λ²
// + A1 λ + A0 with the closed forms of Appendix A, evaluated by the paper's
// straight-line program (40 multiplications; the constant term det(b) is
// "E = constant" in the paper and is computed here by cofactors). This is the
// fast path of the static test in double; tests check it against the generic
// determinant expansion (kernel/characteristic_polynomial.hpp) exactly over
// the rationals and to rounding in double.
// Requirements on T: ring operations (constexpr ones for a constant evaluation, number/static_bound.hpp's
// StaticDepth); b must be symmetric (only its upper
// triangle and diagonal are read, as in the paper). The result is a
// std::array (no heap allocation: the static test in double is meant to run
// in well under a microsecond, 001 section 3).
#include <array>

namespace eccd {

// Coefficients in increasing powers of λ: {A0, A1, A2, A3, A4}.
template <class T>
[[gnu::always_inline]] constexpr std::array<T, 5> appendix_a_coefficients(const T& ea, const T& eb, const T& ec,
                                                                          const std::array<std::array<T, 4>, 4>& m) {
  const T &b11 = m[0][0], &b12 = m[0][1], &b13 = m[0][2], &b14 = m[0][3];
  const T &b22 = m[1][1], &b23 = m[1][2], &b24 = m[1][3];
  const T &b33 = m[2][2], &b34 = m[2][3], &b44 = m[3][3];
  T ab = ea * eb, ac = ea * ec, bc = eb * ec, abc = ab * ec;
  T b2233 = b22 * b33;
  T b12s = b12 * b12, b13s = b13 * b13, b14s = b14 * b14;
  T b23s = b23 * b23, b24s = b24 * b24, b34s = b34 * b34;
  T termA = b11 * bc + b22 * ac + b33 * ab;
  T termB = b2233 * ea + b11 * (b33 * eb + b22 * ec);
  T termC = b23s * ea + b13s * eb + b12s * ec;
  T A4 = -abc;
  T A3 = termA - b44 * abc;
  T A2 = termA * b44 - termB + termC - b34s * ab - b14s * bc - b24s * ac;
  T tmp1 = (termB - termC) * b44;
  T tmp2 = b11 * (b2233 + eb * b34s + ec * b24s - b23s);
  T tmp3 = b22 * (ea * b34s + ec * b14s - b13s);
  T tmp4 = b33 * (ea * b24s + eb * b14s - b12s);
  T tmp5 = b34 * (ea * b23 * b24 + eb * b13 * b14) + b12 * (ec * b14 * b24 - b13 * b23);
  tmp5 = tmp5 + tmp5;
  T A1 = -tmp1 + tmp2 + tmp3 + tmp4 - tmp5;
  // A0 = det(-b) = det(b): cofactor expansion with shared 2x2 minors of rows 3, 4.
  T m34_12 = b13 * b24 - b14 * b23, m34_13 = b13 * b34 - b14 * b33, m34_14 = b13 * b44 - b14 * b34;
  T m34_23 = b23 * b34 - b24 * b33, m34_24 = b23 * b44 - b24 * b34, m34_34 = b33 * b44 - b34 * b34;
  T c1 = b22 * m34_34 - b23 * m34_24 + b24 * m34_23;
  T c2 = b12 * m34_34 - b23 * m34_14 + b24 * m34_13;
  T c3 = b12 * m34_24 - b22 * m34_14 + b24 * m34_12;
  T c4 = b12 * m34_23 - b22 * m34_13 + b23 * m34_12;
  T A0 = b11 * c1 - b12 * c2 + b13 * c3 - b14 * c4;
  return {A0, A1, A2, A3, A4};
}

}  // namespace eccd
