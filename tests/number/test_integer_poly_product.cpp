// number/integer_poly_product.hpp and number/rational_poly_eval.hpp: the Kronecker product of integer and
// rational polynomials equals the schoolbook product exactly (same mpq values,
// lowest terms), on random inputs with signed coefficients of very different
// sizes, zero coefficients, powers-of-two and general denominators, squares,
// and the carries of the signed digit recovery (digits of ±(2^(b-1) - 1));
// integer Horner at a rational point equals Horner in mpq.
#include "kernel/polynomial.hpp"
#include "number/integer_poly_product.hpp"
#include "number/rational_poly_eval.hpp"
#include "number/rational_traits.hpp"

#include <catch2/catch.hpp>

#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

std::vector<mpq_class> schoolbook(const std::vector<mpq_class>& a, const std::vector<mpq_class>& b) {
  std::vector<mpq_class> r(a.size() + b.size() - 1, mpq_class(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

mpz_class random_int(std::mt19937_64& rng, int max_bits) {
  std::uniform_int_distribution<int> nb(0, max_bits);
  int bits = nb(rng);
  mpz_class x = 0;
  for (int i = 0; i < bits; i += 32) {
    x <<= 32;
    x += static_cast<unsigned long>(rng() & 0xffffffffu);
  }
  if (bits > 0) {
    mpz_class m = 1;
    m <<= bits;
    x %= m;
  }
  if (rng() & 1) x = -x;
  if (rng() % 7 == 0) x = 0;
  return x;
}

std::vector<mpq_class> random_poly(std::mt19937_64& rng, std::size_t n, int bits, int den_kind) {
  std::vector<mpq_class> p(n);
  for (auto& c : p) {
    mpz_class num = random_int(rng, bits), den = 1;
    if (den_kind == 1) den <<= int(rng() % 40);                    // dyadic, as the prepared scenes' B
    if (den_kind == 2) den = mpz_class(1 + long(rng() % 100000));  // general
    c = mpq_class(num, den);
    c.canonicalize();
  }
  if (mpz_sgn(p.back().get_num_mpz_t()) == 0) p.back() = 1;
  return p;
}

}  // namespace

TEST_CASE("Kronecker product of rational polynomials equals the schoolbook product", "[integer_poly_product][exact]") {
  std::mt19937_64 rng(20261126);
  for (int trial = 0; trial < 300; ++trial) {
    std::size_t na = 1 + rng() % 60, nb = 1 + rng() % 60;
    int bits_a = 1 + int(rng() % 700), bits_b = 1 + int(rng() % 300);
    int den_kind = int(rng() % 3);
    auto a = random_poly(rng, na, bits_a, den_kind);
    auto b = random_poly(rng, nb, bits_b, int(rng() % 3));
    INFO("trial " << trial << ": sizes " << na << " x " << nb);
    REQUIRE(rational_poly_product(a, b) == schoolbook(a, b));
    REQUIRE(rational_poly_product(a, a) == schoolbook(a, a));  // the squaring path
    // Poly<Rational>'s operator* goes through it and trims
    Poly<Rational> pa(a), pb(b);
    REQUIRE((pa * pb) == Poly<Rational>(schoolbook(a, b)));
  }
}

TEST_CASE("Kronecker product: digits at the edge of the signed range", "[integer_poly_product][exact]") {
  // all coefficients ±(2^k - 1): every product digit is near the bound, and
  // alternating signs exercise the borrow from one digit to the next
  for (int k : {1, 31, 63, 64, 65, 127, 128, 200}) {
    for (int pattern = 0; pattern < 4; ++pattern) {
      std::vector<mpz_class> x(9), y(7);
      mpz_class m = 1;
      m <<= k;
      m -= 1;
      for (std::size_t i = 0; i < x.size(); ++i) x[i] = ((pattern & 1) && i % 2) ? mpz_class(-m) : m;
      for (std::size_t j = 0; j < y.size(); ++j) y[j] = ((pattern & 2) && j % 3 == 1) ? mpz_class(-m) : m;
      std::vector<mpz_class> z, want(x.size() + y.size() - 1, mpz_class(0));
      for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = 0; j < y.size(); ++j) want[i + j] += x[i] * y[j];
      integer_poly_product(x.data(), x.size(), y.data(), y.size(), z);
      INFO("k = " << k << ", pattern " << pattern);
      REQUIRE(z == want);
    }
  }
}

TEST_CASE("Integer Horner at a rational point equals Horner in rationals", "[integer_poly_product][exact]") {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    auto p = random_poly(rng, 1 + rng() % 50, 1 + int(rng() % 400), int(rng() % 3));
    mpq_class t(random_int(rng, 80), mpz_class(1 + long(rng() % 3 ? (1L << (rng() % 60)) : rng() % 1000000)));
    t.canonicalize();
    if (trial % 10 == 0) t = mpq_class(random_int(rng, 20));  // an integer point
    mpq_class want = p.back();
    for (int i = int(p.size()) - 2; i >= 0; --i) {
      want *= t;
      want += p[i];
    }
    INFO("trial " << trial);
    REQUIRE(rational_poly_eval(p, t) == want);
    REQUIRE(Poly<Rational>(p)(t) == want);  // Poly's Horner goes through it
  }
}

}  // namespace ECCD_UNITY_ID
