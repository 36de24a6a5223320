// CGAL's Algebraic_kernel_d_1 behind exact/algebraic_roots.hpp (the only CGAL
// translation unit of the workbench: CGAL is header heavy).
#include "exact/algebraic_roots.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/Gmpz.h>

#include <algorithm>
#include <stdexcept>

namespace eccd {

namespace {
using AK = CGAL::Algebraic_kernel_d_1<CGAL::Gmpz>;
using AKPoly = AK::Polynomial_1;
using AKReal = AK::Algebraic_real_1;
using AKBound = AK::Bound;  // CGAL::Gmpq

AK& kernel() {
  static thread_local AK ak;
  return ak;
}

AKPoly to_integer_poly(const Poly<Rational>& p) {
  mpz_class l = 1;
  for (const auto& c : p.c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  std::vector<CGAL::Gmpz> z;
  z.reserve(p.c.size());
  for (const auto& c : p.c) {
    mpz_class n = c.get_num() * (l / c.get_den());
    z.emplace_back(n.get_mpz_t());
  }
  using PT = CGAL::Polynomial_traits_d<AKPoly>;
  return PT::Construct_polynomial()(z.begin(), z.end());
}

// Back from CGAL, made primitive with a positive leading coefficient.
Poly<Rational> from_integer_poly(const AKPoly& p) {
  using PT = CGAL::Polynomial_traits_d<AKPoly>;
  int n = PT::Degree()(p);
  std::vector<mpz_class> z;
  for (int i = 0; i <= n; ++i) z.emplace_back(PT::Get_coefficient()(p, i).mpz());
  mpz_class c = 0;
  for (const auto& x : z) mpz_gcd(c.get_mpz_t(), c.get_mpz_t(), x.get_mpz_t());
  if (c == 0) return Poly<Rational>();
  if (z.back() < 0) c = -c;
  Poly<Rational> out;
  for (const auto& x : z) out.c.push_back(Rational(mpz_class(x / c)));
  out.trim();
  return out;
}

Rational to_rational(const AKBound& b) { return Rational(b.mpq()); }
AKBound to_bound(const Rational& q) { return AKBound(q.get_mpq_t()); }
}  // namespace

struct AlgebraicRootImpl {
  AKReal alpha;
};

// A bracket of width <= 2^-bits; when r already has one, the new bracket is
// intersected with it, so that refining never moves a bracket outwards.
static void set_bracket(AlgebraicRoot& r, int bits, bool keep_old) {
  auto iv = kernel().approximate_absolute_1_object()(r.impl->alpha, bits);
  Rational lo = to_rational(iv.first), hi = to_rational(iv.second);
  if (keep_old) {
    if (r.lo > lo) lo = r.lo;
    if (r.hi < hi) hi = r.hi;
  }
  r.lo = lo;
  r.hi = hi;
}

// The rational with the smallest denominator in [lo, hi] (continued fractions).
static Rational simplest_rational_in(const Rational& lo, const Rational& hi) {
  // an integer in [lo, hi] if there is one
  mpz_class fl;
  mpz_fdiv_q(fl.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
  if (Rational(fl) == lo) return lo;
  mpz_class c = fl + 1;
  if (Rational(c) <= hi) return Rational(c);
  // lo and hi share the integer part fl: recurse on the reciprocals of the fractional parts
  Rational a = lo - Rational(fl), b = hi - Rational(fl);
  Rational inner = simplest_rational_in(1 / b, 1 / a);
  Rational r = Rational(fl) + 1 / inner;
  return r;
}

std::vector<AlgebraicRoot> real_roots(const Poly<Rational>& p, const Rational& a, const Rational& b, int bits) {
  if (p.is_zero()) throw std::invalid_argument("real_roots: the zero polynomial has every number as a root");
  std::vector<AlgebraicRoot> all;
  if (p.degree() < 1) return all;
  std::vector<std::pair<AKReal, AK::Multiplicity_type>> roots;
  kernel().solve_1_object()(to_integer_poly(p), std::back_inserter(roots));
  for (auto& [alpha, mult] : roots) {
    AlgebraicRoot r;
    r.multiplicity = int(mult);
    r.impl = std::make_shared<AlgebraicRootImpl>(AlgebraicRootImpl{alpha});
    set_bracket(r, bits, false);
    all.push_back(std::move(r));
  }
  // CGAL returns them sorted; refine until consecutive brackets are disjoint.
  for (int b2 = bits; ; b2 *= 2) {
    bool disjoint = true;
    for (std::size_t i = 0; i + 1 < all.size(); ++i)
      if (!(all[i].hi < all[i + 1].lo)) { disjoint = false; set_bracket(all[i], b2 * 2, true); set_bracket(all[i + 1], b2 * 2, true); }
    if (disjoint) break;
  }
  // A rational root with a small denominator is written exactly: the simplest
  // rational in the bracket is a root of p iff it is the bracket's root.
  for (auto& r : all) {
    if (r.lo == r.hi) continue;
    Rational q = simplest_rational_in(r.lo, r.hi);
    if (p(q) == 0) r.lo = r.hi = q;
  }
  std::vector<AlgebraicRoot> out;
  auto cmp = kernel().compare_1_object();
  AKBound ba = to_bound(a), bb = to_bound(b);
  for (auto& r : all) {
    if (cmp(r.impl->alpha, AKReal(ba)) == CGAL::SMALLER) continue;
    if (cmp(r.impl->alpha, AKReal(bb)) == CGAL::LARGER) continue;
    out.push_back(std::move(r));
  }
  return out;
}

Sign sign_at(const Poly<Rational>& q, const AlgebraicRoot& r) {
  if (q.is_zero()) return Sign::zero;
  CGAL::Sign s = kernel().sign_at_1_object()(to_integer_poly(q), r.impl->alpha);
  return s == CGAL::NEGATIVE ? Sign::negative : (s == CGAL::POSITIVE ? Sign::positive : Sign::zero);
}

std::vector<std::pair<Poly<Rational>, int>> square_free_factors(const Poly<Rational>& p) {
  if (p.is_zero()) throw std::invalid_argument("square_free_factors: the zero polynomial");
  using PT = CGAL::Polynomial_traits_d<AKPoly>;
  std::vector<std::pair<AKPoly, int>> f;
  PT::Square_free_factorize_up_to_constant_factor()(to_integer_poly(p), std::back_inserter(f));
  std::vector<std::pair<Poly<Rational>, int>> out;
  for (auto& [q, m] : f)
    if (PT::Degree()(q) > 0) out.push_back({from_integer_poly(q), m});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  return out;
}

Poly<Rational> polynomial_gcd(const Poly<Rational>& p, const Poly<Rational>& q) {
  using PT = CGAL::Polynomial_traits_d<AKPoly>;
  return from_integer_poly(PT::Gcd_up_to_constant_factor()(to_integer_poly(p), to_integer_poly(q)));
}

void refine(AlgebraicRoot& r, int bits) {
  if (r.is_rational()) return;
  set_bracket(r, bits, true);
}

}  // namespace eccd
