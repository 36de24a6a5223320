// FLINT's square-free factorisation and gcd behind exact/flint_poly.hpp (the
// only translation unit that includes FLINT's headers).
#include "exact/flint_poly.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>
#include <flint/fmpq_poly.h>

#include <algorithm>
#include <stdexcept>

namespace eccd {

namespace {

// RAII for fmpz_poly_t.
struct FPoly {
  fmpz_poly_t p;
  FPoly() { fmpz_poly_init(p); }
  explicit FPoly(const std::vector<mpz_class>& z) {
    fmpz_poly_init2(p, slong(z.size()));
    fmpz_t c;
    fmpz_init(c);
    for (std::size_t i = 0; i < z.size(); ++i) {
      fmpz_set_mpz(c, z[i].get_mpz_t());
      fmpz_poly_set_coeff_fmpz(p, slong(i), c);
    }
    fmpz_clear(c);
  }
  ~FPoly() { fmpz_poly_clear(p); }
  FPoly(const FPoly&) = delete;
  FPoly& operator=(const FPoly&) = delete;
};

// The coefficients of p, made primitive with a positive leading coefficient.
std::vector<mpz_class> primitive_of(const fmpz_poly_t p) {
  const slong n = fmpz_poly_length(p);
  std::vector<mpz_class> z(static_cast<std::size_t>(n));
  fmpz_t c;
  fmpz_init(c);
  for (slong i = 0; i < n; ++i) {
    fmpz_poly_get_coeff_fmpz(c, p, i);
    fmpz_get_mpz(z[std::size_t(i)].get_mpz_t(), c);
  }
  fmpz_clear(c);
  if (z.empty()) return z;
  mpz_class g = 0;
  for (const auto& x : z) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x.get_mpz_t());
  if (z.back() < 0) g = -g;
  if (g != 1)
    for (auto& x : z) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
  return z;
}

}  // namespace

std::vector<std::pair<std::vector<mpz_class>, int>> flint_square_free_factors(const std::vector<mpz_class>& z) {
  if (z.empty() || sgn(z.back()) == 0)
    throw std::invalid_argument("flint_square_free_factors: a zero leading coefficient");
  FPoly f(z);
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  fmpz_poly_factor_squarefree(fac, f.p);
  std::vector<std::pair<std::vector<mpz_class>, int>> out;
  for (slong i = 0; i < fac->num; ++i)
    if (fmpz_poly_degree(fac->p + i) > 0) out.push_back({primitive_of(fac->p + i), int(fac->exp[i])});
  fmpz_poly_factor_clear(fac);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  return out;
}

std::vector<mpz_class> flint_gcd(const std::vector<mpz_class>& a, const std::vector<mpz_class>& b) {
  FPoly fa(a), fb(b), g;
  fmpz_poly_gcd(g.p, fa.p, fb.p);
  if (fmpz_poly_length(g.p) == 0) return {};  // both zero: the zero polynomial
  return primitive_of(g.p);
}

struct FlintQPolyImpl {
  fmpq_poly_t p;
  FlintQPolyImpl() { fmpq_poly_init(p); }
  ~FlintQPolyImpl() { fmpq_poly_clear(p); }
  FlintQPolyImpl(const FlintQPolyImpl&) = delete;
  FlintQPolyImpl& operator=(const FlintQPolyImpl&) = delete;
};

FlintQPoly::FlintQPoly() : p_(std::make_unique<FlintQPolyImpl>()) {}
FlintQPoly::FlintQPoly(const Poly<Rational>& q) : p_(std::make_unique<FlintQPolyImpl>()) {
  if (q.c.empty()) return;
  std::vector<__mpq_struct> a(q.c.size());
  for (std::size_t i = 0; i < q.c.size(); ++i) a[i] = *q.c[i].get_mpq_t();  // shallow: read only
  fmpq_poly_set_array_mpq(p_->p, reinterpret_cast<const mpq_t*>(a.data()), slong(a.size()));
}
FlintQPoly::FlintQPoly(const FlintQPoly& o) : p_(std::make_unique<FlintQPolyImpl>()) { fmpq_poly_set(p_->p, o.p_->p); }
FlintQPoly::FlintQPoly(FlintQPoly&& o) noexcept = default;
FlintQPoly& FlintQPoly::operator=(const FlintQPoly& o) {
  if (this != &o) {
    if (!p_) p_ = std::make_unique<FlintQPolyImpl>();
    fmpq_poly_set(p_->p, o.p_->p);
  }
  return *this;
}
FlintQPoly& FlintQPoly::operator=(FlintQPoly&& o) noexcept = default;
FlintQPoly::~FlintQPoly() = default;

Poly<Rational> FlintQPoly::to_poly() const {
  Poly<Rational> out;
  const slong n = fmpq_poly_length(p_->p);
  out.c.resize(std::size_t(n));
  for (slong i = 0; i < n; ++i) fmpq_poly_get_coeff_mpq(out.c[std::size_t(i)].get_mpq_t(), p_->p, i);
  out.trim();
  return out;
}
bool FlintQPoly::is_zero() const { return fmpq_poly_is_zero(p_->p); }

FlintQPoly operator+(const FlintQPoly& a, const FlintQPoly& b) {
  FlintQPoly r;
  fmpq_poly_add(r.p_->p, a.p_->p, b.p_->p);
  return r;
}
FlintQPoly operator-(const FlintQPoly& a, const FlintQPoly& b) {
  FlintQPoly r;
  fmpq_poly_sub(r.p_->p, a.p_->p, b.p_->p);
  return r;
}
FlintQPoly operator*(const FlintQPoly& a, const FlintQPoly& b) {
  FlintQPoly r;
  fmpq_poly_mul(r.p_->p, a.p_->p, b.p_->p);
  return r;
}
FlintQPoly operator*(long k, const FlintQPoly& a) {
  FlintQPoly r;
  fmpq_poly_scalar_mul_si(r.p_->p, a.p_->p, slong(k));
  return r;
}

}  // namespace eccd
