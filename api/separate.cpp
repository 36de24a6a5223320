// Separating planes at an instant and over a frame (api/separate.hpp).
#include "api/separate.hpp"

#include "api/static_status.hpp"
#include "floating/rounded_input.hpp"
#include "kernel/motion.hpp"
#include "kernel/plane_frame_check.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "kernel/separating_plane.hpp"
#include "number/mpfr_real.hpp"
#include "number/rational_traits.hpp"
#include "number/running_error.hpp"
#include "number/simplest_rational.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace eccd {

const char* to_string(PlaneCheck c) {
  switch (c) {
    case PlaneCheck::separates:
      return "separates";
    case PlaneCheck::fails:
      return "fails";
    default:
      return "unknown";
  }
}

namespace {

void refuse_cycloidal(const Scene& s, const char* who) {
  for (const SceneObject* ob : {&s.a, &s.b})
    if (std::holds_alternative<CycloidalMotion>(ob->motion))
      throw NotRationalMotion(
          std::string("object ") + (ob == &s.a ? "a" : "b") + " has a cycloidal motion: " + who +
          " needs a polynomial motion matrix M(t) (rational motions); cycloidal motions are not supported yet");
}

mpq_class to_rational(const mpq_class& x) { return x; }
mpq_class to_rational(const double& x) { return mpq_class(x); }
mpq_class to_rational(const Mpfr& x) {
  mpq_class q;
  mpfr_get_q(q.get_mpq_t(), x.get());
  return q;
}
template <class T>
const T& plain(const T& x) {
  return x;
}
template <class T>
const T& plain(const Bounded<T>& x) {
  return x.value();
}
template <class T>
double bound_of(const T&) {
  return 0;
}
template <class T>
double bound_of(const Bounded<T>& x) {
  return double(x.bound());
}

template <class T, int H>
Matrix<T, H> scene_shape(const SceneObject& ob, const T& like) {
  Matrix<T, H> q;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) q[i][j] = scalar_traits<T>::from_rational(ob.Q.at(i).at(j), like);
  return q;
}
template <class T, int H>
PolyMatrix<T, H> scene_motion(const SceneObject& ob, const T& like) {
  return motion_matrix<T, H>(ob.motion, [&](const Rational& q) { return scalar_traits<T>::from_rational(q, like); });
}
template <class T, int H>
std::array<T, H> plane_vector(const SeparatingPlane& pl, const T& like) {
  if (int(pl.normal.size()) != H - 1)
    throw std::invalid_argument("the plane's normal has " + std::to_string(pl.normal.size()) +
                                " entries; the scene needs " + std::to_string(H - 1));
  bool zero = true;
  for (const auto& x : pl.normal) zero = zero && sgn(x) == 0;
  if (zero) throw std::invalid_argument("the plane's normal is zero");
  std::array<T, H> p;
  for (int i = 0; i < H - 1; ++i) p[i] = scalar_traits<T>::from_rational(pl.normal[i], like);
  p[H - 1] = scalar_traits<T>::from_rational(pl.offset, like);
  return p;
}

// The checks of api/separate.hpp at instant t, in T (exact, or with an error bound).
// Returns "" when all four hold, else which one does not (or cannot be decided).
template <class T, int H>
std::string check_at(const Scene& scene, const SeparatingPlane& pl, const T& t, const T& like,
                     std::vector<PlaneInequality>& out) {
  const T zero = scalar_traits<T>::from_rational(mpq_class(0), like);
  const std::array<T, H> p = plane_vector<T, H>(pl, like);
  std::string failed;
  for (int k = 0; k < 2; ++k) {
    const SceneObject& ob = k ? scene.b : scene.a;
    const std::string name = k ? "b" : "a";
    PlaneAgainstObject<T, H> po =
        plane_against_object<T, H>(scene_shape<T, H>(ob, like), scene_motion<T, H>(ob, like), p, zero);
    auto eval = [&](const Poly<T>& f) { return f.is_zero() ? zero : f(t); };
    T miss = eval(po.miss);
    // n.c + o with c the centre at t: side(t) / (w(t) * Y_c,d), Y_c,d = the cofactor of Q's last entry.
    const Matrix<T, H> adj = adjugate_of<T, H>(scene_shape<T, H>(ob, like), zero);
    const PolyMatrix<T, H> m = scene_motion<T, H>(ob, like);
    T wd = eval(po.w) * adj[H - 1][H - 1];
    T side = eval(po.side) / wd;
    PlaneInequality im{name, "q^T adj(Q) q, q = M(t)^T (n, o)", "> 0", to_rational(plain(miss)), bound_of(miss), {}};
    PlaneInequality is{name, "n.c + o, c the centre at t", k ? "> 0" : "< 0", to_rational(plain(side)), bound_of(side),
                       {}};
    for (int i = 0; i < H - 1; ++i) {
      T ci = zero;
      for (int j = 0; j < H; ++j) ci = ci + eval(m[i][j]) * adj[j][H - 1];
      is.centre.push_back(to_rational(plain(T(ci / wd))));
    }
    out.push_back(im);
    out.push_back(is);
    const Sign sm = sign(miss), ss = sign(side);
    if (failed.empty() && sm != Sign::positive)
      failed = sm == Sign::uncertain ? "object " + name + ": q^T adj(Q) q is within its error bound of 0"
                                     : "object " + name + ": the plane meets it (q^T adj(Q) q <= 0)";
    const Sign want = k ? Sign::positive : Sign::negative;
    if (failed.empty() && ss != want)
      failed = ss == Sign::uncertain ? "object " + name + ": the centre's side is within its error bound of the plane"
                                     : "object " + name + ": its centre is on the wrong side";
  }
  return failed;
}

Mpfr rational_to_mpfr(const Rational& q, int bits) { return Mpfr(q, bits); }

template <class T, int H>
void fill_plane(Separation& s, const PlaneConstruction<T, H>& c, const std::array<mpq_class, H>& p) {
  SeparatingPlane pl;
  for (int i = 0; i < H - 1; ++i) pl.normal.push_back(p[i]);
  pl.offset = p[H - 1];
  s.plane = pl;
  s.tangent_points.clear();
  for (const auto* x : {&c.tangent_a, &c.tangent_b}) {
    std::vector<mpq_class> v;
    for (int i = 0; i < H - 1; ++i) v.push_back(to_rational((*x)(i)));
    s.tangent_points.push_back(v);
  }
}

std::string status_word(Status st) { return to_string(st); }

template <int H>
Separation separate_exact(const Scene& scene, const mpq_class& t) {
  Separation s;
  const Status st = status_at(scene, t, Arithmetic::exact());
  if (st != Status::separate) {
    s.status = status_word(st);
    return s;
  }
  const PreparedPair<H> pp = prepare_pair<H>(scene);
  const Rational rt(t);
  Matrix<Rational, H> a = quadric_at<Rational, H>(pp.qa, pp.na, rt), b = quadric_at<Rational, H>(pp.qb, pp.nb, rt);
  for (auto* m : {&a, &b}) {  // a positive power of two per matrix: entries near 1 (the same solids)
    Rational big(0);
    for (auto& row : *m)
      for (auto& x : row)
        if (abs(x) > big) big = abs(x);
    long k = log2_size(big);
    mpz_class two = 1;
    two <<= std::abs(k);
    Rational f = k > 0 ? Rational(1) / Rational(two) : Rational(two);
    for (auto& row : *m)
      for (auto& x : row) x *= f;
  }
  std::string last;
  for (int bits = 128; bits <= 4096; bits *= 2) {
    Matrix<Mpfr, H> am, bm;
    for (int i = 0; i < H; ++i)
      for (int j = 0; j < H; ++j) {
        am[i][j] = rational_to_mpfr(a[i][j], bits);
        bm[i][j] = rational_to_mpfr(b[i][j], bits);
      }
    PlaneConstruction<Mpfr, H> c = separating_plane<Mpfr, H>(am, bm);
    if (!c.ok) {
      last = c.why + " (" + std::to_string(bits) + " bits)";
      continue;
    }
    std::array<mpq_class, H> exact_p;
    for (int i = 0; i < H; ++i) exact_p[i] = to_rational(c.p(i));
    // Short rationals first: the simplest rational within 2^-e of each entry, e = 16, 32, ..., then the value itself.
    for (int e = 16; e <= bits + 16; e *= 2) {
      std::array<mpq_class, H> p = exact_p;
      if (e <= bits) {
        mpz_class den = 1;
        den <<= e;
        const mpq_class tol(1, den);
        for (auto& x : p) x = simplest_rational_in(x - tol, x + tol);
      }
      Separation cand;
      fill_plane<Mpfr, H>(cand, c, p);
      std::vector<PlaneInequality> checks;
      std::string failed = check_at<Rational, H>(scene, *cand.plane, rt, Rational(1), checks);
      if (failed.empty()) {
        cand.status = "separate";
        cand.checks = checks;
        cand.bits = bits;
        return cand;
      }
      last = failed + " (" + std::to_string(bits) + " bits)";
      if (e > bits) break;
    }
  }
  s.status = "undecided";
  s.why =
      "the pair is separate at t (exact static test) but no rational plane from the construction up to 4096 bits "
      "passed the exact checks; last: " +
      last;
  return s;
}

template <class T, int H>
Separation separate_floating(const Scene& scene, const mpq_class& t, const Arithmetic& arith, const Bounded<T>& like) {
  using B = Bounded<T>;
  Separation s;
  s.bits = scalar_traits<T>::precision(like.value());
  const Status st = status_at(scene, t, arith);
  if (st == Status::uncertain) {
    s.status = "undecided";
    s.why = "the static test at t cannot decide in " + arith.name() + " (a sign within its running error bound)";
    return s;
  }
  if (st != Status::separate) {
    s.status = status_word(st);
    return s;
  }
  std::string trouble;
  const MovingPair<B, H> mp = round_pair<B, H>(scene, like, trouble);
  if (!trouble.empty()) {
    s.status = "undecided";
    s.why = trouble;
    return s;
  }
  const B bt = scalar_traits<B>::from_rational(t, like);
  const Matrix<B, H> ab = quadric_at<B, H>(mp.qa, mp.na, bt), bb = quadric_at<B, H>(mp.qb, mp.nb, bt);
  Matrix<T, H> a, b;
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) {
      a[i][j] = ab[i][j].value();
      b[i][j] = bb[i][j].value();
    }
  PlaneConstruction<T, H> c = separating_plane<T, H>(a, b);
  if (!c.ok) {
    s.status = "undecided";
    s.why = "the construction in " + arith.name() + ": " + c.why;
    return s;
  }
  std::array<mpq_class, H> p;
  for (int i = 0; i < H; ++i) p[i] = to_rational(c.p(i));
  fill_plane<T, H>(s, c, p);
  std::vector<PlaneInequality> checks;
  std::string failed = check_at<B, H>(scene, *s.plane, scalar_traits<B>::from_rational(t, like), like, checks);
  s.checks = checks;
  if (!failed.empty()) {
    s.status = "undecided";
    s.why = "the plane built in " + arith.name() + " is not proved by its checks with their error bounds: " + failed;
    s.plane.reset();
    s.tangent_points.clear();
    return s;
  }
  s.status = "separate";
  return s;
}

// Certified: 000's construction in double from the scene rounded to double; its plane (the exact
// rationals of the doubles) is proved by the four inequalities of check_at evaluated in Bounded<double>, whose
// running error bounds hold against the same formulas on the scene's exact numbers (number/running_error.hpp):
// each certainly-signed value has the exact value's sign, so the plane provably separates a and b at t. When the
// double static test cannot decide or the bounded checks do not all hold, the exact path (separate_exact) decides,
// which also gives the exact statement "touching" / "overlapping".
template <int H>
Separation separate_certified(const Scene& scene, const mpq_class& t) {
  Separation s = separate_floating<double, H>(scene, t, Arithmetic::double_precision(), Bounded<double>(1.0, 0));
  if (s.status == "separate" && s.plane) return s;
  return separate_exact<H>(scene, t);
}

template <int H>
Separation separate_dim(const Scene& scene, const mpq_class& t, const SolveOptions& o) {
  switch (o.arith.kind) {
    case Arithmetic::Double:
      return separate_floating<double, H>(scene, t, o.arith, Bounded<double>(1.0, 0));
    case Arithmetic::Mpfr:
      return separate_floating<Mpfr, H>(scene, t, o.arith, Bounded<Mpfr>(Mpfr(mpq_class(1), o.arith.mpfr_bits), 0));
    case Arithmetic::Certified:
      return separate_certified<H>(scene, t);
    default:
      return separate_exact<H>(scene, t);
  }
}

template <class T, int H>
PlaneCheck frame_check(const Scene& scene, const SeparatingPlane& pl, const T& like) {
  const T zero = scalar_traits<T>::from_rational(mpq_class(0), like);
  const std::array<T, H> p = plane_vector<T, H>(pl, like);
  bool unknown = false;
  for (int k = 0; k < 2; ++k) {
    const SceneObject& ob = k ? scene.b : scene.a;
    PlaneAgainstObject<T, H> po =
        plane_against_object<T, H>(scene_shape<T, H>(ob, like), scene_motion<T, H>(ob, like), p, zero);
    // The centre's side at t = 0: sign(side(0)) * sign(w(0)).
    const Sign side = sign(po.side.is_zero() ? zero : po.side(zero)) * sign(po.w.is_zero() ? zero : po.w(zero));
    const Sign want = k ? Sign::positive : Sign::negative;
    if (side == Sign::uncertain)
      unknown = true;
    else if (side != want)
      return PlaneCheck::fails;
    std::string where;
    switch (positive_on_unit_interval(po.miss, where)) {
      case OnInterval::not_positive:
        return PlaneCheck::fails;
      case OnInterval::unknown:
        unknown = true;
        break;
      default:
        break;
    }
  }
  return unknown ? PlaneCheck::unknown : PlaneCheck::separates;
}

template <int H>
PlaneCheck frame_check_dim(const Scene& scene, const SeparatingPlane& pl, const SolveOptions& o) {
  switch (o.arith.kind) {
    case Arithmetic::Double:
      return frame_check<Bounded<double>, H>(scene, pl, Bounded<double>(1.0, 0));
    case Arithmetic::Mpfr:
      return frame_check<Bounded<Mpfr>, H>(scene, pl, Bounded<Mpfr>(Mpfr(mpq_class(1), o.arith.mpfr_bits), 0));
    case Arithmetic::Exact:
      return frame_check<Rational, H>(scene, pl, Rational(1));
    case Arithmetic::Certified: {
      PlaneCheck c = frame_check<Bounded<double>, H>(scene, pl, Bounded<double>(1.0, 0));
      return c != PlaneCheck::unknown ? c : frame_check<Rational, H>(scene, pl, Rational(1));
    }
  }
  return PlaneCheck::unknown;
}

}  // namespace

Separation separate_at(const Scene& scene, const mpq_class& t, const SolveOptions& o) {
  if (sgn(t) < 0 || t > 1) throw std::invalid_argument("the instant t = " + t.get_str() + " is outside [0, 1]");
  refuse_independent(scene, "a separating plane at one instant");
  refuse_cycloidal(scene, "the separating plane");
  return scene.dim == 3 ? separate_dim<H_3D>(scene, t, o) : separate_dim<H_2D>(scene, t, o);
}

PlaneCheck plane_separates_on_frame(const Scene& scene, const SeparatingPlane& plane, const SolveOptions& o) {
  refuse_cycloidal(scene, "the frame check of a plane");
  return scene.dim == 3 ? frame_check_dim<H_3D>(scene, plane, o) : frame_check_dim<H_2D>(scene, plane, o);
}

}  // namespace eccd
