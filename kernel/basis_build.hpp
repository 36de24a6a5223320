#pragma once
// A polynomial built from f's coefficients in the ring of a basis: the one
// `build` of every pipeline policy (kernel/pipeline_policy.hpp).
//
// Statement. The projection polynomials (Δ, P, D of 003 in 2D; the
// discriminant and the subresultant coefficients of 002 in 3D) are ring
// formulas in g_0..g_N, the coefficients of f(λ;t) in λ. 003 section VI-C
// builds Δ in three ways, which differ only in the ring the formula is
// applied in:
//   power             g_i and the formula in the power basis; the result is
//                     then converted to Bernstein form (what 003 found
//                     unstable in double);
//   bernstein         g_i converted to Bernstein form, the formula applied
//                     there (003's Variants 2 and 3);
//   scaled_bernstein  g_i converted to scaled Bernstein form, the formula
//                     applied there by plain convolutions (003's Variant 1).
// What differs between the arithmetics is only the basis (exact: power, the
// result kept in power form since nothing is rounded; floating: the user's
// choice; certified intervals: bernstein) and the zero a vanishing g_i is
// written as (`zero`: of the run's precision).
// Requirements on T: scalar_traits<T>; the ring operations of Poly<T>,
// Bern<T> and ScaledBern<T> (kernel/polynomial.hpp, kernel/bernstein.hpp,
// kernel/scaled_bernstein.hpp).
#include "kernel/bernstein.hpp"
#include "kernel/polynomial.hpp"
#include "kernel/scaled_bernstein.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace eccd {

enum class Basis { power, bernstein, scaled_bernstein };

inline const char* to_string(Basis b) {
  switch (b) {
    case Basis::power:
      return "power";
    case Basis::bernstein:
      return "bernstein";
    default:
      return "scaled-bernstein";
  }
}
inline Basis parse_basis(const std::string& s) {
  if (s == "power") return Basis::power;
  if (s == "bernstein") return Basis::bernstein;
  if (s == "scaled-bernstein" || s == "scaled") return Basis::scaled_bernstein;
  throw std::invalid_argument("unknown basis '" + s + "' (power, bernstein, scaled-bernstein)");
}

// p in Bernstein form of its own degree; the zero polynomial as the single coefficient `zero`.
template <class T>
Bern<T> bernstein_or_zero(const Poly<T>& p, const T& zero) {
  Bern<T> out = to_bernstein(p, std::max(p.degree(), 0));
  if (p.is_zero()) out.b.assign(1, zero);
  return out;
}

// formula(G) from G = {g_0, ..., g_N} already in Bernstein form, in the ring of `basis` (bernstein or
// scaled_bernstein), in Bernstein form.
template <class T, class F>
Bern<T> build_from_bernstein(Basis basis, const std::vector<Bern<T>>& b, F formula) {
  if (basis == Basis::bernstein) return formula(b);
  std::vector<ScaledBern<T>> s(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) s[i] = to_scaled(b[i]);
  return to_bernstein(formula(s));
}

// formula(G), G = {g_0, ..., g_N} in the ring of `basis`, in Bernstein form.
template <class T, class F>
Bern<T> build_in_basis(Basis basis, const std::vector<Poly<T>>& g, F formula, const T& zero) {
  if (basis == Basis::power) return bernstein_or_zero(Poly<T>(formula(g)), zero);
  std::vector<Bern<T>> b(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) b[i] = bernstein_or_zero(g[i], zero);
  return build_from_bernstein(basis, b, formula);
}

// g_0..g_N in Bernstein form, as build_in_basis converts them, kept for the next build with the same g and the
// same zero: the same bits (compared, not assumed), hence the same conversion, so the builds of Δ, P and D of
// one run convert g once, not three times. For scalar types whose bits are their value (trivially copyable:
// double, Bounded<double>, Interval).
template <class T>
struct BernsteinOfG {
  static_assert(std::is_trivially_copyable_v<T>, "g is compared bit for bit");
  std::vector<Poly<T>> seen;
  T seen_zero{};
  std::vector<Bern<T>> bern;

  const std::vector<Bern<T>>& of(const std::vector<Poly<T>>& g, const T& zero) {
    auto same = [](const Poly<T>& x, const Poly<T>& y) {
      return x.c.size() == y.c.size() &&
             (x.c.empty() || std::memcmp(x.c.data(), y.c.data(), x.c.size() * sizeof(T)) == 0);
    };
    bool hit = g.size() == seen.size() && !bern.empty() && std::memcmp(&zero, &seen_zero, sizeof(T)) == 0;
    for (std::size_t i = 0; hit && i < g.size(); ++i) hit = same(g[i], seen[i]);
    if (!hit) {
      seen = g;
      seen_zero = zero;
      bern.assign(g.size(), Bern<T>());
      for (std::size_t i = 0; i < g.size(); ++i) bern[i] = bernstein_or_zero(g[i], zero);
    }
    return bern;
  }
};

// A 2D formula of (g3, g2, g1, g0) (003's Δ, P, D) as the policy's build of G = {g_0, ..., g_3}.
template <class Policy, class G, class F>
auto build_cubic(const Policy& pol, const G& g, F formula) {
  return pol.build(
      g, [formula](const auto& c) { return formula(c[3], c[2], c[1], c[0]); });  // by value: a policy may keep it
}

}  // namespace eccd
