// `eccd solve`: dispatch to the one templated CD-DISC pipeline in the chosen
// arithmetic, and present its result.
#include "api/solve.hpp"

#include "exact/cd_disc_exact.hpp"
#include "certified/certified_policy.hpp"
#include "number/mpfi_interval.hpp"
#include "floating/ccd3_baselines.hpp"
#include "floating/bezier_ccd.hpp"
#include "kernel/ccd_projection.hpp"
#include "floating/cd_disc_floating.hpp"
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "floating/rounded_input.hpp"
#include "number/running_error.hpp"
#include "kernel/budget.hpp"
#include "io/scene_reader.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace eccd {

std::string Arithmetic::name() const {
  switch (kind) {
    case Double: return "double";
    case Mpfr: return "mpfr:" + std::to_string(bits);
    case Certified: {
      if (rungs == std::vector<int>{256}) return "certified";
      std::string n = "certified:";
      for (std::size_t i = 0; i < rungs.size(); ++i) n += (i ? "," : "") + std::to_string(rungs[i]);
      return rungs.empty() ? n + "none" : n;
    }
    default: return "exact";
  }
}

Arithmetic parse_arithmetic(const std::string& text) {
  Arithmetic a;
  if (text == "double") { a.kind = Arithmetic::Double; a.bits = 53; return a; }
  if (text == "exact") { a.kind = Arithmetic::Exact; return a; }
  if (text == "certified") { a.kind = Arithmetic::Certified; a.bits = 53; a.rungs = {256}; return a; }
  if (text.rfind("certified:", 0) == 0) {
    a.kind = Arithmetic::Certified;
    a.bits = 53;
    std::string list = text.substr(10);
    if (list == "none") return a;
    std::size_t at = 0;
    while (true) {
      std::size_t comma = list.find(',', at);
      std::string b = list.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
      if (b.empty() || b.find_first_not_of("0123456789") != std::string::npos || b.size() > 6)
        throw std::invalid_argument("--arith " + text + ": expected certified:BITS[,BITS...] (MPFI rungs) or certified:none");
      int bits = std::stoi(b);
      if (bits < 54 || bits > 65536 || (!a.rungs.empty() && bits <= a.rungs.back()))
        throw std::invalid_argument("--arith " + text + ": MPFI rungs must increase, each between 54 and 65536 bits");
      a.rungs.push_back(bits);
      if (comma == std::string::npos) break;
      at = comma + 1;
    }
    return a;
  }
  if (text.rfind("mpfr:", 0) == 0) {
    std::string b = text.substr(5);
    if (b.empty() || b.find_first_not_of("0123456789") != std::string::npos || b.size() > 6)
      throw std::invalid_argument("--arith " + text + ": expected mpfr:BITS with BITS a whole number");
    a.kind = Arithmetic::Mpfr;
    a.bits = std::stoi(b);
    if (a.bits < 53 || a.bits > 65536)
      throw std::invalid_argument("--arith " + text + ": MPFR precision must be between 53 and 65536 bits");
    return a;
  }
  throw std::invalid_argument("--arith " + text + ": expected double, mpfr:BITS, exact or certified");
}

namespace {

const char* variant_name(Variant v) {
  switch (v) {
    case Variant::collides: return "collides";
    case Variant::first_contact: return "first-contact";
    case Variant::all_contacts: return "all-contacts";
    default: return "answer";
  }
}

nlohmann::json instant_json(const Instant& i) {
  Answer a;
  a.contacts.push_back(i);
  return answer_to_json(a)["contacts"][0];
}

template <class T>
nlohmann::json report_json(const PipelineResult<T>& r, int dim = 2) {
  nlohmann::json j = answer_to_json(r.answer);
  j["variant"] = variant_name(r.variant);
  if (dim == 3) {
    // 3D first-contact mode (001 section 4) still reports the first interval
    // and the contacts up to its end.
  } else if (r.variant == Variant::collides || r.variant == Variant::first_contact) {
    j["intervals"] = nullptr;
    j["contacts"] = nullptr;
  } else if (r.variant == Variant::all_contacts) {
    j["intervals"] = nullptr;
  }
  nlohmann::json pts = nlohmann::json::array();
  for (const auto& p : r.answer.contact_points) pts.push_back(p.x);
  j["contact_points"] = pts;
  nlohmann::json ci = nlohmann::json::array();
  for (const auto& [a, b] : r.answer.contact_intervals) ci.push_back({instant_json(a), instant_json(b)});
  j["contact_intervals"] = ci;
  nlohmann::json und = nlohmann::json::array();
  for (const auto& u : r.answer.undecided) und.push_back(instant_json(u));
  j["undecided"] = und;
  j["projection_degree"] = r.projection_degree;
  j["projection"] = r.projection_index == 0 ? std::string("discriminant") : "psc_" + std::to_string(r.projection_index);
  j["projection_identically_zero"] = r.projection_identically_zero;
  j["status_at_0"] = to_string(r.status_at_0);
  nlohmann::json crit = nlohmann::json::array();
  for (const auto& c : r.critical)
    crit.push_back({{"t", instant_json(c.t)}, {"status", to_string(c.status)}, {"multiplicity", c.multiplicity}});
  j["critical_instants"] = crit;
  j["undecided_reasons"] = r.undecided_reasons;
  nlohmann::json cells = nlohmann::json::array();
  for (const auto& c : r.cells) cells.push_back({{"sample", instant_json(c.sample)}, {"status", to_string(c.status)}});
  j["cells"] = cells;
  nlohmann::json counters = nlohmann::json::object();
  for (const auto& [k, v] : r.counters) counters[k] = v;
  j["work"] = counters;
  j["time_ms"] = r.seconds * 1e3;
  return j;
}

// The pair a floating run starts from: the scene's numbers rounded to T and
// prepared in T (input mode rounded, floating/rounded_input.hpp), or the
// exactly prepared pair rounded (input mode prepared). trouble: "" or why a
// value is not finite.
template <class T, int N>
MovingPair<T, N> floating_pair(const Scene& scene, const SolveOptions& opt, const T& like, std::string& trouble) {
  trouble.clear();
  if (opt.input == InputMode::prepared) return to_arithmetic<T, N>(prepare_pair<N>(scene), like);
  return round_pair<T, N>(scene, like, trouble);
}

// A floating run whose deadline passed inside a stage that cannot stop half-way
// (a polynomial product, kernel/polynomial.hpp, throws BudgetExhausted) ends
// like every other floating stop: [0, 1] undecided, with the reason.
template <class T>
nlohmann::json undecided_run(const std::string& reason, int dim, Variant v) {
  PipelineResult<T> r;
  r.variant = v;
  undecided_everywhere(r, Instant{"0", std::nullopt, std::nullopt}, Instant{"1", std::nullopt, std::nullopt}, reason);
  nlohmann::json j = report_json(r, dim);
  j["certified"] = false;
  return j;
}

template <class T>
nlohmann::json run_floating(const Scene& scene, const SolveOptions& opt, const T& like) try {
  FloatingPolicy<T> pol(parse_basis(opt.basis), opt.arith.bits, like);
  std::string trouble;
  MovingPair<T, 3> m = floating_pair<T, 3>(scene, opt, like, trouble);
  PipelineResult<T> r;
  if (!trouble.empty()) {
    r.variant = Variant(opt.variant);
    undecided_everywhere(r, pol.instant_at(scalar_traits<T>::from_rational(0, like)),
                         pol.instant_at(scalar_traits<T>::from_rational(1, like)), trouble);
  } else {
    r = cd_disc(m, pol, Variant(opt.variant));
  }
  nlohmann::json j = report_json(r);
  j["basis"] = opt.basis;
  j["certified"] = false;
  return j;
} catch (const BudgetExhausted& e) {
  nlohmann::json j = undecided_run<T>(e.what(), 2, Variant(opt.variant));
  j["basis"] = opt.basis;
  return j;
}

// "sampling:N" / "marching:N" -> N (0 if the method has another name).
int method_grid(const std::string& method, const std::string& name) {
  if (method.rfind(name + ":", 0) != 0) return 0;
  std::string n = method.substr(name.size() + 1);
  if (n.empty() || n.size() > 6 || n.find_first_not_of("0123456789") != std::string::npos || std::stoi(n) < 1)
    throw std::invalid_argument("--method " + method + ": expected " + name + ":N with N a whole number from 1 to 999999");
  return std::stoi(n);
}

template <class T>
nlohmann::json run_floating_3d_stages(const Scene& scene, const SolveOptions& opt, const T& like);

template <class T>
nlohmann::json run_floating_3d(const Scene& scene, const SolveOptions& opt, const T& like) {
  if (parse_basis(opt.basis) == Basis::scaled_bernstein && opt.method != "projection")
    throw std::invalid_argument("--basis scaled-bernstein applies to --method projection only in 3D");
  check_method(opt.method);
  try {
    return run_floating_3d_stages(scene, opt, like);
  } catch (const BudgetExhausted& e) {
    nlohmann::json j = undecided_run<T>(e.what(), 3, Variant::answer);
    j["basis"] = opt.basis;
    j["method"] = opt.method;
    return j;
  }
}

template <class T>
nlohmann::json run_floating_3d_stages(const Scene& scene, const SolveOptions& opt, const T& like) {
  auto start = std::chrono::steady_clock::now();
  Basis basis = parse_basis(opt.basis);
  std::string trouble;
  std::optional<PreparedPair<4>> p;
  if (opt.input == InputMode::prepared) p = prepare_pair<4>(scene);
  MovingPair<T, 4> m = p ? to_arithmetic<T, 4>(*p, like) : round_pair<T, 4>(scene, like, trouble);
  // g_0..g_4: products in Bernstein form from N(t) in Bernstein form, or in power form.
  std::vector<Bern<T>> g;
  if (trouble.empty() && opt.method != "projection")
    g = p ? characteristic_bernstein<T, 4>(*p, basis == Basis::power, like) : characteristic_bernstein_of<T, 4>(m, basis == Basis::power);
  double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!trouble.empty()) {
    PipelineResult<T> r;
    undecided_everywhere(r, Instant{"0", std::nullopt, std::nullopt}, Instant{"1", std::nullopt, std::nullopt}, trouble);
    check_method(opt.method);
    nlohmann::json j = report_json(r, 3);
    j["setup_ms"] = setup * 1e3;
    j["basis"] = opt.basis;
    j["method"] = opt.method;
    j["certified"] = false;
    return j;
  }
  nlohmann::json j;
  if (opt.method == "projection") {
    FloatingPolicy<T> pol(basis, opt.arith.bits, like);
    j = report_json(ccd_projection(m, pol, opt.first_contact), 3);
    setup = 0;  // ccd_projection builds its own coefficients and times them
  } else if (opt.method == "bezier") {
    BezierOptions bo;
    bo.first_contact_only = opt.first_contact;
    if (opt.arith.kind == Arithmetic::Mpfr) bo.max_subdivisions = 2000;  // MPFR steps cost 10-100x double's
    j = report_json(ccd_bezier(g, like, opt.arith.bits, bo), 3);
  } else if (int n = method_grid(opt.method, "sampling")) {
    j = report_json(ccd_sampling(g, like, n, opt.first_contact), 3);
    j["sampled"] = true;  // a grid of instants: nothing is claimed about the gaps between them
  } else if (int n = method_grid(opt.method, "marching")) {
    j = report_json(ccd_marching(g, like, n, opt.first_contact), 3);
    j["sampled"] = true;
  } else {
    throw std::invalid_argument("--method " + opt.method + ": expected bezier, projection, sampling:N or marching:N");
  }
  j["setup_ms"] = setup * 1e3;
  j["time_ms"] = j["time_ms"].get<double>() + setup * 1e3;
  j["basis"] = opt.basis;
  j["method"] = opt.method;
  j["certified"] = false;
  return j;
}

// The exact pipeline's JSON for a prepared pair (2D: cd_disc, 3D: projection).
template <int N>
nlohmann::json run_exact(const PreparedPair<N>& p, const SolveOptions& opt) {
  ExactPolicy pol;
  nlohmann::json j = report_json(projection_pipeline(to_arithmetic<Rational, N>(p, Rational(1)), pol, Variant(opt.variant), opt.first_contact), N - 1);
  if (N == 4) j["method"] = "projection";
  j["basis"] = "exact";
  j["certified"] = true;
  return j;
}

// --arith certified: the same pipeline in interval arithmetic, up a ladder of
// rungs — intervals of doubles, then MPFI intervals at each precision of
// opt.arith.rungs — and, where every rung leaves a sign uncertain (Escalate,
// or an undecided instant), the exact pipeline. The JSON names the rung that
// decided (`decided_in`) and why each lower rung gave up (`escalations`).
template <class T, int N>
std::optional<nlohmann::json> try_certified_rung(const PreparedPair<N>& p, const SolveOptions& opt, const T& like,
                                                 int max_depth, std::string& reason, bool& multiple_root) {
  try {
    CertifiedPolicy<T> pol(like);
    pol.max_depth = max_depth;
    PipelineResult<T> r = projection_pipeline(to_arithmetic<T, N>(p, like), pol, Variant(opt.variant), opt.first_contact);
    if (r.answer.undecided.empty()) {
      nlohmann::json j = report_json(r, N - 1);
      j["work"]["interval_pieces"] = pol.pieces;
      return j;
    }
    reason = std::to_string(r.answer.undecided.size()) + " instant(s) undecided";
  } catch (const Escalate& e) {
    reason = e.what();
    multiple_root = e.kind == Escalate::multiple_root;
  }
  return std::nullopt;
}

template <int N>
nlohmann::json run_certified(const PreparedPair<N>& p, const SolveOptions& opt) {
  auto start = std::chrono::steady_clock::now();
  nlohmann::json escalations = nlohmann::json::array();
  auto finish = [&](nlohmann::json j, const std::string& rung) {
    j["escalated"] = !escalations.empty();
    for (const auto& e : escalations)  // the last rung that was tried, and why it gave up
      if (e["reason"].get<std::string>().rfind("skipped", 0) != 0) j["escalation_reason"] = e["rung"].get<std::string>() + ": " + e["reason"].get<std::string>();
    j["escalations"] = escalations;
    j["decided_in"] = rung;
    j["certified"] = true;
    j["time_ms"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
    return j;
  };
  auto interval_json = [&](nlohmann::json j) {
    j["basis"] = "bernstein";
    if (N == 4) j["method"] = "projection";
    return j;
  };
  std::string reason;
  bool multiple_root = false;
  if (auto j = try_certified_rung<Interval, N>(p, opt, Interval(0), 48, reason, multiple_root))
    return finish(interval_json(*j), "interval");
  escalations.push_back({{"rung", "interval"}, {"reason", reason}});
  for (int bits : opt.arith.rungs) {
    if (multiple_root) {  // no precision separates a multiple root: straight to exact
      escalations.push_back({{"rung", "mpfi:" + std::to_string(bits)}, {"reason", "skipped: the rung below met a multiple root"}});
      break;
    }
    // Deeper subdivision at higher precision (roots closer than 2^-48 can be
    // told apart when the coefficients are known to `bits` bits), but not so
    // deep that a true multiple root (every touch scene) costs much before
    // the exact rung: 2^-64 at the default 256 bits.
    int depth = std::clamp(bits / 4, 48, 256);
    std::string rung = "mpfi:" + std::to_string(bits);
    if (auto j = try_certified_rung<MpfiInterval, N>(p, opt, MpfiInterval(Rational(0), bits), depth, reason, multiple_root))
      return finish(interval_json(*j), rung);
    escalations.push_back({{"rung", rung}, {"reason", reason}});
  }
  return finish(run_exact<N>(p, opt), "exact");
}

nlohmann::json solve_3d(const Scene& scene, const SolveOptions& opt) {
  switch (opt.arith.kind) {
    case Arithmetic::Double: return run_floating_3d<Bounded<double>>(scene, opt, Bounded<double>(1.0, 0));
    case Arithmetic::Mpfr:
      return run_floating_3d<Bounded<eccd::Mpfr>>(scene, opt, Bounded<eccd::Mpfr>(eccd::Mpfr(mpq_class(1), opt.arith.bits), 0));
    case Arithmetic::Certified: return run_certified<4>(prepare_pair<4>(scene), opt);
    default: return run_exact<4>(prepare_pair<4>(scene), opt);
  }
}

nlohmann::json solve_2d(const Scene& scene, const SolveOptions& opt);

}  // namespace

void check_method(const std::string& method) {
  if (method == "bezier" || method == "projection") return;
  if (method_grid(method, "sampling") || method_grid(method, "marching")) return;
  throw std::invalid_argument("--method " + method + ": expected bezier, projection, sampling:N or marching:N");
}

nlohmann::json solve_scene(const Scene& scene, const SolveOptions& opt) {
  nlohmann::json j;
  // Floating runs always end: each method has work bounds, and a run that the
  // caller did not bound otherwise gets this deadline (the earlier of the two
  // deadlines counts, kernel/budget.hpp); what is left then is undecided.
  const bool floating_run = opt.arith.kind == Arithmetic::Double || opt.arith.kind == Arithmetic::Mpfr;
  ScopedDeadline default_budget(floating_run ? kDefaultFloatingSeconds : 0);
  if (scene.dim == 3) {
    j = solve_3d(scene, opt);
  } else {
    j = solve_2d(scene, opt);
  }
  nlohmann::json out;
  out["scene"] = scene.name;
  out["file"] = scene.path;
  out["dim"] = scene.dim;
  out["arith"] = opt.arith.name();
  out["precision_bits"] = opt.arith.bits;
  const bool floating = opt.arith.kind == Arithmetic::Double || opt.arith.kind == Arithmetic::Mpfr;
  out["input"] = to_string(floating ? opt.input : InputMode::prepared);
  for (auto& [k, v] : j.items()) out[k] = v;
  return out;
}

namespace {
nlohmann::json solve_2d(const Scene& scene, const SolveOptions& opt) {
  if (opt.variant < 0 || opt.variant > 3) throw std::invalid_argument("--variant must be 0, 1, 2 or 3");
  bool cyclo = std::holds_alternative<CycloidalMotion>(scene.a.motion) || std::holds_alternative<CycloidalMotion>(scene.b.motion);
  if (cyclo && (opt.arith.kind == Arithmetic::Double || opt.arith.kind == Arithmetic::Mpfr))
    throw std::invalid_argument("cycloidal motions are not solved yet by the floating pipelines (they are not rational)");
  nlohmann::json j;
  switch (opt.arith.kind) {  // prepare_pair refuses cycloidal motions for exact arithmetic
    case Arithmetic::Double: j = run_floating<Bounded<double>>(scene, opt, Bounded<double>(1.0, 0)); break;
    case Arithmetic::Mpfr:
      j = run_floating<Bounded<eccd::Mpfr>>(scene, opt, Bounded<eccd::Mpfr>(eccd::Mpfr(mpq_class(1), opt.arith.bits), 0));
      break;
    case Arithmetic::Exact: j = run_exact<3>(prepare_pair<3>(scene), opt); break;
    case Arithmetic::Certified: j = run_certified<3>(prepare_pair<3>(scene), opt); break;
  }
  j["method"] = "cd-disc";
  return j;
}
}  // namespace

nlohmann::ordered_json stored_answer_of(const nlohmann::json& report) {
  nlohmann::ordered_json ans;
  for (const char* k : {"collides", "intervals", "first_contact", "contacts"}) ans[k] = nlohmann::ordered_json::parse(report.at(k).dump());
  // Continuous touching (docs/answer-format.md): stored only when there is some, so older answers keep their keys.
  if (report.contains("contact_intervals") && report["contact_intervals"].is_array() && !report["contact_intervals"].empty())
    ans["contact_intervals"] = nlohmann::ordered_json::parse(report["contact_intervals"].dump());
  return ans;
}

std::string summary_text(const nlohmann::json& r) {
  std::ostringstream o;
  auto inst = [](const nlohmann::json& i) {
    std::string s = i["approx"].get<std::string>();
    if (!i["lo"].is_null()) {
      if (i["lo"] == i["hi"]) s += " (exactly " + i["lo"].get<std::string>() + ")";
      else s += " in [" + i["lo"].get<std::string>() + ", " + i["hi"].get<std::string>() + "]";
    }
    return s;
  };
  o << "scene " << r["scene"].get<std::string>() << " (" << r["dim"].get<int>() << "D), arithmetic "
    << r["arith"].get<std::string>() << (r["certified"].get<bool>() ? ", certified" : ", not certified")
    << (r["basis"] != "exact" ? ", basis " + r["basis"].get<std::string>() : std::string())
    << (r.contains("input") && r["input"] == "rounded" ? ", input rounded" : "") << "\n";
  o << "  status at t = 0: " << r["status_at_0"].get<std::string>() << "; discriminant degree "
    << r["projection_degree"].get<int>() << (r["projection_identically_zero"].get<bool>() ? " (identically zero)" : "") << ", "
    << r["critical_instants"].size() << " root(s) in [0, 1]\n";
  o << "  collides: " << (r["collides"].get<bool>() ? "yes" : "no") << "\n";
  if (r["intervals"].is_array())
    for (const auto& iv : r["intervals"])
      o << "  collision interval: [" << inst(iv[0]) << ", " << inst(iv[1]) << "]"
        << (iv[0] == iv[1] ? "  (isolated touch)" : "") << "\n";
  if (!r["first_contact"].is_null()) o << "  first contact: " << inst(r["first_contact"]) << "\n";
  if (r["contacts"].is_array())
    for (std::size_t i = 0; i < r["contacts"].size(); ++i) {
      o << "  external contact: " << inst(r["contacts"][i]);
      if (i < r["contact_points"].size() && r["contact_points"][i].size() == 2)
        o << " at (" << r["contact_points"][i][0].get<std::string>() << ", " << r["contact_points"][i][1].get<std::string>() << ")";
      o << "\n";
    }
  for (const auto& iv : r["contact_intervals"])
    o << "  continuous touching (contact interval): [" << inst(iv[0]) << ", " << inst(iv[1]) << "]\n";
  for (const auto& u : r["undecided"]) o << "  undecided near t = " << u["approx"].get<std::string>() << "\n";
  if (r.contains("undecided_reasons") && !r["undecided"].empty())
    for (const auto& why : r["undecided_reasons"]) o << "  undecided because: " << why.get<std::string>() << "\n";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", r["time_ms"].get<double>());
  o << "  time: " << buf << " ms\n";
  return o.str();
}

}  // namespace eccd
