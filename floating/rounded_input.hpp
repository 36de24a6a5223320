#pragma once
// The floating pipelines' default start (input mode "rounded"): each number of
// the scene rounded to the arithmetic, everything after computed in it.
//
// Statement (input mode `rounded`, api/options.hpp). A user's program holds the scene's numbers
// as doubles (or MPFR values) and computes the motion matrices, their
// inverses, A(t), f and Δ in that arithmetic. round_pair does the same: each
// entry of the shape matrix Q and each coefficient of each motion polynomial
// (quaternion, translation, its denominator, matrix entries, kinematic d_i) is
// rounded once to T (scalar_traits<T>::from_rational: nearest double, or MPFR
// at the run's precision), and N(t) is formed in T by the same templated code
// as the exact pipeline (kernel/motion.hpp: for euler motions the rotation's
// inverse is its transpose, for matrix motions the adjugate, for kinematic
// motions 003 eq. (3)). What differs from the "prepared" start
// (kernel/prepared_scene.hpp):
//   - no exact polynomial gcd of N's entries is removed (there is none in
//     rounded arithmetic): a matrix motion keeps the adjugate's factor w, so
//     Δ of 003 Example 2 has degree 192 here, not the paper's 96;
//   - no rational content is removed and nothing is scaled to integers;
//     instead each stage is scaled by a power of two (number/pow2_scaling.hpp):
//     each Q, each N(t), and the pencil is balanced by 2^-k on B's Q, k the
//     nearest integer to the mean of (log2|det B(t)| - log2|det A(t)|)/N over
//     t = 0, 1/2, 1 computed in T (the same rule as prepared mode, which
//     computes it exactly);
//   - a semi-axis a enters as the rounded 1/a² of the scene reader's exact Q
//     (within one rounding of what a user computes from a rounded a).
// In Bernstein form (round_pair_bernstein) N(t) is converted to Bernstein
// form in T (the prepared start converts exactly and then rounds).
// A non-finite value at any of these stages is reported in `trouble`, and the
// caller answers undecided on [0, 1] with that reason.
// Requirements on T: double or Mpfr (number/pow2_scaling.hpp), division.
#include "number/pow2_scaling.hpp"
#include "number/running_error.hpp"
#include "kernel/bernstein.hpp"
#include "kernel/motion.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/ring_determinant.hpp"
#include "kernel/scene.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace eccd {

// The scene's pair rounded to T and prepared in T. trouble: "" or why a stage
// is not finite.
template <class T, int H>
MovingPair<T, H> round_pair(const Scene& s, const T& like, std::string& trouble) {
  if (s.dim + 1 != H) throw std::invalid_argument("scene dimension does not match the pipeline");
  refuse_independent(s);  // kernel/prepared_scene.hpp
  auto conv = [&](const Rational& q) { return scalar_traits<T>::from_rational(q, like); };
  MovingPair<T, H> m;
  trouble.clear();
  auto shape = [&](const SceneObject& o, Matrix<T, H>& q, const char* name) {
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) q[i][j] = conv(o.Q.at(i).at(j));
    if (!normalise_pow2<T>([&](auto f) {
          for (auto& row : q)
            for (auto& x : row) f(x);
        }) &&
        trouble.empty())
      trouble = std::string("non-finite value in the shape matrix of object ") + name;
  };
  auto motion = [&](const SceneObject& o, PolyMatrix<T, H>& n, const char* name) {
    n = motion_inverse<T, H>(o.motion, conv);
    bool ok = normalise_pow2<T>([&](auto f) {
      for (auto& row : n)
        for (auto& e : row)
          for (auto& c : e.c) f(c);
    });
    if (!ok && trouble.empty()) trouble = std::string("overflow in the motion inverse N(t) of object ") + name;
  };
  shape(s.a, m.qa, "a");
  shape(s.b, m.qb, "b");
  motion(s.a, m.na, "a");
  motion(s.b, m.nb, "b");
  if (!trouble.empty()) return m;
  // Balance the pencil (see the header prose). Only the values' exponents are read: with a running error
  // bound (the guarded face) on the values alone, by the same operations, so k is the as-published run's.
  using V = std::decay_t<decltype(value_only(std::declval<const T&>()))>;
  auto values = [](const Matrix<T, H>& q, const PolyMatrix<T, H>& n) {
    std::pair<Matrix<V, H>, PolyMatrix<V, H>> out;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        out.first[i][j] = value_only(q[i][j]);
        for (const auto& c : n[i][j].c) out.second[i][j].c.push_back(value_only(c));
      }
    return out;
  };
  const auto [qa, na] = values(m.qa, m.na);
  const auto [qb, nb] = values(m.qb, m.nb);
  double sum = 0;
  int used = 0;
  for (const mpq_class& tq : {mpq_class(0), mpq_class(1, 2), mpq_class(1)}) {
    V t = value_only(conv(tq));
    V da = field_det<V, H>(quadric_at<V, H>(qa, na, t));
    V db = field_det<V, H>(quadric_at<V, H>(qb, nb, t));
    long ea = binary_exponent(da), eb = binary_exponent(db);
    if (ea == LONG_MIN || eb == LONG_MIN) continue;
    sum += double(eb - ea);
    ++used;
  }
  if (used) {
    long k = std::lround(sum / (used * H));
    if (k != 0)
      for (auto& row : m.qb)
        for (auto& x : row) x = times_pow2(x, -k);
  }
  return m;
}

// The same with N(t) in Bernstein form, converted in T.
template <class T, int H>
MovingPairBern<T, H> to_bernstein_pair(const MovingPair<T, H>& m) {
  const T& like = m.qa[0][0];
  auto bern = [&](const Poly<T>& e) {
    if (e.is_zero()) {
      Bern<T> r;
      r.b.push_back(scalar_traits<T>::from_rational(mpq_class(0), like));
      return r;
    }
    return to_bernstein(e, std::max(e.degree(), 0));
  };
  MovingPairBern<T, H> out;
  out.qa = m.qa;
  out.qb = m.qb;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      out.na[i][j] = bern(m.na[i][j]);
      out.nb[i][j] = bern(m.nb[i][j]);
    }
  return out;
}

// g_0..g_N in Bernstein form from a pair already in T (the rounded start):
// every product in Bernstein form, or in power form with each g_k converted
// at the end (the same two set-ups as characteristic_bernstein).
template <class T, int H>
std::vector<Bern<T>> characteristic_bernstein_of(const MovingPair<T, H>& m, bool power_products) {
  if (!power_products) return characteristic_of(to_bernstein_pair<T, H>(m));
  const T& like = m.qa[0][0];
  std::vector<Bern<T>> out;
  for (const auto& gi : characteristic_of(m)) {
    Bern<T> b = to_bernstein(gi, std::max(gi.degree(), 0));
    if (gi.is_zero()) b.b.assign(1, scalar_traits<T>::from_rational(mpq_class(0), like));
    out.push_back(b);
  }
  return out;
}

// Scales g_0..g_N (Bernstein form) by one power of two; false if a value is not finite.
template <class T>
bool normalise_coefficients(std::vector<Bern<T>>& g) {
  return normalise_pow2<T>([&](auto f) {
    for (auto& gi : g)
      for (auto& x : gi.b) f(x);
  });
}
template <class T>
bool normalise_coefficients(std::vector<Poly<T>>& g) {
  return normalise_pow2<T>([&](auto f) {
    for (auto& gi : g)
      for (auto& x : gi.c) f(x);
  });
}

}  // namespace eccd
