#pragma once
// Subresultants of f and g = ∂f/∂λ, with coefficients in any commutative ring.
//
// Statement. For f of degree m and g of degree n < m in λ, and 0 <= j < n, the
// j-th subresultant is S_j = sum_{i<=j} det(M_j^(i)) λ^i, where M_j is the
// (m+n-2j) x (m+n-j) matrix whose rows hold the coefficients of
// λ^(n-j-1) f, ..., f, λ^(m-j-1) g, ..., g, and M_j^(i) keeps its first
// m+n-2j-1 columns and the column of λ^i. psc_j = det(M_j^(j)) is the j-th
// principal subresultant coefficient. Classical facts used by the exact 3D
// pipeline (001 section 4, 002 section III; e.g. Basu-Pollack-Roy, Algorithms
// in Real Algebraic Geometry, ch. 4 and 8):
//   - psc_0 = Res(f, g); for g = f' it is ± lc(f) · Disc(f);
//   - deg gcd(f, g) = the least j with psc_j ≠ 0, and then gcd = S_j.
// At an instant t*, the multiple roots of f(λ; t*) are the roots of
// gcd(f, f') = S_j(t*). Two spheres have psc_0 ≡ 0 (λ = 1 is a double root
// for every t), so the projection is the first psc_k that is not ≡ 0.
// Determinants by kernel/ring_determinant.hpp, so R needs only +, -, * and a
// zero: it may be a scalar, Poly<T>, Bern<T> or ScaledBern<T>.
#include "kernel/ring_determinant.hpp"

#include <vector>

namespace eccd {

// det of a k x k matrix over R (entries a[r][c]), k <= 20.
// The coefficient s_{j,i} (of λ^i) of S_j(f, g), 0 <= i <= j < n; f, g given
// by coefficients in increasing powers of λ (f.size() = m+1, g.size() = n+1).
// psc_j = subresultant_coefficient(f, g, j, j, zero).
template <class R>
R subresultant_coefficient(const std::vector<R>& f, const std::vector<R>& g, int j, int i, const R& zero) {
  const int m = int(f.size()) - 1, n = int(g.size()) - 1;
  const int rows = m + n - 2 * j, cols = m + n - j;
  // Column c holds the power λ^(cols-1-c); keep the first rows-1 columns and that of λ^i.
  auto entry = [&](int r, int power) -> const R* {
    const std::vector<R>& p = r < n - j ? f : g;
    int shift = r < n - j ? (n - j - 1 - r) : (m - j - 1 - (r - (n - j)));
    int k = power - shift;
    return (k >= 0 && k < int(p.size())) ? &p[k] : nullptr;
  };
  std::vector<std::vector<R>> sq(rows, std::vector<R>(rows, zero));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < rows - 1; ++c)
      if (const R* e = entry(r, cols - 1 - c)) sq[r][c] = *e;
    if (const R* e = entry(r, i)) sq[r][rows - 1] = *e;
  }
  return ring_det(sq, zero);
}

// f' coefficients (increasing powers) of f given by increasing powers.
template <class R>
std::vector<R> lambda_derivative(const std::vector<R>& f) {
  std::vector<R> d;
  for (std::size_t i = 1; i < f.size(); ++i) d.push_back(int(i) * f[i]);
  return d;
}

}  // namespace eccd
