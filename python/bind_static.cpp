// The static test and separating planes for Python: Ellipse,
// Ellipsoid, static_status (one pose, or many in one call from numpy arrays),
// status_at (a scene at an instant) and separate (a separating plane).
#include "bindings.hpp"

namespace eccd_python {

namespace {

// ---------------------------------------------------------------------------
// Poses from numpy arrays or nested sequences (numpy reads both in one call).

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

template <std::size_t N>
std::array<double, N> vector_of(const py::handle& h, const char* what) {
  Array a = Array::ensure(h);
  if (!a || a.ndim() != 1 || a.shape(0) != py::ssize_t(N))
    throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(N) + " numbers");
  std::array<double, N> out;
  std::memcpy(out.data(), a.data(), sizeof out);
  return out;
}

template <std::size_t N>
std::array<std::array<double, N>, N> matrix_of(const py::handle& h, const char* what) {
  Array a = Array::ensure(h);
  if (!a || a.ndim() != 2 || a.shape(0) != py::ssize_t(N) || a.shape(1) != py::ssize_t(N))
    throw std::invalid_argument(std::string(what) + ": expected a " + std::to_string(N) + "x" + std::to_string(N) +
                                " matrix");
  std::array<std::array<double, N>, N> out;
  std::memcpy(out.data(), a.data(), sizeof out);
  return out;
}

// Batch input: (n, D) semi-axes and (n, D+1, D+1) poses, read in place.
// The shapes go into `out`, a buffer kept from call to call (resized, never shrunk): a fresh vector of N shapes
// would cost its pages' first touch on every call, about as much as the static tests themselves.
template <class Shape, std::size_t D>
void shapes_of(const Array& axes, const Array& poses, const char* which, py::ssize_t& n, std::vector<Shape>& out) {
  constexpr py::ssize_t P = py::ssize_t(D) + 1;
  const std::string a = std::string("semi_axes_") + which, p = std::string("poses_") + which;
  if (axes.ndim() != 2 || axes.shape(1) != py::ssize_t(D))
    throw std::invalid_argument(a + ": expected an array of shape (N, " + std::to_string(D) + ")");
  if (poses.ndim() != 3 || poses.shape(1) != P || poses.shape(2) != P)
    throw std::invalid_argument(p + ": expected an array of shape (N, " + std::to_string(P) + ", " + std::to_string(P) +
                                ")");
  if (poses.shape(0) != axes.shape(0))
    throw std::invalid_argument(a + " has " + std::to_string(axes.shape(0)) + " rows and " + p + " " +
                                std::to_string(poses.shape(0)));
  if (n >= 0 && axes.shape(0) != n)
    throw std::invalid_argument("the two bodies' arrays have different lengths (" + std::to_string(n) + " and " +
                                std::to_string(axes.shape(0)) + ")");
  n = axes.shape(0);
  if (out.size() < std::size_t(n)) out.resize(std::size_t(n));
  const double* ax = axes.data();
  const double* po = poses.data();
  for (py::ssize_t i = 0; i < n; ++i) {
    std::memcpy(out[std::size_t(i)].semi_axes.data(), ax + i * py::ssize_t(D), sizeof(double) * D);
    std::memcpy(out[std::size_t(i)].pose.data(), po + i * P * P, sizeof(double) * std::size_t(P * P));
  }
}

}  // namespace

// Ellipse and Ellipsoid: one pose of a shape.
void bind_static_shapes(py::module_& m) {
  py::class_<eccd::Ellipse>(m, "Ellipse",
                            "An ellipse: semi-axes (a, b) along its own x, y and a 3x3 homogeneous pose (its frame -> "
                            "world); numpy arrays or sequences")
      .def(py::init([](const py::object& semi_axes, const py::object& pose) {
             return eccd::Ellipse{vector_of<2>(semi_axes, "semi_axes"),
                                  pose.is_none()
                                      ? std::array<std::array<double, 3>, 3>{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}
                                      : matrix_of<3>(pose, "pose")};
           }),
           py::arg("semi_axes"), py::arg("pose") = py::none())
      .def_readwrite("semi_axes", &eccd::Ellipse::semi_axes)
      .def_readwrite("pose", &eccd::Ellipse::pose);
  py::class_<eccd::Ellipsoid>(
      m, "Ellipsoid",
      "An ellipsoid: semi-axes (a, b, c) and a 4x4 homogeneous pose (its frame -> world); numpy arrays or sequences")
      .def(py::init([](const py::object& semi_axes, const py::object& pose) {
             return eccd::Ellipsoid{
                 vector_of<3>(semi_axes, "semi_axes"),
                 pose.is_none()
                     ? std::array<std::array<double, 4>, 4>{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}
                     : matrix_of<4>(pose, "pose")};
           }),
           py::arg("semi_axes"), py::arg("pose") = py::none())
      .def_readwrite("semi_axes", &eccd::Ellipsoid::semi_axes)
      .def_readwrite("pose", &eccd::Ellipsoid::pose);
}

// static_status, static_status_batch and status_at.
void bind_static_status(py::module_& m) {
  m.def(
      "static_status",
      [](const eccd::Ellipse& a, const eccd::Ellipse& b, const std::string& arith) {
        return status_obj(eccd::static_status(a, b, eccd::parse_arithmetic(arith)));
      },
      py::arg("a"), py::arg("b"), py::arg("arith") = "double",
      "The Status of two ellipses at their poses: separate, touching, overlapping or (double) uncertain; arith "
      "'double', 'exact' or 'certified'");
  m.def(
      "static_status",
      [](const eccd::Ellipsoid& a, const eccd::Ellipsoid& b, const std::string& arith) {
        return status_obj(eccd::static_status(a, b, eccd::parse_arithmetic(arith)));
      },
      py::arg("a"), py::arg("b"), py::arg("arith") = "double",
      "The Status of two ellipsoids at their poses (double: 001 Appendix A with its error bound; exact: proved)");
  m.def(
      "static_status_batch",
      [](const Array& semi_axes_a, const Array& poses_a, const Array& semi_axes_b, const Array& poses_b,
         const std::string& arith) {
        const eccd::Arithmetic ar = eccd::parse_arithmetic(arith);
        py::ssize_t n = -1;
        py::array_t<std::int8_t> out;
        const int dim = semi_axes_a.ndim() == 2 ? int(semi_axes_a.shape(1)) : 0;
        if (dim == 3) {
          thread_local std::vector<eccd::Ellipsoid> a, b;
          thread_local std::vector<eccd::Status> st;
          shapes_of<eccd::Ellipsoid, 3>(semi_axes_a, poses_a, "a", n, a);
          shapes_of<eccd::Ellipsoid, 3>(semi_axes_b, poses_b, "b", n, b);
          if (st.size() < std::size_t(n)) st.resize(std::size_t(n));
          {
            py::gil_scoped_release unlocked;
            const std::size_t k = std::size_t(n);
            eccd::static_status_batch(std::span<const eccd::Ellipsoid>(a.data(), k),
                                      std::span<const eccd::Ellipsoid>(b.data(), k),
                                      std::span<eccd::Status>(st.data(), k), ar);
          }
          out = py::array_t<std::int8_t>(n);
          std::int8_t* o = out.mutable_data();
          for (py::ssize_t i = 0; i < n; ++i) o[i] = std::int8_t(st[std::size_t(i)]);
        } else if (dim == 2) {
          thread_local std::vector<eccd::Ellipse> a, b;
          thread_local std::vector<eccd::Status> st;
          shapes_of<eccd::Ellipse, 2>(semi_axes_a, poses_a, "a", n, a);
          shapes_of<eccd::Ellipse, 2>(semi_axes_b, poses_b, "b", n, b);
          if (st.size() < std::size_t(n)) st.resize(std::size_t(n));
          {
            py::gil_scoped_release unlocked;
            const std::size_t k = std::size_t(n);
            eccd::static_status_batch(std::span<const eccd::Ellipse>(a.data(), k),
                                      std::span<const eccd::Ellipse>(b.data(), k),
                                      std::span<eccd::Status>(st.data(), k), ar);
          }
          out = py::array_t<std::int8_t>(n);
          std::int8_t* o = out.mutable_data();
          for (py::ssize_t i = 0; i < n; ++i) o[i] = std::int8_t(st[std::size_t(i)]);
        } else {
          throw std::invalid_argument(
              "semi_axes_a: expected an array of shape (N, 3) (ellipsoids) or (N, 2) (ellipses)");
        }
        return out;
      },
      py::arg("semi_axes_a"), py::arg("poses_a"), py::arg("semi_axes_b"), py::arg("poses_b"),
      py::arg("arith") = "double",
      "The static test for N pairs at once (api static_status_batch): semi-axes (N, 3) and poses (N, 4, 4) of the a's "
      "and "
      "the b's (2D: (N, 2) and (N, 3, 3)), float64 arrays read in place (others converted once). Returns an int8 array "
      "of "
      "status codes; eccd.status_of_code / eccd.STATUS_CODES name them. The same statuses as static_status pair by "
      "pair.");
  m.def(
      "status_at",
      [](const py::object& scene, const py::object& t, const std::string& arith) {
        static py::object Fraction = py::module_::import("fractions").attr("Fraction");
        const mpq_class q(
            py::str(Fraction(t)).cast<std::string>());  // exact: a float is taken at its exact binary value
        return status_obj(eccd::status_at(scene_of(scene, "status_at"), q, eccd::parse_arithmetic(arith)));
      },
      py::arg("scene"), py::arg("t"), py::arg("arith") = "exact",
      "The Status of the scene's objects at instant t (a Fraction, int, str like '1/3', or float), 0 <= t <= 1");
}

// The static test's shapes and functions.
void bind_static(py::module_& m) {
  bind_static_shapes(m);
  bind_static_status(m);
}

// eccd.separate: a separating plane at an instant, a dict.
void bind_separate(py::module_& m) {
  m.def(
      "separate",
      [](const py::object& scene_arg, const py::object& t, const std::string& arith) {
        static py::object Fraction = py::module_::import("fractions").attr("Fraction");
        std::string label;
        const eccd::Scene scene = scene_of(scene_arg, "separate", &label);
        // exact: a str such as '1/3' or '0.25' is read as a rational; a float is taken at its exact binary value
        const std::string ttext =
            py::isinstance<py::str>(t) ? t.cast<std::string>() : py::str(Fraction(t)).cast<std::string>();
        mpq_class q;
        try {
          q = eccd::parse_rational(ttext);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument("separate: t = " + ttext + ": " + e.what() +
                                      " (expected a rational in [0, 1] such as 1/3 or 0.25)");
        }
        if (sgn(q) < 0 || q > 1)
          throw std::invalid_argument("separate: t = " + ttext + ": the instant must lie in [0, 1]");
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
          text = dump_text(j);
        }
        return json_loads(text);
      },
      py::arg("scene"), py::arg("t"), py::arg("arith") = "exact",
      "The scene's two objects at the instant t (paper 000 section 3; api/separate.hpp): a dict as `eccd separate "
      "SCENE "
      "--at T --json` prints (format eccd-separate/1, without \"version\"): \"status\" ('separate', 'touching', "
      "'overlapping'; floating arithmetics also 'undecided' with \"why\"), and when separate \"plane\" {\"normal\", "
      "\"offset\"} (n.x + o = 0, a on the negative side; exact rational strings), the tangent points and the "
      "inequalities "
      "that prove the plane. scene: an eccd Scene, a dict in the scene format or a file path; t: a rational string "
      "('1/3', '0.25'), a Fraction or an int (a float is taken at its exact binary value), 0 <= t <= 1. arith 'exact' "
      "(default) and 'certified' prove the plane; RuntimeError when they cannot (the command line's exit 4); "
      "ValueError "
      "for a cycloidal or independent-motions scene.");
}

}  // namespace eccd_python
