// The independent check of "eccd-bezier-certificate/2" (docs/certificate-format.md,
// "Bézier certificates"; docs/checking.md): a 3D scene with shared parameters,
// proved separate or overlapping on pieces of [0, 1] by the interval Bézier
// method (paper 001, section 4: with F(u, t) = det((u - 1) A(t) - u B(t)) the
// ellipsoids are separate at t iff max over u in [0, 1] of F(u, t) > 0).
// Claims, in order:
//   certificate format; scene (the scene file's dim, a, b, parameters; 3D,
//   shared parameter, rational motions with det M(t) ≠ 0 on [0, 1] by Sturm);
//   net: the certificate's tensor Bernstein net of F (degree 4 in u) is
//     det((u - 1) α A(t) - u β B(t)) for constants α, β > 0, with A, B the
//     checker's own moving quadrics (certificate/check/pencil.hpp): α^4 and
//     β^4 are read off the faces at t = 0 (exact fourth roots, else rejected),
//     then both sides agree exactly at a grid of 5 x (D + 1) rational points,
//     D at least both sides' degree in t. Any α, β > 0 keep the lemma: u ↦
//     uβ / ((1 - u)α + uβ) maps [0, 1] onto itself and F only gains a
//     positive factor;
//   pieces covering [0, 1] in order: "out"/"in" boxes with every control
//     point of the restricted net > 0 / < 0 (MPFI at precision_bits, outward);
//     the in-groups' u-ranges cover [0, 1]; "end": the faces F(0, t),
//     F(1, t) < 0 on the run, a Krawczyk chain on (F, F_u) in (u, t) (the
//     checker's own test: Moore, Kearfott, Cloud 2009, section 8.2), its
//     first box's t-range covering the run; the exclusion of other zeros of
//     (F, F_u) on [0, 1] x run outside the box's u-range, by the
//     certificate's subdivision tree (a preorder string, '1' split, '0' leaf;
//     u halved at every level, t at every second): each leaf lies in the kept
//     u-range or has F or F_u of one proved sign (intervals of doubles widened
//     outwards, else MPFI); the bracket inside the run holding the run ∩ the
//     last chain box's t-range;
//   answer: assembled by the checker from the checked pieces (each end a
//     touching instant between an in- and an out-cell; certificate/check/claims.hpp).
// Nothing is searched: every box, chain and subdivision is the certificate's.
#include "certificate/check/bernstein.hpp"
#include "certificate/check/claims.hpp"
#include "certificate/check/interval.hpp"
#include "certificate/check/kinds.hpp"
#include "certificate/check/pencil.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace eccd::check {

namespace {

const std::size_t kMaxRationalBits = 1024, kMaxNetBits = 1 << 16, kMaxPieces = 200000, kMaxBoxes = 2000000,
                  kMaxChain = 64, kMaxTreeNodes = 2 * 60000 + 1;
const int kMaxNetDegree = 400, kMaxTreeDepth = 40;

std::string q(const mpq_class& x) { return x.get_str(); }

// The rows of a net (coefficients in t) as integers over one denominator each, so that a row's value at an
// integer t is Σ_j W_j t^j (1 - t)^(n - j) / L in integer arithmetic (W_j = L c_j C(n, j)).
struct IntegerRows {
  int n = 0;
  std::vector<std::vector<mpz_class>> W;
  std::vector<mpz_class> L;
  explicit IntegerRows(const Net2<mpq_class>& f) : n(f.n) {
    for (int i = 0; i <= f.m; ++i) {
      mpz_class l = 1;
      for (int j = 0; j <= n; ++j) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), f.at(i, j).get_den_mpz_t());
      std::vector<mpz_class> w;
      mpz_class binom = 1;
      for (int j = 0; j <= n; ++j) {
        if (j > 0) binom = binom * (n - j + 1) / j;
        w.push_back(f.at(i, j).get_num() * (l / f.at(i, j).get_den()) * binom);
      }
      W.push_back(std::move(w));
      L.push_back(l);
    }
  }
  std::vector<mpq_class> at(long t) const {
    std::vector<mpz_class> pw(n + 1), qw(n + 1);
    pw[0] = qw[0] = 1;
    for (int j = 1; j <= n; ++j) {
      pw[j] = pw[j - 1] * t;
      qw[j] = qw[j - 1] * (1 - t);
    }
    std::vector<mpq_class> r;
    for (std::size_t i = 0; i < W.size(); ++i) {
      mpz_class v = 0;
      for (int j = 0; j <= n; ++j) v += W[i][j] * pw[j] * qw[n - j];
      mpq_class x(v, L[i]);
      x.canonicalize();
      r.push_back(x);
    }
    return r;
  }
};

struct BNode {  // a node of the pieces' timeline (claims.hpp answer_claim)
  mpq_class lo, hi;
  bool cell = false;
  St status = St::separate;
  std::string name;
};

struct BezierChecker {
  const CheckScene& sc;
  const json& cert;
  std::vector<std::string>& checked;
  int bits = 160;
  Net2<mpq_class> F, Fu;
  Net2<MI> mF, mFu;
  Net2<DI> dF, dFu;
  long tree_leaves = 0, tree_mpfi = 0, boxes_mpfi = 0;

  MI mk(const mpq_class& x) const { return MI(x, bits); }
  Net2<MI> enclose(const Net2<mpq_class>& f) const {
    return converted<MI>(f, [&](const mpq_class& x) { return mk(x); });
  }
  static Net2<DI> restrict_di(const Net2<DI>& f, int axis, const mpq_class& a, const mpq_class& b) {
    return restrict_to(f, axis, a, b, [](const mpq_class& x) { return DI::of(x); });
  }
  Net2<MI> restrict_mi(const Net2<MI>& f, int axis, const mpq_class& a, const mpq_class& b) const {
    return restrict_to(f, axis, a, b, [&](const mpq_class& x) { return mk(x); });
  }

  void scene_claim() {
    const json& s = at(cert, "scene", "certificate");
    for (const char* k : {"dim", "a", "b"})
      if (at(s, k, "scene") != sc.doc.at(k))
        reject("scene", std::string("the certificate's \"") + k +
                            "\" differs from the scene file's: it is a certificate for another scene");
    if (s.contains("parameters") != sc.doc.contains("parameters") ||
        (s.contains("parameters") && s["parameters"] != sc.doc["parameters"]))
      reject("scene",
             "the certificate's \"parameters\" differs from the scene file's: it is a certificate for another scene");
    if (sc.dim != 3 || sc.independent || sc.cycloidal)
      reject("scene", "a Bézier certificate is for 3D scenes with shared parameters and rational motions");
    for (const CheckObject* o : {&sc.a, &sc.b}) {
      const QPoly d = motion_determinant(o->M);
      if (d.zero() || sgn(d(0)) == 0 || sgn(d(1)) == 0 || roots_between(d, 0, 1) != 0)
        reject("scene", std::string("det M(t) of object ") + (o == &sc.a ? "a" : "b") +
                            " vanishes in [0, 1]: the motion is not invertible there");
    }
    checked.push_back(
        "scene: dim, a, b and parameters are the scene file's; 3D, shared parameter; det M(t) has no root in [0, 1] "
        "(Sturm)");
  }

  // A stated shape: a positive multiple of the scene's Q.
  QMatrix stated_shape(const json& j, const std::string& place, const QMatrix& Q) {
    if (!j.is_array() || j.size() != 4) reject("certificate format", place + ": expected a 4 x 4 matrix");
    QMatrix S(4, std::vector<mpq_class>(4));
    std::optional<mpq_class> lambda;
    for (std::size_t r = 0; r < 4; ++r) {
      if (!j[r].is_array() || j[r].size() != 4) reject("certificate format", place + ": expected a 4 x 4 matrix");
      for (std::size_t c = 0; c < 4; ++c) {
        S[r][c] = rational(j[r][c], place + "[" + std::to_string(r) + "][" + std::to_string(c) + "]", kMaxNetBits);
        if (!lambda && sgn(Q[r][c]) != 0) lambda = S[r][c] / Q[r][c];
      }
    }
    if (!lambda || sgn(*lambda) <= 0) reject("net", place + " is not a positive multiple of the scene's shape");
    for (std::size_t r = 0; r < 4; ++r)
      for (std::size_t c = 0; c < 4; ++c)
        if (S[r][c] != *lambda * Q[r][c]) reject("net", place + " is not a positive multiple of the scene's shape");
    return S;
  }

  // A stated inverse motion: N(t) M(t) = c(t) I with c(t) a polynomial without a root in [0, 1]
  // (then N^T Q N = c^2 M^-T Q M^-1 is the moving solid times a positive factor at every t of [0, 1]).
  PolyMatrix stated_inverse(const json& j, const std::string& place, const PolyMatrix& M) {
    if (!j.is_array() || j.size() != 4)
      reject("certificate format", place + ": expected a 4 x 4 matrix of polynomials");
    PolyMatrix N(4, std::vector<QPoly>(4));
    for (std::size_t r = 0; r < 4; ++r) {
      if (!j[r].is_array() || j[r].size() != 4)
        reject("certificate format", place + ": expected a 4 x 4 matrix of polynomials");
      for (std::size_t c = 0; c < 4; ++c) {
        const json& p = j[r][c];
        const std::string pl = place + "[" + std::to_string(r) + "][" + std::to_string(c) + "]";
        if (!p.is_array() || p.size() > 65)
          reject("certificate format", pl + ": expected power-basis coefficients (degree at most 64)");
        std::vector<mpq_class> cs;
        for (std::size_t k = 0; k < p.size(); ++k)
          cs.push_back(rational(p[k], pl + "[" + std::to_string(k) + "]", kMaxNetBits));
        N[r][c] = QPoly(std::move(cs));
      }
    }
    const int D = matrix_degree(N) + matrix_degree(M);
    std::vector<mpq_class> cv;
    for (int k = 0; k <= D; ++k) {
      const QMatrix n = at_point(N, mpq_class(k)), m = at_point(M, mpq_class(k));
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
          mpq_class x = 0;
          for (int l = 0; l < 4; ++l) x += n[r][l] * m[l][c];
          if ((r != c && sgn(x) != 0) || (r == c && c > 0 && x != cv.back()))
            reject("net",
                   place + " times the scene's M(t) is not a multiple of the identity at t = " + std::to_string(k));
          if (r == c && c == 0) cv.push_back(x);
        }
    }
    const QPoly cpoly = interpolate_at_integers(cv);
    if (cpoly.zero() || sgn(cpoly(0)) == 0 || sgn(cpoly(1)) == 0 || roots_between(cpoly, 0, 1) != 0)
      reject("net", place + " times M(t) is c(t) I with c vanishing in [0, 1]: not an inverse motion there");
    return N;
  }

  void net_claim() {
    const json& net = at(cert, "net", "certificate");
    const long long m = whole(at(net, "degree_u", "net"), "net.degree_u", 4, 4);
    const long long n = whole(at(net, "degree_t", "net"), "net.degree_t", 0, kMaxNetDegree);
    const json& co = at(net, "coefficients", "net");
    if (!co.is_array() || co.size() != std::size_t(m + 1))
      reject("certificate format", "net.coefficients: expected 5 rows (u = 0 .. 4)");
    F.m = int(m);
    F.n = int(n);
    for (std::size_t i = 0; i < co.size(); ++i) {
      if (!co[i].is_array() || co[i].size() != std::size_t(n + 1))
        reject("certificate format", "net.coefficients[" + std::to_string(i) + "]: expected degree_t + 1 rationals");
      for (std::size_t j = 0; j < co[i].size(); ++j)
        F.c.push_back(
            rational(co[i][j], "net.coefficients[" + std::to_string(i) + "][" + std::to_string(j) + "]", kMaxNetBits));
    }
    const QMatrix Qa = stated_shape(at(net, "shape_a", "net"), "net.shape_a", sc.a.Q);
    const QMatrix Qb = stated_shape(at(net, "shape_b", "net"), "net.shape_b", sc.b.Q);
    const PolyMatrix Na = stated_inverse(at(net, "inverse_a", "net"), "net.inverse_a", sc.a.M);
    const PolyMatrix Nb = stated_inverse(at(net, "inverse_b", "net"), "net.inverse_b", sc.b.M);
    // both sides are polynomials of degree <= 4 in u and <= D in t: equal at 5 x (D + 1) points, they are equal.
    // The points are the integers u = 0..4, t = 0..D (the identity holds off [0, 1] too), all in integers:
    // the net's rows over one denominator each (IntegerRows); A(t) = N_a^T Q_a N_a as the integer matrix
    // A_Z(t) = s_a A(t) (Q_a, N_a times the lcm of their denominators, s_a = l(Q_a) l(N_a)^2), B likewise, so
    // det((u - 1) A - u B) = det((u - 1) s_b A_Z - u s_a B_Z) / (s_a s_b)^4 (Bareiss, every division exact).
    const int D = std::max<int>(F.n, 8 * std::max(matrix_degree(Na), matrix_degree(Nb)));
    const IntegerRows rows(F);
    const ZMatrix QaZ = integer_matrix(Qa), QbZ = integer_matrix(Qb);
    const ZPolyMatrix NaZ = integer_matrix(Na), NbZ = integer_matrix(Nb);
    const mpz_class la = denominators_lcm(Na), lb = denominators_lcm(Nb);
    const mpz_class sa = denominators_lcm(Qa) * la * la, sb = denominators_lcm(Qb) * lb * lb;
    mpz_class s4 = sa * sb;
    s4 *= s4;
    s4 *= s4;
    for (int k = 0; k <= D; ++k) {
      const mpz_class t(k);
      const ZMatrix A = moving_quadric(QaZ, at_point(NaZ, t)), B = moving_quadric(QbZ, at_point(NbZ, t));
      const std::vector<mpq_class> r = rows.at(k);
      for (int i = 0; i <= 4; ++i) {
        const mpz_class u(i);
        ZMatrix P(4, std::vector<mpz_class>(4));
        for (int a = 0; a < 4; ++a)
          for (int c = 0; c < 4; ++c) P[a][c] = (u - 1) * sb * A[a][c] - u * sa * B[a][c];
        // Σ_l r_l C(4, l) u^l (1 - u)^(4 - l)
        mpq_class v = 0;
        static const int binom[5] = {1, 4, 6, 4, 1};
        for (int l = 0; l <= 4; ++l) {
          mpq_class term = r[l] * binom[l];
          for (int e = 0; e < l; ++e) term *= i;
          for (int e = 0; e < 4 - l; ++e) term *= (1 - i);
          v += term;
        }
        if (v * s4 != mpq_class(determinant(P)))
          reject("net", "the net differs from det((u - 1) A(t) - u B(t)) at u = " + std::to_string(i) +
                            ", t = " + std::to_string(k) + ": it is not F for this scene");
      }
    }
    checked.push_back(
        "net: Q_a, Q_b positive multiples of the scene's shapes; N_a M_a, N_b M_b = c(t) I with c free of roots in [0, "
        "1] "
        "(Sturm); F(u, t) = det((u - 1) N_a^T Q_a N_a - u N_b^T Q_b N_b) (degree 4 x " +
        std::to_string(F.n) + ", equal at " + std::to_string(5 * (D + 1)) + " rational points)");
    Fu = derivative(F, 0);
    mF = enclose(F);
    dF = converted<DI>(F, [](const mpq_class& x) { return DI::of(x); });
    dFu = converted<DI>(Fu, [](const mpq_class& x) { return DI::of(x); });
    mFu = enclose(Fu);
  }

  // The derivative net along an axis of a net on a box whose side along that axis is `side` long
  // (d/dx of the box coordinate is 1/side): (deg / side) (c_{k+1} - c_k).
  template <class T, class Make>
  static Net2<T> derivative_on(const Net2<T>& f, int axis, const mpq_class& side, Make&& make) {
    Net2<T> r;
    const int deg = axis == 0 ? f.m : f.n;
    r.m = axis == 0 ? std::max(f.m - 1, 0) : f.m;
    r.n = axis == 1 ? std::max(f.n - 1, 0) : f.n;
    const T k = make(mpq_class(mpq_class(deg) / side));
    if (deg == 0) {
      r.c.assign(std::size_t(r.m + 1) * (r.n + 1), make(mpq_class(0)));
      return r;
    }
    for (int i = 0; i <= r.m; ++i)
      for (int j = 0; j <= r.n; ++j)
        r.c.push_back(k * (axis == 0 ? f.at(i + 1, j) - f.at(i, j) : f.at(i, j + 1) - f.at(i, j)));
    return r;
  }
  template <class T>
  static T hull_of(const Net2<T>& g) {
    T h = g.c[0];
    for (const auto& x : g.c) h = h.hull(x);
    return h;
  }

  // One Krawczyk step on X = [u0, u1] x [t0, t1] for (F, F_u) in the interval type T (F's net in T: Fn): K(X);
  // 1 when K lies in X's interior, 0 when not, -1 when K is not computable (K untouched then). F is restricted
  // to X once; F(c), F_u(c) at the centre c (1/2, 1/2 of the box) and the hulls of the derivative nets on the
  // box (the convex hull property) enclose f(c) and the Jacobian J(X) = [[F_u, F_t], [F_uu, F_ut]] on X.
  template <class T, class Make>
  int krawczyk_in(const Net2<T>& Fn, const std::array<mpq_class, 4>& X, std::array<mpq_class, 4>& K,
                  Make&& make) const {
    if (X[0] >= 1 || X[2] >= 1) return -1;
    const Net2<T> G = restrict_to(restrict_to(Fn, 1, X[2], X[3], make), 0, X[0], X[1], make);
    const mpq_class su = X[1] - X[0], st = X[3] - X[2];
    const Net2<T> Gu = derivative_on(G, 0, su, make), Gt = derivative_on(G, 1, st, make);
    const Net2<T> Guu = derivative_on(Gu, 0, su, make), Gut = derivative_on(Gu, 1, st, make);
    const T half = make(mpq_class(1, 2));
    const T f[2] = {value_at(G, half, half), value_at(Gu, half, half)};
    const T J[2][2] = {{hull_of(Gu), hull_of(Gt)}, {hull_of(Guu), hull_of(Gut)}};
    for (const auto& row : J)
      for (const auto& x : row)
        if (!x.finite()) return -1;
    const double a = J[0][0].mid(), b = J[0][1].mid(), c = J[1][0].mid(), d = J[1][1].mid(), det = a * d - b * c;
    if (!(std::fabs(det) > 0) || !std::isfinite(det)) return -1;
    const double yd[2][2] = {{d / det, -b / det}, {-c / det, a / det}};  // any Y is sound
    std::array<std::array<T, 2>, 2> Y;
    for (int r = 0; r < 2; ++r)
      for (int s = 0; s < 2; ++s) {
        if (!std::isfinite(yd[r][s])) return -1;
        Y[r][s] = make(mpq_class(yd[r][s]));
      }
    const mpq_class cen[2] = {(X[0] + X[1]) / 2, (X[2] + X[3]) / 2};
    bool inside = true;
    std::array<mpq_class, 4> out;
    for (int i = 0; i < 2; ++i) {
      T k = make(cen[i]) - (Y[i][0] * f[0] + Y[i][1] * f[1]);
      for (int j = 0; j < 2; ++j) {
        const T e = make(mpq_class(i == j ? 1 : 0)) - (Y[i][0] * J[0][j] + Y[i][1] * J[1][j]);
        const mpq_class dlo = X[2 * j] - cen[j], dhi = X[2 * j + 1] - cen[j];
        k = k + e * (make(dlo).hull(make(dhi)));
      }
      if (!k.finite()) return -1;
      out[2 * i] = k.lower();
      out[2 * i + 1] = k.upper();
      inside = inside && out[2 * i] > X[2 * i] && out[2 * i + 1] < X[2 * i + 1];
    }
    K = out;
    return inside ? 1 : 0;
  }

  // Krawczyk in intervals of doubles first, in MPFI at precision_bits when doubles do not prove `want`
  // (1: K inside X's interior; 0: K computed).
  int krawczyk(const std::array<mpq_class, 4>& X, std::array<mpq_class, 4>& K, int want) const {
    std::array<mpq_class, 4> k;
    const int r = krawczyk_in(dF, X, k, [](const mpq_class& x) { return DI::of(x); });
    if (r >= want) {
      K = k;
      return r;
    }
    return krawczyk_in(mF, X, K, [&](const mpq_class& x) { return mk(x); });
  }

  // The exclusion tree of an end: preorder '1' split / '0' leaf over [0, 1] x [lo, hi].
  struct Tree {
    const std::string& s;
    std::size_t pos = 0;
  };
  void exclusion(Tree& tr, const Net2<DI>& f, const Net2<DI>& fu, const mpq_class& u0, const mpq_class& u1,
                 const mpq_class& t0, const mpq_class& t1, int depth, const mpq_class& ku0, const mpq_class& ku1,
                 std::optional<Net2<MI>>& strip_f, std::optional<Net2<MI>>& strip_fu, const mpq_class& lo,
                 const mpq_class& hi, const std::string& claim) {
    if (tr.pos >= tr.s.size()) reject(claim, "the exclusion tree ends early: part of [0, 1] x the run is not covered");
    const char ch = tr.s[tr.pos++];
    if (ch == '0') {
      ++tree_leaves;
      if (u0 >= ku0 && u1 <= ku1) return;  // inside the Krawczyk box's u-range (its zero is the end's)
      if (f.strict_sign() != 0 || fu.strict_sign() != 0) return;
      ++tree_mpfi;  // not proved in doubles: the same leaf in MPFI, restricted from the strip directly
      if (!strip_f) strip_f = restrict_mi(mF, 1, lo, hi);
      if (!strip_fu) strip_fu = restrict_mi(mFu, 1, lo, hi);
      const Net2<MI> g = restrict_mi(restrict_mi(*strip_f, 1, (t0 - lo) / (hi - lo), (t1 - lo) / (hi - lo)), 0, u0, u1);
      const Net2<MI> gu =
          restrict_mi(restrict_mi(*strip_fu, 1, (t0 - lo) / (hi - lo), (t1 - lo) / (hi - lo)), 0, u0, u1);
      if (g.strict_sign() != 0 || gu.strict_sign() != 0) return;
      reject(claim, "the exclusion leaf u in [" + q(u0) + ", " + q(u1) + "], t in [" + q(t0) + ", " + q(t1) +
                        "]: neither F nor F_u is of one proved sign there (another zero of (F, F_u) is not excluded)");
    }
    if (ch != '1') reject("certificate format", claim + ": the exclusion tree must be a string of '0' and '1'");
    if (depth >= kMaxTreeDepth)
      reject("certificate format", claim + ": the exclusion tree is deeper than " + std::to_string(kMaxTreeDepth));
    const DI half(0.5, 0.5);
    const mpq_class um = (u0 + u1) / 2, tm = (t0 + t1) / 2;
    const bool split_t = depth % 2 == 1;
    auto [fl, fh] = split_half(f, 0, half);
    auto [gl, gh] = split_half(fu, 0, half);
    for (int side = 0; side < 2; ++side) {
      const Net2<DI>& a = side ? fh : fl;
      const Net2<DI>& b = side ? gh : gl;
      const mpq_class a0 = side ? um : u0, a1 = side ? u1 : um;
      if (!split_t) {
        exclusion(tr, a, b, a0, a1, t0, t1, depth + 1, ku0, ku1, strip_f, strip_fu, lo, hi, claim);
        continue;
      }
      auto [al, ah] = split_half(a, 1, half);
      auto [bl, bh] = split_half(b, 1, half);
      exclusion(tr, al, bl, a0, a1, t0, tm, depth + 1, ku0, ku1, strip_f, strip_fu, lo, hi, claim);
      exclusion(tr, ah, bh, a0, a1, tm, t1, depth + 1, ku0, ku1, strip_f, strip_fu, lo, hi, claim);
    }
  }

  std::array<mpq_class, 4> box4(const json& j, const std::string& place) {
    if (!j.is_array() || j.size() != 4) reject("certificate format", place + ": expected [u0, u1, t0, t1]");
    std::array<mpq_class, 4> b;
    for (std::size_t i = 0; i < 4; ++i) b[i] = rational(j[i], place + "[" + std::to_string(i) + "]", kMaxRationalBits);
    return b;
  }

  void end_piece(const json& it, const std::string& name, const std::string& claim, const mpq_class& lo,
                 const mpq_class& hi, std::vector<BNode>& seq, long& excl) {
    const json& boxes = at(it, "boxes", name);
    if (!boxes.is_array() || boxes.empty() || boxes.size() > kMaxChain)
      reject("certificate format",
             name + ": the Krawczyk chain (boxes) must list 1 to " + std::to_string(kMaxChain) + " boxes");
    std::vector<std::array<mpq_class, 4>> Y;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      Y.push_back(box4(boxes[i], name + " box " + std::to_string(i + 1)));
      if (!(Y.back()[0] < Y.back()[1]) || !(Y.back()[2] < Y.back()[3]))
        reject("certificate format", name + ": chain box " + std::to_string(i) + " is empty in a coordinate");
    }
    // faces: F(0, t) = α^4 det A(t) and F(1, t) = β^4 det B(t) < 0 on the run (the lemma's hypothesis)
    const Net2<DI> run_d = restrict_di(dF, 1, lo, hi), run_ud = restrict_di(dFu, 1, lo, hi);
    std::optional<Net2<MI>> run, run_u;  // in MPFI only where doubles do not decide
    auto faces_negative = [](const auto& g) {
      for (int j = 0; j <= g.n; ++j)
        if (g.at(0, j).sign() != -1 || g.at(g.m, j).sign() != -1) return false;
      return true;
    };
    if (!faces_negative(run_d)) {
      run = restrict_mi(mF, 1, lo, hi);
      if (!faces_negative(*run)) reject(claim, "the faces: F(0, t) or F(1, t) is not proved < 0 on the run");
    }
    // Krawczyk: X = Y_0 covers the run in t, K(X) inside X's interior; the chain keeps the zero
    const auto& X = Y[0];
    if (X[2] > lo || X[3] < hi) reject(claim, "the Krawczyk box's t-range does not cover the run");
    if (sgn(X[0]) < 0 || X[1] > 1) reject(claim, "the Krawczyk box's u-range is not inside [0, 1]");
    std::array<mpq_class, 4> K;
    if (krawczyk(X, K, 1) != 1)
      reject(claim, "Krawczyk's K(X) is not inside the interior of X: the box is not proved to hold one zero");
    for (std::size_t i = 0; i + 1 < Y.size(); ++i) {
      auto keeps = [&](const std::array<mpq_class, 4>& K2) {
        for (int v = 0; v < 2; ++v)
          if (Y[i + 1][2 * v] > std::max(Y[i][2 * v], K2[2 * v]) ||
              Y[i + 1][2 * v + 1] < std::min(Y[i][2 * v + 1], K2[2 * v + 1]))
            return false;
        return true;
      };
      std::array<mpq_class, 4> K2 = K;
      if (i > 0 && krawczyk_in(dF, Y[i], K2, [](const mpq_class& x) { return DI::of(x); }) < 0) K2 = {1, -1, 1, -1};
      if (K2[0] > K2[1] || !keeps(K2)) {  // in MPFI when doubles do not show it
        if (krawczyk_in(mF, Y[i], K2, [&](const mpq_class& x) { return mk(x); }) < 0)
          reject(claim, "K(Y_" + std::to_string(i) + ") is not computable");
        if (!keeps(K2))
          reject(claim, "chain box " + std::to_string(i + 1) + " does not contain Y_" + std::to_string(i) + " ∩ K(Y_" +
                            std::to_string(i) + ")");
      }
    }
    // exclusion by the certificate's tree
    const json& ex = at(it, "exclusion", name);
    if (!ex.is_string() || ex.get_ref<const std::string&>().size() > kMaxTreeNodes)
      reject("certificate format",
             name + ".exclusion: expected a string of at most " + std::to_string(kMaxTreeNodes) + " '0'/'1'");
    Tree tr{ex.get_ref<const std::string&>()};
    const long before = tree_leaves;
    exclusion(tr, run_d, run_ud, 0, 1, lo, hi, 0, X[0], X[1], run, run_u, lo, hi, claim);
    if (tr.pos != tr.s.size()) reject("certificate format", name + ".exclusion: characters after the end of the tree");
    excl += tree_leaves - before;
    // the bracket: inside the run, holding the run ∩ the last chain box's t-range
    const json& br = at(it, "bracket", name);
    if (!br.is_array() || br.size() != 2) reject("certificate format", name + ".bracket: expected [lo, hi]");
    const mpq_class b0 = rational(br[0], name + ".bracket[0]", kMaxRationalBits),
                    b1 = rational(br[1], name + ".bracket[1]", kMaxRationalBits);
    const mpq_class need_lo = std::max(lo, Y.back()[2]), need_hi = std::min(hi, Y.back()[3]);
    if (need_lo > need_hi) reject(claim, "the last chain box misses the run");
    if (b0 > need_lo || b1 < need_hi || b0 < lo || b1 > hi || b0 > b1)
      reject(claim, "the bracket [" + q(b0) + ", " + q(b1) + "] does not hold [" + q(need_lo) + ", " + q(need_hi) +
                        "] (the run ∩ the last chain box) inside the run");
    BNode e;
    e.lo = b0;
    e.hi = b1;
    e.status = St::touching;
    e.name = claim;
    seq.push_back(e);
  }

  static Net2<DI> converted_di(const Net2<MI>& f) {
    Net2<DI> r;
    r.m = f.m;
    r.n = f.n;
    for (const auto& x : f.c) r.c.push_back(DI::of(x));
    return r;
  }

  // What the pieces hold, counted as they are checked.
  struct PieceTally {
    std::size_t nboxes = 0, n_in = 0, n_out = 0, n_end = 0;
    long excl = 0;
    std::vector<std::string> kinds;
    std::vector<BNode> ends;
  };

  void run() {
    const json& fmt = at(cert, "format", "certificate");
    if (fmt != "eccd-bezier-certificate/2")
      reject("certificate format", "format: expected \"eccd-bezier-certificate/2\", got " + shown(fmt));
    checked.push_back("certificate format: eccd-bezier-certificate/2");
    scene_claim();
    bits = int(whole(at(cert, "precision_bits", "certificate"), "precision_bits", 64, 1024));
    net_claim();
    const PieceTally tally = pieces_claim();
    answer_claim(cert, timeline_of(tally), kMaxRationalBits, kMaxRationalBits * 30103 / 100000 + 64, checked);
  }

  // The pieces cover [0, 1] in order, each proved as its kind says; an end lies between an in- and an out-piece.
  PieceTally pieces_claim() {
    const json& items = at(cert, "pieces", "certificate");
    if (!items.is_array() || items.empty() || items.size() > kMaxPieces)
      reject("certificate format",
             "pieces: expected a non-empty list of at most " + std::to_string(kMaxPieces) + " pieces");
    mpq_class cursor = 0;
    PieceTally tally;
    for (std::size_t k = 0; k < items.size(); ++k) {
      const json& it = items[k];
      const std::string name = "piece " + std::to_string(k + 1);
      const json& kind = at(it, "kind", name);
      if (kind != "in" && kind != "out" && kind != "end")
        reject("certificate format", name + ": kind must be \"in\", \"out\" or \"end\"");
      const mpq_class lo = rational(at(it, "lo", name), name + ".lo", kMaxRationalBits),
                      hi = rational(at(it, "hi", name), name + ".hi", kMaxRationalBits);
      const std::string claim = name + " (" + kind.get<std::string>() + ", t in [" + q(lo) + ", " + q(hi) + "])";
      if (lo != cursor)
        reject("coverage",
               claim + ": starts at " + q(lo) + ", the previous piece ends at " + q(cursor) + " (a gap or an overlap)");
      if (!(lo < hi) || hi > 1) reject("coverage", claim + ": not a range inside [0, 1]");
      cursor = hi;
      tally.kinds.push_back(kind.get<std::string>());
      if (kind == "end") {
        end_piece(it, name, claim, lo, hi, tally.ends, tally.excl);
        ++tally.n_end;
        continue;
      }
      const bool in = kind == "in";
      box_piece(it, name, claim, lo, hi, in, tally.nboxes);
      ++(in ? tally.n_in : tally.n_out);
    }
    if (cursor != 1) reject("coverage", "the pieces end at t = " + q(cursor) + ", not 1");
    const std::vector<std::string>& kinds = tally.kinds;
    for (std::size_t k = 0; k < kinds.size(); ++k)
      if (kinds[k] == "end" && (k == 0 || k + 1 == kinds.size() || kinds[k - 1] == "end" || kinds[k + 1] == "end" ||
                                kinds[k - 1] == kinds[k + 1]))
        reject("coverage", "piece " + std::to_string(k + 1) + ": an end must lie between an in-piece and an out-piece");
    checked.push_back("pieces: " + std::to_string(tally.n_in) + " in and " + std::to_string(tally.n_out) + " out (" +
                      std::to_string(tally.nboxes) + " boxes, signs proved, " + std::to_string(boxes_mpfi) +
                      " in MPFI) and " + std::to_string(tally.n_end) + " ends (faces, Krawczyk, exclusion tree of " +
                      std::to_string(tally.excl) + " leaves, " + std::to_string(tree_mpfi) + " in MPFI) cover [0, 1]");
    return tally;
  }

  // An in- or out-piece: F < 0 (in) or > 0 (out) on each box, and the boxes cover the piece.
  void box_piece(const json& it, const std::string& name, const std::string& claim, const mpq_class& lo,
                 const mpq_class& hi, bool in, std::size_t& nboxes) {
    const json& boxes = at(it, "boxes", name);
    if (!boxes.is_array() || boxes.empty()) reject("certificate format", name + ": boxes must be a non-empty list");
    nboxes += boxes.size();
    if (nboxes > kMaxBoxes) reject("certificate format", "pieces: more than " + std::to_string(kMaxBoxes) + " boxes");
    check_box_cover(signed_boxes(boxes, name, claim, lo, hi, in), in, lo, hi, claim);
  }

  // The boxes, each with its sign proved: in intervals of doubles from the net in doubles (widened outwards: a
  // proof too); MPFI (the strip restricted at precision_bits) only where they do not decide.
  std::vector<std::array<mpq_class, 4>> signed_boxes(const json& boxes, const std::string& name,
                                                     const std::string& claim, const mpq_class& lo, const mpq_class& hi,
                                                     bool in) {
    const Net2<DI> strip_d = restrict_di(dF, 1, lo, hi);
    std::optional<Net2<MI>> strip_m;
    std::map<std::pair<mpq_class, mpq_class>, Net2<DI>> by_t_d;
    std::map<std::pair<mpq_class, mpq_class>, Net2<MI>> by_t;
    std::vector<std::array<mpq_class, 4>> bx;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const auto b = box4(boxes[i], name + " box " + std::to_string(i + 1));
      if (!(0 <= b[0] && b[0] < b[1] && b[1] <= 1 && lo <= b[2] && b[2] < b[3] && b[3] <= hi))
        reject("certificate format",
               name + " box " + std::to_string(i + 1) + ": not [u0, u1, t0, t1] inside [0, 1] x [lo, hi]");
      const mpq_class t0 = (b[2] - lo) / (hi - lo), t1 = (b[3] - lo) / (hi - lo);
      auto cd = by_t_d.find({t0, t1});
      if (cd == by_t_d.end()) cd = by_t_d.emplace(std::make_pair(t0, t1), restrict_di(strip_d, 1, t0, t1)).first;
      if (restrict_di(cd->second, 0, b[0], b[1]).strict_sign() == (in ? -1 : 1)) {
        bx.push_back(b);
        continue;
      }
      ++boxes_mpfi;
      if (!strip_m) strip_m = restrict_mi(mF, 1, lo, hi);
      auto cached = by_t.find({t0, t1});
      if (cached == by_t.end()) cached = by_t.emplace(std::make_pair(t0, t1), restrict_mi(*strip_m, 1, t0, t1)).first;
      const Net2<MI> g = restrict_mi(cached->second, 0, b[0], b[1]);
      if (g.strict_sign() != (in ? -1 : 1))
        reject(claim, "box " + std::to_string(i + 1) + " (u in [" + q(b[0]) + ", " + q(b[1]) + "], t in [" + q(b[2]) +
                          ", " + q(b[3]) + "]): its control points are not all " + (in ? "< 0" : "> 0"));
      bx.push_back(b);
    }
    return bx;
  }

  // Where the ranges r cover [a, b] from a: nothing if they do, else how far.
  static std::optional<mpq_class> uncovered_from(std::vector<std::pair<mpq_class, mpq_class>> r, const mpq_class& a,
                                                 const mpq_class& b) {
    std::sort(r.begin(), r.end());
    mpq_class c = a;
    for (const auto& [x, y] : r) {
      if (x > c) break;
      c = std::max(c, y);
    }
    return c >= b ? std::optional<mpq_class>() : std::optional<mpq_class>(c);
  }

  // The boxes' t-ranges cover [lo, hi]; in an in-piece, the boxes of each t-range cover u in [0, 1] too.
  static void check_box_cover(const std::vector<std::array<mpq_class, 4>>& bx, bool in, const mpq_class& lo,
                              const mpq_class& hi, const std::string& claim) {
    std::vector<std::pair<mpq_class, mpq_class>> tr;
    if (in) {
      std::map<std::pair<mpq_class, mpq_class>, std::vector<std::pair<mpq_class, mpq_class>>> groups;
      for (const auto& b : bx) groups[{b[2], b[3]}].push_back({b[0], b[1]});
      for (const auto& [t, us] : groups) {
        if (auto c = uncovered_from(us, 0, 1))
          reject(claim, "the boxes at t in [" + q(t.first) + ", " + q(t.second) +
                            "]: their u-ranges do not cover [0, 1] (covered up to " + q(*c) + ")");
        tr.push_back(t);
      }
    } else {
      for (const auto& b : bx) tr.push_back({b[2], b[3]});
    }
    if (auto c = uncovered_from(tr, lo, hi))
      reject(claim, "the boxes' t-ranges do not cover the piece (covered up to " + q(*c) + ")");
  }

  // The timeline: 0, cell, end, cell, ..., 1; cells alternate between overlapping (in) and separate (out).
  static std::vector<BNode> timeline_of(const PieceTally& tally) {
    std::vector<BNode> seq;
    St cur = tally.kinds.front() == "in" ? St::overlapping : St::separate;
    auto point = [&](const mpq_class& x, bool cell, St s, const std::string& nm) {
      BNode b;
      b.lo = b.hi = x;
      b.cell = cell;
      b.status = s;
      b.name = nm;
      seq.push_back(b);
    };
    point(0, false, cur, "instant 0");
    mpq_class cell_lo = 0;
    for (const BNode& e : tally.ends) {
      point((cell_lo + e.lo) / 2, true, cur, "the cell before " + e.name);
      seq.push_back(e);
      cur = cur == St::separate ? St::overlapping : St::separate;
      cell_lo = e.hi;
    }
    point((cell_lo + 1) / 2, true, cur, "the last cell");
    point(1, false, cur, "instant 1");
    return seq;
  }
};

}  // namespace

void check_bezier_certificate(const CheckScene& scene, const json& cert, std::vector<std::string>& checked) {
  BezierChecker c{scene, cert, checked, 160, {}, {}, {}, {}, {}, {}, 0, 0, 0};
  c.run();
}

}  // namespace eccd::check
