// The independent-motion certificate's writer and checker (io/independent_certificate.hpp).
#include "io/independent_certificate.hpp"

#include "certified/independent_proof.hpp"
#include "io/certificate_json.hpp"
#include "io/certificate_result.hpp"
#include "io/krawczyk_claims.hpp"
#include "io/scene_reader.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/trivariate_bernstein.hpp"

#include <algorithm>
#include <chrono>

namespace eccd {

bool independent_certificate_scene(const Scene& s) { return s.independent; }

namespace {

using json = nlohmann::json;
using independent_detail::Piece;
using independent_detail::Strip;
using I = MpfiInterval;

const int kBits = 160;

// F's exact net (H = 4 for ellipsoids, 3 for ellipses, the factor (-1)^H included), before the reduction.
TriBern<Rational> exact_net(const Scene& scene) {
  Scene shared = scene;
  shared.independent = false;
  if (scene.dim == 3) return independent_ellipsoid_function<Rational, 4>(to_arithmetic_bernstein<Rational, 4>(prepare_pair<4>(shared), Rational(1)));
  return independent_ellipsoid_function<Rational, 3>(to_arithmetic_bernstein<Rational, 3>(prepare_pair<3>(shared), Rational(1)));
}

// The parameters along which F was divided by a factor of one sign (the net's degree there drops to 0).
json reduced_axes(const TriBern<Rational>& full, const TriBern<Rational>& reduced) {
  json r = json::array();
  if (full.n[1] != reduced.n[1]) r.push_back("s");
  if (full.n[2] != reduced.n[2]) r.push_back("t");
  return r;
}

mpq_class dy_lo(const independent_detail::Dyadic& d) { return mpq_class(mpz_class(std::to_string(d.i)), mpz_class(1) << d.d); }
mpq_class dy_hi(const independent_detail::Dyadic& d) { return mpq_class(mpz_class(std::to_string(d.i + 1)), mpz_class(1) << d.d); }
std::string q(const mpq_class& x) { mpq_class y = x; y.canonicalize(); return y.get_str(); }

json projection_json(const IndependentProjectionRecord& rec) {
  json items = json::array();
  std::size_t e = 0;
  for (const Piece& p : rec.pieces) {
    if (p.status == Strip::unknown) {
      // the end proved in this run (the runs are unknown pieces between an in and an out strip)
      if (e >= rec.ends.size() || rec.ends[e].run_lo != p.lo || rec.ends[e].run_hi != p.hi)
        throw CertificationError("internal: an unresolved run without its proved end at [" + q(p.lo) + ", " + q(p.hi) + "]");
      const IndependentEndRecord& r = rec.ends[e++];
      json chain = json::array();
      for (std::size_t i = 0; i < r.chain_lo.size(); ++i) {
        json lo = json::array(), hi = json::array();
        for (const auto& x : r.chain_lo[i]) lo.push_back(q(x));
        for (const auto& x : r.chain_hi[i]) hi.push_back(q(x));
        chain.push_back({{"lo", lo}, {"hi", hi}});
      }
      items.push_back({{"kind", "end"}, {"lo", q(p.lo)}, {"hi", q(p.hi)}, {"system", r.system}, {"chain", chain},
                       {"bracket", {q(r.lo), q(r.hi)}}});
      continue;
    }
    json boxes = json::array();
    for (const auto& b : p.witness) boxes.push_back({q(dy_lo(b.u)), q(dy_hi(b.u)), q(dy_lo(b.t)), q(dy_hi(b.t))});
    items.push_back({{"kind", p.status == Strip::in ? "in" : "out"}, {"lo", q(p.lo)}, {"hi", q(p.hi)}, {"boxes", boxes}});
  }
  if (e != rec.ends.size()) throw CertificationError("internal: a proved end outside the runs");
  return items;
}

// ---------------------------------------------------------------- checker
using namespace certificate_json;

const json& at(const json& j, const std::string& key, const std::string& place) { return certificate_json::at(j, key, place, false); }
mpq_class rat(const json& j, const std::string& place) { return read_short_rational(j, place, kIndependentMaxRationalBits); }

std::vector<mpq_class> rats(const json& j, std::size_t n, const std::string& place) { return read_short_rationals(j, n, place, kIndependentMaxRationalBits); }

// The checked intervals of one projection (var "s" on F, "t" on F with s and t exchanged).
std::vector<std::pair<Instant, Instant>> check_projection(const TriBern<Rational>& exact, const TriBern<I>& F, const json& items,
                                                          const std::string& var, int bits, std::vector<std::string>& checked) {
  using namespace independent_proof_detail;
  const std::string P = var + "_proof";
  if (!items.is_array() || items.empty() || items.size() > kIndependentMaxStrips)
    reject("certificate format", P + ": expected a non-empty list of at most " + std::to_string(kIndependentMaxStrips) + " strips and ends");
  IndependentProofOptions opt;
  opt.bits = bits;
  Nets nets(F, bits);
  EndProver prover(nets, opt, {edge_quotient(exact, 0, bits), edge_quotient(exact, 1, bits)});
  mpq_class cursor = 0;
  std::size_t nboxes = 0, n_in = 0, n_out = 0, n_end = 0;
  struct Item { std::string kind; mpq_class lo, hi, blo, bhi; };
  std::vector<Item> seq;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const json& it = items[k];
    const std::string name = P + " item " + std::to_string(k + 1);
    const json& kind = at(it, "kind", name);
    if (kind != "in" && kind != "out" && kind != "end") reject("certificate format", name + ": kind must be \"in\", \"out\" or \"end\"");
    const mpq_class lo = rat(at(it, "lo", name), name + ".lo"), hi = rat(at(it, "hi", name), name + ".hi");
    const std::string claim = name + " (" + kind.get<std::string>() + ", " + var + " in [" + q(lo) + ", " + q(hi) + "])";
    if (lo != cursor) reject("coverage", claim + ": starts at " + q(lo) + ", the previous item ends at " + q(cursor) + " (a gap or an overlap)");
    if (!(lo < hi) || hi > 1) reject("coverage", claim + ": not a range inside [0, 1]");
    cursor = hi;
    if (kind == "end") {
      const std::string sysn = at(it, "system", name).is_string() ? it["system"].get<std::string>() : "";
      System sys;
      sys.eqs = {{0, 0, 0}, {1, 0, 0}};
      sys.vars = {0, 1};
      if (sysn == "fold") { sys.eqs.push_back({0, 0, 1}); sys.vars.push_back(2); sys.kind = "fold"; }
      else if (sysn == "0" || sysn == "1") { sys.fixed_t = mpq_class(sysn == "0" ? 0 : 1); sys.kind = sysn; }
      else if (sysn == "free") { sys.fixed_t = mpq_class(0); sys.kind = sysn; }  // F of degree 0 in the other parameter
      else reject("certificate format", name + ": system must be \"fold\", \"0\", \"1\" or \"free\"");
      const std::size_t m = sys.vars.size();
      const json& chain = at(it, "chain", name);
      if (!chain.is_array() || chain.empty() || chain.size() > kIndependentMaxChain)
        reject("certificate format", name + ": chain must list 1 to " + std::to_string(kIndependentMaxChain) + " boxes");
      std::vector<Box> Y;
      for (std::size_t i = 0; i < chain.size(); ++i) {
        Box b{rats(at(chain[i], "lo", name), m, name + ".chain"), rats(at(chain[i], "hi", name), m, name + ".chain")};
        for (std::size_t v = 0; v < m; ++v)
          if (!(b.lo[v] < b.hi[v])) reject("certificate format", name + ": chain box " + std::to_string(i) + " is empty in a coordinate");
        Y.push_back(std::move(b));
      }
      check_krawczyk_chain(nets, sys, Y, 1, lo, hi, var, claim);
      const Box& X = Y[0];
      const std::string side = prover.check_end(sys.kind, X, lo, hi);
      if (!side.empty()) reject(claim, side);
      const json& br = at(it, "bracket", name);
      const auto b = rats(br, 2, name + ".bracket");
      check_krawczyk_bracket(Y.back(), 1, lo, hi, b[0], b[1], claim);
      seq.push_back({"end", lo, hi, b[0], b[1]});
      ++n_end;
      continue;
    }
    const bool in = kind == "in";
    const json& boxes = at(it, "boxes", name);
    if (!boxes.is_array() || boxes.empty()) reject("certificate format", name + ": boxes must be a non-empty list");
    nboxes += boxes.size();
    if (nboxes > kIndependentMaxBoxes) reject("certificate format", P + ": more than " + std::to_string(kIndependentMaxBoxes) + " boxes");
    const TriBern<I> strip = restrict_axis(nets.get({0, 0, 0}), 1, lo, hi, bits);
    std::vector<std::array<mpq_class, 4>> bx;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const auto b = rats(boxes[i], 4, name + " box " + std::to_string(i + 1));
      if (!(0 <= b[0] && b[0] < b[1] && b[1] <= 1 && 0 <= b[2] && b[2] < b[3] && b[3] <= 1))
        reject("certificate format", name + " box " + std::to_string(i + 1) + ": not [u0, u1, t0, t1] inside [0, 1]");
      const TriBern<I> f = restrict_axis(restrict_axis(strip, 2, b[2], b[3], bits), 0, b[0], b[1], bits);
      if (f.strict_sign() != (in ? -1 : 1))
        reject(claim, "box " + std::to_string(i + 1) + " (u in [" + q(b[0]) + ", " + q(b[1]) + "], t in [" + q(b[2]) + ", " + q(b[3]) +
                          "]): its control points are not all " + (in ? "< 0" : "> 0"));
      bx.push_back({b[0], b[1], b[2], b[3]});
    }
    // coverage inside the strip: u-ranges over [0, 1] at one t-range (in), t-ranges over [0, 1] (out)
    const int ax = in ? 0 : 2;
    std::sort(bx.begin(), bx.end(), [&](const auto& a, const auto& b) { return a[ax] < b[ax]; });
    mpq_class c = 0;
    for (const auto& b : bx) {
      if (in && (b[2] != bx[0][2] || b[3] != bx[0][3])) reject(claim, "the boxes of an in-strip must share one t-range");
      if (b[ax] > c) break;
      c = std::max(c, b[ax + 1]);
    }
    if (c != 1) reject(claim, std::string("the boxes' ") + (in ? "u" : "t") + "-ranges do not cover [0, 1] (covered up to " + q(c) + ")");
    seq.push_back({in ? "in" : "out", lo, hi, 0, 0});
    ++(in ? n_in : n_out);
  }
  if (cursor != 1) reject("coverage", P + ": the items end at " + var + " = " + q(cursor) + ", not 1");
  for (std::size_t k = 0; k < seq.size(); ++k)
    if (seq[k].kind == "end" && (k == 0 || k + 1 == seq.size() || seq[k - 1].kind == "end" || seq[k + 1].kind == "end" ||
                                 seq[k - 1].kind == seq[k + 1].kind))
      reject("coverage", P + " item " + std::to_string(k + 1) + ": an end must lie between an in-strip and an out-strip");
  checked.push_back(P + ": " + std::to_string(n_in) + " in-strips and " + std::to_string(n_out) + " out-strips (" + std::to_string(nboxes) +
                    " boxes, signs proved) and " + std::to_string(n_end) + " ends (Krawczyk, side conditions, exclusion) cover [0, 1]");
  // the answer: maximal runs of in-strips, bounded by ends' brackets or exact strip ends
  std::vector<std::pair<Instant, Instant>> iv;
  auto exact_end = [](const mpq_class& x) { return bracketed_instant(x, x, x); };
  for (std::size_t k = 0; k < seq.size(); ++k) {
    if (seq[k].kind != "in") continue;
    std::size_t j = k;
    while (j + 1 < seq.size() && seq[j + 1].kind == "in") ++j;
    const Instant a = k > 0 && seq[k - 1].kind == "end" ? bracketed_instant((seq[k - 1].blo + seq[k - 1].bhi) / 2, seq[k - 1].blo, seq[k - 1].bhi)
                                                        : exact_end(seq[k].lo);
    const Instant b = j + 1 < seq.size() && seq[j + 1].kind == "end"
                          ? bracketed_instant((seq[j + 1].blo + seq[j + 1].bhi) / 2, seq[j + 1].blo, seq[j + 1].bhi)
                          : exact_end(seq[j].hi);
    iv.emplace_back(a, b);
    k = j;
  }
  return iv;
}

void check(const Scene& s, const json& scene_doc, const json& cert, std::vector<std::string>& checked) {
  if (at(cert, "format", "certificate") == "eccd-independent-certificate/1")
    reject("certificate format", std::string("eccd-independent-certificate/1 is an old format (3D only, F's net never reduced): "
                                             "it is no longer accepted; write a new certificate (\"") + kIndependentCertificateFormat + "\") with eccd certify");
  if (at(cert, "format", "certificate") != kIndependentCertificateFormat)
    reject("certificate format", std::string("format: expected \"") + kIndependentCertificateFormat + "\" for an independent scene");
  const json& sc = at(cert, "scene", "certificate");
  for (const char* k : {"dim", "a", "b", "parameters"})
    if (at(sc, k, "scene") != scene_doc.at(k))
      reject("scene", std::string("the certificate's \"") + k + "\" differs from the scene file's: it is a certificate for another scene");
  checked.push_back("scene: dim, a, b and parameters are those of " + s.path);
  const json& pb = at(cert, "precision_bits", "certificate");
  if (!pb.is_number_integer() || pb.get<long>() < kIndependentMinBits || pb.get<long>() > kIndependentMaxBits)
    reject("certificate format", "precision_bits must be an integer in [64, 1024]");
  const int bits = pb.get<int>();
  TriBern<Rational> full, exact;
  try {
    full = exact_net(s);
  } catch (const std::exception& e) {
    reject("scene", e.what());
  }
  exact = independent_proof_detail::independent_net_reduced(full);
  const json red = reduced_axes(full, exact);
  if (at(cert, "reduced", "certificate") != red)
    reject("reduced", "the certificate's \"reduced\" is " + cert["reduced"].dump() + "; F's exact net has a factor of one sign along " +
                          (red.empty() ? std::string("no parameter") : red.dump()));
  checked.push_back("reduced: F = p G with p of one sign along " + (red.empty() ? std::string("no parameter (G = F)") : red.dump()) +
                    " (exact cross-multiplication on the net)");
  if (!independent_proof_detail::face_negative(exact, 0) || !independent_proof_detail::face_negative(exact, exact.n[0]))
    reject("faces", "F on the face u = 0 or u = 1 is not proved < 0 (exact control points, halved down to 2^-12): det A(s) or det B(t) "
                    "is not proved negative");
  checked.push_back("faces: F(0, s, t) < 0 and F(1, s, t) < 0 (exact control points of sub-nets; net degrees u " + std::to_string(exact.n[0]) +
                    ", s " + std::to_string(exact.n[1]) + ", t " + std::to_string(exact.n[2]) + ")");
  TriBern<I> F;
  F.n = exact.n;
  for (const auto& x : exact.c) F.c.emplace_back(x, bits);
  const auto s_iv = check_projection(exact, F, at(cert, "s_proof", "certificate"), "s", bits, checked);
  const auto t_iv = check_projection(exact.swap_st(), F.swap_st(), at(cert, "t_proof", "certificate"), "t", bits, checked);
  if (s_iv.empty() != t_iv.empty()) reject("answer", "the s-proof and the t-proof disagree on whether the paths meet");
  Answer want;
  try {
    want = answer_from_json(at(cert, "answer", "certificate"), "certificate", "answer");
  } catch (const std::exception& e) {
    reject("certificate format", e.what());
  }
  auto same_list = [](const auto& x, const auto& y, const char* what) { require_same_intervals(x, y, what, "the proofs"); };
  if (want.collides != !s_iv.empty()) reject("answer", std::string("the proofs give collides = ") + (s_iv.empty() ? "false" : "true"));
  same_list(s_iv, want.s_intervals, "s_intervals");
  same_list(t_iv, want.t_intervals, "t_intervals");
  checked.push_back("answer: collides, s_intervals and t_intervals follow from the checked proofs");
}

}  // namespace

json make_independent_certificate(const Scene& s, const json& scene_doc, Solution* solved) {
  const auto start = std::chrono::steady_clock::now();
  const TriBern<Rational> full = exact_net(s);
  const TriBern<Rational> F = independent_proof_detail::independent_net_reduced(full);
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
  c["scene"] = {{"path", s.path}, {"name", s.name}, {"dim", scene_doc.at("dim")}, {"a", scene_doc.at("a")}, {"b", scene_doc.at("b")},
                {"parameters", scene_doc.at("parameters")}};
  c["convention"] = "F(u, s, t) = (-1)^H det((1 - u) A(s) + u B(t)) in tensor Bernstein form on [0, 1]^3 (degree H in u: 4 for "
                    "ellipsoids, 3 for ellipses), built exactly from the scene, then divided by a factor of one sign along each "
                    "parameter listed in reduced (a body that does not move: the net's degree there is 0); boxes are [u0, u1, t0, t1] "
                    "(for t_proof: [u0, u1, s0, s1]); chain boxes list (u, s, t) or (u, s) (the proof's own parameter second); "
                    "every sign is proved by MPFI at precision_bits";
  c["reduced"] = reduced_axes(full, F);
  c["precision_bits"] = kBits;
  c["answer"] = answer_to_json(r.answer);
  c["s_proof"] = projection_json(r.s_record);
  c["t_proof"] = projection_json(r.t_record);
  // the writer checks its own certificate: a claim it cannot re-prove is never written
  finish_proof_certificate(c, check_independent_certificate(s, scene_doc, c), kIndependentCertificateFormat, kBits, r.answer,
                           "bezier-independent-proved", start, solved);
  if (solved) {
    solved->work = r.counters;
    solved->projection_degree = r.degree_s;
    solved->proofs = r.proofs;
  }
  return c;
}

CertificateCheck check_independent_certificate(const Scene& s, const json& scene_doc, const json& cert) {
  std::vector<std::string> checked;
  return run_checker([&] { check(s, scene_doc, cert, checked); }, checked);
}

}  // namespace eccd
