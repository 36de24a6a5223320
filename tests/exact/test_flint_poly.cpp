// exact/flint_poly.hpp (FLINT's square-free factorisation and gcd, issue 21)
// against CGAL's (the path before it, square_free_factors_cgal /
// polynomial_gcd_cgal): on the projection polynomial (Δ in 2D, the quartic's
// discriminant or psc_k in 3D) of every scene of cases/ that has one, the
// factorisations must be the same list of primitive integer polynomials with
// the same multiplicities, and the gcds with the derivative and with the
// evidence polynomials the same polynomial. Also a product with known factors.
#include "exact/algebraic_roots.hpp"
#include "exact/certificate_algebra.hpp"
#include "exact/flint_poly.hpp"
#include "io/scene_reader.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/quartic_touch_rule.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <thread>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;
using Q = mpq_class;
using RP = Poly<Rational>;

namespace {

RP poly(std::initializer_list<Q> c) { return RP(std::vector<Rational>(c)); }

RP derivative_of(const RP& p) {
  RP d;
  for (std::size_t i = 1; i < p.c.size(); ++i) d.c.push_back(p.c[i] * Rational(long(i)));
  d.trim();
  return d;
}

// The exact algebra of every scene of cases/ with rational motions (animations, cycloidal motions and other files
// that are not such scenes are skipped), handed to f with the file's path.
template <class F>
void for_each_case_algebra(F&& f) {
  namespace fs = std::filesystem;
  for (const auto& e : fs::recursive_directory_iterator(std::string(ECCD_SOURCE_DIR) + "/cases")) {
    if (!e.is_regular_file() || e.path().extension() != ".json") continue;
    CertificateAlgebra alg;
    try {
      alg = certificate_algebra(read_scene_file(e.path().string()));
    } catch (const std::exception&) {
      continue;
    }
    f(e.path().string(), alg);
  }
}

}  // namespace

TEST_CASE("flint_square_free_factors and flint_gcd on a product with known factors", "[exact][flint_poly]") {
  // 6 (2t^2 - 1) (3t - 1)^2 (t^2 + t + 1)^3 t^5: content 6 dropped, factors primitive with positive leading coefficient
  RP a = poly({-1, 0, 2}), b = poly({-1, 3}), c = poly({1, 1, 1}), t = poly({0, 1});
  RP p = Q(6) * a * b * b * c * c * c * t * t * t * t * t;
  auto z = primitive_integer_multiple(p);
  for (auto& x : z) x *= -4;  // a negative multiple: the same factors
  auto F = flint_square_free_factors(z);
  REQUIRE(F.size() == 4);
  CHECK(F[0].second == 1);
  CHECK(F[1].second == 2);
  CHECK(F[2].second == 3);
  CHECK(F[3].second == 5);
  CHECK(F[0].first == std::vector<mpz_class>{-1, 0, 2});
  CHECK(F[1].first == std::vector<mpz_class>{-1, 3});
  CHECK(F[2].first == std::vector<mpz_class>{1, 1, 1});
  CHECK(F[3].first == std::vector<mpz_class>{0, 1});
  CHECK(flint_gcd(primitive_integer_multiple(p), primitive_integer_multiple(a * poly({5, 1}) * b)) ==
        std::vector<mpz_class>{1, -3, -2, 6});                     // (2t^2 - 1)(3t - 1) = 6t^3 - 2t^2 - 3t + 1
  CHECK(flint_gcd({1, 1}, {-1, 1}) == std::vector<mpz_class>{1});  // coprime
  CHECK(square_free_factors(p) == square_free_factors_cgal(p));
}

TEST_CASE("FLINT's square-free factorisation and gcds equal CGAL's on every projection polynomial of cases/",
          "[exact][flint_poly]") {
  int compared = 0, not_square_free = 0;
  for_each_case_algebra([&](const std::string& path, const CertificateAlgebra& alg) {
    if (alg.projection.is_zero() || alg.projection.degree() < 1) return;
    INFO(path << ": " << alg.projection_name << " of degree " << alg.projection.degree());
    const auto F = square_free_factors(alg.projection);
    CHECK(F == square_free_factors_cgal(alg.projection));
    if (F.size() > 1 || (F.size() == 1 && F[0].second > 1)) ++not_square_free;
    const RP d = derivative_of(alg.projection);
    CHECK(polynomial_gcd(alg.projection, d) == polynomial_gcd_cgal(alg.projection, d));
    for (const char* name : {"P", "D", "s(1,1)", "s(1,0)"}) {
      if ((alg.dim == 2) != (name[0] == 'P' || name[0] == 'D')) continue;
      const RP q = alg.evidence(name);
      if (q.is_zero()) continue;
      CHECK(polynomial_gcd(alg.projection, q) == polynomial_gcd_cgal(alg.projection, q));
    }
    ++compared;
  });
  // cases/ has 2D and 3D scenes, paper 002's projection F1 · F2^12 among them
  CHECK(compared >= 100);
  CHECK(not_square_free >= 1);
}

TEST_CASE(
    "FlintQPoly gives the very Poly<Rational> of each formula: random rationals and the g of every scene of cases/",
    "[exact][flint_poly]") {
  auto via_flint = [](const std::vector<RP>& g, auto formula) {
    std::vector<FlintQPoly> G;
    for (const auto& p : g) G.emplace_back(p);
    return formula(G).to_poly();
  };
  auto both = [&](const std::vector<RP>& g) {
    int n = 0;
    if (g.size() == 4) {
      auto disc = [](const auto& G) { return cubic_discriminant(G[3], G[2], G[1], G[0]); };
      auto P = [](const auto& G) { return double_root_numerator(G[3], G[2], G[1], G[0]); };
      auto D = [](const auto& G) { return double_root_denominator(G[3], G[2], G[1]); };
      CHECK(via_flint(g, disc) == disc(g));
      CHECK(via_flint(g, P) == P(g));
      CHECK(via_flint(g, D) == D(g));
      n += 3;
    } else {
      auto disc = [](const auto& G) { return quartic_discriminant(G[4], G[3], G[2], G[1], G[0]); };
      CHECK(via_flint(g, disc) == disc(g));
      ++n;
      for (auto [j, i] : {std::pair{1, 1}, std::pair{1, 0}, std::pair{2, 2}, std::pair{2, -1}, std::pair{3, 3}}) {
        auto s = [j = j, i = i](const auto& G) { return subresultant_evidence(G, j, i); };
        const RP fl = via_flint(g, s), ref = s(g);
        INFO("s(" << j << "," << i << "): degrees " << fl.degree() << " and " << ref.degree() << ", leading "
                  << (fl.c.empty() ? Q(0) : fl.c.back()) << " and " << (ref.c.empty() ? Q(0) : ref.c.back()));
        CHECK(fl == ref);
        ++n;
      }
    }
    return n;
  };
  // random rational coefficients (denominators: the fmpq_poly path with a common denominator), some zero polynomials
  std::uint64_t state = 99;
  auto next = [&state](std::uint64_t m) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (state >> 33) % m;
  };
  int formulas = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t k = trial % 2 ? 4 : 5;
    std::vector<RP> g(k);
    for (auto& p : g) {
      if (next(7) == 0) continue;  // the zero polynomial
      const int deg = int(next(9));
      for (int i = 0; i <= deg; ++i) {
        p.c.push_back(Q(long(next(2001)) - 1000, long(1 + next(50))));
        p.c.back().canonicalize();  // mpq_class(n, d) is not reduced by itself
      }
      p.trim();
    }
    formulas += both(g);
  }
  int scenes = 0;
  for_each_case_algebra([&](const std::string& path, const CertificateAlgebra& alg) {
    if (++scenes % 5) return;  // every fifth scene (the 3D s(j,i) in Poly<Rational> are slow)
    INFO(path);
    formulas += both(alg.g);
  });
  CHECK(formulas >= 100);
}

TEST_CASE("FLINT's square-free factorisation and gcds give the same results from several threads at once",
          "[exact][flint_poly]") {
  // eccd animate decides pair-frames on a thread pool; FLINT (Debian's is built with thread-local storage) must
  // answer each thread as it answers one: paper 002's projection F1 · F2^12 and 2D Δ's, four threads, eight rounds.
  std::vector<RP> polys;
  for (const char* f :
       {"/cases/paper002/example.json", "/cases/paper003/example2.json", "/cases/paper003/example1.json"}) {
    try {
      polys.push_back(certificate_algebra(read_scene_file(std::string(ECCD_SOURCE_DIR) + f)).projection);
    } catch (const std::exception&) {}
  }
  REQUIRE(polys.size() >= 2);
  std::vector<std::vector<std::pair<RP, int>>> ref;
  std::vector<RP> gref;
  for (const auto& p : polys) {
    ref.push_back(square_free_factors(p));
    gref.push_back(polynomial_gcd(p, derivative_of(p)));
  }
  std::vector<int> bad(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 8; ++round)
        for (std::size_t k = 0; k < polys.size(); ++k) {
          if (square_free_factors(polys[k]) != ref[k]) ++bad[t];
          if (polynomial_gcd(polys[k], derivative_of(polys[k])) != gref[k]) ++bad[t];
        }
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) CHECK(bad[t] == 0);
}

}  // namespace ECCD_UNITY_ID
