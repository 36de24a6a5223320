// The compiled part of the Python package eccd (python/eccd/, which
// re-exports it as `eccd`): the typed C++ API (include/eccd/eccd.hpp) for
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
// approximation as a float, for display only. Instants order by their exact
// value where certified (the brackets of one list are disjoint), by .approx
// otherwise. Statuses are members of eccd.Status, a str Enum. Errors: a bad
// scene raises eccd.SceneError (a ValueError) whose message names the file,
// the place and what is wrong (bytes that are not UTF-8 and NUL written as
// \xNN escapes); a missing file FileNotFoundError; a bad keyword value
// ValueError naming the keyword (arith='quad', not --arith quad); a run past
// its time_limit TimeoutError.
#include "eccd/eccd.hpp"
#include "api/animate.hpp"         // eccd.animate (issue 17 point 4)
#include "api/pose_check.hpp"      // eccd.animate(poses=True) (issue 36)
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

namespace {

// ---------------------------------------------------------------------------
// Text for Python: the library's messages are bytes (a file name or a label
// may hold any byte); Python needs valid UTF-8 without NUL cut-offs.

// NUL written as \x00; then decoded as UTF-8 with every invalid byte as \xNN.
py::str python_text(const std::string& bytes) {
  std::string t;
  t.reserve(bytes.size());
  for (char c : bytes) {
    if (c == '\0')
      t += "\\x00";
    else
      t += c;
  }
  PyObject* o = PyUnicode_DecodeUTF8(t.data(), Py_ssize_t(t.size()), "backslashreplace");
  if (!o) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(o);
}

// The command line's option names in a message as Python's keywords: "--arith quad" -> "arith=quad".
std::string python_words(const std::string& m) {
  static const std::regex option("--([a-z][a-z0-9]*(?:-[a-z0-9]+)*) ?");
  std::string out;
  auto begin = std::sregex_iterator(m.begin(), m.end(), option);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    out += m.substr(last, std::size_t(it->position()) - last);
    std::string name = (*it)[1].str();
    for (char& c : name)
      if (c == '-') c = '_';
    out += name + "=";
    last = std::size_t(it->position() + it->length());
  }
  return out + m.substr(last);
}

py::object g_scene_error, g_certification_error;

// A label given by the caller, for messages: what() ends at a NUL, so a NUL is written \x00 before it goes down.
std::string label_text(const std::string& label) {
  std::string t;
  for (char c : label) {
    if (c == '\0')
      t += "\\x00";
    else
      t += c;
  }
  return t;
}

void set_error(PyObject* type, const std::string& message) { PyErr_SetObject(type, python_text(message).ptr()); }

// ---------------------------------------------------------------------------
// Paths: str, bytes or os.PathLike; a NUL is refused (the C library would cut
// the name there and read another file); a missing file is FileNotFoundError.

std::string path_bytes(const py::handle& p, const char* what) {
  py::object b = py::module_::import("os").attr("fsencode")(p);  // TypeError for anything else
  std::string s = b.cast<std::string>();
  if (s.find('\0') != std::string::npos)
    throw std::invalid_argument(std::string(what) + ": the path " + py::repr(p).cast<std::string>() +
                                " holds a NUL character, which no file name can hold");
  return s;
}

void require_existing(const std::string& path, const py::handle& original) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0 && (errno == ENOENT || errno == ENOTDIR)) {
    const int e = errno;
    py::object err = py::module_::import("builtins").attr("FileNotFoundError")(e, std::strerror(e), original);
    PyErr_SetObject(PyExc_FileNotFoundError, err.ptr());
    throw py::error_already_set();
  }
}

bool is_path(const py::handle& h) {
  return py::isinstance<py::str>(h) || py::isinstance<py::bytes>(h) || py::hasattr(h, "__fspath__");
}

// The bytes of an input file named by a Python path (FileNotFoundError, SceneError naming it).
std::string read_input(const py::handle& p, const char* what) {
  const std::string path = path_bytes(p, what);
  require_existing(path, p);
  return eccd::read_file_bytes(path);
}

std::string json_dumps(const py::handle& d) {
  return py::module_::import("json").attr("dumps")(d, py::arg("allow_nan") = false).cast<std::string>();
}

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

// JSON text of a library object for Python: a string that is not UTF-8 (a file name's bytes) gets U+FFFD where
// nlohmann's dump() would throw.
template <class Json>
std::string dump_text(const Json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// A scene from an eccd Scene, a dict in the scene format or a file path.
eccd::Scene scene_of(const py::handle& arg, const char* what, std::string* label = nullptr) {
  if (py::isinstance<eccd::Scene>(arg)) {
    if (label) *label = "<Scene>";
    return arg.cast<eccd::Scene>();
  }
  if (py::isinstance<py::dict>(arg)) {
    if (label) *label = "<dict>";
    return eccd::scene_from_text(json_dumps(arg), "<dict>");
  }
  if (is_path(arg)) {
    const std::string path = path_bytes(arg, what);
    require_existing(path, arg);
    if (label) *label = path;
    return eccd::read_scene(path);
  }
  throw py::type_error(std::string(what) +
                       ": scene must be an eccd Scene, a dict in the scene format or a scene file's path, not " +
                       py::str(py::type::of(arg).attr("__name__")).cast<std::string>());
}

// ---------------------------------------------------------------------------
// Numbers and statuses.

py::object fraction(const std::optional<mpq_class>& q) {
  if (!q) return py::none();
  static py::object Fraction = py::module_::import("fractions").attr("Fraction");
  return Fraction(q->get_str());
}

// A Python number (int, float, Fraction, Decimal, numpy scalar) or a number string as the format's exact text.
std::string number_text(const py::handle& x) {
  if (py::isinstance<py::str>(x)) {
    try {
      return eccd::canonical_number_text(x.cast<std::string>());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(py::repr(x).cast<std::string>() + ": " + e.what());
    }
  }
  if (py::isinstance<py::bool_>(x)) throw py::type_error("a bool is not a number of the scene format");
  if (py::isinstance<py::float_>(x)) return eccd::number_from_double(x.cast<double>());
  if (py::isinstance<py::int_>(x) || py::hasattr(x, "numerator")) {  // int, Fraction, numpy integers
    static py::object Fraction = py::module_::import("fractions").attr("Fraction");
    return eccd::canonical_number_text(py::str(Fraction(x)).cast<std::string>());
  }
  if (py::hasattr(x, "__float__"))
    return eccd::number_from_double(x.attr("__float__")().cast<double>());  // numpy floats, Decimal
  throw py::type_error("expected a number (int, float, Fraction or a string such as '1/3'), not " +
                       py::str(py::type::of(x).attr("__name__")).cast<std::string>());
}

py::object g_status;  // eccd.Status, a str Enum made at import

py::object status_obj(eccd::Status s) { return g_status(std::string(eccd::to_string(s))); }

// ---------------------------------------------------------------------------
// Instants.

std::string instant_repr(const eccd::Instant& i) {
  std::string r = "Instant(" + i.approx;
  if (i.certified()) r += ", [" + i.lo->get_str() + ", " + i.hi->get_str() + "]";
  return r + ")";
}

// The exact value an instant is ordered by: its bracket's midpoint, or its approximation.
mpq_class instant_key(const eccd::Instant& i) {
  if (i.certified()) return (*i.lo + *i.hi) / 2;
  if (!std::isfinite(i.value)) throw std::invalid_argument("the instant " + i.approx + " has no value to compare");
  return mpq_class(i.value);
}

py::list instant_pairs(const std::vector<std::pair<eccd::Instant, eccd::Instant>>& v) {
  py::list out;
  for (const auto& [a, b] : v) out.append(py::make_tuple(a, b));
  return out;
}

// ---------------------------------------------------------------------------
// Answers and solutions.

std::string pairs_repr(const std::vector<std::pair<eccd::Instant, eccd::Instant>>& v) {
  std::string r = "[";
  for (std::size_t i = 0; i < v.size(); ++i)
    r += (i ? ", (" : "(") + instant_repr(v[i].first) + ", " + instant_repr(v[i].second) + ")";
  return r + "]";
}

std::string answer_repr(const std::string& head, const eccd::Answer& a) {
  const std::optional<bool> claim = eccd::collides_claim(a);
  std::string r = head + "collides=" + (!claim ? "None" : *claim ? "True" : "False");
  if (a.independent) {
    r += ", s_intervals=" + pairs_repr(a.s_intervals) + ", t_intervals=" + pairs_repr(a.t_intervals);
  } else {
    r += ", intervals=" + pairs_repr(a.intervals);
    if (!a.contacts.empty()) r += ", contacts=" + std::to_string(a.contacts.size());
    if (!a.contact_intervals.empty()) r += ", contact_intervals=" + std::to_string(a.contact_intervals.size());
  }
  if (!a.undecided.empty()) r += ", undecided=" + std::to_string(a.undecided.size());
  return r + ")";
}

py::tuple floats_of(const std::vector<std::string>& v) {
  py::tuple t(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) t[i] = py::float_(std::strtod(v[i].c_str(), nullptr));
  return t;
}

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

double checked_time_limit(double time_limit) {
  if (!std::isfinite(time_limit) || time_limit < 0)
    throw std::invalid_argument("time_limit=" + py::repr(py::float_(time_limit)).cast<std::string>() +
                                ": expected a finite number of seconds >= 0 (0: no limit)");
  return time_limit;
}

eccd::SolveOptions solve_options(const std::string& arith, const std::string& guard, const std::string& basis,
                                 int variant, const std::string& method, bool first_contact, const std::string& input) {
  eccd::SolveOptions o;
  o.arith = eccd::parse_arithmetic(arith);
  o.guard = eccd::parse_guard(guard);
  try {
    o.basis = eccd::parse_basis(basis);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("basis=" + basis + ": " + e.what());
  }
  if (variant < 0 || variant > 3)
    throw std::invalid_argument("variant must be 0 (answer), 1 (collides), 2 (first contact) or 3 (all contacts)");
  o.variant = static_cast<eccd::Variant>(variant);
  std::tie(o.method, o.grid) = eccd::parse_method(method);
  o.first_contact = first_contact || variant == 2;
  try {
    o.input = eccd::parse_input_mode(input);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("input=" + input + ": " + e.what());
  }
  return o;
}

// The object `eccd solve --json` prints ("format", "version" the package's).
nlohmann::json solution_dict_json(const eccd::Solution& s) {
  nlohmann::json j = eccd::solution_to_json(s);
  j["format"] = eccd::kSolutionFormat;
  j["version"] = ECCD_VERSION;
  return j;
}

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

PYBIND11_MODULE(_eccd, m) {
  m.doc() =
      "eccd's compiled core (import eccd): exact continuous collision detection of moving ellipses and ellipsoids";
  m.attr("__version__") = ECCD_VERSION;

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

  py::class_<eccd::Scene>(m, "Scene", "A scene: two objects and their motions on t in [0, 1]")
      .def_readonly("name", &eccd::Scene::name)
      .def_readonly("path", &eccd::Scene::path)
      .def_readonly("note", &eccd::Scene::note)
      .def_readonly("dim", &eccd::Scene::dim)
      .def_readonly("answer", &eccd::Scene::answer, "the answer stored in the scene file, or None")
      .def("__repr__",
           [](const eccd::Scene& s) { return "Scene('" + s.name + "', dim=" + std::to_string(s.dim) + ")"; });

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

  py::class_<eccd::Certificate>(
      m, "Certificate", "certify's result: the certificate (JSON text, eccd-certificate/2) and the Solution it proves")
      .def_readonly("text", &eccd::Certificate::text)
      .def_readonly("solution", &eccd::Certificate::solution)
      .def("__repr__", [](const eccd::Certificate& c) {
        return "Certificate(" + std::to_string(c.text.size()) + " characters, " + answer_repr("", c.solution.answer) +
               ")";
      });
  py::class_<eccd::CertificateCheck>(m, "CertificateCheck",
                                     "The checker's verdict: valid, the claims that hold, the first that does not")
      .def_readonly("valid", &eccd::CertificateCheck::valid)
      .def_readonly("checked", &eccd::CertificateCheck::checked)
      .def_readonly("failed_claim", &eccd::CertificateCheck::failed_claim)
      .def_readonly("reason", &eccd::CertificateCheck::reason)
      .def("__bool__", [](const eccd::CertificateCheck& c) { return c.valid; })
      .def("__repr__", [](const eccd::CertificateCheck& c) {
        return c.valid ? std::string("CertificateCheck(VALID)")
                       : "CertificateCheck(REJECTED: " + c.failed_claim + ": " + c.reason + ")";
      });
  m.def(
      "certify",
      [](const py::object& scene_arg) {
        const eccd::Scene scene = scene_of(scene_arg, "certify");
        py::gil_scoped_release unlocked;
        return eccd::certify(scene);
      },
      py::arg("scene"),
      "Solves the scene (an eccd Scene, a scene dict or a path) exactly and writes a certificate of the answer (raises "
      "CertificationError if a claim cannot be made provable)");
  m.def(
      "check_certificate",
      [](const py::object& scene_arg, const std::string& text) {
        const eccd::Scene scene = scene_of(scene_arg, "check_certificate");
        py::gil_scoped_release unlocked;
        return eccd::check_certificate(scene, text);
      },
      py::arg("scene"), py::arg("text"),
      "Re-checks a certificate (JSON text) against its scene (an eccd Scene, a scene dict or a path) without the "
      "solver; "
      "text that is not JSON raises SceneError");

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
