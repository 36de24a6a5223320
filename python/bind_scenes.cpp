// Scenes for Python: the Scene class, read_scene, scene_from_text,
// scene_from_dict, and number_text (a number as the formats write it).
#include "bindings.hpp"

namespace eccd_python {

// Scene and the functions that make one.
void bind_scenes(py::module_& m) {
  py::class_<eccd::Scene>(m, "Scene", "A scene: two objects and their motions on t in [0, 1]")
      .def_readonly("name", &eccd::Scene::name)
      .def_readonly("path", &eccd::Scene::path)
      .def_readonly("note", &eccd::Scene::note)
      .def_readonly("dim", &eccd::Scene::dim)
      .def_readonly("answer", &eccd::Scene::answer, "the answer stored in the scene file, or None")
      .def("__repr__",
           [](const eccd::Scene& s) { return "Scene('" + s.name + "', dim=" + std::to_string(s.dim) + ")"; });

  m.def(
      "read_scene", [](const py::object& path) { return scene_of(path, "read_scene"); }, py::arg("path"),
      "Reads and validates a scene file (str or os.PathLike). FileNotFoundError if it does not exist; SceneError "
      "naming the file and the place");
  m.def(
      "scene_from_text",
      [](const std::string& text, const std::string& label) { return eccd::scene_from_text(text, label_text(label)); },
      py::arg("text"), py::arg("label") = "<string>", "A scene from its JSON text (errors name the label)");
  m.def(
      "scene_from_dict",
      [](const py::dict& d, const std::string& label) {
        return eccd::scene_from_text(json_dumps(d), label_text(label));
      },
      py::arg("scene"), py::arg("label") = "<dict>",
      "A scene from a dict in the scene format (numbers as strings, as in the files)");
  m.def("number_text", &number_text, py::arg("x"),
        "A number as the scene and animation formats write it: its exact value (a float by its shortest round-trip "
        "decimal, as repr prints it: 0.1 -> '0.1'); int, float, Fraction or a number string");
}

}  // namespace eccd_python
