// Krawczyk's test and its nets (certified/krawczyk.hpp), against exact
// rational arithmetic on polynomials whose zeros are known exactly.
//
// Statement tested (Moore, Kearfott, Cloud 2009, section 8.2, as cited in the
// header): K(X) = x~ - Y f(x~) + (I - Y J(X))(X - x~); K(X) inside the
// interior of X proves that X holds exactly one zero of f, and every zero of f
// in X lies in K(X) whether or not the test succeeds.
//   - the nets: derivative() of an exact tensor net is the net of the exact
//     partial derivative (compared at random rational points with the
//     derivative of the monomial form, computed by hand in the test);
//     NetsT::get of mixed orders agrees with it; restrict_axis encloses the
//     exact F at the mapped point (MPFI), also for a = 0 and b = 1;
//   - solve_small: exact answers where pivoting is needed, refusal of a
//     singular matrix; newton: converges to a known rational zero, refuses
//     a zero derivative;
//   - krawczyk, over MPFI and over intervals of doubles, on systems with
//     exactly known zeros: a cubic in u with three rational roots (every
//     sub-box of a grid of random boxes), a 2 x 2 system F = F_u = 0 at a
//     fixed t whose zeros are irrational (s = (1 ± √3/4)/2, located by exact
//     signs of a quadratic), a 3 x 3 system F = F_u = F_s = 0 with coupling.
//     Certified: exactly one zero in X, and it lies in K. Any filled K:
//     every zero in X lies in K. Boxes with two zeros or none are never
//     certified; a net with an unbounded coefficient is refused;
//   - the proofs' own use: F(u, s, t) of two unit discs on lines (A at
//     (6, 6s - 3), B at (10t - 5, 0); kernel/trivariate_bernstein.hpp) and
//     the end system F = F_u = 0 on the face t = 1, whose zeros are the
//     touching instants s = (3 ± √3)/6 (centre distance 2 from B(1) = (5, 0))
//     with u = 1/2 (the pair is symmetric under the point reflection that
//     swaps the discs, checked exactly: F_u(1/2, s, 1) = 0); boxes around
//     them are certified and K holds the exact zero.
#include "certified/krawczyk.hpp"
#include "compare/seeded_rng.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/trivariate_bernstein.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <map>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::krawczyk_method;

namespace {

// A polynomial in (u, s, t) in monomial form: coefficient of u^i s^j t^k.
struct Mono3 {
  std::array<int, 3> n{};
  std::map<std::array<int, 3>, mpq_class> a;

  mpq_class operator()(const std::array<mpq_class, 3>& x) const {
    mpq_class r = 0;
    for (const auto& [e, c] : a) {
      mpq_class term = c;
      for (int ax = 0; ax < 3; ++ax)
        for (int p = 0; p < e[ax]; ++p) term *= x[ax];
      r += term;
    }
    return r;
  }
  Mono3 derivative(int axis) const {
    Mono3 d;
    d.n = n;
    d.n[axis] = std::max(n[axis] - 1, 0);
    for (const auto& [e, c] : a)
      if (e[axis] > 0) {
        std::array<int, 3> f = e;
        --f[axis];
        d.a[f] += c * e[axis];
      }
    return d;
  }
};

mpz_class binom(int n, int k) {
  mpz_class r;
  mpz_bin_uiui(r.get_mpz_t(), unsigned(n), unsigned(k));
  return r;
}

// x^i = sum_{j >= i} C(j, i) / C(n, i) B^n_j(x), axis by axis: the exact tensor Bernstein net.
TriBern<mpq_class> to_net(const Mono3& p) {
  TriBern<mpq_class> r;
  r.n = p.n;
  r.c.assign(std::size_t(p.n[0] + 1) * (p.n[1] + 1) * (p.n[2] + 1), mpq_class(0));
  auto w = [](int i, int j, int n) {
    mpq_class q(binom(j, i), binom(n, i));
    q.canonicalize();  // gmpxx's (num, den) constructor does not
    return q;
  };
  for (const auto& [e, c] : p.a)
    for (int j0 = e[0]; j0 <= p.n[0]; ++j0)
      for (int j1 = e[1]; j1 <= p.n[1]; ++j1)
        for (int j2 = e[2]; j2 <= p.n[2]; ++j2)
          r.at(j0, j1, j2) += c * w(e[0], j0, p.n[0]) * w(e[1], j1, p.n[1]) * w(e[2], j2, p.n[2]);
  return r;
}

template <class IT>
TriBern<IT> enclose_net(const TriBern<mpq_class>& f, int bits) {
  TriBern<IT> r;
  r.n = f.n;
  for (const auto& q : f.c) r.c.push_back(Enclose<IT>::point(q, bits));
  return r;
}

template <class IT>
bool encloses(const IT& x, const mpq_class& q) {
  return finite(x) && lower(x) <= q && q <= upper(x);
}

// (u - r0)(u - r1)(u - r2), degree 0 in s and t.
Mono3 cubic_u(const std::array<mpq_class, 3>& r) {
  Mono3 p;
  p.n = {3, 0, 0};
  p.a[{3, 0, 0}] = 1;
  p.a[{2, 0, 0}] = -(r[0] + r[1] + r[2]);
  p.a[{1, 0, 0}] = r[0] * r[1] + r[0] * r[2] + r[1] * r[2];
  p.a[{0, 0, 0}] = -r[0] * r[1] * r[2];
  return p;
}

// F = (u - 1/3)^2 + (s - 1/4)(s - 3/4) - (t - 1/2)/8. At t = 3/8: F = F_u = 0 iff u = 1/3 and
// g(s) = s^2 - s + 13/64 = 0, s = (1 ± √3/4)/2 (irrational, about 0.283 and 0.717).
Mono3 touching_2d() {
  Mono3 p;
  p.n = {2, 2, 1};
  p.a[{2, 0, 0}] = 1;
  p.a[{1, 0, 0}] = mpq_class(-2, 3);
  p.a[{0, 0, 0}] = mpq_class(1, 9) + mpq_class(3, 16) + mpq_class(1, 16);
  p.a[{0, 2, 0}] = 1;
  p.a[{0, 1, 0}] = -1;
  p.a[{0, 0, 1}] = mpq_class(-1, 8);
  return p;
}
mpq_class g2(const mpq_class& s) { return s * s - s + mpq_class(13, 64); }
// Is the root of g on the side `upper_root` greater than q? g falls on s < 1/2 and rises on s > 1/2.
bool root_above(bool upper_root, const mpq_class& q) {
  const mpq_class h(1, 2);
  if (upper_root) return q < h || g2(q) < 0;
  return q < h && g2(q) > 0;
}

// F = (u - 1/3)^2 + (s - 2/5)^2 + (u - 1/3)(s - 2/5) t + (t - 1/5)(t - 7/10): F_u = F_s = 0 iff
// u = 1/3, s = 2/5 (the determinant 4 - t^2 is not 0), and then F = 0 iff t = 1/5 or 7/10.
Mono3 coupled_3d() {
  // expand (u - a)^2 + (s - b)^2 + (u - a)(s - b) t + t^2 - (9/10) t + 7/50 with a = 1/3, b = 2/5
  const mpq_class a(1, 3), b(2, 5);
  Mono3 p;
  p.n = {2, 2, 2};
  p.a[{2, 0, 0}] = 1;
  p.a[{1, 0, 0}] = -2 * a;
  p.a[{0, 2, 0}] = 1;
  p.a[{0, 1, 0}] = -2 * b;
  p.a[{0, 0, 0}] = a * a + b * b + mpq_class(7, 50);
  p.a[{1, 1, 1}] = 1;
  p.a[{1, 0, 1}] = -b;
  p.a[{0, 1, 1}] = -a;
  p.a[{0, 0, 1}] = a * b - mpq_class(9, 10);
  p.a[{0, 0, 2}] = 1;
  return p;
}

bool in_box(const Box& X, std::size_t v, const mpq_class& q) { return X.lo[v] <= q && q <= X.hi[v]; }

}  // namespace

TEST_CASE("krawczyk nets: the test's exact nets are the monomial forms' nets", "[certified][krawczyk]") {
  // The helper to_net is the reference for everything below: check it at random points first.
  SeededRng rng{37};
  for (const Mono3& p : {touching_2d(), coupled_3d(), cubic_u({mpq_class(1, 3), mpq_class(1, 2), mpq_class(4, 5)})}) {
    const TriBern<mpq_class> f = to_net(p);
    for (int k = 0; k < 10; ++k) {
      std::array<mpq_class, 3> x{rng.frac(0, 97, 97), rng.frac(0, 89, 89), rng.frac(0, 83, 83)};
      REQUIRE(f(x[0], x[1], x[2]) == p(x));
    }
  }
}

TEST_CASE("krawczyk nets: derivative and NetsT::get are the exact partial derivatives", "[certified][krawczyk]") {
  SeededRng rng{371};
  const Mono3 p = coupled_3d();
  const TriBern<mpq_class> f = to_net(p);
  for (int ax = 0; ax < 3; ++ax) {
    const TriBern<mpq_class> d = derivative(f, ax, mpq_class(0));
    CHECK(d.n[ax] == f.n[ax] - 1);
    const Mono3 dp = p.derivative(ax);
    for (int k = 0; k < 8; ++k) {
      std::array<mpq_class, 3> x{rng.frac(0, 50, 50), rng.frac(0, 30, 30), rng.frac(0, 70, 70)};
      REQUIRE(d(x[0], x[1], x[2]) == dp(x));
    }
  }
  // a net of degree 0 along the axis: the derivative is the zero net of degree 0 there
  const TriBern<mpq_class> c = to_net(cubic_u({mpq_class(1, 3), mpq_class(1, 2), mpq_class(4, 5)}));
  const TriBern<mpq_class> ds = derivative(c, 1, mpq_class(0));
  CHECK(ds.n == std::array<int, 3>{3, 0, 0});
  for (const auto& x : ds.c) CHECK(x == 0);

  // NetsT over MPFI: get({1, 1, 1}) encloses F_ust, and a second call returns the cached net
  Nets nets(enclose_net<MpfiInterval>(f, 200), 200);
  const Mono3 dust = p.derivative(0).derivative(1).derivative(2);  // = 1
  const Mono3 duu = p.derivative(0).derivative(0);                 // = 2
  for (int k = 0; k < 5; ++k) {
    std::array<mpq_class, 3> x{rng.frac(0, 10, 10), rng.frac(0, 10, 10), rng.frac(0, 10, 10)};
    std::array<MpfiInterval, 3> xi{MpfiInterval(x[0], 200), MpfiInterval(x[1], 200), MpfiInterval(x[2], 200)};
    CHECK(encloses(nets.eval({1, 1, 1}, xi), dust(x)));
    CHECK(encloses(nets.eval({2, 0, 0}, xi), duu(x)));
    CHECK(encloses(nets.eval({0, 1, 0}, xi), p.derivative(1)(x)));
    std::array<double, 3> xd{x[0].get_d(), x[1].get_d(), x[2].get_d()};
    CHECK(nets.eval_mid({0, 0, 0}, xd) == Approx(p(x).get_d()).margin(1e-12));
  }
  CHECK(&nets.get({1, 1, 1}) == &nets.get({1, 1, 1}));
}

TEST_CASE("krawczyk restrict_axis encloses F on the sub-range, ends included", "[certified][krawczyk]") {
  SeededRng rng{3711};
  const Mono3 p = coupled_3d();
  const TriBern<MpfiInterval> f = enclose_net<MpfiInterval>(to_net(p), 160);
  const std::vector<std::pair<mpq_class, mpq_class>> ranges{{mpq_class(0), mpq_class(1, 3)},
                                                            {mpq_class(2, 7), mpq_class(1)},
                                                            {mpq_class(1, 5), mpq_class(3, 4)},
                                                            {mpq_class(0), mpq_class(1)}};
  for (int ax = 0; ax < 3; ++ax)
    for (const auto& [a, b] : ranges) {
      const TriBern<MpfiInterval> r = restrict_axis(f, ax, a, b, 160);
      CHECK(r.n == f.n);
      for (int k = 0; k < 6; ++k) {
        std::array<mpq_class, 3> x{rng.frac(0, 20, 20), rng.frac(0, 20, 20), rng.frac(0, 20, 20)};
        std::array<mpq_class, 3> y = x;
        y[ax] = a + (b - a) * x[ax];  // the point of [0, 1]^3 that x stands for
        const MpfiInterval v = r(MpfiInterval(x[0], 160), MpfiInterval(x[1], 160), MpfiInterval(x[2], 160));
        REQUIRE(encloses(v, p(y)));
        CHECK(upper(v) - lower(v) < mpq_class(1, 1000000));  // an enclosure, not a vacuous one
      }
    }
}

TEST_CASE("krawczyk solve_small and newton", "[certified][krawczyk]") {
  // a permutation needs pivoting; the answer is exact
  std::vector<double> b{3, 5};
  REQUIRE(solve_small({{0, 1}, {1, 0}}, b));
  CHECK(b == std::vector<double>{5, 3});
  // [[2, 1], [1, 3]] x = [3, 5]: x = (4/5, 7/5) by Cramer's rule
  b = {3, 5};
  REQUIRE(solve_small({{2, 1}, {1, 3}}, b));
  CHECK(b[0] == Approx(0.8).epsilon(1e-15));
  CHECK(b[1] == Approx(1.4).epsilon(1e-15));
  // singular and non-finite systems are refused
  b = {1, 2};
  CHECK_FALSE(solve_small({{1, 2}, {2, 4}}, b));
  b = {1};
  CHECK_FALSE(solve_small({{std::nan("")}}, b));

  const Mono3 p = cubic_u({mpq_class(1, 3), mpq_class(1, 2), mpq_class(4, 5)});
  NetsT<Interval> nets(enclose_net<Interval>(to_net(p), 53), 53);
  const System sys{{{0, 0, 0}}, {0}, std::nullopt, "root"};
  auto x = newton(nets, sys, {0.3, 0, 0});
  REQUIRE(x);
  CHECK((*x)[0] == Approx(1.0 / 3).margin(1e-14));
  x = newton(nets, sys, {0.85, 0, 0});
  REQUIRE(x);
  CHECK((*x)[0] == Approx(0.8).margin(1e-14));
  // F = (u - 1/2)^2 - 1/16 from its critical point u = 1/2: F_u = 0, no step
  Mono3 q;
  q.n = {2, 0, 0};
  q.a[{2, 0, 0}] = 1;
  q.a[{1, 0, 0}] = -1;
  q.a[{0, 0, 0}] = mpq_class(3, 16);
  NetsT<Interval> qn(enclose_net<Interval>(to_net(q), 53), 53);
  CHECK_FALSE(newton(qn, sys, {0.5, 0, 0}));
}

TEMPLATE_TEST_CASE("krawczyk certifies exactly one root of a cubic in u, and K keeps every root of X",
                   "[certified][krawczyk]", MpfiInterval, Interval) {
  SeededRng rng{37037};
  long certified = 0, filled = 0;
  for (int trial = 0; trial < 12; ++trial) {
    // three distinct rational roots in (0, 1)
    std::array<mpq_class, 3> r{rng.frac(1, 29, 30), rng.frac(1, 29, 30), rng.frac(1, 29, 30)};
    if (r[0] == r[1] || r[0] == r[2] || r[1] == r[2]) continue;
    NetsT<TestType> nets(enclose_net<TestType>(to_net(cubic_u(r)), 96), 96);
    const System sys{{{0, 0, 0}}, {0}, std::nullopt, "cubic"};
    for (int k = 0; k < 30; ++k) {
      mpq_class lo = rng.frac(0, 99, 100), w = rng.frac(1, 40, 400);
      if (k % 3 == 0) {  // a box around one root
        lo = r[k % 2] - rng.frac(1, 20, 2000);
        w = r[k % 2] - lo + rng.frac(1, 20, 2000);
      }
      const Box X{{lo}, {lo + w}};
      Box K;
      const bool ok = krawczyk(nets, sys, X, K);
      int inside = 0;
      for (const auto& z : r) inside += in_box(X, 0, z);
      if (K.lo.size() == 1) {
        ++filled;
        for (const auto& z : r)
          if (in_box(X, 0, z)) CHECK(in_box(K, 0, z));
      }
      if (ok) {
        ++certified;
        INFO("X = [" << X.lo[0] << ", " << X.hi[0] << "], K = [" << K.lo[0] << ", " << K.hi[0] << "]");
        CHECK(inside == 1);
        CHECK(X.lo[0] < K.lo[0]);
        CHECK(K.hi[0] < X.hi[0]);
      }
    }
  }
  CHECK(certified >= 60);  // the boxes around one root, at least: the test is not vacuous
  CHECK(filled >= 300);
}

TEMPLATE_TEST_CASE("krawczyk refuses boxes with two roots, with none, and an unbounded net", "[certified][krawczyk]",
                   MpfiInterval, Interval) {
  const std::array<mpq_class, 3> r{mpq_class(1, 3), mpq_class(1, 2), mpq_class(4, 5)};
  NetsT<TestType> nets(enclose_net<TestType>(to_net(cubic_u(r)), 128), 128);
  const System sys{{{0, 0, 0}}, {0}, std::nullopt, "cubic"};
  Box K;
  CHECK_FALSE(krawczyk(nets, sys, Box{{mpq_class(3, 10)}, {mpq_class(6, 10)}}, K));  // 1/3 and 1/2
  CHECK_FALSE(krawczyk(nets, sys, Box{{mpq_class(6, 10)}, {mpq_class(7, 10)}}, K));  // none
  CHECK_FALSE(krawczyk(nets, sys, Box{{mpq_class(0)}, {mpq_class(1)}}, K));          // all three
  // a small box around 1/3 is certified, with K around 1/3
  REQUIRE(krawczyk(nets, sys, Box{{mpq_class(32, 100)}, {mpq_class(34, 100)}}, K));
  CHECK(in_box(K, 0, mpq_class(1, 3)));

  TriBern<TestType> bad = enclose_net<TestType>(to_net(cubic_u(r)), 128);
  if constexpr (std::is_same_v<TestType, Interval>) {
    bad.c[1] = Interval::entire();
  } else {
    mpfi_set_d(bad.c[1].get(), 1.0);
    mpfi_put_d(bad.c[1].get(), std::numeric_limits<double>::infinity());
  }
  NetsT<TestType> badnets(bad, 128);
  CHECK_FALSE(krawczyk(badnets, sys, Box{{mpq_class(32, 100)}, {mpq_class(34, 100)}}, K));
}

TEMPLATE_TEST_CASE("krawczyk on F = F_u = 0 at a fixed t: the irrational touching zeros", "[certified][krawczyk]",
                   MpfiInterval, Interval) {
  // unknowns (u, s), t fixed at 3/8; zeros (1/3, (1 ± √3/4)/2)
  NetsT<TestType> nets(enclose_net<TestType>(to_net(touching_2d()), 128), 128);
  const System sys{{{0, 0, 0}, {1, 0, 0}}, {0, 1}, mpq_class(3, 8), "touch"};
  SeededRng rng{3737};
  long certified = 0;
  for (int k = 0; k < 200; ++k) {
    const mpq_class u0 = rng.frac(20, 40, 100), s0 = rng.frac(10, 80, 100);
    const mpq_class wu = rng.frac(1, 20, 200), ws = rng.frac(1, 40, 200);
    const Box X{{u0, s0}, {u0 + wu, s0 + ws}};
    Box K;
    const bool ok = krawczyk(nets, sys, X, K);
    // which zeros lie in X (u = 1/3 exactly; s by the signs of g)
    const bool u_in = in_box(X, 0, mpq_class(1, 3));
    int inside = 0;
    for (bool up : {false, true}) {
      const bool s_in = root_above(up, X.lo[1]) && !root_above(up, X.hi[1]);
      inside += u_in && s_in;
      if (u_in && s_in && K.lo.size() == 2) {
        CHECK(in_box(K, 0, mpq_class(1, 3)));
        CHECK(root_above(up, K.lo[1]));
        CHECK_FALSE(root_above(up, K.hi[1]));
      }
    }
    if (ok) {
      ++certified;
      CHECK(inside == 1);
      for (std::size_t v = 0; v < 2; ++v) CHECK((X.lo[v] < K.lo[v] && K.hi[v] < X.hi[v]));
    }
  }
  // boxes centred on the zeros are certified
  for (bool up : {false, true}) {
    const mpq_class s = up ? mpq_class(717, 1000) : mpq_class(283, 1000);
    const Box X{{mpq_class(33, 100), s - mpq_class(1, 100)}, {mpq_class(34, 100), s + mpq_class(1, 100)}};
    Box K;
    REQUIRE(krawczyk(nets, sys, X, K));
    CHECK(root_above(up, K.lo[1]));
    CHECK_FALSE(root_above(up, K.hi[1]));
    ++certified;
  }
  CHECK(certified >= 2);
  // a box holding both zeros is not certified
  Box K;
  CHECK_FALSE(krawczyk(nets, sys, Box{{mpq_class(3, 10), mpq_class(1, 10)}, {mpq_class(4, 10), mpq_class(9, 10)}}, K));
}

TEMPLATE_TEST_CASE("krawczyk on F = F_u = F_s = 0 in three unknowns", "[certified][krawczyk]", MpfiInterval, Interval) {
  // zeros (1/3, 2/5, 1/5) and (1/3, 2/5, 7/10)
  NetsT<TestType> nets(enclose_net<TestType>(to_net(coupled_3d()), 128), 128);
  const System sys{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}, std::nullopt, "critical"};
  const std::array<std::array<mpq_class, 3>, 2> zeros{
      {{mpq_class(1, 3), mpq_class(2, 5), mpq_class(1, 5)}, {mpq_class(1, 3), mpq_class(2, 5), mpq_class(7, 10)}}};
  SeededRng rng{373737};
  long certified = 0;
  for (int k = 0; k < 150; ++k) {
    Box X;
    for (int v = 0; v < 3; ++v) {
      mpq_class lo = rng.frac(0, 90, 100);
      if (k % 2 == 0) lo = zeros[k % 4 / 2][v] - rng.frac(1, 10, 1000);  // a box around a zero
      X.lo.push_back(lo);
      X.hi.push_back(lo + rng.frac(1, 10, 1000) + (k % 2 == 0 ? zeros[k % 4 / 2][v] - lo : mpq_class(0)));
    }
    Box K;
    const bool ok = krawczyk(nets, sys, X, K);
    int inside = 0;
    for (const auto& z : zeros) {
      const bool in = in_box(X, 0, z[0]) && in_box(X, 1, z[1]) && in_box(X, 2, z[2]);
      inside += in;
      if (in && K.lo.size() == 3)
        for (std::size_t v = 0; v < 3; ++v) CHECK(in_box(K, v, z[v]));
    }
    if (ok) {
      ++certified;
      CHECK(inside == 1);
    }
  }
  CHECK(certified >= 50);  // most of the 75 boxes around a zero: the test is not vacuous
}

TEST_CASE("krawczyk certifies the touching ends of two discs on lines from the scene's F", "[certified][krawczyk]") {
  auto disc = [](const Rational& x0, const Rational& dx, const Rational& y0, const Rational& dy) {
    SceneObject o;
    o.Q = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    MatrixMotion m;
    m.m.assign(3, std::vector<RPoly>(3));
    for (int i = 0; i < 3; ++i) m.m[i][i] = RPoly::constant(Rational(1));
    m.m[0][2] = RPoly(std::vector<Rational>{x0, dx});
    m.m[1][2] = RPoly(std::vector<Rational>{y0, dy});
    o.motion = m;
    return o;
  };
  Scene sc;
  sc.dim = 2;
  sc.a = disc(6, 0, -3, 6);
  sc.b = disc(-5, 10, 0, 0);
  sc.independent = false;  // prepare_pair's shared preparation; F takes A's parameter as s and B's as t
  const TriBern<Rational> F = independent_ellipsoid_function<Rational, 3>(
      to_arithmetic_bernstein<Rational, 3>(prepare_pair<3>(sc), Rational(1)));
  // the symmetry that puts the double root at u = 1/2, exactly
  const TriBern<Rational> Fu = derivative(F, 0, Rational(0));
  for (const Rational& s : {Rational(0), Rational(1, 5), Rational(2, 3), Rational(1)})
    REQUIRE(Fu(Rational(1, 2), s, Rational(1)) == 0);
  REQUIRE(sgn(F(Rational(1, 2), Rational(1, 2), Rational(1))) < 0);  // s = 1/2: overlapping at t = 1

  Nets nets(enclose_net<MpfiInterval>(F, 200), 200);
  const System sys{{{0, 0, 0}, {1, 0, 0}}, {0, 1}, Rational(1), "end t = 1"};
  auto q = [](const mpq_class& s) -> mpq_class { return (6 * s - 3) * (6 * s - 3) - 3; };  // zero at the ends
  for (bool upper : {false, true}) {
    const mpq_class approx = upper ? mpq_class(7887, 10000) : mpq_class(2113, 10000);
    const Box X{{mpq_class(49, 100), approx - mpq_class(1, 200)}, {mpq_class(51, 100), approx + mpq_class(1, 200)}};
    Box K, Y = X;
    // Krawczyk's iteration X <- K: each step certified again, each K holding the exact zero
    for (int step = 0; step < 4; ++step) {
      INFO("step " << step);
      REQUIRE(krawczyk(nets, sys, Y, K));
      CHECK(in_box(K, 0, mpq_class(1, 2)));
      // s* in [K.lo, K.hi]: q changes sign there, on one side of 1/2
      CHECK(sgn(q(K.lo[1])) == -sgn(q(K.hi[1])));
      CHECK((upper ? K.lo[1] > mpq_class(1, 2) : K.hi[1] < mpq_class(1, 2)));
      Y = K;
    }
    CHECK(K.hi[1] - K.lo[1] < mpq_class(1, 100000000));  // it converges (quadratically) onto the zero
  }
  // a box on the face around s = 1/2 (overlap, no touching zero) is not certified
  Box K;
  CHECK_FALSE(
      krawczyk(nets, sys, Box{{mpq_class(45, 100), mpq_class(45, 100)}, {mpq_class(55, 100), mpq_class(55, 100)}}, K));
}

}  // namespace ECCD_UNITY_ID
