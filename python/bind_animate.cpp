// Animations for Python: the Animation class (from a file, or built in
// code from keyframes or a CSV of poses, with its checked JSON) and
// eccd.animate (the animation answer, a dict).
#include "bindings.hpp"

namespace eccd_python {

namespace {

// ---------------------------------------------------------------------------
// Animations built in code: the keyframes and their checked JSON.

struct PyAnimation {
  eccd::Keyframes keyframes;
  nlohmann::ordered_json json;
  std::string label;
};

std::vector<std::string> numbers_of(const py::handle& row, std::size_t n, const std::string& what) {
  py::sequence s = py::reinterpret_borrow<py::sequence>(row);
  if (!py::isinstance<py::sequence>(row) && !py::hasattr(row, "__len__"))
    throw std::invalid_argument(what + ": expected " + std::to_string(n) + " numbers");
  if (py::len(row) != n)
    throw std::invalid_argument(what + ": expected " + std::to_string(n) + " numbers, got " +
                                std::to_string(py::len(row)));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n; ++i) {
    try {
      out.push_back(number_text(row[py::int_(i)]));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(what + "[" + std::to_string(i) + "]: " + e.what());
    }
  }
  return out;
}

PyAnimation animation_from_keyframes(const py::handle& times, const py::sequence& bodies, const std::string& name,
                                     const py::object& pairs, const std::string& note) {
  eccd::Keyframes k;
  k.name = name;
  k.note = note;
  const std::size_t K = py::len(times);
  k.times = numbers_of(times, K, "times");
  if (py::len(bodies) < 2) throw std::invalid_argument("bodies: an animation needs at least two bodies");
  int dim = 0;
  for (std::size_t bi = 0; bi < py::len(bodies); ++bi) {
    const std::string at = "bodies[" + std::to_string(bi) + "]";
    py::object b = bodies[py::int_(bi)];
    if (!py::isinstance<py::dict>(b))
      throw py::type_error(at +
                           ": expected a dict with name, semi_axes (or shape), positions, quaternions (2D: angles)");
    py::dict d = b;
    for (auto item : d) {
      const std::string key = py::str(item.first).cast<std::string>();
      static const std::set<std::string> allowed{"name",        "group",  "semi_axes",    "shape",       "positions",
                                                 "quaternions", "angles", "orientations", "deformations"};
      if (!allowed.count(key))
        throw std::invalid_argument(at + ": unknown key '" + key +
                                    "' (allowed: name, group, semi_axes or shape, positions, quaternions (3D), angles "
                                    "or orientations (2D), deformations)");
    }
    if (!d.contains("name") || !d.contains("positions"))
      throw std::invalid_argument(at + ": needs 'name' and 'positions'");
    eccd::KeyframeBody body;
    body.name = py::str(d["name"]).cast<std::string>();
    if (d.contains("group")) body.group = py::str(d["group"]).cast<std::string>();
    py::object positions = d["positions"];
    if (py::len(positions) != K)
      throw std::invalid_argument(at + ": positions has " + std::to_string(py::len(positions)) + " rows for " +
                                  std::to_string(K) + " times");
    const int bdim = K ? int(py::len(positions[py::int_(0)])) : 0;
    if (bdim != 2 && bdim != 3) throw std::invalid_argument(at + ": positions must have 2 (2D) or 3 (3D) columns");
    if (dim && bdim != dim)
      throw std::invalid_argument(at + ": a " + std::to_string(bdim) + "D body beside " + std::to_string(dim) +
                                  "D ones");
    dim = bdim;
    if (d.contains("shape") == d.contains("semi_axes"))
      throw std::invalid_argument(at + ": give either semi_axes or shape (a dict of the scene format)");
    if (d.contains("semi_axes"))
      body.shape["semi_axes"] = numbers_of(d["semi_axes"], std::size_t(dim), at + ".semi_axes");
    else
      body.shape = nlohmann::ordered_json::parse(json_dumps(d["shape"]));
    const char* turn = dim == 3 ? "quaternions" : (d.contains("angles") ? "angles" : "orientations");
    if (!d.contains(turn))
      throw std::invalid_argument(at + (dim == 3 ? ": needs 'quaternions' (K rows of w, x, y, z)"
                                                 : ": needs 'angles' (K radians) or 'orientations' (K rows of w, z)"));
    if (dim == 3 && (d.contains("angles") || d.contains("orientations")))
      throw std::invalid_argument(at + ": angles and orientations are for 2D bodies; 3D ones take quaternions");
    py::object turns = d[turn];
    if (py::len(turns) != K)
      throw std::invalid_argument(at + ": " + turn + " has " + std::to_string(py::len(turns)) + " entries for " +
                                  std::to_string(K) + " times");
    py::object deformations = d.contains("deformations") ? py::object(d["deformations"]) : py::object(py::none());
    if (!deformations.is_none() && py::len(deformations) != K)
      throw std::invalid_argument(at + ": deformations has " + std::to_string(py::len(deformations)) + " entries for " +
                                  std::to_string(K) + " times");
    for (std::size_t i = 0; i < K; ++i) {
      std::string row = std::to_string(i);  // "[i]", built without "[" + ... (GCC 12 -Wrestrict false positive)
      row.insert(row.begin(), '[');
      row.push_back(']');
      eccd::KeyframePose pose;
      pose.position = numbers_of(positions[py::int_(i)], std::size_t(dim), at + ".positions" + row);
      if (std::string(turn) == "angles")
        pose.orientation = eccd::orientation_of_angle(py::float_(turns[py::int_(i)]).cast<double>());
      else
        pose.orientation = numbers_of(turns[py::int_(i)], dim == 3 ? 4 : 2, at + "." + turn + row);
      if (!deformations.is_none()) {
        py::object m = deformations[py::int_(i)];
        if (py::len(m) != std::size_t(dim))
          throw std::invalid_argument(at + ".deformations" + row + ": expected a " + std::to_string(dim) + "x" +
                                      std::to_string(dim) + " matrix");
        for (int r = 0; r < dim; ++r)
          pose.deformation.push_back(
              numbers_of(m[py::int_(r)], std::size_t(dim), at + ".deformations" + row + "[" + std::to_string(r) + "]"));
      }
      body.poses.push_back(std::move(pose));
    }
    k.bodies.push_back(std::move(body));
  }
  k.dim = dim;
  if (py::isinstance<py::str>(pairs))
    k.pairs = pairs.cast<std::string>();
  else
    k.pairs = nlohmann::ordered_json::parse(json_dumps(pairs));
  PyAnimation a;
  a.label = "<Animation " + name + ">";
  a.json = eccd::animation_json(k, a.label);
  a.keyframes = std::move(k);
  return a;
}

}  // namespace

// The Animation class.
void bind_animation(py::module_& m) {
  // Animations: files, or built in code (Animation.from_keyframes, from_csv).
  py::class_<PyAnimation>(
      m, "Animation",
      "An animation file's content (docs/animation-format.md), built in code and checked as the reader checks a file")
      .def_static(
          "from_keyframes", &animation_from_keyframes, py::arg("times"), py::arg("bodies"),
          py::arg("name") = "animation", py::arg("pairs") = "all", py::arg("note") = "",
          "times: K key times (increasing). bodies: a list of dicts {'name', 'group' (optional), 'semi_axes' (or "
          "'shape', a dict of the scene format), 'positions' (K, dim), 3D 'quaternions' (K, 4) as w, x, y, z, 2D "
          "'angles' (K,) in radians or 'orientations' (K, 2) as w, z, 'deformations' (K, dim, dim) optional}; "
          "numpy arrays or sequences. Floats are written by their shortest round-trip decimal (repr), ints and "
          "Fractions exactly. pairs: 'all', 'between-groups' or a list of name pairs.")
      .def_static(
          "from_csv",
          [](const py::object& poses, const py::object& shapes) {
            PyAnimation a;
            const std::string shapes_text = read_input(shapes, "Animation.from_csv");
            const std::string csv_text = read_input(poses, "Animation.from_csv");
            const std::string shapes_label = path_bytes(shapes, "Animation.from_csv");
            a.label = path_bytes(poses, "Animation.from_csv");
            a.keyframes =
                eccd::pose_keyframes_from_csv(csv_text, a.label, eccd::shapes_from_text(shapes_text, shapes_label));
            a.json = eccd::animation_json(a.keyframes, a.label);
            return a;
          },
          py::arg("poses"), py::arg("shapes"),
          "An animation from a CSV of poses (time, body, x, y, z, qw, qx, qy, qz; 2D time, body, x, y, angle) and a "
          "shapes file: what `eccd import-poses POSES --shapes SHAPES` writes (docs/import-poses.md). Errors name the "
          "file, the line and the column.")
      .def_property_readonly("name", [](const PyAnimation& a) { return a.keyframes.name; })
      .def_property_readonly("dim", [](const PyAnimation& a) { return a.keyframes.dim; })
      .def_property_readonly(
          "times",
          [](const PyAnimation& a) {
            static py::object Fraction = py::module_::import("fractions").attr("Fraction");
            py::list out;
            for (const auto& t : a.keyframes.times) out.append(Fraction(eccd::parse_rational(t).get_str()));
            return out;
          },
          "the key times, Fractions")
      .def_property_readonly(
          "bodies",
          [](const PyAnimation& a) {
            py::list out;
            for (const auto& b : a.keyframes.bodies) out.append(b.name);
            return out;
          },
          "the bodies' names")
      .def(
          "pair_frame_scene",
          [](const PyAnimation& a, const std::string& body_a, const std::string& body_b, std::size_t frame) {
            const eccd::Animation anim = eccd::animation_from_text(dump_text(a.json), a.label);
            auto index = [&](const std::string& name) {
              for (std::size_t i = 0; i < anim.bodies.size(); ++i)
                if (anim.bodies[i].name == name) return i;
              throw std::invalid_argument("pair_frame_scene: no body named '" + name + "'");
            };
            const std::size_t i = index(body_a), j = index(body_b);
            if (i == j) throw std::invalid_argument("pair_frame_scene: two different bodies are needed");
            if (frame >= anim.frames())
              throw std::invalid_argument("pair_frame_scene: frame=" + std::to_string(frame) +
                                          ": the animation has frames 0 to " + std::to_string(anim.frames() - 1));
            return eccd::pair_frame_scene(anim, i, j, frame);
          },
          py::arg("body_a"), py::arg("body_b"), py::arg("frame"),
          "The scene of two bodies in frame k ([t_k, t_k+1] as local time 0..1): what eccd.animate solves for that "
          "pair-frame (api/animate.hpp pair_frame_scene); for eccd.solve, eccd.fcl, eccd.judge")
      .def(
          "to_json", [](const PyAnimation& a) { return eccd::animation_text(a.json); },
          "The animation file's text (format ellipse-ccd-animation/1), as `eccd import-poses` writes it")
      .def("to_dict", [](const PyAnimation& a) { return json_loads(dump_text(a.json)); })
      .def("__repr__", [](const PyAnimation& a) {
        return "Animation(" + py::repr(py::str(a.keyframes.name)).cast<std::string>() +
               ", dim=" + std::to_string(a.keyframes.dim) + ", bodies=" + std::to_string(a.keyframes.bodies.size()) +
               ", times=" + std::to_string(a.keyframes.times.size()) + ")";
      });
}

// eccd.animate.
void bind_animate(py::module_& m) {
  m.def(
      "animate",
      [](const py::object& source, const std::string& arith, int threads, bool all_intervals, bool planes,
         double time_limit, bool poses) {
        eccd::AnimateOptions o;
        o.solve.arith = eccd::parse_arithmetic(arith);
        if (threads < 1 || threads > 256)
          throw std::invalid_argument("threads=" + std::to_string(threads) + ": expected 1 to 256");
        o.threads = threads;
        o.all_intervals = all_intervals;
        o.planes = planes;
        o.solve.time_limit_s = checked_time_limit(time_limit);
        std::string text, label;
        if (py::isinstance<PyAnimation>(source)) {
          const PyAnimation& a = source.cast<const PyAnimation&>();
          text = dump_text(a.json);
          label = a.label;
        } else if (is_path(source)) {
          label = path_bytes(source, "animate");
          text = read_input(source, "animate");
        } else {
          throw py::type_error("animate: expected an animation file's path or an eccd.Animation");
        }
        {
          py::gil_scoped_release unlocked;
          const eccd::Animation anim = eccd::animation_from_text(text, label);
          nlohmann::ordered_json j;
          j["format"] = eccd::kAnimationAnswerFormat;
          const nlohmann::ordered_json body = poses ? eccd::poses_result_to_json(eccd::animate_poses(anim, o))
                                                    : eccd::animation_result_to_json(eccd::animate(anim, o));
          for (const auto& it : body.items()) j[it.key()] = it.value();
          text = dump_text(j);
        }
        return json_loads(text);
      },
      py::arg("animation"), py::arg("arith") = "double", py::arg("threads") = 2, py::arg("all_intervals") = false,
      py::arg("planes") = true, py::arg("time_limit") = 0.0, py::arg("poses") = false,
      "Every checked pair of the animation (a file's path or an eccd.Animation) in every frame "
      "(docs/animation-format.md; "
      "api/animate.hpp): bounding spheres, the separating plane kept from the previous frame, then the continuous test "
      "in "
      "`arith` ('double', 'mpfr:BITS', 'exact', 'certified'); first contact only unless all_intervals. Returns the "
      "answer "
      "object of `eccd animate FILE --json` as a dict (format ellipse-ccd-animation-answer/1, without the program's "
      "\"version\"; its times are this run's). threads: pair-frames in parallel (the answer does not depend on it); "
      "planes=False is --no-planes; time_limit: seconds per pair-frame's solve (0: the pipelines' default), beyond it "
      "the "
      "pair-frame is undecided. poses=True is --poses (api/pose_check.hpp): the static test of each pair at each key "
      "pose, "
      "the plane kept from pose to pose (000 section 4), arith 'double', 'exact' or 'certified', \"mode\": \"poses\". "
      "A missing file raises FileNotFoundError, a bad one SceneError naming the file and the JSON "
      "place; a refused request ValueError.");
}

}  // namespace eccd_python
