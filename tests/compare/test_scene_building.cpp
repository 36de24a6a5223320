// The scene generators' building blocks (compare/scene_building.hpp), checked
// with exact rational arithmetic over many seeds:
//  - random_unit gives vectors of length exactly 1 (2D from a half-angle
//    tangent, 3D from an integer quaternion);
//  - shape_with_normal gives squared semi-axes and a point on
//    x^T diag(1/alpha) x = 1 whose outward normal diag(1/alpha) x is a
//    positive multiple of n, the solved semi-axis within [1/4, 6];
//  - householder(w) is the reflection I - 2 w w^T / w^T w (symmetric, an
//    involution, w to -w, w's orthogonal complement fixed); orthogonal_to is
//    orthogonal to n and non-zero; rotation_taking(m, n) is orthogonal with
//    determinant +1 and takes m to -n, and refuses m = -n in 3D;
//  - from_bernstein agrees with the Bernstein sum evaluated directly;
//    vanishes_on_unit_interval counts roots on the closed [0, 1] (ends
//    included, double roots included); badly_scaled is max/min > 16 over
//    65 instants or a root;
//  - hconst / hmul compose affine maps like [R s; 0 1] matrices; hdegree;
//  - pow10, number_text ("p/q", or an exact decimal under g_decimal_output),
//    poly_json (power basis, the zero polynomial as ["0"]), bern_json;
//  - motion_json and shape_json are read back by the scene reader as the same
//    motion matrix and the quadric diag(1/alpha, -1) (up to a positive factor);
//  - the builders, judged by the exact static test (api/static_status.hpp,
//    status_at) on the scene written from what they return: build_touch's pair
//    touches at its t0 and is apart at t0 +- 1/64 (strict convexity: the
//    collision set is {t0}); with the near-miss family (d = 10^-3) it is apart
//    at t0 too; build_random's free pair is apart at every t = k/16.
#include "compare/scene_building.hpp"

#include "api/static_status.hpp"
#include "io/scene_reader.hpp"
#include "kernel/motion.hpp"

#include <catch2/catch.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd;
using namespace eccd::scene_building;

namespace {
Rational rq(long p, long q) {
  Rational x(p, q);
  x.canonicalize();
  return x;
}
Rational det3(const Mat& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
Mat transpose(const Mat& a) {
  Mat t(a[0].size(), Vec(a.size()));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a[0].size(); ++j) t[j][i] = a[i][j];
  return t;
}
mpz_class binomial(unsigned n, unsigned k) {
  mpz_class b;
  mpz_bin_uiui(b.get_mpz_t(), n, k);
  return b;
}
}  // namespace

TEST_CASE("scene building: random unit vectors have length exactly 1", "[compare][scene-building]") {
  for (int dim : {2, 3}) {
    Rng r{std::uint64_t(100 + dim)};
    for (int k = 0; k < 300; ++k) {
      const Vec v = random_unit(r, dim);
      REQUIRE(int(v.size()) == dim);
      CHECK(dot(v, v) == 1);
    }
  }
}

TEST_CASE("scene building: shape_with_normal puts a point with outward normal n on the ellipse",
          "[compare][scene-building]") {
  for (int dim : {2, 3}) {
    Rng r{std::uint64_t(7 * dim)};
    for (int k = 0; k < 150; ++k) {
      const Vec n = random_unit(r, dim);
      const Tangency t = shape_with_normal(r, n);
      REQUIRE(int(t.alpha.size()) == dim);
      REQUIRE(int(t.point.size()) == dim);
      Rational on = 0;
      for (int i = 0; i < dim; ++i) {
        CHECK(t.alpha[i] >= rq(1, 4));
        CHECK(t.alpha[i] <= 6);
        on += t.point[i] * t.point[i] / t.alpha[i];
      }
      CHECK(on == 1);
      // The gradient diag(1/alpha) x is lambda n with lambda > 0 (the outward normal is n).
      const Vec g = [&] {
        Vec x(dim);
        for (int i = 0; i < dim; ++i) x[i] = t.point[i] / t.alpha[i];
        return x;
      }();
      const Rational lambda = dot(g, n);  // n is a unit vector
      CHECK(lambda > 0);
      for (int i = 0; i < dim; ++i) CHECK(g[i] == lambda * n[i]);
    }
  }
}

TEST_CASE("scene building: Householder reflections and rotations taking m to -n", "[compare][scene-building]") {
  Rng r{31};
  const Mat I3 = identity(3);
  for (int k = 0; k < 100; ++k) {
    const Vec w{r.frac(-5, 5, 3), r.frac(-5, 5, 3), r.frac(1, 5, 2)};  // never zero (third entry > 0)
    const Mat H = householder(w);
    CHECK(H == transpose(H));
    CHECK(mat_mul(H, H) == I3);
    const Vec hw = mat_vec(H, w);
    for (int i = 0; i < 3; ++i) CHECK(hw[i] == -w[i]);
    const Vec n = random_unit(r, 3);
    const Vec u = orthogonal_to(r, n);
    CHECK(dot(u, n) == 0);
    CHECK(dot(u, u) != 0);
    // A vector orthogonal to w is fixed: u - (u.w / w.w) w.
    Vec p = u;
    const Rational c = dot(u, w) / dot(w, w);
    for (int i = 0; i < 3; ++i) p[i] -= c * w[i];
    CHECK(mat_vec(H, p) == p);
    CHECK(det3(H) == -1);
  }
  for (int dim : {2, 3}) {
    Rng s{std::uint64_t(50 + dim)};
    for (int k = 0; k < 100; ++k) {
      const Vec m = random_unit(s, dim), n = random_unit(s, dim);
      Mat R;
      try {
        R = rotation_taking(s, m, n);
      } catch (const std::domain_error&) {
        continue;  // m = -n in 3D: checked below
      }
      const Vec img = mat_vec(R, m);
      for (int i = 0; i < dim; ++i) CHECK(img[i] == -n[i]);
      CHECK(mat_mul(transpose(R), R) == identity(dim));
      if (dim == 3)
        CHECK(det3(R) == 1);
      else
        CHECK(R[0][0] * R[1][1] - R[0][1] * R[1][0] == 1);
    }
  }
  const Vec e{Rational(1), Rational(0), Rational(0)}, minus_e{Rational(-1), Rational(0), Rational(0)};
  Rng t{1};
  CHECK_THROWS_AS(rotation_taking(t, e, minus_e), std::domain_error);
  // m = n (the 3D degenerate case is m = -n only): a rotation taking e to -e.
  const Mat R = rotation_taking(t, e, e);
  CHECK(mat_vec(R, e) == minus_e);
}

TEST_CASE("scene building: polynomials from Bernstein coefficients, roots on [0, 1], scaling",
          "[compare][scene-building]") {
  Rng r{5};
  for (int deg = 0; deg <= 6; ++deg) {
    std::vector<Rational> ctrl;
    for (int i = 0; i <= deg; ++i) ctrl.push_back(r.frac(-9, 9, 4));
    const RPoly p = from_bernstein(ctrl);
    CHECK(p.degree() <= deg);
    for (long k = 0; k <= 8; ++k) {
      const Rational t = rq(k, 8);
      Rational direct = 0;  // sum_i b_i C(n, i) t^i (1 - t)^(n - i)
      for (int i = 0; i <= deg; ++i) {
        Rational term = ctrl[i] * Rational(binomial(deg, i));
        for (int a = 0; a < i; ++a) term *= t;
        for (int a = i; a < deg; ++a) term *= 1 - t;
        direct += term;
      }
      CHECK(p(t) == direct);
    }
  }
  const RPoly t_minus = RPoly({rq(-1, 2), Rational(1)});  // t - 1/2
  CHECK(vanishes_on_unit_interval(t_minus));
  CHECK(vanishes_on_unit_interval(t_minus * t_minus));                                             // a double root
  CHECK(vanishes_on_unit_interval(RPoly({Rational(0), Rational(1)})));                             // t: root at 0
  CHECK(vanishes_on_unit_interval(RPoly({Rational(-1), Rational(1)})));                            // t - 1: root at 1
  CHECK(vanishes_on_unit_interval(RPoly()));                                                       // zero polynomial
  CHECK_FALSE(vanishes_on_unit_interval(RPoly({Rational(-2), Rational(1)})));                      // t - 2
  CHECK_FALSE(vanishes_on_unit_interval(RPoly({Rational(1), Rational(0), Rational(1)})));          // t^2 + 1
  CHECK_FALSE(vanishes_on_unit_interval(RPoly({1 + rq(1, 1000000), Rational(-2), Rational(1)})));  // (t - 1)^2 + 10^-6
  CHECK_FALSE(badly_scaled(RPoly({Rational(1), Rational(15)})));                                   // 1 .. 16
  CHECK(badly_scaled(RPoly({Rational(1), Rational(16) + rq(1, 100)})));                            // 1 .. 17.01
  CHECK(badly_scaled(RPoly({Rational(-1), Rational(-16)})));  // -1 .. -17: by absolute value
  CHECK(badly_scaled(t_minus));
  // random_poly and random_axes: coefficients in their ranges.
  for (int k = 0; k < 50; ++k) {
    const RPoly q = random_poly(r, 3, -6, 6, 5);
    CHECK(q.degree() <= 3);
    for (const auto& c : q.c) CHECK((c >= rq(-6, 5) && c <= rq(6, 5)));
    for (const auto& a : random_axes(r, 3)) CHECK((a >= rq(1, 2) && a <= 4));
  }
}

TEST_CASE("scene building: homogeneous matrices compose like affine maps", "[compare][scene-building]") {
  Rng r{77};
  const Vec n = random_unit(r, 3), m = random_unit(r, 3);
  const Mat R1 = rotation_taking(r, m, n), R2 = householder(orthogonal_to(r, n));
  const Vec s1{rq(1, 2), rq(-3, 4), Rational(2)}, s2{Rational(0), rq(5, 3), rq(-1, 7)};
  const HMat a = hconst(R1, s1), b = hconst(R2, s2);
  CHECK(hdegree(a) == 0);
  const HMat ab = hmul(a, b);
  // [R1 s1; 0 1][R2 s2; 0 1] = [R1 R2, R1 s2 + s1; 0 1].
  const Mat R12 = mat_mul(R1, R2);
  Vec s12 = mat_vec(R1, s2);
  for (int i = 0; i < 3; ++i) s12[i] += s1[i];
  const HMat want = hconst(R12, s12);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(ab[i][j] == want[i][j]);
  // A time-dependent factor raises the degree: diag(t, t, t, 1) times a, degree 1; squared, degree 2.
  HMat tdiag(4, std::vector<RPoly>(4));
  for (int i = 0; i < 3; ++i) tdiag[i][i] = RPoly({Rational(0), Rational(1)});
  tdiag[3][3] = constant(Rational(1));
  CHECK(hdegree(hmul(tdiag, a)) == 1);
  CHECK(hdegree(hmul(tdiag, hmul(tdiag, a))) == 2);
}

TEST_CASE("scene building: numbers and polynomials as JSON text", "[compare][scene-building]") {
  CHECK(pow10(0) == 1);
  CHECK(pow10(3) == 1000);
  CHECK(pow10(-2) == rq(1, 100));
  CHECK(pow10(-30) * pow10(30) == 1);
  CHECK(number_text(rq(-3, 8)) == "-3/8");
  CHECK(number_text(Rational(5)) == "5");
  {
    g_decimal_output = true;
    CHECK(number_text(rq(-3, 8)) == "-0.375");
    CHECK(number_text(rq(1, 1000)) == "0.001");
    g_decimal_output = false;
  }
  CHECK(poly_json(RPoly()) == nlohmann::ordered_json::array({"0"}));
  CHECK(poly_json(RPoly({rq(1, 2), Rational(0), Rational(-3)})) == nlohmann::ordered_json::array({"1/2", "0", "-3"}));
  CHECK(bern_json(rq(1, 3), Rational(2)).dump() == R"({"bernstein":["1/3","2"]})");
  CHECK(shape_json({Rational(2), rq(9, 4)}).dump() == R"({"semi_axes_squared":["2","9/4"]})");
  CHECK(semi_axes_json({rq(3, 2), Rational(1)}).dump() == R"({"semi_axes":["3/2","1"]})");
}

TEST_CASE("scene building: written motions and shapes read back as the same motion and quadric",
          "[compare][scene-building]") {
  Rng r{2718};
  for (int trial = 0; trial < 6; ++trial) {
    const int dim = trial % 2 ? 3 : 2;
    Motion mo;
    if (dim == 2) {
      KinematicMotion k;
      for (auto& d : k.d) d = random_poly(r, 2, -5, 5, 3);
      k.d[3] += constant(Rational(4));  // keep d2^2 + d3^2 away from zero
      mo = k;
    } else if (trial == 1) {
      EulerMotion e;
      for (auto& x : e.e) x = random_poly(r, 1, -4, 4, 2);
      e.e[0] += constant(Rational(5));
      for (auto& x : e.v) x = random_poly(r, 2, -4, 4, 3);
      e.v3 = constant(Rational(2));
      mo = e;
    } else {
      MatrixMotion mm;
      const Vec n = random_unit(r, 3), m = random_unit(r, 3);
      const HMat h = hconst(rotation_taking(r, m, n), {r.frac(-3, 3, 2), r.frac(-3, 3, 2), r.frac(-3, 3, 2)});
      mm.m = h;
      mm.m[0][3] += RPoly({Rational(0), Rational(1)});  // x moves with t
      mo = mm;
    }
    const Vec alpha = random_axes(r, dim);
    nlohmann::ordered_json doc;
    doc["format"] = "ellipse-ccd-scene/1";
    doc["name"] = "building-" + std::to_string(trial);
    doc["dim"] = dim;
    doc["a"] = {{"shape", shape_json(alpha)}, {"motion", motion_json(mo)}};
    doc["b"] = {{"shape", shape_json(alpha)}, {"motion", {{"type", "static"}}}};
    INFO(doc.dump());
    const Scene s = parse_scene(doc.dump(), "building.json");
    REQUIRE(s.a.motion.index() == mo.index());
    if (dim == 2) {
      CHECK(to_hmat<3>(s.a.motion) == to_hmat<3>(mo));
      CHECK(motion_degree(2, mo) == hdegree(to_hmat<3>(mo)));
    } else {
      CHECK(to_hmat<4>(s.a.motion) == to_hmat<4>(mo));
    }
    // The quadric: diag(1/alpha, -1) up to a positive factor.
    const auto& Q = s.a.Q;
    const Rational f = -Q[dim][dim];
    REQUIRE(f > 0);
    for (int i = 0; i <= dim; ++i)
      for (int j = 0; j <= dim; ++j)
        if (i != j) CHECK(Q[i][j] == 0);
    for (int i = 0; i < dim; ++i) CHECK(Q[i][i] * alpha[i] == f);
  }
}

namespace {
Scene scene_of(const Built& b, int dim) {
  nlohmann::ordered_json doc;
  doc["format"] = "ellipse-ccd-scene/1";
  doc["name"] = "built";
  doc["dim"] = dim;
  doc["a"] = {{"shape", shape_json(b.alpha_a)}, {"motion", motion_json(b.ma)}};
  doc["b"] = {{"shape", shape_json(b.alpha_b)}, {"motion", motion_json(b.mb)}};
  return parse_scene(doc.dump(), "built.json");
}
}  // namespace

TEST_CASE("scene building: touch, near-miss and free builders, judged by the exact static test",
          "[compare][scene-building]") {
  int touches = 0, misses = 0, frees = 0;
  for (int dim : {2, 3})
    for (int degree : {2, 3}) {
      GeneratorSpec sp;
      sp.dim = dim;
      sp.degree = degree;
      sp.motion = dim == 2 ? "kinematic" : "euler";
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        INFO(dim << "D degree " << degree << " seed " << seed);
        for (const char* family : {"touch", "near-miss", "free"}) {
          sp.family = family;
          sp.d_exponent = 3;
          Rng r{seed * 1000 + std::uint64_t(dim * 10 + degree)};
          Built b;
          bool built = false;
          for (int attempt = 0; attempt < 20 && !built; ++attempt) {
            try {
              b = sp.family == "free" ? build_random(r, sp) : build_touch(r, sp);
              built = true;
            } catch (const std::domain_error&) {}
          }
          REQUIRE(built);
          const Scene s = scene_of(b, dim);
          if (sp.family == "free") {
            CHECK_FALSE(b.t0.has_value());
            for (long k = 0; k <= 16; ++k) CHECK(status_at(s, rq(k, 16)) == Status::separate);
            ++frees;
            continue;
          }
          REQUIRE(b.t0.has_value());
          const Rational t0 = *b.t0;
          REQUIRE((t0 > 0 && t0 < 1));
          CHECK(status_at(s, t0) == (sp.family == "touch" ? Status::touching : Status::separate));
          for (const Rational& t : {Rational(t0 - rq(1, 64)), Rational(t0 + rq(1, 64))})
            if (t >= 0 && t <= 1) CHECK(status_at(s, t) == Status::separate);
          (sp.family == "touch" ? touches : misses)++;
        }
      }
    }
  CHECK(touches == 12);
  CHECK(misses == 12);
  CHECK(frees == 12);
}

}  // namespace ECCD_UNITY_ID
