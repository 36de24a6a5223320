// The certificate checker's tensor Bernstein nets (certificate/check/bernstein.hpp),
// against polynomials given in monomial form and evaluated in mpq_class:
//   - exact nets (T = mpq_class): value_at is p(x, y); restrict_to along u or
//     t is p reparameterised, r(x, y) = p(a + (b - a) x, y) (also for a range
//     reaching outside [0, 1], "an identity of polynomials", and for a = 0 or
//     b = 1); split_half gives p on [0, 1/2] and [1/2, 1]; derivative is the
//     net of the exact partial derivative (a constant: the zero net);
//   - interval nets (MI at 96 bits, DI): converted, restricted and split
//     nets and values at rational points enclose the exact ones, and a
//     strict_sign claimed holds for the exact polynomial at random points of
//     the net's range (convex hull property, Farin chapter 5).
#include "certificate/check/bernstein.hpp"
#include "certificate/check/interval.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using eccd::check::DI;
using eccd::check::MI;
using eccd::check::Net2;

namespace {

struct Mono2 {  // coefficient of u^i t^j
  int m = 0, n = 0;
  std::map<std::pair<int, int>, mpq_class> a;
  mpq_class operator()(const mpq_class& u, const mpq_class& t) const {
    mpq_class r = 0;
    for (const auto& [e, c] : a) {
      mpq_class term = c;
      for (int k = 0; k < e.first; ++k) term *= u;
      for (int k = 0; k < e.second; ++k) term *= t;
      r += term;
    }
    return r;
  }
};

mpq_class weight(int i, int j, int n) {  // u^i = Σ_{j >= i} C(j, i) / C(n, i) B^n_j(u)
  mpz_class a, b;
  mpz_bin_uiui(a.get_mpz_t(), unsigned(j), unsigned(i));
  mpz_bin_uiui(b.get_mpz_t(), unsigned(n), unsigned(i));
  mpq_class q(a, b);
  q.canonicalize();
  return q;
}

Net2<mpq_class> to_net(const Mono2& p) {
  Net2<mpq_class> f;
  f.m = p.m;
  f.n = p.n;
  f.c.assign(std::size_t(p.m + 1) * (p.n + 1), mpq_class(0));
  for (const auto& [e, c] : p.a)
    for (int i = e.first; i <= p.m; ++i)
      for (int j = e.second; j <= p.n; ++j) f.at(i, j) += c * weight(e.first, i, p.m) * weight(e.second, j, p.n);
  return f;
}

Mono2 random_mono(SeededRng& rng) {
  Mono2 p;
  p.m = int(rng.uniform(0, 4));
  p.n = int(rng.uniform(0, 4));
  for (int i = 0; i <= p.m; ++i)
    for (int j = 0; j <= p.n; ++j)
      if (rng.uniform(0, 2) != 0) p.a[{i, j}] = rng.frac(-50, 50, rng.uniform(1, 9));
  return p;
}

Mono2 diff(const Mono2& p, int axis) {
  Mono2 d;
  d.m = axis == 0 ? std::max(p.m - 1, 0) : p.m;
  d.n = axis == 1 ? std::max(p.n - 1, 0) : p.n;
  for (const auto& [e, c] : p.a) {
    const int k = axis == 0 ? e.first : e.second;
    if (k == 0) continue;
    d.a[axis == 0 ? std::make_pair(e.first - 1, e.second) : std::make_pair(e.first, e.second - 1)] += c * k;
  }
  return d;
}

MI mi(const mpq_class& q) { return MI(q, 96); }
DI di(const mpq_class& q) { return DI::of(q); }

template <class T>
bool holds(const T& x, const mpq_class& q) {
  return x.finite() && x.lower() <= q && q <= x.upper();
}

}  // namespace

TEST_CASE("check Net2 exact: value, restriction, halves and derivatives", "[certificate][check_bernstein]") {
  SeededRng rng{201};
  for (int trial = 0; trial < 60; ++trial) {
    const Mono2 p = random_mono(rng);
    const Net2<mpq_class> f = to_net(p);
    for (int k = 0; k < 4; ++k) {
      const mpq_class x = rng.frac(0, 31, 31), y = rng.frac(0, 29, 29);
      REQUIRE(check::value_at(f, x, y) == p(x, y));
    }
    for (int axis : {0, 1}) {
      mpq_class a = rng.frac(-8, 16, 16), b = rng.frac(-8, 24, 16);
      if (trial % 5 == 0) a = 0;
      if (trial % 5 == 1) b = 1;
      if (a == b || a == 1) continue;
      if (b < a) std::swap(a, b);
      if (a == 1) continue;
      const Net2<mpq_class> r = check::restrict_to(f, axis, a, b, [](const mpq_class& q) { return q; });
      const auto [lo, hi] = check::split_half(f, axis, mpq_class(1, 2));
      const Mono2 d = diff(p, axis);
      const Net2<mpq_class> df = check::derivative(f, axis);
      for (int k = 0; k < 4; ++k) {
        const mpq_class x = rng.frac(0, 17, 17), y = rng.frac(0, 13, 13);
        // the restricted axis' coordinate is x for u, y for t
        const mpq_class mapped = a + (b - a) * (axis == 0 ? x : y);
        INFO("axis " << axis << ", [" << a << ", " << b << "]");
        CHECK(check::value_at(r, x, y) == (axis == 0 ? p(mapped, y) : p(x, mapped)));
        CHECK(check::value_at(lo, x, y) == (axis == 0 ? p(x / 2, y) : p(x, y / 2)));
        CHECK(check::value_at(hi, x, y) == (axis == 0 ? p((1 + x) / 2, y) : p(x, (1 + y) / 2)));
        CHECK(check::value_at(df, x, y) == d(x, y));
      }
    }
  }
  // a constant along u: the derivative is the zero net of degree 0 there
  Mono2 c;
  c.m = 0;
  c.n = 2;
  c.a[{0, 2}] = 3;
  const Net2<mpq_class> dc = check::derivative(to_net(c), 0);
  CHECK(dc.m == 0);
  CHECK(dc.n == 2);
  for (const auto& x : dc.c) CHECK(x == 0);
}

TEMPLATE_TEST_CASE("check Net2 in intervals encloses the exact nets and proves only true signs",
                   "[certificate][check_bernstein]", MI, DI) {
  SeededRng rng{202};
  auto make = [](const mpq_class& q) {
    if constexpr (std::is_same_v<TestType, MI>)
      return mi(q);
    else
      return di(q);
  };
  long signs = 0;
  for (int trial = 0; trial < 80; ++trial) {
    Mono2 p = random_mono(rng);
    if (trial % 2 == 0) p.a[{0, 0}] += 60;  // often of one sign on the square
    const Net2<mpq_class> f = to_net(p);
    const Net2<TestType> fi = check::converted<TestType>(f, make);
    const mpq_class a = rng.frac(0, 7, 8), b = a + rng.frac(1, 8, 64);
    for (int axis : {0, 1}) {
      const Net2<TestType> r = check::restrict_to(fi, axis, a, b, make);
      const Net2<mpq_class> re = check::restrict_to(f, axis, a, b, [](const mpq_class& q) { return q; });
      for (std::size_t i = 0; i < r.c.size(); ++i) CHECK(holds(r.c[i], re.c[i]));
      const auto [lo, hi] = check::split_half(fi, axis, make(mpq_class(1, 2)));
      const auto [elo, ehi] = check::split_half(f, axis, mpq_class(1, 2));
      for (std::size_t i = 0; i < lo.c.size(); ++i) {
        CHECK(holds(lo.c[i], elo.c[i]));
        CHECK(holds(hi.c[i], ehi.c[i]));
      }
      const int s = r.strict_sign();
      if (s != 0) {
        ++signs;
        for (int k = 0; k < 6; ++k) {
          const mpq_class x = rng.frac(0, 19, 19), y = rng.frac(0, 23, 23);
          const mpq_class v = axis == 0 ? p(a + (b - a) * x, y) : p(y, a + (b - a) * x);
          CHECK(sgn(v) == s);
        }
      }
    }
    const mpq_class x = rng.frac(0, 37, 37), y = rng.frac(0, 41, 41);
    CHECK(holds(check::value_at(fi, make(x), make(y)), p(x, y)));
  }
  CHECK(signs >= 40);
}

}  // namespace ECCD_UNITY_ID
