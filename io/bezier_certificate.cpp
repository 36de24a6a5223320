// The Bézier certificate's writer and checker (io/bezier_certificate.hpp).
#include "io/bezier_certificate.hpp"

#include "certified/bezier_proof.hpp"
#include "certified/exclusion.hpp"
#include "io/certificate.hpp"
#include "io/certificate_json.hpp"
#include "io/cycloidal_certificate.hpp"
#include "io/independent_certificate.hpp"
#include "io/krawczyk_claims.hpp"
#include "io/scene_reader.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/collision_timeline.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "kernel/prepared_scene.hpp"
#include "number/interval.hpp"

#include <algorithm>
#include <chrono>
#include <map>

namespace eccd {

bool bezier_certificate_scene(const Scene& s) { return s.dim == 3 && !s.independent; }

namespace {

using json = nlohmann::json;
using namespace certificate_json;
using krawczyk_detail::Box;
using krawczyk_detail::Nets;
using krawczyk_detail::System;
using I = MpfiInterval;
using krawczyk_detail::restrict_axis;

const int kBits = 160;

std::string q(const mpq_class& x) { mpq_class y = x; y.canonicalize(); return y.get_str(); }

// ---------------------------------------------------------------- checker
mpq_class rat(const json& j, const std::string& place) { return read_short_rational(j, place, kBezierMaxRationalBits); }
std::vector<mpq_class> rats(const json& j, std::size_t n, const std::string& place) {
  return read_short_rationals(j, n, place, kBezierMaxRationalBits);
}

// F(u, t)'s net from the scene, exactly, as a tensor net (u, s, t) of degree 0 in s.
TriBern<Rational> exact_net(const Scene& scene) {
  if (!bezier_certificate_scene(scene)) throw std::invalid_argument("a Bézier certificate is for 3D scenes with shared parameters");
  const PreparedPair<4> p = prepare_pair<4>(scene);
  const BiBern<Rational> f = ellipsoid_function(characteristic_bernstein<Rational, 4>(p, false, Rational(0)), Rational(0));
  TriBern<Rational> t;
  t.n = {f.degree_u(), 0, f.degree_t()};
  for (const auto& row : f.b)
    for (const auto& x : row) t.c.push_back(x);
  return t;
}

// An MPFI net enclosed outwards in intervals of doubles (each end rounded away from the other).
TriBern<Interval> to_double_intervals(const TriBern<I>& f) {
  TriBern<Interval> r;
  r.n = f.n;
  r.c.reserve(f.c.size());
  for (const auto& x : f.c)
    r.c.emplace_back(mpfr_get_d(&x.get()->left, MPFR_RNDD), mpfr_get_d(&x.get()->right, MPFR_RNDU));
  return r;
}

void check(const Scene& s, const json& scene_doc, const json& cert, std::vector<std::string>& checked) {
  if (at(cert, "format", "certificate", false) != kBezierCertificateFormat)
    reject("certificate format", std::string("format: expected \"") + kBezierCertificateFormat + "\"");
  const json& sc = at(cert, "scene", "certificate", false);
  for (const char* k : {"dim", "a", "b"})
    if (at(sc, k, "scene", false) != scene_doc.at(k))
      reject("scene", std::string("the certificate's \"") + k + "\" differs from the scene file's: it is a certificate for another scene");
  if (sc.contains("parameters") != scene_doc.contains("parameters") || (sc.contains("parameters") && sc["parameters"] != scene_doc["parameters"]))
    reject("scene", "the certificate's \"parameters\" differs from the scene file's: it is a certificate for another scene");
  checked.push_back("scene: dim, a and b are those of " + s.path);
  const json& pb = at(cert, "precision_bits", "certificate", false);
  if (!pb.is_number_integer() || pb.get<long>() < kBezierMinBits || pb.get<long>() > kBezierMaxBits)
    reject("certificate format", "precision_bits must be an integer in [64, 1024]");
  const int bits = pb.get<int>();
  TriBern<Rational> exact;
  try {
    exact = exact_net(s);
  } catch (const std::exception& e) {
    reject("scene", e.what());
  }
  TriBern<I> F;
  F.n = exact.n;
  for (const auto& x : exact.c) F.c.emplace_back(x, bits);
  Nets nets(F, bits);
  System sys;
  sys.eqs = {{0, 0, 0}, {1, 0, 0}};
  sys.vars = {0, 2};
  sys.kind = "bezier-end";

  const json& items = at(cert, "pieces", "certificate", false);
  if (!items.is_array() || items.empty() || items.size() > kBezierMaxPieces)
    reject("certificate format", "pieces: expected a non-empty list of at most " + std::to_string(kBezierMaxPieces) + " pieces");
  mpq_class cursor = 0;
  std::size_t nboxes = 0, n_in = 0, n_out = 0, n_end = 0;
  long exclusion_boxes = 0;
  struct Item { std::string kind; mpq_class lo, hi, blo, bhi; };
  std::vector<Item> seq;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const json& it = items[k];
    const std::string name = "piece " + std::to_string(k + 1);
    const json& kind = at(it, "kind", name, false);
    if (kind != "in" && kind != "out" && kind != "end") reject("certificate format", name + ": kind must be \"in\", \"out\" or \"end\"");
    const mpq_class lo = rat(at(it, "lo", name, false), name + ".lo"), hi = rat(at(it, "hi", name, false), name + ".hi");
    const std::string claim = name + " (" + kind.get<std::string>() + ", t in [" + q(lo) + ", " + q(hi) + "])";
    if (lo != cursor) reject("coverage", claim + ": starts at " + q(lo) + ", the previous piece ends at " + q(cursor) + " (a gap or an overlap)");
    if (!(lo < hi) || hi > 1) reject("coverage", claim + ": not a range inside [0, 1]");
    cursor = hi;
    const json& boxes = at(it, "boxes", name, false);
    if (!boxes.is_array() || boxes.empty()) reject("certificate format", name + ": boxes must be a non-empty list");
    nboxes += boxes.size();
    if (nboxes > kBezierMaxBoxes) reject("certificate format", "pieces: more than " + std::to_string(kBezierMaxBoxes) + " boxes");
    if (kind == "end") {
      if (boxes.size() > kBezierMaxChain)
        reject("certificate format", name + ": the Krawczyk chain (boxes) must list 1 to " + std::to_string(kBezierMaxChain) + " boxes");
      std::vector<Box> Y;
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto b = rats(boxes[i], 4, name + " box " + std::to_string(i + 1));
        if (!(b[0] < b[1]) || !(b[2] < b[3])) reject("certificate format", name + ": chain box " + std::to_string(i) + " is empty in a coordinate");
        Y.push_back(Box{{b[0], b[2]}, {b[1], b[3]}});
      }
      // the lemma needs the faces F(0, t) = det A(t) and F(1, t) = det B(t) < 0 on the run
      const TriBern<I> run = restrict_axis(F, 2, lo, hi, bits);
      for (int j = 0; j <= run.n[2]; ++j)
        if (sign(run.at(0, 0, j)) != Sign::negative || sign(run.at(run.n[0], 0, j)) != Sign::negative)
          reject(claim, "the faces: F(0, t) = det A(t) or F(1, t) = det B(t) is not proved < 0 on the run");
      check_krawczyk_chain(nets, sys, Y, 1, lo, hi, "t", claim);
      const Box& X = Y[0];
      if (sgn(X.lo[0]) < 0 || X.hi[0] > 1) reject(claim, "the Krawczyk box's u-range is not inside [0, 1]");
      // exclusion: F or F_u of one sign on [0, 1] x [lo, hi] outside X's u-range
      // (the restricted nets enclosed outwards in intervals of doubles: the signs are still proofs, at a fraction of MPFI's cost)
      std::array<TriBern<Interval>, 2> f{to_double_intervals(run), to_double_intervals(restrict_axis(nets.get({1, 0, 0}), 2, lo, hi, bits))};
      auto excluded = [](const std::array<TriBern<Interval>, 2>& g, const ExclusionRegion&) { return g[0].strict_sign() != 0 || g[1].strict_sign() != 0; };
      const ExclusionResult e = exclude_region(std::move(f), 0, 2, {0, 1, lo, hi}, {X.lo[0], X.hi[0], lo, hi}, excluded,
                                               kBezierMaxExclusionBoxes, kBezierMaxExclusionDepth, 2, Interval(0.5, 0.5));
      exclusion_boxes += e.boxes;
      if (e.status == ExclusionResult::too_many_boxes)
        reject(claim, "the exclusion of other zeros of (F, F_u) needed more than " + std::to_string(kBezierMaxExclusionBoxes) + " boxes");
      if (e.status == ExclusionResult::deadline) reject(claim, "the exclusion of other zeros of (F, F_u): " + deadline_reason());
      if (e.status == ExclusionResult::stuck)
        reject(claim, "another zero of (F, F_u) near u = " + decimal_string(e.u0, 8) + ", t = " + decimal_string(e.t0, 8) + " could not be excluded");
      const auto b = rats(at(it, "bracket", name, false), 2, name + ".bracket");
      check_krawczyk_bracket(Y.back(), 1, lo, hi, b[0], b[1], claim);
      seq.push_back({"end", lo, hi, b[0], b[1]});
      ++n_end;
      continue;
    }
    const bool in = kind == "in";
    const TriBern<I> strip = restrict_axis(F, 2, lo, hi, bits);
    std::map<std::pair<mpq_class, mpq_class>, TriBern<I>> by_t;
    std::vector<std::array<mpq_class, 4>> bx;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const auto b = rats(boxes[i], 4, name + " box " + std::to_string(i + 1));
      if (!(0 <= b[0] && b[0] < b[1] && b[1] <= 1 && lo <= b[2] && b[2] < b[3] && b[3] <= hi))
        reject("certificate format", name + " box " + std::to_string(i + 1) + ": not [u0, u1, t0, t1] inside [0, 1] x [lo, hi]");
      // the strip's t-coordinates of the box, then u
      const mpq_class t0 = (b[2] - lo) / (hi - lo), t1 = (b[3] - lo) / (hi - lo);
      auto cached = by_t.find({t0, t1});  // boxes of one t-range (an in piece's groups) share the restriction in t
      if (cached == by_t.end()) cached = by_t.emplace(std::make_pair(t0, t1), restrict_axis(strip, 2, t0, t1, bits)).first;
      const TriBern<I> g = restrict_axis(cached->second, 0, b[0], b[1], bits);
      if (g.strict_sign() != (in ? -1 : 1))
        reject(claim, "box " + std::to_string(i + 1) + " (u in [" + q(b[0]) + ", " + q(b[1]) + "], t in [" + q(b[2]) + ", " + q(b[3]) +
                          "]): its control points are not all " + (in ? "< 0" : "> 0"));
      bx.push_back({b[0], b[1], b[2], b[3]});
    }
    // coverage: out: the t-ranges cover [lo, hi]; in: per t-range, the u-ranges cover [0, 1], and the t-ranges cover [lo, hi]
    auto covers = [](std::vector<std::pair<mpq_class, mpq_class>> r, const mpq_class& a, const mpq_class& b) {
      std::sort(r.begin(), r.end());
      mpq_class c = a;
      for (const auto& [x, y] : r) {
        if (x > c) break;
        c = std::max(c, y);
      }
      return c >= b ? std::optional<mpq_class>() : std::optional<mpq_class>(c);
    };
    std::vector<std::pair<mpq_class, mpq_class>> tr;
    if (in) {
      std::map<std::pair<mpq_class, mpq_class>, std::vector<std::pair<mpq_class, mpq_class>>> groups;
      for (const auto& b : bx) groups[{b[2], b[3]}].push_back({b[0], b[1]});
      for (const auto& [t, us] : groups) {
        if (auto c = covers(us, 0, 1))
          reject(claim, "the boxes at t in [" + q(t.first) + ", " + q(t.second) + "]: their u-ranges do not cover [0, 1] (covered up to " + q(*c) + ")");
        tr.push_back(t);
      }
    } else {
      for (const auto& b : bx) tr.push_back({b[2], b[3]});
    }
    if (auto c = covers(tr, lo, hi)) reject(claim, "the boxes' t-ranges do not cover the piece (covered up to " + q(*c) + ")");
    seq.push_back({in ? "in" : "out", lo, hi, 0, 0});
    ++(in ? n_in : n_out);
  }
  if (cursor != 1) reject("coverage", "the pieces end at t = " + q(cursor) + ", not 1");
  for (std::size_t k = 0; k < seq.size(); ++k)
    if (seq[k].kind == "end" && (k == 0 || k + 1 == seq.size() || seq[k - 1].kind == "end" || seq[k + 1].kind == "end" ||
                                 seq[k - 1].kind == seq[k + 1].kind))
      reject("coverage", "piece " + std::to_string(k + 1) + ": an end must lie between an in-piece and an out-piece");
  checked.push_back("pieces: " + std::to_string(n_in) + " in and " + std::to_string(n_out) + " out (" + std::to_string(nboxes) +
                    " boxes, signs proved) and " + std::to_string(n_end) + " ends (faces, Krawczyk, exclusion in " +
                    std::to_string(exclusion_boxes) + " boxes) cover [0, 1]");
  // the answer: the timeline of the pieces, assembled as every pipeline does
  auto point = [](const mpq_class& x) { return bracketed_instant(x, x, x); };
  std::vector<TimelineNode> tl;
  Status cur = seq.front().kind == "in" ? Status::overlapping : Status::separate;
  tl.push_back({point(0), cur, false});
  mpq_class cell_lo = 0;
  for (const auto& it : seq) {
    if (it.kind != "end") continue;
    tl.push_back({point((cell_lo + it.blo) / 2), cur, true});
    tl.push_back({bracketed_instant((it.blo + it.bhi) / 2, it.blo, it.bhi), Status::touching, false});
    cur = cur == Status::separate ? Status::overlapping : Status::separate;
    cell_lo = it.bhi;
  }
  tl.push_back({point((cell_lo + 1) / 2), cur, true});
  tl.push_back({point(1), cur, false});
  Answer got;
  assemble_answer(tl, got, [](std::size_t) {});
  Answer want;
  try {
    want = answer_from_json(at(cert, "answer", "certificate", false), "certificate", "answer");
  } catch (const std::exception& e) {
    reject("certificate format", e.what());
  }
  auto same_list = [](const auto& x, const auto& y, const char* what) { require_same_intervals(x, y, what, "the pieces"); };
  if (got.collides != want.collides) reject("answer", std::string("the pieces give collides = ") + (got.collides ? "true" : "false"));
  same_list(got.intervals, want.intervals, "collision interval(s)");
  same_list(got.contact_intervals, want.contact_intervals, "contact interval(s)");
  if (got.first_contact.has_value() != want.first_contact.has_value() || (got.first_contact && !same_instant(*got.first_contact, *want.first_contact)))
    reject("answer", "first_contact differs from the one the pieces give");
  if (got.contacts.size() != want.contacts.size())
    reject("answer", "the pieces give " + std::to_string(got.contacts.size()) + " contact(s), the certificate " + std::to_string(want.contacts.size()));
  for (std::size_t i = 0; i < got.contacts.size(); ++i)
    if (!same_instant(got.contacts[i], want.contacts[i])) reject("answer", "contact " + std::to_string(i + 1) + " differs from the one the pieces give");
  checked.push_back("answer: follows from the checked pieces");
}

json box_json(const BezierBox& b) { return json::array({q(b.u_lo), q(b.u_hi), q(b.t_lo), q(b.t_hi)}); }

}  // namespace

json make_bezier_certificate(const Scene& s, const json& scene_doc, Solution* solved) {
  const auto start = std::chrono::steady_clock::now();
  if (!bezier_certificate_scene(s)) throw CertificationError("a Bézier certificate is for 3D scenes with shared parameters");
  BezierProofOptions po;
  po.record = true;
  po.bits = kBits;
  const BezierProofResult r = prove_bezier(prepare_pair<4>(s), po);
  if (!r.decided) throw CertificationError("the interval Bézier proof does not decide the scene: " + r.reason);
  json c;
  c["format"] = kBezierCertificateFormat;
  c["scene"] = {{"path", s.path}, {"name", s.name}, {"dim", scene_doc.at("dim")}, {"a", scene_doc.at("a")}, {"b", scene_doc.at("b")}};
  if (scene_doc.contains("parameters")) c["scene"]["parameters"] = scene_doc["parameters"];
  c["convention"] = "F(u, t) = det((u - 1) A(t) - u B(t)) in tensor Bernstein form on [0, 1]^2 (degree 4 in u), built exactly from "
                    "the scene; boxes are [u0, u1, t0, t1] in absolute coordinates; an end's boxes are its Krawczyk chain on "
                    "(F, F_u) in (u, t); every sign is proved by MPFI at precision_bits";
  c["precision_bits"] = kBits;
  c["answer"] = answer_to_json(r.answer);
  json pieces = json::array();
  for (const BezierPiece& p : r.pieces) {
    json boxes = json::array();
    for (const auto& b : p.boxes) boxes.push_back(box_json(b));
    json item = {{"kind", p.kind == BezierPiece::out ? "out" : p.kind == BezierPiece::in ? "in" : "end"}, {"lo", q(p.lo)}, {"hi", q(p.hi)},
                 {"boxes", boxes}};
    if (p.kind == BezierPiece::end) item["bracket"] = {q(p.bracket_lo), q(p.bracket_hi)};
    pieces.push_back(item);
  }
  c["pieces"] = pieces;
  // the writer checks its own certificate: a claim it cannot re-prove is never written
  finish_proof_certificate(c, check_bezier_certificate(s, scene_doc, c), kBezierCertificateFormat, kBits, r.answer,
                           "bezier-proved", start, solved);
  if (solved) solved->work = r.work;
  return c;
}

json make_certified_mode_certificate(const Scene& s, const json& scene_doc, std::string& route, std::string& why, Solution* solved) {
  why.clear();
  if (bezier_certificate_scene(s)) {
    try {
      route = "bezier";
      return make_bezier_certificate(s, scene_doc, solved);
    } catch (const CertificationError& e) {
      why = e.what();
    }
  } else {
    why = s.dim == 2 ? "a 2D scene: the Bézier route is 3D only; the exact (or cycloidal) certificate"
                     : "independent motions: their own certificate (eccd-independent-certificate/1)";
  }
  route = cycloidal_certificate_scene(s) ? "cycloidal" : independent_certificate_scene(s) ? "independent" : "exact";
  return make_certificate(s, scene_doc, solved);
}

CertificateCheck check_bezier_certificate(const Scene& s, const json& scene_doc, const json& cert) {
  std::vector<std::string> checked;
  return run_checker([&] { check(s, scene_doc, cert, checked); }, checked);
}

}  // namespace eccd
