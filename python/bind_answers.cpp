// Answers for Python: Instant (an exact bracket as fractions.Fraction,
// ordered by value), ContactPoint and Answer (a scene's stored answer).
#include "bindings.hpp"

namespace eccd_python {

// Instant, ContactPoint and Answer.
void bind_answers(py::module_& m) {
  py::class_<eccd::Instant>(
      m, "Instant",
      "An instant of the answer: .approx (float), .lo / .hi (Fraction, where certified); ordered by value")
      .def_property_readonly(
          "approx", [](const eccd::Instant& i) { return i.value; }, "the approximation as a float (display only)")
      .def_property_readonly(
          "approx_text", [](const eccd::Instant& i) { return i.approx; }, "the decimal approximation as text")
      .def_property_readonly(
          "lo", [](const eccd::Instant& i) { return fraction(i.lo); }, "fractions.Fraction, or None if not certified")
      .def_property_readonly(
          "hi", [](const eccd::Instant& i) { return fraction(i.hi); }, "fractions.Fraction, or None if not certified")
      .def_property_readonly("certified", &eccd::Instant::certified)
      .def("__float__", [](const eccd::Instant& i) { return i.value; })
      .def("__lt__", [](const eccd::Instant& a, const eccd::Instant& b) { return instant_key(a) < instant_key(b); })
      .def("__le__", [](const eccd::Instant& a, const eccd::Instant& b) { return instant_key(a) <= instant_key(b); })
      .def("__gt__", [](const eccd::Instant& a, const eccd::Instant& b) { return instant_key(a) > instant_key(b); })
      .def("__ge__", [](const eccd::Instant& a, const eccd::Instant& b) { return instant_key(a) >= instant_key(b); })
      .def("__eq__",
           [](const eccd::Instant& a, const py::object& o) {
             if (!py::isinstance<eccd::Instant>(o)) return false;
             const eccd::Instant& b = o.cast<const eccd::Instant&>();
             return a.approx == b.approx && a.lo == b.lo && a.hi == b.hi;
           })
      .def("__hash__",
           [](const eccd::Instant& i) {
             return py::hash(py::make_tuple(i.approx, i.lo ? i.lo->get_str() : "", i.hi ? i.hi->get_str() : ""));
           })
      .def(
          "to_dict", [](const eccd::Instant& i) { return json_loads(dump_text(eccd::instant_to_json(i))); },
          "{'approx', 'lo', 'hi'} as the answer format writes an instant")
      .def(py::pickle(
          [](const eccd::Instant& i) { return dump_text(eccd::instant_to_json(i)); },
          [](const std::string& text) { return eccd::instant_from_json(nlohmann::json::parse(text), "<pickle>", ""); }))
      .def("__repr__", &instant_repr);

  py::class_<eccd::ContactPoint>(
      m, "ContactPoint",
      "Where the objects touch at a contact: .point and A's unit outward normal .normal (display only)")
      .def_property_readonly(
          "point", [](const eccd::ContactPoint& c) { return floats_of(c.x); }, "the touching point, floats")
      .def_property_readonly(
          "normal", [](const eccd::ContactPoint& c) { return floats_of(c.normal); },
          "A's unit outward normal there (from a towards b), floats")
      .def_readonly("point_text", &eccd::ContactPoint::x, "the point as the JSON writes it (decimals)")
      .def_readonly("normal_text", &eccd::ContactPoint::normal)
      .def("__repr__", [](const eccd::ContactPoint& c) {
        return "ContactPoint(point=" + py::repr(floats_of(c.x)).cast<std::string>() +
               ", normal=" + py::repr(floats_of(c.normal)).cast<std::string>() + ")";
      });

  py::class_<eccd::Answer> answer(m, "Answer", "A scene's stored answer");
  answer_properties(answer, [](const eccd::Answer& a) -> const eccd::Answer& { return a; });
  answer.def("__repr__", [](const eccd::Answer& a) { return answer_repr("Answer(", a); })
      .def(
          "to_dict", [](const eccd::Answer& a) { return json_loads(dump_text(eccd::answer_to_json(a))); },
          "the answer in the scene format's keys (what a scene file stores under \"answer\")");
}

}  // namespace eccd_python
