// The independent-motion certificate's writer (certificate/write/independent_certificate.hpp); its checker is
// eccd-check's.
#include "certificate/write/independent_certificate.hpp"

#include "certified/independent_proof.hpp"
#include "certificate/check_certificate.hpp"
#include "certificate/write/certificate_json.hpp"
#include "certificate/certificate_result.hpp"
#include "io/scene_reader.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/trivariate_bernstein.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <tuple>

namespace eccd {

bool independent_certificate_scene(const Scene& s) { return s.independent; }

namespace {

using json = nlohmann::json;
using independent_subdivision::Piece;
using independent_subdivision::Strip;
using I = MpfiInterval;

const int kBits = 160;

// F's exact net (H = 4 for ellipsoids, 3 for ellipses), with a body that does not move as a set held at its
// parameter 0 (kernel/trivariate_bernstein.hpp, hold_still; `still` says which).
TriBern<Rational> exact_net(const Scene& scene, std::array<bool, 2>& still) {
  Scene shared = scene;
  shared.independent = false;
  if (scene.dim == 3)
    return independent_ellipsoid_function<Rational, 4>(
        to_arithmetic_bernstein<Rational, 4>(prepare_pair<4>(shared), Rational(1)), &still);
  return independent_ellipsoid_function<Rational, 3>(
      to_arithmetic_bernstein<Rational, 3>(prepare_pair<3>(shared), Rational(1)), &still);
}

mpq_class dy_lo(const independent_subdivision::Dyadic& d) {
  return mpq_class(mpz_class(std::to_string(d.i)), mpz_class(1) << d.d);
}
mpq_class dy_hi(const independent_subdivision::Dyadic& d) {
  return mpq_class(mpz_class(std::to_string(d.i + 1)), mpz_class(1) << d.d);
}
std::string q(const mpq_class& x) {
  mpq_class y = x;
  y.canonicalize();
  return y.get_str();
}

// The exclusion of an end as the subdivision tree the checker replays (certificate/check/independent_certificate.cpp):
// preorder over (u, t) in [0, 1]^2 at s in the strip, '1' split (u halved, then t, at every level; children u-low
// t-low, u-low t-high, u-high t-low, u-high t-high), '0' a leaf inside the kept box or with F or F_u of one proved
// sign, or with its t-range inside (0, 1) and F_t and F_uu of one sign (f: F, F_u, F_t, F_uu restricted to the strip).
struct Keep {
  mpq_class u0, u1, t0, t1;
};
void exclusion_tree(const std::array<TriBern<I>, 4>& f, const mpq_class& u0, const mpq_class& u1, const mpq_class& t0,
                    const mpq_class& t1, int depth, const Keep& k, const I& half, long& nodes, std::string& out) {
  if (++nodes > long(kIndependentMaxBoxes))
    throw CertificationError("the exclusion of an end needs more than " + std::to_string(kIndependentMaxBoxes) +
                             " boxes");
  const bool inner = sgn(t0) > 0 && t1 < 1;
  if ((u0 >= k.u0 && u1 <= k.u1 && t0 >= k.t0 && t1 <= k.t1) || f[0].strict_sign() != 0 || f[1].strict_sign() != 0 ||
      (inner && f[2].strict_sign() != 0 && f[3].strict_sign() != 0)) {
    out += '0';
    return;
  }
  if (depth >= kIndependentMaxTreeDepth)
    throw CertificationError("the exclusion of an end does not close within " +
                             std::to_string(kIndependentMaxTreeDepth) + " levels");
  out += '1';
  const mpq_class um = (u0 + u1) / 2, tm = (t0 + t1) / 2;
  std::array<TriBern<I>, 4> lo, hi;
  for (int i = 0; i < 4; ++i) std::tie(lo[i], hi[i]) = f[i].split_half(0, half);
  for (int side = 0; side < 2; ++side) {
    std::array<TriBern<I>, 4> lt, ht;
    for (int i = 0; i < 4; ++i) std::tie(lt[i], ht[i]) = (side ? hi : lo)[i].split_half(2, half);
    const mpq_class a0 = side ? um : u0, a1 = side ? u1 : um;
    exclusion_tree(lt, a0, a1, t0, tm, depth + 1, k, half, nodes, out);
    exclusion_tree(ht, a0, a1, tm, t1, depth + 1, k, half, nodes, out);
  }
}

// The box the exclusion of an end leaves to its Krawczyk box X (certified/independent_proof.hpp, EndProver::prove_at).
Keep kept_box(const std::string& system, const std::vector<mpq_class>& xlo, const std::vector<mpq_class>& xhi) {
  Keep k{xlo[0], xhi[0], 0, 1};
  const mpq_class rho = (xhi[0] - xlo[0]) / 2;
  if (system == "0") k.t1 = rho;
  if (system == "1") k.t0 = 1 - rho;
  if (system == "fold") k.t0 = xlo[2], k.t1 = xhi[2];
  return k;
}

// The items of one projection; F: the net with the proof's parameter second, in MPFI.
json projection_json(const IndependentProjectionRecord& rec, const TriBern<I>& F) {
  krawczyk_method::Nets nets(F, kBits);
  const I half(mpq_class(1, 2), kBits);
  json items = json::array();
  std::size_t e = 0;
  for (const Piece& p : rec.pieces) {
    if (p.status == Strip::unknown) {
      // the end proved in this run (the runs are unknown pieces between an in and an out strip)
      if (e >= rec.ends.size() || rec.ends[e].run_lo != p.lo || rec.ends[e].run_hi != p.hi)
        throw CertificationError("internal: an unresolved run without its proved end at [" + q(p.lo) + ", " + q(p.hi) +
                                 "]");
      const IndependentEndRecord& r = rec.ends[e++];
      json chain = json::array();
      for (std::size_t i = 0; i < r.chain_lo.size(); ++i) {
        json lo = json::array(), hi = json::array();
        for (const auto& x : r.chain_lo[i]) lo.push_back(q(x));
        for (const auto& x : r.chain_hi[i]) hi.push_back(q(x));
        chain.push_back({{"lo", lo}, {"hi", hi}});
      }
      std::array<TriBern<I>, 4> f;
      const std::array<std::array<int, 3>, 4> ords{{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {2, 0, 0}}};
      for (int i = 0; i < 4; ++i) f[i] = krawczyk_method::restrict_axis(nets.get(ords[i]), 1, p.lo, p.hi, kBits);
      std::string tree;
      long nodes = 0;
      exclusion_tree(f, 0, 1, 0, 1, 0, kept_box(r.system, r.chain_lo[0], r.chain_hi[0]), half, nodes, tree);
      items.push_back({{"kind", "end"},
                       {"lo", q(p.lo)},
                       {"hi", q(p.hi)},
                       {"system", r.system},
                       {"chain", chain},
                       {"exclusion", tree},
                       {"bracket", {q(r.lo), q(r.hi)}}});
      continue;
    }
    json boxes = json::array();
    for (const auto& b : p.witness) boxes.push_back({q(dy_lo(b.u)), q(dy_hi(b.u)), q(dy_lo(b.t)), q(dy_hi(b.t))});
    items.push_back(
        {{"kind", p.status == Strip::in ? "in" : "out"}, {"lo", q(p.lo)}, {"hi", q(p.hi)}, {"boxes", boxes}});
  }
  if (e != rec.ends.size()) throw CertificationError("internal: a proved end outside the runs");
  return items;
}

template <class M>
json matrix_json(const M& m) {
  json r = json::array();
  for (const auto& row : m) {
    json r1 = json::array();
    for (const auto& x : row) r1.push_back(q(x));
    r.push_back(r1);
  }
  return r;
}
template <class M>
json poly_matrix_json(const M& m) {
  json r = json::array();
  for (const auto& row : m) {
    json r1 = json::array();
    for (const auto& p : row) {
      json cs = json::array();
      for (const auto& x : p.c) cs.push_back(q(x));
      r1.push_back(cs);
    }
    r.push_back(r1);
  }
  return r;
}

// The net claim's data: F's net and the shapes and inverse motions it is built from (the checker verifies all).
template <int H>
json net_json(const Scene& scene, const TriBern<Rational>& F) {
  Scene shared = scene;
  shared.independent = false;
  const PreparedPair<H> p = prepare_pair<H>(shared);
  json co = json::array();
  for (const auto& x : F.c) co.push_back(q(x));
  return {{"degrees", {F.n[0], F.n[1], F.n[2]}}, {"coefficients", co},
          {"shape_a", matrix_json(p.qa)},        {"shape_b", matrix_json(p.qb)},
          {"inverse_a", poly_matrix_json(p.na)}, {"inverse_b", poly_matrix_json(p.nb)}};
}

}  // namespace

json make_independent_certificate(const Scene& s, const json& scene_doc, Solution* solved) {
  const auto start = std::chrono::steady_clock::now();
  std::array<bool, 2> still{};
  const TriBern<Rational> F = exact_net(s, still);
  if (!(independent_net_reduced(F).c == F.c))
    throw CertificationError(
        "F has a factor of one sign along a parameter whose body moves: the proof runs on F divided by it, "
        "which the certificate's net claim does not cover");
  IndependentProofOptions po;
  po.bits = kBits;
  po.record = true;
  const IndependentProofResult r = prove_independent(F, po);
  if (!r.answer.undecided.empty()) {
    std::string why = "the proof of the independent scene leaves ranges undecided, so nothing is certified:";
    for (const auto& u : r.undecided_reasons) why += " " + u + ";";
    throw CertificationError(why);
  }
  json c;
  c["format"] = kIndependentCertificateFormat;
  c["scene"] = {{"path", s.path},         {"name", s.name},         {"dim", scene_doc.at("dim")},
                {"a", scene_doc.at("a")}, {"b", scene_doc.at("b")}, {"parameters", scene_doc.at("parameters")}};
  c["convention"] =
      "F(u, s, t) = det((1 - u) A(s) + u B(t)) in tensor Bernstein form on [0, 1]^3 (degree H in u: 4 for ellipsoids, "
      "3 for ellipses), net.coefficients in row-major (u, s, t) order, A = N_a^T Q_a N_a and B = N_b^T Q_b N_b from "
      "the "
      "stated shapes and inverse motions; a parameter listed in reduced has its body held at 0 (it does not move as a "
      "set: A(s) = c(s) A(0)); boxes are [u0, u1, t0, t1] (for t_proof: [u0, u1, s0, s1]); chain boxes list (u, s, t) "
      "or "
      "(u, s) (the proof's own parameter second); an end's exclusion is the subdivision tree of (u, other parameter) "
      "in "
      "[0, 1]^2 in preorder ('1' split: both halved at every level; '0' leaf); every sign is proved by outward-rounded "
      "intervals";
  json red = json::array();
  if (still[0]) red.push_back("s");
  if (still[1]) red.push_back("t");
  c["reduced"] = red;
  c["precision_bits"] = kBits;
  c["answer"] = answer_to_json(r.answer);
  c["net"] = s.dim == 3 ? net_json<4>(s, F) : net_json<3>(s, F);
  TriBern<I> FI;
  FI.n = F.n;
  for (const auto& x : F.c) FI.c.emplace_back(x, kBits);
  c["s_proof"] = projection_json(r.s_record, FI);
  c["t_proof"] = projection_json(r.t_record, FI.swap_st());
  // the writer checks its own certificate with eccd-check's library: a claim it cannot re-prove is never written
  certificate_json::finish_proof_certificate(c, check_independent_certificate(s, scene_doc, c),
                                             kIndependentCertificateFormat, kBits, r.answer,
                                             "bezier-independent-proved", start, solved);
  if (solved) {
    solved->dim = s.dim;
    solved->work = r.counters;
    solved->projection_degree = r.degree_s;
    solved->proofs = r.proofs;
  }
  return c;
}

CertificateCheck check_independent_certificate(const Scene& s, const json& scene_doc, const json& cert) {
  return check_certificate(s, scene_doc, cert);  // eccd-check's library (certificate/check/independent_certificate.cpp)
}

}  // namespace eccd
