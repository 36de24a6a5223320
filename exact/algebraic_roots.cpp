// Real roots of rational polynomials behind exact/algebraic_roots.hpp (the
// only CGAL translation unit of the workbench: CGAL is header heavy).
//
// CGAL's Algebraic_kernel_d_1 over CORE::BigInt does the isolation of every
// real root (solve_1) when the range is not [0, 1]; the square-free
// factorisation and the polynomial gcds are FLINT's (exact/flint_poly.hpp:
// CGAL's modular gcd would be a fifth of the exact pipelines). CORE is
// header-only in CGAL 5.5 (Debian libcgal-dev) and enabled by CGAL itself when
// GMP and MPFR are there (CGAL_USE_CORE); nothing else to link. Everything
// after isolation is done on the isolating intervals, in integer arithmetic
// (exact/root_refinement.hpp): refinement by quadratic interval refinement
// (QIR, Abbott 2006: secant steps snapped to a dyadic grid, bisection after a
// failed step) with exact signs of the square-free factor at dyadic points,
// comparisons with the ends of the range, and signs of other polynomials at
// the roots (a mean-value bound first, a gcd for the zero case, refinement
// otherwise). CGAL's own refinement and Sign_at_1 evaluate at rationals in
// rational arithmetic (a gcd per operation): with refinement of every root to
// 2^-64 that would be two thirds of the exact 2D pipeline.
//
// Bounded: every refinement loop asks the running thread's deadline
// (kernel/budget.hpp: BudgetExhausted when it passed). CGAL's modular gcd has
// 2000 primes of about 26 bits; a gcd that needs more loops forever printing
// "primes in the array exhausted" to std::cerr. Every call into CGAL is made
// under CgalGuard: polynomials with coefficients beyond kMaxCgalBits are
// refused up front (BudgetExhausted), CGAL's std::cerr output is captured (it
// never reaches the user), and that message ends the call with BudgetExhausted.
#include "exact/algebraic_roots.hpp"
#include "exact/root_refinement.hpp"
#include "number/simplest_rational.hpp"
#include "exact/integer_polynomial.hpp"
#include "exact/flint_poly.hpp"
#include "kernel/budget.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/CORE_BigInt.h>
#include <CGAL/CORE_arithmetic_kernel.h>

#include <algorithm>
#include <iostream>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <streambuf>
#include <string>

namespace eccd {

namespace {
using root_refinement::certainly_square_free;
using root_refinement::compare_root;
using root_refinement::constant_sign;
using root_refinement::dyadic;
using root_refinement::Dyadic;
using root_refinement::dyadic_parts;
using root_refinement::eval_dyadic;
using root_refinement::IntPoly;
using root_refinement::is_root;
using root_refinement::kMaxLevel;
using root_refinement::Refiner;
using root_refinement::sign_at_rational;

using AK = CGAL::Algebraic_kernel_d_1<CORE::BigInt>;  // CORE's BigInt and BigRat (GMP inside)
using AKPoly = AK::Polynomial_1;
using AKReal = AK::Algebraic_real_1;
using PT = CGAL::Polynomial_traits_d<AKPoly>;

AK& kernel() {
  static thread_local AK ak;
  return ak;
}

// The deadline read from the clock now: for the coarse steps (each isolation,
// gcd, sign), which are few.
void check_deadline_now(const char* where) { check_deadline(where); }

// Largest coefficient (bits) of a polynomial handed to CGAL's modular gcd:
// well inside what its 2000 primes (~52 000 bits) can reconstruct. FLINT's
// gcds (exact/flint_poly.hpp) have no such limit; the same check guards them,
// so that CGAL and FLINT refuse the same inputs.
constexpr std::size_t kMaxCgalBits = 20000;

// std::cerr while CGAL runs: keeps what CGAL prints (never shown) and stops
// the run on the prime-exhaustion message. Threads (eccd animate runs
// pair-frames on a pool): std::cerr is one object, so the first guard of the
// process installs the buffer and the last one restores std::cerr (a count
// under a mutex; swapping per guard let one thread restore another's buffer
// after it was destroyed); the text is kept per thread, by the thread that
// writes it (CGAL's own code).
class CgalErrBuf : public std::streambuf {
 public:
  static std::string& text() {
    static thread_local std::string t;
    return t;
  }

 protected:
  int overflow(int ch) override {
    if (ch != EOF) put(char(ch));
    return ch == EOF ? 0 : ch;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i) put(s[i]);
    return n;
  }

 private:
  void put(char c) {
    std::string& t = text();
    if (t.size() < 4096) t += c;
    if (t.find("primes in the array exhausted") != std::string::npos)
      throw BudgetExhausted(
          "exact root isolation: the coefficients are too large for CGAL's modular gcd (it ran out of primes)");
  }
};

class CgalGuard {
 public:
  CgalGuard() {
    std::lock_guard<std::mutex> lock(shared().mu);
    CgalErrBuf::text().clear();
    if (shared().depth++ == 0) {
      shared().old = std::cerr.rdbuf(&shared().buf);
      shared().old_ex = std::cerr.exceptions();
      std::cerr.exceptions(std::ios::badbit);
    }
  }
  ~CgalGuard() {
    std::lock_guard<std::mutex> lock(shared().mu);
    if (--shared().depth == 0) {
      std::cerr.rdbuf(shared().old);
      std::cerr.clear();
      std::cerr.exceptions(shared().old_ex);
    }
  }
  CgalGuard(const CgalGuard&) = delete;
  CgalGuard& operator=(const CgalGuard&) = delete;
  // Refuses coefficients that CGAL's modular gcd cannot reconstruct.
  static void check_size(const std::vector<mpz_class>& z, const char* what) {
    for (const auto& x : z)
      if (mpz_sizeinbase(x.get_mpz_t(), 2) > kMaxCgalBits)
        throw BudgetExhausted(std::string(what) + ": a polynomial coefficient of " +
                              std::to_string(mpz_sizeinbase(x.get_mpz_t(), 2)) + " bits, beyond the " +
                              std::to_string(kMaxCgalBits) +
                              "-bit limit of CGAL's modular gcd (the scene's numbers have too many digits)");
    check_deadline_now(what);
  }

 private:
  struct Shared {
    std::mutex mu;
    int depth = 0;
    CgalErrBuf buf;
    std::streambuf* old = nullptr;
    std::ios::iostate old_ex{};
  };
  static Shared& shared() {
    static Shared s;
    return s;
  }
};

// Runs f (a call into CGAL) under CgalGuard; an exception escaping CGAL's
// stream code is turned back into the BudgetExhausted that started it.
template <class F>
auto with_cgal(F&& f) {
  CgalGuard g;
  try {
    return f();
  } catch (const std::ios::failure&) {
    throw BudgetExhausted(
        "exact root isolation: the coefficients are too large for CGAL's modular gcd (it ran out of primes)");
  }
}

// A positive rational multiple of p with coprime integer coefficients.
IntPoly integer_multiple(const Poly<Rational>& p) { return primitive_integer_multiple(p); }

AKPoly to_ak(const IntPoly& z) {
  std::vector<CORE::BigInt> c;
  c.reserve(z.size());
  for (const auto& x : z) c.emplace_back(x.get_mpz_t());
  return PT::Construct_polynomial()(c.begin(), c.end());
}

IntPoly from_ak(const AKPoly& p) {
  int n = PT::Degree()(p);
  IntPoly z;
  z.reserve(n + 1);
  for (int i = 0; i <= n; ++i) z.emplace_back(PT::Get_coefficient()(p, i).get_mp());
  return z;
}

// Back from CGAL, made primitive with a positive leading coefficient.
Poly<Rational> poly_from_ak(const AKPoly& p) {
  IntPoly z = from_ak(p);
  mpz_class c = 0;
  for (const auto& x : z) mpz_gcd(c.get_mpz_t(), c.get_mpz_t(), x.get_mpz_t());
  if (c == 0) return Poly<Rational>();
  if (z.back() < 0) c = -c;
  Poly<Rational> out;
  for (const auto& x : z) out.c.push_back(Rational(mpz_class(x / c)));
  out.trim();
  return out;
}

// An integer polynomial (already primitive, positive leading coefficient) as Poly<Rational>.
Poly<Rational> int_poly_to_rational(const IntPoly& z) {
  Poly<Rational> out;
  for (const auto& x : z) out.c.push_back(Rational(x));
  out.trim();
  return out;
}

Rational to_rational(const AK::Bound& b) { return Rational(b.get_mp()); }

}  // namespace

struct AlgebraicRootImpl {
  IntPoly f;   // the square-free factor of p that the root is a simple root of (primitive, integer)
  AKPoly fak;  // the same, as CGAL's polynomial (only on the general path: to tell CGAL's factors apart)
};

namespace {

void set_bracket(AlgebraicRoot& r, const Dyadic& d) {
  r.lo = dyadic(d.A, d.k);
  r.hi = dyadic(d.B, d.k);
}

// Refines r (with its dyadic bracket d) to width <= 2^-bits.
void refine_to(AlgebraicRoot& r, Dyadic& d, Refiner& rf, long bits) {
  std::optional<Rational> exact;
  if (!rf.refine(d, bits, exact)) {
    r.lo = r.hi = *exact;
    return;
  }
  set_bracket(r, d);
}

struct Work {
  AlgebraicRoot r;
  Dyadic d;
};

// The common end of real_roots: consecutive brackets made disjoint (the roots
// are distinct and sorted; with reorder, the roots of several factors, sorted
// again after each refinement pass), and a rational root with a small denominator
// written exactly (the simplest rational in the bracket is a root of the
// factor iff it is the bracket's root).
std::vector<AlgebraicRoot> finish_roots(std::vector<Work>& all, int bits, bool reorder = false) {
  for (long b2 = std::max(2L * bits, 1L);; b2 *= 2) {
    check_deadline("separating root brackets");
    if (reorder) std::sort(all.begin(), all.end(), [](const Work& x, const Work& y) { return x.r.lo < y.r.lo; });
    bool disjoint = true;
    for (std::size_t i = 0; i + 1 < all.size(); ++i) {
      if (all[i].r.hi < all[i + 1].r.lo) continue;
      if (all[i + 1].r.hi < all[i].r.lo)
        throw std::logic_error("internal error: the roots are not in increasing order");
      if (b2 > long(kMaxLevel)) throw std::logic_error("internal error: brackets of distinct roots do not separate");
      disjoint = false;
      for (Work* w : {&all[i], &all[i + 1]})
        if (!w->r.is_rational()) {
          Refiner rf(w->r.impl->f);
          refine_to(w->r, w->d, rf, b2);
        }
    }
    if (disjoint) break;
  }
  std::vector<AlgebraicRoot> out;
  for (auto& w : all) {
    if (!w.r.is_rational()) {
      Rational q = simplest_rational_in(w.r.lo, w.r.hi);
      if (is_root(w.r.impl->f, q)) w.r.lo = w.r.hi = q;
    }
    out.push_back(std::move(w.r));
  }
  return out;
}

// Descartes' method on (0, 1) (Collins-Akritas 1976, as in CGAL's
// Algebraic_kernel_d/Descartes.h zero_one_descartes, here on GMP integers
// without CGAL's polynomial class): P(x) = 2^(D n) f((i + x) / 2^D) up to a
// positive power of two, so P's roots in (0, 1) are f's in (i/2^D,
// (i+1)/2^D). V = sign variations of (1 + x)^n P(1 / (1 + x)) bounds their
// number, with V - #roots even and >= 0 (exact/descartes.hpp): V = 0, none;
// V = 1 with P(0), P(1) != 0, exactly one, simple, and f is non-zero at both
// ends; otherwise bisect: 2^n P(x / 2) for the left half, its Taylor shift
// by 1 for the right one, whose constant term is P at the midpoint (zero:
// the midpoint is an exact root). Terminates for square-free f (Vincent's
// theorem); bounded by the run's deadline and by kMaxLevel.
void zero_one_descartes(const IntPoly& P, const mpz_class& i, unsigned long D,
                        std::vector<std::pair<Rational, Rational>>& brackets, std::vector<bool>& exact) {
  check_deadline("exact root isolation");
  if (D > kMaxLevel) throw std::logic_error("internal error: root isolation does not converge");
  const std::size_t n = P.size() - 1;
  auto taylor_shift_1 = [n](IntPoly& r) {  // r(x) <- r(x + 1)
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t k = n - 1;; --k) {
        mpz_add(r[k].get_mpz_t(), r[k].get_mpz_t(), r[k + 1].get_mpz_t());
        if (k == a) break;
      }
  };
  IntPoly R(P.rbegin(), P.rend());
  taylor_shift_1(R);
  int V = 0, last = 0;
  for (const auto& x : R) {
    int sx = sgn(x);
    if (sx == 0) continue;
    if (last != 0 && sx != last) ++V;
    last = sx;
  }
  if (V == 0) return;
  if (V == 1 && sgn(P[0]) != 0 && sgn(R[0]) != 0) {  // R(0) = P(1)
    brackets.push_back({dyadic(i, D), dyadic(mpz_class(i + 1), D)});
    exact.push_back(false);
    return;
  }
  IntPoly Q(P);  // 2^n P(x / 2): Q_k = 2^(n - k) P_k, then the common power of two removed
  unsigned long common = ~0ul;
  for (std::size_t k = 0; k <= n; ++k) {
    mpz_mul_2exp(Q[k].get_mpz_t(), Q[k].get_mpz_t(), n - k);
    if (sgn(Q[k])) common = std::min<unsigned long>(common, mpz_scan1(Q[k].get_mpz_t(), 0));
  }
  if (common != ~0ul && common > 0)
    for (auto& x : Q) mpz_fdiv_q_2exp(x.get_mpz_t(), x.get_mpz_t(), common);
  const mpz_class left = 2 * i;
  zero_one_descartes(Q, left, D + 1, brackets, exact);
  taylor_shift_1(Q);  // the right half
  if (sgn(Q[0]) == 0) {
    brackets.push_back({dyadic(mpz_class(left + 1), D + 1), dyadic(mpz_class(left + 1), D + 1)});
    exact.push_back(true);
  }
  zero_one_descartes(Q, mpz_class(left + 1), D + 1, brackets, exact);
}

// The roots in [0, 1] of the square-free integer polynomial z (degree >= 1),
// each of multiplicity m in the caller's polynomial, appended to `all`
// (increasing). Roots at 0 and 1 are z(0) = 0 and z(1) = 0 (exact); they are
// divided out (exactly, in integers), leaving f, square-free, with f(0),
// f(1) != 0, whose roots in the open (0, 1) are isolated on that interval
// alone by zero_one_descartes (each returned interval holds exactly one root
// of f and f is non-zero at its ends, or it is a dyadic midpoint that is a
// root) and refined to width 2^-bits.
void unit_roots_of_square_free(IntPoly z, int m, int bits, std::vector<Work>& all) {
  if (z.back() < 0)
    for (auto& x : z) x = -x;
  auto rational_root = [&](const Rational& x) {
    Work w;
    w.r.lo = w.r.hi = x;
    w.r.multiplicity = m;
    all.push_back(std::move(w));
  };
  const bool at0 = sgn(z[0]) == 0;
  if (at0) z.erase(z.begin());  // z / t
  mpz_class sum = 0;
  for (const auto& x : z) sum += x;
  const bool at1 = sgn(sum) == 0;
  if (at1) {  // z / (t - 1) by synthetic division: q_(i-1) = z_i + q_i, from the top
    IntPoly q(z.size() - 1);
    mpz_class carry = 0;
    for (std::size_t i = z.size() - 1; i >= 1; --i) {
      carry += z[i];
      q[i - 1] = carry;
    }
    z.swap(q);
  }
  if (at0) rational_root(Rational(0));
  if (z.size() >= 2) {
    auto impl = std::make_shared<AlgebraicRootImpl>(AlgebraicRootImpl{z, AKPoly()});
    std::vector<std::pair<Rational, Rational>> brackets;
    std::vector<bool> exact;
    zero_one_descartes(z, 0, 0, brackets, exact);
    for (std::size_t i = 0; i < brackets.size(); ++i) {
      if (exact[i]) {
        rational_root(brackets[i].first);
        continue;
      }
      Work w;
      w.r.impl = impl;
      w.r.multiplicity = m;
      Refiner rf(impl->f);
      std::optional<Rational> ex;
      if (!rf.init(brackets[i].first, brackets[i].second, w.d, ex))
        w.r.lo = w.r.hi = *ex;
      else
        refine_to(w.r, w.d, rf, bits);
      all.push_back(std::move(w));
    }
  }
  if (at1) rational_root(Rational(1));
}

// real_roots on [0, 1]: only the roots there are isolated (the general path
// below isolates every real root of p). When p's primitive integer multiple z
// is certainly square-free (certainly_square_free, a modular certificate: the
// usual case in 2D), every root is simple and no factorisation is needed;
// otherwise FLINT's square-free factorisation z = c · Π F_i^m_i (pairwise
// coprime, so the roots of different factors are distinct) and each F_i's
// roots in [0, 1] with multiplicity m_i, merged in increasing order: brackets
// are sorted by their left ends and overlapping neighbours (of distinct
// roots) refined until all are disjoint, which puts them in root order.
std::vector<AlgebraicRoot> unit_interval_roots(const Poly<Rational>& p, int bits) {
  IntPoly z = integer_multiple(p);
  CgalGuard::check_size(z, "exact root isolation");
  std::vector<Work> all;
  if (certainly_square_free(z)) return unit_roots_of_square_free(z, 1, bits, all), finish_roots(all, bits);
  for (auto& [q, m] : flint_square_free_factors(z)) unit_roots_of_square_free(std::move(q), m, bits, all);
  return finish_roots(all, bits, /*reorder: roots of different factors interleave*/ true);
}

}  // namespace

std::vector<AlgebraicRoot> real_roots(const Poly<Rational>& p, const Rational& a, const Rational& b, int bits) {
  if (p.is_zero()) throw std::invalid_argument("real_roots: the zero polynomial has every number as a root");
  std::vector<AlgebraicRoot> out;
  if (p.degree() < 1) return out;
  if (a == 0 && b == 1) return unit_interval_roots(p, bits);
  std::vector<std::pair<AKReal, AK::Multiplicity_type>> roots;
  {
    IntPoly z = integer_multiple(p);
    CgalGuard::check_size(z, "exact root isolation");
    with_cgal([&] {
      kernel().solve_1_object()(to_ak(z), std::back_inserter(roots));
      return 0;
    });
  }
  // CGAL returns them sorted. Only those whose isolating interval meets [a, b]
  // are worked on; the others are known to be outside.
  std::vector<Work> all;
  std::vector<std::shared_ptr<AlgebraicRootImpl>> factors;
  for (auto& [alpha, mult] : roots) {
    Work w;
    w.r.multiplicity = int(mult);
    Rational lo = to_rational(alpha.low()), hi = to_rational(alpha.high());
    if (alpha.is_rational() || lo == hi) {
      Rational x = alpha.is_rational() ? to_rational(alpha.rational()) : lo;
      if (x < a || x > b) continue;
      w.r.lo = w.r.hi = x;
    } else {
      if (hi <= a || lo >= b) continue;  // the root is in the open (lo, hi)
      std::shared_ptr<AlgebraicRootImpl> impl;
      for (const auto& f : factors)
        if (f->fak == alpha.polynomial()) impl = f;
      if (!impl) {
        impl = std::make_shared<AlgebraicRootImpl>(AlgebraicRootImpl{from_ak(alpha.polynomial()), alpha.polynomial()});
        factors.push_back(impl);
      }
      w.r.impl = impl;
      Refiner rf(impl->f);
      std::optional<Rational> exact;
      if (!rf.init(lo, hi, w.d, exact)) {
        w.r.lo = w.r.hi = *exact;
      } else {
        refine_to(w.r, w.d, rf, bits);
      }
      if (!w.r.is_rational()) {
        // exactly where it lies with respect to [a, b]
        int ca = compare_root(impl->f, w.r.lo, w.r.hi, sgn(w.d.FA), a);
        if (ca < 0) continue;
        int cb = compare_root(impl->f, w.r.lo, w.r.hi, sgn(w.d.FA), b);
        if (cb > 0) continue;
        if (ca == 0)
          w.r.lo = w.r.hi = a;
        else if (cb == 0)
          w.r.lo = w.r.hi = b;
      } else if (w.r.lo < a || w.r.lo > b) {
        continue;
      }
    }
    all.push_back(std::move(w));
  }
  return finish_roots(all, bits);
}

Sign sign_at(const Poly<Rational>& q, const AlgebraicRoot& r) {
  if (q.is_zero()) return Sign::zero;
  if (q.degree() == 0) return sign(q.c[0]);
  IntPoly Q = integer_multiple(q);  // a positive multiple: same signs
  if (r.is_rational()) return sign_of_int(sign_at_rational(Q, r.lo));
  if (!r.impl) throw std::invalid_argument("sign_at: a root without its polynomial");
  check_deadline_now("sign at an algebraic number");
  // The bracket as it is (no evaluation of the factor yet).
  Dyadic d;
  mpz_class A, B;
  unsigned long ja, jb;
  bool have_dyadic = dyadic_parts(r.lo, A, ja) && dyadic_parts(r.hi, B, jb);
  if (have_dyadic) {
    d.k = std::max(ja, jb);
    d.A = A << (d.k - ja);
    d.B = B << (d.k - jb);
    if (int s = constant_sign(Q, d)) return sign_of_int(s);
  }
  // Zero iff gcd(q, f) has the root: it divides f, whose only root in the
  // bracket is simple, so it has it iff it changes sign over the bracket.
  const IntPoly& f = r.impl->f;
  CgalGuard::check_size(Q, "sign at an algebraic number");
  IntPoly gi = flint_gcd(Q, f);
  if (gi.size() > 1) {
    int glo = sign_at_rational(gi, r.lo), ghi = sign_at_rational(gi, r.hi);
    if (glo == 0 || ghi == 0)
      throw std::invalid_argument("sign_at: the root's factor vanishes at an end of its bracket");
    if (glo != ghi) return Sign::zero;
  }
  // q(root) != 0: refine a copy of the bracket until the bound decides.
  std::optional<Rational> exact;
  Refiner rf(f);
  if (!rf.init(r.lo, r.hi, d, exact)) return sign_of_int(sign_at_rational(Q, *exact));
  for (long bits = std::max<long>(64, long(d.k));; bits *= 2) {
    check_deadline("sign at an algebraic number");
    if (int s = constant_sign(Q, d)) return sign_of_int(s);
    if (bits > long(kMaxLevel))
      throw std::logic_error("internal error: the sign at an algebraic number does not converge");
    if (!rf.refine(d, bits, exact)) return sign_of_int(sign_at_rational(Q, *exact));
  }
}

std::vector<std::pair<Poly<Rational>, int>> square_free_factors(const Poly<Rational>& p) {
  if (p.is_zero()) throw std::invalid_argument("square_free_factors: the zero polynomial");
  IntPoly z = integer_multiple(p);
  CgalGuard::check_size(z, "square-free factorisation");
  std::vector<std::pair<Poly<Rational>, int>> out;
  for (auto& [q, m] : flint_square_free_factors(z)) out.push_back({int_poly_to_rational(q), m});
  return out;
}

Poly<Rational> polynomial_gcd(const Poly<Rational>& p, const Poly<Rational>& q) {
  IntPoly zp = integer_multiple(p), zq = integer_multiple(q);
  CgalGuard::check_size(zp, "polynomial gcd");
  CgalGuard::check_size(zq, "polynomial gcd");
  return int_poly_to_rational(flint_gcd(zp, zq));
}

std::vector<std::pair<Poly<Rational>, int>> square_free_factors_cgal(const Poly<Rational>& p) {
  if (p.is_zero()) throw std::invalid_argument("square_free_factors: the zero polynomial");
  std::vector<std::pair<AKPoly, int>> f;
  IntPoly z = integer_multiple(p);
  CgalGuard::check_size(z, "square-free factorisation");
  with_cgal([&] {
    PT::Square_free_factorize_up_to_constant_factor()(to_ak(z), std::back_inserter(f));
    return 0;
  });
  std::vector<std::pair<Poly<Rational>, int>> out;
  for (auto& [q, m] : f)
    if (PT::Degree()(q) > 0) out.push_back({poly_from_ak(q), m});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  return out;
}

Poly<Rational> polynomial_gcd_cgal(const Poly<Rational>& p, const Poly<Rational>& q) {
  IntPoly zp = integer_multiple(p), zq = integer_multiple(q);
  CgalGuard::check_size(zp, "polynomial gcd");
  CgalGuard::check_size(zq, "polynomial gcd");
  return poly_from_ak(with_cgal([&] { return PT::Gcd_up_to_constant_factor()(to_ak(zp), to_ak(zq)); }));
}

void refine(AlgebraicRoot& r, int bits) {
  if (r.is_rational()) return;
  if (!r.impl) throw std::invalid_argument("refine: a root without its polynomial");
  // already narrow enough?
  Rational w = r.hi - r.lo;
  mpq_mul_2exp(w.get_mpq_t(), w.get_mpq_t(), static_cast<unsigned long>(std::max(bits, 0)));
  if (w <= 1) return;
  Dyadic d;
  std::optional<Rational> exact;
  Refiner rf(r.impl->f);
  if (!rf.init(r.lo, r.hi, d, exact)) {
    r.lo = r.hi = *exact;
    return;
  }
  refine_to(r, d, rf, bits);
}

}  // namespace eccd
