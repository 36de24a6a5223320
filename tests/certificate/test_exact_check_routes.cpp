// The routes eccd-check takes for eccd-certificate/2 (certificate/check/):
// the quartic's discriminant by its closed form against Res(f, f') from the
// Sylvester-Habicht determinant; the pencil's coefficients on integers
// against the rational ones; a sign on a bracket by the mean value theorem;
// and, end to end, the writer's gap points making every piece between them
// count its roots exactly (Descartes' bound = its brackets), so that no
// bracket needs a Descartes count of its own, while a root claimed for the
// wrong factor is rejected by the missing sign change.
#include "certificate/check/pencil.hpp"
#include "certificate/check/qpoly.hpp"
#include "certificate/check/verdict.hpp"
#include "certificate/write/exact_certificate.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;
using json = nlohmann::json;

namespace {

const std::string src = ECCD_SOURCE_DIR;

// (x - r1)(x - r2)(x - r3)(x - r4) times k, lowest degree first.
std::vector<mpz_class> quartic_with_roots(long k, long r1, long r2, long r3, long r4) {
  std::vector<mpz_class> p{mpz_class(k)};
  for (long r : {r1, r2, r3, r4}) {
    std::vector<mpz_class> n(p.size() + 1);
    for (std::size_t i = 0; i < p.size(); ++i) {
      n[i + 1] += p[i];
      n[i] -= p[i] * r;
    }
    p = n;
  }
  return p;
}

}  // namespace

TEST_CASE("eccd-check: the quartic's closed-form discriminant is Res(f, f') / g_4, zero exactly at a double root",
          "[eccd-check][exact-routes]") {
  std::mt19937 rng(20261201);
  std::uniform_int_distribution<long> d(-40, 40);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<mpz_class> g;
    for (int k = 0; k < 5; ++k) g.push_back(mpz_class(d(rng)));
    if (g[4] == 0) g[4] = 1;
    const mpz_class res = check::subresultant_at(g, 0, 0), disc = check::quartic_discriminant_at(g);
    INFO("trial " << trial);
    CHECK(res == g[4] * disc);
  }
  // Roots 1, 1, -2, 3: a double root, disc 0. Roots 1, 2, 3, 4 (k = 1): disc = Π (ri - rj)² = 144.
  CHECK(check::quartic_discriminant_at(quartic_with_roots(3, 1, 1, -2, 3)) == 0);
  CHECK(check::quartic_discriminant_at(quartic_with_roots(1, 1, 2, 3, 4)) == 144);
}

TEST_CASE("eccd-check: the pencil's coefficients on integers are H! times the rational route's",
          "[eccd-check][exact-routes]") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<long> d(-9, 9);
  for (std::size_t H : {3u, 4u}) {
    for (int trial = 0; trial < 50; ++trial) {
      check::ZMatrix A(H, std::vector<mpz_class>(H)), B = A;
      check::QMatrix Aq(H, std::vector<mpq_class>(H)), Bq = Aq;
      for (std::size_t i = 0; i < H; ++i)
        for (std::size_t j = i; j < H; ++j) {
          A[i][j] = A[j][i] = d(rng);
          B[i][j] = B[j][i] = d(rng);
          Aq[i][j] = Aq[j][i] = mpq_class(A[i][j]);
          Bq[i][j] = Bq[j][i] = mpq_class(B[i][j]);
        }
      const std::vector<mpz_class> z = check::pencil_coefficients(A, B);
      const std::vector<mpq_class> r = check::pencil_coefficients(Aq, Bq);
      const long factorial = H == 3 ? 6 : 24;
      REQUIRE(z.size() == H + 1);
      for (std::size_t k = 0; k <= H; ++k) CHECK(mpq_class(z[k]) == factorial * r[k]);
    }
  }
}

TEST_CASE("eccd-check: N = adj(M) / the gcd of its entries, on integer polynomials", "[eccd-check][exact-routes]") {
  // The rotation by the half-angle tangent with a translation: det M = (1 + t²)³ and adj(M)'s entries have no
  // common factor (the translation's cofactors are not multiples of 1 + t²), so N = adj(M), N M = det M · I.
  auto poly = [](std::vector<long> c) {
    std::vector<mpq_class> q;
    for (long x : c) q.emplace_back(x);
    return check::QPoly(std::move(q));
  };
  const check::PolyMatrix M{{poly({1, 0, -1}), poly({0, -2}), poly({3, 1})},
                            {poly({0, 2}), poly({1, 0, -1}), poly({-1, 0, 2})},
                            {poly({}), poly({}), poly({1, 0, 1})}};
  const check::PolyMatrix N = check::primitive_inverse(M);
  const check::QPoly det = check::motion_determinant(M);
  CHECK(det == poly({1, 0, 3, 0, 3, 0, 1}));  // (1 + t²)³
  check::QPoly c;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      check::QPoly e;
      for (std::size_t k = 0; k < 3; ++k) e = e + N[i][k] * M[k][j];
      if (i != j) CHECK(e.zero());
      if (i == 0 && j == 0) c = e;
      if (i == j) CHECK(e == c);
    }
  CHECK(c == det);
  CHECK(check::matrix_degree(N) == 4);
  // The identity times 1 + t²: adj = (1 + t²)² I, the common factor (1 + t²)² divided out, N a constant matrix.
  const check::PolyMatrix S{{poly({1, 0, 1}), poly({}), poly({})},
                            {poly({}), poly({1, 0, 1}), poly({})},
                            {poly({}), poly({}), poly({1, 0, 1})}};
  CHECK(check::matrix_degree(check::primitive_inverse(S)) == 0);
}

TEST_CASE("eccd-check: a sign on a bracket by the mean value theorem, or no answer", "[eccd-check][exact-routes]") {
  const std::vector<mpz_class> p{mpz_class(-1), mpz_class(3)};               // 3t - 1, root 1/3
  CHECK(check::sign_on_bracket(p, mpq_class(1, 2), mpq_class(6, 10)) == 1);  // |p(1/2)| = 1/2 > (1/10) · 3
  CHECK(check::sign_on_bracket(p, mpq_class(1, 2), mpq_class(3, 4)) == 0);  // no root, but 1/2 < (1/4) · 3: cannot tell
  CHECK(check::sign_on_bracket(p, mpq_class(0), mpq_class(1, 4)) == -1);
  CHECK(check::sign_on_bracket(p, mpq_class(0), mpq_class(1, 2)) == 0);  // the root is inside
  CHECK(check::sign_on_bracket(p, mpq_class(3334, 10000), mpq_class(1, 2)) ==
        0);  // no root, but |p(lo)| is too small to tell
  const std::vector<mpz_class> q{mpz_class(1), mpz_class(0), mpz_class(-4)};  // 1 - 4t², roots ±1/2
  CHECK(check::sign_on_bracket(q, mpq_class(1, 2) + mpq_class(1, 1000), mpq_class(1)) == 0);
  CHECK(check::sign_on_bracket(q, mpq_class(-1, 20), mpq_class(1, 20)) == 1);  // q(lo) = 0.99 > (1/10) · 8
  CHECK(check::sign_at(q, mpq_class(1, 2)) == 0);
  CHECK(check::sign_at(q, mpq_class(-3, 4)) == -1);
}

TEST_CASE(
    "eccd-check: the writer's gap points let every piece count its roots, and a root given to the wrong factor is "
    "rejected",
    "[eccd-check][exact-routes][certificate]") {
  for (const std::string rel : {"paper003/example2.json", "paper002/example.json",
                                "generated/2d/2d-deg6-colliding-kinematic-793321409713674.json"}) {
    const std::string path = src + "/cases/" + rel, text = read_file_bytes(path);
    const Scene s = parse_scene(text, path);
    const json cert = make_certificate(s, parse_json_document(text, path));
    INFO(rel);
    check::Verdict v = check::check_certificate_text(text, path, cert.dump(), "certificate");
    REQUIRE(v.outcome == check::Outcome::valid);
    bool counted = false;
    for (const auto& line : v.checked)
      if (line.rfind("gaps: ", 0) == 0) counted = line.find(" 0 bracket by bracket") != std::string::npos;
    CHECK(counted);
    // The first interior root, claimed for another factor: that factor does not change sign across the bracket.
    const json& F = cert["projection"]["square_free_factors"];
    if (F.size() < 2) continue;
    for (std::size_t k = 2; k + 1 < cert["timeline"].size(); k += 2) {
      json forged = cert;
      const int f = cert["timeline"][k]["root_of_factor"].get<int>();
      forged["timeline"][k]["root_of_factor"] = (f + 1) % int(F.size());
      v = check::check_certificate_text(text, path, forged.dump(), "certificate");
      CHECK(v.outcome == check::Outcome::rejected);
      CHECK(v.claim.rfind("instant " + std::to_string(k / 2), 0) == 0);
      break;
    }
  }
}

}  // namespace ECCD_UNITY_ID
