#pragma once
// The exact oracle at a rational instant (certified/ladder.hpp: escalate one
// decision, not the scene).
//
// Statement. At a rational instant t the motions of a prepared pair are
// exact rationals, so A(t), B(t) and the coefficients g_0..g_H of
// f(λ; t) = det(λA(t) − B(t)) (003 eq. (1), 002 section III) are exact
// rationals, computed from the pair's rational matrices with a few dozen
// products: the entries of the motion evaluated at t, A(t) and B(t)
// (kernel/quadric.hpp on numbers), det(kA(t) − B(t)) for k = 0..H by
// Gaussian elimination over Q, and the interpolating polynomial in λ.
// From them, without building any projection polynomial:
//   - the static test at t (kernel/contact_status.hpp in 2D, 002 Theorem 1 /
//     kernel/quartic_status.hpp in 3D) is an exact decision;
//   - the value at t of any ring formula of g_0..g_H (Δ, P, D, the quartic
//     discriminant, a subresultant coefficient s_{j,i}) is exact: the formula
//     commutes with evaluation at t, so formula(g(t)) = formula(g)(t).
// The certified policy (certified/certified_policy.hpp) takes this interface
// by pointer, so it stays templated over its interval scalar and includes no
// exact pipeline; the ladder (certified/ladder.cpp) fills it from the
// PreparedPair. g_at(t) equals the exact pipeline's characteristic_of(pair)
// evaluated at t (tests/certified/test_local_escalation.cpp).
// Requirements: H = 3 (2D) or 4 (3D); t rational (any, not only dyadic).
#include "kernel/contact_status.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/quartic_status.hpp"

#include <vector>

namespace eccd {

// f's coefficients g_0..g_H at a rational instant, exactly; and the static test there.
struct ExactPointOracle {
  virtual ~ExactPointOracle() = default;
  virtual std::vector<Rational> g_at(const Rational& t) const = 0;
  Status status_at(const Rational& t) const {
    const std::vector<Rational> g = g_at(t);
    if (g.size() == 4) return cubic_contact_status(g[3], g[2], g[1], g[0]);
    return quartic_contact_status(g);
  }
};

template <int H>
class PreparedPointOracle final : public ExactPointOracle {
 public:
  explicit PreparedPointOracle(const PreparedPair<H>& p) : p_(p) {}
  std::vector<Rational> g_at(const Rational& t) const override {
    Matrix<Rational, H> na{}, nb{};
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        na[i][j] = p_.na[i][j].is_zero() ? Rational(0) : p_.na[i][j](t);
        nb[i][j] = p_.nb[i][j].is_zero() ? Rational(0) : p_.nb[i][j](t);
      }
    const Rational zero(0);
    const auto a = moving_quadric_in<Rational, Rational, H>(p_.qa, na, zero);
    const auto b = moving_quadric_in<Rational, Rational, H>(p_.qb, nb, zero);
    // f(λ) = det(λA − B) at λ = 0..H (Gaussian elimination over Q), then the
    // interpolating polynomial's coefficients (Newton's divided differences):
    // H + 1 small determinants instead of the 2^H of the expansion.
    std::vector<Rational> c(H + 1);
    for (int k = 0; k <= H; ++k) {
      Matrix<Rational, H> m;
      for (int i = 0; i < H; ++i)
        for (int j = 0; j < H; ++j) m[i][j] = Rational(k) * a[i][j] - b[i][j];
      c[k] = det(m);
    }
    for (int j = 1; j <= H; ++j)  // divided differences on the nodes 0..H
      for (int k = H; k >= j; --k) c[k] = (c[k] - c[k - 1]) / Rational(j);
    std::vector<Rational> g(H + 1, zero);  // Σ c_k Π_{i<k} (λ − i), expanded from the top
    g[0] = c[H];
    for (int k = H - 1; k >= 0; --k) {
      for (int i = H; i >= 1; --i) g[i] = g[i - 1] - Rational(k) * g[i];
      g[0] = c[k] - Rational(k) * g[0];
    }
    return g;
  }

 private:
  static Rational det(Matrix<Rational, H> m) {
    Rational d(1);
    for (int col = 0; col < H; ++col) {
      int piv = col;
      while (piv < H && sgn(m[piv][col]) == 0) ++piv;
      if (piv == H) return Rational(0);
      if (piv != col) {
        std::swap(m[piv], m[col]);
        d = -d;
      }
      d *= m[col][col];
      for (int r = col + 1; r < H; ++r) {
        if (sgn(m[r][col]) == 0) continue;
        const Rational f = m[r][col] / m[col][col];
        for (int k = col + 1; k < H; ++k) m[r][k] -= f * m[col][k];
      }
    }
    return d;
  }
  const PreparedPair<H>& p_;
};

}  // namespace eccd
