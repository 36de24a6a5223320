// The shared part of the Python bindings (python/eccd_module.cpp and its
// bind_*.cpp files, one per topic): text for Python (valid UTF-8, NUL kept
// visible), paths and scenes from Python objects, exact numbers as
// fractions.Fraction, instants and answers as Python sees them, the solve
// options from keywords, and the exception objects and eccd.Status made at
// import. Nothing is computed here: every binding calls the typed C++ API
// (include/eccd/eccd.hpp) and converts its types. Requirements: pybind11 2.6.
#pragma once

#include "eccd/eccd.hpp"
#include "api/animate.hpp"         // eccd.animate
#include "api/pose_check.hpp"      // eccd.animate(poses=True)
#include "api/separate_json.hpp"   // eccd.separate's dict: the same builder as `eccd separate --json`
#include "compare/fcl_engine.hpp"  // eccd.fcl: FCL as a peer engine, as `eccd fcl` runs it
#include "io/animation_reader.hpp"
#include "certificate/certificate_result.hpp"
#include "io/pose_import.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"
#include "kernel/budget.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sys/stat.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <regex>
#include <set>

#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace eccd_python {

// eccd.SceneError, eccd.CertificationError and eccd.Status, made at import.
extern py::object g_scene_error, g_certification_error;
extern py::object g_status;

py::str python_text(const std::string& bytes);
std::string python_words(const std::string& m);
std::string label_text(const std::string& label);
void set_error(PyObject* type, const std::string& message);
std::string path_bytes(const py::handle& p, const char* what);
void require_existing(const std::string& path, const py::handle& original);
bool is_path(const py::handle& h);
std::string read_input(const py::handle& p, const char* what);
std::string json_dumps(const py::handle& d);
py::object json_loads(const std::string& text);
eccd::Scene scene_of(const py::handle& arg, const char* what, std::string* label = nullptr);
py::object fraction(const std::optional<mpq_class>& q);
std::string number_text(const py::handle& x);
py::object status_obj(eccd::Status s);
std::string instant_repr(const eccd::Instant& i);
mpq_class instant_key(const eccd::Instant& i);
py::list instant_pairs(const std::vector<std::pair<eccd::Instant, eccd::Instant>>& v);
std::string pairs_repr(const std::vector<std::pair<eccd::Instant, eccd::Instant>>& v);
std::string answer_repr(const std::string& head, const eccd::Answer& a);
py::tuple floats_of(const std::vector<std::string>& v);
double checked_time_limit(double time_limit);
eccd::SolveOptions solve_options(const std::string& arith, const std::string& guard, const std::string& basis,
                                 int variant, const std::string& method, bool first_contact, const std::string& input);
nlohmann::json solution_dict_json(const eccd::Solution& s);

// JSON text of a library object for Python: a string that is not UTF-8 (a file name's bytes) gets U+FFFD where
// nlohmann's dump() would throw.
template <class Json>
std::string dump_text(const Json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// The answer's properties (collides, intervals, ...) on a class whose objects
// hold an Answer (get: the object -> its Answer).
template <class C, class Get>
void answer_properties(py::class_<C>& c, Get get) {
  c.def_property_readonly(
       "collides", [get](const C& x) { return eccd::collides_claim(get(x)); },
       "True where a collision is proved, False only for a complete answer without one, None (unknown) "
       "while a stretch is undecided and no collision is proved: the JSON's collides")
      .def_property_readonly(
          "intervals", [get](const C& x) { return instant_pairs(get(x).intervals); },
          "the maximal collision intervals: a list of (Instant, Instant) ([] for independent motions)")
      .def_property_readonly(
          "first_contact", [get](const C& x) { return get(x).first_contact; }, "an Instant or None")
      .def_property_readonly(
          "contacts", [get](const C& x) { return get(x).contacts; }, "the instants of external tangency")
      .def_property_readonly(
          "contact_intervals", [get](const C& x) { return instant_pairs(get(x).contact_intervals); },
          "intervals of continuous touching (docs/answer-format.md)")
      .def_property_readonly(
          "contact_points", [get](const C& x) { return get(x).contact_points; },
          "one ContactPoint (.point, .normal) per contact, in the order of contacts")
      .def_property_readonly(
          "undecided", [get](const C& x) { return get(x).undecided; },
          "floating runs: the instants they could not classify")
      .def_property_readonly(
          "independent", [get](const C& x) { return get(x).independent; },
          "an answer for independent motions (scene \"parameters\": \"independent\"): s_intervals, t_intervals")
      .def_property_readonly(
          "s_intervals", [get](const C& x) { return instant_pairs(get(x).s_intervals); },
          "independent motions: the maximal intervals of s where A(s) meets B(t) for some t")
      .def_property_readonly(
          "t_intervals", [get](const C& x) { return instant_pairs(get(x).t_intervals); },
          "independent motions: the maximal intervals of t where B(t) meets A(s) for some s");
}

// The topics, in the order the module registers them (a type before the
// functions whose signatures name it).
void bind_errors(py::module_& m);
void bind_status(py::module_& m);
void bind_answers(py::module_& m);
void bind_solution(py::module_& m);
void bind_scenes(py::module_& m);
void bind_static(py::module_& m);
void bind_certify(py::module_& m);
void bind_judge(py::module_& m);
void bind_animation(py::module_& m);
void bind_fcl(py::module_& m);
void bind_animate(py::module_& m);
void bind_separate(py::module_& m);
void bind_solve(py::module_& m);

}  // namespace eccd_python
