// number/forward_bound.hpp: plain double with an a-priori error bound carried
// as a magnitude and a rounding depth (Higham, Lemma 3.1). Checked against the
// same programs run exactly in mpq on the same doubles (the leaves), over
// seeded random straight-line programs of +, -, * (and negation, integer
// constants): |v - exact| <= bound() = 2 d u m whenever d u <= 2^-10, and
// m >= |v|; the depth rules of the statement (leaf 0, a ± b max + 1, a * b
// sum + 1, -a unchanged, a constant 0); inverse_square_leaf at depth 2;
// underflow (products below the smallest normal) stays inside the bound;
// scalar_traits sign: zero only when m = 0, uncertain when |v| <= bound, for
// a NaN or infinite magnitude and for depths past 2^43, else v's sign, and
// that claimed sign is the exact one.
#include "number/forward_bound.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

struct Both {
  ForwardBound f;
  mpq_class q;
};

// A random program: a pool of leaves, each step combines two pool entries.
Both random_program(std::mt19937_64& rng, double scale, int steps) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Both> pool;
  for (int i = 0; i < 6; ++i) {
    const double x = u(rng) * scale;
    pool.push_back({ForwardBound::exact(x), mpq_class(x)});
  }
  for (int s = 0; s < steps; ++s) {
    const Both& a = pool[rng() % pool.size()];
    const Both& b = pool[rng() % pool.size()];
    switch (rng() % 5) {
      case 0:
        pool.push_back({a.f + b.f, a.q + b.q});
        break;
      case 1:
        pool.push_back({a.f - b.f, a.q - b.q});
        break;
      case 2:
        pool.push_back({a.f * b.f, a.q * b.q});
        break;
      case 3:
        pool.push_back({-a.f, -a.q});
        break;
      default:
        pool.push_back({3 * a.f, 3 * a.q});
        break;
    }
  }
  return pool.back();
}

}  // namespace

TEST_CASE("ForwardBound's bound holds against the exact program on the same doubles", "[number][forward_bound]") {
  std::mt19937_64 rng(4342);
  int certain = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = trial % 3 == 0 ? 1e-3 : trial % 3 == 1 ? 1.0 : 1e5;
    const Both p = random_program(rng, scale, 4 + int(trial % 20));
    const ForwardBound& f = p.f;
    if (!(f.depth() * 0x1p-53 <= 0x1p-10) || !std::isfinite(f.magnitude())) continue;
    INFO("trial " << trial);
    CHECK(abs(mpq_class(f.value()) - p.q) <= mpq_class(f.bound()));
    CHECK(f.magnitude() >= std::fabs(f.value()));
    const Sign s = sign(f);
    if (s != Sign::uncertain) {
      CHECK(s == sign(p.q));
      ++certain;
    }
  }
  CHECK(certain > 1000);
}

TEST_CASE("ForwardBound's depth rules, leaves and sign rule", "[number][forward_bound]") {
  const ForwardBound a = ForwardBound::exact(3.0), b = ForwardBound::exact(-0.1);
  CHECK(a.depth() == 0);
  CHECK(a.magnitude() == 3.0);
  CHECK(ForwardBound(7).depth() == 0);
  CHECK((a + b).depth() == 1);
  CHECK((a * b).depth() == 1);
  CHECK(((a * b) * (a + b)).depth() == 3);  // 1 + 1 + 1
  CHECK(((a * b) + a).depth() == 2);        // max(1, 0) + 1
  CHECK((-(a * b)).depth() == 1);
  CHECK((a - b).magnitude() == 3.0 + 0.1);  // a subtraction adds magnitudes
  // 1 / (a a) rounded twice: depth 2, and the exact 1/a² is within the bound
  const double x = 3.3;
  const ForwardBound inv = ForwardBound::inverse_square_leaf(x);
  CHECK(inv.depth() == 2);
  CHECK(abs(mpq_class(inv.value()) - 1 / (mpq_class(x) * mpq_class(x))) <= mpq_class(inv.bound()));
  // underflow: (1e-200)² is 0 in double, 1e-400 exactly; the 2^-1022 added per product covers it
  const ForwardBound t = ForwardBound::exact(1e-200) * ForwardBound::exact(1e-200);
  CHECK(t.value() == 0);
  CHECK(abs(mpq_class(t.value()) - mpq_class(1e-200) * mpq_class(1e-200)) <= mpq_class(t.bound()));
  CHECK(sign(t) == Sign::uncertain);  // a non-zero tiny value: not called zero
  // sign: zero only when every monomial is zero
  CHECK(sign(ForwardBound::exact(0.0) * a) == Sign::uncertain);  // m = 2^-1022 > 0: not a proof of zero
  CHECK(sign(ForwardBound::exact(0.0) + ForwardBound::exact(0.0)) == Sign::zero);
  CHECK(sign(ForwardBound(1.0, 1.0, 0x1p44)) == Sign::uncertain);  // depth past 2^43
  CHECK(sign(ForwardBound(1.0, std::numeric_limits<double>::infinity(), 1)) == Sign::uncertain);
  CHECK(sign(ForwardBound(std::nan(""), 1.0, 1)) == Sign::uncertain);
  CHECK(sign(ForwardBound(1e-15, 1.0, 10)) == Sign::uncertain);  // |v| <= 2 · 10 · 2^-53
  CHECK(sign(ForwardBound(-1e-10, 1.0, 10)) == Sign::negative);
  CHECK(scalar_traits<ForwardBound>::abs(ForwardBound(-2.0, 5.0, 3)).value() == 2.0);
  CHECK(scalar_traits<ForwardBound>::abs(ForwardBound(-2.0, 5.0, 3)).bound() == ForwardBound(-2.0, 5.0, 3).bound());
}

}  // namespace ECCD_UNITY_ID
