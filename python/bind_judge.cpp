// Judging and peer engines for Python: Judgement, answer_from_dict and
// judge (any engine's answer against the certified one, api/judge.hpp), and
// eccd.fcl (FCL as a peer engine, as `eccd fcl` runs it).
#include "bindings.hpp"

namespace eccd_python {

// Judgement, answer_from_dict and judge.
void bind_judge(py::module_& m) {
  // Judge any engine's answer against the certified one (api/judge.hpp).
  py::class_<eccd::Judgement>(
      m, "Judgement", "judge's result: .agrees, .verdict, .differences (in words), .counts, .certified (the Solution)")
      .def_readonly("agrees", &eccd::Judgement::agrees)
      .def_readonly("verdict", &eccd::Judgement::verdict)
      .def_property_readonly("differences", [](const eccd::Judgement& j) { return j.difference.differences; })
      .def_property_readonly(
          "counts",
          [](const eccd::Judgement& j) {
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
            c["first_contact_error"] =
                d.first_contact_error ? py::object(py::float_(*d.first_contact_error)) : py::object(py::none());
            c["max_endpoint_error"] =
                d.max_endpoint_error ? py::object(py::float_(*d.max_endpoint_error)) : py::object(py::none());
            return c;
          },
          "the counts of api/answer_difference.hpp (missed, false, endpoints_off, ...) as a dict")
      .def_readonly("certified", &eccd::Judgement::certified, "the certified Solution it was compared with")
      .def_readonly("certified_from", &eccd::Judgement::certified_from, "'exact pipeline' or 'stored answer'")
      .def("__bool__", [](const eccd::Judgement& j) { return j.agrees; })
      .def("__repr__", [](const eccd::Judgement& j) { return "Judgement(" + j.verdict + ")"; });
  m.def(
      "answer_from_dict",
      [](const py::dict& d, const std::string& label) {
        return eccd::answer_from_text(json_dumps(d), label_text(label)).answer;
      },
      py::arg("answer"), py::arg("label") = "<dict>",
      "An Answer from a dict in the scene format (a bare answer, or a scene dict with an 'answer'); errors name the "
      "label and the place");
  m.def(
      "judge",
      [](const py::object& scene_arg, const py::object& answer, double tol, const std::string& name, bool use_stored) {
        const eccd::Scene scene = scene_of(scene_arg, "judge");
        eccd::Answer theirs;
        if (py::isinstance<eccd::Solution>(answer))
          theirs = answer.cast<const eccd::Solution&>().answer;
        else if (py::isinstance<eccd::Answer>(answer))
          theirs = answer.cast<eccd::Answer>();
        else if (py::isinstance<py::dict>(answer))
          theirs = eccd::answer_from_text(json_dumps(answer), "<dict>").answer;
        else if (py::isinstance<py::str>(answer))
          theirs = eccd::answer_from_text(answer.cast<std::string>(), "<string>").answer;
        else
          throw py::type_error(
              "judge: answer must be an eccd Answer or Solution, a dict in the scene format, or JSON text");
        eccd::JudgeOptions o;
        o.tol = tol;
        o.name = name;
        o.use_stored = use_stored;
        py::gil_scoped_release unlocked;
        return eccd::judge(scene, theirs, o);
      },
      py::arg("scene"), py::arg("answer"), py::arg("tol") = 1e-6, py::arg("name") = "yours",
      py::arg("use_stored") = false,
      "Compares an answer (Answer, Solution, dict in the scene format or JSON text) with the scene's certified answer "
      "(scene: an eccd Scene, a scene dict or a path); returns a Judgement (.agrees, .verdict, .differences, .counts)");
}

// eccd.fcl.
void bind_fcl(py::module_& m) {
  m.def(
      "fcl",
      [](const py::object& scene_arg, int samples, int ccd, double gjk_tolerance) {
        const eccd::Scene scene = scene_of(scene_arg, "fcl");
        const eccd::FclAvailability fa = eccd::fcl_availability();
        if (!fa.available) throw std::runtime_error("fcl: " + fa.reason);
        if (samples < 1) throw std::invalid_argument("samples=" + std::to_string(samples) + ": expected at least 1");
        if (ccd != 0 && ccd < 2)
          throw std::invalid_argument("ccd=" + std::to_string(ccd) + ": expected at least 2 iterations");
        if (!std::isfinite(gjk_tolerance) || gjk_tolerance < 0)
          throw std::invalid_argument("gjk_tolerance: expected a positive number (0: FCL's default)");
        if (ccd && gjk_tolerance > 0) throw std::invalid_argument("gjk_tolerance applies to sampling, not to ccd");
        eccd::FclOptions fo;
        fo.gjk_tolerance = gjk_tolerance;
        py::gil_scoped_release unlocked;
        return ccd ? eccd::fcl_ccd(scene, ccd, fo) : eccd::fcl_sample(scene, samples, fo);
      },
      py::arg("scene"), py::arg("samples") = 100, py::arg("ccd") = 0, py::arg("gjk_tolerance") = 0.0,
      "FCL's answer for a scene (docs/fcl.md), as `eccd fcl SCENE` computes it: fcl::collide at t = k/samples, "
      "colliding "
      "samples merged into intervals (fcl/sample:N), or with ccd=N fcl::continuousCollide (collides and first contact "
      "only; constant shapes moving by a translation linear in t). An Answer, for eccd.judge. RuntimeError when FCL is "
      "not built in; ValueError for a motion FCL cannot be given.");
}

}  // namespace eccd_python
