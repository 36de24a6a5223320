// kernel/contact_point_integer.hpp: the exact 2D contact point over the
// integers must print the very strings contact_point<mpq_class> prints (the
// point's coordinates and the normal), at the instants the exact pipeline
// uses (the mid-points of 64-bit brackets of the roots of Δ) and at other
// rationals, on every 2D scene of cases/ with rational motions; plus the
// truncation rule it reads doubles by (that of mpq_get_d).
#include "exact/algebraic_roots.hpp"
#include "io/scene_reader.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/contact_point_integer.hpp"
#include "kernel/prepared_scene.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

TEST_CASE("truncated_double reads n / d as mpq_get_d does, without reducing the fraction",
          "[kernel][contact_point_integer]") {
  std::mt19937_64 rng(7);
  int checked = 0;
  for (int k = 0; k < 2000; ++k) {
    mpz_class n, d, f;
    mpz_class r1 = mpz_class(std::to_string(rng())), r2 = mpz_class(std::to_string(rng() | 1)),
              r3 = mpz_class(std::to_string(rng() % 1000 + 1));
    n = r1 << static_cast<unsigned long>(rng() % 300);
    d = r2 << static_cast<unsigned long>(rng() % 300);
    f = r3 << static_cast<unsigned long>(rng() % 5);
    if (k % 3 == 0) n = -n;
    n *= f;  // a common factor: the fraction is not in lowest terms
    d *= f;
    mpq_class q(n, d);
    q.canonicalize();
    double r;
    REQUIRE(contact_integer_detail::truncated_double(n, d, r));
    CHECK(r == q.get_d());
    ++checked;
  }
  double r;
  CHECK_FALSE(contact_integer_detail::truncated_double(mpz_class(1), mpz_class(1) << 1200,
                                                       r));  // below 2^-1000: reduced instead
  CHECK(contact_integer_detail::to_double_of(mpz_class(3), mpz_class(3) << 1200) ==
        mpq_class(mpz_class(1), mpz_class(1) << 1200).get_d());
  CHECK(checked == 2000);
}

TEST_CASE("contact_point_integer prints what contact_point<mpq_class> prints, on the 2D scenes of cases/",
          "[kernel][contact_point_integer]") {
  namespace fs = std::filesystem;
  int scenes = 0, points = 0;
  std::mt19937_64 rng(11);
  for (const auto& e : fs::recursive_directory_iterator(std::string(ECCD_SOURCE_DIR) + "/cases")) {
    if (!e.is_regular_file() || e.path().extension() != ".json") continue;
    MovingPair2<Rational> pair;
    try {
      Scene s = read_scene_file(e.path().string());
      if (s.dim != 2) continue;
      pair = to_arithmetic<Rational, H_2D>(prepare_pair<H_2D>(s), Rational(1));
    } catch (const std::exception&) {
      continue;  // not a 2D scene with rational motions
    }
    const PolyMatrix<Rational, 3> A = moving_quadric<Rational, H_2D>(pair.qa, pair.na);
    const PolyMatrix<Rational, 3> B = moving_quadric<Rational, H_2D>(pair.qb, pair.nb);
    const auto g = characteristic_coefficients<Rational, H_2D>(A, B);
    std::vector<Rational> ts;
    const auto delta = cubic_discriminant(g[3], g[2], g[1], g[0]);
    if (!delta.is_zero() && delta.degree() >= 1)
      for (const auto& r : real_roots(delta, Rational(0), Rational(1), 64)) ts.push_back((r.lo + r.hi) / 2);
    ts.push_back(Rational(0));
    ts.push_back(Rational(1));
    ts.push_back(Rational(long(rng() % 1000), 1000));
    ts.push_back(Rational(long(rng() % 997), 997));
    INFO(e.path().string());
    for (const auto& t : ts) {
      INFO("t = " << t);
      const ContactPoint ref = contact_point(A, B, g, t), got = contact_point_integer(A, B, g, t);
      CHECK(got.x == ref.x);
      CHECK(got.normal == ref.normal);
      if (!ref.x.empty()) ++points;
    }
    ++scenes;
  }
  CHECK(scenes >= 20);
  CHECK(points >= 50);
}

}  // namespace ECCD_UNITY_ID
