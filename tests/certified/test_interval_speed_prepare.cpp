// Issue 18 (2D certified cost): the shortcuts taken in the exact preparation
// that every certified run starts from change nothing.
//  - coprime_mod_p (kernel/modular_coprime.hpp) never claims coprime for
//    polynomials with a common factor (random factors, huge rational
//    coefficients, primes hidden in denominators), and whenever it claims
//    coprime the exact Euclid gcd over Q is a constant;
//  - prepare_pair (kernel/prepared_scene.hpp: the content filter and
//    det A(t) = det Q · det N(t)^2 in the pencil balancing) gives exactly the
//    pair that the plain construction gives (Euclid gcd on every entry, A(t)
//    formed and its determinant taken) on every rational scene of cases/;
//  - products of Poly<Rational> (number/rational_convolution.hpp) are the
//    coefficient-wise products, in the same canonical form.
#include "io/scene_reader.hpp"
#include "kernel/cycloidal_motion.hpp"
#include "kernel/modular_coprime.hpp"
#include "kernel/prepared_scene.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

const std::string kCases = std::string(ECCD_SOURCE_DIR) + "/cases/";

RPoly random_poly(std::mt19937_64& rng, int degree, int bits) {
  std::uniform_int_distribution<int> coin(0, 3);
  std::vector<Rational> c(degree + 1);
  for (auto& x : c) {
    mpz_class n = 0, d = 1;
    for (int k = 0; k < bits; k += 30) n = (n << 30) + mpz_class(std::to_string(rng() & ((1u << 30) - 1)));
    if (coin(rng) == 0) n = -n;
    if (coin(rng) == 1)
      for (int k = 0; k < bits; k += 30) d = (d << 30) + mpz_class(std::to_string(1 + (rng() & 0xffff)));
    x = Rational(n, d);
    x.canonicalize();
  }
  if (c.back() == 0) c.back() = 1;
  return RPoly(c);
}

// The plain preparation (before the shortcuts): Euclid on every entry, A(t) formed.
template <int H>
void plain_content(PolyMatrix<Rational, H>& n) {
  RPoly g;
  for (auto& row : n)
    for (auto& e : row)
      if (!e.is_zero()) g = g.is_zero() ? gcd(e, e) : gcd(g, e);
  if (g.degree() > 0)
    for (auto& row : n)
      for (auto& e : row) {
        RPoly q, r;
        divide(e, g, q, r);
        e = q;
      }
  std::vector<Rational*> all;
  for (auto& row : n)
    for (auto& e : row)
      for (auto& c : e.c) all.push_back(&c);
  make_primitive(all);
}
template <int H>
PreparedPair<H> plain_prepare(const Scene& s) {
  auto id = [](const Rational& q) { return q; };
  PreparedPair<H> p;
  p.qa = shape_matrix<H>(s.a);
  p.qb = shape_matrix<H>(s.b);
  p.na = motion_inverse<Rational, H>(s.a.motion, id);
  p.nb = motion_inverse<Rational, H>(s.b.motion, id);
  plain_content<H>(p.na);
  plain_content<H>(p.nb);
  long sum = 0;
  int used = 0;
  for (const Rational& t : {Rational(0), Rational(1, 2), Rational(1)}) {
    Rational da = field_det<Rational, H>(quadric_at<Rational, H>(p.qa, p.na, t));
    Rational db = field_det<Rational, H>(quadric_at<Rational, H>(p.qb, p.nb, t));
    if (da == 0 || db == 0) continue;
    sum += log2_size(db) - log2_size(da);
    ++used;
  }
  long k = used ? std::lround(double(sum) / (used * H)) : 0;
  if (k != 0) {
    mpz_class two = 1;
    two <<= std::abs(k);
    Rational f = k > 0 ? Rational(1) / Rational(two) : Rational(two);
    for (auto& row : p.qb)
      for (auto& x : row) x *= f;
  }
  return p;
}

template <int H>
bool same_pair(const PreparedPair<H>& x, const PreparedPair<H>& y) {
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j)
      if (x.qa[i][j] != y.qa[i][j] || x.qb[i][j] != y.qb[i][j] || x.na[i][j].c != y.na[i][j].c ||
          x.nb[i][j].c != y.nb[i][j].c)
        return false;
  return true;
}

}  // namespace

TEST_CASE("coprime_mod_p never claims coprime for a common factor", "[certified][interval-speed]") {
  std::mt19937_64 rng(18);
  for (int trial = 0; trial < 300; ++trial) {
    const int bits = trial % 3 == 0 ? 200 : 40;
    RPoly c = random_poly(rng, 1 + trial % 3, bits);
    RPoly a = random_poly(rng, trial % 4, bits) * c, b = random_poly(rng, trial % 5, bits) * c;
    CHECK_FALSE(coprime_mod_p(a, b));
  }
  // The prime itself in a denominator or in the leading numerator: not proved, never a wrong claim.
  const mpz_class p = mpz_class(1) << 61;
  const Rational pr(p - 1);
  RPoly x({Rational(1), Rational(1) / pr});  // 1 + t/p
  RPoly y({Rational(2), pr});                // 2 + p t
  CHECK_FALSE(coprime_mod_p(x, y));
  CHECK_FALSE(coprime_mod_p(y, RPoly({Rational(1), Rational(1)})));
  // Constants: a non-zero constant is coprime to anything non-zero; zero is coprime to nothing.
  CHECK(coprime_mod_p(RPoly::constant(Rational(3, 7)), RPoly({Rational(1), Rational(1)})));
  CHECK_FALSE(coprime_mod_p(RPoly(), RPoly::constant(Rational(1))));
}

TEST_CASE("coprime_mod_p agrees with the exact gcd on random pairs", "[certified][interval-speed]") {
  std::mt19937_64 rng(21);
  int claimed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int bits = trial % 2 ? 90 : 20;
    RPoly a = random_poly(rng, 1 + trial % 6, bits), b = random_poly(rng, 1 + trial % 5, bits);
    const bool proved = coprime_mod_p(a, b);
    const RPoly g = gcd(a, b);
    if (proved) {
      ++claimed;
      CHECK(g.degree() == 0);
    }
    if (g.degree() == 0) CHECK(proved);  // an unlucky prime (p | a resultant of ~100-bit numbers) does not occur here
  }
  CHECK(claimed > 250);
}

TEST_CASE("prepare_pair with the shortcuts equals the plain preparation on cases/", "[certified][interval-speed]") {
  int checked2 = 0, checked3 = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kCases)) {
    if (e.path().extension() != ".json") continue;
    Scene s;
    try {
      s = read_scene_file(e.path().string());
    } catch (const std::exception&) {
      continue;  // not a scene (answers, animations, certificates)
    }
    if (s.independent || has_cycloidal_motion(s)) continue;
    INFO(e.path().string());
    if (s.dim == 2) {
      CHECK(same_pair<3>(prepare_pair<3>(s), plain_prepare<3>(s)));
      ++checked2;
    } else {
      CHECK(same_pair<4>(prepare_pair<4>(s), plain_prepare<4>(s)));
      ++checked3;
    }
  }
  CHECK(checked2 >= 20);
  CHECK(checked3 >= 20);
}

TEST_CASE("rational polynomial products over common denominators are the coefficient-wise products",
          "[certified][interval-speed]") {
  std::mt19937_64 rng(2026);
  for (int trial = 0; trial < 400; ++trial) {
    const int bits = trial % 4 == 0 ? 300 : 30;
    RPoly a = random_poly(rng, trial % 9, bits), b = random_poly(rng, (trial / 3) % 7, bits);
    if (trial % 5 == 0 && a.degree() > 0) a.c.front() = 0;  // zero coefficients inside
    std::vector<Rational> naive(a.c.size() + b.c.size() - 1, Rational(0));
    for (std::size_t i = 0; i < a.c.size(); ++i)
      for (std::size_t j = 0; j < b.c.size(); ++j) naive[i + j] += a.c[i] * b.c[j];
    const RPoly p = a * b;
    REQUIRE(p.c.size() == naive.size());
    for (std::size_t k = 0; k < naive.size(); ++k) {
      CHECK(p.c[k] == naive[k]);
      CHECK(mpz_cmp(p.c[k].get_den_mpz_t(), naive[k].get_den_mpz_t()) == 0);  // canonical: the same representation
    }
  }
  // Many unrelated denominators (the common one would be long): the coefficient-wise route, same values.
  std::vector<Rational> c;
  for (int k = 0; k < 40; ++k) c.push_back(Rational(1, 1000003 + 2 * k));
  const RPoly x{std::vector<Rational>(c)};
  CHECK(rational_convolution(c, c).empty());
  CHECK((x * x).c[0] == c[0] * c[0]);
}

}  // namespace ECCD_UNITY_ID
