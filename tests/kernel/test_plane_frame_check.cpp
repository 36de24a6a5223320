// kernel/plane_frame_check.hpp: does a fixed plane miss a moving object for
// all t (000 section 4, frame coherence)? Checked against:
//   - adjugate_of: adj(Q) Q = det(Q) I in mpq over seeded random 3x3 and 4x4;
//   - plane_against_object on a circle / sphere of radius r translated by c(t):
//     by hand adj(diag(1, .., 1, -r²)) = diag(-r², .., -r², 1) and q(t) =
//     M(t)ᵀp = (n, n·c(t) + p_h), so h(t) = (n·c(t) + p_h)² - r² |n|² (> 0 iff
//     the centre is farther than r from the plane), the centre's side
//     n·c(t) + p_h, and w = 1;
//   - positive_on_unit_interval, exact: Bernstein-positive h, h positive with
//     a negative Bernstein coefficient (the Sturm path), a double root inside,
//     h(0) <= 0, h = 0; with Bounded<double>: a clear margin is positive, a
//     dip below 0 is not_positive, an exact double root (a touching plane) is
//     unknown with the piece named; Bounded<Mpfr> likewise.
// keyframe_plane_check is compared with the exact check in
// tests/api/test_kept_plane_check.cpp.
#include "kernel/plane_frame_check.hpp"
#include "number/mpfr_real.hpp"
#include "number/rational_traits.hpp"
#include "number/running_error.hpp"
#include "tests/support/exact_values.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using RP = Poly<Rational>;

using test::q;  // a / b in lowest terms (tests/support/exact_values.hpp)

template <int H>
void check_adjugate(std::mt19937_64& rng) {
  Matrix<Rational, H> m;
  for (auto& row : m)
    for (auto& x : row) x = q(long(rng() % 21) - 10, long(rng() % 3) + 1);
  const Matrix<Rational, H> adj = adjugate_of<Rational, H>(m, Rational(0));
  std::vector<std::vector<Rational>> mv(H, std::vector<Rational>(H));
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) mv[i][j] = m[i][j];
  const Rational det = ring_det(mv, Rational(0));
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      Rational s = 0, s2 = 0;
      for (int k = 0; k < H; ++k) {
        s += adj[i][k] * m[k][j];
        s2 += m[i][k] * adj[k][j];
      }
      CHECK(s == (i == j ? det : Rational(0)));
      CHECK(s2 == (i == j ? det : Rational(0)));
    }
}

}  // namespace

TEST_CASE("adjugate_of: adj(Q) Q = Q adj(Q) = det(Q) I", "[kernel][plane_frame_check]") {
  std::mt19937_64 rng(4338);
  for (int k = 0; k < 30; ++k) {
    check_adjugate<3>(rng);
    check_adjugate<4>(rng);
  }
}

TEST_CASE("plane_against_object for a translated circle and sphere: h and the side by hand",
          "[kernel][plane_frame_check]") {
  std::mt19937_64 rng(4339);
  for (int trial = 0; trial < 20; ++trial) {
    const Rational r = q(long(rng() % 5) + 1, 2), ph = q(long(rng() % 11) - 5, 1);
    {  // 2D: M(t) = [[1, 0, cx(t)], [0, 1, cy(t)], [0, 0, 1]], Q = diag(1, 1, -r²)
      const RP cx({q(long(rng() % 11) - 5, 1), q(long(rng() % 11) - 5, 1)}), cy({Rational(1), Rational(-2)});
      Matrix<Rational, 3> Q{};
      Q[0][0] = Q[1][1] = 1;
      Q[2][2] = -r * r;
      PolyMatrix<Rational, 3> m = identity_poly_matrix<Rational, 3>();
      m[0][2] = cx;
      m[1][2] = cy;
      const std::array<Rational, 3> p = {q(3, 1), q(-4, 1), ph};  // n = (3, -4), |n|² = 25
      const auto out = plane_against_object<Rational, 3>(Q, m, p, Rational(0));
      // adj(Q) = diag(-r², -r², 1): h = -r² |n|² + (n·c + p_h)²; the centre adj(Q) e_2 = (0, 0, 1).
      const RP side = RP::constant(Rational(3)) * cx - RP::constant(Rational(4)) * cy + RP::constant(ph);
      CHECK(out.miss == side * side - RP::constant(25 * r * r));
      CHECK(out.side == side);
      CHECK(out.w == RP::constant(Rational(1)));
    }
    {  // 3D: a sphere, Q = diag(1, 1, 1, -r²): adj(Q) = diag(-r², -r², -r², 1)
      Matrix<Rational, 4> Q{};
      Q[0][0] = Q[1][1] = Q[2][2] = 1;
      Q[3][3] = -r * r;
      PolyMatrix<Rational, 4> m = identity_poly_matrix<Rational, 4>();
      const RP cz({q(long(rng() % 11) - 5, 1), Rational(3), Rational(-1)});
      m[2][3] = cz;
      const std::array<Rational, 4> p = {Rational(0), Rational(2), Rational(1), ph};  // |n|² = 5
      const auto out = plane_against_object<Rational, 4>(Q, m, p, Rational(0));
      const RP side = cz + RP::constant(ph);  // n·c = 2·0 + 1·cz
      CHECK(out.miss == side * side - RP::constant(5 * r * r));
      CHECK(out.side == side);
    }
  }
}

TEST_CASE("positive_on_unit_interval: exact proofs and refutations", "[kernel][plane_frame_check]") {
  std::string where;
  const RP t({Rational(0), Rational(1)}), half = t - RP::constant(q(1, 2));
  CHECK(positive_on_unit_interval(RP::constant(Rational(2)) + t, where) == OnInterval::positive);  // Bernstein > 0
  // (t - 1/2)² + 1/100: a negative Bernstein coefficient (0.26 - 0.5), but no root: the Sturm path proves it
  const RP dip = half * half + RP::constant(q(1, 100));
  CHECK(sgn(to_bernstein(dip).b[1]) < 0);
  CHECK(positive_on_unit_interval(dip, where) == OnInterval::positive);
  CHECK(positive_on_unit_interval(half * half, where) == OnInterval::not_positive);  // touches 0 at 1/2
  CHECK(positive_on_unit_interval(half * half - RP::constant(q(1, 100)), where) == OnInterval::not_positive);
  CHECK(positive_on_unit_interval(t, where) == OnInterval::not_positive);                              // h(0) = 0
  CHECK(positive_on_unit_interval(RP::constant(Rational(1)) - t, where) == OnInterval::not_positive);  // h(1) = 0
  CHECK(positive_on_unit_interval(RP(), where) == OnInterval::not_positive);
  // a root just outside [0, 1]: still positive inside
  CHECK(positive_on_unit_interval(t + RP::constant(q(1, 1000)), where) == OnInterval::positive);
}

TEMPLATE_TEST_CASE("positive_on_unit_interval with an error bound: decides where the bound allows, names the rest",
                   "[kernel][plane_frame_check]", Bounded<double>, Bounded<Mpfr>) {
  using T = TestType;
  auto c = [](const Rational& x) {
    if constexpr (std::is_same_v<T, Bounded<Mpfr>>)
      return T(Mpfr(x, 120), 0);
    else
      return T(x.get_d(), 0);
  };
  // h = (t - 1/2)² + e = t² - t + 1/4 + e (exact coefficients in binary for e = ±1/1024 and 0)
  auto h = [&](const Rational& e) { return Poly<T>(std::vector<T>{c(q(1, 4) + e), c(Rational(-1)), c(Rational(1))}); };
  std::string where;
  CHECK(positive_on_unit_interval(h(q(1, 1024)), where) == OnInterval::positive);
  CHECK(positive_on_unit_interval(h(q(-1, 1024)), where) == OnInterval::not_positive);
  where.clear();
  CHECK(positive_on_unit_interval(h(Rational(0)), where, 8) == OnInterval::unknown);  // a touch: never a claim
  CHECK(where.find("after 8 subdivisions") != std::string::npos);
  CHECK(where.find("0.5") != std::string::npos);  // the piece at the double root
}

}  // namespace ECCD_UNITY_ID
