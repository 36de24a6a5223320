#pragma once
// QPoly: univariate polynomials with exact rational coefficients, written for
// the certificate checker alone (certificate/check/), sharing no code with
// the provers' polynomial classes.
//
// Statement. Coefficients lowest degree first, always trimmed (the zero
// polynomial has no coefficient). What a checker needs and nothing more:
// ring operations, division with remainder, the monic gcd (Euclid), the value
// at a rational point (Horner; for integer multiples, on integers only),
// Newton interpolation at the integers 0..D, a sign on a bracket by the mean
// value theorem, and two root counts at rational points, each exact:
//   descartes(p, lo, hi)  the sign variations of p after the map of (lo, hi)
//       onto (0, ∞), an upper bound of the number of roots of p in the open
//       interval (lo, hi), counted with multiplicity, and of the same parity;
//       so 0 proves no root and 1 exactly one (a simple one). Computed on
//       integers: scale, shift by lo, scale by hi - lo, reverse, shift by 1.
//   negative_roots(p)     the number of distinct real roots of p in
//       (-∞, 0) by Sturm's theorem (p(0) ≠ 0 required); roots_between(p, a, b)
//       the same in (a, b) (p(a), p(b) ≠ 0).
// Requirements: GMP (gmpxx). Known failure modes: none are rounded; cost is
// quadratic in the degree for the root counts, cubic for interpolation.
#include <gmpxx.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace eccd::check {

struct QPoly {
  std::vector<mpq_class> c;

  QPoly() = default;
  explicit QPoly(std::vector<mpq_class> coeffs) : c(std::move(coeffs)) { trim(); }
  static QPoly constant(const mpq_class& x) { return QPoly(std::vector<mpq_class>{x}); }

  void trim() {
    while (!c.empty() && sgn(c.back()) == 0) c.pop_back();
  }
  bool zero() const { return c.empty(); }
  int degree() const { return int(c.size()) - 1; }  // -1 for the zero polynomial
  const mpq_class& lead() const { return c.back(); }

  mpq_class operator()(const mpq_class& x) const {
    mpq_class v = 0;
    for (std::size_t i = c.size(); i-- > 0;) v = v * x + c[i];
    return v;
  }
};

inline bool operator==(const QPoly& a, const QPoly& b) { return a.c == b.c; }

inline QPoly operator+(const QPoly& a, const QPoly& b) {
  std::vector<mpq_class> r(std::max(a.c.size(), b.c.size()));
  for (std::size_t i = 0; i < a.c.size(); ++i) r[i] += a.c[i];
  for (std::size_t i = 0; i < b.c.size(); ++i) r[i] += b.c[i];
  return QPoly(std::move(r));
}
inline QPoly operator-(const QPoly& a, const QPoly& b) {
  std::vector<mpq_class> r(std::max(a.c.size(), b.c.size()));
  for (std::size_t i = 0; i < a.c.size(); ++i) r[i] += a.c[i];
  for (std::size_t i = 0; i < b.c.size(); ++i) r[i] -= b.c[i];
  return QPoly(std::move(r));
}
inline QPoly operator*(const QPoly& a, const QPoly& b) {
  if (a.zero() || b.zero()) return QPoly();
  std::vector<mpq_class> r(a.c.size() + b.c.size() - 1);
  for (std::size_t i = 0; i < a.c.size(); ++i)
    for (std::size_t j = 0; j < b.c.size(); ++j) r[i + j] += a.c[i] * b.c[j];
  return QPoly(std::move(r));
}
inline QPoly operator*(const mpq_class& k, const QPoly& a) {
  std::vector<mpq_class> r(a.c);
  for (auto& x : r) x *= k;
  return QPoly(std::move(r));
}

// a = q b + r with deg r < deg b (b ≠ 0).
inline void divmod(const QPoly& a, const QPoly& b, QPoly& q, QPoly& r) {
  if (b.zero()) throw std::domain_error("polynomial division by zero");
  r = a;
  q = QPoly();
  if (r.degree() < b.degree()) return;
  std::vector<mpq_class> qc(std::size_t(r.degree() - b.degree() + 1));
  while (!r.zero() && r.degree() >= b.degree()) {
    const int s = r.degree() - b.degree();
    const mpq_class k = r.lead() / b.lead();
    qc[std::size_t(s)] = k;
    for (std::size_t i = 0; i < b.c.size(); ++i) r.c[i + std::size_t(s)] -= k * b.c[i];
    r.c.pop_back();  // the leading term cancels exactly
    r.trim();
  }
  q = QPoly(std::move(qc));
}

inline QPoly derivative(const QPoly& p) {
  std::vector<mpq_class> d;
  for (std::size_t i = 1; i < p.c.size(); ++i) d.push_back(mpq_class(long(i)) * p.c[i]);
  return QPoly(std::move(d));
}

// The monic gcd (zero when both are zero).
inline QPoly gcd(QPoly a, QPoly b) {
  while (!b.zero()) {
    QPoly q, r;
    divmod(a, b, q, r);
    a = std::move(b);
    b = std::move(r);
  }
  if (a.zero()) return a;
  return mpq_class(1 / a.lead()) * a;
}

// The polynomial of degree <= values.size() - 1 through (k, values[k]), k = 0, 1, ... (Newton's divided differences).
inline QPoly interpolate_at_integers(std::vector<mpq_class> d) {
  const std::size_t n = d.size();
  for (std::size_t j = 1; j < n; ++j)
    for (std::size_t i = n - 1; i >= j; --i) {
      d[i] = (d[i] - d[i - 1]) / mpq_class(long(j));
      if (i == j) break;
    }
  // p(x) = d0 + d1 x + d2 x (x - 1) + ...: expand by Horner from the top.
  QPoly p;
  for (std::size_t i = n; i-- > 0;) {
    // p = p * (x - i) + d[i]
    std::vector<mpq_class> r(p.c.size() + 1);
    for (std::size_t k = 0; k < p.c.size(); ++k) {
      r[k + 1] += p.c[k];
      r[k] -= mpq_class(long(i)) * p.c[k];
    }
    r[0] += d[i];
    p = QPoly(std::move(r));
  }
  return p;
}

// A positive integer multiple of p (times the lcm of its denominators), lowest degree first.
inline std::vector<mpz_class> integer_multiple(const QPoly& p, const mpz_class& l) {
  std::vector<mpz_class> z;
  for (const auto& x : p.c) z.push_back(x.get_num() * (l / x.get_den()));
  return z;
}
inline mpz_class denominator_lcm(const QPoly& p, mpz_class l = 1) {
  for (const auto& x : p.c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  return l;
}
// The value of an integer polynomial at an integer (Horner).
// A t that fits a long (the usual case: small evaluation points) is applied in place.
inline mpz_class value_at(const std::vector<mpz_class>& z, const mpz_class& t) {
  mpz_class v = 0;
  if (t.fits_slong_p()) {
    const long s = t.get_si();
    for (std::size_t i = z.size(); i-- > 0;) {
      mpz_mul_si(v.get_mpz_t(), v.get_mpz_t(), s);
      mpz_add(v.get_mpz_t(), v.get_mpz_t(), z[i].get_mpz_t());
    }
    return v;
  }
  for (std::size_t i = z.size(); i-- > 0;) v = v * t + z[i];
  return v;
}

// The sign of p(x) for an integer polynomial p and a rational x = a/b (b > 0):
// the sign of b^n p(a/b), by Horner on integers (no rational arithmetic).
inline int sign_at(const std::vector<mpz_class>& z, const mpq_class& x) {
  if (z.empty()) return 0;
  const mpz_class &a = x.get_num(), &b = x.get_den();
  mpz_class v = z.back(), bp = 1;
  for (std::size_t i = z.size() - 1; i-- > 0;) {
    bp *= b;
    v = v * a + z[i] * bp;
  }
  return sgn(v);
}
// b^n p(a/b) itself (n = z.size() - 1).
inline mpz_class scaled_value_at(const std::vector<mpz_class>& z, const mpq_class& x) {
  if (z.empty()) return 0;
  const mpz_class &a = x.get_num(), &b = x.get_den();
  mpz_class v = z.back(), bp = 1;
  for (std::size_t i = z.size() - 1; i-- > 0;) {
    bp *= b;
    v = v * a + z[i] * bp;
  }
  return v;
}

// A sign of p proved on all of [lo, hi] ⊂ [-1, 1] by the mean value theorem:
// |p(t) - p(lo)| <= (hi - lo) max |p'| <= (hi - lo) Σ k |z_k| there, so if
// |p(lo)| is larger, p keeps the sign of p(lo) on the bracket. Returns that
// sign, or 0 when this cheap test cannot tell (p may vanish, or p(lo) is too
// small: then Descartes decides).
inline int sign_on_bracket(const std::vector<mpz_class>& z, const mpq_class& lo, const mpq_class& hi) {
  if (z.empty() || abs(lo) > 1 || abs(hi) > 1 || hi < lo) return 0;
  const mpz_class v = scaled_value_at(z, lo);  // den(lo)^n p(lo)
  if (sgn(v) == 0) return 0;
  mpz_class slope = 0;  // Σ k |z_k|
  for (std::size_t k = 1; k < z.size(); ++k) slope += mpz_class(abs(z[k])) * (unsigned long)k;
  const mpq_class w = hi - lo;
  mpz_class dn;
  mpz_pow_ui(dn.get_mpz_t(), lo.get_den_mpz_t(), (unsigned long)(z.size() - 1));
  // |v| / dn > w · slope  <=>  |v| · den(w) > dn · num(w) · slope
  return mpz_class(abs(v) * w.get_den()) > mpz_class(dn * w.get_num() * slope) ? sgn(v) : 0;
}

namespace qpoly_impl {
inline void taylor_shift(std::vector<mpz_class>& a, const mpz_class& s) {  // a(x) -> a(x + s)
  const std::size_t n = a.size();
  if (n < 2 || s == 0) return;
  for (std::size_t i = 0; i + 1 < n; ++i)
    for (std::size_t j = n - 1; j-- > i;) a[j] += s * a[j + 1];
}
inline int variations(const std::vector<mpz_class>& a) {
  int v = 0, last = 0;
  for (const auto& x : a) {
    const int s = sgn(x);
    if (s == 0) continue;
    if (last != 0 && s != last) ++v;
    last = s;
  }
  return v;
}
}  // namespace qpoly_impl

// Descartes' bound on the roots of p in the open interval (lo, hi), lo < hi.
inline int descartes(const QPoly& p, const mpq_class& lo, const mpq_class& hi) {
  const int n = p.degree();
  if (n <= 0) return 0;
  if (!(lo < hi)) throw std::domain_error("descartes: empty interval");
  mpz_class l = 1;
  for (const auto& x : p.c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  // x = (A + B y) / D maps y in (0, 1) onto (lo, hi).
  const mpq_class w = hi - lo;
  const mpz_class D = lo.get_den() * w.get_den(), A = lo.get_num() * w.get_den(), B = w.get_num() * lo.get_den();
  std::vector<mpz_class> a(std::size_t(n) + 1);
  mpz_class dp = 1;  // D^(n - i), from i = n down
  for (int i = n; i >= 0; --i) {
    a[std::size_t(i)] = p.c[std::size_t(i)].get_num() * (l / p.c[std::size_t(i)].get_den()) * dp;
    dp *= D;
  }
  // D^n p((z + A) / D) then z = B y: D^n p(lo + w y).
  qpoly_impl::taylor_shift(a, A);
  mpz_class bp = 1;
  for (auto& x : a) {
    x *= bp;
    bp *= B;
  }
  // (1 + y)^n q(1 / (1 + y)): reverse, shift by 1.
  std::vector<mpz_class> r(a.rbegin(), a.rend());
  qpoly_impl::taylor_shift(r, 1);
  return qpoly_impl::variations(r);
}

// Distinct real roots of p in (-∞, 0) by Sturm's theorem; p(0) ≠ 0.
inline int negative_roots(const QPoly& p) {
  if (p.degree() <= 0) return 0;
  if (sgn(p.c[0]) == 0) throw std::domain_error("negative_roots: p(0) = 0");
  std::vector<QPoly> seq{p, derivative(p)};
  while (!seq.back().zero()) {
    QPoly q, r;
    divmod(seq[seq.size() - 2], seq.back(), q, r);
    if (r.zero()) break;
    seq.push_back(mpq_class(-1) * r);
  }
  auto count = [](const std::vector<int>& s) {
    int v = 0, last = 0;
    for (int x : s) {
      if (x == 0) continue;
      if (last != 0 && x != last) ++v;
      last = x;
    }
    return v;
  };
  std::vector<int> at_minus_inf, at_zero;
  for (const auto& q : seq) {
    at_minus_inf.push_back(sgn(q.lead()) * (q.degree() % 2 == 0 ? 1 : -1));
    at_zero.push_back(q.zero() ? 0 : sgn(q.c[0]));
  }
  return count(at_minus_inf) - count(at_zero);
}

// Distinct real roots of p in (a, b) by Sturm's theorem; p(a), p(b) ≠ 0.
inline int roots_between(const QPoly& p, const mpq_class& a, const mpq_class& b) {
  if (p.degree() <= 0) return 0;
  if (sgn(p(a)) == 0 || sgn(p(b)) == 0) throw std::domain_error("roots_between: p vanishes at an end");
  std::vector<QPoly> seq{p, derivative(p)};
  while (true) {
    QPoly q, r;
    divmod(seq[seq.size() - 2], seq.back(), q, r);
    if (r.zero()) break;
    seq.push_back(mpq_class(-1) * r);
  }
  auto var = [&](const mpq_class& x) {
    int v = 0, last = 0;
    for (const auto& q : seq) {
      const int s = sgn(q(x));
      if (s == 0) continue;
      if (last != 0 && s != last) ++v;
      last = s;
    }
    return v;
  };
  return var(a) - var(b);
}

}  // namespace eccd::check
