// The cycloidal certificate's checker (io/cycloidal_certificate.hpp). Deliberately
// simple: MPFI enclosures of Δ, Δ' and the static test (io/cycloidal_enclosures.hpp)
// at the certificate's brackets, samples and gap points, and the timeline-to-answer
// step; no subdivision search, no refinement, no solver.
#include "io/cycloidal_certificate.hpp"
#include "io/certificate_json.hpp"

#include "io/cycloidal_enclosures.hpp"
#include "io/scene_reader.hpp"
#include "kernel/collision_timeline.hpp"

namespace eccd {

namespace {

using json = nlohmann::json;

using namespace certificate_json;

const json& at(const json& j, const std::string& key, const std::string& place) { return certificate_json::at(j, key, place, false); }
mpq_class rat(const json& j, const std::string& place) { return read_short_rational(j, place, kCycloidalMaxRationalBits); }

Status status_named(const json& j, const std::string& place, bool uncertain_ok) {
  if (j.is_string())
    for (Status s : {Status::separate, Status::touching, Status::overlapping, Status::uncertain})
      if (j.get<std::string>() == to_string(s) && (uncertain_ok || s != Status::uncertain)) return s;
  reject("certificate format", place + ": expected \"separate\", \"touching\" or \"overlapping\"" + std::string(uncertain_ok ? " or \"uncertain\"" : ""));
}

std::string bracket(const mpq_class& lo, const mpq_class& hi) {
  return lo == hi ? "[" + lo.get_str() + "]" : "[" + lo.get_str() + ", " + hi.get_str() + "] (~" + decimal_string(mpq_class((lo + hi) / 2), 12) + ")";
}

bool same(const Instant& a, const Instant& b) { return a.lo && b.lo && a.hi && b.hi && *a.lo == *b.lo && *a.hi == *b.hi; }

void check(const Scene& s, const json& scene_doc, const json& cert, std::vector<std::string>& checked) {
  if (at(cert, "format", "certificate") != kCycloidalCertificateFormat)
    reject("certificate format", std::string("format: expected \"") + kCycloidalCertificateFormat + "\" for a cycloidal scene");
  const json& sc = at(cert, "scene", "certificate");
  for (const char* k : {"dim", "a", "b"})
    if (at(sc, k, "scene") != scene_doc.at(k))
      reject("scene", std::string("the certificate's \"") + k + "\" differs from the scene file's: it is a certificate for another scene");
  checked.push_back("scene: dim, a and b are those of " + s.path);
  const json& pb = at(at(cert, "delta", "certificate"), "precision_bits", "delta");
  if (!pb.is_number_integer() || pb.get<long long>() < kCycloidalMinBits || pb.get<long long>() > kCycloidalMaxBits)
    reject("certificate format", "delta.precision_bits: expected a whole number from " + std::to_string(kCycloidalMinBits) + " to " +
                                     std::to_string(kCycloidalMaxBits));
  const int bits = pb.get<int>();
  const CycloidalEnclosures enc(s, bits);

  // Timeline: instant, cell, ..., instant from 0 to 1.
  const json& tl = at(cert, "timeline", "certificate");
  if (!tl.is_array() || tl.size() < 3 || tl.size() % 2 == 0 || tl.size() > kCycloidalMaxTimeline)
    reject("timeline", "expected instant, cell, instant, ..., instant (an odd number >= 3 of entries, at most " +
                           std::to_string(kCycloidalMaxTimeline) + ")");
  struct Node { mpq_class lo, hi; Status status; std::string kind, name, place; json entry; };
  std::vector<Node> nodes;
  for (std::size_t k = 0; k < tl.size(); ++k) {
    const std::string place = "timeline[" + std::to_string(k) + "]";
    Node n;
    n.place = place;
    n.entry = tl[k];
    if (k % 2 == 1) {
      n.lo = n.hi = rat(at(tl[k], "cell_sample", place), place + ".cell_sample");
      n.kind = "cell";
      n.name = "cell " + std::to_string(k / 2) + " (sample " + n.lo.get_str() + ")";
      n.status = status_named(at(tl[k], "status", place), place + ".status", false);
    } else {
      const json& in = at(tl[k], "instant", place);
      n.lo = rat(at(in, "lo", place + ".instant"), place + ".instant.lo");
      n.hi = rat(at(in, "hi", place + ".instant"), place + ".instant.hi");
      const json& kind = at(tl[k], "kind", place);
      n.kind = kind.is_string() ? kind.get<std::string>() : "";
      if (n.kind != "end" && n.kind != "simple_root" && n.kind != "undecided")
        reject("certificate format", place + ".kind: expected \"end\", \"simple_root\" or \"undecided\"");
      n.name = "instant " + std::to_string(k / 2) + " " + bracket(n.lo, n.hi);
      n.status = status_named(at(tl[k], "status", place), place + ".status", n.kind == "undecided");
      if (n.kind == "undecided" && n.status != Status::uncertain) reject(n.name, "an undecided stretch must have status \"uncertain\"");
      if (n.lo > n.hi) reject(n.name, "lo > hi");
      const json& approx = at(in, "approx", place + ".instant");
      if (!approx.is_string() || approx.get_ref<const std::string&>().size() > 64)
        reject("certificate format", place + ".instant.approx: expected a decimal string of at most 64 characters");
      mpq_class v;
      try {
        v = parse_rational(approx.get<std::string>());
      } catch (const std::exception&) {
        reject("certificate format", place + ".instant.approx: not a decimal");
      }
      if (n.lo == n.hi ? v != n.lo : (v < n.lo || v > n.hi)) reject(n.name, "approx " + approx.get<std::string>() + " lies outside its bracket");
    }
    nodes.push_back(n);
  }
  const Node &first = nodes.front(), &last = nodes.back();
  if (first.lo != 0 || (first.kind == "end" && first.hi != 0)) reject("timeline", "the first instant must start at 0 (an end [0, 0], or a stretch from 0)");
  if (last.hi != 1 || (last.kind == "end" && last.lo != 1)) reject("timeline", "the last instant must end at 1 (an end [1, 1], or a stretch to 1)");
  for (std::size_t k = 0; k < nodes.size(); k += 2)
    if (nodes[k].kind == "end" && k != 0 && k + 1 != nodes.size()) reject(nodes[k].name, "an interior instant cannot be of kind \"end\"");
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k)
    if (!(nodes[k].hi < nodes[k + 1].lo))
      reject(nodes[k].kind == "cell" ? nodes[k].name : nodes[k + 1].name,
             "each cell sample must lie strictly between the brackets of its two instants, and brackets must be disjoint");
  checked.push_back("timeline: " + std::to_string(nodes.size() / 2 + 1) + " instants and " + std::to_string(nodes.size() / 2) +
                    " cells in order, brackets disjoint");

  // An incomplete certificate claims no more than it proves: with a stretch
  // undecided, "collides": false would claim that no collision hides there.
  {
    std::size_t undecided = 0;
    for (const auto& n : nodes) undecided += n.kind == "undecided";
    const json& aj = at(cert, "answer", "certificate");
    if (undecided && aj.is_object() && aj.contains("collides") && aj["collides"] == false)
      reject("answer", "answer.collides is false but " + std::to_string(undecided) +
                           " stretch(es) of the timeline are undecided: an incomplete certificate may claim a collision where one "
                           "is proved (true), otherwise only null (unknown), never false");
  }

  // Instants.
  int roots = 0, stretches = 0;
  std::optional<mpq_class> whole_bound;
  for (std::size_t k = 0; k < nodes.size(); k += 2) {
    Node& n = nodes[k];
    if (n.kind == "end") {
      Status st = enc.status_at(n.lo);
      if (st == Status::uncertain) reject(n.name, "the static test at t = " + n.lo.get_str() + " is not proved at " + std::to_string(bits) + " bits");
      if (st != n.status) reject(n.name, std::string("the static test gives ") + to_string(st) + ", not " + to_string(n.status) + " as claimed");
    } else if (n.kind == "simple_root") {
      ++roots;
      Sign sl = enc.delta_sign_at(n.lo), sh = enc.delta_sign_at(n.hi);
      if (!CycloidalEnclosures::proved_nonzero(sl) || !CycloidalEnclosures::proved_nonzero(sh) || sl == sh)
        reject(n.name, "Delta at lo and hi are not proved of opposite signs (lo: " + std::string(to_string(sl)) + ", hi: " + to_string(sh) + ")");
      if (!CycloidalEnclosures::proved_nonzero(enc.derivative_sign_over(n.lo, n.hi)))
        reject(n.name, "Delta' is not proved non-zero on the bracket: it may hold more than one root, or a multiple one");
      Status st = enc.status_at_root(n.lo, n.hi);
      if (st == Status::uncertain) reject(n.name, "the signs of P and D are not proved on the bracket");
      if (st != n.status) reject(n.name, std::string("P and D give ") + to_string(st) + ", not " + to_string(n.status) + " as claimed");
    } else {
      ++stretches;
      const mpq_class eps = rat(at(n.entry, "epsilon", n.place), n.place + ".epsilon");
      if (eps < 0) reject(n.name, "epsilon must not be negative");
      // A stretch is where Δ comes close to 0 (a possible double root), not a
      // place to hide a part of [0, 1]: epsilon at most 2^-10 of an upper bound
      // of |Δ| on all of [0, 1], so "|Δ| <= epsilon" says Δ is small there.
      if (!whole_bound) whole_bound = enc.magnitude_upper(mpq_class(0), mpq_class(1));
      if (eps * 1024 > *whole_bound)
        reject(n.name, "epsilon = " + decimal_string(eps, 6) + " is not small: more than 2^-10 of the bound " + decimal_string(*whole_bound, 6) +
                           " of |Delta| on [0, 1]; an undecided stretch claims Delta near 0");
      if (enc.magnitude_upper(n.lo, n.hi) > eps)
        reject(n.name, "|Delta| <= epsilon = " + eps.get_str() + " on the stretch is not proved (an enclosure bounds it by " +
                           decimal_string(enc.magnitude_upper(n.lo, n.hi), 6) + ")");
    }
  }
  checked.push_back("instants: " + std::to_string(roots) + " simple root(s) proved (opposite signs of Delta at the bracket ends, "
                    "Delta' non-zero on it; status from P and D), the ends by the static test, " + std::to_string(stretches) +
                    " undecided stretch(es) with |Delta| <= epsilon proved (touch or near miss within epsilon)");

  // Gaps: Δ has no root outside the brackets.
  const json& gp = at(cert, "gap_points", "certificate");
  if (!gp.is_array() || gp.size() > kCycloidalMaxGapPoints)
    reject("certificate format", "gap_points: expected an array of at most " + std::to_string(kCycloidalMaxGapPoints) + " points");
  std::vector<mpq_class> pts;
  for (std::size_t i = 0; i < gp.size(); ++i) pts.push_back(rat(gp[i], "gap_points[" + std::to_string(i) + "]"));
  std::size_t used = 0, pieces = 0;
  for (std::size_t k = 0; k + 2 < nodes.size(); k += 2) {
    const mpq_class a = nodes[k].hi, b = nodes[k + 2].lo;
    std::vector<mpq_class> cut{a};
    while (used < pts.size() && pts[used] < b) {
      if (!(cut.back() < pts[used])) reject("gaps", "gap point " + pts[used].get_str() + " is not strictly inside a gap, or the points are not increasing");
      cut.push_back(pts[used++]);
    }
    cut.push_back(b);
    for (std::size_t i = 0; i + 1 < cut.size(); ++i, ++pieces)
      if (!enc.root_free(cut[i], cut[i + 1]))
        reject("gaps", "Delta is not proved root-free on [" + cut[i].get_str() + ", " + cut[i + 1].get_str() + "] (~" +
                           decimal_string(cut[i], 12) + ") outside every bracket");
  }
  if (used != pts.size()) reject("gaps", "gap point " + pts[used].get_str() + " is not strictly inside a gap");
  checked.push_back("gaps: Delta has no root in [0, 1] outside the brackets (" + std::to_string(pieces) + " piece(s), each proved root-free)");

  // Cells.
  for (std::size_t k = 1; k < nodes.size(); k += 2) {
    Status st = enc.status_at(nodes[k].lo);
    if (st == Status::uncertain) reject(nodes[k].name, "the static test at the sample is not proved");
    if (st != nodes[k].status) reject(nodes[k].name, std::string("the static test gives ") + to_string(st) + ", not " + to_string(nodes[k].status));
  }
  checked.push_back("cells: the static test at each of the " + std::to_string(nodes.size() / 2) + " sample(s) proves the claimed status");

  // Answer.
  std::vector<TimelineNode> seq;
  for (const auto& n : nodes) seq.push_back({bracketed_instant(mpq_class((n.lo + n.hi) / 2), n.lo, n.hi), n.status, n.kind == "cell"});
  Answer got;
  assemble_answer(seq, got, [](std::size_t) {});
  const json& aj = at(cert, "answer", "certificate");
  Answer want;
  json plain = aj;
  if (plain.is_object()) plain.erase("undecided");
  // collides: true iff a collision is proved; with a stretch undecided and
  // none proved, null (unknown): an incomplete certificate never claims false.
  const std::optional<bool> proved = collides_claim(got);
  const json claimed = plain.is_object() && plain.contains("collides") ? plain["collides"] : json();
  if (claimed.is_boolean() || claimed.is_null()) {
    if (claimed != (proved ? json(*proved) : json(nullptr)))
      reject("answer", "answer.collides is " + claimed.dump() + " but the checked timeline proves " +
                           (!proved ? std::string("neither: no collision is proved and ") + std::to_string(got.undecided.size()) +
                                          " stretch(es) are undecided, so collides must be null (unknown), never false"
                                    : *proved ? std::string("a collision (collides must be true)")
                                              : std::string("that there is none (collides must be false)")));
    if (claimed.is_null()) plain["collides"] = false;  // the typed answer: no proved interval
  }
  try {
    want = answer_from_json(plain, "certificate", "answer");
  } catch (const std::exception& e) {
    reject("certificate format", e.what());
  }
  auto same_list = [&](const std::vector<std::pair<Instant, Instant>>& x, const std::vector<std::pair<Instant, Instant>>& y, const char* what) {
    if (x.size() != y.size()) reject("answer", std::string("the timeline gives ") + std::to_string(x.size()) + " " + what + ", the certificate " + std::to_string(y.size()));
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!same(x[i].first, y[i].first) || !same(x[i].second, y[i].second)) reject("answer", std::string(what) + " " + std::to_string(i + 1) + " differs from the timeline's");
  };
  if (got.collides != want.collides) reject("answer", std::string("the timeline gives collides = ") + (got.collides ? "true" : "false"));
  same_list(got.intervals, want.intervals, "collision interval(s)");
  same_list(got.contact_intervals, want.contact_intervals, "contact interval(s)");
  if (got.first_contact.has_value() != want.first_contact.has_value() || (got.first_contact && !same(*got.first_contact, *want.first_contact)))
    reject("answer", "first_contact differs from the one the timeline gives");
  if (got.contacts.size() != want.contacts.size())
    reject("answer", "the timeline gives " + std::to_string(got.contacts.size()) + " contact(s), the certificate " + std::to_string(want.contacts.size()));
  for (std::size_t i = 0; i < got.contacts.size(); ++i)
    if (!same(got.contacts[i], want.contacts[i])) reject("answer", "contact " + std::to_string(i + 1) + " differs from the timeline's");
  const json& und = aj.is_object() && aj.contains("undecided") ? aj["undecided"] : json();
  if (!und.is_array() || und.size() != got.undecided.size())
    reject("answer", "answer.undecided must list the " + std::to_string(got.undecided.size()) + " undecided stretch(es) of the timeline");
  const json& complete = at(cert, "complete", "certificate");
  if (complete != json(got.undecided.empty()))
    reject("answer", std::string("complete must be ") + (got.undecided.empty() ? "true" : "false: an undecided stretch is left"));
  checked.push_back("answer: follows from the checked timeline" +
                    std::string(got.undecided.empty() ? "" : " (" + std::to_string(got.undecided.size()) + " stretch(es) undecided: not a complete answer)"));
}

}  // namespace

CertificateCheck check_cycloidal_certificate(const Scene& s, const json& scene_doc, const json& cert) {
  std::vector<std::string> checked;
  return run_checker([&] { check(s, scene_doc, cert, checked); }, checked);
}

}  // namespace eccd
