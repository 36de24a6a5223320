// The Bézier certificate's writer and checker (certificate/write/bezier_certificate.hpp).
#include "certificate/write/bezier_certificate.hpp"

#include "certified/bezier_proof.hpp"
#include "certificate/write/exact_certificate.hpp"
#include "certificate/check_certificate.hpp"
#include "certificate/write/certificate_json.hpp"
#include "certificate/write/cycloidal_certificate.hpp"
#include "certificate/write/independent_certificate.hpp"
#include "certified/krawczyk.hpp"
#include "io/scene_reader.hpp"
#include "kernel/characteristic_polynomial.hpp"
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
using krawczyk_method::Box;
using krawczyk_method::Nets;
using krawczyk_method::System;
using I = MpfiInterval;
using krawczyk_method::restrict_axis;

const int kBits = 160;

std::string q(const mpq_class& x) {
  mpq_class y = x;
  y.canonicalize();
  return y.get_str();
}

// F(u, t)'s net from the scene, exactly, as a tensor net (u, s, t) of degree 0 in s, and as rows b[u][t].
BiBern<Rational> exact_bi(const Scene& scene) {
  const PreparedPair<4> p = prepare_pair<4>(scene);
  return ellipsoid_function(characteristic_bernstein<Rational, 4>(p, false, Rational(0)), Rational(0));
}
TriBern<Rational> exact_net(const BiBern<Rational>& f) {
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

// The exclusion of an end as the subdivision tree the checker replays (certificate/check/bezier_certificate.cpp):
// preorder, '1' split / '0' leaf; u halved at every level, t at every second; a leaf lies in the Krawczyk box's
// u-range [ku0, ku1] or has F or F_u of one proved sign.
void exclusion_tree(const TriBern<Interval>& f, const TriBern<Interval>& fu, const mpq_class& u0, const mpq_class& u1,
                    int depth, const mpq_class& ku0, const mpq_class& ku1, long& nodes, std::string& out) {
  if (++nodes > kBezierMaxExclusionBoxes)
    throw CertificationError("the exclusion of an end needs more than " + std::to_string(kBezierMaxExclusionBoxes) +
                             " boxes");
  if ((u0 >= ku0 && u1 <= ku1) || f.strict_sign() != 0 || fu.strict_sign() != 0) {
    out += '0';
    return;
  }
  if (depth >= kBezierMaxExclusionDepth)
    throw CertificationError("the exclusion of an end does not close within " +
                             std::to_string(kBezierMaxExclusionDepth) + " levels");
  out += '1';
  const Interval half(0.5, 0.5);
  const mpq_class um = (u0 + u1) / 2;
  auto [fl, fh] = f.split_half(0, half);
  auto [gl, gh] = fu.split_half(0, half);
  for (int side = 0; side < 2; ++side) {
    const auto& a = side ? fh : fl;
    const auto& b = side ? gh : gl;
    const mpq_class a0 = side ? um : u0, a1 = side ? u1 : um;
    if (depth % 2 == 0) {
      exclusion_tree(a, b, a0, a1, depth + 1, ku0, ku1, nodes, out);
      continue;
    }
    auto [al, ah] = a.split_half(2, half);
    auto [bl, bh] = b.split_half(2, half);
    exclusion_tree(al, bl, a0, a1, depth + 1, ku0, ku1, nodes, out);
    exclusion_tree(ah, bh, a0, a1, depth + 1, ku0, ku1, nodes, out);
  }
}

json box_json(const BezierBox& b) { return json::array({q(b.u_lo), q(b.u_hi), q(b.t_lo), q(b.t_hi)}); }

}  // namespace

json make_bezier_certificate(const Scene& s, const json& scene_doc, Solution* solved) {
  const auto start = std::chrono::steady_clock::now();
  if (!bezier_certificate_scene(s))
    throw CertificationError("a Bézier certificate is for 3D scenes with shared parameters");
  BezierProofOptions po;
  po.record = true;
  po.bits = kBits;
  const BezierProofResult r = prove_bezier(prepare_pair<4>(s), po);
  if (!r.decided) throw CertificationError("the interval Bézier proof does not decide the scene: " + r.reason);
  json c;
  c["format"] = kBezierCertificateFormat;
  c["scene"] = {{"path", s.path},
                {"name", s.name},
                {"dim", scene_doc.at("dim")},
                {"a", scene_doc.at("a")},
                {"b", scene_doc.at("b")}};
  if (scene_doc.contains("parameters")) c["scene"]["parameters"] = scene_doc["parameters"];
  c["convention"] =
      "F(u, t) = det((u - 1) A(t) - u B(t)) in tensor Bernstein form on [0, 1]^2 (degree 4 in u), built exactly from "
      "the scene and given in net (rows u = 0..4, columns t = 0..degree_t); boxes are [u0, u1, t0, t1] in absolute "
      "coordinates; an end's boxes are its Krawczyk chain on (F, F_u) in (u, t) and its exclusion the subdivision "
      "tree of [0, 1] x [lo, hi] in preorder ('1' split: u halved at every level, t at every second; '0' leaf: in "
      "the chain box's u-range, or F or F_u of one sign); every sign is proved by outward-rounded intervals";
  c["precision_bits"] = kBits;
  c["answer"] = answer_to_json(r.answer);
  // the net: F exactly (the checker verifies it against the scene at rational points, its own way)
  const BiBern<Rational> bi = exact_bi(s);
  json rows = json::array();
  for (const auto& row : bi.b) {
    json r1 = json::array();
    for (const auto& x : row) r1.push_back(q(x));
    rows.push_back(r1);
  }
  // the moving solids it is built from: A(t) = N_a(t)^T Q_a N_a(t), N_a a polynomial multiple of M_a(t)^-1 (the checker
  // verifies both)
  const PreparedPair<4> prep = prepare_pair<4>(s);
  auto mat = [](const auto& m) {
    json matrix = json::array();
    for (const auto& row : m) {
      json r1 = json::array();
      for (const auto& x : row) r1.push_back(q(x));
      matrix.push_back(r1);
    }
    return matrix;
  };
  auto pmat = [](const auto& m) {
    json matrix = json::array();
    for (const auto& row : m) {
      json r1 = json::array();
      for (const auto& p : row) {
        json cs = json::array();
        for (const auto& x : p.c) cs.push_back(q(x));
        r1.push_back(cs);
      }
      matrix.push_back(r1);
    }
    return matrix;
  };
  c["net"] = {{"degree_u", bi.degree_u()}, {"degree_t", bi.degree_t()}, {"coefficients", rows},
              {"shape_a", mat(prep.qa)},   {"shape_b", mat(prep.qb)},   {"inverse_a", pmat(prep.na)},
              {"inverse_b", pmat(prep.nb)}};
  const TriBern<Rational> exact = exact_net(bi);
  TriBern<I> F;
  F.n = exact.n;
  for (const auto& x : exact.c) F.c.emplace_back(x, kBits);
  Nets nets(F, kBits);
  json pieces = json::array();
  for (const BezierPiece& p : r.pieces) {
    json boxes = json::array();
    for (const auto& b : p.boxes) boxes.push_back(box_json(b));
    json item = {{"kind", p.kind == BezierPiece::out  ? "out"
                          : p.kind == BezierPiece::in ? "in"
                                                      : "end"},
                 {"lo", q(p.lo)},
                 {"hi", q(p.hi)},
                 {"boxes", boxes}};
    if (p.kind == BezierPiece::end) {
      item["bracket"] = {q(p.bracket_lo), q(p.bracket_hi)};
      // the exclusion: what the checker would otherwise search, as a tree it replays
      const TriBern<Interval> f = to_double_intervals(restrict_axis(F, 2, p.lo, p.hi, kBits));
      const TriBern<Interval> fu = to_double_intervals(restrict_axis(nets.get({1, 0, 0}), 2, p.lo, p.hi, kBits));
      std::string tree;
      long nodes = 0;
      exclusion_tree(f, fu, 0, 1, 0, p.boxes.front().u_lo, p.boxes.front().u_hi, nodes, tree);
      item["exclusion"] = tree;
    }
    pieces.push_back(item);
  }
  c["pieces"] = pieces;
  // the writer checks its own certificate: a claim it cannot re-prove is never written
  finish_proof_certificate(c, check_bezier_certificate(s, scene_doc, c), kBezierCertificateFormat, kBits, r.answer,
                           "bezier-proved", start, solved);
  if (solved) solved->work = r.work;
  return c;
}

json make_certified_mode_certificate(const Scene& s, const json& scene_doc, std::string& route, std::string& why,
                                     Solution* solved) {
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
                     : "independent motions: their own certificate (eccd-independent-certificate/3)";
  }
  route = cycloidal_certificate_scene(s) ? "cycloidal" : independent_certificate_scene(s) ? "independent" : "exact";
  return make_certificate(s, scene_doc, solved);
}

CertificateCheck check_bezier_certificate(const Scene& s, const json& scene_doc, const json& cert) {
  return check_certificate(s, scene_doc, cert);  // eccd-check's library (certificate/check/bezier_certificate.cpp)
}

}  // namespace eccd
