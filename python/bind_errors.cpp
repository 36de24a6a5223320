// Errors and statuses for Python: eccd.SceneError (a ValueError),
// eccd.CertificationError (a RuntimeError), the translation of every library
// exception (a run past its time_limit is TimeoutError, a bad keyword value
// ValueError naming the keyword), and eccd.Status, a str Enum.
#include "bindings.hpp"

namespace eccd_python {

// The exception types and the translator of library exceptions.
void bind_errors(py::module_& m) {
  g_scene_error = py::exception<eccd::SceneError>(m, "SceneError", PyExc_ValueError);
  g_certification_error = py::exception<eccd::CertificationError>(m, "CertificationError", PyExc_RuntimeError);
  // Every message through python_text (valid UTF-8, NUL kept visible); the
  // last registered translator is tried first.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const eccd::SceneError& e) {
      set_error(g_scene_error.ptr(), e.what());
    } catch (const eccd::CertificationError& e) {
      set_error(g_certification_error.ptr(), e.what());
    } catch (const eccd::BudgetExhausted& e) {
      set_error(PyExc_TimeoutError, e.what());
    } catch (const std::invalid_argument& e) {
      set_error(PyExc_ValueError, python_words(e.what()));
    } catch (const std::out_of_range& e) {
      set_error(PyExc_IndexError, e.what());
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "out of memory");
    } catch (const py::builtin_exception& e) {
      e.set_error();
    } catch (const py::error_already_set&) {
      throw;
    } catch (const std::runtime_error& e) {
      set_error(PyExc_RuntimeError, e.what());
    }
  });
}

// eccd.Status: a str Enum ("separate" == Status.separate), codes as in the C++ enum.
void bind_status(py::module_& m) {
  {  // eccd.Status: a str Enum ("separate" == Status.separate), codes as in the C++ enum
    py::list members;
    py::list codes;
    for (eccd::Status s :
         {eccd::Status::separate, eccd::Status::touching, eccd::Status::overlapping, eccd::Status::uncertain}) {
      members.append(py::make_tuple(eccd::to_string(s), eccd::to_string(s)));
      codes.append(py::make_tuple(static_cast<int>(s), eccd::to_string(s)));
    }
    // enum.StrEnum (Python 3.11) prints as its value; before 3.11 an Enum with the str mixin.
    py::module_ en = py::module_::import("enum");
    g_status = py::hasattr(en, "StrEnum")
                   ? en.attr("StrEnum")("Status", members, py::arg("module") = "eccd")
                   : en.attr("Enum")("Status", members, py::arg("module") = "eccd",
                                     py::arg("type") = py::module_::import("builtins").attr("str"));
    g_status.attr("__doc__") =
        "The contact status of two objects at one instant (a str: Status.separate == 'separate')";
    m.attr("Status") = g_status;
    m.attr("_status_codes") = codes;
  }
}

}  // namespace eccd_python
