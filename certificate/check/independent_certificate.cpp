// The independent check of "eccd-independent-certificate/3" (docs/certificate-
// format.md, "Independent scenes"; docs/checking.md): two ellipses or two
// ellipsoids moving with unrelated parameters s (A) and t (B). Paper 001,
// section 4: with F(u, s, t) = det((1 - u) A(s) + u B(t)), A(s) and B(t) meet
// iff F(., s, t) <= 0 on (0, 1); the answer is P_s = { s : A(s) meets B(t) for
// some t } and P_t likewise, as maximal closed intervals.
// Claims, in order:
//   certificate format; scene (the scene file's dim, a, b, parameters;
//   independent, rational motions);
//   net: the certificate's net is F of the stated shapes and inverse motions
//     (certificate/check/independent_net.hpp: both checked against the scene,
//     the net equal to det(...) on an integer grid), with A(0) (B(0)) in
//     place of a body listed in "reduced" after checking that it does not
//     move as a set; the faces u = 0, 1 are det A(s), det B(t) < 0 by that
//     check (det Q < 0, N invertible on [0, 1]);
//   s_proof (on F) and t_proof (on F with s and t exchanged), each a list of
//     items covering [0, 1] in order:
//       "in": boxes [u0, u1, t0, t1] sharing one t-range, u-ranges covering
//       [0, 1], every control point of F restricted to the box x the strip
//       < 0 (so every s of the strip meets B(t) there);
//       "out": every control point > 0 on boxes whose t-ranges cover [0, 1];
//       "end" (between an in- and an out-strip): a square system ("fold":
//       F = F_u = F_t = 0 in (u, s, t); "0" / "1": F = F_u = 0 in (u, s) on
//       t = 0 / 1; "free": the same where the net has degree 0 in t), a
//       Krawczyk chain (the checker's own test: Moore, Kearfott, Cloud 2009,
//       section 8.2; K(X) inside X's interior proves one zero in X, X's
//       s-range covering the strip), the side conditions (fold: F_uu < 0 on
//       X, X's t-range inside (0, 1); on t = t_b: F_t, or F_t / t resp.
//       F_t / (1 - t) where F_t vanishes on that face, and F_uu of one sign on
//       X's (u, s) box x [0, rho] resp. [1 - rho, 1], rho X's u-half-width),
//       the exclusion tree of the other candidate extreme points (a preorder
//       string over (u, t) in [0, 1]^2 at s in the strip, '1' split, u and t
//       halved at every level, '0' a leaf inside the kept box (X's u-range x
//       its t-range, or [0, 1] for "free") or with F or F_u of one proved
//       sign, or with its t-range inside (0, 1) and F_t and F_uu of one sign),
//       and the bracket inside the strip holding the strip ∩ the last chain
//       box's s-range. Why this proves exactly one end in the strip: the
//       lemma of certified/independent_proof.hpp, step 3 (re-stated in
//       docs/checking.md);
//   answer: the maximal runs of in-strips, each end an exact strip end or an
//     end's bracket, are the certificate's s_intervals and t_intervals, and
//     collides says whether they are non-empty (both lists must agree).
// Signs: intervals of doubles widened outwards first, MPFI at precision_bits
// where they do not decide (certificate/check/interval.hpp). Nothing is
// searched: every box, chain and tree is the certificate's.
#include "certificate/check/claims.hpp"
#include "certificate/check/independent_net.hpp"
#include "certificate/check/interval.hpp"
#include "certificate/check/kinds.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace eccd::check {

namespace {

const std::size_t kMaxRationalBits = 1024, kMaxNetBits = 1 << 16, kMaxStrips = 200000, kMaxBoxes = 2000000,
                  kMaxChain = 64, kMaxTreeChars = 4000001;
const int kMaxNetDegree = 400, kMaxTreeDepth = 40;
const char* const kFormat = "eccd-independent-certificate/3";

std::string q(const mpq_class& x) { return x.get_str(); }

struct KBox {
  std::vector<mpq_class> lo, hi;  // per unknown: (u, s) or (u, s, t)
};

// One projection's nets (its own parameter second): exact, in doubles and in MPFI.
struct ProjNets {
  Net3<mpq_class> F, Fu, Ft, Fuu;
  Net3<DI> dF, dFu, dFt, dFuu;
  Net3<MI> mF, mFu, mFt, mFuu;
  std::array<std::optional<Net3<mpq_class>>, 2> quotient;  // F_t / t, F_t / (1 - t) where F_t vanishes on that face
  std::array<Net3<mpq_class>, 2> face;                     // F on t = 0 and t = 1
};

// Inverse of a small matrix in double (Gauss-Jordan); false when singular. Any Y is sound in Krawczyk's test.
bool invert(std::vector<std::vector<double>> a, std::vector<std::vector<double>>& inv) {
  const std::size_t m = a.size();
  inv.assign(m, std::vector<double>(m, 0.0));
  for (std::size_t i = 0; i < m; ++i) inv[i][i] = 1;
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
    if (!(std::fabs(a[p][c]) > 0) || !std::isfinite(a[p][c])) return false;
    std::swap(a[p], a[c]);
    std::swap(inv[p], inv[c]);
    const double d = a[c][c];
    for (std::size_t k = 0; k < m; ++k) a[c][k] /= d, inv[c][k] /= d;
    for (std::size_t r = 0; r < m; ++r) {
      if (r == c) continue;
      const double f = a[r][c];
      for (std::size_t k = 0; k < m; ++k) a[r][k] -= f * a[c][k], inv[r][k] -= f * inv[c][k];
    }
  }
  for (const auto& row : inv)
    for (double x : row)
      if (!std::isfinite(x)) return false;
  return true;
}

// Krawczyk's K(X) for (F, F_u[, F_t]) in the unknowns (u, s[, t]) on `base` (F, or F's face t = t_b for the
// 2 x 2 systems): 1 when K lies inside X's interior, 0 when computed but not inside, -1 when not computable.
// F is restricted to X once; the equations' values at X's centre and the hulls of their derivative nets on X
// (the convex hull property) enclose f(c) and J(X).
template <class T, class Make>
int krawczyk_in(const Net3<T>& base, const KBox& X, KBox& K, Make&& make) {
  const std::size_t m = X.lo.size();
  for (std::size_t v = 0; v < m; ++v)
    if (X.lo[v] == 1 || !(X.lo[v] < X.hi[v])) return -1;
  Net3<T> G = restrict3(restrict3(base, 0, X.lo[0], X.hi[0], make), 1, X.lo[1], X.hi[1], make);
  if (m == 3) G = restrict3(G, 2, X.lo[2], X.hi[2], make);
  std::vector<mpq_class> side(m), cen(m);
  for (std::size_t v = 0; v < m; ++v) side[v] = X.hi[v] - X.lo[v], cen[v] = (X.lo[v] + X.hi[v]) / 2;
  std::vector<Net3<T>> E{G, deriv3(G, 0, side[0], make)};
  if (m == 3) E.push_back(deriv3(G, 2, side[2], make));
  const T half = make(mpq_class(1, 2));
  std::vector<T> f;
  std::vector<std::vector<T>> J(m);
  std::vector<std::vector<double>> Jm(m, std::vector<double>(m));
  for (std::size_t e = 0; e < m; ++e) {
    f.push_back(centre_value(E[e], half));
    if (!f.back().finite()) return -1;
    for (std::size_t v = 0; v < m; ++v) {
      J[e].push_back(deriv3(E[e], int(v), side[v], make).hull());
      if (!J[e][v].finite()) return -1;
      Jm[e][v] = J[e][v].mid();
    }
  }
  std::vector<std::vector<double>> Yd;
  if (!invert(Jm, Yd)) return -1;
  std::vector<std::vector<T>> Y(m);
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t c = 0; c < m; ++c) Y[r].push_back(make(mpq_class(Yd[r][c])));
  K = KBox{std::vector<mpq_class>(m), std::vector<mpq_class>(m)};
  bool inside = true;
  for (std::size_t i = 0; i < m; ++i) {
    T k = make(cen[i]);
    for (std::size_t e = 0; e < m; ++e) k = k - Y[i][e] * f[e];
    for (std::size_t j = 0; j < m; ++j) {
      T a = make(mpq_class(i == j ? 1 : 0));
      for (std::size_t e = 0; e < m; ++e) a = a - Y[i][e] * J[e][j];
      k = k + a * make(mpq_class(X.lo[j] - cen[j])).hull(make(mpq_class(X.hi[j] - cen[j])));
    }
    if (!k.finite()) return -1;
    K.lo[i] = k.lower();
    K.hi[i] = k.upper();
    inside = inside && K.lo[i] > X.lo[i] && K.hi[i] < X.hi[i];
  }
  return inside ? 1 : 0;
}

struct IndependentChecker {
  const CheckScene& sc;
  const json& cert;
  std::vector<std::string>& checked;
  int bits = 160;
  Net3<mpq_class> net;
  long mpfi_boxes = 0, tree_leaves = 0, tree_mpfi = 0;

  MI mk(const mpq_class& x) const { return MI(x, bits); }
  auto mmake() const {
    return [this](const mpq_class& x) { return mk(x); };
  }
  static DI dmake(const mpq_class& x) { return DI::of(x); }

  void scene_claim() {
    const json& s = at(cert, "scene", "certificate");
    for (const char* k : {"dim", "a", "b", "parameters"}) {
      if (!sc.doc.contains(k) || at(s, k, "scene") != sc.doc.at(k))
        reject("scene", std::string("the certificate's \"") + k +
                            "\" differs from the scene file's: it is a certificate for another scene");
    }
    if (!sc.independent || sc.cycloidal)
      reject(
          "scene",
          "an independent-motion certificate is for scenes with \"parameters\": \"independent\" and rational motions");
    checked.push_back("scene: dim, a, b and parameters are the scene file's; independent parameters, rational motions");
  }

  void net_claim() {
    const std::size_t H = std::size_t(sc.dim) + 1;
    const json& nj = at(cert, "net", "certificate");
    const json& deg = at(nj, "degrees", "net");
    if (!deg.is_array() || deg.size() != 3) reject("certificate format", "net.degrees: expected [u, s, t]");
    net.n = {int(whole(deg[0], "net.degrees[0]", long(H), long(H))),
             int(whole(deg[1], "net.degrees[1]", 0, kMaxNetDegree)),
             int(whole(deg[2], "net.degrees[2]", 0, kMaxNetDegree))};
    const json& co = at(nj, "coefficients", "net");
    const std::size_t count = std::size_t(net.n[0] + 1) * (net.n[1] + 1) * (net.n[2] + 1);
    if (!co.is_array() || co.size() != count)
      reject("certificate format",
             "net.coefficients: expected " + std::to_string(count) + " rationals ((u, s, t) in row-major order)");
    for (std::size_t i = 0; i < count; ++i)
      net.c.push_back(rational(co[i], "net.coefficients[" + std::to_string(i) + "]", kMaxNetBits));
    const QMatrix Qa = stated_shape_h(at(nj, "shape_a", "net"), "net.shape_a", sc.a.Q, kMaxNetBits);
    const QMatrix Qb = stated_shape_h(at(nj, "shape_b", "net"), "net.shape_b", sc.b.Q, kMaxNetBits);
    const PolyMatrix Na = stated_inverse_h(at(nj, "inverse_a", "net"), "net.inverse_a", sc.a.M, kMaxNetBits);
    const PolyMatrix Nb = stated_inverse_h(at(nj, "inverse_b", "net"), "net.inverse_b", sc.b.M, kMaxNetBits);
    const json& red = at(cert, "reduced", "certificate");
    if (!red.is_array() || red.size() > 2) reject("certificate format", "reduced: expected a list of \"s\" and \"t\"");
    bool still[2] = {false, false};
    for (const auto& r : red) {
      if (r != "s" && r != "t")
        reject("certificate format", "reduced: expected a list of \"s\" and \"t\", got " + shown(r));
      still[r == "s" ? 0 : 1] = true;
    }
    if (still[0] && !holds_still(Qa, Na))
      reject("reduced", "A(s) is not c(s) A(0): body a moves as a set, so s cannot be reduced");
    if (still[1] && !holds_still(Qb, Nb))
      reject("reduced", "B(t) is not c(t) B(0): body b moves as a set, so t cannot be reduced");
    const int Ds = std::max(net.n[1], still[0] ? 0 : 2 * int(H) * matrix_degree(Na));
    const int Dt = std::max(net.n[2], still[1] ? 0 : 2 * int(H) * matrix_degree(Nb));
    if (double(Ds + 1) * double(Dt + 1) > 200000)
      reject("certificate format", "net: the motions' degrees are too large to check");
    const auto vals = net_on_grid(net, Ds, Dt);
    std::vector<QMatrix> A, B;
    for (int y = 0; y <= Ds; ++y) A.push_back(moving_quadric(Qa, Na, mpq_class(still[0] ? 0 : y)));
    for (int z = 0; z <= Dt; ++z) B.push_back(moving_quadric(Qb, Nb, mpq_class(still[1] ? 0 : z)));
    for (int x = 0; x <= int(H); ++x)
      for (int y = 0; y <= Ds; ++y)
        for (int z = 0; z <= Dt; ++z) {
          QMatrix P(H, std::vector<mpq_class>(H));
          for (std::size_t i = 0; i < H; ++i)
            for (std::size_t j = 0; j < H; ++j) P[i][j] = (1 - x) * A[y][i][j] + x * B[z][i][j];
          if (vals[x][y][z] != determinant(P))
            reject("net", "the net differs from det((1 - u) A(s) + u B(t)) at u = " + std::to_string(x) + ", s = " +
                              std::to_string(y) + ", t = " + std::to_string(z) + ": it is not F for this scene");
        }
    checked.push_back(
        "net: Q_a, Q_b positive multiples of the scene's shapes with det < 0; N_a M_a, N_b M_b = c I with c free of "
        "roots "
        "in [0, 1] (Sturm); F = det((1 - u) A(s) + u B(t)) (degrees " +
        std::to_string(net.n[0]) + " x " + std::to_string(net.n[1]) + " x " + std::to_string(net.n[2]) + ", equal on " +
        std::to_string((H + 1) * (Ds + 1) * (Dt + 1)) + " integer points)" +
        (red.empty() ? std::string("")
                     : "; reduced " + red.dump() + ": the body does not move as a set (A(x) = c(x) A(0))"));
    checked.push_back(
        "faces: F(0, s, t) = det A(s) < 0 and F(1, s, t) = det B(t) < 0 (det Q < 0, N invertible on [0, 1])");
  }

  ProjNets nets_of(const Net3<mpq_class>& F) const {
    ProjNets p;
    p.F = F;
    p.Fu = deriv3(F, 0, mpq_class(1), [](const mpq_class& x) { return x; });
    p.Ft = deriv3(F, 2, mpq_class(1), [](const mpq_class& x) { return x; });
    p.Fuu = deriv3(p.Fu, 0, mpq_class(1), [](const mpq_class& x) { return x; });
    p.dF = converted3<DI>(p.F, dmake), p.dFu = converted3<DI>(p.Fu, dmake), p.dFt = converted3<DI>(p.Ft, dmake),
    p.dFuu = converted3<DI>(p.Fuu, dmake);
    p.mF = converted3<MI>(p.F, mmake()), p.mFu = converted3<MI>(p.Fu, mmake()), p.mFt = converted3<MI>(p.Ft, mmake()),
    p.mFuu = converted3<MI>(p.Fuu, mmake());
    p.quotient = {edge_quotient(F, 0), edge_quotient(F, 1)};
    p.face = {t_face(F, 0), t_face(F, 1)};
    return p;
  }

  // Krawczyk in doubles first, then in MPFI at precision_bits and at three times that where the lower precision
  // does not give `want` (1: inside; 0: computed); more bits only narrow the enclosures (the chain's last boxes
  // are about 2^-100 wide, where the rounding of 160 bits shows).
  int krawczyk(const Net3<mpq_class>& base, const KBox& X, KBox& K, int want) const {
    KBox k;
    int r = krawczyk_in(converted3<DI>(base, dmake), X, k, dmake);
    for (const int b : {bits, 3 * bits}) {
      if (r >= want) break;
      const auto make = [b](const mpq_class& x) { return MI(x, b); };
      r = krawczyk_in(converted3<MI>(base, make), X, k, make);
    }
    K = k;
    return r;
  }

  // The restriction of an MPFI net to a box (u, s, t ranges), its control points' common strict sign.
  int box_sign(const Net3<MI>& f, const std::array<mpq_class, 6>& b) const {
    Net3<MI> g =
        restrict3(restrict3(restrict3(f, 1, b[2], b[3], mmake()), 2, b[4], b[5], mmake()), 0, b[0], b[1], mmake());
    return g.strict_sign();
  }

  struct Tree {
    const std::string& s;
    std::size_t pos = 0;
  };
  struct Keep {
    mpq_class u0, u1, t0, t1;
  };

  // The exclusion tree over (u, t) at s in [lo, hi]: nets in doubles along the tree, MPFI from the strip at leaves
  // doubles do not decide.
  void exclusion(Tree& tr, const std::array<Net3<DI>, 4>& f, const mpq_class& u0, const mpq_class& u1,
                 const mpq_class& t0, const mpq_class& t1, int depth, const Keep& keep,
                 std::optional<std::array<Net3<MI>, 4>>& strip, const ProjNets& P, const mpq_class& lo,
                 const mpq_class& hi, const std::string& claim) {
    if (tr.pos >= tr.s.size())
      reject(claim, "the exclusion tree ends early: part of [0, 1]^2 x the strip is not covered");
    const char ch = tr.s[tr.pos++];
    if (ch == '0') {
      ++tree_leaves;
      if (u0 >= keep.u0 && u1 <= keep.u1 && t0 >= keep.t0 && t1 <= keep.t1) return;
      const bool inner = sgn(t0) > 0 && t1 < 1;
      if (f[0].strict_sign() != 0 || f[1].strict_sign() != 0 ||
          (inner && f[2].strict_sign() != 0 && f[3].strict_sign() != 0))
        return;
      ++tree_mpfi;
      if (!strip)
        strip = std::array<Net3<MI>, 4>{restrict3(P.mF, 1, lo, hi, mmake()), restrict3(P.mFu, 1, lo, hi, mmake()),
                                        restrict3(P.mFt, 1, lo, hi, mmake()), restrict3(P.mFuu, 1, lo, hi, mmake())};
      std::array<int, 4> sg;
      for (int i = 0; i < 4; ++i)
        sg[i] = restrict3(restrict3((*strip)[i], 2, t0, t1, mmake()), 0, u0, u1, mmake()).strict_sign();
      if (sg[0] != 0 || sg[1] != 0 || (inner && sg[2] != 0 && sg[3] != 0)) return;
      reject(claim, "the exclusion leaf u in [" + q(u0) + ", " + q(u1) + "], t in [" + q(t0) + ", " + q(t1) +
                        "]: neither F nor F_u (nor F_t and F_uu inside (0, 1)) is of one proved sign there: another "
                        "extreme point is not excluded");
    }
    if (ch != '1') reject("certificate format", claim + ": the exclusion tree must be a string of '0' and '1'");
    if (depth >= kMaxTreeDepth)
      reject("certificate format", claim + ": the exclusion tree is deeper than " + std::to_string(kMaxTreeDepth));
    const DI half(0.5, 0.5);
    const mpq_class um = (u0 + u1) / 2, tm = (t0 + t1) / 2;
    std::array<Net3<DI>, 4> a, b;
    for (int i = 0; i < 4; ++i) std::tie(a[i], b[i]) = split3(f[i], 0, half);
    for (int side = 0; side < 2; ++side) {
      const auto& g = side ? b : a;
      std::array<Net3<DI>, 4> lt, ht;
      for (int i = 0; i < 4; ++i) std::tie(lt[i], ht[i]) = split3(g[i], 2, half);
      const mpq_class a0 = side ? um : u0, a1 = side ? u1 : um;
      exclusion(tr, lt, a0, a1, t0, tm, depth + 1, keep, strip, P, lo, hi, claim);
      exclusion(tr, ht, a0, a1, tm, t1, depth + 1, keep, strip, P, lo, hi, claim);
    }
  }

  std::vector<mpq_class> rats(const json& j, std::size_t n, const std::string& place) const {
    if (!j.is_array() || j.size() != n)
      reject("certificate format", place + ": expected " + std::to_string(n) + " rationals");
    std::vector<mpq_class> r;
    for (std::size_t i = 0; i < n; ++i)
      r.push_back(rational(j[i], place + "[" + std::to_string(i) + "]", kMaxRationalBits));
    return r;
  }

  // An end item: the system, its chain, its side conditions, its exclusion tree and its bracket. Returns the bracket.
  std::pair<mpq_class, mpq_class> end_item(const ProjNets& P, const json& it, const std::string& name,
                                           const std::string& claim, const mpq_class& lo, const mpq_class& hi) {
    const json& sj = at(it, "system", name);
    const std::string sys = sj.is_string() ? sj.get<std::string>() : "";
    if (sys != "fold" && sys != "0" && sys != "1" && sys != "free")
      reject("certificate format", name + ": system must be \"fold\", \"0\", \"1\" or \"free\"");
    const bool fold = sys == "fold";
    if (sys == "free" && P.F.n[2] != 0) reject(claim, "system free needs F of degree 0 in the other parameter");
    const std::size_t m = fold ? 3 : 2;
    const Net3<mpq_class>& base = fold ? P.F : P.face[sys == "1" ? 1 : 0];
    const json& chain = at(it, "chain", name);
    if (!chain.is_array() || chain.empty() || chain.size() > kMaxChain)
      reject("certificate format", name + ": chain must list 1 to " + std::to_string(kMaxChain) + " boxes");
    std::vector<KBox> Y;
    for (std::size_t i = 0; i < chain.size(); ++i) {
      KBox b{rats(at(chain[i], "lo", name), m, name + ".chain lo"),
             rats(at(chain[i], "hi", name), m, name + ".chain hi")};
      for (std::size_t v = 0; v < m; ++v)
        if (!(b.lo[v] < b.hi[v]))
          reject("certificate format", name + ": chain box " + std::to_string(i) + " is empty in a coordinate");
      Y.push_back(std::move(b));
    }
    const KBox& X = Y[0];
    if (X.lo[1] > lo || X.hi[1] < hi)
      reject(claim, "the Krawczyk box's range of the proof's parameter does not cover the strip");
    KBox K;
    if (krawczyk(base, X, K, 1) != 1)
      reject(claim, "Krawczyk's K(X) is not inside the interior of X: the box is not proved to hold one zero");
    for (std::size_t i = 0; i + 1 < Y.size(); ++i) {
      auto keeps = [&](const KBox& K2) {
        for (std::size_t v = 0; v < m; ++v)
          if (Y[i + 1].lo[v] > std::max(Y[i].lo[v], K2.lo[v]) || Y[i + 1].hi[v] < std::min(Y[i].hi[v], K2.hi[v]))
            return false;
        return true;
      };
      KBox K2;
      if (krawczyk(base, Y[i], K2, 0) >= 0 && keeps(K2)) continue;
      // or Y_{i+1} inside X holding one zero by its own Krawczyk test: X's only zero
      bool inside_x = true;
      for (std::size_t v = 0; v < m; ++v) inside_x = inside_x && Y[i + 1].lo[v] >= X.lo[v] && Y[i + 1].hi[v] <= X.hi[v];
      KBox K3;
      if (!inside_x || krawczyk(base, Y[i + 1], K3, 1) != 1)
        reject(claim, "chain box " + std::to_string(i + 1) + " does not contain Y_" + std::to_string(i) + " ∩ K(Y_" +
                          std::to_string(i) + ")");
    }
    // side conditions and the box the exclusion keeps
    Keep keep{X.lo[0], X.hi[0], 0, 1};
    if (sys == "0" || sys == "1") {
      const mpq_class rho = (X.hi[0] - X.lo[0]) / 2;
      if (rho > mpq_class(1, 16)) reject(claim, "the box's half-width in u is more than 1/16");
      keep.t0 = sys == "0" ? mpq_class(0) : mpq_class(1 - rho);
      keep.t1 = sys == "0" ? rho : mpq_class(1);
      const std::array<mpq_class, 6> region{X.lo[0], X.hi[0], X.lo[1], X.hi[1], keep.t0, keep.t1};
      const auto& quo = P.quotient[sys == "0" ? 0 : 1];
      const bool ft = box_sign(P.mFt, region) != 0 || (quo && box_sign(converted3<MI>(*quo, mmake()), region) != 0);
      if (!ft || box_sign(P.mFuu, region) == 0)
        reject(claim,
               "F_t (or F_t / t, F_t / (1 - t) where F_t vanishes on that face) or F_uu is not proved of one sign near "
               "that end of the path");
    } else if (fold) {
      keep.t0 = X.lo[2];
      keep.t1 = X.hi[2];
      if (sgn(keep.t0) <= 0 || keep.t1 >= 1 ||
          box_sign(P.mFuu, {X.lo[0], X.hi[0], X.lo[1], X.hi[1], X.lo[2], X.hi[2]}) != -1)
        reject(claim, "F_uu is not proved < 0 on the box, or its t-range is not inside (0, 1)");
    }
    const json& ex = at(it, "exclusion", name);
    if (!ex.is_string() || ex.get_ref<const std::string&>().size() > kMaxTreeChars)
      reject("certificate format",
             name + ".exclusion: expected a string of at most " + std::to_string(kMaxTreeChars) + " '0'/'1'");
    Tree tr{ex.get_ref<const std::string&>()};
    const std::array<Net3<DI>, 4> strip{restrict3(P.dF, 1, lo, hi, dmake), restrict3(P.dFu, 1, lo, hi, dmake),
                                        restrict3(P.dFt, 1, lo, hi, dmake), restrict3(P.dFuu, 1, lo, hi, dmake)};
    std::optional<std::array<Net3<MI>, 4>> mstrip;
    exclusion(tr, strip, 0, 1, 0, 1, 0, keep, mstrip, P, lo, hi, claim);
    if (tr.pos != tr.s.size()) reject("certificate format", name + ".exclusion: characters after the end of the tree");
    const auto b = rats(at(it, "bracket", name), 2, name + ".bracket");
    const mpq_class need_lo = std::max(lo, Y.back().lo[1]), need_hi = std::min(hi, Y.back().hi[1]);
    if (need_lo > need_hi) reject(claim, "the last chain box misses the strip");
    if (b[0] > need_lo || b[1] < need_hi || b[0] < lo || b[1] > hi)
      reject(claim, "the bracket [" + q(b[0]) + ", " + q(b[1]) + "] does not hold [" + q(need_lo) + ", " + q(need_hi) +
                        "] (the strip ∩ the last chain box) inside the strip");
    return {b[0], b[1]};
  }

  // An in- or out-strip: its boxes' signs and their coverage.
  void strip_item(const ProjNets& P, const json& it, const std::string& name, const std::string& claim,
                  const mpq_class& lo, const mpq_class& hi, bool in, std::size_t& nboxes) {
    const json& boxes = at(it, "boxes", name);
    if (!boxes.is_array() || boxes.empty()) reject("certificate format", name + ": boxes must be a non-empty list");
    nboxes += boxes.size();
    if (nboxes > kMaxBoxes) reject("certificate format", "more than " + std::to_string(kMaxBoxes) + " boxes");
    const Net3<DI> sd = restrict3(P.dF, 1, lo, hi, dmake);
    std::optional<Net3<MI>> sm;
    std::map<std::pair<mpq_class, mpq_class>, Net3<DI>> by_t;
    std::vector<std::array<mpq_class, 4>> bx;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const auto v = rats(boxes[i], 4, name + " box " + std::to_string(i + 1));
      const std::array<mpq_class, 4> b{v[0], v[1], v[2], v[3]};
      if (!(0 <= b[0] && b[0] < b[1] && b[1] <= 1 && 0 <= b[2] && b[2] < b[3] && b[3] <= 1))
        reject("certificate format", name + " box " + std::to_string(i + 1) + ": not [u0, u1, t0, t1] inside [0, 1]");
      auto c = by_t.find({b[2], b[3]});
      if (c == by_t.end()) c = by_t.emplace(std::make_pair(b[2], b[3]), restrict3(sd, 2, b[2], b[3], dmake)).first;
      bx.push_back(b);
      if (restrict3(c->second, 0, b[0], b[1], dmake).strict_sign() == (in ? -1 : 1)) continue;
      ++mpfi_boxes;
      if (!sm) sm = restrict3(P.mF, 1, lo, hi, mmake());
      if (restrict3(restrict3(*sm, 2, b[2], b[3], mmake()), 0, b[0], b[1], mmake()).strict_sign() != (in ? -1 : 1))
        reject(claim, "box " + std::to_string(i + 1) + " (u in [" + q(b[0]) + ", " + q(b[1]) +
                          "], other parameter in [" + q(b[2]) + ", " + q(b[3]) + "]): its control points are not all " +
                          (in ? "< 0" : "> 0"));
    }
    const int ax = in ? 0 : 2;
    std::sort(bx.begin(), bx.end(), [&](const auto& a, const auto& b) { return a[ax] < b[ax]; });
    mpq_class c = 0;
    for (const auto& b : bx) {
      if (in && (b[2] != bx[0][2] || b[3] != bx[0][3]))
        reject(claim, "the boxes of an in-strip must share one range of the other parameter");
      if (b[ax] > c) break;
      c = std::max(c, b[ax + 1]);
    }
    if (c != 1)
      reject(claim, std::string("the boxes' ") + (in ? "u" : "other parameter's") +
                        " ranges do not cover [0, 1] (covered up to " + q(c) + ")");
  }

  using Br = std::pair<mpq_class, mpq_class>;

  // One projection: the checked intervals (brackets of their ends).
  std::vector<std::pair<Br, Br>> projection(const Net3<mpq_class>& F, const json& items, const std::string& var) {
    const std::string P = var + "_proof";
    if (!items.is_array() || items.empty() || items.size() > kMaxStrips)
      reject("certificate format",
             P + ": expected a non-empty list of at most " + std::to_string(kMaxStrips) + " strips and ends");
    const ProjNets nets = nets_of(F);
    struct Item {
      std::string kind;
      mpq_class lo, hi, blo, bhi;
    };
    std::vector<Item> seq;
    mpq_class cursor = 0;
    std::size_t nboxes = 0, n_in = 0, n_out = 0, n_end = 0;
    const long leaves0 = tree_leaves;
    for (std::size_t k = 0; k < items.size(); ++k) {
      const json& it = items[k];
      const std::string name = P + " item " + std::to_string(k + 1);
      const json& kind = at(it, "kind", name);
      if (kind != "in" && kind != "out" && kind != "end")
        reject("certificate format", name + ": kind must be \"in\", \"out\" or \"end\"");
      const mpq_class lo = rational(at(it, "lo", name), name + ".lo", kMaxRationalBits),
                      hi = rational(at(it, "hi", name), name + ".hi", kMaxRationalBits);
      const std::string claim =
          name + " (" + kind.get<std::string>() + ", " + var + " in [" + q(lo) + ", " + q(hi) + "])";
      if (lo != cursor)
        reject("coverage",
               claim + ": starts at " + q(lo) + ", the previous item ends at " + q(cursor) + " (a gap or an overlap)");
      if (!(lo < hi) || hi > 1) reject("coverage", claim + ": not a range inside [0, 1]");
      cursor = hi;
      if (kind == "end") {
        const Br b = end_item(nets, it, name, claim, lo, hi);
        seq.push_back({"end", lo, hi, b.first, b.second});
        ++n_end;
        continue;
      }
      strip_item(nets, it, name, claim, lo, hi, kind == "in", nboxes);
      seq.push_back({kind.get<std::string>(), lo, hi, 0, 0});
      ++(kind == "in" ? n_in : n_out);
    }
    if (cursor != 1) reject("coverage", P + ": the items end at " + var + " = " + q(cursor) + ", not 1");
    for (std::size_t k = 0; k < seq.size(); ++k)
      if (seq[k].kind == "end" && (k == 0 || k + 1 == seq.size() || seq[k - 1].kind == "end" ||
                                   seq[k + 1].kind == "end" || seq[k - 1].kind == seq[k + 1].kind))
        reject("coverage",
               P + " item " + std::to_string(k + 1) + ": an end must lie between an in-strip and an out-strip");
    checked.push_back(P + ": " + std::to_string(n_in) + " in-strips and " + std::to_string(n_out) + " out-strips (" +
                      std::to_string(nboxes) + " boxes, signs proved) and " + std::to_string(n_end) +
                      " ends (Krawczyk, side conditions, exclusion trees of " + std::to_string(tree_leaves - leaves0) +
                      " leaves) cover [0, 1]");
    std::vector<std::pair<Br, Br>> iv;
    for (std::size_t k = 0; k < seq.size(); ++k) {
      if (seq[k].kind != "in") continue;
      std::size_t j = k;
      while (j + 1 < seq.size() && seq[j + 1].kind == "in") ++j;
      const Br a = k > 0 && seq[k - 1].kind == "end" ? Br{seq[k - 1].blo, seq[k - 1].bhi} : Br{seq[k].lo, seq[k].lo};
      const Br b = j + 1 < seq.size() && seq[j + 1].kind == "end" ? Br{seq[j + 1].blo, seq[j + 1].bhi}
                                                                  : Br{seq[j].hi, seq[j].hi};
      iv.emplace_back(a, b);
      k = j;
    }
    return iv;
  }

  void answer_claim(const std::vector<std::pair<Br, Br>>& s_iv, const std::vector<std::pair<Br, Br>>& t_iv) {
    if (s_iv.empty() != t_iv.empty())
      reject("answer", "the s-proof and the t-proof disagree on whether the paths meet");
    const json& a = at(cert, "answer", "certificate");
    if (!a.is_object()) reject("certificate format", "answer: expected an object");
    for (auto it = a.begin(); it != a.end(); ++it)
      if (it.key() != "collides" && it.key() != "s_intervals" && it.key() != "t_intervals")
        reject(
            "certificate format",
            "answer." + it.key() + ": not a key of a complete independent answer (collides, s_intervals, t_intervals)");
    const json& col = at(a, "collides", "answer");
    if (col != json(!s_iv.empty()))
      reject("answer", "answer.collides is " + shown(col) + " but the checked proofs prove " +
                           (s_iv.empty() ? "that the paths never meet" : "a meeting"));
    const std::size_t chars = kMaxRationalBits * 30103 / 100000 + 64;
    auto list = [&](const char* key, const std::vector<std::pair<Br, Br>>& want) {
      const std::string place = std::string("answer.") + key;
      const json& l = at(a, key, "answer");
      if (!l.is_array()) reject("certificate format", place + ": expected an array");
      if (l.size() != want.size())
        reject("answer", "the checked proofs give " + std::to_string(want.size()) + " " + key + ", the certificate " +
                             std::to_string(l.size()));
      for (std::size_t i = 0; i < l.size(); ++i) {
        if (!l[i].is_array() || l[i].size() != 2)
          reject("certificate format", place + "[" + std::to_string(i) + "]: expected [start, end]");
        for (int e = 0; e < 2; ++e) {
          const std::string p = place + "[" + std::to_string(i) + "][" + std::to_string(e) + "]";
          const json& j = l[i][e];
          if (!j.is_object()) reject("certificate format", p + ": expected an instant {approx, lo, hi}");
          for (auto k = j.begin(); k != j.end(); ++k)
            if (k.key() != "approx" && k.key() != "lo" && k.key() != "hi")
              reject("certificate format", p + "." + k.key() + ": not a key of an instant");
          const mpq_class lo = rational(at(j, "lo", p), p + ".lo", kMaxRationalBits),
                          hi = rational(at(j, "hi", p), p + ".hi", kMaxRationalBits);
          const Br& w = e ? want[i].second : want[i].first;
          if (lo != w.first || hi != w.second)
            reject("answer", p + ": the instant " + bracket_text(lo, hi) + " differs from the checked proofs' " +
                                 bracket_text(w.first, w.second));
          // approx: a decimal rounding (to its own last digit) of a point of the bracket
          const json& ap = at(j, "approx", p);
          mpq_class v, unit;
          if (!ap.is_string() || !read_decimal(ap.get<std::string>(), chars, v, unit))
            reject("answer", p + ".approx: expected a decimal string, got " + shown(ap));
          if (v + unit / 2 < lo || v - unit / 2 > hi)
            reject("answer", p + ".approx " + shown(ap) + " is not a rounding of a point of " + bracket_text(lo, hi));
        }
      }
    };
    list("s_intervals", s_iv);
    list("t_intervals", t_iv);
    checked.push_back(
        "answer: collides, s_intervals and t_intervals assembled by the checker from the checked proofs, equal to the "
        "certificate's");
  }

  void run() {
    const json& fmt = at(cert, "format", "certificate");
    if (fmt != kFormat)
      reject("certificate format", std::string("format: expected \"") + kFormat + "\", got " + shown(fmt));
    checked.push_back(std::string("certificate format: ") + kFormat);
    scene_claim();
    bits = int(whole(at(cert, "precision_bits", "certificate"), "precision_bits", 64, 1024));
    net_claim();
    const auto s_iv = projection(net, at(cert, "s_proof", "certificate"), "s");
    const auto t_iv = projection(swap_st(net), at(cert, "t_proof", "certificate"), "t");
    if (mpfi_boxes + tree_mpfi > 0)
      checked.push_back("MPFI at " + std::to_string(bits) + " bits where doubles did not decide: " +
                        std::to_string(mpfi_boxes) + " boxes, " + std::to_string(tree_mpfi) + " exclusion leaves");
    answer_claim(s_iv, t_iv);
  }
};

}  // namespace

void check_independent_certificate(const CheckScene& scene, const json& cert, std::vector<std::string>& checked) {
  IndependentChecker c{scene, cert, checked, 160, {}, 0, 0, 0};
  c.run();
}

}  // namespace eccd::check
