// The certificate writer (certificate/write/exact_certificate.hpp): the exact pipeline's own
// timeline, with its brackets refined until the simple checks of
// certificate/write/prover_self_check.hpp prove every claim.
#include "certificate/write/exact_certificate.hpp"
#include "certificate/write/cycloidal_certificate.hpp"
#include "certificate/write/independent_certificate.hpp"

#include "exact/algebraic_roots.hpp"
#include "exact/cd_disc_exact.hpp"
#include "exact/certificate_algebra.hpp"
#include "exact/descartes.hpp"
#include "kernel/ccd_projection.hpp"
#include "io/scene_reader.hpp"

#include <algorithm>
#include <chrono>
#include <map>

namespace eccd {

namespace {

constexpr int kMaxBits = 1 << 14;  // refinement limit for a bracket (also certificate_max_bits)
constexpr int kMaxGapDepth = 200;  // bisection limit for a gap

struct Evidence {
  std::string name;
  Poly<Rational> q;
  Sign sign = Sign::uncertain;
  Poly<Rational> common;  // zero sign: gcd(q, F_i)
};

struct RootWork {
  AlgebraicRoot root;
  Rational old_lo, old_hi;  // the bracket the pipeline reported
  int factor = -1;
  std::vector<Evidence> evidence;
};

std::string q_str(const Rational& q) { return q.get_str(); }

nlohmann::json coeffs_json(const Poly<Rational>& p) { return integer_coefficients(p); }

// Do the checker's claims about this bracket hold?
bool bracket_proves(const RootWork& w, const std::vector<std::pair<Poly<Rational>, int>>& F, const Poly<Rational>& P) {
  const Rational &lo = w.root.lo, &hi = w.root.hi;
  if (lo == hi) return true;
  if (sign(P(lo)) == Sign::zero || sign(P(hi)) == Sign::zero) return false;
  for (std::size_t j = 0; j < F.size(); ++j)
    if (descartes_variations(F[j].first, lo, hi) != (int(j) == w.factor ? 1 : 0)) return false;
  for (const auto& e : w.evidence) {
    if (e.sign == Sign::zero) {
      if (descartes_variations(e.common, lo, hi) != 1) return false;
    } else if (sign(e.q(lo)) == Sign::zero || descartes_variations(e.q, lo, hi) != 0) {
      return false;
    }
  }
  return true;
}

// Splits (a, b) at points until every factor has 0 sign variations on each piece.
void clear_gap(const Rational& a, const Rational& b, const std::vector<std::pair<Poly<Rational>, int>>& F,
               const Poly<Rational>& P, std::vector<Rational>& points, int depth) {
  bool clean = true;
  for (const auto& f : F)
    if (descartes_variations(f.first, a, b) != 0) {
      clean = false;
      break;
    }
  if (clean) return;
  if (depth > kMaxGapDepth)
    throw CertificationError("cannot certify: a gap between two roots could not be cleared by bisection");
  Rational m = simplest_dyadic_between(Rational((2 * a + b) / 3), Rational((a + 2 * b) / 3));
  if (sign(P(m)) == Sign::zero)
    throw std::logic_error("internal error: a root of the projection outside every bracket");
  clear_gap(a, m, F, P, points, depth + 1);
  points.push_back(m);
  clear_gap(m, b, F, P, points, depth + 1);
}

// A root's bracket and the factor it is a root of (lo = hi for a rational root).
struct Bracketed {
  Rational lo, hi;
  int factor;
};

// Does Descartes' bound of every factor on (a, b) equal the number of its
// bracketed roots there? Then the checker proves those brackets by their
// sign changes alone (certificate/check/exact_certificate.cpp).
bool piece_is_tight(const Rational& a, const Rational& b, const std::vector<Bracketed>& br, std::size_t i0,
                    std::size_t i1, const std::vector<std::pair<Poly<Rational>, int>>& F) {
  for (std::size_t j = 0; j < F.size(); ++j) {
    int count = 0;
    for (std::size_t i = i0; i < i1; ++i) count += br[i].factor == int(j);
    if (descartes_variations(F[j].first, a, b) != count) return false;
  }
  return true;
}

// Cuts (a, b), which holds the brackets br[i0 .. i1), at points in its gaps
// until every piece is tight: between the middle two brackets, or, around a
// single bracket, closer to it on both sides; a piece without a bracket is
// bisected. Returns false (and adds nothing) when depth runs out: that piece
// is then proved bracket by bracket.
bool tighten_piece(const Rational& a, const Rational& b, const std::vector<Bracketed>& br, std::size_t i0,
                   std::size_t i1, const std::vector<std::pair<Poly<Rational>, int>>& F, std::vector<Rational>& points,
                   int depth) {
  if (piece_is_tight(a, b, br, i0, i1, F)) return true;
  if (depth > 24) return false;
  const std::size_t mark = points.size();
  auto cut = [&](const Rational& lo, const Rational& hi) {
    return simplest_dyadic_between(Rational((2 * lo + hi) / 3), Rational((lo + 2 * hi) / 3));
  };
  bool ok = false;
  if (i1 - i0 >= 2) {
    const std::size_t m = i0 + (i1 - i0) / 2;
    const Rational c = cut(br[m - 1].hi, br[m].lo);
    ok = tighten_piece(a, c, br, i0, m, F, points, depth + 1);
    points.push_back(c);
    ok = ok && tighten_piece(c, b, br, m, i1, F, points, depth + 1);
  } else if (i1 - i0 == 1) {
    const Rational c1 = cut(a, br[i0].lo), c2 = cut(br[i0].hi, b);
    ok = tighten_piece(a, c1, br, i0, i0, F, points, depth + 1);
    points.push_back(c1);
    ok = ok && tighten_piece(c1, c2, br, i0, i1, F, points, depth + 1);
    points.push_back(c2);
    ok = ok && tighten_piece(c2, b, br, i1, i1, F, points, depth + 1);
  } else {
    const Rational c = cut(a, b);
    ok = tighten_piece(a, c, br, i0, i0, F, points, depth + 1);
    points.push_back(c);
    ok = ok && tighten_piece(c, b, br, i0, i0, F, points, depth + 1);
  }
  if (!ok) points.resize(mark);
  return ok;
}

// More gap points, so that Descartes' bound on each piece between them
// counts exactly the bracketed roots there (tighten_piece). Each gap piece
// clear_gap left has 0 sign variations for every factor and a piece's parts
// have at most its variations, so the brackets-and-gaps proof still holds as
// well. Nothing is added if it would pass the checker's bound on gap points.
void add_counting_points(const std::vector<RootWork>& roots, const std::vector<std::pair<Poly<Rational>, int>>& F,
                         const Poly<Rational>& P, std::vector<Rational>& points) {
  std::vector<Bracketed> br;
  for (const auto& w : roots)  // the roots inside (0, 1): a root at 0 or 1 is an end instant, not in any piece
    if (w.root.lo > 0 && w.root.hi < 1) br.push_back({w.root.lo, w.root.hi, w.factor});
  std::sort(br.begin(), br.end(), [](const Bracketed& x, const Bracketed& y) { return x.lo < y.lo; });
  std::vector<Rational> cuts{Rational(0)};
  cuts.insert(cuts.end(), points.begin(), points.end());
  cuts.push_back(Rational(1));
  std::vector<Rational> more;
  std::size_t i0 = 0;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    std::size_t i1 = i0;
    while (i1 < br.size() && br[i1].hi < cuts[c + 1]) ++i1;
    tighten_piece(cuts[c], cuts[c + 1], br, i0, i1, F, more, 0);
    i0 = i1;
  }
  if (points.size() + more.size() <= certificate_max_gap_points(std::size_t(P.degree()))) {
    points.insert(points.end(), more.begin(), more.end());
    std::sort(points.begin(), points.end());
  }
}

template <int N>
PipelineResult<Rational> run_exact_recording_isolation(const Scene& s, std::vector<Isolation>& record) {
  ExactPolicy pol;
  pol.record = &record;
  return projection_pipeline(to_arithmetic<Rational, N>(prepare_pair<N>(s), Rational(1)), pol);
}

// The certificate's format, scene and f = det(λA - B).
nlohmann::json certificate_head(const Scene& s, const nlohmann::json& scene_doc, const CertificateAlgebra& alg) {
  nlohmann::json c;
  c["format"] = "eccd-certificate/2";
  c["scene"] = {{"path", s.path},
                {"name", s.name},
                {"dim", scene_doc.at("dim")},
                {"a", scene_doc.at("a")},
                {"b", scene_doc.at("b")}};
  nlohmann::json g = nlohmann::json::array();
  for (const auto& gk : alg.g) {
    nlohmann::json row = nlohmann::json::array();
    for (const auto& x : gk.c) row.push_back(q_str(x));
    g.push_back(row);
  }
  c["f"] = {
      {"convention",
       "f(lambda; t) = det(lambda A(t) - B(t)) = sum_k g_k(t) lambda^k; g_k in the power basis, lowest degree first"},
      {"g", g}};
  return c;
}

// Continuous touching: P·D without a root in [0, 1] keeps the status of the double root constant
// (certificate/write/prover_self_check.hpp).
nlohmann::json continuous_touching_json(const CertificateAlgebra& alg, const PipelineResult<Rational>& res) {
  const Poly<Rational> PD = alg.evidence("P") * alg.evidence("D");
  const Rational half(1, 2);
  nlohmann::json ct = {
      {"convention", PD.is_zero()
                         ? "P = 9 g3 g0 - g2 g1, D = g2^2 - 3 g3 g1 (003 Theorem 6); P*D vanishes identically: the "
                           "double root is 0 or triple, overlapping on all of [0, 1]"
                         : "P = 9 g3 g0 - g2 g1, D = g2^2 - 3 g3 g1 (003 Theorem 6); P*D has no root in [0, 1] (gap "
                           "points, Descartes), so the status (touching iff the double root P/(2D) is "
                           "negative) is that of the sample on all of [0, 1]"},
      {"identically_zero", PD.is_zero()},
      {"sample", q_str(half)},
      {"status", to_string(alg.status_at(half))}};
  std::vector<Rational> pts;
  if (!PD.is_zero()) {
    if (sign(PD(Rational(0))) == Sign::zero || sign(PD(Rational(1))) == Sign::zero || res.cells.size() != 1)
      throw CertificationError(
          "cannot certify: the discriminant vanishes identically and the status changes inside [0, 1] "
          "(P*D has a root there), which the certificate format does not cover");
    clear_gap(Rational(0), Rational(1), {{PD, 1}}, PD, pts, 0);
  }
  nlohmann::json ptj = nlohmann::json::array();
  for (const auto& x : pts) ptj.push_back(q_str(x));
  ct["gap_points"] = ptj;
  return ct;
}

// 2D, Δ ≡ 0: never separate (003 Corollary 7); the certificate's projection, empty timeline, continuous touching
// and answer.
void certify_identically_zero(nlohmann::json& c, nlohmann::json& proj, const CertificateAlgebra& alg,
                              const PipelineResult<Rational>& res) {
  if (!res.projection_identically_zero) throw std::logic_error("internal error: Δ ≡ 0 but the pipeline disagrees");
  proj["identically_zero"] = true;
  c["projection"] = proj;
  c["gap_points"] = nlohmann::json::array();
  c["timeline"] = nlohmann::json::array();
  c["continuous_touching"] = continuous_touching_json(alg, res);
  const Rational half(1, 2);
  Answer ans = res.answer;  // the answer keys only (contact points are a display extra)
  ans.contact_points.clear();
  if (ans.contact_intervals.size() != (alg.status_at(half) == Status::touching ? 1u : 0u))
    throw std::logic_error("internal error: the pipeline's contact intervals disagree with the status at t = 1/2");
  c["answer"] = answer_to_json(ans);
}

// A root of the projection: its factor, the evidence of its status (irrational roots) and a bracket refined until
// it proves the checker's claims (at most max_bits).
RootWork prove_root(const AlgebraicRoot& r, const Scene& s, const CertificateAlgebra& alg,
                    const std::vector<std::pair<Poly<Rational>, int>>& F, const Poly<Rational>& P, int max_bits) {
  RootWork w;
  w.root = r;
  w.old_lo = r.lo;
  w.old_hi = r.hi;
  for (std::size_t j = 0; j < F.size(); ++j)
    if (F[j].second == r.multiplicity) w.factor = int(j);
  if (w.factor < 0) throw std::logic_error("internal error: no square-free factor of the root's multiplicity");
  if (!r.is_rational()) {
    auto add = [&](const std::string& name) -> Sign {
      for (const auto& e : w.evidence)
        if (e.name == name) return e.sign;
      Evidence e;
      e.name = name;
      e.q = alg.evidence(name);
      e.sign = eccd::sign_at(e.q, r);
      if (e.sign == Sign::zero) e.common = polynomial_gcd(e.q, F[w.factor].first);
      w.evidence.push_back(e);
      return e.sign;
    };
    if (s.dim == 2) {
      add("P");
      add("D");
    } else {
      negative_multiple_root(alg.projection_index, [&](int j, int i) { return add(subresultant_evidence_name(j, i)); });
    }
  }
  for (int bits = 128; !bracket_proves(w, F, P); bits *= 2) {
    if (bits > max_bits)
      throw CertificationError("cannot certify: the bracket of the root near t = " + decimal_string(w.old_lo) +
                               " does not prove its claims even at width 2^-" + std::to_string(max_bits));
    refine(w.root, bits);
  }
  return w;
}

// The refined bracket of a pipeline instant, with an approx that lies in it.
Instant refined(const std::vector<RootWork>& roots, const Instant& i) {
  if (!i.certified()) throw std::logic_error("internal error: an exact instant without a bracket");
  for (const auto& w : roots)
    if (w.old_lo == *i.lo && w.old_hi == *i.hi)
      return Instant{approx_in_bracket(w.root.lo, w.root.hi), w.root.lo, w.root.hi,
                     nearest_double((w.root.lo + w.root.hi) / 2)};
  return Instant{approx_in_bracket(*i.lo, *i.hi), *i.lo, *i.hi, nearest_double((*i.lo + *i.hi) / 2)};
}

// Gaps between consecutive brackets (and 0, 1) hold no root: the points that prove it.
std::vector<Rational> gap_points(const std::vector<RootWork>& roots,
                                 const std::vector<std::pair<Poly<Rational>, int>>& F, const Poly<Rational>& P) {
  std::vector<Rational> points;
  Rational prev = 0;
  for (const auto& w : roots) {
    if (prev < w.root.lo) clear_gap(prev, w.root.lo, F, P, points, 0);
    prev = w.root.hi;
  }
  if (prev < Rational(1)) clear_gap(prev, Rational(1), F, P, points, 0);
  add_counting_points(roots, F, P, points);
  if (points.size() > certificate_max_gap_points(std::size_t(P.degree())))
    throw CertificationError("cannot certify: clearing the gaps between the brackets takes more than " +
                             std::to_string(certificate_max_gap_points(std::size_t(P.degree()))) + " points");
  return points;
}

// The evidence of an irrational root's status and what it decides.
void add_evidence(nlohmann::json& j, const RootWork& w, const Scene& s, const CertificateAlgebra& alg) {
  nlohmann::json ev = nlohmann::json::array();
  for (const auto& e : w.evidence) {
    nlohmann::json x = {{"poly", e.name}, {"sign", to_string(e.sign)}};
    if (e.sign == Sign::zero) x["common_factor"] = coeffs_json(e.common);
    ev.push_back(x);
  }
  j["evidence"] = ev;
  if (s.dim == 2) {
    j["decided_by"] = "signs of P and D at the root (003 Theorem 6)";
    return;
  }
  std::map<std::string, Sign> sg;
  for (const auto& e : w.evidence) sg[e.name] = e.sign;
  Sign touch = negative_multiple_root(alg.projection_index,
                                      [&](int a, int b) { return sg.at(subresultant_evidence_name(a, b)); });
  j["decided_by"] = touch == Sign::positive
                        ? "subresultant signs at the root: a negative multiple root (touching)"
                        : "subresultant signs at the root: no negative multiple root, so the status of the "
                          "neighbouring cells";
}

// The timeline with statuses and evidence.
nlohmann::json timeline_json(const PipelineResult<Rational>& res, const std::vector<RootWork>& roots, const Scene& s,
                             const CertificateAlgebra& alg) {
  nlohmann::json tl = nlohmann::json::array();
  for (std::size_t k = 0; k < res.timeline.size(); ++k) {
    const TimelineNode& n = res.timeline[k];
    if (n.is_cell) {
      tl.push_back({{"cell_sample", q_str(*n.t.lo)}, {"status", to_string(n.status)}});
      continue;
    }
    Instant t = refined(roots, n.t);
    nlohmann::json j = {{"instant", {{"approx", t.approx}, {"lo", q_str(*t.lo)}, {"hi", q_str(*t.hi)}}},
                        {"status", to_string(n.status)}};
    const RootWork* w = nullptr;
    for (const auto& x : roots)
      if (x.root.lo == *t.lo && x.root.hi == *t.hi) w = &x;
    j["root_of_factor"] = w ? nlohmann::json(w->factor) : nlohmann::json(nullptr);
    if (!w || w->root.is_rational())
      j["decided_by"] = "static test at the rational instant";
    else
      add_evidence(j, *w, s, alg);
    tl.push_back(j);
  }
  return tl;
}

// The pipeline's answer with every instant's bracket refined, without the contact points.
Answer refined_answer(const Answer& answer, const std::vector<RootWork>& roots) {
  Answer ans = answer;
  for (auto& [a, b] : ans.intervals) {
    a = refined(roots, a);
    b = refined(roots, b);
  }
  if (ans.first_contact) ans.first_contact = refined(roots, *ans.first_contact);
  for (auto& x : ans.contacts) x = refined(roots, x);
  for (auto& [a, b] : ans.contact_intervals) {
    a = refined(roots, a);
    b = refined(roots, b);
  }
  ans.contact_points.clear();
  return ans;
}

}  // namespace

nlohmann::json make_certificate(const Scene& s, const nlohmann::json& scene_doc, Solution* solved) {
  if (cycloidal_certificate_scene(s))
    return make_cycloidal_certificate(s, scene_doc, solved);  // certificate/write/cycloidal_certificate.hpp
  if (independent_certificate_scene(s))
    return make_independent_certificate(s, scene_doc, solved);  // certificate/write/independent_certificate.hpp
  auto start = std::chrono::steady_clock::now();
  std::vector<Isolation> record;
  PipelineResult<Rational> res =
      s.dim == 2 ? run_exact_recording_isolation<3>(s, record) : run_exact_recording_isolation<4>(s, record);
  const CertificateAlgebra alg = certificate_algebra(s);
  if (alg.g != res.g) throw std::logic_error("internal error: the certificate's f differs from the pipeline's");

  nlohmann::json c = certificate_head(s, scene_doc, alg);
  nlohmann::json proj = {{"name", alg.projection_name}, {"vanishing", alg.vanishing}};
  if (alg.projection.is_zero()) {
    certify_identically_zero(c, proj, alg, res);
    c["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return c;
  }

  if (record.size() != 1 || record[0].poly != alg.projection)
    throw std::logic_error("internal error: the pipeline isolated the roots of another polynomial than the projection");
  const Poly<Rational>& P = alg.projection;
  const auto F = square_free_factors(P);
  // The checker's size bound (certificate/write/exact_certificate.hpp), a few bits of slack for refine's rounding.
  const int max_bits =
      std::min<int>(kMaxBits, int(certificate_max_bits(std::size_t(P.degree()), integer_coefficient_bits(P))) - 8);
  proj["identically_zero"] = false;
  proj["degree"] = P.degree();
  proj["coefficients"] = coeffs_json(P);
  nlohmann::json fj = nlohmann::json::array();
  for (const auto& [f, m] : F) fj.push_back({{"multiplicity", m}, {"coefficients", coeffs_json(f)}});
  proj["square_free_factors"] = fj;
  c["projection"] = proj;

  std::vector<RootWork> roots;
  for (const auto& r : record[0].roots) roots.push_back(prove_root(r, s, alg, F, P, max_bits));
  nlohmann::json pts = nlohmann::json::array();
  for (const auto& p : gap_points(roots, F, P)) pts.push_back(q_str(p));
  c["gap_points"] = pts;
  c["timeline"] = timeline_json(res, roots, s, alg);

  Answer ans = refined_answer(res.answer, roots);
  c["answer"] = answer_to_json(ans);
  c["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (solved) {
    *solved = solution_of(res, s.dim);
    ans.contact_points = res.answer.contact_points;
    solved->answer = ans;
  }
  return c;
}

}  // namespace eccd
