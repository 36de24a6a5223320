// The exclusion step of the end proofs (certified/exclusion.hpp), against
// exact rational arithmetic on polynomials whose zero sets are known.
//
// Tested, over MPFI intervals and intervals of doubles:
//   - the nets handed to the predicate are the nets of the box it is told:
//     a Bernstein net's corner coefficients are F's values at the box's
//     corners, so they must enclose the exact F (and, for a second net, F_u)
//     there;
//   - soundness with the sign predicate of the proofs (every control point
//     of one strict sign): on the circle F = (u - 1/2)^2 + (t - 1/2)^2 - 1/16
//     every excluded box holds no zero (decided exactly by the box's nearest
//     and farthest points from the centre), the excluded boxes are disjoint
//     sub-boxes that with the kept region cover the whole region (areas),
//     and none lies inside the kept region;
//   - a zero outside the kept region makes the run stuck at max_depth on a
//     box that truly meets the zero set (the line u = t - 1/3, exact signs at
//     the box's corners), whose size is the region's halved max_depth times;
//   - t_every: u is halved every level, t once every t_every levels (the
//     sides of the boxes the predicate sees);
//   - the budgets: max_boxes (the count passed by one), the kept region
//     covering everything (one box, no predicate call), a passed deadline.
#include "certified/exclusion.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <map>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

struct Mono3 {  // coefficient of u^i s^j t^k
  std::array<int, 3> n{};
  std::map<std::array<int, 3>, mpq_class> a;
  mpq_class operator()(const mpq_class& u, const mpq_class& s, const mpq_class& t) const {
    mpq_class r = 0;
    const std::array<const mpq_class*, 3> x{&u, &s, &t};
    for (const auto& [e, c] : a) {
      mpq_class term = c;
      for (int ax = 0; ax < 3; ++ax)
        for (int p = 0; p < e[ax]; ++p) term *= *x[ax];
      r += term;
    }
    return r;
  }
};

mpz_class binom(int n, int k) {
  mpz_class r;
  mpz_bin_uiui(r.get_mpz_t(), unsigned(n), unsigned(k));
  return r;
}

// x^i = sum_{j >= i} C(j, i) / C(n, i) B^n_j(x) along each axis, enclosed in T.
template <class T>
TriBern<T> to_net(const Mono3& p, int bits) {
  std::vector<mpq_class> c(std::size_t(p.n[0] + 1) * (p.n[1] + 1) * (p.n[2] + 1), mpq_class(0));
  auto w = [](int i, int j, int n) {
    mpq_class q(binom(j, i), binom(n, i));
    q.canonicalize();  // gmpxx's (num, den) constructor does not
    return q;
  };
  auto idx = [&](int i, int j, int k) { return (std::size_t(i) * (p.n[1] + 1) + j) * (p.n[2] + 1) + k; };
  for (const auto& [e, v] : p.a)
    for (int j0 = e[0]; j0 <= p.n[0]; ++j0)
      for (int j1 = e[1]; j1 <= p.n[1]; ++j1)
        for (int j2 = e[2]; j2 <= p.n[2]; ++j2)
          c[idx(j0, j1, j2)] += v * w(e[0], j0, p.n[0]) * w(e[1], j1, p.n[1]) * w(e[2], j2, p.n[2]);
  TriBern<T> r;
  r.n = p.n;
  for (const auto& q : c) {
    if constexpr (std::is_same_v<T, Interval>) {
      (void)bits;
      r.c.push_back(interval_of(q));
    } else {
      r.c.push_back(MpfiInterval(q, bits));
    }
  }
  return r;
}

mpq_class lo_of(const Interval& x) { return mpq_class(x.lo); }
mpq_class hi_of(const Interval& x) { return mpq_class(x.hi); }
mpq_class lo_of(const MpfiInterval& x) {
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), &x.get()->left);
  return q;
}
mpq_class hi_of(const MpfiInterval& x) {
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), &x.get()->right);
  return q;
}
template <class T>
bool encloses(const T& x, const mpq_class& q) {
  return lo_of(x) <= q && q <= hi_of(x);
}

template <class T>
T half_of() {
  if constexpr (std::is_same_v<T, Interval>)
    return Interval(0.5, 0.5);
  else
    return MpfiInterval(mpq_class(1, 2), 128);
}

// (u - 1/2)^2 + (t - 1/2)^2 - 1/16: zero on the circle of radius 1/4 about (1/2, 1/2); degree 0 in s.
Mono3 circle() {
  Mono3 p;
  p.n = {2, 0, 2};
  p.a[{2, 0, 0}] = 1;
  p.a[{1, 0, 0}] = -1;
  p.a[{0, 0, 2}] = 1;
  p.a[{0, 0, 1}] = -1;
  p.a[{0, 0, 0}] = mpq_class(1, 2) - mpq_class(1, 16);
  return p;
}
Mono3 circle_du() {  // 2u - 1
  Mono3 p;
  p.n = {1, 0, 2};
  p.a[{1, 0, 0}] = 2;
  p.a[{0, 0, 0}] = -1;
  return p;
}

// The exact test: does the closed box [u0, u1] x [t0, t1] meet the circle?
bool box_meets_circle(const ExclusionRegion& b) {
  const mpq_class c(1, 2), r2(1, 16);
  auto nearest = [&](const mpq_class& a0, const mpq_class& a1) {
    return c < a0 ? mpq_class(a0 - c) : c > a1 ? mpq_class(c - a1) : mpq_class(0);
  };
  auto farthest = [&](const mpq_class& a0, const mpq_class& a1) {
    return std::max(mpq_class(abs(a0 - c)), mpq_class(abs(a1 - c)));
  };
  const mpq_class nu = nearest(b.u0, b.u1), nt = nearest(b.t0, b.t1);
  const mpq_class fu = farthest(b.u0, b.u1), ft = farthest(b.t0, b.t1);
  return nu * nu + nt * nt <= r2 && r2 <= fu * fu + ft * ft;
}

}  // namespace

TEMPLATE_TEST_CASE("exclude_region excludes only boxes free of zeros and covers the region", "[certified][exclusion]",
                   MpfiInterval, Interval) {
  const Mono3 F = circle(), Fu = circle_du();
  const std::array<TriBern<TestType>, 2> nets{to_net<TestType>(F, 128), to_net<TestType>(Fu, 128)};
  const ExclusionRegion region{0, 1, 0, 1};
  for (const ExclusionRegion& keep :
       {ExclusionRegion{mpq_class(1, 5), mpq_class(4, 5), mpq_class(1, 5), mpq_class(4, 5)},
        ExclusionRegion{mpq_class(3, 16), mpq_class(13, 16), mpq_class(3, 16), mpq_class(13, 16)}}) {
    std::vector<ExclusionRegion> excluded;
    long calls = 0;
    auto pred = [&](const std::array<TriBern<TestType>, 2>& f, const ExclusionRegion& b) {
      ++calls;
      // the nets are those of the box b: corner coefficients enclose F and F_u at b's corners
      const int nu = f[0].n[0], nt = f[0].n[2];
      CHECK(encloses(f[0].at(0, 0, 0), F(b.u0, 0, b.t0)));
      CHECK(encloses(f[0].at(nu, 0, nt), F(b.u1, 0, b.t1)));
      CHECK(encloses(f[0].at(nu, 0, 0), F(b.u1, 0, b.t0)));
      CHECK(encloses(f[1].at(f[1].n[0], 0, 0), Fu(b.u1, 0, b.t0)));
      CHECK(encloses(f[1].at(0, 0, f[1].n[2]), Fu(b.u0, 0, b.t1)));
      if (f[0].strict_sign() == 0) return false;
      excluded.push_back(b);
      return true;
    };
    const ExclusionResult res = exclude_region(nets, 0, 2, region, keep, pred, 100000, 12, 1, half_of<TestType>());
    REQUIRE(res.status == ExclusionResult::ok);
    CHECK(calls >= 4);
    CHECK(res.boxes > calls);  // the boxes inside the kept region are counted, not asked about
    mpq_class area = 0;
    for (const auto& b : excluded) {
      INFO("box [" << b.u0 << ", " << b.u1 << "] x [" << b.t0 << ", " << b.t1 << "]");
      CHECK_FALSE(box_meets_circle(b));
      CHECK_FALSE((b.u0 >= keep.u0 && b.u1 <= keep.u1 && b.t0 >= keep.t0 && b.t1 <= keep.t1));
      area += (b.u1 - b.u0) * (b.t1 - b.t0);
    }
    // disjoint sub-boxes of the unit square that, with the kept region, cover it
    CHECK(area <= 1);
    CHECK(area >= 1 - (keep.u1 - keep.u0) * (keep.t1 - keep.t0));
  }
  // the kept square [1/4, 3/4]^2 touches the circle at (1/2, 1/4) from inside: the box below that point
  // holds the zero at its corner and cannot be excluded
  auto sign_only = [](const std::array<TriBern<TestType>, 2>& f, const ExclusionRegion&) {
    return f[0].strict_sign() != 0;
  };
  const ExclusionResult res = exclude_region(
      nets, 0, 2, region, ExclusionRegion{mpq_class(1, 4), mpq_class(3, 4), mpq_class(1, 4), mpq_class(3, 4)},
      sign_only, 100000, 8, 1, half_of<TestType>());
  CHECK(res.status == ExclusionResult::stuck);
}

TEMPLATE_TEST_CASE("exclude_region is stuck on a box that meets a zero outside the kept region",
                   "[certified][exclusion]", MpfiInterval, Interval) {
  // F = u - t + 1/3: zero on the line u = t - 1/3, which crosses the region [0, 1]^2 away from the kept box
  Mono3 F;
  F.n = {1, 0, 1};
  F.a[{1, 0, 0}] = 1;
  F.a[{0, 0, 1}] = -1;
  F.a[{0, 0, 0}] = mpq_class(1, 3);
  const std::array<TriBern<TestType>, 1> nets{to_net<TestType>(F, 128)};
  const ExclusionRegion keep{mpq_class(1, 2), 1, 0, mpq_class(1, 2)};
  for (int depth : {1, 4, 7}) {
    auto pred = [](const std::array<TriBern<TestType>, 1>& f, const ExclusionRegion&) {
      return f[0].strict_sign() != 0;
    };
    const ExclusionResult res =
        exclude_region(nets, 0, 2, ExclusionRegion{0, 1, 0, 1}, keep, pred, 100000, depth, 1, half_of<TestType>());
    REQUIRE(res.status == ExclusionResult::stuck);
    // the stuck box has side 2^-depth and its corner on that grid; F takes both signs (or 0) at its corners
    const mpq_class w(1, mpz_class(1) << depth);
    const mpq_class gu = res.u0 / w, gt = res.t0 / w;
    CHECK(gu.get_den() == 1);
    CHECK(gt.get_den() == 1);
    mpq_class lo = F(res.u0, 0, res.t0), hi = lo;
    for (const auto& v : {F(res.u0 + w, 0, res.t0), F(res.u0, 0, res.t0 + w), F(res.u0 + w, 0, res.t0 + w)}) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    CHECK(lo <= 0);
    CHECK(hi >= 0);
  }
}

TEST_CASE("exclude_region splits t once every t_every levels", "[certified][exclusion]") {
  Mono3 F;  // a positive constant: never excluded by this predicate, so every box down to max_depth is visited
  F.n = {2, 0, 2};
  F.a[{0, 0, 0}] = 1;
  const std::array<TriBern<Interval>, 1> nets{to_net<Interval>(F, 53)};
  for (int every : {1, 2, 3}) {
    long calls = 0;
    auto pred = [&](const std::array<TriBern<Interval>, 1>&, const ExclusionRegion& b) {
      ++calls;
      // at depth d the u side is 2^-d (u halves every level) and the t side (1/2) 2^-floor(d / every)
      const mpq_class wu = b.u1 - b.u0, wt = b.t1 - b.t0;
      REQUIRE(wu.get_num() == 1);
      REQUIRE(mpz_popcount(wu.get_den_mpz_t()) == 1);
      const long d = long(mpz_sizeinbase(wu.get_den_mpz_t(), 2)) - 1;
      INFO("every " << every << " depth " << d);
      CHECK(wt == mpq_class(1, mpz_class(1) << (1 + d / every)));
      return false;
    };
    const int depth = 6;
    const ExclusionResult res =
        exclude_region(nets, 0, 2, ExclusionRegion{0, 1, 0, mpq_class(1, 2)}, ExclusionRegion{2, 2, 2, 2}, pred,
                       1000000, depth, every, Interval(0.5, 0.5));
    CHECK(res.status == ExclusionResult::stuck);
    // along the path to the first stuck leaf: one box per level 0..depth
    CHECK(calls == depth + 1);
    CHECK(res.boxes == depth + 1);
  }
}

TEST_CASE("exclude_region budgets: boxes, a kept region covering all, the deadline", "[certified][exclusion]") {
  Mono3 F;
  F.n = {1, 0, 1};
  F.a[{0, 0, 0}] = 1;
  const std::array<TriBern<MpfiInterval>, 1> nets{to_net<MpfiInterval>(F, 64)};
  const MpfiInterval half(mpq_class(1, 2), 64);
  long calls = 0;
  auto never = [&](const std::array<TriBern<MpfiInterval>, 1>&, const ExclusionRegion&) {
    ++calls;
    return false;
  };
  const ExclusionRegion all{0, 1, 0, 1};
  ExclusionResult res = exclude_region(nets, 0, 2, all, ExclusionRegion{2, 2, 2, 2}, never, 10, 30, 1, half);
  CHECK(res.status == ExclusionResult::too_many_boxes);
  CHECK(res.boxes == 11);
  CHECK(calls == 10);

  calls = 0;
  res = exclude_region(nets, 0, 2, all, ExclusionRegion{-1, 2, -1, 2}, never, 10, 30, 1, half);
  CHECK(res.status == ExclusionResult::ok);
  CHECK(res.boxes == 1);
  CHECK(calls == 0);

  calls = 0;
  {
    ScopedDeadline gone(1e-9);
    while (!deadline_passed()) {}
    res = exclude_region(nets, 0, 2, all, ExclusionRegion{2, 2, 2, 2}, never, 10, 30, 1, half);
  }
  CHECK(res.status == ExclusionResult::deadline);
  CHECK(res.boxes == 1);
  CHECK(calls == 0);
}

}  // namespace ECCD_UNITY_ID
