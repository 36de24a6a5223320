#pragma once
// Sturm sequences: the number of distinct real roots of p in an interval.
//
// Statement. For square-free or not, p0 = p, p1 = p', p_{k+1} = -rem(p_{k-1}, p_k);
// the number of distinct real roots in (a, b] is V(a) - V(b), V = sign
// changes of the sequence at a point (Sturm's theorem; used by 001 section 3
// for the static test and by the certificate checker).
// With exact T the count is a proof; with rounded T it is an estimate.
// Requirements on T: a field (+, -, *, /), scalar_traits<T>.
// Known failure modes: coefficient growth (use it on low degree: cubics and
// quartics in λ, motion denominators), and in rounded arithmetic remainders
// whose leading coefficient should be 0 but is not.
#include "kernel/polynomial.hpp"

#include <optional>
#include <vector>

namespace eccd {

template <class T>
std::vector<Poly<T>> sturm_sequence(const Poly<T>& p) {
  std::vector<Poly<T>> s;
  if (p.is_zero()) return s;
  s.push_back(p);
  Poly<T> d = derivative(p);
  if (d.is_zero()) return s;
  s.push_back(d);
  while (true) {
    Poly<T> r = s[s.size() - 2];
    const Poly<T>& b = s.back();
    while (!r.is_zero() && r.degree() >= b.degree()) {
      int k = r.degree() - b.degree();
      T f = r.lead() / b.lead();
      for (int i = 0; i <= b.degree(); ++i) { T q = f * b.c[i]; r.c[i + k] = r.c[i + k] - q; }
      r.c.pop_back();
      r.trim();
    }
    if (r.is_zero()) break;
    s.push_back(-r);
  }
  // With exact T, divide by the last element (gcd(p, p')): the sequence of
  // p / gcd then counts distinct roots even at an end that is a multiple root.
  if constexpr (scalar_traits<T>::is_exact) {
    if (s.back().degree() > 0) {
      Poly<T> g = s.back();
      for (auto& x : s) { Poly<T> q, rem; divide(x, g, q, rem); x = q; }
    }
  }
  return s;
}

// Sign changes of the sequence at x; x == nullopt with dir = -1 / +1 means -inf / +inf.
// -1 if a sign is uncertain (interval arithmetic, NaN): then there is no count.
template <class T>
int sturm_variations(const std::vector<Poly<T>>& s, const std::optional<T>& x, int dir = 1) {
  int v = 0;
  Sign last = Sign::zero;
  for (const auto& p : s) {
    Sign sg;
    if (x) {
      sg = eccd::sign(p(*x));
    } else {
      sg = eccd::sign(p.lead());
      if (dir < 0 && p.degree() % 2 == 1) sg = sg * Sign::negative;
    }
    if (sg == Sign::uncertain) return -1;
    if (sg == Sign::zero) continue;
    if (last != Sign::zero && sg != last) ++v;
    last = sg;
  }
  return v;
}

// Distinct real roots of p in (a, b]; a or b = nullopt stands for -inf / +inf.
// -1: p is the zero polynomial (every point is a root); -2: a sign along the
// sequence was uncertain, so there is no count (never with exact T).
template <class T>
int count_roots(const Poly<T>& p, const std::optional<T>& a, const std::optional<T>& b) {
  auto s = sturm_sequence(p);
  if (s.empty()) return -1;
  int va = sturm_variations(s, a, -1), vb = sturm_variations(s, b, +1);
  if (va < 0 || vb < 0) return -2;
  return va - vb;
}

// Distinct real roots of p in the closed interval [a, b] (exact T: a proof).
template <class T>
int count_roots_closed(const Poly<T>& p, const T& a, const T& b) {
  int n = count_roots(p, std::optional<T>(a), std::optional<T>(b));
  if (n < 0) return n;
  return n + (eccd::is_zero(p(a)) ? 1 : 0);
}

}  // namespace eccd
