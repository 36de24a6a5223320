#pragma once
// The peak of a univariate Bernstein polynomial on [0, 1]: the larger of its
// end values and its values at the roots of its derivative (001 section 4's
// static test reads the sign of max_u F(u, t0)). The u found is a witness,
// not a decision (see below).
// Requirements on U: scalar_traits<U>, PlainOf<U> (number/running_error.hpp),
// ring operations, comparison.
#include "floating/bernstein_roots.hpp"
#include "kernel/bernstein.hpp"
#include "number/running_error.hpp"

#include <algorithm>

namespace eccd {

// argmax of a univariate Bernstein polynomial on [0, 1] by the roots of its
// derivative (rounded arithmetic), with the value there.
//
// The peak's u is a witness, not a decision (any u with F(u, t0) > 0 proves
// separation; the value is then computed, with its bound, at that u): it is
// located in the plain arithmetic under a running bound (Bounded<V>: V), and
// only to 2^-(bits/2 + 6) of its piece. Near a simple maximum u* of f,
// f(u) = f(u*) - O(|f''| (u - u*)^2), so a witness that close gives the peak's
// value to within |f''| 2^-(bits + 12), below the rounding of its evaluation
// (n(n-1) = 12 for the quartic F(., t0)); refining further (to 2^-50 at
// every static test and shot) changes nothing but the last
// bits of u and costs a third of a 3D query. Clusters (a multiple
// root of f', an inflection) are still found at the full precision.
template <class U>
struct Peak {
  U u, value;
};

// u0, u1: 0 and 1 at the precision of f's coefficients.
template <class U>
Peak<U> bern_argmax(const Bern<U>& f, int bits, const U& u0, const U& u1) {
  using P = PlainOf<U>;
  using V = typename P::type;
  Peak<U> best{u0, f(u0)};
  U v1 = f(u1);
  if (v1 > best.value) best = {u1, v1};
  Bern<V> df;  // f' in V: the same values as f' in U (a running bound only adds a bound)
  const int n = f.degree();
  df.b.reserve(std::max(n, 1));
  if (n <= 0) df.b.push_back(V(0));
  for (int i = 0; i < n; ++i) {
    V diff = P::of(f.b[i + 1]) - P::of(f.b[i]);
    df.b.push_back(V(n) * diff);
  }
  BernsteinRootOptions<V> ro;
  ro.precision_bits = bits;
  ro.simple_bits = std::min(bits, bits / 2 + 6);
  for (const auto& r : bernstein_roots(df, ro)) {
    U u = P::lift(r.value);
    U v = f(u);
    if (v > best.value) best = {u, v};
  }
  return best;
}
template <class U>
Peak<U> bern_argmax(const Bern<U>& f, int bits) {
  const U& like = f.b.front();
  return bern_argmax(f, bits, scalar_traits<U>::from_rational(mpq_class(0), like),
                     scalar_traits<U>::from_rational(mpq_class(1), like));
}

}  // namespace eccd
