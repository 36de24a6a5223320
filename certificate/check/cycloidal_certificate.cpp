// The independent check of "eccd-cycloidal-certificate/2" (docs/certificate-format.md,
// "Cycloidal scenes"; docs/checking.md): a 2D scene whose motions are static or
// cycloidal (003 section V; not rational, so Δ(t), the discriminant of
// f(λ; t) = det(λA(t) - B(t)), is not a polynomial). Every claim is proved by
// the checker's own MPFI enclosures at the certificate's precision_bits:
//   A(t) = N(t)^T Q N(t) with N the inverse of the object's motion
//   X = c + R(t)(X_body - c) + V(t) (scene-format.md): N = [[R^T, -R^T d],
//   [0, 1]], d = (I - R) c + V; f's coefficients by the adjugate identity
//   det(λA - B) = λ³ det A - λ² tr(adj(A) B) + λ tr(A adj(B)) - det B; Δ the
//   cubic's discriminant; Δ' in forward mode (a value and a derivative, each
//   an interval; sin and cos of π(θ0 + θ1 t) by MPFI).
// Claims, in order: certificate format; scene; timeline (instant, cell, ...,
// instant over [0, 1], brackets disjoint, each sample strictly between);
// instants (an end: the static test at t; a simple root: Δ at lo and hi of
// proved opposite signs and Δ' of one proved sign on the bracket, its status
// by the signs of P = 9 g3 g0 - g2 g1 and D = g2² - 3 g3 g1 on it (003
// Theorem 6); an undecided stretch: |Δ| <= ε proved on it, ε at most 2^-10 of
// the checker's bound of |Δ| on [0, 1]); gaps (each piece between brackets
// and gap points root-free by the proof the certificate names in gap_proofs:
// "natural" (an enclosure of Δ on the piece excludes 0), "mean_value"
// (Δ(m) + Δ'([a, b])([a, b] - m) excludes 0), "monotone" (Δ' of one proved
// sign, Δ(a), Δ(b) of the same proved sign); that one first, the other two
// when the checker's own enclosures do not prove it); cells (the static test at each
// sample); answer (assembled from the checked timeline, undecided stretches
// as undecided instants: collides true iff a collision is proved, else null
// when a stretch is undecided, never false then).
// The static test (003 Theorem 6 for ellipses): Δ < 0 overlapping; Δ > 0:
// f has three real roots, separate iff two of them are negative (the sign
// changes of f(-λ), Descartes, exact for a real-rooted cubic), overlapping if
// none. Nothing is searched: every point and every proof is the certificate's.
#include "certificate/check/claims.hpp"
#include "certificate/check/interval.hpp"
#include "certificate/check/kinds.hpp"

#include <array>
#include <cstdio>
#include <optional>

namespace eccd::check {

namespace {

const std::size_t kMaxRationalBits = 1024, kMaxGapPoints = 20000, kMaxTimeline = 4001;

// A value and its derivative in t, each enclosed (forward mode).
struct DMI {
  MI v, d;
};
DMI operator+(const DMI& a, const DMI& b) { return {a.v + b.v, a.d + b.d}; }
DMI operator-(const DMI& a, const DMI& b) { return {a.v - b.v, a.d - b.d}; }
DMI operator*(const DMI& a, const DMI& b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }

struct Cyc {
  int bits = 160;
  MI pi;
  MI mk(const mpq_class& q) const { return MI(q, bits); }
  MI konst(const mpq_class& q, MI*) const { return mk(q); }
  DMI konst(const mpq_class& q, DMI*) const { return {mk(q), mk(0)}; }
  void sin_cos_pi(const MI& x, MI& s, MI& c) const {
    MI a = pi * x;
    s = a;
    c = a;
    mpfi_sin(s.get(), a.get());
    mpfi_cos(c.get(), a.get());
  }
  void sin_cos_pi(const DMI& x, DMI& s, DMI& c) const {
    MI sv, cv;
    sin_cos_pi(x.v, sv, cv);
    const MI dx = pi * x.d;
    s = {sv, cv * dx};
    c = {cv, mk(0) - sv * dx};
  }
};

template <class R>
using M3 = std::array<std::array<R, 3>, 3>;

template <class R>
R det3(const M3<R>& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
template <class R>
M3<R> adj3(const M3<R>& m) {
  M3<R> a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      a[i][j] = m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];  // cofactor (j, i): cyclic indices carry the sign
    }
  return a;
}
template <class R>
R trace_product(const M3<R>& x, const M3<R>& y) {
  R t = x[0][0] * y[0][0];
  bool first = true;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      if (first) {
        first = false;
        continue;
      }
      t = t + x[i][k] * y[k][i];
    }
  return t;
}

std::string decimal_text(const mpq_class& x) {  // about 6 significant digits, for messages
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x.get_d());
  return buf;
}

struct Obj {
  std::array<std::array<mpq_class, 3>, 3> Q;
  mpq_class cx, cy, th0, th1, x0, x1, y0, y1;
};

struct CycloidalChecker {
  const CheckScene& sc;
  const json& cert;
  std::vector<std::string>& checked;
  Cyc cy;
  Obj oa, ob;

  Obj object(const CheckObject& o, const char* which) {
    Obj r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.Q[i][j] = o.Q[std::size_t(i)][std::size_t(j)];
    const mpq_class det = r.Q[0][0] * r.Q[1][1] - r.Q[0][1] * r.Q[1][0];
    if (sgn(det) == 0) reject("scene", std::string("object ") + which + ": not an ellipse (singular quadratic part)");
    // the centre: Q[0:2, 0:2] c = -Q[0:2, 2]
    r.cx = (-r.Q[0][2] * r.Q[1][1] + r.Q[1][2] * r.Q[0][1]) / det;
    r.cy = (-r.Q[1][2] * r.Q[0][0] + r.Q[0][2] * r.Q[1][0]) / det;
    if (o.motion_type == "cycloidal") {
      r.th0 = o.cycloid[0];
      r.th1 = o.cycloid[1];
      r.x0 = o.cycloid[2];
      r.x1 = o.cycloid[3];
      r.y0 = o.cycloid[4];
      r.y1 = o.cycloid[5];
    } else if (o.motion_type != "static") {
      reject("scene", std::string("object ") + which + " has a " + o.motion_type +
                          " motion beside a cycloidal one: only static and cycloidal motions combine");
    }
    return r;
  }

  // A(t) = N^T Q N, N the inverse of X -> R X + d (d = (I - R) c + V): N = [[R^T, -R^T d], [0, 1]].
  template <class R>
  M3<R> quadric(const Obj& o, const R& t) const {
    R* tag = nullptr;
    R s, c;
    cy.sin_cos_pi(cy.konst(o.th0, tag) + cy.konst(o.th1, tag) * t, s, c);
    const R one = cy.konst(1, tag), zero = cy.konst(0, tag);
    const R cx = cy.konst(o.cx, tag), cyy = cy.konst(o.cy, tag);
    const R dx = (one - c) * cx + s * cyy + cy.konst(o.x0, tag) + cy.konst(o.x1, tag) * t;  // R = [[c, -s], [s, c]]
    const R dy = zero - s * cx + (one - c) * cyy + cy.konst(o.y0, tag) + cy.konst(o.y1, tag) * t;
    M3<R> N;
    N[0] = {c, s, zero - (c * dx + s * dy)};
    N[1] = {zero - s, c, s * dx - c * dy};
    N[2] = {zero, zero, one};
    M3<R> QN, A;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        QN[i][j] = cy.konst(o.Q[i][0], tag) * N[0][j] + cy.konst(o.Q[i][1], tag) * N[1][j] +
                   cy.konst(o.Q[i][2], tag) * N[2][j];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A[i][j] = N[0][i] * QN[0][j] + N[1][i] * QN[1][j] + N[2][i] * QN[2][j];
    return A;
  }
  template <class R>
  std::array<R, 4> g_at(const R& t) const {  // g_0 .. g_3 of det(λA - B)
    const M3<R> A = quadric(oa, t), B = quadric(ob, t);
    R* tag = nullptr;
    const R zero = cy.konst(0, tag);
    return {zero - det3(B), trace_product(A, adj3(B)), zero - trace_product(adj3(A), B), det3(A)};
  }
  template <class R>
  static R disc(const std::array<R, 4>& g) {
    const R &a = g[3], &b = g[2], &c = g[1], &d = g[0];
    return b * b * c * c - small(4, b * b * b * d) - small(4, a * c * c * c) - small(27, a * a * d * d) +
           small(18, a * b * c * d);
  }
  template <class R>
  static R small(int n, const R& x) {  // n x by additions (exact)
    R r = x;
    for (int i = 1; i < n; ++i) r = r + x;
    return r;
  }

  MI point(const mpq_class& t) const { return cy.mk(t); }
  MI range(const mpq_class& a, const mpq_class& b) const { return MI(a, b, cy.bits); }
  MI delta(const MI& t) const { return disc(g_at(t)); }
  MI delta_prime(const mpq_class& a, const mpq_class& b) const {
    const DMI t{range(a, b), cy.mk(1)};
    const std::array<DMI, 4> g = g_at(t);
    // Δ(g) in forward mode
    const DMI &A = g[3], &B = g[2], &C = g[1], &D = g[0];
    auto sm = [](int n, const DMI& x) {
      DMI r = x;
      for (int i = 1; i < n; ++i) r = r + x;
      return r;
    };
    const DMI d =
        B * B * C * C - sm(4, B * B * B * D) - sm(4, A * C * C * C) - sm(27, A * A * D * D) + sm(18, A * B * C * D);
    return d.d;
  }
  MI mean_value(const mpq_class& a, const mpq_class& b) const {
    const mpq_class m = (a + b) / 2;
    return delta(point(m)) + delta_prime(a, b) * MI(mpq_class(a - m), mpq_class(b - m), cy.bits);
  }
  static mpq_class magnitude(const MI& x) {
    mpq_class l = abs(x.lower()), h = abs(x.upper());
    return l < h ? h : l;
  }
  mpq_class magnitude_upper(const mpq_class& a, const mpq_class& b) const {
    if (!delta(range(a, b)).finite() || !mean_value(a, b).finite())
      reject("instants", "no finite enclosure of Delta on [" + a.get_str() + ", " + b.get_str() + "]");
    const mpq_class x = magnitude(delta(range(a, b))), y = magnitude(mean_value(a, b));
    return x < y ? x : y;
  }
  // the static test at t: St, or nullopt when not proved
  std::optional<St> status_at(const mpq_class& t) const {
    const auto g = g_at(point(t));
    const int sd = disc(g).sign();
    if (sd == 0) return std::nullopt;
    if (sd < 0) return St::overlapping;
    const int seq[4] = {-g[3].sign(), g[2].sign(), -g[1].sign(), g[0].sign()};
    for (int s : seq)
      if (s == 0) return std::nullopt;
    int changes = 0;
    for (int k = 0; k + 1 < 4; ++k) changes += seq[k] != seq[k + 1];
    if (changes == 2) return St::separate;
    if (changes == 0) return St::overlapping;
    return std::nullopt;
  }
  std::optional<St> status_at_root(const mpq_class& a, const mpq_class& b) const {
    const auto g = g_at(range(a, b));
    const int sP = (small(9, g[3] * g[0]) - g[2] * g[1]).sign(), sD = (g[2] * g[2] - small(3, g[3] * g[1])).sign();
    if (sP == 0 || sD == 0) return std::nullopt;
    return sP * sD < 0 ? St::touching : St::overlapping;
  }

  struct Node {
    mpq_class lo, hi;
    bool cell = false, undecided = false;
    St status = St::separate;
    std::string kind, name, place;
    json entry;
  };

  void run() {
    check_header();
    const std::size_t approx_chars = kMaxRationalBits * 30103 / 100000 + 64;
    std::vector<Node> nodes = read_timeline(approx_chars);
    check_timeline_order(nodes);
    const json& aj = at(cert, "answer", "certificate");
    check_incomplete_claim(nodes, aj);
    check_instants(nodes);
    check_gaps(nodes);
    check_cells(nodes);
    answer(nodes, aj, approx_chars);
  }

  // The format, the scene (the scene file's, 2D, static and cycloidal motions) and the enclosures' precision.
  void check_header() {
    const json& fmt = at(cert, "format", "certificate");
    if (fmt != "eccd-cycloidal-certificate/2")
      reject("certificate format", "format: expected \"eccd-cycloidal-certificate/2\", got " + shown(fmt));
    checked.push_back("certificate format: eccd-cycloidal-certificate/2");
    const json& s = at(cert, "scene", "certificate");
    for (const char* k : {"dim", "a", "b"})
      if (at(s, k, "scene") != sc.doc.at(k))
        reject("scene", std::string("the certificate's \"") + k +
                            "\" differs from the scene file's: it is a certificate for another scene");
    if (sc.dim != 2 || !sc.cycloidal || sc.independent)
      reject("scene", "a cycloidal certificate is for 2D scenes with a cycloidal motion and a shared parameter");
    oa = object(sc.a, "a");
    ob = object(sc.b, "b");
    checked.push_back("scene: dim, a and b are the scene file's; 2D, static and cycloidal motions");
    cy.bits =
        int(whole(at(at(cert, "delta", "certificate"), "precision_bits", "delta"), "delta.precision_bits", 64, 1024));
    cy.pi = cy.mk(0);
    mpfi_set_prec(cy.pi.get(), cy.bits);
    mpfi_const_pi(cy.pi.get());
  }

  // The timeline's entries, read and checked one by one (instant, cell, instant, ..., instant).
  std::vector<Node> read_timeline(std::size_t approx_chars) const {
    const json& tl = at(cert, "timeline", "certificate");
    if (!tl.is_array() || tl.size() < 3 || tl.size() % 2 == 0 || tl.size() > kMaxTimeline)
      reject("timeline", "expected instant, cell, instant, ..., instant (an odd number >= 3 of entries, at most " +
                             std::to_string(kMaxTimeline) + ")");
    std::vector<Node> nodes;
    for (std::size_t k = 0; k < tl.size(); ++k)
      nodes.push_back(k % 2 == 1 ? cell_node(tl, k) : instant_node(tl, k, approx_chars));
    return nodes;
  }

  static Node cell_node(const json& tl, std::size_t k) {
    const std::string place = "timeline[" + std::to_string(k) + "]";
    Node n;
    n.place = place;
    n.entry = tl[k];
    const json& st = at(tl[k], "status", place);
    n.lo = n.hi = rational(at(tl[k], "cell_sample", place), place + ".cell_sample", kMaxRationalBits);
    n.cell = true;
    n.kind = "cell";
    n.name = "cell " + std::to_string(k / 2) + " (sample " + n.lo.get_str() + ")";
    n.status = status_named(st, place + ".status");
    return n;
  }

  static Node instant_node(const json& tl, std::size_t k, std::size_t approx_chars) {
    const std::string place = "timeline[" + std::to_string(k) + "]";
    Node n;
    n.place = place;
    n.entry = tl[k];
    const json& st = at(tl[k], "status", place);
    const json& in = at(tl[k], "instant", place);
    n.lo = rational(at(in, "lo", place + ".instant"), place + ".instant.lo", kMaxRationalBits);
    n.hi = rational(at(in, "hi", place + ".instant"), place + ".instant.hi", kMaxRationalBits);
    const json& kind = at(tl[k], "kind", place);
    n.kind = kind.is_string() ? kind.get<std::string>() : "";
    if (n.kind != "end" && n.kind != "simple_root" && n.kind != "undecided")
      reject("certificate format", place + ".kind: expected \"end\", \"simple_root\" or \"undecided\"");
    n.name = "instant " + std::to_string(k / 2) + " " + bracket_text(n.lo, n.hi);
    if (n.kind == "undecided") {
      if (st != "uncertain") reject(n.name, "an undecided stretch must have status \"uncertain\"");
      n.undecided = true;
    } else {
      n.status = status_named(st, place + ".status");
    }
    if (n.lo > n.hi) reject(n.name, "lo > hi");
    check_approx(at(in, "approx", place + ".instant"), n.lo, n.hi, n.name, place + ".instant.approx", approx_chars);
    return n;
  }

  // From 0 to 1, ends only at the ends, samples strictly between disjoint brackets.
  void check_timeline_order(const std::vector<Node>& nodes) {
    const Node &first = nodes.front(), &last = nodes.back();
    if (first.lo != 0 || (first.kind == "end" && first.hi != 0))
      reject("timeline", "the first instant must start at 0 (an end [0, 0], or a stretch from 0)");
    if (last.hi != 1 || (last.kind == "end" && last.lo != 1))
      reject("timeline", "the last instant must end at 1 (an end [1, 1], or a stretch to 1)");
    for (std::size_t k = 0; k < nodes.size(); k += 2)
      if (nodes[k].kind == "end" && k != 0 && k + 1 != nodes.size())
        reject(nodes[k].name, "an interior instant cannot be of kind \"end\"");
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k)
      if (!(nodes[k].hi < nodes[k + 1].lo))
        reject(nodes[k].cell ? nodes[k].name : nodes[k + 1].name,
               "each cell sample must lie strictly between the brackets of its two instants, and brackets must be "
               "disjoint");
    checked.push_back("timeline: " + std::to_string(nodes.size() / 2 + 1) + " instants and " +
                      std::to_string(nodes.size() / 2) + " cells in order, brackets disjoint");
  }

  // An incomplete certificate claims no more than it proves.
  static void check_incomplete_claim(const std::vector<Node>& nodes, const json& aj) {
    std::size_t undecided = 0;
    for (const auto& n : nodes) undecided += n.undecided;
    if (undecided && aj.is_object() && aj.contains("collides") && aj["collides"] == false)
      reject("answer", "answer.collides is false but " + std::to_string(undecided) +
                           " stretch(es) of the timeline are undecided: an incomplete certificate may claim a "
                           "collision where one is proved "
                           "(true), otherwise only null (unknown), never false");
  }

  // Each instant's claim: the static test at an end, a simple root of Δ and its status from P and D, or an
  // undecided stretch with |Δ| <= epsilon.
  void check_instants(const std::vector<Node>& nodes) {
    int roots = 0, stretches = 0;
    std::optional<mpq_class> whole_bound;
    for (std::size_t k = 0; k < nodes.size(); k += 2) {
      const Node& n = nodes[k];
      if (n.kind == "end") {
        check_end(n);
      } else if (n.kind == "simple_root") {
        ++roots;
        check_simple_root(n);
      } else {
        ++stretches;
        check_stretch(n, whole_bound);
      }
    }
    checked.push_back("instants: " + std::to_string(roots) +
                      " simple root(s) proved (opposite signs of Delta at the bracket ends, Delta' non-zero "
                      "on it; status from P and D), the ends by the static test, " +
                      std::to_string(stretches) + " undecided stretch(es) with |Delta| <= epsilon proved");
  }

  void check_end(const Node& n) const {
    const auto st = status_at(n.lo);
    if (!st)
      reject(n.name,
             "the static test at t = " + n.lo.get_str() + " is not proved at " + std::to_string(cy.bits) + " bits");
    if (*st != n.status)
      reject(n.name, std::string("the static test gives ") + name(*st) + ", not " + name(n.status) + " as claimed");
  }

  void check_simple_root(const Node& n) const {
    const int sl = delta(point(n.lo)).sign(), sh = delta(point(n.hi)).sign();
    if (sl == 0 || sh == 0 || sl == sh) reject(n.name, "Delta at lo and hi are not proved of opposite signs");
    if (delta_prime(n.lo, n.hi).sign() == 0)
      reject(n.name, "Delta' is not proved non-zero on the bracket: it may hold more than one root, or a multiple one");
    const auto st = status_at_root(n.lo, n.hi);
    if (!st) reject(n.name, "the signs of P and D are not proved on the bracket");
    if (*st != n.status)
      reject(n.name, std::string("P and D give ") + name(*st) + ", not " + name(n.status) + " as claimed");
  }

  // whole_bound: the bound of |Δ| on [0, 1], computed at the first stretch.
  void check_stretch(const Node& n, std::optional<mpq_class>& whole_bound) const {
    const json& ej = at(n.entry, "epsilon", n.place);
    mpq_class eps, unit;  // a decimal as the writer writes it (upper_decimal), or a rational "p/q"
    if (!(ej.is_string() && read_decimal(ej.get<std::string>(), 400, eps, unit)))
      eps = rational(ej, n.place + ".epsilon", kMaxRationalBits);
    if (sgn(eps) < 0) reject(n.name, "epsilon must not be negative");
    if (!whole_bound) whole_bound = magnitude_upper(0, 1);
    if (eps * 1024 > *whole_bound)
      reject(n.name,
             "epsilon is not small: more than 2^-10 of the checker's bound of |Delta| on [0, 1]; an undecided "
             "stretch claims Delta near 0");
    const mpq_class bound = magnitude_upper(n.lo, n.hi);
    if (bound > eps)
      reject(n.name, "|Delta| <= epsilon on the stretch is not proved (the checker's enclosure bounds it by " +
                         decimal_text(bound) + ", epsilon is " + decimal_text(eps) + ")");
  }

  // Δ has no root in [0, 1] outside the brackets: each gap, cut at the gap points, piece by piece as named.
  void check_gaps(const std::vector<Node>& nodes) {
    const json& gp = at(cert, "gap_points", "certificate");
    const json& proofs = at(cert, "gap_proofs", "certificate");
    if (!gp.is_array() || gp.size() > kMaxGapPoints)
      reject("certificate format",
             "gap_points: expected an array of at most " + std::to_string(kMaxGapPoints) + " points");
    if (!proofs.is_array()) reject("certificate format", "gap_proofs: expected an array, one proof per gap piece");
    std::vector<mpq_class> pts;
    for (std::size_t i = 0; i < gp.size(); ++i)
      pts.push_back(rational(gp[i], "gap_points[" + std::to_string(i) + "]", kMaxRationalBits));
    std::size_t used = 0, pieces = 0;
    for (std::size_t k = 0; k + 2 < nodes.size(); k += 2) {
      const mpq_class a = nodes[k].hi, b = nodes[k + 2].lo;
      std::vector<mpq_class> cut{a};
      while (used < pts.size() && pts[used] < b) {
        if (!(cut.back() < pts[used]))
          reject("gaps", "gap point " + pts[used].get_str() +
                             " is not strictly inside a gap, or the points are not increasing");
        cut.push_back(pts[used++]);
      }
      cut.push_back(b);
      for (std::size_t i = 0; i + 1 < cut.size(); ++i, ++pieces) {
        if (pieces >= proofs.size()) reject("certificate format", "gap_proofs: fewer proofs than gap pieces");
        check_gap_piece(cut[i], cut[i + 1], proofs[pieces], pieces);
      }
    }
    if (used != pts.size()) reject("gaps", "gap point " + pts[used].get_str() + " is not strictly inside a gap");
    if (pieces != proofs.size()) reject("certificate format", "gap_proofs: more proofs than gap pieces");
    checked.push_back("gaps: Delta has no root in [0, 1] outside the brackets (" + std::to_string(pieces) +
                      " piece(s), each proved root-free as named)");
  }

  // Δ is root-free on [a, b] by the proof `how` (gap_proofs[index]).
  void check_gap_piece(const mpq_class& a, const mpq_class& b, const json& how, std::size_t index) const {
    const std::string where = "[" + a.get_str() + ", " + b.get_str() + "]";
    auto holds = [&](const std::string& proof) {
      if (proof == "natural") return delta(range(a, b)).sign() != 0;
      if (proof == "mean_value") return mean_value(a, b).sign() != 0;
      const int sa = delta(point(a)).sign(), sb = delta(point(b)).sign();
      return delta_prime(a, b).sign() != 0 && sa != 0 && sa == sb;
    };
    if (how != "natural" && how != "mean_value" && how != "monotone")
      reject("certificate format",
             "gap_proofs[" + std::to_string(index) + "]: expected \"natural\", \"mean_value\" or \"monotone\"");
    // the named proof first; the checker's enclosures are not the writer's, so the other two (a fixed, bounded
    // list, no subdivision) may stand in when the named one is not proved at this precision
    bool ok = holds(how.get<std::string>());
    for (const char* other : {"natural", "mean_value", "monotone"})
      if (!ok && how != other) ok = holds(other);
    if (!ok)
      reject("gaps", "Delta is not proved root-free on " + where + " (the " + how.get<std::string>() +
                         " proof the certificate names, nor another)");
  }

  // The static test at each cell's sample proves its status.
  void check_cells(const std::vector<Node>& nodes) {
    for (std::size_t k = 1; k < nodes.size(); k += 2) {
      const auto st = status_at(nodes[k].lo);
      if (!st) reject(nodes[k].name, "the static test at the sample is not proved");
      if (*st != nodes[k].status)
        reject(nodes[k].name, std::string("the static test gives ") + name(*st) + ", not " + name(nodes[k].status));
    }
    checked.push_back("cells: the static test at each of the " + std::to_string(nodes.size() / 2) +
                      " sample(s) proves the claimed status");
  }

  // The answer of the checked timeline (docs/answer-format.md): undecided instants are listed and break runs;
  // a run of nodes in collision is an interval (from the instant before a leading cell to the one after a
  // trailing cell); touching cells make contact intervals; touching instants outside them are contacts.
  void answer(const std::vector<Node>& seq, const json& aj, std::size_t approx_chars) {
    using Br = std::pair<mpq_class, mpq_class>;
    auto br = [&](std::size_t k) { return Br{seq[k].lo, seq[k].hi}; };
    auto in_c = [&](std::size_t k) { return !seq[k].undecided && seq[k].status != St::separate; };
    auto touching_cell = [&](std::size_t k) { return k < seq.size() && seq[k].cell && seq[k].status == St::touching; };
    std::vector<std::pair<Br, Br>> intervals, contact_intervals;
    std::vector<Br> contacts, undecided;
    for (std::size_t k = 0; k < seq.size(); ++k) {
      if (!touching_cell(k)) continue;
      std::size_t e = k;
      while (touching_cell(e + 2) && !seq[e + 1].undecided && seq[e + 1].status == St::touching) e += 2;
      contact_intervals.push_back({br(k - 1), br(e + 1)});
      k = e;
    }
    auto contact = [&](std::size_t k) {
      if (!touching_cell(k + 1) && !(k > 0 && touching_cell(k - 1))) contacts.push_back(br(k));
    };
    for (std::size_t k = 0; k < seq.size(); ++k) {
      if (seq[k].undecided) {
        undecided.push_back(br(k));
        continue;
      }
      if (!seq[k].cell && seq[k].status == St::touching) contact(k);
      if (!in_c(k)) continue;
      std::size_t e = k;
      while (e + 1 < seq.size() && in_c(e + 1)) {
        ++e;
        if (!seq[e].cell && seq[e].status == St::touching) contact(e);
      }
      intervals.push_back({seq[k].cell ? br(k - 1) : br(k), seq[e].cell ? br(e + 1) : br(e)});
      k = e;
    }
    if (!aj.is_object()) reject("certificate format", "answer: expected an object");
    for (auto it = aj.begin(); it != aj.end(); ++it)
      if (it.key() != "collides" && it.key() != "intervals" && it.key() != "first_contact" && it.key() != "contacts" &&
          it.key() != "contact_intervals" && it.key() != "undecided")
        reject("certificate format", "answer." + it.key() + ": not a key of the answer");
    const json want_collides = !intervals.empty() ? json(true) : undecided.empty() ? json(false) : json(nullptr);
    const json& col = at(aj, "collides", "answer");
    if (col != want_collides)
      reject("answer",
             "answer.collides is " + shown(col) + " but the checked timeline proves " +
                 (want_collides.is_null() ? std::string("neither: no collision is proved and a stretch is undecided, "
                                                        "so collides must be null (unknown), never false")
                  : want_collides == true ? std::string("a collision")
                                          : std::string("there is none")));
    auto inst = [&](const json& j, const std::string& place, const Br& want) {
      if (!j.is_object()) reject("certificate format", place + ": expected an instant {approx, lo, hi}");
      for (auto it = j.begin(); it != j.end(); ++it)
        if (it.key() != "approx" && it.key() != "lo" && it.key() != "hi")
          reject("certificate format", place + "." + it.key() + ": not a key of an instant");
      const mpq_class lo = rational(at(j, "lo", place), place + ".lo", kMaxRationalBits),
                      hi = rational(at(j, "hi", place), place + ".hi", kMaxRationalBits);
      if (lo != want.first || hi != want.second)
        reject("answer", place + ": the instant " + bracket_text(lo, hi) + " differs from the checked timeline's " +
                             bracket_text(want.first, want.second));
      check_approx(at(j, "approx", place), lo, hi, "answer", place + ".approx", approx_chars);
    };
    auto list = [&](const char* key, std::size_t n, bool optional, auto&& each) {
      const std::string place = std::string("answer.") + key;
      if (optional && !aj.contains(key)) {
        if (n) reject("answer", place + " is missing but the checked timeline has " + std::to_string(n));
        return;
      }
      const json& l = at(aj, key, "answer");
      if (!l.is_array()) reject("certificate format", place + ": expected an array");
      if (l.size() != n)
        reject("answer", "the checked timeline gives " + std::to_string(n) + " " + key + ", the certificate " +
                             std::to_string(l.size()));
      for (std::size_t i = 0; i < n; ++i) each(l[i], place + "[" + std::to_string(i) + "]", i);
    };
    auto pair_of = [&](const std::vector<std::pair<Br, Br>>& v) {
      return [&v, &inst](const json& j, const std::string& p, std::size_t i) {
        if (!j.is_array() || j.size() != 2) reject("certificate format", p + ": expected [start, end]");
        inst(j[0], p + "[0]", v[i].first);
        inst(j[1], p + "[1]", v[i].second);
      };
    };
    list("intervals", intervals.size(), false, pair_of(intervals));
    list("contact_intervals", contact_intervals.size(), true, pair_of(contact_intervals));
    list("contacts", contacts.size(), false,
         [&](const json& j, const std::string& p, std::size_t i) { inst(j, p, contacts[i]); });
    list("undecided", undecided.size(), false,
         [&](const json& j, const std::string& p, std::size_t i) { inst(j, p, undecided[i]); });
    const json& fc = at(aj, "first_contact", "answer");
    if (intervals.empty() != fc.is_null())
      reject("answer",
             "first_contact must be " + std::string(intervals.empty() ? "null" : "the start of the first interval"));
    if (!intervals.empty()) inst(fc, "answer.first_contact", intervals.front().first);
    const json& complete = at(cert, "complete", "certificate");
    if (complete != json(undecided.empty()))
      reject("answer",
             std::string("complete must be ") + (undecided.empty() ? "true" : "false: an undecided stretch is left"));
    checked.push_back("answer: assembled by the checker from the checked timeline, equal to the certificate's" +
                      std::string(undecided.empty() ? ""
                                                    : " (" + std::to_string(undecided.size()) +
                                                          " stretch(es) undecided: not a complete answer)"));
  }
};

}  // namespace

void check_cycloidal_certificate(const CheckScene& scene, const json& cert, std::vector<std::string>& checked) {
  CycloidalChecker c{scene, cert, checked, {}, {}, {}};
  c.run();
}

}  // namespace eccd::check
