// The checker's three-variable nets and the net claim's readers
// (certificate/check/independent_net.hpp), against polynomials in monomial
// form evaluated in mpq_class:
//   - restrict3 (inside and reaching outside [0, 1]; a box starting at 1
//     refused), split3, deriv3 on a box of side h (the net of the partial
//     derivative in the original variable), centre_value, t_face, swap_st,
//     converted3 into MI (enclosures and a proved sign only where true);
//   - edge_quotient: F_t / t and F_t / (1 - t) exactly when F_t vanishes on
//     that face, nothing otherwise;
//   - net_on_grid: the net's values at integers outside [0, 1] (the
//     polynomial identity the net claim rests on);
//   - holds_still: true for a scaling N = (1 + x) I, false for a translation
//     and a zero shape;
//   - stated_shape_h: a positive multiple of Q accepted; a negative or
//     non-multiple, det >= 0, a wrong size rejected; stated_inverse_h: the
//     adjugate of a translation accepted; M itself, a c(x) with a root in
//     [0, 1], a degree above 64 rejected.
#include "certificate/check/independent_net.hpp"
#include "certificate/check/interval.hpp"
#include "compare/seeded_rng.hpp"

#include <catch2/catch.hpp>

#include <functional>
#include <map>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::check;
// the checker's PolyMatrix, not kernel/poly_matrix.hpp's (a unity batch of tests may include both)
using PolyMatrix = eccd::check::PolyMatrix;

namespace {

struct Mono3 {
  std::array<int, 3> n{};
  std::map<std::array<int, 3>, mpq_class> a;
  mpq_class operator()(const mpq_class& u, const mpq_class& s, const mpq_class& t) const {
    mpq_class r = 0;
    for (const auto& [e, c] : a) {
      mpq_class term = c;
      for (int k = 0; k < e[0]; ++k) term *= u;
      for (int k = 0; k < e[1]; ++k) term *= s;
      for (int k = 0; k < e[2]; ++k) term *= t;
      r += term;
    }
    return r;
  }
  Mono3 diff(int axis) const {
    Mono3 d;
    d.n = n;
    d.n[axis] = std::max(n[axis] - 1, 0);
    for (const auto& [e, c] : a)
      if (e[axis] > 0) {
        auto f = e;
        --f[axis];
        d.a[f] += c * e[axis];
      }
    return d;
  }
};

mpq_class binq(int n, int k) {
  mpz_class r;
  mpz_bin_uiui(r.get_mpz_t(), unsigned(n), unsigned(k));
  return mpq_class(r);
}

Net3<mpq_class> to_net(const Mono3& p) {
  Net3<mpq_class> f;
  f.n = p.n;
  f.c.assign(std::size_t(p.n[0] + 1) * (p.n[1] + 1) * (p.n[2] + 1), mpq_class(0));
  auto w = [](int i, int j, int n) -> mpq_class { return binq(j, i) / binq(n, i); };
  for (const auto& [e, c] : p.a)
    for (int i = e[0]; i <= p.n[0]; ++i)
      for (int j = e[1]; j <= p.n[1]; ++j)
        for (int k = e[2]; k <= p.n[2]; ++k)
          f.at(i, j, k) += c * w(e[0], i, p.n[0]) * w(e[1], j, p.n[1]) * w(e[2], k, p.n[2]);
  return f;
}

// Σ c_ijk B_i(u) B_j(s) B_k(t), from the definition
mpq_class value(const Net3<mpq_class>& f, const mpq_class& u, const mpq_class& s, const mpq_class& t) {
  auto B = [](int n, int k, const mpq_class& x) {
    mpq_class r = binq(n, k);
    for (int i = 0; i < k; ++i) r *= x;
    for (int i = 0; i < n - k; ++i) r *= 1 - x;
    return r;
  };
  mpq_class v = 0;
  for (int i = 0; i <= f.n[0]; ++i)
    for (int j = 0; j <= f.n[1]; ++j)
      for (int k = 0; k <= f.n[2]; ++k) v += f.at(i, j, k) * B(f.n[0], i, u) * B(f.n[1], j, s) * B(f.n[2], k, t);
  return v;
}

Mono3 random_mono(SeededRng& rng) {
  Mono3 p;
  p.n = {int(rng.uniform(0, 3)), int(rng.uniform(0, 3)), int(rng.uniform(1, 3))};
  for (int i = 0; i <= p.n[0]; ++i)
    for (int j = 0; j <= p.n[1]; ++j)
      for (int k = 0; k <= p.n[2]; ++k)
        if (rng.uniform(0, 2) != 0) p.a[{i, j, k}] = rng.frac(-20, 20, rng.uniform(1, 6));
  return p;
}

const auto exact = [](const mpq_class& q) { return q; };

Rejected rejection(const std::function<void()>& f) {
  try {
    f();
  } catch (const Rejected& r) {
    return r;
  }
  return Rejected{"", ""};
}

QPoly poly(std::vector<mpq_class> c) { return QPoly(std::move(c)); }

}  // namespace

TEST_CASE("check Net3 restriction, halves, derivatives, faces and swaps are exact", "[certificate][independent_net]") {
  SeededRng rng{401};
  for (int trial = 0; trial < 40; ++trial) {
    const Mono3 p = random_mono(rng);
    const Net3<mpq_class> f = to_net(p);
    const mpq_class h(1, 2);
    CHECK(centre_value(f, h) == p(h, h, h));
    for (int axis = 0; axis < 3; ++axis) {
      mpq_class a = rng.frac(-4, 12, 16), b = rng.frac(-4, 24, 16);
      if (b < a) std::swap(a, b);
      if (a == b || a == 1) continue;
      const Net3<mpq_class> r = restrict3(f, axis, a, b, exact);
      const auto [lo, hi] = split3(f, axis, h);
      const Net3<mpq_class> dr = deriv3(r, axis, b - a, exact), df = to_net(p.diff(axis));
      for (int k = 0; k < 3; ++k) {
        std::array<mpq_class, 3> x{rng.frac(0, 7, 7), rng.frac(0, 9, 9), rng.frac(0, 11, 11)};
        auto mapped = [&](const mpq_class& lo_, const mpq_class& w) {
          std::array<mpq_class, 3> y = x;
          y[axis] = lo_ + w * x[axis];
          return y;
        };
        const auto y = mapped(a, b - a), yl = mapped(0, h), yh = mapped(h, h);
        INFO("axis " << axis << ", [" << a << ", " << b << "]");
        CHECK(value(r, x[0], x[1], x[2]) == p(y[0], y[1], y[2]));
        CHECK(value(lo, x[0], x[1], x[2]) == p(yl[0], yl[1], yl[2]));
        CHECK(value(hi, x[0], x[1], x[2]) == p(yh[0], yh[1], yh[2]));
        // the derivative on the box, in the original variable: ∂p/∂x at the mapped point
        CHECK(value(dr, x[0], x[1], x[2]) == p.diff(axis)(y[0], y[1], y[2]));
        CHECK(value(df, x[0], x[1], x[2]) == p.diff(axis)(x[0], x[1], x[2]));
      }
    }
    for (int end : {0, 1}) {
      const Net3<mpq_class> face = t_face(f, end);
      CHECK(face.n[2] == 0);
      CHECK(value(face, mpq_class(1, 3), mpq_class(2, 7), 0) == p(mpq_class(1, 3), mpq_class(2, 7), end));
    }
    const Net3<mpq_class> sw = swap_st(f);
    CHECK(value(sw, mpq_class(1, 3), mpq_class(2, 7), mpq_class(4, 5)) ==
          p(mpq_class(1, 3), mpq_class(4, 5), mpq_class(2, 7)));
    // the grid values outside [0, 1]: the polynomial itself
    const auto g = net_on_grid(f, f.n[1] + 1, f.n[2] + 2);
    for (int x = 0; x <= f.n[0]; ++x)
      for (int y = 0; y <= f.n[1] + 1; ++y)
        for (int z = 0; z <= f.n[2] + 2; ++z) CHECK(g[x][y][z] == p(x, y, z));
    // in MI: enclosures, and a sign only where true
    const Net3<MI> fi = converted3<MI>(f, [](const mpq_class& q) { return MI(q, 80); });
    const MI c = centre_value(fi, MI(h, 80));
    CHECK((c.lower() <= p(h, h, h) && p(h, h, h) <= c.upper()));
    const MI hull = fi.hull();
    CHECK((hull.lower() <= p(h, 0, 1) && p(h, 0, 1) <= hull.upper()));
    if (fi.strict_sign() != 0) CHECK(sgn(p(mpq_class(2, 9), mpq_class(5, 9), mpq_class(7, 9))) == fi.strict_sign());
  }
  Net3<mpq_class> one;
  one.n = {0, 0, 1};
  one.c = {1, 2};
  CHECK_THROWS_AS(restrict3(one, 2, mpq_class(1), mpq_class(2), exact), std::domain_error);
  const Net3<mpq_class> d0 = deriv3(one, 0, mpq_class(1), exact);  // constant along u
  for (const auto& x : d0.c) CHECK(x == 0);
}

TEST_CASE("check Net3 edge_quotient divides F_t by t or 1 - t exactly", "[certificate][independent_net]") {
  // F = 3 + u s + t² (u - 2) + t³ s: F_t = 2t (u - 2) + 3t² s vanishes at t = 0; F_t / t = 2(u - 2) + 3t s
  Mono3 p;
  p.n = {1, 1, 3};
  p.a[{0, 0, 0}] = 3;
  p.a[{1, 1, 0}] = 1;
  p.a[{1, 0, 2}] = 1;
  p.a[{0, 0, 2}] = -2;
  p.a[{0, 1, 3}] = 1;
  const auto g0 = edge_quotient(to_net(p), 0);
  REQUIRE(g0);
  for (const auto& x : {std::array<mpq_class, 3>{mpq_class(1, 3), mpq_class(1, 2), mpq_class(2, 5)},
                        std::array<mpq_class, 3>{0, 1, mpq_class(7, 8)}})
    CHECK(value(*g0, x[0], x[1], x[2]) == 2 * (x[0] - 2) + 3 * x[2] * x[1]);
  CHECK_FALSE(edge_quotient(to_net(p), 1));  // F_t(t = 1) = 2(u - 2) + 3s is not 0
  // G = (1 - t)² (u + s) + 5: G_t = -2(1 - t)(u + s) vanishes at t = 1; G_t / (1 - t) = -2(u + s)
  Mono3 q;
  q.n = {1, 1, 2};
  for (const auto& [e, c] : std::map<std::array<int, 3>, mpq_class>{{{1, 0, 0}, 1},
                                                                    {{0, 1, 0}, 1},
                                                                    {{1, 0, 1}, -2},
                                                                    {{0, 1, 1}, -2},
                                                                    {{1, 0, 2}, 1},
                                                                    {{0, 1, 2}, 1},
                                                                    {{0, 0, 0}, 5}})
    q.a[e] = c;
  const auto g1 = edge_quotient(to_net(q), 1);
  REQUIRE(g1);
  CHECK(value(*g1, mpq_class(1, 3), mpq_class(1, 4), mpq_class(1, 2)) == -2 * (mpq_class(1, 3) + mpq_class(1, 4)));
  Net3<mpq_class> linear;  // degree 1 in t: F_t constant, no quotient of degree >= 0 to form
  linear.n = {0, 0, 1};
  linear.c = {1, 1};
  CHECK_FALSE(edge_quotient(linear, 0));
}

TEST_CASE("check Net3 holds_still and the stated shape and inverse motion", "[certificate][independent_net]") {
  const QMatrix Q{{1, 0, 0}, {0, 4, 0}, {0, 0, -1}};
  PolyMatrix scale(3, std::vector<QPoly>(3)), translate(3, std::vector<QPoly>(3));
  for (int i = 0; i < 3; ++i) {
    scale[i][i] = poly({1, 1});
    translate[i][i] = QPoly::constant(1);
  }
  translate[0][2] = poly({0, -2});
  CHECK(holds_still(Q, scale));
  CHECK_FALSE(holds_still(Q, translate));
  CHECK_FALSE(holds_still(QMatrix(3, std::vector<mpq_class>(3)), scale));

  const json twice =
      json::array({json::array({"2", "0", "0"}), json::array({"0", "8", "0"}), json::array({"0", "0", "-2"})});
  CHECK(stated_shape_h(twice, "net.a.shape", Q, 64) == QMatrix{{2, 0, 0}, {0, 8, 0}, {0, 0, -2}});
  const json negative =
      json::array({json::array({"-1", "0", "0"}), json::array({"0", "-4", "0"}), json::array({"0", "0", "1"})});
  CHECK(rejection([&] { stated_shape_h(negative, "p", Q, 64); }).reason ==
        "p is not a positive multiple of the scene's shape");
  const json other =
      json::array({json::array({"2", "0", "0"}), json::array({"0", "4", "0"}), json::array({"0", "0", "-2"})});
  CHECK(rejection([&] { stated_shape_h(other, "p", Q, 64); }).claim == "net");
  const QMatrix P{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // det > 0: not an ellipse
  const json same =
      json::array({json::array({"1", "0", "0"}), json::array({"0", "1", "0"}), json::array({"0", "0", "1"})});
  CHECK(rejection([&] { stated_shape_h(same, "p", P, 64); }).reason.find("det Q is not < 0") != std::string::npos);
  CHECK(rejection([&] { stated_shape_h(json::array({json::array({"1"})}), "p", Q, 64); }).claim ==
        "certificate format");

  // M(x) = [[1, 0, 3x], [0, 1, 0], [0, 0, 1]]: its inverse [[1, 0, -3x], ...], c = 1
  PolyMatrix M(3, std::vector<QPoly>(3));
  for (int i = 0; i < 3; ++i) M[i][i] = QPoly::constant(1);
  M[0][2] = poly({0, 3});
  auto mat = [](const std::string& c02, const std::string& d) {
    return json::array({json::array({json::array({d}), json::array(), json::parse(c02)}),
                        json::array({json::array(), json::array({d}), json::array()}),
                        json::array({json::array(), json::array(), json::array({d})})});
  };
  const PolyMatrix N = stated_inverse_h(mat(R"(["0", "-3"])", "1"), "net.a.inverse", M, 64);
  CHECK(N[0][2] == poly({0, -3}));
  CHECK(rejection([&] {
          stated_inverse_h(mat(R"(["0", "3"])", "1"), "p", M, 64);
        }).reason.find("not a multiple of the identity") != std::string::npos);
  // (x - 1/2) times the inverse: c(x) = x - 1/2 vanishes in [0, 1]
  json half = json::array({json::array({json::array({"-1/2", "1"}), json::array(), json::array({"0", "3/2", "-3"})}),
                           json::array({json::array(), json::array({"-1/2", "1"}), json::array()}),
                           json::array({json::array(), json::array(), json::array({"-1/2", "1"})})});
  CHECK(rejection([&] { stated_inverse_h(half, "p", M, 64); }).reason.find("c vanishing in [0, 1]") !=
        std::string::npos);
  json deep = mat(R"(["0", "-3"])", "1");
  deep[1][0] = json::array();
  for (int k = 0; k < 66; ++k) deep[1][0].push_back("0");
  CHECK(rejection([&] { stated_inverse_h(deep, "p", M, 64); }).reason.find("degree at most 64") != std::string::npos);
}

}  // namespace ECCD_UNITY_ID
