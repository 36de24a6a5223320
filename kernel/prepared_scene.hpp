#pragma once
// PreparedPair<H>: a scene's two objects as exact integer matrices Q and
// polynomial inverse motions N(t), and MovingPair<T, H>: the same rounded to
// the arithmetic T of one pipeline run. H = dim + 1 is the size of the
// homogeneous matrices: PreparedPair2 / MovingPair2<T> for two ellipses
// (H = 3), PreparedPair3 / MovingPair3<T> for two ellipsoids (H = 4).
//
// Statement. The scene is exact (scene-format.md, "Numbers are exact"), so
// the motion inverses N(t) (kernel/motion.hpp) are formed exactly, once, when
// a pipeline is prepared:
//   - the common polynomial factor of N's entries is divided out (exact gcd;
//     it is non-zero on [0, 1] because det M is), which gives the degrees of
//     003 Table I (e.g. Δ of degree 96 for 003 Example 2, not 192);
//   - Q and N are scaled by positive rationals to primitive integer entries.
// Both steps multiply A(t) by a positive function and change no root of
// f(λ;t) (docs/architecture.md, "Use the adjugate"). Every pipeline (double, MPFR, exact) then starts from
// these same coefficients, rounded to its own arithmetic; all later work
// (A(t), f, Δ, roots, decisions) is done in that arithmetic, which is what
// the harness measures. Requirements on T: scalar_traits<T>::from_rational.
//
// Input modes (api/options.hpp, InputMode). This exact preparation is the start of the exact
// and certified pipelines, and of the floating ones in input mode `prepared`.
// No user's program works this way, so the floating pipelines' default is
// `rounded` (floating/rounded_input.hpp): each number of the scene rounded to
// the arithmetic, and N(t), A(t), f, Δ or F(u,t) computed in it, with power-
// of-two scaling instead of the exact gcd and integer scaling (so Δ of 003
// Example 2 has degree 192 there, not 96). Comparing the two modes separates
// the error of rounding the input from the error of the computation.
#include "kernel/bernstein.hpp"
#include "kernel/modular_coprime.hpp"
#include "kernel/motion.hpp"
#include "kernel/quadric.hpp"
#include "kernel/quadric_determinant.hpp"
#include "kernel/ring_determinant.hpp"
#include "kernel/scene.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace eccd {

// Where a floating pipeline starts (see the header prose). Exact arithmetic always starts prepared.
enum class InputMode { rounded, prepared };
inline const char* to_string(InputMode m) { return m == InputMode::rounded ? "rounded" : "prepared"; }
// Throws std::invalid_argument unless s is "rounded" or "prepared" (the
// message names the value; the caller names where it came from).
inline InputMode parse_input_mode(const std::string& s) {
  if (s == "rounded") return InputMode::rounded;
  if (s == "prepared") return InputMode::prepared;
  throw std::invalid_argument(s + ": expected rounded or prepared");
}

// H = dim + 1 (H_2D, H_3D: kernel/scene.hpp); the aliases below name the dimension.
template <int H>
struct PreparedPair {
  Matrix<Rational, H> qa{}, qb{};
  PolyMatrix<Rational, H> na{}, nb{};
};

template <class T, int H>
struct MovingPair {
  Matrix<T, H> qa{}, qb{};
  PolyMatrix<T, H> na{}, nb{};
};

using PreparedPair2 = PreparedPair<H_2D>;  // two ellipses
using PreparedPair3 = PreparedPair<H_3D>;  // two ellipsoids
template <class T>
using MovingPair2 = MovingPair<T, H_2D>;
template <class T>
using MovingPair3 = MovingPair<T, H_3D>;

// Scales a list of rationals (in place, by one positive factor) to coprime integers.
inline void make_primitive(std::vector<Rational*> xs) {
  mpz_class l = 1, g = 0;
  for (auto* x : xs) {
    x->canonicalize();
    mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x->get_den_mpz_t());
  }
  for (auto* x : xs) {
    mpz_class n = x->get_num() * (l / x->get_den());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), n.get_mpz_t());
  }
  if (g == 0) return;
  // x · l / g is the integer num(x) · (l / den(x)) / g (exact divisions): the same value, no rational gcds
  for (auto* x : xs) {
    mpz_class n = x->get_num() * (l / x->get_den());
    mpz_divexact(n.get_mpz_t(), n.get_mpz_t(), g.get_mpz_t());
    *x = Rational(n);
  }
}

template <int H>
void remove_polynomial_content(PolyMatrix<Rational, H>& n) {
  RPoly g;
  if (!content_is_constant(n))  // proved constant modulo a prime (kernel/modular_coprime.hpp): no Euclid over Q
    for (auto& row : n)
      for (auto& e : row)
        if (!e.is_zero()) g = g.is_zero() ? gcd(e, e) : gcd(g, e);
  if (g.degree() > 0)
    for (auto& row : n)
      for (auto& e : row) {
        RPoly q, r;
        divide(e, g, q, r);
        e = q;
      }
  std::vector<Rational*> all;
  for (auto& row : n)
    for (auto& e : row)
      for (auto& c : e.c) all.push_back(&c);
  make_primitive(all);
}

template <int H>
Matrix<Rational, H> shape_matrix(const SceneObject& o) {
  Matrix<Rational, H> q{};
  std::vector<Rational*> all;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      q[i][j] = o.Q.at(i).at(j);
    }
  for (auto& row : q)
    for (auto& x : row) all.push_back(&x);
  make_primitive(all);
  return q;
}

// Balancing the pencil λA - B. make_primitive scales Q and N of each object
// by its own integer factor, so A(t) and B(t) can differ in size by many
// orders of magnitude; then the negative roots of f(λ) lie near 0 or near -∞,
// and in 001's variable u = 1/(1 - λ) the region where F(u, t) > 0 is squeezed
// against u = 0 or u = 1, where sampled and Bézier tests in u miss it. B's
// shape matrix is therefore multiplied by 2^-k, k the nearest integer to the
// mean of log2 |det B(t) / det A(t)| / N over t = 0, 1/2, 1, so that the
// product of the roots of f is near 1 in size. A positive factor on B scales
// every root λ by the same positive factor: no status, no root of Δ and no
// answer changes, and a power of two is exact in every arithmetic.
inline long log2_size(const Rational& x) {  // floor-ish log2 |x|, within 1
  return long(mpz_sizeinbase(x.get_num_mpz_t(), 2)) - long(mpz_sizeinbase(x.get_den_mpz_t(), 2));
}
template <int H>
void balance_pencil(PreparedPair<H>& p) {
  long sum = 0;
  int used = 0;
  for (const Rational& t : {Rational(0), Rational(1, 2), Rational(1)}) {
    // det A(t) without forming A(t): the same rational (kernel/quadric_determinant.hpp).
    Rational da = quadric_det_at<H>(p.qa, p.na, t);
    Rational db = quadric_det_at<H>(p.qb, p.nb, t);
    if (da == 0 || db == 0) continue;
    sum += log2_size(db) - log2_size(da);
    ++used;
  }
  if (!used) return;
  long k = std::lround(double(sum) / (used * H));
  if (k == 0) return;
  mpz_class two = 1;
  two <<= std::abs(k);
  Rational f = k > 0 ? Rational(1) / Rational(two) : Rational(two);
  for (auto& row : p.qb)
    for (auto& x : row) x *= f;
}

// A scene the exact preparation cannot represent: a motion with no polynomial
// form (cycloidal). The message says what is wrong; what to do instead (which
// arithmetic, which option) is the caller's to say (app/commands.hpp).
struct NotRationalMotion : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A scene with independent motions ("parameters": "independent", A(s) and
// B(t)) given to a pipeline that treats A(t) and B(t) at one shared t: every
// such pipeline refuses it (exit 3 on the command line), with this message.
struct IndependentMotionsRefused : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
inline void refuse_independent(const Scene& s, const std::string& who = "this pipeline") {
  if (s.independent)
    throw IndependentMotionsRefused(
        "the scene has independent motions (\"parameters\": \"independent\": A(s), B(t)); " + who +
        " treats one shared t; independent scenes are solved by eccd::solve (`eccd solve`, `regress`, `report`, "
        "`plot`; --arith exact or certified: proved answers; double or mpfr:BITS) and certified by `eccd certify`");
}

// Throws NotRationalMotion for a motion that has no polynomial form (cycloidal),
// IndependentMotionsRefused for a scene with independent motions (the
// independent pipeline prepares a copy marked shared: api/solve.cpp).
template <int H>
PreparedPair<H> prepare_pair(const Scene& s) {
  if (s.dim + 1 != H) throw std::invalid_argument("scene dimension does not match the pipeline");
  refuse_independent(s);
  for (const SceneObject* o : {&s.a, &s.b})
    if (std::holds_alternative<CycloidalMotion>(o->motion))
      throw NotRationalMotion(std::string("object ") + (o == &s.a ? "a" : "b") +
                              " has a cycloidal motion, which is not rational: exact arithmetic cannot represent it "
                              "(use --arith double, mpfr:BITS or certified, which solve it)");
  auto id = [](const Rational& q) { return q; };
  PreparedPair<H> p;
  p.qa = shape_matrix<H>(s.a);
  p.qb = shape_matrix<H>(s.b);
  p.na = motion_inverse<Rational, H>(s.a.motion, id);
  p.nb = motion_inverse<Rational, H>(s.b.motion, id);
  remove_polynomial_content<H>(p.na);
  remove_polynomial_content<H>(p.nb);
  balance_pencil<H>(p);
  return p;
}

template <class T, int H>
MovingPair<T, H> to_arithmetic(const PreparedPair<H>& p, const T& like) {
  auto conv = [&](const Rational& q) { return scalar_traits<T>::from_rational(q, like); };
  MovingPair<T, H> m;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      m.qa[i][j] = conv(p.qa[i][j]);
      m.qb[i][j] = conv(p.qb[i][j]);
      m.na[i][j] = map_coeffs<T>(p.na[i][j], conv);
      m.nb[i][j] = map_coeffs<T>(p.nb[i][j], conv);
    }
  return m;
}

// The same pair with N(t) in Bernstein form on [0, 1]: converted exactly,
// then rounded coefficient by coefficient (a floating pipeline that computes
// A(t) and f in Bernstein form starts from here).
template <class T, int H>
struct MovingPairBern {
  Matrix<T, H> qa{}, qb{};
  std::array<std::array<Bern<T>, H>, H> na{}, nb{};
};
template <class T>
using MovingPairBern2 = MovingPairBern<T, H_2D>;
template <class T>
using MovingPairBern3 = MovingPairBern<T, H_3D>;

template <class T, int H>
MovingPairBern<T, H> to_arithmetic_bernstein(const PreparedPair<H>& p, const T& like) {
  auto conv = [&](const Rational& q) { return scalar_traits<T>::from_rational(q, like); };
  auto bern = [&](const Poly<Rational>& e) {
    Bern<T> r;
    if (e.is_zero()) {
      r.b.push_back(conv(Rational(0)));
      return r;
    }
    for (const auto& c : to_bernstein(e).b) r.b.push_back(conv(c));
    return r;
  };
  MovingPairBern<T, H> m;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      m.qa[i][j] = conv(p.qa[i][j]);
      m.qb[i][j] = conv(p.qb[i][j]);
      m.na[i][j] = bern(p.na[i][j]);
      m.nb[i][j] = bern(p.nb[i][j]);
    }
  return m;
}

}  // namespace eccd
