#pragma once
// Sturm sequences: the number of distinct real roots of p in an interval.
//
// Statement. For square-free or not, p0 = p, p1 = p', p_{k+1} = -rem(p_{k-1}, p_k);
// the number of distinct real roots in (a, b] is V(a) - V(b), V = sign
// changes of the sequence at a point (Sturm's theorem; used by 001 section 3
// for the static test and by the certificate checker).
// With exact T the count is a proof; with rounded T it is an estimate.
// Storage. One implementation (namespace sturm_core) over any vector-like
// storage: std::vector (Poly<T>, any degree) or InlineVector<T, N> (a fixed
// capacity, no heap allocation), which the static test of two ellipsoids uses
// for its quartic (kernel/quartic_status.hpp; 001 section 3 runs a fixed
// Sturm sequence of the quartic: the hot path of the static test in double).
// Inside the core a polynomial is held leading coefficient first (c[0] is the
// coefficient of x^deg), and every loop runs up to the storage's capacity
// with a guard: with a fixed capacity the loops unroll completely and every
// index is a constant, so the compiler keeps the sequence in registers (the
// double static test twice as fast as with indices computed from degrees).
// Both storages run the same operations in the same order, so they give the
// same sequence and the same count.
// Requirements on T: a field (+, -, *, /), scalar_traits<T>.
// Known failure modes: coefficient growth (use it on low degree: cubics and
// quartics in λ, motion denominators), and in rounded arithmetic remainders
// whose leading coefficient should be 0 but is not.
#include "kernel/polynomial.hpp"
#include "kernel/sign_variations.hpp"

#include <algorithm>
#include <climits>
#include <cstddef>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace eccd {

// At most N values of T stored inline (no heap allocation by the container):
// the part of std::vector's interface that the Sturm core uses. Elements are
// constructed when pushed and destroyed when popped, as in std::vector (an
// unused slot holds no object, so an Mpfr or mpq_class costs nothing until
// used); for a trivially copyable T (double) the container is trivially
// copyable too, which lets the compiler keep it in registers.
template <class T, std::size_t N>
class InlineVector {
  static constexpr bool kTrivial = std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>;

 public:
  using value_type = T;
  static constexpr std::size_t inline_capacity = N;

  InlineVector() {}  // NOLINT: the slots stay unconstructed
  InlineVector(const InlineVector&) requires kTrivial = default;
  InlineVector(InlineVector&&) requires kTrivial = default;
  InlineVector& operator=(const InlineVector&) requires kTrivial = default;
  InlineVector& operator=(InlineVector&&) requires kTrivial = default;
  ~InlineVector() requires kTrivial = default;
  InlineVector(const InlineVector& o) {
    for (const T& x : o) push_back(x);
  }
  InlineVector(InlineVector&& o) noexcept {
    for (T& x : o) push_back(std::move(x));
    o.clear();
  }
  InlineVector& operator=(const InlineVector& o) {
    if (this != &o) {
      clear();
      for (const T& x : o) push_back(x);
    }
    return *this;
  }
  InlineVector& operator=(InlineVector&& o) noexcept {
    if (this != &o) {
      clear();
      for (T& x : o) push_back(std::move(x));
      o.clear();
    }
    return *this;
  }
  ~InlineVector() { clear(); }

  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  T* begin() { return a_; }
  const T* begin() const { return a_; }
  T* end() { return a_ + n_; }
  const T* end() const { return a_ + n_; }
  T& operator[](std::size_t i) { return a_[i]; }
  const T& operator[](std::size_t i) const { return a_[i]; }
  T& back() { return a_[n_ - 1]; }
  const T& back() const { return a_[n_ - 1]; }
  template <class U>
  void push_back(U&& x) {
    if (n_ == N) throw std::length_error("InlineVector: capacity exceeded");
    std::construct_at(a_ + n_, std::forward<U>(x));
    ++n_;
  }
  void pop_back() { std::destroy_at(a_ + --n_); }
  void clear() {
    while (n_ > 0) pop_back();
  }

 private:
  union {
    T a_[N];
  };  // slots [0, n_) hold objects
  std::size_t n_ = 0;
};

namespace sturm_core {

// The loop bound of a storage: its capacity if fixed (loops then unroll), else unbounded.
template <class V>
constexpr int bound() {
  if constexpr (requires { V::inline_capacity; })
    return int(V::inline_capacity);
  else
    return INT_MAX;
}

// eccd::is_zero; for double a plain comparison (the same answer: NaN is not zero).
template <class T>
bool is_zero_coeff(const T& x) {
  if constexpr (std::is_floating_point_v<T>)
    return x == T(0);
  else
    return eccd::is_zero(x);
}

// Drop the leading coefficient (c[0]).
template <class V>
void pop_lead(V& c) {
  constexpr int cap = bound<V>();
#pragma GCC unroll 8
  for (int j = 0; j + 1 < cap; ++j) {
    if (j + 1 >= int(c.size())) break;
    c[j] = std::move(c[j + 1]);
  }
  c.pop_back();
}

// Drop leading zeros.
template <class V>
void trim(V& c) {
  constexpr int cap = bound<V>();
#pragma GCC unroll 8
  for (int t = 0; t < cap; ++t) {
    if (c.empty() || !is_zero_coeff(c[0])) break;
    pop_lead(c);
  }
}

// r <- rem(r, b) by long division (b nonzero, trimmed): step k subtracts f b
// x^(deg r - deg b), f = lead(r) / lead(b), and drops r's cancelled lead.
// With q: q receives the quotient (exact T, where b divides r: the division
// by gcd(p, p') below).
template <class V>
void reduce(V& r, const V& b, V* q = nullptr) {
  using T = typename V::value_type;
  const int nb = int(b.size()), nq = int(r.size()) - nb + 1;
  if (q) {
    q->clear();
    for (int k = 0; k < nq; ++k) q->push_back(T(0));
  }
  constexpr int cap = bound<V>();
#pragma GCC unroll 8
  for (int step = 0; step < cap; ++step) {
    if (r.empty() || int(r.size()) < nb) break;
    T f = r[0] / b[0];
    if (q) (*q)[nq - (int(r.size()) - nb + 1)] = f;
#pragma GCC unroll 8
    for (int j = 0; j < cap; ++j) {
      if (j >= nb) break;
      T p = f * b[j];
      r[j] = r[j] - p;
    }
    pop_lead(r);  // cancelled (exactly, with exact T)
    trim(r);
  }
  if (q) trim(*q);
}

// s = {p} (p trimmed, leading coefficient first) on entry; on exit the Sturm
// sequence of p (empty if p is zero). With exact T every element is divided
// by the last one (gcd(p, p')): the sequence of p / gcd then counts distinct
// roots even at an end that is a multiple root.
template <class S>
void build(S& s) {
  using V = typename S::value_type;
  using T = typename V::value_type;
  if (s.empty() || s[0].empty()) {
    s.clear();
    return;
  }
  V d;
  const int n = int(s[0].size());
  constexpr int cap = bound<V>();
#pragma GCC unroll 8
  for (int j = 0; j + 1 < cap; ++j) {  // the coefficient of x^(n-1-j) times n-1-j
    if (j + 1 >= n) break;
    d.push_back(T(n - 1 - j) * s[0][j]);
  }
  trim(d);
  if (d.empty()) return;
  s.push_back(std::move(d));
  constexpr int cap_s = bound<S>();
#pragma GCC unroll 8
  for (int k = 2; k < cap_s; ++k) {
    if (s.back().size() <= 1) break;  // the remainder by a constant is zero
    V r = s[s.size() - 2];
    reduce(r, s.back());
    if (r.empty()) break;
#pragma GCC unroll 8
    for (int j = 0; j < cap; ++j) {
      if (j >= int(r.size())) break;
      r[j] = -r[j];
    }
    s.push_back(std::move(r));
  }
  if constexpr (scalar_traits<T>::is_exact) {
    if (s.back().size() > 1) {
      V g = s.back(), q;
      for (auto& x : s) {
        reduce(x, g, &q);
        x = q;
      }
    }
  }
}

// The sign of c at x (Horner from the leading coefficient, as Poly<T>::operator());
// x == nullopt: at -inf (dir < 0) or +inf.
template <class V, class T>
Sign sign_at(const V& c, const std::optional<T>& x, int dir) {
  if (c.empty()) return Sign::zero;
  if (x) {
    T r = c[0];
    constexpr int cap = bound<V>();
#pragma GCC unroll 8
    for (int j = 1; j < cap; ++j) {
      if (j >= int(c.size())) break;
      r = r * *x;
      r = r + c[j];
    }
    return eccd::sign(r);
  }
  Sign sg = eccd::sign(c[0]);
  if (dir < 0 && (c.size() - 1) % 2 == 1) sg = sg * Sign::negative;
  return sg;
}

// Sign changes of the sequence at x; -1 if a sign is uncertain (kernel/sign_variations.hpp).
template <class S, class T>
int variations(const S& s, const std::optional<T>& x, int dir) {
  SignVariations v = sign_variations_n<bound<S>()>(s.size(), [&](std::size_t k) { return sign_at(s[k], x, dir); });
  return v.uncertain ? -1 : v.count;
}

// Distinct real roots in (a, b] of the polynomial s[0] (s = {p} on entry); see count_roots.
template <class S, class T>
int count(S& s, const std::optional<T>& a, const std::optional<T>& b) {
  build(s);
  if (s.empty()) return -1;
  int va = variations(s, a, -1), vb = variations(s, b, +1);
  if (va < 0 || vb < 0) return -2;
  return va - vb;
}

// Poly<T> (c[i]: coefficient of t^i) <-> the core's order (leading coefficient first).
template <class T>
std::vector<T> lead_first(const Poly<T>& p) {
  return std::vector<T>(p.c.rbegin(), p.c.rend());
}

}  // namespace sturm_core

template <class T>
std::vector<Poly<T>> sturm_sequence(const Poly<T>& p) {
  std::vector<std::vector<T>> s;
  if (!p.is_zero()) s.push_back(sturm_core::lead_first(p));
  sturm_core::build(s);
  std::vector<Poly<T>> out(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) out[i].c.assign(s[i].rbegin(), s[i].rend());
  return out;
}

// Sign changes of the sequence at x; x == nullopt with dir = -1 / +1 means -inf / +inf.
// -1 if a sign is uncertain (interval arithmetic, NaN): then there is no count.
template <class T>
int sturm_variations(const std::vector<Poly<T>>& s, const std::optional<T>& x, int dir = 1) {
  std::vector<std::vector<T>> lf;
  for (const auto& p : s) lf.push_back(sturm_core::lead_first(p));
  return sturm_core::variations(lf, x, dir);
}

// Distinct real roots of p in (a, b]; a or b = nullopt stands for -inf / +inf.
// -1: p is the zero polynomial (every point is a root); -2: a sign along the
// sequence was uncertain, so there is no count (never with exact T).
template <class T>
int count_roots(const Poly<T>& p, const std::optional<T>& a, const std::optional<T>& b) {
  std::vector<std::vector<T>> s;
  if (!p.is_zero()) s.push_back(sturm_core::lead_first(p));
  return sturm_core::count(s, a, b);
}

// The same for the polynomial c[0] + c[1] x + ... of degree below N (zero
// leading coefficients allowed) without heap allocation: the sequence lives
// in InlineVector storage. Throws std::length_error if c has more than N values.
template <std::size_t N, class T>
int count_roots_inline(std::span<const T> c, const std::optional<T>& a, const std::optional<T>& b) {
  if (c.size() > N) throw std::length_error("count_roots_inline: more than N coefficients");
  InlineVector<InlineVector<T, N>, N> s;
  s.push_back(InlineVector<T, N>());
  for (std::size_t i = c.size(); i-- > 0;) s[0].push_back(c[i]);
  sturm_core::trim(s[0]);
  if (s[0].empty()) s.clear();
  return sturm_core::count(s, a, b);
}

// Distinct real roots of p in the closed interval [a, b] (exact T: a proof).
template <class T>
int count_roots_closed(const Poly<T>& p, const T& a, const T& b) {
  int n = count_roots(p, std::optional<T>(a), std::optional<T>(b));
  if (n < 0) return n;
  return n + (eccd::is_zero(p(a)) ? 1 : 0);
}

}  // namespace eccd
