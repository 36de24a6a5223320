// The independent check of "eccd-certificate/2" (docs/certificate-format.md,
// docs/checking.md): every claim re-proved with the checker's own algebra.
// Claims, in order (the names tools/check_certificate.py uses):
//   certificate format, scene (the scene's dim, a, b; det M(t) ≠ 0 on [0, 1]),
//   f (g_k = α^k β^(H-k) h_k, α, β > 0: certificate/check/pencil.hpp),
//   projection (the candidates named vanish identically, P ∝ the named one,
//   by values at deg + 1 integers), factors (Π F_i^m_i ∝ P, by values), all
//   on integers, timeline, instant K (a sign change of its factor), gaps
//   (on each piece between gap points, Descartes' bound of each factor equals
//   its brackets there; else Descartes on each bracket and gap), cell K
//   (static test: negative roots of f by Descartes where its count is
//   exact, else Sturm), status of each instant
//   (evidence signs proved on the bracket: mean value theorem or Descartes),
//   answer (assembled by the checker from the checked timeline).
#include "certificate/check/verdict.hpp"

#include "certificate/check/claims.hpp"
#include "certificate/check/kinds.hpp"

#include "certificate/check/pencil.hpp"
#include "certificate/check/qpoly.hpp"
#include "certificate/check/scene.hpp"
#include "certificate/check/strict_json.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

namespace eccd::check {

namespace {

using json = nlohmann::json;

std::size_t primitive_bits(const QPoly& p) {  // τ: bits of the primitive integer multiple
  mpz_class l = 1, g = 0;
  for (const auto& x : p.c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  std::vector<mpz_class> z;
  for (const auto& x : p.c) {
    z.push_back(x.get_num() * (l / x.get_den()));
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), z.back().get_mpz_t());
  }
  std::size_t b = 0;
  for (auto& x : z) {
    if (g != 0) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
    b = std::max<std::size_t>(b, mpz_sizeinbase(x.get_mpz_t(), 2));
  }
  return b;
}

struct Node {
  mpq_class lo, hi;
  bool cell = false;
  St status = St::overlapping;
  std::optional<int> factor;
  json evidence = json::array();
  std::string name, place;
};

struct Checker {
  const CheckScene& sc;
  const json& cert;
  std::vector<std::string>& checked;
  Checker(const CheckScene& s, const json& c, std::vector<std::string>& out) : sc(s), cert(c), checked(out) {}
  int H = 3;
  std::vector<QPoly> g;  // the certificate's f, once proved
  QPoly P;               // the projection, once proved
  int projection_k = 0;  // 3D: psc_k
  std::vector<std::pair<QPoly, int>> F;
  std::vector<Node> nodes;
  std::size_t max_bits = 256, factor_bits = 256, approx_chars = 200, degree = 0;
  std::map<std::string, QPoly> evidence_cache;

  int g_degree() const {
    int d = 0;
    for (const auto& x : g) d = std::max(d, x.degree());
    return d;
  }

  void scene_claim() {
    const json& s = at(cert, "scene", "certificate");
    for (const char* k : {"dim", "a", "b"})
      if (at(s, k, "scene") != sc.doc.at(k))
        reject("scene", std::string("the certificate's \"") + k +
                            "\" differs from the scene file's: it is a certificate for another scene");
    if (sc.cycloidal)
      reject("certificate format",
             "the scene has a cycloidal motion: its certificate is an eccd-cycloidal-certificate/2");
    if (sc.independent)
      reject("certificate format",
             "the scene has independent motions: its certificate is an eccd-independent-certificate/3");
    for (const CheckObject* o : {&sc.a, &sc.b}) {
      const QPoly d = motion_determinant(o->M);
      if (d.zero() || sgn(d(0)) == 0 || sgn(d(1)) == 0 || roots_between(d, 0, 1) != 0)
        reject("scene", std::string("det M(t) of object ") + (o == &sc.a ? "a" : "b") +
                            " vanishes in [0, 1]: the motion is not invertible there");
    }
    checked.push_back(
        "scene: dim, a and b are the scene file's; det M(t) has no root in [0, 1] for either object (Sturm)");
  }

  void f_claim() {
    const json& gj = at(at(cert, "f", "certificate"), "g", "f");
    if (!gj.is_array() || int(gj.size()) != H + 1)
      reject("f", "expected " + std::to_string(H + 1) + " coefficient polynomials g_0 .. g_" + std::to_string(H));
    const PolyMatrix Na = primitive_inverse(sc.a.M), Nb = primitive_inverse(sc.b.M);
    const int D = 2 * H * std::max(matrix_degree(Na), matrix_degree(Nb));
    for (int k = 0; k <= H; ++k) {
      const std::string place = "f.g[" + std::to_string(k) + "]";
      if (!gj[std::size_t(k)].is_array() || int(gj[std::size_t(k)].size()) > D + 1)
        reject("f", place + ": expected an array of at most " + std::to_string(D + 1) +
                        " coefficients (the degree the scene allows)");
      std::vector<mpq_class> c;
      for (std::size_t i = 0; i < gj[std::size_t(k)].size(); ++i)
        c.push_back(rational(gj[std::size_t(k)][i], place + "[" + std::to_string(i) + "]", 1u << 16));
      g.push_back(QPoly(std::move(c)));
    }
    // g_k(t_j) = ρ_k h_k(t_j) at D + 1 integers t_j, one constant ρ_k per k; on
    // integers: G_k = L g_k against H! det(λ a A - b B)'s coefficients (a, b > 0
    // the integer scales of N^T Q N), which scales every ρ_k by L / (H! a^k b^(H-k)):
    // the same form, so the test on the ρ_k below is unchanged.
    make_integer_g();
    const ZPolyMatrix NaZ = integer_matrix(Na), NbZ = integer_matrix(Nb);
    const ZMatrix QaZ = integer_matrix(sc.a.Q), QbZ = integer_matrix(sc.b.Q);
    std::vector<std::optional<std::pair<mpz_class, mpz_class>>> first(std::size_t(H) +
                                                                      1);  // (G_k, h_k) where h_k ≠ 0 first
    std::vector<bool> h_zero(std::size_t(H) + 1, true);
    for (int j = 0; j <= D; ++j) {
      const mpz_class t = point(j, D + 1);
      const std::vector<mpz_class> h =
          pencil_coefficients(moving_quadric(QaZ, at_point(NaZ, t)), moving_quadric(QbZ, at_point(NbZ, t)));
      for (int k = 0; k <= H; ++k) {
        const mpz_class gv = value_at(G[std::size_t(k)], t);
        const mpz_class& hv = h[std::size_t(k)];
        auto& f0 = first[std::size_t(k)];
        if (sgn(hv) != 0) h_zero[std::size_t(k)] = false;
        if (!f0 && sgn(hv) != 0) f0 = std::make_pair(gv, hv);
        if (f0 ? gv * f0->second != f0->first * hv : sgn(gv) != 0)
          reject("f", "g_" + std::to_string(k) + " is not a constant multiple of the coefficient of lambda^" +
                          std::to_string(k) +
                          " of det(lambda A(t) - B(t)) computed from the scene (they disagree at t = " + t.get_str() +
                          ")");
      }
    }
    std::vector<std::optional<mpq_class>> rho(std::size_t(H) + 1);
    for (int k = 0; k <= H; ++k)
      if (first[std::size_t(k)]) {
        mpq_class r(first[std::size_t(k)]->first, first[std::size_t(k)]->second);
        r.canonicalize();  // also makes the denominator positive
        rho[std::size_t(k)] = r;
      }
    if (h_zero[0] || h_zero[std::size_t(H)])
      reject("f", "det A(t) or det B(t) vanishes identically: a degenerate scene");
    const mpq_class rH = *rho[std::size_t(H)], r0 = *rho[0];
    if (sgn(rH) <= 0 || sgn(r0) <= 0)
      reject("f", "g_0 or g_" + std::to_string(H) + " has the wrong sign: the roots lambda would change sign");
    for (int k = 1; k < H; ++k) {
      if (h_zero[std::size_t(k)]) continue;
      const mpq_class r = *rho[std::size_t(k)];
      mpq_class lhs = 1, rhs = 1;
      for (int i = 0; i < H; ++i) lhs *= r;
      for (int i = 0; i < k; ++i) rhs *= rH;
      for (int i = 0; i < H - k; ++i) rhs *= r0;
      if (sgn(r) <= 0 || lhs != rhs)
        reject("f", "g_" + std::to_string(k) + " is scaled differently from g_0 and g_" + std::to_string(H) +
                        ": not f(lambda) up to positive factors on A and B (the roots lambda would move)");
    }
    checked.push_back("f: g_0 .. g_" + std::to_string(H) +
                      " equal det(lambda A(t) - B(t)) from the scene up to positive factors on A and B (" +
                      std::to_string(D + 1) + " points)");
  }

  // g scaled by one positive integer L to integer coefficients (after the f claim): values at integers in mpz.
  std::vector<std::vector<mpz_class>> G;
  void make_integer_g() {
    if (!G.empty()) return;
    mpz_class L = 1;
    for (const auto& x : g) L = denominator_lcm(x, L);
    for (const auto& x : g) G.push_back(integer_multiple(x, L));
  }
  std::vector<mpz_class> G_at(const mpz_class& t) const {
    std::vector<mpz_class> v;
    for (const auto& x : G) v.push_back(value_at(x, t));
    return v;
  }
  // The named candidate's value at t for L·g (a fixed positive multiple of
  // its value for g): "discriminant" (2D: of the cubic; 3D: of the quartic,
  // each by its closed form; psc_0 = Res(f, f') = g_4 disc f) or psc_k (k >= 1,
  // a determinant of the Sylvester-Habicht rows).
  mpz_class candidate_at(int k, const mpz_class& t) const {
    const std::vector<mpz_class> v = G_at(t);
    if (H == 3) return cubic_discriminant_at(v);
    if (k == 0) return quartic_discriminant_at(v);
    return subresultant_at(v, k, k);
  }
  // A bound on the degree in t of Σ over monomials Π g_{k_i} (`factors` of
  // them, Σ k_i = weight): the discriminant of a degree-n polynomial is
  // homogeneous of degree 2n - 2 and isobaric of weight n(n - 1) in its
  // coefficients, Res(f, f') of degree 2n - 1 and weight n²; so its degree
  // is at most the best Σ deg g_{k_i} (dynamic programming). -1: every
  // monomial has a zero factor.
  int isobaric_bound(int factors, int weight) const {
    std::vector<int> best(std::size_t(weight) + 1, -1);
    best[0] = 0;
    for (int f = 0; f < factors; ++f) {
      std::vector<int> next(std::size_t(weight) + 1, -1);
      for (int w = 0; w <= weight; ++w) {
        if (best[std::size_t(w)] < 0) continue;
        for (int k = 0; k <= H && w + k <= weight; ++k)
          if (!g[std::size_t(k)].zero())
            next[std::size_t(w + k)] =
                std::max(next[std::size_t(w + k)], best[std::size_t(w)] + g[std::size_t(k)].degree());
      }
      best = next;
    }
    return best[std::size_t(weight)];
  }
  int candidate_bound(int k) const {
    if (H == 3) return isobaric_bound(4, 6);
    if (k == 0) return isobaric_bound(6, 12);
    return (2 * H - 1 - 2 * k) * g_degree();
  }
  static mpz_class point(int j, int count) { return mpz_class(j - count / 2); }  // symmetric about 0: smaller values

  // Returns false when the 2D discriminant vanishes identically.
  bool projection_claim() {
    const json& p = at(cert, "projection", "certificate");
    std::vector<std::string> names{"discriminant"};
    if (H == 4) names = {"discriminant", "psc_1", "psc_2", "psc_3"};
    const int k = projection_index(p, names);
    projection_k = k;
    const bool zero = at(p, "identically_zero", "projection") == true;
    if (!at(p, "identically_zero", "projection").is_boolean())
      reject("certificate format", "projection.identically_zero: expected true or false");
    const int bound = candidate_bound(k);
    if (zero) {
      if (H != 3) reject("projection", "a 3D certificate names a projection that vanishes identically");
      for (int j = 0; j <= bound; ++j)
        if (sgn(candidate_at(k, point(j, bound + 1))) != 0)
          reject("projection", "the discriminant does not vanish identically (non-zero at t = " +
                                   point(j, bound + 1).get_str() + ")");
      checked.push_back("projection: the discriminant vanishes identically (values at " +
                        std::to_string(std::max(bound, -1) + 1) + " points)");
      return false;
    }
    const json& cj = at(p, "coefficients", "projection");
    if (!cj.is_array() || cj.empty() || int(cj.size()) > bound + 1)  // P's degree: at most the candidate's
      reject("projection",
             "expected at most " + std::to_string(bound + 1) + " coefficients (the degree the scene allows)");
    std::vector<mpq_class> c;
    for (std::size_t i = 0; i < cj.size(); ++i)
      c.push_back(rational(cj[i], "projection.coefficients[" + std::to_string(i) + "]", 1u << 20));
    P = QPoly(std::move(c));
    if (P.zero()) reject("projection", "the projection's coefficients are all zero but identically_zero is false");
    if (whole(at(p, "degree", "projection"), "projection.degree", 0, 1 << 30) != P.degree())
      reject("projection", "projection.degree differs from the degree of its coefficients");
    const int points = std::max(bound, P.degree()) + 1;  // both sides have degree < points
    const std::vector<mpz_class> p_values = projection_values(k, names[std::size_t(k)], points);
    degree = std::size_t(P.degree());
    const std::size_t tau = primitive_bits(P);
    max_bits = std::min<std::size_t>(
        4 * tau + 1024, std::max<std::size_t>(256, (std::size_t(1) << 24) / std::max<std::size_t>(degree * degree, 1)));
    factor_bits = tau + 2 * degree + 64;
    approx_chars = max_bits * 30103 / 100000 + 64;
    checked.push_back("projection: " + names[std::size_t(k)] + " of degree " + std::to_string(degree) +
                      ", a constant multiple of the one of f (values at " + std::to_string(points) + " points)" +
                      (k ? ", the candidates before it vanish identically" : ""));
    factors_claim(at(p, "square_free_factors", "projection"), points, p_values);
    return true;
  }

  // The index k of the projection the certificate names in `names`; the candidates before it vanish identically.
  int projection_index(const json& p, const std::vector<std::string>& names) const {
    const json& nm = at(p, "name", "projection");
    const json& vanishing = at(p, "vanishing", "projection");
    if (!vanishing.is_array() || vanishing.size() > 3)
      reject("certificate format", "projection.vanishing: expected an array of names");
    int k = -1;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (nm == names[i]) k = int(i);
    if (k < 0) reject("projection", "the certificate names " + shown(nm) + ", not a projection this checker knows");
    if (vanishing.size() != std::size_t(k))
      reject("projection", "projection.vanishing must list the " + std::to_string(k) + " candidate(s) before " +
                               names[std::size_t(k)]);
    for (int i = 0; i < k; ++i) {
      if (vanishing[std::size_t(i)] != names[std::size_t(i)])
        reject("projection", "projection.vanishing must list the candidates in order");
      const int count = candidate_bound(i) + 1;
      for (int j = 0; j < count; ++j)
        if (sgn(candidate_at(i, point(j, count))) != 0)
          reject("projection", names[std::size_t(i)] + " does not vanish identically (it is non-zero at t = " +
                                   point(j, count).get_str() + ")");
    }
    return k;
  }

  // P is a constant multiple of candidate k (named `name`) at `points` integers; returns P's values there (times
  // its denominators' lcm).
  std::vector<mpz_class> projection_values(int k, const std::string& name, int points) const {
    const std::vector<mpz_class> PZ = integer_multiple(P, denominator_lcm(P));
    std::optional<std::pair<mpz_class, mpz_class>>
        ratio;  // (got, want) where want ≠ 0 first: got / want is the constant
    std::vector<mpz_class> p_values;
    for (int j = 0; j < points; ++j) {
      const mpz_class t = point(j, points), want = candidate_at(k, t);
      const mpz_class got = value_at(PZ, t);
      p_values.push_back(got);
      if (!ratio && sgn(want) != 0) ratio = std::make_pair(got, want);
      if (ratio ? got * ratio->second != ratio->first * want : sgn(got) != 0)
        reject("projection",
               "P is not a constant multiple of the " + name + " of f (they disagree at t = " + t.get_str() + ")");
    }
    if (!ratio) reject("projection", name + " vanishes identically, but the certificate says it does not");
    return p_values;
  }

  // The square-free factors F: their degrees times multiplicities add up to P's, and their product is P up to a
  // constant (at the `points` integers where P has p_values, points > degree).
  void factors_claim(const json& fj, int points, const std::vector<mpz_class>& p_values) {
    if (!fj.is_array() || fj.empty() || fj.size() > degree)
      reject("factors", "expected a non-empty list of at most " + std::to_string(degree) + " factors");
    long long total = 0;
    for (std::size_t i = 0; i < fj.size(); ++i) {
      const std::string place = "projection.square_free_factors[" + std::to_string(i) + "]";
      const json& co = at(fj[i], "coefficients", place);
      if (!co.is_array() || co.size() > degree + 1)
        reject("certificate format",
               place + ".coefficients: expected at most " + std::to_string(degree + 1) + " coefficients");
      std::vector<mpq_class> c2;
      for (std::size_t k2 = 0; k2 < co.size(); ++k2)
        c2.push_back(rational(co[k2], place + ".coefficients[" + std::to_string(k2) + "]", factor_bits));
      QPoly fi(std::move(c2));
      const int m = int(whole(at(fj[i], "multiplicity", place), place + ".multiplicity", 1, (long long)degree));
      if (fi.degree() < 1) reject("factors", "factor " + std::to_string(i) + " is constant");
      total += (long long)m * fi.degree();
      F.push_back({fi, m});
    }
    if (total != (long long)degree)
      reject("factors", "the factors' degrees times multiplicities add up to " + std::to_string(total) + ", not " +
                            std::to_string(degree));
    std::optional<std::pair<mpz_class, mpz_class>> r2;
    std::vector<std::vector<mpz_class>> FZ;
    for (const auto& fm : F) FZ.push_back(integer_multiple(fm.first, denominator_lcm(fm.first)));
    for (int j = 0; j < points; ++j) {
      const mpz_class t = point(j, points);
      mpz_class prod = 1;
      for (std::size_t i = 0; i < F.size(); ++i) {
        const mpz_class v = value_at(FZ[i], t);
        for (int e = 0; e < F[i].second; ++e) prod *= v;
      }
      const mpz_class& pv = p_values[std::size_t(j)];
      if (!r2 && sgn(pv) != 0) r2 = std::make_pair(prod, pv);
      if (r2 ? prod * r2->second != r2->first * pv : sgn(prod) != 0)
        reject("factors",
               "the product of the factors is not a constant multiple of the projection (they disagree at t = " +
                   t.get_str() + ")");
    }
    checked.push_back("factors: the product of " + std::to_string(F.size()) +
                      " factor(s) is the projection up to a constant (values at " + std::to_string(points) +
                      " points)");
  }

  // The static test at a rational instant: negative roots of f(λ; t) (Descartes where exact, else Sturm).
  St static_status(const mpq_class& t) const {
    // den(t)^n L g_k(t) on integers (n the largest degree): f times a positive constant.
    std::size_t n = 0;
    for (const auto& x : G) n = std::max(n, x.size());
    std::vector<mpz_class> z;
    for (const auto& x : G) {
      mpz_class pad;
      mpz_pow_ui(pad.get_mpz_t(), t.get_den_mpz_t(), (unsigned long)(n - std::max<std::size_t>(x.size(), 1)));
      z.push_back(scaled_value_at(x, t) * pad);
    }
    std::vector<mpq_class> v(z.begin(), z.end());
    const QPoly f(std::move(v));
    if (f.zero() || sgn(f.c[0]) == 0 || f.degree() < H)
      reject("scene", "f(lambda; " + t.get_str() + ") is degenerate (det A or det B vanishes)");
    // Descartes on f(-lambda) first: at most one sign variation means at most
    // one negative root counted with multiplicity (not two, and no multiple
    // one): overlapping. A cubic with a positive discriminant has three
    // distinct real roots, none zero, where Descartes' count is exact: two
    // or more variations are as many negative roots, separate. Else Sturm.
    std::vector<mpz_class> mirrored = z;
    for (std::size_t k = 1; k < mirrored.size(); k += 2) mirrored[k] = -mirrored[k];
    const int v_neg = qpoly_impl::variations(mirrored);
    if (v_neg <= 1) return St::overlapping;
    if (H == 3 && sgn(cubic_discriminant_at(z)) > 0) return St::separate;
    if (negative_roots(f) >= 2) return St::separate;
    const QPoly h = gcd(f, derivative(f));
    if (h.degree() >= 1 && negative_roots(h) >= 1) return St::touching;
    return St::overlapping;
  }

  QPoly evidence(const std::string& nm) {
    if (auto it = evidence_cache.find(nm); it != evidence_cache.end()) return it->second;
    QPoly q;
    const mpq_class four = 4;
    // 2D on the integer G = L g: L² times P or D, the same signs and roots.
    auto combine = [](const ZPoly& x, const ZPoly& y, long k) {
      ZPoly r = product(x, y);
      for (auto& c : r) c *= k;
      return r;
    };
    if (H == 3 && nm == "P") {
      make_integer_g();
      ZPoly z = combine(G[3], G[0], 9);
      add_to(z, product(G[2], G[1]), -1);
      q = to_qpoly(trimmed(std::move(z)));
    } else if (H == 3 && nm == "D") {
      make_integer_g();
      ZPoly z = product(G[2], G[2]);
      add_to(z, combine(G[3], G[1], 3), -1);
      q = to_qpoly(trimmed(std::move(z)));
    } else if (H == 4) {
      auto s = [&](int j, int i) {
        const int bound = (2 * H - 1 - 2 * j) * g_degree();
        std::vector<mpq_class> v;
        for (int k = 0; k <= bound; ++k)
          v.push_back(
              mpq_class(subresultant_at(G_at(mpz_class(k)), j, i)));  // L^rows times s(j,i): a positive constant
        return interpolate_at_integers(v);
      };
      int j = -1, i = -1;
      char tail = 0;
      if (nm == "disc(S_2)") {
        const QPoly a = s(2, 2), b = s(2, 1), c = s(2, 0);
        q = b * b - four * (a * c);
      } else if (std::sscanf(nm.c_str(), "s(%d,%d%c", &j, &i, &tail) == 3 && tail == ')' && i >= 0 && i <= j &&
                 j <= 3 && "s(" + std::to_string(j) + "," + std::to_string(i) + ")" == nm) {
        q = s(j, i);
      } else {
        reject("certificate format", "unknown evidence polynomial \"" + nm + "\"");
      }
    } else {
      reject("certificate format", "unknown evidence polynomial \"" + nm + "\"");
    }
    evidence_cache[nm] = q;
    return q;
  }

  int continuous_claim() {  // 2D, Δ ≡ 0; returns the status on [0, 1]
    const json& ct = at(cert, "continuous_touching", "certificate");
    const QPoly PD = evidence("P") * evidence("D");
    const bool zero = PD.zero();
    const QPoly sized = zero ? g[0] : PD;
    degree = std::size_t(std::max(sized.degree(), 0));
    const std::size_t tau = primitive_bits(sized);
    max_bits = std::min<std::size_t>(
        4 * tau + 1024, std::max<std::size_t>(256, (std::size_t(1) << 24) / std::max<std::size_t>(degree * degree, 1)));
    approx_chars = max_bits * 30103 / 100000 + 64;
    if (at(ct, "identically_zero", "continuous_touching") != json(zero))
      reject("continuous touching", zero ? "P·D vanishes identically, the certificate says it does not"
                                         : "P·D does not vanish identically, the certificate says it does");
    const mpq_class sample = rational(at(ct, "sample", "continuous_touching"), "continuous_touching.sample", max_bits);
    if (!(0 < sample && sample < 1)) reject("continuous touching", "continuous_touching.sample must lie in (0, 1)");
    const St claimed = status_named(at(ct, "status", "continuous_touching"), "continuous_touching.status");
    const St st = static_status(sample);
    if (st != claimed)
      reject("continuous touching",
             std::string("the static test at the sample gives ") + name(st) + ", not " + name(claimed));
    if (st == St::separate)
      reject("continuous touching", "separate at the sample although the discriminant vanishes identically");
    const json& gp = at(ct, "gap_points", "continuous_touching");
    if (!gp.is_array() || gp.size() > 8 * degree + 64)
      reject("certificate format", "continuous_touching.gap_points: too many points");
    if (zero) {
      if (!gp.empty())
        reject("certificate format", "continuous_touching.gap_points: expected [] when P·D vanishes identically");
      if (st != St::overlapping)
        reject("continuous touching", "P·D ≡ 0: a triple or zero double root, overlapping, not touching");
    } else {
      if (sgn(PD(0)) == 0 || sgn(PD(1)) == 0) reject("continuous touching", "P·D vanishes at t = 0 or t = 1");
      std::vector<mpq_class> cut{mpq_class(0)};
      for (std::size_t i = 0; i < gp.size(); ++i) {
        const mpq_class x = rational(gp[i], "continuous_touching.gap_points[" + std::to_string(i) + "]", max_bits);
        if (!(cut.back() < x && x < 1))
          reject("continuous touching", "continuous_touching.gap_points are not increasing inside (0, 1)");
        if (sgn(PD(x)) == 0) reject("continuous touching", "P·D vanishes at gap point " + x.get_str());
        cut.push_back(x);
      }
      cut.push_back(mpq_class(1));
      for (std::size_t i = 0; i + 1 < cut.size(); ++i)
        if (descartes(PD, cut[i], cut[i + 1]) != 0)
          reject("continuous touching", "P·D may have a root in (" + cut[i].get_str() + ", " + cut[i + 1].get_str() +
                                            "): the status may change inside [0, 1]");
    }
    checked.push_back(std::string("continuous touching: ") +
                      (zero ? "P·D vanishes identically, overlapping on [0, 1]"
                            : std::string("P·D has no root in [0, 1], ") + name(st) + " on all of [0, 1]"));
    return int(st);
  }

  void timeline_claim() {
    const json& tl = at(cert, "timeline", "certificate");
    if (!tl.is_array() || tl.size() < 3 || tl.size() % 2 == 0 || tl.size() > 2 * degree + 3)
      reject("timeline", "expected instant, cell, ..., instant (an odd number >= 3 of entries, at most " +
                             std::to_string(2 * degree + 3) + ")");
    for (std::size_t k = 0; k < tl.size(); ++k) {
      const std::string place = "timeline[" + std::to_string(k) + "]";
      Node n;
      n.cell = k % 2 == 1;
      n.place = place;
      if (n.cell) {
        n.lo = n.hi = rational(at(tl[k], "cell_sample", place), place + ".cell_sample", max_bits);
        n.name = "cell " + std::to_string(k / 2) + " (sample " + n.lo.get_str() + ")";
      } else {
        const json& in = at(tl[k], "instant", place);
        n.lo = rational(at(in, "lo", place + ".instant"), place + ".instant.lo", max_bits);
        n.hi = rational(at(in, "hi", place + ".instant"), place + ".instant.hi", max_bits);
        n.name = "instant " + std::to_string(k / 2) + " " + bracket_text(n.lo, n.hi);
        if (n.lo > n.hi) reject(n.name, place + ".instant: lo > hi");
        check_approx(at(in, "approx", place + ".instant"), n.lo, n.hi, n.name, place + ".instant.approx", approx_chars);
        const json& f = at(tl[k], "root_of_factor", place);
        if (!f.is_null()) n.factor = int(whole(f, place + ".root_of_factor", 0, (long long)F.size() - 1));
        if (tl[k].contains("evidence")) n.evidence = tl[k]["evidence"];
        if (!n.evidence.is_array() || n.evidence.size() > 16)
          reject("certificate format", place + ".evidence: expected an array of at most 16 objects");
        for (std::size_t i = 0; i < n.evidence.size(); ++i)
          if (!n.evidence[i].is_object())
            reject("certificate format", place + ".evidence[" + std::to_string(i) +
                                             "]: expected an object {\"poly\", \"sign\"}, got " + shown(n.evidence[i]));
      }
      n.status = status_named(at(tl[k], "status", place), place + ".status");
      nodes.push_back(n);
    }
    if (!(nodes.front().lo == 0 && nodes.front().hi == 0)) reject("timeline", "the first instant must be [0, 0]");
    if (!(nodes.back().lo == 1 && nodes.back().hi == 1)) reject("timeline", "the last instant must be [1, 1]");
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k)
      if (!(nodes[k].hi < nodes[k + 1].lo))
        reject(nodes[k].cell ? nodes[k].name : nodes[k + 1].name,
               "each cell sample must lie strictly between its two brackets, and brackets must be disjoint");
    checked.push_back("timeline: " + std::to_string(nodes.size() / 2 + 1) + " instants and " +
                      std::to_string(nodes.size() / 2) + " cells in order");
  }

  // Every root of P in (0, 1) lies in a bracket of its factor, one per
  // bracket. The gap points cut [0, 1] into pieces; on each piece every
  // factor F_j changes sign across each of its brackets there (so each holds
  // at least one root, the brackets being disjoint) and Descartes' bound for
  // F_j on the whole piece equals the number of its brackets there (so each
  // holds exactly one, and F_j has no other root in the piece). A piece where
  // a bound exceeds that count is proved bracket by bracket instead:
  // Descartes 1 for the bracket's factor and 0 for the others on each
  // bracket, 0 for every factor between the brackets.
  void isolation_claim() {
    std::vector<std::vector<mpz_class>> FZ;
    for (const auto& fm : F) FZ.push_back(integer_multiple(fm.first, denominator_lcm(fm.first)));
    int roots = 0;
    for (std::size_t k = 0; k < nodes.size(); k += 2) {
      const Node& n = nodes[k];
      const bool end = k == 0 || k + 1 == nodes.size();
      if (!n.factor) {
        if (!end) reject(n.name, "an interior instant must be a root of the projection (root_of_factor is null)");
        if (sgn(P(n.lo)) == 0) reject(n.name, "claimed not to be a root, but the projection vanishes there");
        continue;
      }
      ++roots;
      const std::size_t f = std::size_t(*n.factor);
      if (n.lo == n.hi) {
        if (sign_at(FZ[f], n.lo) != 0)
          reject(n.name, "claimed to be a root of factor " + std::to_string(f) + ", which does not vanish there");
        continue;
      }
      for (const auto& z : FZ)
        if (sign_at(z, n.lo) == 0 || sign_at(z, n.hi) == 0)
          reject(n.name, "the projection vanishes at an end of the bracket");
      if (sign_at(FZ[f], n.lo) == sign_at(FZ[f], n.hi))
        reject(n.name, "factor " + std::to_string(f) +
                           " has the same sign at both ends of the bracket: no root of it is proved there");
    }
    const json& gp = at(cert, "gap_points", "certificate");
    if (!gp.is_array() || gp.size() > 8 * degree + 64)
      reject("certificate format",
             "gap_points: expected an array of at most " + std::to_string(8 * degree + 64) + " points");
    std::vector<mpq_class> cuts{mpq_class(0)};
    std::size_t node = 2;  // the first interior instant
    for (std::size_t i = 0; i < gp.size(); ++i) {
      const mpq_class x = rational(gp[i], "gap_points[" + std::to_string(i) + "]", max_bits);
      while (node + 1 < nodes.size() && nodes[node].hi < x) node += 2;
      // x lies in the gap between the instants node - 2 and node: after the one, before the other
      if (!(cuts.back() < x) || !(nodes[node - 2].hi < x && x < nodes[node].lo))
        reject("gaps", "gap point " + x.get_str() + " is not strictly inside a gap, or the points are not increasing");
      for (const auto& z : FZ)
        if (sign_at(z, x) == 0) reject("gaps", "the projection vanishes at gap point " + x.get_str());
      cuts.push_back(x);
    }
    cuts.push_back(mpq_class(1));
    int counted = 0, bracketed = 0;
    std::size_t first = 2;  // the first interior instant of the current piece
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      std::size_t last = first;  // one past the piece's last interior instant
      while (last + 1 < nodes.size() && nodes[last].hi < cuts[c + 1]) last += 2;
      std::vector<int> count(F.size(), 0);
      for (std::size_t k = first; k < last; k += 2) ++count[std::size_t(*nodes[k].factor)];
      bool tight = true;
      for (std::size_t j = 0; j < F.size() && tight; ++j)
        tight = descartes(F[j].first, cuts[c], cuts[c + 1]) == count[j];
      if (tight) {
        ++counted;
      } else {
        ++bracketed;
        piece_by_brackets(cuts[c], cuts[c + 1], first, last);
      }
      first = last;
    }
    checked.push_back(
        "brackets: each of the " + std::to_string(roots) +
        " root bracket(s) holds exactly one root of the projection (a sign change of its factor, and Descartes' bound "
        "on the piece of [0, 1] around it equal to the number of brackets there, or 1 on the bracket)");
    checked.push_back("gaps: no other root of the projection in [0, 1] (" + std::to_string(counted) +
                      " piece(s) by Descartes' count, " + std::to_string(bracketed) + " bracket by bracket)");
  }

  // A piece (a, b) holding the interior instants first, first + 2, ..., last - 2, bracket by bracket.
  void piece_by_brackets(const mpq_class& a, const mpq_class& b, std::size_t first, std::size_t last) {
    mpq_class from = a;
    auto clear = [&](const mpq_class& lo, const mpq_class& hi) {
      if (!(lo < hi)) return;
      for (std::size_t j = 0; j < F.size(); ++j)
        if (descartes(F[j].first, lo, hi) != 0)
          reject("gaps", "the projection may have a root in (" + lo.get_str() + ", " + hi.get_str() +
                             ") outside every bracket (factor " + std::to_string(j) + ")");
    };
    for (std::size_t k = first; k < last; k += 2) {
      const Node& n = nodes[k];
      clear(from, n.lo);
      from = n.hi;
      if (n.lo == n.hi) continue;
      for (std::size_t j = 0; j < F.size(); ++j) {
        const int v = descartes(F[j].first, n.lo, n.hi);
        if (int(j) == *n.factor && v != 1)
          reject(n.name, "does not provably hold exactly one root: factor " + std::to_string(j) + " has " +
                             std::to_string(v) + " sign variation(s) on the bracket");
        if (int(j) != *n.factor && v != 0)
          reject(n.name, "another factor (" + std::to_string(j) + ") may have a root in the bracket (" +
                             std::to_string(v) + " sign variations)");
      }
    }
    clear(from, b);
  }

  int evidence_sign(const Node& n, const std::string& want) {
    for (std::size_t i = 0; i < n.evidence.size(); ++i) {
      const json& e = n.evidence[i];
      const std::string place = n.place + ".evidence[" + std::to_string(i) + "]";
      if (at(e, "poly", place) != want) continue;
      const QPoly q = evidence(want);
      const int claimed = sign_named(at(e, "sign", place), place + ".sign");
      if (claimed != 0) {
        // The sign on the whole bracket: by the mean value theorem when |q(lo)| is large enough, else by Descartes (0
        // variations).
        const std::vector<mpz_class> z = integer_multiple(q, denominator_lcm(q));
        int s = sign_on_bracket(z, n.lo, n.hi);
        if (s == 0) {
          s = sign_at(z, n.lo);
          if (s == 0 || descartes(q, n.lo, n.hi) != 0)
            reject(n.name, "the sign of " + want + " at the root is not proved: it may vanish on the bracket");
        }
        if (s != claimed) reject(n.name, want + " has the other sign on the bracket than claimed");
        return claimed;
      }
      const json& hj = at(e, "common_factor", place);
      if (!hj.is_array() || hj.size() > degree + 1)
        reject("certificate format",
               place + ".common_factor: expected at most " + std::to_string(degree + 1) + " coefficients");
      std::vector<mpq_class> c;
      for (std::size_t k = 0; k < hj.size(); ++k)
        c.push_back(rational(hj[k], place + ".common_factor[" + std::to_string(k) + "]", factor_bits));
      const QPoly h(std::move(c));
      if (h.degree() < 1) reject(n.name, "the common factor offered for " + want + " = 0 is constant");
      QPoly quo, rem;
      divmod(q, h, quo, rem);
      if (!rem.zero()) reject(n.name, "the common factor offered for " + want + " = 0 does not divide " + want);
      divmod(F[std::size_t(*n.factor)].first, h, quo, rem);
      if (!rem.zero())
        reject(n.name, "the common factor offered for " + want + " = 0 does not divide the root's factor");
      if (sgn(h(n.lo)) == 0 || sgn(h(n.hi)) == 0 || descartes(h, n.lo, n.hi) != 1)
        reject(n.name, "the common factor offered for " + want + " = 0 has no proved root in the bracket");
      return 0;
    }
    reject(n.name, "the evidence for the sign of " + want + " at the root is missing");
  }

  void status_claims() {
    for (std::size_t k = 1; k < nodes.size(); k += 2) {
      const St st = static_status(nodes[k].lo);
      if (st != nodes[k].status)
        reject(nodes[k].name, std::string("the static test gives ") + name(st) + ", not " + name(nodes[k].status));
    }
    checked.push_back(
        "cells: the static test (negative roots of f by Descartes where exact, else Sturm) at each of the " +
        std::to_string(nodes.size() / 2) + " sample(s) gives the claimed status");
    int rational_count = 0, irrational = 0;
    for (std::size_t k = 0; k < nodes.size(); k += 2) {
      Node& n = nodes[k];
      St st;
      if (n.lo == n.hi) {
        st = static_status(n.lo);
        ++rational_count;
      } else if (!n.factor) {
        reject(n.name, "an end instant that is not a root must be a point");
      } else {
        ++irrational;
        if (H == 3) {
          // 003 Theorem 6: at a double root of f, it is -P/(... ) with the sign of P·D: touching iff P·D < 0; D = 0: a
          // triple root, overlapping.
          const int sp = evidence_sign(n, "P"), sd = evidence_sign(n, "D");
          st = sd == 0 ? St::overlapping : sp * sd < 0 ? St::touching : St::overlapping;
        } else {
          const int touch = negative_multiple_root(n);
          if (touch > 0) {
            st = St::touching;
          } else {
            st = nodes[k - 1].status;
            if (nodes[k + 1].status != st)
              reject(n.name, "no negative multiple root, yet the neighbouring cells have different statuses");
          }
        }
      }
      if (st != n.status) reject(n.name, std::string("the evidence gives ") + name(st) + ", not " + name(n.status));
    }
    checked.push_back("instants: " + std::to_string(rational_count) + " rational instant(s) by the static test, " +
                      std::to_string(irrational) + " root(s) by proved signs of the evidence polynomials");
  }

  // 3D: does f have a negative multiple root at the root of node n (gcd(f, f') = S_j, j the least > k with s(j,j) ≠ 0)?
  int negative_multiple_root(const Node& n) {
    auto sg = [&](int j, int i) {
      return evidence_sign(n,
                           i < 0 ? std::string("disc(S_2)") : "s(" + std::to_string(j) + "," + std::to_string(i) + ")");
    };
    for (int j = projection_k + 1; j <= 3; ++j) {
      const int lead = sg(j, j);
      if (lead == 0) continue;
      if (j == 1 || j == 3) return sg(j, j - 1) * lead > 0 ? 1 : 0;  // the root -s(j,j-1)/(j' s(j,j)) is negative
      const int b = sg(2, 1), c = sg(2, 0), d = sg(2, -1);
      if (d < 0) return 0;  // a complex pair
      const bool neg = lead * c < 0 || (lead * c > 0 && lead * b > 0) || (c == 0 && lead * b > 0);
      return neg ? 1 : 0;
    }
    reject(n.name, "every subresultant coefficient s(j,j), j > k, vanishes at the root: impossible for a quartic");
  }

  void run() {
    const json& fmt = at(cert, "format", "certificate");
    if (fmt != "eccd-certificate/2")
      reject("certificate format",
             "format: expected \"eccd-certificate/2\", got " + shown(fmt) +
                 (fmt == "eccd-certificate/1" ? " (format 1 is no longer accepted: run eccd certify again)" : ""));
    checked.push_back("certificate format: eccd-certificate/2");
    H = sc.dim + 1;
    scene_claim();
    f_claim();
    if (!projection_claim()) {
      const St st = St(continuous_claim());
      using Br = std::pair<mpq_class, mpq_class>;
      const Br z{0, 0}, o{1, 1};
      std::vector<std::pair<Br, Br>> iv{{z, o}}, ci;
      if (st == St::touching) ci.push_back({z, o});
      compare_answer(cert, iv, {}, ci, max_bits, approx_chars, checked);
      return;
    }
    timeline_claim();
    isolation_claim();
    status_claims();
    if (H == 3)
      for (std::size_t k = 2; k + 2 < nodes.size(); k += 2)
        if (nodes[k].status == St::overlapping && nodes[k - 1].status == St::separate &&
            nodes[k + 1].status == St::separate)
          reject("timeline",
                 "the statuses contradict 003 Theorem 6: an overlapping instant between two separate cells");
    answer_claim(cert, nodes, max_bits, approx_chars, checked);
  }
};

}  // namespace

void check_exact_certificate(const CheckScene& sc, const json& cert, std::vector<std::string>& checked) {
  Checker c(sc, cert, checked);
  c.run();
}

}  // namespace eccd::check
