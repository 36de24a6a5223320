// The cycloidal certificate's writer (certificate/write/cycloidal_certificate.hpp).
#include "certificate/write/cycloidal_certificate.hpp"

#include "certified/ladder.hpp"
#include "certificate/write/cycloidal_enclosures.hpp"
#include "io/scene_reader.hpp"
#include "kernel/collision_timeline.hpp"

#include <chrono>
#include <cstdio>
#include <algorithm>
#include <functional>

namespace eccd {

bool cycloidal_certificate_scene(const Scene& s) { return s.dim == 2 && !s.independent && has_cycloidal_motion(s); }

namespace {

using json = nlohmann::json;

const char* const kConvention =
    "f(lambda; t) = det(lambda A(t) - B(t)) = g3 lambda^3 + g2 lambda^2 + g1 lambda + g0 with A(t), B(t) of the "
    "scene's "
    "static or cycloidal motions (kernel/cycloidal_motion.hpp, 003 section V); Delta = the discriminant of that cubic; "
    "every claim is proved by MPFI interval evaluation at precision_bits (outward rounding)";

int decided_bits(const Solution& s) {
  const std::string& r = s.decided_in;  // "mpfi:BITS"
  if (r.rfind("mpfi:", 0) == 0) return std::stoi(r.substr(5));
  return 128;
}

json instant_json(const Instant& i) { return {{"approx", i.approx}, {"lo", i.lo->get_str()}, {"hi", i.hi->get_str()}}; }

std::string upper_decimal(const mpq_class& x) {  // a decimal >= x (3 significant digits, rounded up), exact when parsed
  char buf[64];
  double d = x.get_d();
  std::snprintf(buf, sizeof buf, "%.3e", d * (1 + 1e-3) + 1e-300);
  return buf;
}

// An instant of the timeline: an end (0 or 1), a simple root's bracket or an undecided stretch.
struct Inst {
  mpq_class lo, hi;
  std::string kind;
  Status status = Status::uncertain;
  json evidence;
};

// The timeline's instants: 0, the certified run's critical stretches, 1 (a stretch reaching 0 or 1 replaces that
// end).
std::vector<Inst> timeline_instants(const Solution& sol) {
  struct Stretch {
    mpq_class lo, hi;
    bool simple;
  };
  std::vector<Stretch> crit;
  for (const auto& c : sol.critical) {
    if (!c.t.certified()) throw CertificationError("a critical instant of the certified run has no bracket");
    crit.push_back({*c.t.lo, *c.t.hi, c.multiplicity == 1});
  }
  std::vector<Inst> inst;
  if (crit.empty() || crit.front().lo != 0) inst.push_back({0, 0, "end", Status::uncertain, json()});
  for (const auto& c : crit)
    inst.push_back({c.lo, c.hi, c.simple ? "simple_root" : "undecided", Status::uncertain, json()});
  if (crit.empty() || crit.back().hi != 1) inst.push_back({1, 1, "end", Status::uncertain, json()});
  return inst;
}

// The gap between two consecutive instants cut into proved root-free pieces; returns the cuts. An undecided
// stretch at 0 or 1 comes from the certified run as the end point itself ([0, 0] or [1, 1]); its extent is found
// here: the pieces next to it that no enclosure proves root-free (down to 2^-64) join the stretch.
std::vector<mpq_class> cover_gap(const CycloidalEnclosures& enc, Inst& left, Inst& right) {
  const bool grow_left = left.kind == "undecided" && left.lo == 0 && left.hi == 0;
  const bool grow_right = right.kind == "undecided" && right.lo == 1 && right.hi == 1;
  std::vector<mpq_class> cuts;
  // left to right (or right to left when the stretch at 1 grows), bisecting until each piece is root-free
  std::function<void(const mpq_class&, const mpq_class&, int)> cover = [&](const mpq_class& x, const mpq_class& y,
                                                                           int depth) {
    if (enc.root_free(x, y)) return;
    if (depth >= 64 && grow_left && x == left.hi) {
      left.hi = y;
      return;
    }
    if (depth >= 64 && grow_right && y == right.lo) {
      right.lo = x;
      return;
    }
    if (depth >= 200 || cuts.size() >= kCycloidalMaxGapPoints)
      throw CertificationError("no root-free cover of the gap [" + left.hi.get_str() + ", " + right.lo.get_str() +
                               "] near t = " + decimal_string(x, 12));
    const mpq_class m = (x + y) / 2;
    if (grow_right) {
      cover(m, y, depth + 1);
      cuts.push_back(m);
      cover(x, m, depth + 1);
    } else {
      cover(x, m, depth + 1);
      cuts.push_back(m);
      cover(m, y, depth + 1);
    }
  };
  cover(left.hi, right.lo, 0);
  if (grow_right) std::reverse(cuts.begin(), cuts.end());
  // cuts swallowed by a grown stretch are not in the gap any more
  std::vector<mpq_class> kept;
  for (const auto& c : cuts)
    if (left.hi < c && c < right.lo) kept.push_back(c);
  return kept;
}

// The certificate's timeline, gap points and gap proofs, built instant by instant, and the timeline the answer is
// assembled from.
struct TimelineWriter {
  TimelineWriter(const CycloidalEnclosures& e, int b) : enc(e), bits(b) {}

  const CycloidalEnclosures& enc;
  int bits;
  json timeline = json::array(), gaps = json::array(), proofs = json::array();
  std::vector<TimelineNode> seq;
  bool complete = true;

  // An instant's entry with its proved status (and the evidence of a simple root, the epsilon of a stretch).
  void add_instant(Inst& n) {
    json e;
    if (n.kind == "end") {
      n.status = enc.status_at(n.lo);
      if (n.status == Status::uncertain)
        throw CertificationError("the static test at t = " + n.lo.get_str() + " is not proved in MPFI at " +
                                 std::to_string(bits) + " bits");
    } else if (n.kind == "simple_root") {
      if (!enc.simple_root(n.lo, n.hi))
        throw CertificationError("the bracket [" + n.lo.get_str() + ", " + n.hi.get_str() +
                                 "] is not proved to hold one simple root");
      n.status = enc.status_at_root(n.lo, n.hi);
      if (n.status == Status::uncertain)
        throw CertificationError("the status at the root in [" + n.lo.get_str() + ", " + n.hi.get_str() +
                                 "] is not proved");
      e["evidence"] = {{"delta_at_lo", to_string(enc.delta_sign_at(n.lo))},
                       {"delta_at_hi", to_string(enc.delta_sign_at(n.hi))},
                       {"delta_prime", to_string(enc.derivative_sign_over(n.lo, n.hi))}};
    } else {
      complete = false;
      // twice the writer's bound: the checker's own enclosures (certificate/check/cycloidal_certificate.cpp) are not
      // the same
      e["epsilon"] = upper_decimal(mpq_class(2 * enc.magnitude_upper(n.lo, n.hi)));
      e["claim"] =
          "touch or near miss within epsilon: |Delta(t)| <= epsilon on [lo, hi]; nothing else is claimed there";
    }
    Instant it = n.lo == n.hi ? bracketed_instant(n.lo, n.lo, n.hi)
                              : bracketed_instant(mpq_class((n.lo + n.hi) / 2), n.lo, n.hi);
    e["instant"] = instant_json(it);
    e["kind"] = n.kind;
    e["status"] = to_string(n.status);
    timeline.push_back(e);
    seq.push_back({it, n.status, false});
  }

  // The cell from a to b (the instants' brackets' ends) with its sample's status, and the gap's points and the
  // proof of each gap piece, named (the checker runs only that one).
  void add_cell(const mpq_class& a, const mpq_class& b, const std::vector<mpq_class>& gap_cuts) {
    if (!(a < b))
      throw CertificationError("two critical stretches share an end at t = " + a.get_str() + ": no cell between them");
    const mpq_class sample = (a + b) / 2;
    const Status cs = enc.status_at(sample);
    if (cs == Status::uncertain)
      throw CertificationError("the static test at the cell sample " + sample.get_str() + " is not proved");
    timeline.push_back({{"cell_sample", sample.get_str()}, {"status", to_string(cs)}});
    seq.push_back({bracketed_instant(sample, sample, sample), cs, true});
    for (const auto& c : gap_cuts) gaps.push_back(c.get_str());
    std::vector<mpq_class> cut{a};
    cut.insert(cut.end(), gap_cuts.begin(), gap_cuts.end());
    cut.push_back(b);
    for (std::size_t i = 0; i + 1 < cut.size(); ++i) {
      const char* how = enc.root_free_by(cut[i], cut[i + 1]);
      if (!how)
        throw CertificationError("the gap piece [" + cut[i].get_str() + ", " + cut[i + 1].get_str() +
                                 "] is not proved root-free");
      proofs.push_back(how);
    }
  }
};

// The answer's JSON. Undecided stretches and no proved collision: collides is unknown (null), never false.
json certificate_answer_json(const Answer& ans) {
  json answer = answer_to_json(ans);
  const std::optional<bool> claim = collides_claim(ans);
  answer["collides"] = claim ? json(*claim) : json(nullptr);
  answer["undecided"] = json::array();
  for (const auto& u : ans.undecided) answer["undecided"].push_back(instant_json(u));
  return answer;
}

}  // namespace

json make_cycloidal_certificate(const Scene& s, const json& scene_doc, Solution* solved) {
  auto start = std::chrono::steady_clock::now();
  Solution sol = run_certified_cycloidal(s, {}, Variant::answer);
  const int bits = decided_bits(sol);
  const CycloidalEnclosures enc(s, bits);
  std::vector<Inst> inst = timeline_instants(sol);
  // Gap covers first: they may grow an undecided stretch at 0 or 1.
  std::vector<std::vector<mpq_class>> gap_cuts(inst.size());
  for (std::size_t k = 0; k + 1 < inst.size(); ++k) gap_cuts[k] = cover_gap(enc, inst[k], inst[k + 1]);
  TimelineWriter w(enc, bits);
  for (std::size_t k = 0; k < inst.size(); ++k) {
    w.add_instant(inst[k]);
    if (k + 1 < inst.size()) w.add_cell(inst[k].hi, inst[k + 1].lo, gap_cuts[k]);
  }
  if (w.gaps.size() > kCycloidalMaxGapPoints) throw CertificationError("more gap points than the checker accepts");
  Answer ans;
  assemble_answer(w.seq, ans, [](std::size_t) {});
  json cert;
  cert["format"] = kCycloidalCertificateFormat;
  cert["scene"] = {{"path", s.path},
                   {"name", s.name},
                   {"dim", scene_doc.at("dim")},
                   {"a", scene_doc.at("a")},
                   {"b", scene_doc.at("b")}};
  cert["delta"] = {{"convention", kConvention}, {"precision_bits", bits}};
  cert["timeline"] = w.timeline;
  cert["gap_points"] = w.gaps;
  cert["gap_proofs"] = w.proofs;
  cert["complete"] = w.complete;
  cert["answer"] = certificate_answer_json(ans);
  cert["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (solved) {
    *solved = sol;
    solved->answer = ans;
  }
  return cert;
}

}  // namespace eccd
