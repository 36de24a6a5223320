// Real roots of rational polynomials behind exact/algebraic_roots.hpp (the
// only CGAL translation unit of the workbench: CGAL is header heavy).
//
// CGAL's Algebraic_kernel_d_1 over CORE::BigInt does the isolation of every
// real root (solve_1) when the range is not [0, 1]; the square-free
// factorisation and the polynomial gcds are FLINT's (exact/flint_poly.hpp,
// issue 21: CGAL's modular gcd was a fifth of the exact pipelines). CORE is
// header-only in CGAL 5.5 (Debian libcgal-dev) and enabled by CGAL itself when
// GMP and MPFR are there (CGAL_USE_CORE); nothing else to link. Everything
// after isolation is done here on the isolating intervals, in integer
// arithmetic: refinement by quadratic interval refinement (QIR, Abbott 2006:
// secant steps snapped to a dyadic grid, bisection after a failed step) with
// exact signs of the square-free factor at dyadic points, comparisons with
// the ends of the range, and signs of other polynomials at the roots (a
// mean-value bound first, a gcd for the zero case, refinement otherwise).
// CGAL's own refinement and Sign_at_1 evaluate at rationals in rational
// arithmetic (a gcd per operation): with refinement of every root to 2^-64
// that was two thirds of the exact 2D pipeline before (issue 6).
//
// Bounded (issue 15): every refinement loop asks the running thread's deadline
// (kernel/budget.hpp: BudgetExhausted when it passed). CGAL's modular gcd has
// 2000 primes of about 26 bits; a gcd that needs more loops forever printing
// "primes in the array exhausted" to std::cerr. Every call into CGAL is made
// under CgalGuard: polynomials with coefficients beyond kMaxCgalBits are
// refused up front (BudgetExhausted), CGAL's std::cerr output is captured (it
// never reaches the user), and that message ends the call with BudgetExhausted.
#include "exact/algebraic_roots.hpp"
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
using AK = CGAL::Algebraic_kernel_d_1<CORE::BigInt>;  // CORE's BigInt and BigRat (GMP inside)
using AKPoly = AK::Polynomial_1;
using AKReal = AK::Algebraic_real_1;
using PT = CGAL::Polynomial_traits_d<AKPoly>;
using IntPoly = std::vector<mpz_class>;  // lowest degree first, nonzero leading coefficient

constexpr unsigned long kMaxLevel = 1ul << 20;  // refinement limit (bits of a bracket's ends): a bug guard

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
// so what is refused did not change with them (issue 21).
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

// out = 2^(k·n) f(a / 2^k), n = deg f: the exact value, up to a positive factor.
void eval_dyadic(mpz_class& out, const IntPoly& f, const mpz_class& a, unsigned long k) {
  static thread_local mpz_class t;
  const int n = int(f.size()) - 1;
  mpz_set(out.get_mpz_t(), f[n].get_mpz_t());
  for (int i = n - 1; i >= 0; --i) {
    mpz_mul(out.get_mpz_t(), out.get_mpz_t(), a.get_mpz_t());
    if (mpz_sgn(f[i].get_mpz_t()) == 0) continue;
    mpz_mul_2exp(t.get_mpz_t(), f[i].get_mpz_t(), k * static_cast<unsigned long>(n - i));
    mpz_add(out.get_mpz_t(), out.get_mpz_t(), t.get_mpz_t());
  }
}

// The exact sign of f at the rational x (den^n f(num / den) by Horner).
int sign_at_rational(const IntPoly& f, const Rational& x) {
  const int n = int(f.size()) - 1;
  if (n < 0) return 0;
  mpz_class s = f[n], pw = 1, t;
  for (int i = n - 1; i >= 0; --i) {
    pw *= x.get_den();
    s *= x.get_num();
    mpz_mul(t.get_mpz_t(), f[i].get_mpz_t(), pw.get_mpz_t());
    s += t;
  }
  return sgn(s);
}

// x = a / 2^j (lowest terms) when x's denominator is a power of two.
bool dyadic_parts(const Rational& x, mpz_class& a, unsigned long& j) {
  if (mpz_popcount(x.get_den_mpz_t()) != 1) return false;
  j = mpz_scan1(x.get_den_mpz_t(), 0);
  a = x.get_num();
  return true;
}

Rational dyadic(const mpz_class& a, unsigned long k) {
  Rational r(a);
  mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), k);
  return r;
}

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

// Is the rational q (lowest terms) a root of the primitive integer f? By the
// rational root theorem only if its denominator divides the leading and its
// numerator the constant coefficient; only then is f evaluated.
bool is_root(const IntPoly& f, const Rational& q) {
  if (sgn(q) == 0) return sgn(f[0]) == 0;
  if (!mpz_divisible_p(f.back().get_mpz_t(), q.get_den_mpz_t())) return false;
  if (!mpz_divisible_p(f[0].get_mpz_t(), q.get_num_mpz_t())) return false;
  return sign_at_rational(f, q) == 0;
}

// A certificate that the integer polynomial z (degree >= 1) is square-free:
// gcd(z mod q, z' mod q) = 1 for a prime q not dividing lc(z). If z had a
// square factor h² (deg h >= 1, h primitive), h would divide z and z' over
// Z; lc(h) divides lc(z), so h mod q keeps its degree and divides both
// reductions, whose gcd would then have degree >= 1. So a constant gcd mod q
// proves z square-free; a non-constant one proves nothing (q may be unlucky),
// and the caller falls back to FLINT's square-free factorisation (further
// primes only when q divides lc(z) or z'). Arithmetic mod q < 2^62 in unsigned 128-bit products.
bool certainly_square_free(const IntPoly& z) {
  using u64 = unsigned long long;
  using u128 = unsigned __int128;
  const int n = int(z.size()) - 1;
  if (n < 1) return false;
  for (u64 q : {4611686018427387847ull, 4611686018427387817ull, 4611686018427387787ull}) {
    auto mod = [q](const mpz_class& x) { return u64(mpz_fdiv_ui(x.get_mpz_t(), static_cast<unsigned long>(q))); };
    auto mul = [q](u64 x, u64 y) { return u64(u128(x) * y % q); };
    auto inv = [&](u64 x) {  // x^(q-2) mod q
      u64 r = 1, e = q - 2;
      for (; e; e >>= 1, x = mul(x, x))
        if (e & 1) r = mul(r, x);
      return r;
    };
    std::vector<u64> a(n + 1), b(n);
    for (int i = 0; i <= n; ++i) a[i] = mod(z[i]);
    if (a[n] == 0) continue;
    for (int i = 1; i <= n; ++i) b[i - 1] = mul(a[i], u64(i) % q);
    auto trim = [](std::vector<u64>& v) {
      while (!v.empty() && v.back() == 0) v.pop_back();
    };
    trim(b);
    if (b.empty()) continue;
    // Euclid: a <- a mod b, swap, until b = 0; deg gcd = deg a at the end.
    while (!b.empty()) {
      const u64 li = inv(b.back());
      while (a.size() >= b.size()) {
        const u64 f = mul(a.back(), li);
        const std::size_t k = a.size() - b.size();
        for (std::size_t i = 0; i < b.size(); ++i) a[i + k] = (a[i + k] + q - mul(f, b[i])) % q;
        a.pop_back();  // cancelled exactly
        trim(a);
        if (a.empty()) break;
      }
      a.swap(b);
    }
    // A non-zero constant: square-free. Otherwise z is almost surely not
    // square-free (q would have to divide its discriminant): FLINT's
    // factorisation decides at once instead of two more primes (issue 21).
    return a.size() == 1;
  }
  return false;
}

// Where the root in the isolating bracket (lo, hi) of f (s_lo: the sign of f
// at lo) lies with respect to the rational c: -1 below, 0 at, 1 above.
int compare_root(const IntPoly& f, const Rational& lo, const Rational& hi, int s_lo, const Rational& c) {
  if (c <= lo) return 1;
  if (c >= hi) return -1;
  int s = sign_at_rational(f, c);
  if (s == 0) return 0;
  return s == s_lo ? 1 : -1;
}

// Sign of Q on the closed interval [A, B] / 2^k when a bound proves it
// constant there, else 0 (unknown). With m the midpoint, r the half-width and
// x in the interval, Taylor at m with Lagrange's remainder:
//   |Q(x) - Q(m)| <= sum_{j=1}^{J-1} |Q^(j)(m) / j!| r^j + r^J max |Q^(J) / J!|,
//   max |Q^(J)(ξ) / J!| <= N_J = sum_i C(i, J) |c_i| 2^(e (i - J))
// over |ξ| <= 2^e, e >= 0 with max(|lo|, |hi|) <= 2^e. J = 1 (the mean-value
// bound: one evaluation) is tried first; then J up to 8, which does not suffer
// from the power basis' cancellation (N_J is multiplied by r^J; the first
// terms are the exact local derivatives). In integers, at level s = k + 1,
// M = A + B, R = B - A, b_j = 2^(s(n-j)) Q^(j)(m) / j!:
//   |b_0| > sum_{j=1}^{J-1} |b_j| R^j + R^J 2^(s(n-J)) N_J.
int constant_sign(const IntPoly& Q, const Dyadic& d) {
  const int n = int(Q.size()) - 1;
  const unsigned long s = d.k + 1;
  const mpz_class& mx = mpz_cmpabs(d.A.get_mpz_t(), d.B.get_mpz_t()) >= 0 ? d.A : d.B;
  long e = long(mpz_sizeinbase(mx.get_mpz_t(), 2)) - long(d.k);  // |x| < 2^e on the interval
  if (e < 0) e = 0;
  const mpz_class M = d.A + d.B, R = d.B - d.A;
  const int J = std::min(n, 8);
  // N_j for j <= J: Taylor coefficients of sum |c_i| x^i at x = 2^e (Horner's
  // scheme for derivatives); b_j likewise for the scaled polynomial at M.
  std::vector<mpz_class> N(J + 1), b(J + 1);
  auto taylor_of_abs = [&](int jmax) {  // N_0..N_jmax
    for (auto& x : N) x = 0;
    N[0] = abs(Q[n]);
    for (int i = n - 1; i >= 0; --i) {
      for (int j = std::min(jmax, n - i); j >= 1; --j) {
        N[j] <<= static_cast<unsigned long>(e);
        N[j] += N[j - 1];
      }
      N[0] <<= static_cast<unsigned long>(e);
      N[0] += abs(Q[i]);
    }
  };
  mpz_class t;
  // J = 1 first: b_0 alone
  taylor_of_abs(1);
  eval_dyadic(b[0], Q, M, s);
  mpz_class rhs = R * N[1];
  rhs <<= s * static_cast<unsigned long>(n - 1);
  if (mpz_cmpabs(b[0].get_mpz_t(), rhs.get_mpz_t()) > 0) return sgn(b[0]);
  if (J < 2) return 0;
  taylor_of_abs(J);
  b[0] = Q[n];
  for (int i = n - 1; i >= 0; --i) {
    for (int j = std::min(J - 1, n - i); j >= 1; --j) {
      b[j] *= M;
      b[j] += b[j - 1];
    }
    b[0] *= M;
    mpz_mul_2exp(t.get_mpz_t(), Q[i].get_mpz_t(), s * static_cast<unsigned long>(n - i));
    b[0] += t;
  }
  // rhs for J: sum_{j<J} |b_j| R^j + R^J 2^(s(n-J)) N_J, by increasing J
  mpz_class sum = 0, Rj = 1;
  for (int j = 1; j <= J; ++j) {
    Rj *= R;  // R^j
    rhs = Rj * N[j];
    rhs <<= s * static_cast<unsigned long>(n - j);
    rhs += sum;
    if (mpz_cmpabs(b[0].get_mpz_t(), rhs.get_mpz_t()) > 0) return sgn(b[0]);
    if (j < J) {
      t = abs(b[j]);
      t *= Rj;
      sum += t;
    }
  }
  return 0;
}

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
