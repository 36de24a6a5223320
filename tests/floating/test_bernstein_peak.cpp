// bern_argmax (floating/bernstein_peak.hpp): the peak of a Bernstein
// polynomial on [0, 1] in double, MPFR and double with a running error bound
// (Bounded<double>), against the exact maximum.
//
// The reference: f is built from its derivative f'(u) = c (u - r1)...(u - rm)
// with rational r_i, so f's maximum on [0, 1] is exactly the largest of f(0),
// f(1) and f(r_i) for r_i in [0, 1] (mpq_class). Checked:
//   - the witness u lies in [0, 1] and the value returned is f's value there
//     (the exact f(u) within the rounding of one evaluation; for Bounded, within
//     its own bound);
//   - the witness is a peak: max f - f(u) is below the rounding of the
//     arithmetic. The header's argument: u to 2^-(bits/2 + 6) of a simple
//     maximum gives the value to |f''| 2^-(bits + 12); with |f''| <= 2^6 here
//     and the evaluation's rounding that is below 2^-40 in double and 2^-150
//     at 200 bits;
//   - a positive maximum yields a witness with exact f(u) > 0 (what the static
//     test needs: any u with F(u) > 0 proves separation);
//   - the witness of a clear interior maximum at a simple critical point r*
//     lies within 16 · 2^-(bits/2 + 6) of r* (the header's location claim);
//   - degrees 0 and 1 (no interior critical point), a maximum at an end, a
//     double root of f' (an inflection: no extremum there).
#include "floating/bernstein_peak.hpp"
#include "compare/seeded_rng.hpp"
#include "number/mpfr_real.hpp"
#include "tests/support/exact_values.hpp"

#include <mpfr.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

mpz_class binom(int n, int k) {
  mpz_class r;
  mpz_bin_uiui(r.get_mpz_t(), unsigned(n), unsigned(k));
  return r;
}

// Monomial coefficients (lowest first) to Bernstein of the same degree: b_j = sum_{i <= j} C(j, i) / C(n, i) a_i.
std::vector<mpq_class> to_bern(const std::vector<mpq_class>& a) {
  const int n = int(a.size()) - 1;
  std::vector<mpq_class> b(a.size(), mpq_class(0));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= j; ++i) {
      mpq_class w(binom(j, i), binom(n, i));
      w.canonicalize();  // gmpxx's (num, den) constructor does not
      b[j] += a[i] * w;
    }
  return b;
}

mpq_class value(const std::vector<mpq_class>& a, const mpq_class& x) {
  mpq_class r = 0;
  for (int i = int(a.size()) - 1; i >= 0; --i) r = r * x + a[i];
  return r;
}

// f with f' = c (u - r1)...(u - rm) and f(0) = f0, in monomial form.
std::vector<mpq_class> from_derivative_roots(const mpq_class& c, const std::vector<mpq_class>& roots,
                                             const mpq_class& f0) {
  std::vector<mpq_class> d{c};
  for (const auto& r : roots) {
    std::vector<mpq_class> e(d.size() + 1, mpq_class(0));
    for (std::size_t i = 0; i < d.size(); ++i) {
      e[i + 1] += d[i];
      e[i] -= r * d[i];
    }
    d = e;
  }
  std::vector<mpq_class> f{f0};
  for (std::size_t i = 0; i < d.size(); ++i) f.push_back(d[i] / int(i + 1));
  return f;
}

template <class T>
struct Kind;
template <>
struct Kind<double> {
  static double of(const mpq_class& q) { return q.get_d(); }
  static mpq_class exact(const double& x) { return mpq_class(x); }
  static int bits() { return 53; }
  static mpq_class tol() { return mpq_class(1, mpz_class(1) << 40); }
  static mpq_class eval_tol(const double&) { return mpq_class(1, mpz_class(1) << 45); }
};
template <>
struct Kind<Mpfr> {
  static Mpfr of(const mpq_class& q) { return Mpfr(q, 200); }
  static mpq_class exact(const Mpfr& x) {  // mpfr_get_q: exact, and cheap for 0 too
    mpq_class q;
    mpfr_get_q(q.get_mpq_t(), x.get());
    return q;
  }
  static int bits() { return 200; }
  static mpq_class tol() { return mpq_class(1, mpz_class(1) << 150); }
  static mpq_class eval_tol(const Mpfr&) { return mpq_class(1, mpz_class(1) << 180); }
};
template <>
struct Kind<Bounded<double>> {
  static Bounded<double> of(const mpq_class& q) {
    return scalar_traits<Bounded<double>>::from_rational(q, Bounded<double>());
  }
  static mpq_class exact(const Bounded<double>& x) { return mpq_class(x.value()); }
  static int bits() { return 53; }
  static mpq_class tol() { return mpq_class(1, mpz_class(1) << 40); }
  // the running bound covers the value's error against f's exact coefficients' value at u
  static mpq_class eval_tol(const Bounded<double>& x) { return mpq_class(x.bound()); }
};

template <class T>
void check_peak(const std::vector<mpq_class>& mono, const std::vector<mpq_class>& roots) {
  const std::vector<mpq_class> bq = to_bern(mono);
  Bern<T> f;
  for (const auto& q : bq) f.b.push_back(Kind<T>::of(q));
  const Peak<T> p = bern_argmax(f, Kind<T>::bits());
  mpq_class best = std::max(value(mono, 0), value(mono, 1));
  for (const auto& r : roots)
    if (r >= 0 && r <= 1) best = std::max(best, value(mono, r));
  const mpq_class u = Kind<T>::exact(p.u), v = Kind<T>::exact(p.value);
  INFO("degree " << mono.size() - 1 << ", max " << best.get_d() << ", witness u " << u.get_d());
  REQUIRE(u >= 0);
  REQUIRE(u <= 1);
  const mpq_class fu = value(mono, u);
  // Bounded: the bound is against the exact coefficients; double and Mpfr: the coefficients' rounding too
  CHECK(test::abs_q(v - fu) <= Kind<T>::eval_tol(p.value));
  CHECK(best - fu >= 0);
  CHECK(best - fu <= Kind<T>::tol());
  if (best > mpq_class(1, 1000)) CHECK(fu > 0);
  // A clear interior maximum at a simple root r* of f' (every other candidate lower by more than 1/1000, the
  // neighbouring roots of f' more than 1/100 away): the witness lies within 2^-(bits/2 + 6) of r* up to a
  // factor 16 (the header: located to 2^-(bits/2 + 6) of its piece, pieces no wider than [0, 1]).
  mpq_class second = -1000000;
  std::optional<mpq_class> at;
  for (const auto& r : roots)
    if (r > 0 && r < 1 && value(mono, r) == best) at = r;
  if (!at) return;
  bool clear = std::count(roots.begin(), roots.end(), *at) == 1;  // a simple root of f'
  for (const auto& r : roots)
    if (r != *at) clear = clear && test::abs_q(r - *at) > mpq_class(1, 100);
  for (const mpq_class& x : {mpq_class(0), mpq_class(1)}) second = std::max(second, value(mono, x));
  for (const auto& r : roots)
    if (r != *at && r >= 0 && r <= 1) second = std::max(second, value(mono, r));
  if (!clear || best - second <= mpq_class(1, 1000)) return;
  const int e = Kind<T>::bits() / 2 + 6 - 4;
  CHECK(test::abs_q(u - *at) <= mpq_class(1, mpz_class(1) << e));
}

}  // namespace

TEMPLATE_TEST_CASE("bern_argmax finds the exact maximum of polynomials with known critical points",
                   "[floating][bernstein_peak]", double, Mpfr, Bounded<double>) {
  SeededRng rng{9091};
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<mpq_class> roots;
    const int m = int(rng.uniform(1, 5));
    for (int i = 0; i < m; ++i) roots.push_back(rng.frac(-20, 120, 100));  // some outside [0, 1]
    const mpq_class c = rng.frac(-64, 64, 8);
    if (c == 0) continue;
    check_peak<TestType>(from_derivative_roots(c, roots, rng.frac(-100, 100, 100)), roots);
  }
}

TEMPLATE_TEST_CASE("bern_argmax on degenerate and end-point peaks", "[floating][bernstein_peak]", double, Mpfr,
                   Bounded<double>) {
  // degree 0: the constant, at u = 0
  check_peak<TestType>({mpq_class(-3, 4)}, {});
  // degree 1: the larger end
  check_peak<TestType>({mpq_class(1, 3), mpq_class(-1)}, {});
  check_peak<TestType>({mpq_class(-1, 3), mpq_class(1)}, {});
  // the quartic shape of F(., t0): F(0) < 0, F(1) < 0, an interior maximum at u = 2/5 of value 1/50 - ...
  const std::vector<mpq_class> r4{mpq_class(1, 10), mpq_class(2, 5), mpq_class(7, 10)};
  check_peak<TestType>(from_derivative_roots(mpq_class(4), r4, mpq_class(-1, 100)), r4);
  // f' = -3 (u - 1/2)^2: f decreasing with an inflection at 1/2; the maximum is f(0)
  const std::vector<mpq_class> dbl{mpq_class(1, 2), mpq_class(1, 2)};
  check_peak<TestType>(from_derivative_roots(mpq_class(-3), dbl, mpq_class(1, 7)), dbl);
  // a maximum at a root of f' exactly at u = 1
  const std::vector<mpq_class> at1{mpq_class(1), mpq_class(-1, 2)};
  check_peak<TestType>(from_derivative_roots(mpq_class(-2), at1, mpq_class(0)), at1);
}

}  // namespace ECCD_UNITY_ID
