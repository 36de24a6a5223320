// The prover-side self-check of eccd-certificate/2
// (certificate/write/prover_self_check.hpp). Deliberately simple: it includes
// no root isolation and no CCD driver, only the exact algebra of
// exact/certificate_algebra.hpp, Descartes' rule and the timeline-to-answer step.
#include "certificate/write/prover_self_check.hpp"

#include "certificate/write/certificate_json.hpp"
#include "certificate/write/exact_certificate.hpp"
#include "exact/certificate_algebra.hpp"
#include "exact/descartes.hpp"
#include "io/scene_reader.hpp"
#include "kernel/collision_timeline.hpp"

#include <map>
#include <optional>

namespace eccd {

namespace {

using json = nlohmann::json;

using namespace certificate_json;

Rational rat(const json& j, const std::string& place, std::size_t max_bits) {
  return read_rational(j, place, max_bits);
}

Poly<Rational> poly(const json& j, const std::string& place, std::size_t max_bits, std::size_t max_terms) {
  if (!j.is_array()) reject("certificate format", place + ": expected an array of coefficients");
  if (j.size() > max_terms)
    reject("certificate format",
           place + ": " + std::to_string(j.size()) + " coefficients, more than the degree allows");
  Poly<Rational> p;
  for (std::size_t i = 0; i < j.size(); ++i) p.c.push_back(rat(j[i], place + "[" + std::to_string(i) + "]", max_bits));
  p.trim();
  return p;
}

// A JSON integer in [lo, hi] (no truncation: 4294967296 is not 0).
long long whole(const json& j, const std::string& place, long long lo, long long hi) {
  bool ok = j.is_number_integer();
  long long v = 0;
  if (ok && j.is_number_unsigned()) {
    ok = j.get<std::uint64_t>() <= std::uint64_t(hi) && hi >= 0;
    if (ok) v = (long long)j.get<std::uint64_t>();
  } else if (ok) {
    v = j.get<std::int64_t>();
  }
  if (!ok || v < lo || v > hi)
    reject("certificate format", place + ": expected a whole number from " + std::to_string(lo) + " to " +
                                     std::to_string(hi) + ", got " + j.dump().substr(0, 40));
  return v;
}

Status status_named(const json& j, const std::string& place) {
  if (j.is_string())
    for (Status s : {Status::separate, Status::touching, Status::overlapping})
      if (j.get<std::string>() == to_string(s)) return s;
  reject("certificate format", place + ": expected \"separate\", \"touching\" or \"overlapping\"");
}

Sign sign_named(const json& j, const std::string& place) {
  if (j.is_string())
    for (Sign s : {Sign::negative, Sign::zero, Sign::positive})
      if (j.get<std::string>() == to_string(s)) return s;
  reject("certificate format", place + ": expected \"negative\", \"zero\" or \"positive\"");
}

// An instant's approx must be a plain decimal lying in its bracket [lo, hi];
// for a point [r, r] whose r needs more digits, r correctly rounded to the
// approx's own last digit (exact/certificate_algebra.hpp, approx_in_bracket).
void check_approx(const json& approx, const Rational& lo, const Rational& hi, const std::string& claim,
                  const std::string& place, std::size_t max_chars) {
  if (!approx.is_string())
    reject(claim, place + ": approx must be a decimal string, got " + approx.dump().substr(0, 40));
  const std::string& a = approx.get_ref<const std::string&>();
  const std::string shown = json(a.size() > 40 ? a.substr(0, 40) + "..." : a).dump();
  auto v = read_approx(a, max_chars);
  if (!v) reject(claim, place + ": approx " + shown + " is not a decimal number");
  bool ok = lo == hi ? abs(Rational(v->value - lo)) * 2 <= v->unit : (lo <= v->value && v->value <= hi);
  if (!ok)
    reject(claim, place + ": approx " + shown + " lies outside its bracket [" + lo.get_str() + ", " + hi.get_str() +
                      "] (~" + decimal_string(Rational((lo + hi) / 2), 12) + ")");
}

std::string bracket_text(const Rational& lo, const Rational& hi) {
  if (lo == hi) return "[" + lo.get_str() + "]";
  return "[" + lo.get_str() + ", " + hi.get_str() + "] (~" + decimal_string(Rational((lo + hi) / 2), 12) + ")";
}

bool same_instant(const Instant& a, const Instant& b) {
  return a.certified() && b.certified() && *a.lo == *b.lo && *a.hi == *b.hi;
}

struct Node {
  Rational lo, hi;  // instant bracket, or the cell sample (lo = hi)
  bool is_cell = false;
  Status status = Status::uncertain;
  std::optional<int> factor;
  json evidence;
  std::string name;   // for messages
  std::string place;  // JSON place, e.g. timeline[2]
};

struct Checker {
  const Scene& s;
  const json& scene_doc;
  const json& cert;
  CertificateAlgebra alg;
  std::vector<std::pair<Poly<Rational>, int>> F;
  std::vector<Node> nodes;
  std::vector<std::string> checked;
  // Size bounds relative to the scene (denial of service): every rational the
  // checker computes with has at most max_bits bits; factor coefficients at
  // most factor_bits; a decimal approx at most approx_chars characters.
  std::size_t max_bits = 0, factor_bits = 0, approx_chars = 0, degree = 0;
  Answer continuous;  // Δ ≡ 0: the answer the continuous-touching claim gives

  void set_bounds(const Poly<Rational>& p) {
    const std::size_t tau = integer_coefficient_bits(p);
    degree = std::size_t(std::max(p.degree(), 0));
    max_bits = certificate_max_bits(degree, tau);
    factor_bits = tau + 2 * degree + 64;
    approx_chars = max_bits * 30103 / 100000 + 64;
  }

  void scene() {
    const json& sc = at(cert, "scene", "certificate");
    for (const char* k : {"dim", "a", "b"})
      if (at(sc, k, "scene") != scene_doc.at(k))
        reject("scene", std::string("the certificate's \"") + k +
                            "\" differs from the scene file's: it is a certificate for another scene");
    checked.push_back("scene: dim, a and b are those of " + s.path);
  }

  void f() {
    const json& g = at(at(cert, "f", "certificate"), "g", "f");
    if (!g.is_array() || g.size() != alg.g.size())
      reject("f", "expected " + std::to_string(alg.g.size()) + " coefficient polynomials g_0 .. g_" +
                      std::to_string(alg.g.size() - 1));
    for (std::size_t k = 0; k < alg.g.size(); ++k) {
      Poly<Rational> gk = poly(g[k], "f.g[" + std::to_string(k) + "]", coefficient_bits(alg.g[k]) + 64,
                               std::size_t(alg.g[k].degree() + 2));
      if (!(gk == alg.g[k]))
        reject("f", "g_" + std::to_string(k) + " differs from det(lambda A(t) - B(t)) recomputed from the scene");
    }
    checked.push_back("f: g_0 .. g_" + std::to_string(alg.g.size() - 1) +
                      " equal the recomputed characteristic polynomial");
  }

  // Returns false when the projection vanishes identically (2D Δ ≡ 0).
  bool projection() {
    const json& p = at(cert, "projection", "certificate");
    const json& name = at(p, "name", "projection");
    if (!name.is_string() || name.get<std::string>() != alg.projection_name)
      reject("projection", "the certificate names " + name.dump() + " but the recomputed projection is " +
                               alg.projection_name +
                               (alg.vanishing.empty() ? "" : " (the candidates before it vanish identically)"));
    if (at(p, "vanishing", "projection") != json(alg.vanishing))
      reject("projection", "the list of identically vanishing candidates differs from the recomputed one");
    bool zero = alg.projection.is_zero();
    if (at(p, "identically_zero", "projection") != json(zero))
      reject("projection", zero ? "the recomputed projection vanishes identically"
                                : "the recomputed projection does not vanish identically");
    if (zero) {
      checked.push_back("projection: the discriminant vanishes identically (003 Corollary 7: never separate)");
      continuous_touching();
      return false;
    }
    set_bounds(alg.projection);
    if (whole(at(p, "degree", "projection"), "projection.degree", 0, 1 << 30) != alg.projection.degree())
      reject("projection", "projection.degree says " + at(p, "degree", "projection").dump() + " but the recomputed " +
                               alg.projection_name + " has degree " + std::to_string(alg.projection.degree()));
    std::vector<std::string> want = integer_coefficients(alg.projection);
    const json& coeffs = at(p, "coefficients", "projection");
    if (!coeffs.is_array() || coeffs.size() != want.size())
      reject("projection", "expected " + std::to_string(want.size()) + " coefficients (degree " +
                               std::to_string(alg.projection.degree()) + ")");
    for (std::size_t i = 0; i < want.size(); ++i)
      if (!coeffs[i].is_string() || coeffs[i].get<std::string>() != want[i])
        reject("projection", "coefficient " + std::to_string(i) + " (of t^" + std::to_string(i) +
                                 ") differs from the recomputed " + alg.projection_name);
    checked.push_back("projection: " + alg.projection_name + " of degree " + std::to_string(alg.projection.degree()) +
                      ", integer coefficients equal the recomputed ones");
    // Square-free factors.
    const json& fj = at(p, "square_free_factors", "projection");
    if (!fj.is_array() || fj.empty() || fj.size() > degree)
      reject("factors", "expected a non-empty list of at most " + std::to_string(degree) + " square-free factors");
    long long total = 0;
    for (std::size_t i = 0; i < fj.size(); ++i) {
      std::string place = "projection.square_free_factors[" + std::to_string(i) + "]";
      Poly<Rational> fi = poly(at(fj[i], "coefficients", place), place + ".coefficients", factor_bits, degree + 1);
      int m = int(whole(at(fj[i], "multiplicity", place), place + ".multiplicity", 1, (long long)degree));
      if (fi.degree() < 1) reject("factors", "factor " + std::to_string(i) + " is constant");
      total += (long long)m * fi.degree();
      F.push_back({fi, m});
    }
    if (total != alg.projection.degree())  // checked before multiplying: a forged multiplicity costs nothing
      reject("factors", "the degrees of the square-free factors times their multiplicities add up to " +
                            std::to_string(total) + ", not the projection's degree " +
                            std::to_string(alg.projection.degree()));
    Poly<Rational> prod({Rational(1)});
    for (const auto& [fi, m] : F)
      for (int k = 0; k < m; ++k) prod = prod * fi;
    Poly<Rational> lhs = prod.lead() * alg.projection, rhs = alg.projection.lead() * prod;
    if (!(lhs == rhs))
      reject("factors",
             "the product of the square-free factors (with their multiplicities) is not a constant multiple of the "
             "projection");
    checked.push_back("factors: the product of " + std::to_string(F.size()) +
                      " square-free factor(s) is the projection up to a constant");
    return true;
  }

  // 2D, Δ ≡ 0: never separate (003 Corollary 7), so C = [0, 1]. The double
  // root of f is P/(2D) (P, D of 003 Theorem 6); where P·D has no root the
  // status is constant: touching (negative double root) or overlapping. The
  // certificate claims P·D has no root in [0, 1] (gap points, Descartes 0 on
  // each piece, P·D ≠ 0 at 0, 1 and the points) and gives the status at one
  // sample (the exact static test); touching means the contact interval
  // [0, 1]. If P·D ≡ 0, the double root is 0 or triple: overlapping.
  void continuous_touching() {
    const json& ct = at(cert, "continuous_touching", "certificate");
    const Poly<Rational> PD = alg.evidence("P") * alg.evidence("D");
    set_bounds(PD.is_zero() ? alg.g[0] : PD);
    const bool zero = PD.is_zero();
    if (at(ct, "identically_zero", "continuous_touching") != json(zero))
      reject("continuous touching", zero
                                        ? "P·D vanishes identically (recomputed), the certificate says it does not"
                                        : "P·D does not vanish identically (recomputed), the certificate says it does");
    const Rational sample = rat(at(ct, "sample", "continuous_touching"), "continuous_touching.sample", max_bits);
    if (!(Rational(0) < sample && sample < Rational(1)))
      reject("continuous touching", "continuous_touching.sample must lie in (0, 1)");
    Status claimed = status_named(at(ct, "status", "continuous_touching"), "continuous_touching.status");
    Status st = alg.status_at(sample);
    if (st != claimed)
      reject("continuous touching",
             std::string("the exact static test at the sample gives ") + to_string(st) + ", not " + to_string(claimed));
    if (st == Status::separate)
      reject("continuous touching", "separate at the sample although the discriminant vanishes identically");
    const json& gp = at(ct, "gap_points", "continuous_touching");
    const std::size_t max_points = certificate_max_gap_points(degree);
    if (!gp.is_array() || gp.size() > max_points)
      reject("certificate format",
             "continuous_touching.gap_points: expected an array of at most " + std::to_string(max_points) + " points");
    if (zero) {
      if (!gp.empty())
        reject("certificate format", "continuous_touching.gap_points: expected [] when P·D vanishes identically");
      if (st != Status::overlapping)
        reject("continuous touching", "P·D ≡ 0 means a triple or zero double root: overlapping, not touching");
    } else {
      if (is_zero(PD(Rational(0))) || is_zero(PD(Rational(1))))
        reject("continuous touching",
               "P·D vanishes at t = 0 or t = 1: the status may change there (not certifiable in this format)");
      std::vector<Rational> cut{Rational(0)};
      for (std::size_t i = 0; i < gp.size(); ++i) {
        Rational x = rat(gp[i], "continuous_touching.gap_points[" + std::to_string(i) + "]", max_bits);
        if (!(cut.back() < x && x < Rational(1)))
          reject("continuous touching",
                 "continuous_touching.gap_points[" + std::to_string(i) + "] is not increasing inside (0, 1)");
        if (is_zero(PD(x))) reject("continuous touching", "P·D vanishes at gap point " + x.get_str());
        cut.push_back(x);
      }
      cut.push_back(Rational(1));
      for (std::size_t i = 0; i + 1 < cut.size(); ++i)
        if (int v = descartes_variations(PD, cut[i], cut[i + 1]); v != 0)
          reject("continuous touching", "P·D may have a root in (" + cut[i].get_str() + ", " + cut[i + 1].get_str() +
                                            "): " + std::to_string(v) +
                                            " sign variation(s), so the status may change inside [0, 1]");
    }
    Instant i0{"0", Rational(0), Rational(0)}, i1{"1", Rational(1), Rational(1)};
    continuous.collides = true;
    continuous.intervals.push_back({i0, i1});
    continuous.first_contact = i0;
    if (st == Status::touching) continuous.contact_intervals.push_back({i0, i1});
    checked.push_back(std::string("continuous touching: ") +
                      (zero ? "P·D vanishes identically, overlapping on [0, 1]"
                            : std::string("P·D has no root in [0, 1], so the status is ") + to_string(st) +
                                  " on all of [0, 1]" + (st == Status::touching ? " (contact interval [0, 1])" : "")));
  }

  void timeline() {
    const json& tl = at(cert, "timeline", "certificate");
    if (!tl.is_array() || tl.size() < 3 || tl.size() % 2 == 0 || tl.size() > 2 * degree + 3)
      reject("timeline", "expected instant, cell, instant, ..., instant (an odd number >= 3 of entries, at most " +
                             std::to_string(2 * degree + 3) + " for a projection of degree " + std::to_string(degree) +
                             ")");
    for (std::size_t k = 0; k < tl.size(); ++k) {
      std::string place = "timeline[" + std::to_string(k) + "]";
      Node n;
      n.is_cell = k % 2 == 1;
      if (n.is_cell) {
        n.lo = n.hi = rat(at(tl[k], "cell_sample", place), place + ".cell_sample", max_bits);
        n.name = "cell " + std::to_string(k / 2) + " (sample " + n.lo.get_str() + ")";
      } else {
        const json& in = at(tl[k], "instant", place);
        n.lo = rat(at(in, "lo", place + ".instant"), place + ".instant.lo", max_bits);
        n.hi = rat(at(in, "hi", place + ".instant"), place + ".instant.hi", max_bits);
        n.name = "instant " + std::to_string(k / 2) + " " + bracket_text(n.lo, n.hi);
        if (n.lo > n.hi) reject(n.name, place + ".instant: lo > hi");
        check_approx(at(in, "approx", place + ".instant"), n.lo, n.hi, n.name, place + ".instant.approx", approx_chars);
        const json& f = at(tl[k], "root_of_factor", place);
        if (!f.is_null()) n.factor = int(whole(f, place + ".root_of_factor", 0, (long long)F.size() - 1));
        n.evidence = tl[k].contains("evidence") ? tl[k]["evidence"] : json::array();
        if (!n.evidence.is_array() || n.evidence.size() > 16)
          reject("certificate format",
                 place + ".evidence: expected an array of at most 16 objects {\"poly\", \"sign\"}, got " +
                     n.evidence.dump().substr(0, 40));
        for (std::size_t i = 0; i < n.evidence.size(); ++i)
          if (!n.evidence[i].is_object())
            reject("certificate format", place + ".evidence[" + std::to_string(i) +
                                             "]: expected an object {\"poly\", \"sign\", ...}, got " +
                                             n.evidence[i].dump().substr(0, 40));
        n.place = place;
      }
      n.status = status_named(at(tl[k], "status", place), place + ".status");
      nodes.push_back(n);
    }
    if (!(nodes.front().lo == 0 && nodes.front().hi == 0)) reject("timeline", "the first instant must be [0, 0]");
    if (!(nodes.back().lo == 1 && nodes.back().hi == 1)) reject("timeline", "the last instant must be [1, 1]");
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k)
      if (!(nodes[k].hi < nodes[k + 1].lo))
        reject(nodes[k].is_cell ? nodes[k].name : nodes[k + 1].name,
               "the sample of a cell must lie strictly between the brackets of its two instants, and brackets must be "
               "disjoint");
    checked.push_back("timeline: " + std::to_string(nodes.size() / 2 + 1) + " instants and " +
                      std::to_string(nodes.size() / 2) +
                      " cells, brackets disjoint, each sample strictly between its brackets");
  }

  void isolation() {
    const Poly<Rational>& P = alg.projection;
    int roots = 0;
    for (std::size_t k = 0; k < nodes.size(); k += 2) {
      const Node& n = nodes[k];
      bool end = k == 0 || k + 1 == nodes.size();
      if (!n.factor) {
        if (!end) reject(n.name, "an interior instant must be a root of the projection (root_of_factor is null)");
        if (is_zero(P(n.lo))) reject(n.name, "claimed not to be a root, but the projection vanishes there");
        continue;
      }
      ++roots;
      const Poly<Rational>& Fi = F[*n.factor].first;
      if (n.lo == n.hi) {
        if (!is_zero(Fi(n.lo)))
          reject(n.name,
                 "claimed to be a root of factor " + std::to_string(*n.factor) + ", which does not vanish there");
        continue;
      }
      if (is_zero(P(n.lo)) || is_zero(P(n.hi))) reject(n.name, "the projection vanishes at an end of the bracket");
      for (std::size_t j = 0; j < F.size(); ++j) {
        int v = descartes_variations(F[j].first, n.lo, n.hi);
        if (int(j) == *n.factor && v != 1)
          reject(n.name, "does not provably hold exactly one root: factor " + std::to_string(j) + " has " +
                             std::to_string(v) + " sign variation(s) on the bracket (Descartes needs 1)");
        if (int(j) != *n.factor && v != 0)
          reject(n.name, "another factor (" + std::to_string(j) + ") may have a root in the bracket (" +
                             std::to_string(v) + " sign variations)");
      }
    }
    checked.push_back("brackets: each of the " + std::to_string(roots) +
                      " root bracket(s) holds exactly one root of the projection (Descartes)");
    // Gaps.
    std::vector<Rational> pts;
    const json& gp = at(cert, "gap_points", "certificate");
    const std::size_t max_points = certificate_max_gap_points(degree);
    if (!gp.is_array() || gp.size() > max_points)
      reject("certificate format",
             "gap_points: expected an array of at most " + std::to_string(max_points) + " points");
    for (std::size_t i = 0; i < gp.size(); ++i)
      pts.push_back(rat(gp[i], "gap_points[" + std::to_string(i) + "]", max_bits));
    std::size_t used = 0;
    int pieces = 0;
    for (std::size_t k = 0; k + 2 < nodes.size(); k += 2) {
      Rational a = nodes[k].hi, b = nodes[k + 2].lo;
      std::vector<Rational> cut{a};
      while (used < pts.size() && pts[used] < b) {
        if (!(cut.back() < pts[used]))
          reject("gaps", "gap point " + pts[used].get_str() +
                             " is not strictly inside a gap, or the points are not increasing");
        if (is_zero(P(pts[used]))) reject("gaps", "the projection vanishes at gap point " + pts[used].get_str());
        cut.push_back(pts[used++]);
      }
      cut.push_back(b);
      for (std::size_t i = 0; i + 1 < cut.size(); ++i, ++pieces)
        for (std::size_t j = 0; j < F.size(); ++j)
          if (int v = descartes_variations(F[j].first, cut[i], cut[i + 1]); v != 0)
            reject("gaps", "the projection may have a root in (" + cut[i].get_str() + ", " + cut[i + 1].get_str() +
                               ") outside every bracket: factor " + std::to_string(j) + " has " + std::to_string(v) +
                               " sign variation(s) there");
    }
    if (used != pts.size()) reject("gaps", "gap point " + pts[used].get_str() + " is not strictly inside a gap");
    checked.push_back("gaps: no other root of the projection in [0, 1] (" + std::to_string(pieces) +
                      " piece(s), 0 sign variations each)");
  }

  // The proved sign of an evidence polynomial at the root of node n.
  Sign evidence_sign(const Node& n, const std::string& want) {
    for (std::size_t i = 0; i < n.evidence.size(); ++i) {
      const json& e = n.evidence[i];
      std::string place = n.place + ".evidence[" + std::to_string(i) + "]";
      const json& nm = at(e, "poly", place);
      if (!nm.is_string() || nm.get<std::string>() != want) continue;
      Poly<Rational> q;
      try {
        q = alg.evidence(want);
      } catch (const std::invalid_argument& ex) {
        reject(n.name, ex.what());
      }
      Sign claimed = sign_named(at(e, "sign", place), place + ".sign");
      if (claimed != Sign::zero) {
        if (is_zero(q(n.lo)) || descartes_variations(q, n.lo, n.hi) != 0)
          reject(n.name, "the sign of " + want + " at the root is not proved: " + want + " may vanish on the bracket");
        if (sign(q(n.lo)) != claimed)
          reject(n.name, want + " is " + to_string(sign(q(n.lo))) + " on the bracket, not " + to_string(claimed) +
                             " as claimed");
        return claimed;
      }
      Poly<Rational> h = poly(at(e, "common_factor", place), place + ".common_factor", factor_bits, degree + 1), quo,
                     rem;
      if (h.degree() < 1) reject(n.name, "the common factor offered for " + want + " = 0 is constant");
      divide(q, h, quo, rem);
      if (!rem.is_zero()) reject(n.name, "the common factor offered for " + want + " = 0 does not divide " + want);
      divide(F[*n.factor].first, h, quo, rem);
      if (!rem.is_zero())
        reject(n.name, "the common factor offered for " + want + " = 0 does not divide the root's factor");
      if (descartes_variations(h, n.lo, n.hi) != 1)
        reject(n.name, "the common factor offered for " + want + " = 0 has no proved root in the bracket");
      return Sign::zero;
    }
    reject(n.name, "the evidence for the sign of " + want + " at the root is missing");
  }

  void statuses() {
    int cells = 0;
    for (std::size_t k = 1; k < nodes.size(); k += 2, ++cells) {
      Status st = alg.status_at(nodes[k].lo);
      if (st != nodes[k].status)
        reject(nodes[k].name, std::string("the exact static test gives ") + to_string(st) + ", not " +
                                  to_string(nodes[k].status) + " as claimed");
    }
    checked.push_back("cells: the exact static test at each of the " + std::to_string(cells) +
                      " sample(s) gives the claimed status");
    int rational = 0, irrational = 0;
    for (std::size_t k = 0; k < nodes.size(); k += 2) {
      Node& n = nodes[k];
      Status st;
      if (n.lo == n.hi) {
        st = alg.status_at(n.lo);
        ++rational;
      } else {
        ++irrational;
        if (alg.dim == 2) {
          Sign sp = evidence_sign(n, "P"), sd = evidence_sign(n, "D");
          st = status_at_multiple_root(sp, sd);
        } else {
          Sign touch = negative_multiple_root(
              alg.projection_index, [&](int j, int i) { return evidence_sign(n, subresultant_evidence_name(j, i)); });
          if (touch == Sign::positive) {
            st = Status::touching;
          } else {
            st = nodes[k - 1].status;
            if (nodes[k + 1].status != st)
              reject(n.name,
                     "no negative multiple root, yet the neighbouring cells have different statuses (the status can "
                     "only change through a touch)");
          }
        }
      }
      if (st != n.status)
        reject(n.name,
               std::string("the evidence gives ") + to_string(st) + ", not " + to_string(n.status) + " as claimed");
    }
    checked.push_back("instants: " + std::to_string(rational) + " rational instant(s) by the exact static test, " +
                      std::to_string(irrational) + " root(s) by proved signs of the evidence polynomials");
  }

  void answer(const std::optional<Answer>& derived) {
    Answer want;
    try {
      want = answer_from_json(at(cert, "answer", "certificate"), "certificate", "answer");
    } catch (const SceneError& e) {
      reject("certificate format", e.what());
    }
    const Answer& got = *derived;
    auto approx_ok = [&](const Instant& i, const std::string& place) {
      if (!i.certified()) reject("answer", place + ": the instant has no bracket (lo, hi null)");
      check_approx(json(i.approx), *i.lo, *i.hi, "answer", place + ".approx", approx_chars ? approx_chars : 200);
    };
    for (std::size_t i = 0; i < want.intervals.size(); ++i) {
      approx_ok(want.intervals[i].first, "answer.intervals[" + std::to_string(i) + "][0]");
      approx_ok(want.intervals[i].second, "answer.intervals[" + std::to_string(i) + "][1]");
    }
    if (want.first_contact) approx_ok(*want.first_contact, "answer.first_contact");
    for (std::size_t i = 0; i < want.contacts.size(); ++i)
      approx_ok(want.contacts[i], "answer.contacts[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < want.contact_intervals.size(); ++i) {
      approx_ok(want.contact_intervals[i].first, "answer.contact_intervals[" + std::to_string(i) + "][0]");
      approx_ok(want.contact_intervals[i].second, "answer.contact_intervals[" + std::to_string(i) + "][1]");
    }
    if (got.collides != want.collides)
      reject("answer", std::string("the timeline gives collides = ") + (got.collides ? "true" : "false"));
    if (got.intervals.size() != want.intervals.size())
      reject("answer", "the timeline gives " + std::to_string(got.intervals.size()) +
                           " collision interval(s), the certificate " + std::to_string(want.intervals.size()));
    for (std::size_t i = 0; i < got.intervals.size(); ++i)
      if (!same_instant(got.intervals[i].first, want.intervals[i].first) ||
          !same_instant(got.intervals[i].second, want.intervals[i].second))
        reject("answer", "collision interval " + std::to_string(i + 1) + " differs from the one the timeline gives");
    if (got.first_contact.has_value() != want.first_contact.has_value() ||
        (got.first_contact && !same_instant(*got.first_contact, *want.first_contact)))
      reject("answer", "first_contact differs from the one the timeline gives");
    if (got.contacts.size() != want.contacts.size())
      reject("answer", "the timeline gives " + std::to_string(got.contacts.size()) + " contact(s), the certificate " +
                           std::to_string(want.contacts.size()));
    for (std::size_t i = 0; i < got.contacts.size(); ++i)
      if (!same_instant(got.contacts[i], want.contacts[i]))
        reject("answer", "contact " + std::to_string(i + 1) + " differs from the one the timeline gives");
    if (got.contact_intervals.size() != want.contact_intervals.size())
      reject("answer", "the timeline gives " + std::to_string(got.contact_intervals.size()) +
                           " contact interval(s) (continuous touching), the certificate " +
                           std::to_string(want.contact_intervals.size()) +
                           (got.contact_intervals.size() > want.contact_intervals.size()
                                ? ": it would pass a continuous touch off as an overlap"
                                : ""));
    for (std::size_t i = 0; i < got.contact_intervals.size(); ++i)
      if (!same_instant(got.contact_intervals[i].first, want.contact_intervals[i].first) ||
          !same_instant(got.contact_intervals[i].second, want.contact_intervals[i].second))
        reject("answer", "contact interval " + std::to_string(i + 1) + " differs from the one the timeline gives");
    checked.push_back("answer: follows from the checked timeline, every approx in its bracket");
  }

  void run() {
    const json& fmt = at(cert, "format", "certificate");
    if (fmt != "eccd-certificate/2")
      reject("certificate format",
             std::string("format: expected \"eccd-certificate/2\"") +
                 (fmt == "eccd-certificate/1" ? " (format 1, written by an older eccd, has no checked approx and no "
                                                "continuous touching: run eccd certify again)"
                                              : ""));
    scene();
    f();
    if (!projection()) {
      answer(continuous);  // Δ ≡ 0: the collision set is [0, 1], continuous touching as checked
      return;
    }
    timeline();
    isolation();
    statuses();
    std::vector<TimelineNode> seq;
    for (const auto& n : nodes) {
      Rational mid = (n.lo + n.hi) / 2;
      seq.push_back({bracketed_instant(mid, n.lo, n.hi), n.status, n.is_cell});
    }
    if (alg.dim == 2) {
      try {
        check_isolated_instants(seq, true);
      } catch (const std::logic_error& e) {
        reject("timeline", "the statuses contradict 003 Theorem 6: an overlapping instant between two separate cells");
      }
    }
    Answer derived;
    assemble_answer(seq, derived, [](std::size_t) {});
    answer(derived);
  }
};

}  // namespace

CertificateCheck prover_self_check(const Scene& s, const nlohmann::json& scene_doc, const nlohmann::json& cert) {
  Checker c{s, scene_doc, cert, certificate_algebra(s), {}, {}, {}, 0, 0, 0, 0, {}};
  return run_checker([&] { c.run(); }, c.checked);
}

}  // namespace eccd
