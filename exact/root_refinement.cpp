// Exact refinement of real roots on dyadic brackets (see exact/root_refinement.hpp):
// the signs, tests and bounds the Refiner and exact/algebraic_roots.cpp use.
#include "exact/root_refinement.hpp"

namespace eccd::root_refinement {

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
  __extension__ typedef unsigned __int128 u128;  // GCC and Clang; __extension__: not ISO C++ (-Wpedantic)
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
    // factorisation decides at once instead of two more primes.
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

}  // namespace eccd::root_refinement
