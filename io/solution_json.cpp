// A Solution as JSON and as text (io/solution_json.hpp).
#include "io/solution_json.hpp"

#include "io/scene_reader.hpp"

#include <cstdio>
#include <sstream>

namespace eccd {

using nlohmann::json;

namespace {
// "yes", "no", or "unknown" when nothing is proved and something is undecided (collides_claim).
// The text of the `collides` claim (collides_claim: unknown while anything is undecided and no collision is proved).
std::string claim_text(const Answer& a) {
  const std::optional<bool> c = collides_claim(a);
  if (c) return *c ? "yes" : "no";
  return "unknown (no collision proved; " + std::to_string(a.undecided.size()) + " instant(s) undecided, below)";
}
json pair_list(const std::vector<std::pair<Instant, Instant>>& v) {
  json a = json::array();
  for (const auto& [s, e] : v) a.push_back({instant_to_json(s), instant_to_json(e)});
  return a;
}
}  // namespace

json solution_to_json(const Solution& s) {
  json j = answer_to_json(s.answer);
  // An answer with undecided stretches claims a collision only where one is
  // proved: otherwise collides is null (unknown), never false (kernel/answer.hpp).
  const std::optional<bool> claim = collides_claim(s.answer);
  j["collides"] = claim ? json(*claim) : json(nullptr);
  j["scene"] = s.scene;
  j["file"] = s.file;
  j["dim"] = s.dim;
  j["arith"] = s.arith.name();
  j["precision_bits"] = s.arith.precision_bits();
  j["input"] = to_string(s.input);
  // The face of a floating run: "none" (as published) or "bound" (guarded); null for exact and certified runs.
  j["guard"] = s.guard.empty() ? json(nullptr) : json(s.guard);
  j["variant"] = variant_name(s.variant);
  // 2D variants 1-3 (003 VI-C) do not compute what they do not report; 3D
  // first-contact mode (001 section 4) still reports the first interval and
  // the contacts up to its end.
  if (s.dim == 2 && (s.variant == Variant::collides || s.variant == Variant::first_contact)) {
    j["intervals"] = nullptr;
    j["contacts"] = nullptr;
  } else if (s.dim == 2 && s.variant == Variant::all_contacts) {
    j["intervals"] = nullptr;
  }
  if (s.answer.independent) {
    j["parameters"] = "independent";  // the answer keys are collides, s_intervals, t_intervals
  } else {
    json pts = json::array();
    for (const auto& p : s.answer.contact_points) pts.push_back(p.x);
    j["contact_points"] = pts;
    // The common normal at each contact point (ContactPoint::normal), same order; only when some point has one.
    json normals = json::array();
    bool any_normal = false;
    for (const auto& p : s.answer.contact_points) {
      normals.push_back(p.normal);
      any_normal = any_normal || !p.normal.empty();
    }
    if (any_normal) j["contact_normals"] = normals;
    j["contact_intervals"] = pair_list(s.answer.contact_intervals);
  }
  json und = json::array();
  for (const auto& u : s.answer.undecided) und.push_back(instant_to_json(u));
  j["undecided"] = und;
  j["projection_degree"] = s.projection_degree;
  // The JSON keeps its values for readers of older files: the Bézier method, which has no
  // univariate projection, is written "discriminant".
  j["projection"] = s.projection == "bezier" ? std::string("discriminant") : s.projection;
  j["projection_identically_zero"] = s.projection_identically_zero;
  j["status_at_0"] = to_string(s.status_at_0);
  json crit = json::array();
  for (const auto& c : s.critical)
    crit.push_back({{"t", instant_to_json(c.t)}, {"status", to_string(c.status)}, {"multiplicity", c.multiplicity}});
  j["critical_instants"] = crit;
  j["undecided_reasons"] = s.undecided_reasons;
  json cells = json::array();
  for (const auto& c : s.cells)
    cells.push_back({{"sample", instant_to_json(c.sample)}, {"status", to_string(c.status)}});
  j["cells"] = cells;
  json work = json::object();
  for (const auto& [k, v] : s.work) work[k] = v;
  j["work"] = work;
  j["time_ms"] = s.time_ms;
  j["basis"] = s.basis;
  j["method"] = s.method;
  j["certified"] = s.certified;
  if (!s.proofs.empty()) j["proofs"] = s.proofs;  // independent motions: how each end was proved
  if (s.sampled) j["sampled"] = true;
  if (s.dim == 3 && s.arith.floating()) j["setup_ms"] = s.setup_ms;
  if (s.arith.kind == Arithmetic::Certified) {
    j["escalated"] = !s.escalations.empty();
    json esc = json::array();
    for (const auto& e : s.escalations) {
      esc.push_back({{"rung", e.rung}, {"reason", e.reason}, {"spent_ms", e.spent_ms}, {"budget_ms", e.budget_ms}});
      // the last rung that was tried, and why it gave up
      if (e.reason.rfind("skipped", 0) != 0) j["escalation_reason"] = e.rung + ": " + e.reason;
    }
    j["escalations"] = esc;
    if (!s.local_decisions.empty()) {  // decided locally, exactly at one rational instant (certified/ladder.hpp)
      json local = json::object();
      for (const auto& [k, v] : s.local_decisions) local[k] = v;
      j["local_decisions"] = local;
    }
    j["decided_in"] = s.decided_in;
  }
  return j;
}

nlohmann::ordered_json stored_answer_of(const json& report) {
  nlohmann::ordered_json ans;
  if (report.contains("s_intervals")) {  // independent motions (scene-format.md, "Independent motions")
    for (const char* k : {"collides", "s_intervals", "t_intervals"})
      ans[k] = nlohmann::ordered_json::parse(report.at(k).dump());
    return ans;
  }
  for (const char* k : {"collides", "intervals", "first_contact", "contacts"})
    ans[k] = nlohmann::ordered_json::parse(report.at(k).dump());
  // Continuous touching (docs/answer-format.md): stored only when there is some, so older answers keep their keys.
  if (report.contains("contact_intervals") && report["contact_intervals"].is_array() &&
      !report["contact_intervals"].empty())
    ans["contact_intervals"] = nlohmann::ordered_json::parse(report["contact_intervals"].dump());
  return ans;
}

nlohmann::ordered_json stored_answer_of(const Solution& s) { return stored_answer_of(solution_to_json(s)); }

namespace {

// A solution report being read: its JSON, its label for messages, and typed
// accessors that throw SceneError "LABEL: PLACE: what" at the key's place.
struct ReportFields {
  const json& j;
  const std::string& label;

  [[noreturn]] void fail(const std::string& place, const std::string& what) const {
    throw SceneError(label + ": " + (place.empty() ? std::string("top level") : place) + ": " + what);
  }
  std::string text(const char* k, const std::string& def = "") const {
    const json* v = j.contains(k) ? &j[k] : nullptr;
    if (!v || v->is_null()) return def;
    if (!v->is_string()) fail(std::string("/") + k, "expected a string");
    return v->get<std::string>();
  }
  double number(const char* k, double def) const {
    if (!j.contains(k) || j[k].is_null()) return def;
    if (!j[k].is_number()) fail(std::string("/") + k, "expected a number");
    return j[k].get<double>();
  }
  Status status(const json& v, const std::string& place) const {
    for (Status st : {Status::separate, Status::touching, Status::overlapping, Status::uncertain})
      if (v.is_string() && v.get<std::string>() == to_string(st)) return st;
    fail(place, "expected a status (separate, touching, overlapping, uncertain)");
  }
  json list(const char* k) const {
    if (!j.contains(k) || j[k].is_null()) return json::array();
    if (!j[k].is_array()) fail(std::string("/") + k, "expected an array");
    return j[k];
  }
};

// The report's answer: the spec's keys (null lists of the 2D variants read as
// empty), then the extras (undecided stretches, contact points and normals).
Answer answer_of_report(const ReportFields& r) {
  json ans = json::object();
  ans["collides"] = r.j.contains("collides") ? r.j["collides"] : json(nullptr);
  // collides null: unknown, which only an answer with undecided stretches may
  // say (solution_to_json); the typed answer then holds false (no interval).
  if (ans["collides"].is_null() && r.j.contains("collides")) {
    if (r.list("undecided").empty())
      r.fail("/collides", "collides is null (unknown) but nothing is undecided: a complete answer says true or false");
    ans["collides"] = false;
  }
  if (r.j.contains("s_intervals")) {  // independent motions
    // A run left undecided may have proved one side's intervals and none of
    // the other's: an empty list next to collides = true is then not the
    // contradiction it is in a stored answer (scene-format.md), so it is left
    // out rather than refused.
    const bool undecided = !r.list("undecided").empty();
    for (const char* k : {"s_intervals", "t_intervals"})
      if (!(undecided && r.list(k).empty())) ans[k] = r.list(k);
  } else {
    for (const char* k : {"intervals", "contacts", "contact_intervals"}) ans[k] = r.list(k);
    ans["first_contact"] = r.j.contains("first_contact") ? r.j["first_contact"] : json(nullptr);
  }
  Answer answer = answer_from_json(ans, r.label, "");
  const json und = r.list("undecided");
  for (std::size_t i = 0; i < und.size(); ++i)
    answer.undecided.push_back(instant_from_json(und[i], r.label, "/undecided/" + std::to_string(i)));
  const json pts = r.list("contact_points");
  for (std::size_t i = 0; i < pts.size(); ++i) {
    ContactPoint p;
    if (!pts[i].is_array()) r.fail("/contact_points/" + std::to_string(i), "expected an array of decimal strings");
    for (const auto& x : pts[i]) {
      if (!x.is_string()) r.fail("/contact_points/" + std::to_string(i), "expected an array of decimal strings");
      p.x.push_back(x.get<std::string>());
    }
    answer.contact_points.push_back(p);
  }
  const json nrm = r.list("contact_normals");
  for (std::size_t i = 0; i < nrm.size() && i < answer.contact_points.size(); ++i) {
    if (!nrm[i].is_array()) r.fail("/contact_normals/" + std::to_string(i), "expected an array of decimal strings");
    for (const auto& x : nrm[i]) {
      if (!x.is_string()) r.fail("/contact_normals/" + std::to_string(i), "expected an array of decimal strings");
      answer.contact_points[i].normal.push_back(x.get<std::string>());
    }
  }
  return answer;
}

// The critical instants and the cells between them.
void read_timeline(const ReportFields& r, Solution& s) {
  const json crit = r.list("critical_instants");
  for (std::size_t i = 0; i < crit.size(); ++i) {
    const std::string place = "/critical_instants/" + std::to_string(i);
    if (!crit[i].is_object() || !crit[i].contains("t")) r.fail(place, "expected {\"t\", \"status\", \"multiplicity\"}");
    s.critical.push_back({instant_from_json(crit[i]["t"], r.label, place + "/t"),
                          r.status(crit[i].value("status", json()), place + "/status"),
                          crit[i].value("multiplicity", 0)});
  }
  const json cells = r.list("cells");
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::string place = "/cells/" + std::to_string(i);
    if (!cells[i].is_object() || !cells[i].contains("sample")) r.fail(place, "expected {\"sample\", \"status\"}");
    s.cells.push_back({instant_from_json(cells[i]["sample"], r.label, place + "/sample"),
                       r.status(cells[i].value("status", json()), place + "/status")});
  }
}

// A bracketed instant's value is the double nearest its bracket's mid-point
// (kernel/answer.hpp bracketed_instant), not its approx, which carries only
// the digits the bracket supports: a Solution read back equals the one written.
void values_from_brackets(Solution& s) {
  auto from_bracket = [](Instant& i) {
    if (i.certified()) i.value = nearest_double(mpq_class((*i.lo + *i.hi) / 2));
  };
  for (auto& [a, b] : s.answer.intervals) from_bracket(a), from_bracket(b);
  for (auto& [a, b] : s.answer.contact_intervals) from_bracket(a), from_bracket(b);
  for (auto& [a, b] : s.answer.s_intervals) from_bracket(a), from_bracket(b);
  for (auto& [a, b] : s.answer.t_intervals) from_bracket(a), from_bracket(b);
  if (s.answer.first_contact) from_bracket(*s.answer.first_contact);
  for (auto& c : s.answer.contacts) from_bracket(c);
  for (auto& c : s.critical) from_bracket(c.t);
  for (auto& c : s.cells) from_bracket(c.sample);
}

}  // namespace

Solution solution_from_json(const json& j, const std::string& label) {
  const ReportFields r{j, label};
  if (!j.is_object()) r.fail("", "expected a solution report (a JSON object)");
  Solution s;
  s.answer = answer_of_report(r);
  s.scene = r.text("scene");
  s.file = r.text("file");
  s.dim = int(r.number("dim", 2));
  try {
    s.arith = parse_arithmetic(r.text("arith", "exact"));
    s.input = parse_input_mode(r.text("input", "prepared"));
  } catch (const std::invalid_argument& e) {
    r.fail("", e.what());
  }
  s.guard = r.text("guard");
  if (!s.guard.empty() && s.guard != "none" && s.guard != "bound")
    r.fail("/guard", "expected \"none\", \"bound\" or null, got \"" + s.guard + "\"");
  s.basis = r.text("basis");
  s.method = r.text("method");
  for (Variant v : {Variant::answer, Variant::collides, Variant::first_contact, Variant::all_contacts})
    if (r.text("variant", "answer") == variant_name(v)) s.variant = v;
  s.certified = j.value("certified", false);
  s.sampled = j.value("sampled", false);
  if (j.contains("status_at_0")) s.status_at_0 = r.status(j["status_at_0"], "/status_at_0");
  s.projection = r.text("projection", "discriminant");
  s.projection_degree = int(r.number("projection_degree", -1));
  s.projection_identically_zero = j.value("projection_identically_zero", false);
  read_timeline(r, s);
  values_from_brackets(s);
  for (const auto& reason : r.list("undecided_reasons")) {
    if (!reason.is_string()) r.fail("/undecided_reasons", "expected strings");
    s.undecided_reasons.push_back(reason.get<std::string>());
  }
  if (j.contains("work") && j["work"].is_object())
    for (const auto& [k, v] : j["work"].items())
      if (v.is_number_integer()) s.work.push_back({k, v.get<long>()});
  s.time_ms = r.number("time_ms", 0);
  s.setup_ms = r.number("setup_ms", 0);
  s.decided_in = r.text("decided_in");
  for (const auto& e : r.list("escalations"))
    if (e.is_object())
      s.escalations.push_back({e.value("rung", std::string()), e.value("reason", std::string()),
                               e.value("spent_ms", 0.0), e.value("budget_ms", 0.0)});
  return s;
}

std::string summary_text(const Solution& s) {
  std::ostringstream o;
  auto inst = [](const Instant& i) {
    std::string t = i.approx;
    if (i.certified()) {
      if (*i.lo == *i.hi)
        t += " (exactly " + i.lo->get_str() + ")";
      else
        t += " in [" + i.lo->get_str() + ", " + i.hi->get_str() + "]";
    }
    return t;
  };
  if (s.answer.independent) {  // independent motions: A(s), B(t) (scene-format.md, "Independent motions")
    o << "scene " << s.scene << " (" << s.dim << "D, independent motions A(s), B(t)), arithmetic " << s.arith.name()
      << (s.certified ? ", certified" : ", not certified") << ", method " << s.method
      << (s.guard == "none"    ? ", as published (no guard)"
          : s.guard == "bound" ? ", guarded"
                               : "")
      << "\n";
    o << "  collides: " << claim_text(s.answer) << "\n";
    for (const auto& [a, b] : s.answer.s_intervals)
      o << "  s-interval (A's path inside B's swept volume): [" << inst(a) << ", " << inst(b) << "]\n";
    for (const auto& [a, b] : s.answer.t_intervals)
      o << "  t-interval (B's path inside A's swept volume): [" << inst(a) << ", " << inst(b) << "]\n";
    for (const auto& u : s.answer.undecided) o << "  undecided near " << u.approx << "\n";
    if (!s.answer.undecided.empty())
      for (const auto& why : s.undecided_reasons) o << "  undecided because: " << why << "\n";
    char tb[64];
    std::snprintf(tb, sizeof tb, "%.3f", s.time_ms);
    o << "  time: " << tb << " ms\n";
    return o.str();
  }
  const bool two_d_partial = s.dim == 2 && s.variant != Variant::answer;  // intervals not computed
  o << "scene " << s.scene << " (" << s.dim << "D), arithmetic " << s.arith.name()
    << (s.certified ? ", certified" : ", not certified") << (s.basis != "exact" ? ", basis " + s.basis : std::string())
    << (s.input == InputMode::rounded ? ", input rounded" : "")
    << (s.guard == "none"    ? ", as published (no guard)"
        : s.guard == "bound" ? ", guarded"
                             : "")
    << "\n";
  // Say what the polynomial is: Δ, psc_k, or for the Bézier method F(u,t).
  std::string poly = s.projection == "bezier" ? "F(u,t) of degree " + std::to_string(s.projection_degree) + " in t"
                     : s.method == "cd-disc-cycloidal" ? s.projection + " (cycloidal: not a polynomial)"
                     : s.projection_degree < 0 ? "no polynomial in t (method " + s.method + " tests instants only)"
                                               : s.projection + " degree " + std::to_string(s.projection_degree);
  o << "  status at t = 0: " << to_string(s.status_at_0) << "; " << poly
    << (!s.projection_identically_zero       ? ""
        : s.projection.rfind("psc_", 0) == 0 ? " (the discriminant vanishes identically)"
                                             : " (identically zero)")
    << ", " << s.critical.size()
    << (s.projection_degree < 0 && s.projection != "bezier" && s.method != "cd-disc-cycloidal"
            ? " change(s) of status between samples\n"
            : " root(s) in [0, 1]\n");
  o << "  collides: " << claim_text(s.answer) << "\n";
  if (!two_d_partial)
    for (const auto& [a, b] : s.answer.intervals) {
      const bool touch = instant_to_json(a) == instant_to_json(b);
      o << "  collision interval: [" << inst(a) << ", " << inst(b) << "]" << (touch ? "  (isolated touch)" : "")
        << "\n";
    }
  if (s.answer.first_contact) o << "  first contact: " << inst(*s.answer.first_contact) << "\n";
  if (!(s.dim == 2 && (s.variant == Variant::collides || s.variant == Variant::first_contact)))
    for (std::size_t i = 0; i < s.answer.contacts.size(); ++i) {
      o << "  external contact: " << inst(s.answer.contacts[i]);
      auto tuple = [](const std::vector<std::string>& v) {
        std::string r = "(";
        for (std::size_t k = 0; k < v.size(); ++k) r += (k ? ", " : "") + v[k];
        return r + ")";
      };
      if (i < s.answer.contact_points.size() && !s.answer.contact_points[i].x.empty()) {
        o << " at " << tuple(s.answer.contact_points[i].x);
        if (!s.answer.contact_points[i].normal.empty()) o << ", normal " << tuple(s.answer.contact_points[i].normal);
      }
      o << "\n";
    }
  for (const auto& [a, b] : s.answer.contact_intervals)
    o << "  continuous touching (contact interval): [" << inst(a) << ", " << inst(b) << "]\n";
  for (const auto& u : s.answer.undecided) o << "  undecided near t = " << u.approx << "\n";
  if (!s.answer.undecided.empty())
    for (const auto& why : s.undecided_reasons) o << "  undecided because: " << why << "\n";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", s.time_ms);
  o << "  time: " << buf << " ms\n";
  return o.str();
}

}  // namespace eccd
