// The guard's one-pass loops (number/running_error_loops.hpp, issue 30 point
// 5): products in Bernstein and power form, de Casteljau evaluation and
// subdivision, Horner and the power-to-Bernstein conversion, in
// Bounded<double>. Each result must (a) hold the plain-double value bit for
// bit (the guard decides with the as-published numbers) and (b) have a bound
// that contains the exact result computed in rationals from exact inputs
// anywhere within the inputs' own bounds (the inputs are perturbed to the
// ends of their bounds and inside). Degrees up to 144 (2D Δ of motion degree 6), past 56, where the
// binomial coefficients of double are rounded; and the binomial rows of
// Bounded<double> are exact (bound 0) up to 2^53 and contain C(n, k) above.
#include "kernel/bernstein.hpp"
#include "kernel/bivariate_bernstein.hpp"
#include "kernel/binomial.hpp"
#include "kernel/polynomial.hpp"
#include "number/bernstein_columns.hpp"
#include "number/rational_traits.hpp"
#include "number/running_error.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using BD = Bounded<double>;

struct Input {
  std::vector<BD> b;
  std::vector<mpq_class> exact;  // within the bounds of b
  std::vector<double> plain;
};

// n + 1 values of mixed signs and magnitudes; every other one with an error bound, its exact value at
// -e, +e or a fraction of e from the double.
Input random_input(std::mt19937_64& rng, int n, bool with_errors) {
  std::uniform_real_distribution<double> val(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-6, 2), pick(-4, 4);
  Input in;
  for (int i = 0; i <= n; ++i) {
    double v = std::ldexp(val(rng), scale(rng));
    double e = (with_errors && i % 2 == 0) ? std::fabs(v) * 0x1p-50 + 0x1p-70 : 0.0;
    in.b.emplace_back(v, e);
    in.plain.push_back(v);
    in.exact.push_back(mpq_class(v) + mpq_class(e) * mpq_class(pick(rng), 4));
  }
  return in;
}

void check_contains(const std::vector<BD>& got, const std::vector<mpq_class>& exact, const std::vector<double>& plain) {
  REQUIRE(got.size() == exact.size());
  REQUIRE(got.size() == plain.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    INFO("k = " << k);
    CHECK(got[k].value() == plain[k]);  // bit for bit: == on doubles is meant
    REQUIRE(std::isfinite(got[k].bound()));
    mpq_class err = abs(mpq_class(got[k].value()) - exact[k]);
    CHECK(err <= mpq_class(got[k].bound()));
  }
}

// The same loops with Bounded<double>'s operators, one by one (the generic code of kernel/bernstein.hpp):
// the one-pass bounds must equal these to rounding (a term left out would make them smaller).
std::vector<BD> generic_convolution(const std::vector<BD>& x, const std::vector<BD>& y) {
  std::vector<BD> r(x.size() + y.size() - 1, BD(0));
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < y.size(); ++j) {
      BD p = x[i] * y[j];
      r[i + j] = r[i + j] + p;
    }
  return r;
}
std::vector<BD> generic_right_piece(std::vector<BD> w, const BD& t) {
  BD s = BD(1) - t;
  const int n = int(w.size()) - 1;
  for (int r = 1; r <= n; ++r)
    for (int i = 0; i + r <= n; ++i) {
      BD x = s * w[i];
      BD y = t * w[i + 1];
      w[i] = x + y;
    }
  return w;
}
void check_same_bounds(const std::vector<BD>& fused, const std::vector<BD>& generic) {
  REQUIRE(fused.size() == generic.size());
  for (std::size_t k = 0; k < fused.size(); ++k) {
    INFO("k = " << k << ": one pass " << fused[k].bound() << ", by operators " << generic[k].bound());
    CHECK(fused[k].value() == generic[k].value());
    CHECK(fused[k].bound() <= generic[k].bound() * (1 + 0x1p-30));
    CHECK(fused[k].bound() >= generic[k].bound() * (1 - 0x1p-30));
  }
}

}  // namespace

TEST_CASE("running_error_loops: the one-pass bounds are those of Bounded's operators, to rounding",
          "[running-error-loops]") {
  std::mt19937_64 rng(34);
  for (int m : {0, 4, 36, 72})
    for (int n : {0, 9, 36}) {
      INFO("degrees " << m << " x " << n);
      Input x = random_input(rng, m, true), y = random_input(rng, n, false);
      const Poly<BD> r = Poly<BD>(x.b) * Poly<BD>(y.b);
      check_same_bounds(r.c, generic_convolution(x.b, y.b));
    }
  // A split at a point (t exact, s = fl(1 - t)) takes the a-priori bound of the triangle
  // (running_error_loops.hpp, AprioriTriangle): not the operators' bound, but within a small factor of it
  // (on these inputs of mixed signs it counts |b| where the operators count the cancelled intermediate
  // values; measured: up to about x9.4 at degree 24; above degree 32 the running bound is kept); containment is checked
  // in the tests below.
  // At the midpoint (bisection's split: t = 1/2 exact) the weights are exact and the products exact halvings:
  // the step's bound has the sum's rounding only, at most the operators' bound at every degree.
  double worst = 0, worst_split_limit = 0;
  int midpoint_checks = 0;
  for (int n : {1, 24, 40, 41, 144}) {
    INFO("degree " << n);
    Input x = random_input(rng, n, true);
    for (double tau : {0.5, 0.375}) {
      const BD t(tau, 0);
      const std::vector<BD> fused = split(Bern<BD>(x.b), t).second.b, generic = generic_right_piece(x.b, t);
      for (std::size_t k = 0; k < fused.size(); ++k) {
        CHECK(fused[k].value() == generic[k].value());
        (n <= 32 || n > 40 ? worst : worst_split_limit) =
            std::max(n <= 32 || n > 40 ? worst : worst_split_limit, fused[k].bound() / generic[k].bound());
        if (tau == 0.5) {
          CHECK(fused[k].bound() <= generic[k].bound() * (1 + 0x1p-30) + 0x1p-1060);
          ++midpoint_checks;
        }
      }
    }
  }
  CHECK(midpoint_checks == 2 + 25 + 41 + 42 + 145);
  INFO("the a-priori bound over the operators' bound, at most " << worst << " (degrees 33 to 40: " << worst_split_limit
                                                                << ")");
  CHECK(worst <= 16.0);
  // Subdivision keeps the a-priori bound up to degree 40 (kAprioriMaxDegreeSplit, for paper 002's degree-36 net):
  // its looseness grows with the degree, measured x17.3 at degree 40 on these inputs; the same answers on every
  // guarded run measured when that limit was set.
  CHECK(worst_split_limit <= 24.0);
}

TEST_CASE("running_error_loops: Bernstein products hold the plain values and their bounds contain the exact product",
          "[running-error-loops]") {
  std::mt19937_64 rng(30);
  for (int m : {0, 1, 5, 24, 36, 60, 144})
    for (int n : {0, 3, 24, 36, 50}) {
      INFO("degrees " << m << " x " << n);
      Input x = random_input(rng, m, true), y = random_input(rng, n, true);
      const Bern<BD> r = Bern<BD>(x.b) * Bern<BD>(y.b);
      const Bern<mpq_class> ex = Bern<mpq_class>(x.exact) * Bern<mpq_class>(y.exact);
      const Bern<double> pl = Bern<double>(x.plain) * Bern<double>(y.plain);
      check_contains(r.b, ex.b, pl.b);
    }
}

TEST_CASE("running_error_loops: power-form products and Horner contain the exact results", "[running-error-loops]") {
  std::mt19937_64 rng(31);
  for (int m : {1, 7, 24, 72})
    for (int n : {0, 12, 36}) {
      INFO("degrees " << m << " x " << n);
      Input x = random_input(rng, m, true), y = random_input(rng, n, true);
      // Leading coefficients non-zero (Poly trims zeros): the inputs are non-zero almost surely.
      const Poly<BD> r = Poly<BD>(x.b) * Poly<BD>(y.b);
      const Poly<mpq_class> ex = Poly<mpq_class>(x.exact) * Poly<mpq_class>(y.exact);
      const Poly<double> pl = Poly<double>(x.plain) * Poly<double>(y.plain);
      check_contains(r.c, ex.c, pl.c);
      for (double tv : {0.0, 0.3, 0.5, 0.999, 1.0, -0.7}) {
        INFO("t = " << tv);
        const BD t(tv, tv == 0.5 ? 0.0 : 0x1p-60);  // with and without an error of its own
        const BD h = r(t);
        const double hp = pl(tv);
        CHECK(h.value() == hp);
        for (int side : {-1, 1}) {
          const mpq_class te = mpq_class(tv) + side * mpq_class(t.bound());
          // Horner of the computed coefficients' exact counterparts: r's coefficients are within their own
          // bounds of ex's, and h's bound covers those, t's and the rounding.
          mpq_class v = 0;
          for (int i = ex.degree(); i >= 0; --i) v = v * te + ex.c[i];
          CHECK(abs(mpq_class(h.value()) - v) <= mpq_class(h.bound()));
        }
      }
    }
}

TEST_CASE("running_error_loops: de Casteljau values and subdivision contain the exact ones", "[running-error-loops]") {
  std::mt19937_64 rng(32);
  for (int n : {0, 1, 8, 30, 63, 64, 90, 144}) {
    Input x = random_input(rng, n, true);
    for (double tau : {0.5, 0.25, 0.8125, 0.1}) {
      INFO("degree " << n << ", tau " << tau);
      const BD t(tau, 0);
      auto [l, r] = split(Bern<BD>(x.b), t);
      auto [le, re] = split(Bern<mpq_class>(x.exact), mpq_class(tau));
      auto [lp, rp] = split(Bern<double>(x.plain), tau);
      check_contains(l.b, le.b, lp.b);
      check_contains(r.b, re.b, rp.b);
      std::vector<BD> kl = x.b, kr = x.b;  // the in-place pieces: the same as split's
      keep_left(std::span<BD>(kl), t);
      keep_right(std::span<BD>(kr), t);
      check_contains(kl, le.b, lp.b);
      check_contains(kr, re.b, rp.b);
      std::vector<BD> sl(x.b.size()), sr(x.b.size());  // both pieces from one triangle: the same again
      split_into(std::span<const BD>(x.b), t, std::span<BD>(sl), std::span<BD>(sr));
      check_contains(sl, le.b, lp.b);
      check_contains(sr, re.b, rp.b);
      const BD v = Bern<BD>(x.b)(t);
      CHECK(v.value() == Bern<double>(x.plain)(tau));
      CHECK(abs(mpq_class(v.value()) - Bern<mpq_class>(x.exact)(mpq_class(tau))) <= mpq_class(v.bound()));
    }
  }
}

TEST_CASE("running_error_loops: above degree 32 a value takes the a-priori bound only where it reads the sign",
          "[running-error-loops]") {
  // A value is one sign read: where the a-priori bound decides the sign it is kept, else the running
  // triangle's (tighter where signs mix) is. Far from a root both decide; at a root of the exact polynomial
  // (the line t - tau, Bernstein coefficients i/n - tau, and the same line plus a multiple of
  // (t - tau)^2 of mixed-sign coefficients) the value is rounding noise, and the bound must be no larger
  // than the running bound of Bounded's operators, one by one, while containing the exact value 0.
  std::mt19937_64 rng(37);
  int near_root_checks = 0;
  for (int n : {33, 40, 57, 90, 144}) {
    for (double tau : {0.5, 0.3, 0.8125}) {
      INFO("degree " << n << ", tau " << tau);
      const BD t(tau, 0);
      Input x = random_input(rng, n, true);  // generic: mixed signs, the value far from 0
      const BD v = Bern<BD>(x.b)(t);
      CHECK(v.value() == Bern<double>(x.plain)(tau));
      CHECK(abs(mpq_class(v.value()) - Bern<mpq_class>(x.exact)(mpq_class(tau))) <= mpq_class(v.bound()));
      // t - tau, exactly: b_i = i/n - tau (rounded: the exact coefficients are those doubles)
      std::vector<BD> line;
      std::vector<double> plain;
      std::vector<mpq_class> exact;
      for (int i = 0; i <= n; ++i) {
        const double c = double(i) / n - tau;
        line.emplace_back(c, 0.0);
        plain.push_back(c);
        exact.push_back(mpq_class(c));
      }
      const BD at = Bern<BD>(line)(t);
      const BD generic = generic_right_piece(line, t)[0];
      CHECK(at.value() == Bern<double>(plain)(tau));
      CHECK(abs(mpq_class(at.value()) - Bern<mpq_class>(exact)(mpq_class(tau))) <= mpq_class(at.bound()));
      if (std::fabs(at.value()) <= at.bound()) {  // the sign is open: the running bound was asked
        CHECK(at.bound() <= generic.bound() * (1 + 0x1p-30));
        ++near_root_checks;
      }
    }
  }
  CHECK(near_root_checks > 5);  // the lines' values are noise: most leave the sign open
}

TEST_CASE("running_error_loops: the power-to-Bernstein conversion contains the exact coefficients",
          "[running-error-loops]") {
  std::mt19937_64 rng(33);
  for (int n : {0, 1, 12, 36, 56, 57, 80, 144}) {
    INFO("degree " << n);
    Input x = random_input(rng, n, true);
    const Bern<BD> b = to_bernstein(Poly<BD>(x.b), n);
    const Bern<mpq_class> be = to_bernstein(Poly<mpq_class>(x.exact), n);
    const Bern<double> bp = to_bernstein(Poly<double>(x.plain), n);
    check_contains(b.b, be.b, bp.b);
  }
}

// The conversion's bounds against Bounded's operators term by term (a product, a division by C(n, i) and a
// sum each): equal to rounding, for exact binomial rows (n <= 56) and rounded ones with bounds of their own
// (n > 56, where each quotient's bound takes the divisor's error), and for a polynomial of lower degree.
TEST_CASE("running_error_loops: the conversion's bounds are those of Bounded's operators, to rounding",
          "[running-error-loops]") {
  std::mt19937_64 rng(35);
  for (int n : {1, 12, 56, 57, 100, 144})
    for (int deg : {n, n / 3}) {
      INFO("degree " << deg << " in the basis of degree " << n);
      Input x = random_input(rng, deg, true);
      const Poly<BD> p(x.b);
      const Bern<BD> fused = to_bernstein(p, n);
      const BD like(1.0, 0);
      const std::vector<BD>& cn = binomial_row(n, like);
      std::vector<BD> generic(n + 1, BD(0));
      for (int k = 0; k <= n; ++k) {
        const std::vector<BD>& ck = binomial_row(k, like);
        for (int i = 0; i <= k && i <= p.degree(); ++i) {
          BD term = ck[i] * p.c[i] / cn[i];
          generic[k] = generic[k] + term;
        }
      }
      check_same_bounds(fused.b, generic);
    }
}

// to_bernstein's column order (to_bernstein_columns, exact binomials, n <= 56) against its row order (one
// sum_of_ratios per output over the binomial rows, the loop it replaces): the same values and the same bounds,
// bit for bit, at every degree and for polynomials of lower degree; not applicable above degree 56 or for a
// non-finite coefficient (to_bernstein then takes the row order).
TEST_CASE("running_error_loops: the conversion in column order is the row order's, bit for bit",
          "[running-error-loops]") {
  std::mt19937_64 rng(37);
  const BD like(1.0, 0);
  int compared = 0;
  for (int n = 0; n <= 56; ++n)
    for (int deg : {n, n / 2, 0}) {
      INFO("degree " << deg << " in the basis of degree " << n);
      const Input x = random_input(rng, deg, true);
      std::vector<BD> cols(n + 1);
      REQUIRE(bernstein_columns::to_bernstein_columns(std::span<const BD>(x.b), n, std::span<BD>(cols)));
      const std::vector<BD>& cn = binomial_row(n, like);
      running_error_loops::DivisorFactors factors;
      REQUIRE(running_error_loops::divisor_factors(std::span<const BD>(cn), factors));
      for (int k = 0; k <= n; ++k) {
        const std::vector<BD>& ck = binomial_row(k, like);
        const BD row =
            running_error_loops::sum_of_ratios(ck.data(), x.b.data(), cn.data(), std::min(k, deg) + 1, &factors);
        INFO("k = " << k);
        CHECK(cols[k].value() == row.value());  // == on doubles is meant: bit for bit
        CHECK(cols[k].bound() == row.bound());
        ++compared;
      }
    }
  CHECK(compared > 3000);
  for (int n : {0, 7, 36, 56}) {  // the plain face's column order: the generic loop's values, bit for bit
    const Input x = random_input(rng, n / 2, false);
    std::vector<double> plain(n + 1);
    REQUIRE(bernstein_columns::to_bernstein_columns(std::span<const double>(x.plain), n, std::span<double>(plain)));
    const std::vector<double>& cn = binomial_row(n, 1.0);
    for (int k = 0; k <= n; ++k) {
      const std::vector<double>& ck = binomial_row(k, 1.0);
      double acc = 0;
      for (int i = 0; i <= k && i <= n / 2; ++i) {
        const double term = ck[i] * x.plain[i] / cn[i];
        acc = acc + term;
      }
      CHECK(plain[k] == acc);
    }
  }
  std::vector<BD> out(58), high(58, BD(1.0, 0));
  CHECK_FALSE(bernstein_columns::to_bernstein_columns(std::span<const BD>(high), 57, std::span<BD>(out)));
  std::vector<BD> bad{BD(1.0, 0), BD(std::numeric_limits<double>::infinity(), 0)};
  out.resize(3);
  CHECK_FALSE(bernstein_columns::to_bernstein_columns(std::span<const BD>(bad), 2, std::span<BD>(out)));
}

TEST_CASE("running_error_loops: binomial rows of Bounded<double> are exact below 2^53 and contain C(n, k) above",
          "[running-error-loops]") {
  const BD like(1.0, 0);
  for (int n : {10, 56, 57, 100, 200}) {
    const std::vector<BD>& row = binomial_row(n, like);
    mpz_class c = 1;
    for (int k = 0; k <= n; ++k) {
      INFO("C(" << n << ", " << k << ")");
      if (c <= mpz_class(9007199254740992.0)) {
        CHECK(row[k].bound() == 0);
        CHECK(mpq_class(row[k].value()) == mpq_class(c));
      } else {
        CHECK(abs(mpq_class(row[k].value()) - mpq_class(c)) <= mpq_class(row[k].bound()));
      }
      c = c * (n - k) / (k + 1);
    }
  }
}

namespace {

// A net of (m + 1) rows of n + 1 random inputs, with their exact and plain counterparts.
struct Net {
  BiBern<BD> b;
  BiBern<mpq_class> exact;
  BiBern<double> plain;
};
Net random_net(std::mt19937_64& rng, int m, int n) {
  Net net;
  for (int i = 0; i <= m; ++i) {
    Input row = random_input(rng, n, true);
    net.b.b.push_back(row.b);
    net.exact.b.push_back(row.exact);
    net.plain.b.push_back(row.plain);
  }
  return net;
}
// How many entries of got miss the exact net when their bounds are scaled by `scale` (1: the bound itself);
// the values must be the plain ones bit for bit.
int misses(const BiBern<BD>& got, const BiBern<mpq_class>& exact, const BiBern<double>& plain, double scale) {
  int out = 0;
  for (std::size_t i = 0; i < got.b.size(); ++i)
    for (std::size_t j = 0; j < got.b[i].size(); ++j) {
      CHECK(got.b[i][j].value() == plain.b[i][j]);  // bit for bit
      if (!(abs(mpq_class(got.b[i][j].value()) - exact.b[i][j]) <= mpq_class(got.b[i][j].bound() * scale))) ++out;
    }
  return out;
}

}  // namespace

// floating/bezier_ccd.hpp (classify_on_u) stops splitting a piece none of whose control points has a sign
// (|b_i| <= e_i for all i), because no piece split from it can have one: each split entry is a convex
// combination of the b_i, and its bound is at least that combination of the e_i plus the rounding. Checked on
// both pieces of splits at the midpoint (the running bound of a sum), at other points (the a-priori bound up to
// degree 40, the running one above) and for values: every entry stays without a sign.
TEST_CASE("running_error_loops: splitting coefficients without a sign gives coefficients without a sign",
          "[running-error-loops]") {
  std::mt19937_64 rng(36);
  std::uniform_real_distribution<double> val(-1.0, 1.0), frac(0.0, 1.0);
  std::uniform_int_distribution<int> scale(-40, 0);
  int checked = 0;
  for (int n : {1, 2, 4, 8, 30, 36, 41, 90, 144})
    for (int rep = 0; rep < 20; ++rep) {
      std::vector<BD> b;
      for (int i = 0; i <= n; ++i) {  // |v| <= e, some with |v| = e exactly, some with v = 0
        const double e = std::ldexp(frac(rng) + 0x1p-30, scale(rng));
        const double v = rep % 5 == 0 && i % 3 == 0 ? (i % 2 ? e : -e) : (rep % 7 == 1 ? 0.0 : e * val(rng));
        b.emplace_back(v, e);
        REQUIRE(sign(b.back()) == Sign::uncertain);
      }
      for (double tau : {0.5, 0.25, 0.8125, 0.1, 0.999}) {
        INFO("degree " << n << ", rep " << rep << ", tau " << tau);
        const BD t(tau, 0);
        std::vector<BD> lo(b.size()), hi(b.size());
        split_into(std::span<const BD>(b), t, std::span<BD>(lo), std::span<BD>(hi));
        for (std::size_t k = 0; k < b.size(); ++k) {
          CHECK(sign(lo[k]) == Sign::uncertain);
          CHECK(sign(hi[k]) == Sign::uncertain);
          checked += 2;
        }
        CHECK(sign(Bern<BD>(b)(t)) == Sign::uncertain);
      }
    }
  CHECK(checked > 10000);
}

TEST_CASE("running_error_loops: a net's subdivision in u holds the plain values and contains the exact net",
          "[running-error-loops]") {
  std::mt19937_64 rng(35);
  int weakened_misses = 0;
  for (int m : {1, 4, 12, 30})
    for (int n : {0, 4, 20})
      for (double tau : {0.5, 0.3125, 0.9}) {
        INFO("degrees " << m << " x " << n << ", tau " << tau);
        const Net net = random_net(rng, m, n);
        const BD t(tau, 0);
        for (bool left : {false, true}) {
          INFO((left ? "keep_u_left" : "keep_u_right"));
          BiBern<BD> f = net.b;
          BiBern<mpq_class> fe = net.exact;
          BiBern<double> fp = net.plain;
          if (left) {
            keep_u_left(f, t);
            keep_u_left(fe, mpq_class(tau));
            keep_u_left(fp, tau);
          } else {
            keep_u_right(f, t);
            keep_u_right(fe, mpq_class(tau));
            keep_u_right(fp, tau);
          }
          CHECK(misses(f, fe, fp, 1.0) == 0);
          weakened_misses += misses(f, fe, fp, 0x1p-8);
          // Column by column through the univariate one-pass loop: the same values, bounds equal to rounding.
          for (std::size_t j = 0; j < net.b.b[0].size(); ++j) {
            std::vector<BD> col;
            for (const auto& row : net.b.b) col.push_back(row[j]);
            if (left)
              keep_left(std::span<BD>(col), t);
            else
              keep_right(std::span<BD>(col), t);
            for (std::size_t i = 0; i < col.size(); ++i) {
              CHECK(f.b[i][j].value() == col[i].value());
              CHECK(f.b[i][j].bound() >= col[i].bound());
              CHECK(f.b[i][j].bound() <= col[i].bound() * (1 + 0x1p-30));
            }
          }
        }
      }
  // The check is not vacuous: the same bounds divided by 2^8 miss the exact net (the inputs sit at the
  // ends of their own bounds, whose propagation is most of the bound).
  CHECK(weakened_misses > 100);
}

// The a-priori bounds (running_error_loops.hpp: AprioriTriangle, bernstein_sum_nonnegative,
// elevate_exact_binomials) where the other tests do not reach them: an evaluation point with an error of its
// own (the restriction's tau = (b - a) / (1 - a)), the O(n) sum of the bound (degrees 12 to 32), and degree
// elevation with exact binomial rows. Each must hold the plain value bit for bit and contain the exact value
// for every exact point within the point's bound; the same bounds divided by 2^8 must miss somewhere, so the
// check is not vacuous.
TEST_CASE("running_error_loops: the a-priori bounds contain the exact values", "[running-error-loops]") {
  std::mt19937_64 rng(36);
  int weakened_misses = 0, checks = 0;
  for (int n : {3, 12, 20, 30, 32}) {
    Input x = random_input(rng, n, true);
    for (double tau : {0.5, 0.3, 0.875, 0.0625}) {
      for (double te : {0.0, 0x1p-52, 0x1p-40}) {
        INFO("degree " << n << ", tau " << tau << ", its bound " << te);
        const BD t(tau, te);
        const BD v = Bern<BD>(x.b)(t);
        CHECK(v.value() == Bern<double>(x.plain)(tau));
        for (int side : {-1, 0, 1}) {
          const mpq_class ts = mpq_class(tau) + side * mpq_class(te);
          const mpq_class err = abs(mpq_class(v.value()) - Bern<mpq_class>(x.exact)(ts));
          CHECK(err <= mpq_class(v.bound()));
          weakened_misses += err > mpq_class(v.bound() / 256) ? 1 : 0;
          ++checks;
        }
        // The restriction's pieces at a point with its own error: the piece at tau, against the exact one.
        std::vector<BD> kr = x.b;
        keep_right(std::span<BD>(kr), t);
        std::vector<double> pr = x.plain;
        keep_right(std::span<double>(pr), tau);
        for (int side : {-1, 1}) {
          std::vector<mpq_class> er = x.exact;
          keep_right(std::span<mpq_class>(er), mpq_class(mpq_class(tau) + side * mpq_class(te)));
          check_contains(kr, er, pr);
        }
      }
    }
  }
  for (int n : {0, 2, 4, 16, 30})
    for (int r : {1, 3, 12, 26}) {
      if (n + r > 56) continue;
      INFO("elevation of degree " << n << " by " << r);
      Input x = random_input(rng, n, true);
      const Bern<BD> e = elevate(Bern<BD>(x.b), r);
      const Bern<mpq_class> ee = elevate(Bern<mpq_class>(x.exact), r);
      const Bern<double> ep = elevate(Bern<double>(x.plain), r);
      check_contains(e.b, ee.b, ep.b);
      for (std::size_t k = 0; k < e.b.size(); ++k) {
        weakened_misses += abs(mpq_class(e.b[k].value()) - ee.b[k]) > mpq_class(e.b[k].bound() / 256) ? 1 : 0;
        ++checks;
      }
    }
  INFO(weakened_misses << " of " << checks << " checks miss with the bounds divided by 2^8");
  CHECK(weakened_misses > checks / 10);
}

}  // namespace ECCD_UNITY_ID
