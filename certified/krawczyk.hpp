#pragma once
// Krawczyk's test and the interval nets it runs on, shared by the proofs of
// interval ends in certified mode: independent motions F(u, s, t)
// (certified/independent_proof.hpp) and the shared-parameter Bézier proof
// F(u, t) (certified/bezier_proof.cpp, as a net of degree 0 in s).
//
// Statement. Krawczyk 1969; Moore, Kearfott, Cloud, "Introduction to Interval
// Analysis", 2009, section 8.2: for a square system f on a box X, a point x~ in
// X and any matrix Y, K(X) = x~ - Y f(x~) + (I - Y J(X))(X - x~) (J(X) an
// enclosure of the Jacobian on X) inside the interior of X proves that X holds
// exactly one zero of f, and every zero in X lies in K(X) (so X ∩ K(X) keeps
// it). The equations are partial derivatives of F (orders in u, s, t) taken
// from F's tensor Bernstein net enclosed in MPFI intervals (outward rounding,
// `bits` bits): every evaluation encloses the exact value. Double is used
// only to propose points (Newton) and for Y (any value is sound there).
// The nets and the test are templated on the interval type (NetsT<IT>, IT =
// MpfiInterval or Interval: intervals of doubles, widened outwards): the same
// test on an enclosure of the same net is the same proof, only cheaper and
// with wider brackets in doubles.
// restrict_axis encloses the net restricted to a rational range of one axis.
// Requirements: TriBern<MpfiInterval> (kernel/trivariate_bernstein.hpp).
#include "kernel/trivariate_bernstein.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"
#include "number/rational_traits.hpp"

#include <gmpxx.h>
#include <mpfi.h>
#include <mpfr.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eccd {
// The pieces of the method, public: the Bézier proof (certified/bezier_proof.cpp),
// the independent-motion proofs and the certificate writers (certificate/write/) use them.
namespace krawczyk_method {

using I = MpfiInterval;

inline mpq_class lower(const I& x) {
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), &x.get()->left);
  return q;
}
inline mpq_class upper(const I& x) {
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), &x.get()->right);
  return q;
}
inline bool finite(const I& x) {
  return !mpfi_nan_p(x.get()) && mpfr_number_p(&x.get()->left) && mpfr_number_p(&x.get()->right);
}
inline mpq_class exact_of(double d) { return mpq_class(d); }  // a double is an exact rational
// The same for intervals of doubles (number/interval.hpp): its end points are doubles, exact rationals.
inline mpq_class lower(const Interval& x) { return mpq_class(x.lo); }
inline mpq_class upper(const Interval& x) { return mpq_class(x.hi); }
inline bool finite(const Interval& x) { return std::isfinite(x.lo) && std::isfinite(x.hi); }

// Enclosures of rationals in an interval type (MPFI at `bits`, or doubles rounded outwards).
template <class IT>
struct Enclose;
template <>
struct Enclose<MpfiInterval> {
  static MpfiInterval point(const mpq_class& q, int bits) { return MpfiInterval(q, bits); }
  static MpfiInterval hull(const mpq_class& a, const mpq_class& b, int bits) { return MpfiInterval(a, b, bits); }
};
template <>
struct Enclose<Interval> {
  static Interval point(const mpq_class& q, int) { return interval_of(q); }
  static Interval hull(const mpq_class& a, const mpq_class& b, int) {
    return Interval(interval_of(a).lo, interval_of(b).hi);
  }
};

// The derivative of a tensor Bernstein net along `axis` (degree one lower there; a constant gives 0).
template <class T>
TriBern<T> derivative(const TriBern<T>& f, int axis, const T& zero) {
  TriBern<T> r;
  r.n = f.n;
  const int n = f.n[axis];
  r.n[axis] = std::max(n - 1, 0);
  r.c.assign(std::size_t(r.n[0] + 1) * (r.n[1] + 1) * (r.n[2] + 1), zero);
  if (n == 0) return r;
  for (int i = 0; i <= r.n[0]; ++i)
    for (int j = 0; j <= r.n[1]; ++j)
      for (int k = 0; k <= r.n[2]; ++k) {
        std::array<int, 3> a{i, j, k}, b{i, j, k};
        ++b[axis];
        T d = f.at(b[0], b[1], b[2]) - f.at(a[0], a[1], a[2]);
        r.at(i, j, k) = T(n) * d;
      }
  return r;
}

// The net restricted to [a, b] along `axis` (rationals, 0 <= a < b <= 1), reparameterised to [0, 1]:
// de Casteljau at a (keep the right part), then at (b - a)/(1 - a) (keep the left part), in intervals.
inline TriBern<I> restrict_axis(const TriBern<I>& f, int axis, const mpq_class& a, const mpq_class& b, int bits) {
  TriBern<I> r = f;
  const std::size_t st = f.stride(axis), len = std::size_t(f.n[axis]) + 1;
  std::vector<I> line(len);
  const I ta(a, bits);
  const bool cut_right = b < 1;
  const I tb(cut_right ? mpq_class((b - a) / (1 - a)) : mpq_class(1), bits);
  for (std::size_t base = 0; base < f.c.size(); ++base) {
    if ((base / st) % len != 0) continue;
    for (std::size_t m = 0; m < len; ++m) line[m] = f.c[base + m * st];
    if (sgn(a) != 0) keep_right(std::span<I>(line), ta);
    if (cut_right) keep_left(std::span<I>(line), tb);
    for (std::size_t m = 0; m < len; ++m) r.c[base + m * st] = line[m];
  }
  return r;
}

// The nets of F and its partial derivatives (orders (a, b, c) in u, s, t), in intervals IT (MPFI or
// doubles) and (mid-points) in double.
template <class IT>
class NetsT {
  using I = IT;

 public:
  NetsT(const TriBern<I>& F, int bits) : bits_(bits), zero_(Enclose<I>::point(mpq_class(0), bits)) {
    nets_[{0, 0, 0}] = F;
  }
  const TriBern<I>& get(std::array<int, 3> o) {
    auto it = nets_.find(o);
    if (it != nets_.end()) return it->second;
    for (int ax = 0; ax < 3; ++ax)
      if (o[ax] > 0) {
        std::array<int, 3> p = o;
        --p[ax];
        TriBern<I> d = derivative(get(p), ax, zero_);
        return nets_.emplace(o, std::move(d)).first->second;
      }
    return nets_.at({0, 0, 0});
  }
  const TriBern<double>& mid(std::array<int, 3> o) {
    auto it = mids_.find(o);
    if (it != mids_.end()) return it->second;
    const TriBern<I>& f = get(o);
    TriBern<double> d;
    d.n = f.n;
    for (const auto& x : f.c) d.c.push_back(x.mid());
    return mids_.emplace(o, std::move(d)).first->second;
  }
  I eval(std::array<int, 3> o, const std::array<I, 3>& x) { return get(o)(x[0], x[1], x[2]); }
  double eval_mid(std::array<int, 3> o, const std::array<double, 3>& x) { return mid(o)(x[0], x[1], x[2]); }
  int bits() const { return bits_; }

 private:
  int bits_;
  I zero_;
  std::map<std::array<int, 3>, TriBern<I>> nets_;
  std::map<std::array<int, 3>, TriBern<double>> mids_;
};
using Nets = NetsT<MpfiInterval>;

// A square system: equations are partial derivatives of F (orders), unknowns a subset of (u, s, t);
// the other coordinate (t for an end on t = t_b) is fixed.
struct System {
  std::vector<std::array<int, 3>> eqs;
  std::vector<int> vars;
  std::optional<mpq_class> fixed_t;
  std::string kind;
};

inline std::array<int, 3> plus(std::array<int, 3> o, int ax) {
  ++o[ax];
  return o;
}

// Solve the m x m system a x = b in double by Gaussian elimination with partial pivoting; false if singular.
inline bool solve_small(std::vector<std::vector<double>> a, std::vector<double>& b) {
  const std::size_t m = b.size();
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
    if (!(std::fabs(a[p][c]) > 0) || !std::isfinite(a[p][c])) return false;
    std::swap(a[p], a[c]);
    std::swap(b[p], b[c]);
    for (std::size_t r = 0; r < m; ++r) {
      if (r == c) continue;
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < m; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = 0; c < m; ++c) b[c] /= a[c][c];
  return true;
}

// Newton's method in double (only proposes a point).
template <class IT>
std::optional<std::array<double, 3>> newton(NetsT<IT>& nets, const System& sys, std::array<double, 3> x) {
  const std::size_t m = sys.vars.size();
  for (int it = 0; it < 60; ++it) {
    std::vector<double> g(m);
    std::vector<std::vector<double>> J(m, std::vector<double>(m));
    for (std::size_t e = 0; e < m; ++e) {
      g[e] = -nets.eval_mid(sys.eqs[e], x);
      for (std::size_t v = 0; v < m; ++v) J[e][v] = nets.eval_mid(plus(sys.eqs[e], sys.vars[v]), x);
    }
    if (!solve_small(J, g)) return std::nullopt;
    double step = 0;
    for (std::size_t v = 0; v < m; ++v) {
      x[sys.vars[v]] += g[v];
      step = std::max(step, std::fabs(g[v]));
    }
    for (double c : x)
      if (!std::isfinite(c) || std::fabs(c) > 4) return std::nullopt;
    if (step < 1e-15) return x;
  }
  return std::nullopt;
}

struct Box {
  std::vector<mpq_class> lo, hi;  // per unknown
};

// One Krawczyk step on box X: K(X) in K; true if K lies in the interior of X.
// I: the interval type of the nets (the namespace's I, MpfiInterval, or another).
template <class I>
bool krawczyk(NetsT<I>& nets, const System& sys, const Box& X, Box& K) {
  using E = Enclose<I>;
  const int bits = nets.bits();
  const std::size_t m = sys.vars.size();
  std::array<I, 3> centre, box;
  std::vector<mpq_class> mid(m);
  for (int ax = 0; ax < 3; ++ax) centre[ax] = box[ax] = E::point(mpq_class(sys.fixed_t.value_or(0)), bits);
  for (std::size_t v = 0; v < m; ++v) {
    mid[v] = (X.lo[v] + X.hi[v]) / 2;
    // a short rational near the mid-point (any point of X is a valid centre)
    centre[sys.vars[v]] = E::point(mid[v], bits);
    box[sys.vars[v]] = E::hull(X.lo[v], X.hi[v], bits);
  }
  std::vector<I> fx;
  std::vector<std::vector<I>> J(m);
  std::vector<std::vector<double>> Jm(m, std::vector<double>(m));
  for (std::size_t e = 0; e < m; ++e) {
    fx.push_back(nets.eval(sys.eqs[e], centre));
    for (std::size_t v = 0; v < m; ++v) {
      J[e].push_back(nets.eval(plus(sys.eqs[e], sys.vars[v]), box));
      if (!finite(J[e][v])) return false;
      Jm[e][v] = J[e][v].mid();
    }
  }
  // Y = inverse of mid J, column by column, in double (any Y is sound)
  std::vector<std::vector<I>> Y(m, std::vector<I>(m));
  for (std::size_t c = 0; c < m; ++c) {
    std::vector<double> col(m, 0.0);
    col[c] = 1;
    if (!solve_small(Jm, col)) return false;
    for (std::size_t r = 0; r < m; ++r) Y[r][c] = E::point(exact_of(col[r]), bits);
  }
  K = Box{std::vector<mpq_class>(m), std::vector<mpq_class>(m)};
  bool inside = true;
  for (std::size_t i = 0; i < m; ++i) {
    I k = centre[sys.vars[i]];
    for (std::size_t j = 0; j < m; ++j) k = k - Y[i][j] * fx[j];
    for (std::size_t j = 0; j < m; ++j) {
      I a(i == j ? 1 : 0);
      for (std::size_t l = 0; l < m; ++l) a = a - Y[i][l] * J[l][j];
      k = k + a * (box[sys.vars[j]] - centre[sys.vars[j]]);
    }
    if (!finite(k)) {
      K = Box{};
      return false;
    }  // no enclosure: K left empty, never half filled
    K.lo[i] = lower(k);
    K.hi[i] = upper(k);
    inside = inside && K.lo[i] > X.lo[i] && K.hi[i] < X.hi[i];
  }
  return inside;
}

}  // namespace krawczyk_method
}  // namespace eccd
