// Exact refinement of real roots of square-free integer polynomials on dyadic
// brackets, in integer arithmetic only (GMP): the engine behind
// exact/algebraic_roots.hpp once a root is isolated.
//
// Statement. A Dyadic bracket (A / 2^k, B / 2^k) holds exactly one root of the
// square-free f with f nonzero at both ends. Refiner narrows it by quadratic
// interval refinement (QIR, Abbott 2006: secant steps snapped to the dyadic
// grid, bisection after a failed step) on exact signs of f at dyadic points;
// a zero there is the root itself, which is then exact. Beside it: exact
// signs at rationals and dyadics, the rational root test, a modular
// certificate of square-freeness, the comparison of a root with a rational,
// and constant_sign, a Taylor bound proving the sign of another polynomial on
// a whole bracket (docs/references.md: Abbott 2006 for QIR).
// Every loop asks the running thread's deadline (kernel/budget.hpp).
// Requirements: GMP integers and rationals (number/rational_traits.hpp).
#pragma once

#include "number/rational_traits.hpp"
#include "kernel/budget.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

namespace eccd::root_refinement {

using IntPoly = std::vector<mpz_class>;  // lowest degree first, nonzero leading coefficient

constexpr unsigned long kMaxLevel = 1ul << 20;  // refinement limit (bits of a bracket's ends): a bug guard

// out = 2^(k·n) f(a / 2^k), n = deg f: the exact value, up to a positive factor.
void eval_dyadic(mpz_class& out, const IntPoly& f, const mpz_class& a, unsigned long k);
// The exact sign of f at the rational x.
int sign_at_rational(const IntPoly& f, const Rational& x);
// x = a / 2^j (lowest terms) when x's denominator is a power of two.
bool dyadic_parts(const Rational& x, mpz_class& a, unsigned long& j);
// a / 2^k.
Rational dyadic(const mpz_class& a, unsigned long k);

// An isolating bracket on the dyadic grid of level k: the open interval
// (A / 2^k, B / 2^k), A < B, holds exactly one root of the square-free f, and
// f is not zero at its ends: FA = 2^(k·n) f(A / 2^k) and FB (likewise) are
// nonzero and of opposite signs.
struct Dyadic {
  unsigned long k = 0;
  mpz_class A, B, FA, FB;
};

// Refinement of a root of the square-free integer polynomial f. Every step
// decides on exact signs of f at dyadic points; a zero there is the root
// itself (the only root of f in the bracket), which is then exact.
class Refiner {
 public:
  explicit Refiner(const IntPoly& f) : f_(f), n_(static_cast<unsigned long>(f.size() - 1)) {}

  // From an isolating open interval (lo, hi) with arbitrary rational ends.
  // Returns false and sets `exact` if the root turned out to be a grid point.
  bool init(const Rational& lo_in, const Rational& hi_in, Dyadic& d, std::optional<Rational>& exact) {
    Rational lo = lo_in, hi = hi_in;
    mpz_class a, b;
    unsigned long ja, jb;
    if (dyadic_parts(lo, a, ja) && dyadic_parts(hi, b, jb)) {
      d.k = std::max(ja, jb);
      d.A = a << (d.k - ja);
      d.B = b << (d.k - jb);
      eval_dyadic(d.FA, f_, d.A, d.k);
      eval_dyadic(d.FB, f_, d.B, d.k);
      if (sgn(d.FA) * sgn(d.FB) >= 0)
        throw std::logic_error("internal error: not an isolating interval of a simple root");
      return true;
    }
    // Rational ends: take grid points j1 < j2 inside (lo, hi) (at least three
    // of them at level k); the root lies in (lo, j1), [j1, j2] or (j2, hi),
    // and the outer pieces shrink by 4 or more each round.
    int s_lo = sign_at_rational(f_, lo);
    if (s_lo == 0 || s_lo == sign_at_rational(f_, hi))
      throw std::logic_error("internal error: not an isolating interval of a simple root");
    for (;;) {
      check_deadline("exact root refinement");
      Rational w = hi - lo;
      unsigned long k = 0;
      for (Rational s = w; s < 4; s *= 2) ++k;
      if (k > kMaxLevel) throw std::logic_error("internal error: bracket refinement does not converge");
      Rational L = lo, H = hi;
      mpq_mul_2exp(L.get_mpq_t(), L.get_mpq_t(), k);
      mpq_mul_2exp(H.get_mpq_t(), H.get_mpq_t(), k);
      mpz_class j1, j2;
      mpz_fdiv_q(j1.get_mpz_t(), L.get_num_mpz_t(), L.get_den_mpz_t());
      j1 += 1;
      mpz_cdiv_q(j2.get_mpz_t(), H.get_num_mpz_t(), H.get_den_mpz_t());
      j2 -= 1;
      mpz_class F1, F2;
      eval_dyadic(F1, f_, j1, k);
      if (sgn(F1) == 0) {
        exact = dyadic(j1, k);
        return false;
      }
      eval_dyadic(F2, f_, j2, k);
      if (sgn(F2) == 0) {
        exact = dyadic(j2, k);
        return false;
      }
      if (sgn(F1) != s_lo) {
        hi = dyadic(j1, k);
      } else if (sgn(F2) == s_lo) {
        lo = dyadic(j2, k);
      } else {
        d.k = k;
        d.A = j1;
        d.B = j2;
        d.FA = F1;
        d.FB = F2;
        return true;
      }
      if (dyadic_parts(lo, a, ja) && dyadic_parts(hi, b, jb)) return init(lo, hi, d, exact);
    }
  }

  // Shrinks d until its width is at most 2^-bits. Returns false and sets
  // `exact` if the root turned out to be a grid point.
  bool refine(Dyadic& d, long bits, std::optional<Rational>& exact) {
    bool failed = false;
    for (;;) {
      check_deadline("exact root refinement");
      long need = halvings_needed(d, bits);
      if (need <= 0) return true;
      if (d.k > kMaxLevel) throw std::logic_error("internal error: bracket refinement does not converge");
      if (failed) {  // after a failed secant step, one bisection (progress is certain)
        if (!bisect(d, exact)) return false;
        failed = false;
        continue;
      }
      // a successful step shrinks the bracket 2^L-fold: no finer than asked
      int L = int(std::min<long>(log2n_, need));
      int result = qir_step(d, L, exact);
      if (result < 0) return false;
      if (result == 1) {
        log2n_ = std::min(2 * log2n_, 1 << 12);
      } else {
        log2n_ = std::max(1, log2n_ / 2);
        failed = true;
      }
    }
  }

 private:
  // How many halvings until (B - A) / 2^k <= 2^-bits (0 if none).
  static long halvings_needed(const Dyadic& d, long bits) {
    mpz_class w = d.B - d.A;
    long e = long(mpz_sizeinbase(w.get_mpz_t(), 2));  // 2^(e-1) <= w < 2^e
    if (mpz_popcount(w.get_mpz_t()) == 1) e -= 1;     // w = 2^e exactly
    // width = w / 2^k <= 2^(e - k); need e - k <= -bits
    return e - long(d.k) + bits;
  }

  void lift(Dyadic& d, unsigned long L) {
    d.k += L;
    d.A <<= L;
    d.B <<= L;
    d.FA <<= L * n_;
    d.FB <<= L * n_;
  }

  // One bisection at the midpoint.
  bool bisect(Dyadic& d, std::optional<Rational>& exact) {
    mpz_class s = d.A + d.B;
    if (mpz_odd_p(s.get_mpz_t())) {
      lift(d, 1);
      s = d.A + d.B;
    }
    mpz_class M = s >> 1, FM;
    eval_dyadic(FM, f_, M, d.k);
    if (sgn(FM) == 0) {
      exact = dyadic(M, d.k);
      return false;
    }
    if (sgn(FM) == sgn(d.FA)) {
      d.A = M;
      d.FA = FM;
    } else {
      d.B = M;
      d.FB = FM;
    }
    return true;
  }

  // A QIR step with N = 2^L: the secant point of the bracket snapped to the
  // grid, and the point one N-th of the bracket further on the side of the
  // root. Returns 1 when the root was caught between the two (the bracket
  // shrank N-fold), 0 when the bracket only shrank, -1 when the root is a
  // grid point (exact).
  int qir_step(Dyadic& d, int L, std::optional<Rational>& exact) {
    mpz_class w = d.B - d.A;
    long bl = long(mpz_sizeinbase(w.get_mpz_t(), 2)) - 1;  // 2^bl <= w
    if (bl < L + 1) {                                      // room for N steps of at least 2 grid cells
      lift(d, static_cast<unsigned long>(L + 1 - bl));
      w = d.B - d.A;
    }
    mpz_class h = w >> static_cast<unsigned long>(L);  // the step, >= 2
    // the secant point A + round(w·|FA| / (|FA| + |FB|)), inside (A, B)
    mpz_class aFA = abs(d.FA), aFB = abs(d.FB);
    mpz_class den = aFA + aFB, num = w * aFA, off;
    num = 2 * num + den;
    den *= 2;
    mpz_fdiv_q(off.get_mpz_t(), num.get_mpz_t(), den.get_mpz_t());
    if (off < 1) off = 1;
    if (off > w - 1) off = w - 1;
    mpz_class M = d.A + off, FM;
    eval_dyadic(FM, f_, M, d.k);
    if (sgn(FM) == 0) {
      exact = dyadic(M, d.k);
      return -1;
    }
    const int sa = sgn(d.FA);
    if (sgn(FM) == sa) {  // the root is in (M, B)
      d.A = M;
      d.FA = FM;
      mpz_class M1 = M + h;
      if (M1 >= d.B) return 1;
      mpz_class F1;
      eval_dyadic(F1, f_, M1, d.k);
      if (sgn(F1) == 0) {
        exact = dyadic(M1, d.k);
        return -1;
      }
      if (sgn(F1) == sa) {
        d.A = M1;
        d.FA = F1;
        return 0;
      }
      d.B = M1;
      d.FB = F1;
      return 1;
    }
    d.B = M;  // the root is in (A, M)
    d.FB = FM;
    mpz_class M1 = M - h;
    if (M1 <= d.A) return 1;
    mpz_class F1;
    eval_dyadic(F1, f_, M1, d.k);
    if (sgn(F1) == 0) {
      exact = dyadic(M1, d.k);
      return -1;
    }
    if (sgn(F1) != sa) {
      d.B = M1;
      d.FB = F1;
      return 0;
    }
    d.A = M1;
    d.FA = F1;
    return 1;
  }

  const IntPoly& f_;
  unsigned long n_;
  int log2n_ = 2;
};

// Is the rational q (lowest terms) a root of the primitive integer f?
bool is_root(const IntPoly& f, const Rational& q);
// true: the integer polynomial z (degree >= 1) is proved square-free (a
// gcd modulo a prime); false proves nothing.
bool certainly_square_free(const IntPoly& z);
// Where the root in the isolating bracket (lo, hi) of f (s_lo: the sign of f
// at lo) lies with respect to the rational c: -1 below, 0 at, 1 above.
int compare_root(const IntPoly& f, const Rational& lo, const Rational& hi, int s_lo, const Rational& c);
// Sign of Q on the closed bracket d when a bound proves it constant there, else 0.
int constant_sign(const IntPoly& Q, const Dyadic& d);

}  // namespace eccd::root_refinement
