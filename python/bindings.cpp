// The shared part of the Python bindings (see python/bindings.hpp).
#include "bindings.hpp"

namespace eccd_python {

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

// A scene from an eccd Scene, a dict in the scene format or a file path.
eccd::Scene scene_of(const py::handle& arg, const char* what, std::string* label) {
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

}  // namespace eccd_python
