// Solving for Python: the Solution class (the answer and the run's
// diagnostics, to_dict() as `eccd solve --json`, picklable) and eccd.solve.
#include "bindings.hpp"

namespace eccd_python {

// The Solution class.
void bind_solution(py::module_& m) {
  py::class_<eccd::Solution> solution(m, "Solution", py::dynamic_attr(),
                                      "What solve returns: the answer and the run's diagnostics");
  answer_properties(solution, [](const eccd::Solution& s) -> const eccd::Answer& { return s.answer; });
  solution.def_readonly("answer", &eccd::Solution::answer)
      .def_readonly("certified", &eccd::Solution::certified, "every instant carries a proved rational bracket")
      .def_property_readonly("decided", &eccd::Solution::decided, "nothing is undecided")
      .def_property_readonly("arith", [](const eccd::Solution& s) { return s.arith.name(); })
      .def_readonly("scene", &eccd::Solution::scene, "the scene's name")
      .def_readonly("file", &eccd::Solution::file, "the scene's file ('' if built in code)")
      .def_readonly("dim", &eccd::Solution::dim)
      .def_readonly("basis", &eccd::Solution::basis)
      .def_readonly("method", &eccd::Solution::method)
      .def_property_readonly(
          "guard",
          [](const eccd::Solution& s) -> py::object {
            return s.guard.empty() ? py::object(py::none()) : py::object(py::str(s.guard));
          },
          "floating runs: 'none' (as published) or 'bound' (guarded); None for exact and certified runs")
      .def_property_readonly("status_at_0", [](const eccd::Solution& s) { return status_obj(s.status_at_0); })
      .def_readonly("projection", &eccd::Solution::projection)
      .def_readonly("projection_degree", &eccd::Solution::projection_degree)
      .def_property_readonly(
          "critical",
          [](const eccd::Solution& s) {
            py::list out;
            for (const auto& c : s.critical) out.append(py::make_tuple(c.t, status_obj(c.status), c.multiplicity));
            return out;
          },
          "the critical instants: a list of (Instant, Status, multiplicity)")
      .def_readonly("undecided_reasons", &eccd::Solution::undecided_reasons)
      .def_property_readonly("work",
                             [](const eccd::Solution& s) {
                               py::dict d;
                               for (const auto& [k, v] : s.work) d[py::str(k)] = v;
                               return d;
                             })
      .def_readonly("time_ms", &eccd::Solution::time_ms)
      .def_readonly("setup_ms", &eccd::Solution::setup_ms)
      .def_readonly("decided_in", &eccd::Solution::decided_in, "certified runs: the rung that decided")
      .def_property_readonly(
          "escalations",
          [](const eccd::Solution& s) {
            py::list out;
            for (const auto& e : s.escalations) out.append(py::make_tuple(e.rung, e.reason));
            return out;
          },
          "certified runs: (rung, why it gave up) for each lower rung")
      .def(
          "to_dict",
          [](const py::object& self) {
            return json_loads(dump_text(solution_dict_json(self.cast<const eccd::Solution&>())));
          },
          "the object `eccd solve --json` prints (format eccd-solution/1; \"version\" is the package's), "
          "JSON-serialisable")
      .def(py::pickle(
          [](const py::object& self) {
            return py::make_tuple(dump_text(eccd::solution_to_json(self.cast<const eccd::Solution&>())),
                                  self.attr("__dict__"));
          },
          [](const py::tuple& state) {
            if (state.size() != 2) throw std::invalid_argument("Solution: not a pickled Solution");
            eccd::Solution s =
                eccd::solution_from_json(nlohmann::json::parse(state[0].cast<std::string>()), "<pickle>");
            return std::make_pair(std::move(s), py::dict(state[1]));
          }))
      .def("__repr__", [](const py::object& self) {
        const eccd::Solution& s = self.cast<const eccd::Solution&>();
        std::string head = "Solution(arith=" + s.arith.name() + ", ";
        if (!s.scene.empty())
          head = "Solution(" + py::repr(py::str(s.scene)).cast<std::string>() + ", arith=" + s.arith.name() + ", ";
        return answer_repr(head, s.answer);
      });
}

// eccd.solve.
void bind_solve(py::module_& m) {
  m.def(
      "solve",
      [](const py::object& scene_arg, const std::string& arith, const std::string& guard, const std::string& basis,
         int variant, const std::string& method, bool first_contact, const std::string& input, double time_limit) {
        const eccd::SolveOptions o = solve_options(arith, guard, basis, variant, method, first_contact, input);
        const double limit = checked_time_limit(time_limit);
        const eccd::Scene scene = scene_of(scene_arg, "solve");
        eccd::Solution s;
        {
          py::gil_scoped_release unlocked;
          eccd::ScopedDeadline deadline(limit);  // the command line's --time-limit (kernel/budget.hpp)
          s = eccd::solve(scene, o);
        }
        return py::cast(std::move(s));
      },
      py::arg("scene"), py::arg("arith") = "exact", py::arg("guard") = "bound", py::arg("basis") = "bernstein",
      py::arg("variant") = 0, py::arg("method") = "bezier", py::arg("first_contact") = false,
      py::arg("input") = "rounded", py::arg("time_limit") = 300.0,
      "Solves a scene (an eccd Scene, a dict in the scene format, or a scene file's path). arith: 'double', "
      "'mpfr:BITS', "
      "'exact', 'certified[:B1,B2,...|:none]'; guard (floating): 'bound' (an error bound turns unsure signs into "
      "undecided) or 'none' (the published algorithm as is); basis: power|bernstein|scaled-bernstein (floating); "
      "variant "
      "0-3 (2D: answer, collides, first contact, all contacts); method: bezier|projection|sampling:N|marching:N (3D "
      "floating); first_contact (3D); input: rounded|prepared (floating); time_limit: seconds for the run, as the "
      "command "
      "line's --time-limit (default 300; 0: none), TimeoutError beyond it. The same answer as `eccd solve`; "
      "Solution.to_dict() is its --json object.");
}

}  // namespace eccd_python
