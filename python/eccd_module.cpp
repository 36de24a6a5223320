// The Python module eccd: the typed C++ API (include/eccd/eccd.hpp) for
// Python, with pybind11. Nothing is computed here: every function calls the
// API and converts its types.
//
//   import eccd
//   s = eccd.read_scene("cases/paper003/example2.json")   # or eccd.scene_from_dict(d), eccd.scene_from_text(t)
//   r = eccd.solve(s, arith="exact")                        # "double", "mpfr:128", "exact", "certified", ...
//   r.collides, r.intervals, r.first_contact, r.contacts    # instants: .approx (float), .lo / .hi (Fraction or None)
//   eccd.animate("cases/animations/swarm-2d.json", arith="certified")   # the animation answer, a dict
//   eccd.separate(s, "1/3")                                 # a separating plane at t = 1/3, a dict
//
// Types: an Instant's bracket [lo, hi] is exact (fractions.Fraction, made
// from the rational's text, never through a float); .approx is the
// approximation as a float, for display only. Errors: a bad scene raises
// eccd.SceneError (a ValueError) whose message names the file, the place and
// what is wrong; a request the pipelines refuse raises ValueError.
#include "eccd/eccd.hpp"
#include "api/animate.hpp"          // eccd.animate (issue 17 point 4)
#include "api/separate_json.hpp"    // eccd.separate's dict: the same builder as `eccd separate --json`
#include "io/animation_reader.hpp"
#include "io/scene_reader.hpp"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>

#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

py::object fraction(const std::optional<mpq_class>& q) {
  if (!q) return py::none();
  static py::object Fraction = py::module_::import("fractions").attr("Fraction");
  return Fraction(q->get_str());
}

std::string instant_repr(const eccd::Instant& i) {
  std::string r = "Instant(" + i.approx;
  if (i.certified()) r += ", [" + i.lo->get_str() + ", " + i.hi->get_str() + "]";
  return r + ")";
}

py::list instant_pairs(const std::vector<std::pair<eccd::Instant, eccd::Instant>>& v) {
  py::list out;
  for (const auto& [a, b] : v) out.append(py::make_tuple(a, b));
  return out;
}

// The answer's properties, shared by Answer (a scene's stored answer) and
// Solution (what solve returns); Get maps the bound object to its Answer.
std::string answer_repr(const std::string& head, const eccd::Answer& a) {
  std::string r = head + "collides=" + (a.collides ? "True" : "False") + ", intervals=[";
  for (std::size_t i = 0; i < a.intervals.size(); ++i)
    r += (i ? ", (" : "(") + instant_repr(a.intervals[i].first) + ", " + instant_repr(a.intervals[i].second) + ")";
  r += "]";
  if (!a.contact_intervals.empty()) r += ", contact_intervals=" + std::to_string(a.contact_intervals.size());
  if (!a.undecided.empty()) r += ", undecided=" + std::to_string(a.undecided.size());
  return r + ")";
}

template <class C, class Get>
void answer_properties(py::class_<C>& c, Get get) {
  c.def_property_readonly("collides", [get](const C& x) { return get(x).collides; })
      .def_property_readonly("intervals", [get](const C& x) { return instant_pairs(get(x).intervals); },
                             "the maximal collision intervals: a list of (Instant, Instant)")
      .def_property_readonly("first_contact", [get](const C& x) { return get(x).first_contact; }, "an Instant or None")
      .def_property_readonly("contacts", [get](const C& x) { return get(x).contacts; }, "the instants of external tangency")
      .def_property_readonly("contact_intervals", [get](const C& x) { return instant_pairs(get(x).contact_intervals); },
                             "intervals of continuous touching (docs/answer-format.md)")
      .def_property_readonly("undecided", [get](const C& x) { return get(x).undecided; },
                             "floating runs: the instants they could not classify");
}

eccd::SolveOptions solve_options(const std::string& arith, const std::string& basis, int variant, const std::string& method,
                                 bool first_contact, const std::string& input, double time_limit) {
  eccd::SolveOptions o;
  o.arith = eccd::parse_arithmetic(arith);
  o.basis = eccd::parse_basis(basis);
  if (variant < 0 || variant > 3) throw std::invalid_argument("variant must be 0 (answer), 1 (collides), 2 (first contact) or 3 (all contacts)");
  o.variant = static_cast<eccd::Variant>(variant);
  std::tie(o.method, o.grid) = eccd::parse_method(method);
  o.first_contact = first_contact;
  o.input = eccd::parse_input_mode(input);
  if (time_limit < 0) throw std::invalid_argument("time_limit must be >= 0 seconds");
  o.time_limit_s = time_limit;
  return o;
}

}  // namespace

PYBIND11_MODULE(eccd, m) {
  m.doc() = "eccd: exact continuous collision detection of moving ellipses and ellipsoids (double, MPFR, exact, certified)";
  py::register_exception<eccd::SceneError>(m, "SceneError", PyExc_ValueError);

  py::class_<eccd::Instant>(m, "Instant", "An instant of the answer: .approx (float), .lo / .hi (Fraction, where certified)")
      .def_property_readonly("approx", [](const eccd::Instant& i) { return i.value; }, "the approximation as a float (display only)")
      .def_property_readonly("approx_text", [](const eccd::Instant& i) { return i.approx; }, "the decimal approximation as text")
      .def_property_readonly("lo", [](const eccd::Instant& i) { return fraction(i.lo); }, "fractions.Fraction, or None if not certified")
      .def_property_readonly("hi", [](const eccd::Instant& i) { return fraction(i.hi); }, "fractions.Fraction, or None if not certified")
      .def_property_readonly("certified", &eccd::Instant::certified)
      .def("__float__", [](const eccd::Instant& i) { return i.value; })
      .def("__repr__", &instant_repr);

  py::class_<eccd::Answer> answer(m, "Answer", "A scene's stored answer");
  answer_properties(answer, [](const eccd::Answer& a) -> const eccd::Answer& { return a; });
  answer.def("__repr__", [](const eccd::Answer& a) { return answer_repr("Answer(", a); });

  py::class_<eccd::Scene>(m, "Scene", "A scene: two objects and their motions on t in [0, 1]")
      .def_readonly("name", &eccd::Scene::name)
      .def_readonly("path", &eccd::Scene::path)
      .def_readonly("note", &eccd::Scene::note)
      .def_readonly("dim", &eccd::Scene::dim)
      .def_readonly("answer", &eccd::Scene::answer, "the answer stored in the scene file, or None")
      .def("__repr__", [](const eccd::Scene& s) { return "Scene('" + s.name + "', dim=" + std::to_string(s.dim) + ")"; });

  py::class_<eccd::Solution> solution(m, "Solution", "What solve returns: the answer and the run's diagnostics");
  answer_properties(solution, [](const eccd::Solution& s) -> const eccd::Answer& { return s.answer; });
  solution.def_readonly("answer", &eccd::Solution::answer)
      .def_readonly("certified", &eccd::Solution::certified, "every instant carries a proved rational bracket")
      .def_property_readonly("decided", &eccd::Solution::decided, "nothing is undecided")
      .def_property_readonly("arith", [](const eccd::Solution& s) { return s.arith.name(); })
      .def_readonly("dim", &eccd::Solution::dim)
      .def_readonly("basis", &eccd::Solution::basis)
      .def_readonly("method", &eccd::Solution::method)
      .def_property_readonly("status_at_0", [](const eccd::Solution& s) { return std::string(eccd::to_string(s.status_at_0)); })
      .def_readonly("projection", &eccd::Solution::projection)
      .def_readonly("projection_degree", &eccd::Solution::projection_degree)
      .def_property_readonly("critical", [](const eccd::Solution& s) {
            py::list out;
            for (const auto& c : s.critical) out.append(py::make_tuple(c.t, std::string(eccd::to_string(c.status)), c.multiplicity));
            return out;
          }, "the critical instants: a list of (Instant, status, multiplicity)")
      .def_readonly("undecided_reasons", &eccd::Solution::undecided_reasons)
      .def_property_readonly("work", [](const eccd::Solution& s) {
            py::dict d;
            for (const auto& [k, v] : s.work) d[py::str(k)] = v;
            return d;
          })
      .def_readonly("time_ms", &eccd::Solution::time_ms)
      .def_readonly("setup_ms", &eccd::Solution::setup_ms)
      .def_readonly("decided_in", &eccd::Solution::decided_in, "certified runs: the rung that decided")
      .def_property_readonly("escalations", [](const eccd::Solution& s) {
            py::list out;
            for (const auto& e : s.escalations) out.append(py::make_tuple(e.rung, e.reason));
            return out;
          }, "certified runs: (rung, why it gave up) for each lower rung")
      .def("__repr__", [](const eccd::Solution& s) { return answer_repr("Solution(arith=" + s.arith.name() + ", ", s.answer); });

  m.def("read_scene", &eccd::read_scene, py::arg("path"), "Reads and validates a scene file (raises SceneError naming the file and the place)");
  m.def("scene_from_text", &eccd::scene_from_text, py::arg("text"), py::arg("label") = "<string>",
        "A scene from its JSON text (errors name the label)");
  m.def("scene_from_dict", [](const py::dict& d, const std::string& label) {
        const std::string text = py::module_::import("json").attr("dumps")(d).cast<std::string>();
        return eccd::scene_from_text(text, label);
      }, py::arg("scene"), py::arg("label") = "<dict>",
      "A scene from a dict in the scene format (numbers as strings, as in the files)");
  py::class_<eccd::Ellipse>(m, "Ellipse", "An ellipse: semi-axes (a, b) along its own x, y and a 3x3 homogeneous pose (its frame -> world)")
      .def(py::init([](const std::array<double, 2>& semi_axes, const std::array<std::array<double, 3>, 3>& pose) {
             return eccd::Ellipse{semi_axes, pose};
           }), py::arg("semi_axes"), py::arg("pose") = std::array<std::array<double, 3>, 3>{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}})
      .def_readwrite("semi_axes", &eccd::Ellipse::semi_axes)
      .def_readwrite("pose", &eccd::Ellipse::pose);
  py::class_<eccd::Ellipsoid>(m, "Ellipsoid", "An ellipsoid: semi-axes (a, b, c) and a 4x4 homogeneous pose (its frame -> world)")
      .def(py::init([](const std::array<double, 3>& semi_axes, const std::array<std::array<double, 4>, 4>& pose) {
             return eccd::Ellipsoid{semi_axes, pose};
           }), py::arg("semi_axes"), py::arg("pose") = std::array<std::array<double, 4>, 4>{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}})
      .def_readwrite("semi_axes", &eccd::Ellipsoid::semi_axes)
      .def_readwrite("pose", &eccd::Ellipsoid::pose);

  m.def("static_status", [](const eccd::Ellipse& a, const eccd::Ellipse& b, const std::string& arith) {
        return std::string(eccd::to_string(eccd::static_status(a, b, eccd::parse_arithmetic(arith))));
      }, py::arg("a"), py::arg("b"), py::arg("arith") = "double",
      "The status of two ellipses at their poses: 'separate', 'touching', 'overlapping' or (double) 'uncertain'; arith 'double' or 'exact'");
  m.def("static_status", [](const eccd::Ellipsoid& a, const eccd::Ellipsoid& b, const std::string& arith) {
        return std::string(eccd::to_string(eccd::static_status(a, b, eccd::parse_arithmetic(arith))));
      }, py::arg("a"), py::arg("b"), py::arg("arith") = "double",
      "The status of two ellipsoids at their poses (double: 001 Appendix A with its error bound; exact: proved)");
  m.def("status_at", [](const eccd::Scene& scene, const py::object& t, const std::string& arith) {
        static py::object Fraction = py::module_::import("fractions").attr("Fraction");
        const mpq_class q(py::str(Fraction(t)).cast<std::string>());  // exact: a float is taken at its exact binary value
        return std::string(eccd::to_string(eccd::status_at(scene, q, eccd::parse_arithmetic(arith))));
      }, py::arg("scene"), py::arg("t"), py::arg("arith") = "exact",
      "The status of the scene's objects at instant t (a Fraction, int, str like '1/3', or float), 0 <= t <= 1");

  py::register_exception<eccd::CertificationError>(m, "CertificationError", PyExc_RuntimeError);
  py::class_<eccd::Certificate>(m, "Certificate", "certify's result: the certificate (JSON text, eccd-certificate/2) and the Solution it proves")
      .def_readonly("text", &eccd::Certificate::text)
      .def_readonly("solution", &eccd::Certificate::solution)
      .def("__repr__", [](const eccd::Certificate& c) {
        return "Certificate(" + std::to_string(c.text.size()) + " characters, " + answer_repr("", c.solution.answer) + ")";
      });
  py::class_<eccd::CertificateCheck>(m, "CertificateCheck", "The checker's verdict: valid, the claims that hold, the first that does not")
      .def_readonly("valid", &eccd::CertificateCheck::valid)
      .def_readonly("checked", &eccd::CertificateCheck::checked)
      .def_readonly("failed_claim", &eccd::CertificateCheck::failed_claim)
      .def_readonly("reason", &eccd::CertificateCheck::reason)
      .def("__bool__", [](const eccd::CertificateCheck& c) { return c.valid; })
      .def("__repr__", [](const eccd::CertificateCheck& c) {
        return c.valid ? std::string("CertificateCheck(VALID)") : "CertificateCheck(REJECTED: " + c.failed_claim + ": " + c.reason + ")";
      });
  m.def("certify", &eccd::certify, py::arg("scene"), py::call_guard<py::gil_scoped_release>(),
        "Solves the scene exactly and writes a certificate of the answer (raises CertificationError if a claim cannot be made provable)");
  m.def("check_certificate", &eccd::check_certificate, py::arg("scene"), py::arg("text"), py::call_guard<py::gil_scoped_release>(),
        "Re-checks a certificate (JSON text) against its scene without the solver; text that is not JSON raises SceneError");

  // Judge any engine's answer against the certified one (api/judge.hpp).
  py::class_<eccd::Judgement>(m, "Judgement", "judge's result: .agrees, .verdict, .differences (in words), .counts, .certified (the Solution)")
      .def_readonly("agrees", &eccd::Judgement::agrees)
      .def_readonly("verdict", &eccd::Judgement::verdict)
      .def_property_readonly("differences", [](const eccd::Judgement& j) { return j.difference.differences; })
      .def_property_readonly("counts", [](const eccd::Judgement& j) {
            const eccd::AnswerDifference& d = j.difference;
            py::dict c;
            c["collides_differs"] = d.collides_differs;
            c["missed"] = d.missed;
            c["false"] = d.spurious;
            c["split"] = d.split;
            c["merged"] = d.merged;
            c["endpoints_off"] = d.endpoints_off;
            c["undecided"] = d.undecided;
            c["contact_intervals_differ"] = d.contact_intervals_differ;
            c["missed_contacts"] = d.missed_contacts;
            c["false_contacts"] = d.false_contacts;
            c["intervals"] = d.intervals;
            c["certified_intervals"] = d.reference_intervals;
            c["first_contact_error"] = d.first_contact_error ? py::object(py::float_(*d.first_contact_error)) : py::object(py::none());
            c["max_endpoint_error"] = d.max_endpoint_error ? py::object(py::float_(*d.max_endpoint_error)) : py::object(py::none());
            return c;
          }, "the counts of api/answer_difference.hpp (missed, false, endpoints_off, ...) as a dict")
      .def_readonly("certified", &eccd::Judgement::certified, "the certified Solution it was compared with")
      .def_readonly("certified_from", &eccd::Judgement::certified_from, "'exact pipeline' or 'stored answer'")
      .def("__bool__", [](const eccd::Judgement& j) { return j.agrees; })
      .def("__repr__", [](const eccd::Judgement& j) { return "Judgement(" + j.verdict + ")"; });
  m.def("answer_from_dict", [](const py::dict& d, const std::string& label) {
        const std::string text = py::module_::import("json").attr("dumps")(d).cast<std::string>();
        return eccd::answer_from_text(text, label).answer;
      }, py::arg("answer"), py::arg("label") = "<dict>",
      "An Answer from a dict in the scene format (a bare answer, or a scene dict with an 'answer'); errors name the label and the place");
  m.def("judge", [](const eccd::Scene& scene, const py::object& answer, double tol, const std::string& name, bool use_stored) {
        eccd::Answer theirs;
        if (py::isinstance<eccd::Solution>(answer)) theirs = answer.cast<const eccd::Solution&>().answer;
        else if (py::isinstance<eccd::Answer>(answer)) theirs = answer.cast<eccd::Answer>();
        else if (py::isinstance<py::dict>(answer))
          theirs = eccd::answer_from_text(py::module_::import("json").attr("dumps")(answer).cast<std::string>(), "<dict>").answer;
        else if (py::isinstance<py::str>(answer)) theirs = eccd::answer_from_text(answer.cast<std::string>(), "<string>").answer;
        else throw py::type_error("judge: answer must be an eccd Answer or Solution, a dict in the scene format, or JSON text");
        eccd::JudgeOptions o;
        o.tol = tol;
        o.name = name;
        o.use_stored = use_stored;
        py::gil_scoped_release unlocked;
        return eccd::judge(scene, theirs, o);
      }, py::arg("scene"), py::arg("answer"), py::arg("tol") = 1e-6, py::arg("name") = "yours", py::arg("use_stored") = false,
      "Compares an answer (Answer, Solution, dict in the scene format or JSON text) with the scene's certified answer; "
      "returns a Judgement (.agrees, .verdict, .differences, .counts)");

  // Animations and separating planes (issue 17 point 4): the same JSON objects as `eccd animate --json` and
  // `eccd separate --json`, as dicts (built by the API's own functions, then json.loads).
  m.def("animate", [](const std::string& path, const std::string& arith, int threads, bool all_intervals, bool planes,
                      double time_limit) {
        eccd::AnimateOptions o;
        o.solve.arith = eccd::parse_arithmetic(arith);
        if (threads < 1 || threads > 256) throw std::invalid_argument("threads must be 1 to 256");
        if (time_limit < 0) throw std::invalid_argument("time_limit must be >= 0 seconds");
        o.threads = threads;
        o.all_intervals = all_intervals;
        o.planes = planes;
        o.solve.time_limit_s = time_limit;
        std::string text;
        {
          py::gil_scoped_release unlocked;
          const eccd::Animation anim = eccd::read_animation(path);
          nlohmann::ordered_json j;
          j["format"] = eccd::kAnimationAnswerFormat;
          const nlohmann::ordered_json body = eccd::animation_result_to_json(eccd::animate(anim, o));
          for (const auto& it : body.items()) j[it.key()] = it.value();
          text = j.dump();
        }
        return py::module_::import("json").attr("loads")(text);
      }, py::arg("path"), py::arg("arith") = "double", py::arg("threads") = 2, py::arg("all_intervals") = false,
      py::arg("planes") = true, py::arg("time_limit") = 0.0,
      "Every checked pair of the animation file in every frame (docs/animation-format.md; api/animate.hpp): bounding "
      "spheres, the separating plane kept from the previous frame, then the continuous test in `arith` ('double', "
      "'mpfr:BITS', 'exact', 'certified'); first contact only unless all_intervals. Returns the answer object of "
      "`eccd animate FILE --json` as a dict (format ellipse-ccd-animation-answer/1, without the program's \"version\"; "
      "its times are this run's). threads: pair-frames in parallel (the answer does not depend on it); planes=False is "
      "--no-planes; time_limit: seconds per pair-frame's solve (0: the pipelines' default), beyond it the pair-frame is "
      "undecided. A bad file raises SceneError naming the file and the JSON place; a refused request ValueError.");
  m.def("separate", [](const py::object& scene_arg, const py::object& t, const std::string& arith) {
        static py::object Fraction = py::module_::import("fractions").attr("Fraction");
        eccd::Scene scene;
        std::string label;
        if (py::isinstance<eccd::Scene>(scene_arg)) {
          scene = scene_arg.cast<eccd::Scene>();
          label = "<Scene>";
        } else if (py::isinstance<py::dict>(scene_arg)) {
          label = "<dict>";
          scene = eccd::scene_from_text(py::module_::import("json").attr("dumps")(scene_arg).cast<std::string>(), label);
        } else if (py::isinstance<py::str>(scene_arg)) {
          label = scene_arg.cast<std::string>();
          scene = eccd::read_scene(label);
        } else {
          throw py::type_error("separate: scene must be an eccd Scene, a scene dict or a scene file's path");
        }
        // exact: a str such as '1/3' or '0.25' is read as a rational; a float is taken at its exact binary value
        const std::string ttext = py::isinstance<py::str>(t) ? t.cast<std::string>() : py::str(Fraction(t)).cast<std::string>();
        mpq_class q;
        try {
          q = eccd::parse_rational(ttext);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument("separate: t = " + ttext + ": " + e.what() + " (expected a rational in [0, 1] such as 1/3 or 0.25)");
        }
        if (sgn(q) < 0 || q > 1) throw std::invalid_argument("separate: t = " + ttext + ": the instant must lie in [0, 1]");
        eccd::SolveOptions o;
        o.arith = eccd::parse_arithmetic(arith);
        std::string text;
        {
          py::gil_scoped_release unlocked;
          const eccd::Separation sep = eccd::separate_at(scene, q, o);
          if (!o.arith.floating() && sep.status == "undecided")
            throw std::runtime_error("separate: " + label + ": " + sep.why);  // `eccd separate` exits 4 here
          nlohmann::ordered_json j;
          j["format"] = eccd::kSeparateFormat;
          const nlohmann::ordered_json body = eccd::separation_to_json(scene, label, q, o.arith, sep);
          for (const auto& it : body.items()) j[it.key()] = it.value();
          text = j.dump();
        }
        return py::module_::import("json").attr("loads")(text);
      }, py::arg("scene"), py::arg("t"), py::arg("arith") = "exact",
      "The scene's two objects at the instant t (paper 000 section 3; api/separate.hpp): a dict as `eccd separate SCENE "
      "--at T --json` prints (format eccd-separate/1, without \"version\"): \"status\" ('separate', 'touching', "
      "'overlapping'; floating arithmetics also 'undecided' with \"why\"), and when separate \"plane\" {\"normal\", "
      "\"offset\"} (n.x + o = 0, a on the negative side; exact rational strings), the tangent points and the inequalities "
      "that prove the plane. scene: an eccd Scene, a dict in the scene format or a file path; t: a rational string "
      "('1/3', '0.25'), a Fraction or an int (a float is taken at its exact binary value), 0 <= t <= 1. arith 'exact' "
      "(default) and 'certified' prove the plane; RuntimeError when they cannot (the command line's exit 4); ValueError "
      "for a cycloidal or independent-motions scene.");

  m.def("solve", [](const eccd::Scene& scene, const std::string& arith, const std::string& basis, int variant,
                    const std::string& method, bool first_contact, const std::string& input, double time_limit) {
        const eccd::SolveOptions o = solve_options(arith, basis, variant, method, first_contact, input, time_limit);
        py::gil_scoped_release unlocked;
        return eccd::solve(scene, o);
      }, py::arg("scene"), py::arg("arith") = "exact", py::arg("basis") = "bernstein", py::arg("variant") = 0,
      py::arg("method") = "bezier", py::arg("first_contact") = false, py::arg("input") = "rounded", py::arg("time_limit") = 0.0,
      "Solves a scene. arith: 'double', 'mpfr:BITS', 'exact', 'certified[:B1,B2,...|:none]'; the other options as on the command line "
      "(basis: power|bernstein|scaled-bernstein; variant 0-3 (2D); method: bezier|projection|sampling:N|marching:N (3D floating); "
      "input: rounded|prepared (floating); time_limit in seconds, 0 = default)");
}
