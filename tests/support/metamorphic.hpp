#pragma once
// Test support: metamorphic transformations of a scene, and the comparison of
// two certified answers that the transformations must leave equal.
//
// What. Each transformation returns a new Scene (same shapes Q, in each
// object's own frame) whose two objects carry MatrixMotion M'(t), a
// polynomial matrix built exactly from the original M(t) (kernel/motion.hpp):
//   as_matrix_motion(s)      M' = M: the same scene written entry by entry
//                            (separates "representation" from the relations);
//   swap_objects(s)          A and B exchanged;
//   with_common_motion(s,G)  M'(t) = G(t) M(t) for both objects, G a rational
//                            motion given as a polynomial matrix with last row
//                            (0, ..., 0, w_G(t)); the product's last row is
//                            then (0, ..., 0, w_G w_M) by itself;
//   reversed_time(s)         every entry p(t) -> p(1 - t);
//   scaled_space(s, k)       M'(t) = diag(k, ..., k, 1) M(t), k > 0 rational
//                            (with_common_motion with a constant G).
//
// Why the certified answer cannot change. The collision set is
// C = { t : A(t) ∩ B(t) ≠ ∅ } with A(t) = M_A(t) solid_A (scene-format.md).
//   - Swapping: ∩ is symmetric, so C and the external contacts (touching with
//     disjoint interiors) are the same sets.
//   - A common motion: G(t) is a bijection of space at every t (det ≠ 0 on
//     [0, 1]), so G(t)A(t) ∩ G(t)B(t) = G(t)(A(t) ∩ B(t)) is non-empty iff
//     A(t) ∩ B(t) is, and it maps interiors to interiors, so external
//     tangency is kept too. This holds for any invertible affine G; the tests
//     use rigid G (rotation with rational entries plus translation) and the
//     uniform scaling, which is the common motion diag(k, ..., k, 1).
//     In the pencil, A'(t) = G^-T A(t) G^-1, so f'(λ; t) = det(G)^-2 f(λ; t):
//     Δ' is Δ times a factor without roots in [0, 1].
//   - Reversing time: the scene at t is the original at 1 - t, so
//     C' = { 1 - t : t ∈ C }: the intervals come in reverse order with start
//     and end exchanged, every instant t becomes 1 - t (a certified bracket
//     [lo, hi] becomes [1 - hi, 1 - lo]), and the contacts come reversed.
// A certified bracket holds exactly one instant of its list, so the original
// and the transformed answers must have the same number of intervals and
// contacts, and corresponding brackets (after mirroring) must overlap: both
// contain the same true instant. Overlap is what is compared, not equality:
// the brackets are computed from different polynomials.
//
// Requirements. Exact rationals only (mpq_class); no double decides anything.
// The scene must be rational (no cycloidal motion). G must have last row
// (0, ..., 0, w_G) with w_G and det of its upper-left block non-zero on
// [0, 1] (checked exactly with Sturm counts; std::invalid_argument if not).
#include "kernel/answer.hpp"
#include "kernel/motion.hpp"
#include "kernel/scene.hpp"
#include "kernel/sturm.hpp"

#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd::test {

using PolyRows = std::vector<std::vector<RPoly>>;  // (dim+1) x (dim+1), as MatrixMotion::m

// ---- polynomial matrices of runtime size -------------------------------------

// M(t) of a motion as rows of polynomials (kernel/motion.hpp's motion_matrix).
inline PolyRows world_matrix(const Motion& m, int dim) {
  auto id = [](const Rational& q) { return q; };
  PolyRows out;
  auto copy = [&](const auto& pm) {
    for (const auto& row : pm) out.emplace_back(row.begin(), row.end());
  };
  if (dim == 2)
    copy(motion_matrix<Rational, 3>(m, id));
  else if (dim == 3)
    copy(motion_matrix<Rational, 4>(m, id));
  else
    throw std::invalid_argument("metamorphic: dimension must be 2 or 3");
  return out;
}

inline PolyRows rows_product(const PolyRows& a, const PolyRows& b) {
  std::size_t n = a.size();
  PolyRows r(n, std::vector<RPoly>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k)
        if (!a[i][k].is_zero() && !b[k][j].is_zero()) r[i][j] += a[i][k] * b[k][j];
  return r;
}

// Determinant of a small polynomial matrix (Laplace along the first row).
inline RPoly rows_det(const PolyRows& a) {
  std::size_t n = a.size();
  if (n == 1) return a[0][0];
  RPoly d;
  for (std::size_t j = 0; j < n; ++j) {
    if (a[0][j].is_zero()) continue;
    PolyRows sub;
    for (std::size_t i = 1; i < n; ++i) {
      std::vector<RPoly> row;
      for (std::size_t k = 0; k < n; ++k)
        if (k != j) row.push_back(a[i][k]);
      sub.push_back(row);
    }
    RPoly term = a[0][j] * rows_det(sub);
    if (j % 2)
      d -= term;
    else
      d += term;
  }
  return d;
}

// p(1 - t), exactly (Horner in the polynomial 1 - t).
inline RPoly reflect_time(const RPoly& p) {
  RPoly one_minus_t(std::vector<Rational>{Rational(1), Rational(-1)});
  RPoly r;
  for (int i = p.degree(); i >= 0; --i) r = r * one_minus_t + RPoly::constant(p.c[i]);
  return r;
}

inline bool vanishes_on_unit_interval(const RPoly& p) {
  return p.is_zero() || count_roots_closed(p, Rational(0), Rational(1)) != 0;
}

// Throws unless m has last row (0, ..., 0, w) with w and det of the
// upper-left block both free of roots on [0, 1].
inline void check_motion_rows(const PolyRows& m, int dim, const std::string& what) {
  if (int(m.size()) != dim + 1) throw std::invalid_argument(what + ": wrong matrix size");
  for (const auto& row : m)
    if (int(row.size()) != dim + 1) throw std::invalid_argument(what + ": wrong matrix size");
  for (int j = 0; j < dim; ++j)
    if (!m[dim][j].is_zero()) throw std::invalid_argument(what + ": last row must be (0, ..., 0, w(t))");
  if (vanishes_on_unit_interval(m[dim][dim])) throw std::invalid_argument(what + ": w(t) vanishes on [0, 1]");
  PolyRows L(dim, std::vector<RPoly>(dim));
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) L[i][j] = m[i][j];
  if (vanishes_on_unit_interval(rows_det(L)))
    throw std::invalid_argument(what + ": the linear part is singular on [0, 1]");
}

// True iff m is a rational rigid motion up to its weight: with L the
// upper-left block and w the last entry, L^T L = w^2 I and det L = w^dim
// (a rotation, not a reflection, times w, plus any translation).
inline bool is_rigid_motion(const PolyRows& m, int dim) {
  const RPoly& w = m[dim][dim];
  RPoly w2 = w * w;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) {
      RPoly s;
      for (int k = 0; k < dim; ++k) s += m[k][i] * m[k][j];
      if (!(s == (i == j ? w2 : RPoly()))) return false;
    }
  PolyRows L(dim, std::vector<RPoly>(dim));
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) L[i][j] = m[i][j];
  RPoly wd = RPoly::constant(Rational(1));
  for (int i = 0; i < dim; ++i) wd = wd * w;
  return rows_det(L) == wd;
}

// ---- rational motions used as common motions G -------------------------------

// A constant 2D rotation by the angle of the Pythagorean triple (a, b, c)
// (cos = a/c, sin = b/c), followed by the translation (x(t), y(t)).
inline PolyRows rigid_2d(long a, long b, const RPoly& x, const RPoly& y) {
  mpz_class c2 = mpz_class(a) * a + mpz_class(b) * b, c;
  mpz_sqrt(c.get_mpz_t(), c2.get_mpz_t());
  if (c * c != c2 || c == 0)
    throw std::invalid_argument("rigid_2d: (a, b) is not the leg pair of a Pythagorean triple");
  Rational co(mpz_class(a), c), si(mpz_class(b), c);
  co.canonicalize();
  si.canonicalize();
  PolyRows g(3, std::vector<RPoly>(3));
  g[0][0] = RPoly::constant(co);
  g[0][1] = RPoly::constant(Rational(-si));
  g[0][2] = x;
  g[1][0] = RPoly::constant(si);
  g[1][1] = RPoly::constant(co);
  g[1][2] = y;
  g[2][2] = RPoly::constant(Rational(1));
  return g;
}

// A constant 3D rotation by the rational quaternion (e0, e1, e2, e3), divided
// by its norm E (so the weight is 1), followed by the translation v(t).
inline PolyRows rigid_3d(const std::array<long, 4>& e, const std::array<RPoly, 3>& v) {
  Poly<Rational> q[4];
  Rational E = 0;
  for (int i = 0; i < 4; ++i) {
    q[i] = RPoly::constant(Rational(e[i]));
    E += Rational(e[i]) * Rational(e[i]);
  }
  if (E == 0) throw std::invalid_argument("rigid_3d: zero quaternion");
  PolyMatrix<Rational, 4> r = quaternion_matrix(q);  // E R
  PolyRows g(4, std::vector<RPoly>(4));
  Rational inv = Rational(1) / E;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) g[i][j] = inv * r[i][j];
    g[i][3] = v[i];
  }
  g[3][3] = RPoly::constant(Rational(1));
  return g;
}

// diag(k, ..., k, 1).
inline PolyRows uniform_scaling(int dim, const Rational& k) {
  PolyRows g(dim + 1, std::vector<RPoly>(dim + 1));
  for (int i = 0; i < dim; ++i) g[i][i] = RPoly::constant(k);
  g[dim][dim] = RPoly::constant(Rational(1));
  return g;
}

// ---- the transformations -------------------------------------------------------

inline Motion matrix_motion(const PolyRows& m) {
  MatrixMotion mm;
  mm.m = m;
  return Motion(mm);
}

// The same scene with both motions written as MatrixMotion.
inline Scene as_matrix_motion(const Scene& s) {
  Scene r = s;
  r.path.clear();
  r.answer.reset();
  r.name = s.name + "+matrix";
  r.a.motion = matrix_motion(world_matrix(s.a.motion, s.dim));
  r.b.motion = matrix_motion(world_matrix(s.b.motion, s.dim));
  return r;
}

inline Scene swap_objects(const Scene& s) {
  Scene r = as_matrix_motion(s);
  std::swap(r.a, r.b);
  r.name = s.name + "+swap";
  return r;
}

inline Scene with_common_motion(const Scene& s, const PolyRows& g) {
  check_motion_rows(g, s.dim, "common motion G");
  Scene r = as_matrix_motion(s);
  for (SceneObject* o : {&r.a, &r.b}) {
    PolyRows m = rows_product(g, std::get<MatrixMotion>(o->motion).m);
    check_motion_rows(m, s.dim, "G M");
    o->motion = matrix_motion(m);
  }
  r.name = s.name + "+common";
  return r;
}

inline Scene reversed_time(const Scene& s) {
  Scene r = as_matrix_motion(s);
  for (SceneObject* o : {&r.a, &r.b}) {
    PolyRows m = std::get<MatrixMotion>(o->motion).m;
    for (auto& row : m)
      for (auto& e : row) e = reflect_time(e);
    o->motion = matrix_motion(m);
  }
  r.name = s.name + "+reversed";
  return r;
}

inline Scene scaled_space(const Scene& s, const Rational& k) {
  if (k <= 0) throw std::invalid_argument("scaled_space: k must be positive");
  Scene r = with_common_motion(s, uniform_scaling(s.dim, k));
  r.name = s.name + "+scaled";
  return r;
}

// ---- comparing certified answers -------------------------------------------------

// [lo, hi] -> [1 - hi, 1 - lo].
inline Instant mirror_instant(const Instant& i) {
  Instant m;
  if (i.lo && i.hi) {
    m.lo = Rational(Rational(1) - *i.hi);
    m.hi = Rational(Rational(1) - *i.lo);
  }
  m.approx = "mirror of " + i.approx;
  return m;
}

// The answer of the time-reversed scene predicted from the original one.
inline Answer mirror_answer(const Answer& a) {
  Answer m;
  m.collides = a.collides;
  for (auto it = a.intervals.rbegin(); it != a.intervals.rend(); ++it)
    m.intervals.push_back({mirror_instant(it->second), mirror_instant(it->first)});
  if (!m.intervals.empty()) m.first_contact = m.intervals.front().first;
  for (auto it = a.contacts.rbegin(); it != a.contacts.rend(); ++it) m.contacts.push_back(mirror_instant(*it));
  for (auto it = a.contact_intervals.rbegin(); it != a.contact_intervals.rend(); ++it)
    m.contact_intervals.push_back({mirror_instant(it->second), mirror_instant(it->first)});
  return m;
}

inline std::string bracket_text(const Instant& i) {
  if (!i.certified()) return "(uncertified " + i.approx + ")";
  return "[" + i.lo->get_str() + ", " + i.hi->get_str() + "]";
}

// Both certified and [lo, hi] ∩ [lo', hi'] ≠ ∅, decided exactly.
inline bool brackets_overlap(const Instant& x, const Instant& y) {
  if (!x.certified() || !y.certified()) return false;
  const mpq_class& lo = *x.lo > *y.lo ? *x.lo : *y.lo;
  const mpq_class& hi = *x.hi < *y.hi ? *x.hi : *y.hi;
  return lo <= hi;
}

inline std::string answer_text(const Answer& a) {
  std::ostringstream o;
  o << "collides=" << (a.collides ? "yes" : "no") << " intervals={";
  for (const auto& [s, e] : a.intervals) o << " " << bracket_text(s) << ".." << bracket_text(e);
  o << " } contacts={";
  for (const auto& c : a.contacts) o << " " << bracket_text(c);
  o << " } first_contact=" << (a.first_contact ? bracket_text(*a.first_contact) : "none");
  if (!a.contact_intervals.empty()) o << " contact_intervals=" << a.contact_intervals.size();
  if (!a.undecided.empty()) o << " undecided=" << a.undecided.size();
  return o.str();
}

// "" if `got` is the answer `expected` predicts (same collides, same numbers
// of intervals / contacts / continuous-contact intervals, pairwise overlapping
// certified brackets, the same first contact, nothing undecided); otherwise a
// description of the first difference.
inline std::string answer_mismatch(const Answer& expected, const Answer& got) {
  std::ostringstream o;
  auto pair_ok = [&](const char* what, std::size_t i, const Instant& x, const Instant& y) {
    if (brackets_overlap(x, y)) return true;
    o << what << " " << i << ": expected " << bracket_text(x) << ", got " << bracket_text(y);
    return false;
  };
  if (!got.undecided.empty() || !expected.undecided.empty()) return "an answer has undecided instants";
  if (expected.collides != got.collides) return "collides differs";
  if (expected.intervals.size() != got.intervals.size()) return "number of intervals differs";
  if (expected.contacts.size() != got.contacts.size()) return "number of contacts differs";
  if (expected.contact_intervals.size() != got.contact_intervals.size()) return "number of contact intervals differs";
  if (expected.first_contact.has_value() != got.first_contact.has_value())
    return "first contact present in one answer only";
  for (std::size_t i = 0; i < expected.intervals.size(); ++i)
    if (!pair_ok("interval start", i, expected.intervals[i].first, got.intervals[i].first) ||
        !pair_ok("interval end", i, expected.intervals[i].second, got.intervals[i].second))
      return o.str();
  for (std::size_t i = 0; i < expected.contacts.size(); ++i)
    if (!pair_ok("contact", i, expected.contacts[i], got.contacts[i])) return o.str();
  for (std::size_t i = 0; i < expected.contact_intervals.size(); ++i)
    if (!pair_ok("contact interval start", i, expected.contact_intervals[i].first, got.contact_intervals[i].first) ||
        !pair_ok("contact interval end", i, expected.contact_intervals[i].second, got.contact_intervals[i].second))
      return o.str();
  if (expected.first_contact && !pair_ok("first contact", 0, *expected.first_contact, *got.first_contact))
    return o.str();
  return "";
}

}  // namespace eccd::test
