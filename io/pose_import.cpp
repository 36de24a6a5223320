#include "io/pose_import.hpp"

#include "io/animation_reader.hpp"
#include "io/scene_error.hpp"
#include "io/scene_reader.hpp"
#include "kernel/answer.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace eccd {

namespace {

// The exponent of p in n (n > 0), n divided by p that many times.
int strip_factor(mpz_class& n, unsigned long p) {
  int k = 0;
  while (mpz_divisible_ui_p(n.get_mpz_t(), p)) {
    mpz_divexact_ui(n.get_mpz_t(), n.get_mpz_t(), p);
    ++k;
  }
  return k;
}

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  return s.substr(a, b - a);
}

}  // namespace

std::string canonical_number(const Rational& q_in) {
  mpq_class q = q_in;
  q.canonicalize();
  if (q.get_den() == 1) return q.get_num().get_str();
  mpz_class den = q.get_den();
  const int twos = strip_factor(den, 2), fives = strip_factor(den, 5);
  if (den != 1) return q.get_str();  // no finite decimal
  // q = m / 10^k with m an integer: the digits of m, the point k places from the right.
  const int k = twos > fives ? twos : fives;
  mpz_class m = q.get_num();
  for (int i = twos; i < k; ++i) m *= 2;
  for (int i = fives; i < k; ++i) m *= 5;
  const bool negative = m < 0;
  if (negative) m = -m;
  std::string digits = m.get_str();  // no trailing zero (q is canonical, k minimal)
  std::string out;
  if (k <= 20) {
    if (int(digits.size()) <= k) digits = std::string(std::size_t(k - int(digits.size()) + 1), '0') + digits;
    out = digits.substr(0, digits.size() - std::size_t(k)) + "." + digits.substr(digits.size() - std::size_t(k));
  } else {  // d.ddd e-E: the same value, without a run of zeros
    const long exponent = long(digits.size()) - 1 - k;
    out = digits.substr(0, 1) + (digits.size() > 1 ? "." + digits.substr(1) : "") + "e" + std::to_string(exponent);
  }
  return negative ? "-" + out : out;
}

std::string number_from_double(double x) {
  if (!std::isfinite(x))
    throw std::invalid_argument(std::string(std::isnan(x) ? "NaN" : "an infinite value") +
                                " is not a number of the animation format");
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);  // shortest round-trip
  return canonical_number(parse_rational(std::string(buf, r.ptr)));
}

std::string canonical_number_text(const std::string& text) { return canonical_number(parse_rational(text)); }

std::vector<std::string> orientation_of_angle(double theta) {
  if (!std::isfinite(theta)) throw std::invalid_argument("the angle must be a finite number of radians");
  return {number_from_double(std::cos(theta / 2)), number_from_double(std::sin(theta / 2))};
}

nlohmann::ordered_json animation_json(const Keyframes& k, const std::string& label) {
  nlohmann::ordered_json j;
  j["format"] = kAnimationFormat;
  j["name"] = k.name;
  j["dim"] = k.dim;
  j["times"] = k.times;
  j["bodies"] = nlohmann::ordered_json::array();
  for (const KeyframeBody& b : k.bodies) {
    nlohmann::ordered_json body;
    body["name"] = b.name;
    if (!b.group.empty()) body["group"] = b.group;
    body["shape"] = b.shape;
    body["poses"] = nlohmann::ordered_json::array();
    for (const KeyframePose& p : b.poses) {
      nlohmann::ordered_json pose;
      pose["position"] = p.position;
      pose["orientation"] = p.orientation;
      if (!p.deformation.empty()) pose["deformation"] = p.deformation;
      body["poses"].push_back(std::move(pose));
    }
    j["bodies"].push_back(std::move(body));
  }
  if (k.pairs != "all") j["pairs"] = k.pairs;
  if (!k.note.empty()) j["note"] = k.note;
  animation_from_text(j.dump(), label);  // every check of the format, naming `label`
  return j;
}

std::string animation_text(const nlohmann::ordered_json& animation) {
  // Indented to the poses; each pose on one line (a file of thousands of poses stays readable).
  std::string out = "{\n";
  bool first = true;
  for (const auto& [key, value] : animation.items()) {
    out += first ? "" : ",\n";
    first = false;
    out += ' ';
    out += nlohmann::ordered_json(key).dump();
    out += ": ";
    if (key != "bodies") {
      out += value.dump();
      continue;
    }
    out += "[\n";
    for (std::size_t i = 0; i < value.size(); ++i) {
      const auto& body = value[i];
      out += "  {";
      bool first_key = true;
      for (const auto& [bk, bv] : body.items()) {
        out += first_key ? "" : ", ";
        first_key = false;
        out += nlohmann::ordered_json(bk).dump();
        out += ": ";
        if (bk != "poses") {
          out += bv.dump();
          continue;
        }
        out += "[\n";
        for (std::size_t p = 0; p < bv.size(); ++p) out += "    " + bv[p].dump() + (p + 1 < bv.size() ? ",\n" : "\n");
        out += "  ]";
      }
      out += i + 1 < value.size() ? "},\n" : "}\n";
    }
    out += " ]";
  }
  return out + "\n}\n";
}

Keyframes shapes_from_text(const std::string& json_text, const std::string& label) {
  const StrictJson doc = parse_strict_json(json_text, label);
  const nlohmann::json& root = doc.root;
  auto fail = [&](const std::string& pointer, const std::string& what) -> void {
    throw SceneError(label + ": " + json_place(pointer) + ": " + what);
  };
  if (!root.is_object()) fail("", "a shapes file is a JSON object {\"dim\", \"bodies\", ...} (docs/import-poses.md)");
  static const std::set<std::string> allowed{"format", "name", "dim", "bodies", "pairs", "note"};
  for (const auto& [key, value] : root.items())
    if (!allowed.count(key))
      fail("/" + key, "unknown key " + json_quote(key) + " (allowed: format, name, dim, bodies, pairs, note)");
  if (root.contains("format") && !(root["format"].is_string() && root["format"].get<std::string>() == kShapesFormat))
    fail("/format", std::string("expected \"") + kShapesFormat + "\"");
  Keyframes k;
  if (root.contains("name")) {
    if (!root["name"].is_string() || root["name"].get<std::string>().empty())
      fail("/name", "expected a non-empty string");
    k.name = root["name"].get<std::string>();
  }
  if (root.contains("note")) {
    if (!root["note"].is_string()) fail("/note", "expected a string");
    k.note = root["note"].get<std::string>();
  }
  if (!root.contains("dim")) fail("", "missing key \"dim\" (2 or 3)");
  const Rational dim = json_rational(doc, root["dim"], label, "/dim");
  if (dim != 2 && dim != 3) fail("/dim", "expected 2 or 3");
  k.dim = int(dim.get_num().get_si());
  if (!root.contains("bodies") || !root["bodies"].is_array() || root["bodies"].size() < 2)
    fail(root.contains("bodies") ? "/bodies" : "",
         "expected \"bodies\": a list of at least two bodies {\"name\", \"shape\"}");
  std::set<std::string> names;
  for (std::size_t i = 0; i < root["bodies"].size(); ++i) {
    const nlohmann::json& b = root["bodies"][i];
    const std::string at = "/bodies/" + std::to_string(i);
    if (!b.is_object()) fail(at, "expected an object {\"name\", \"shape\", \"group\" (optional)}");
    for (const auto& [key, value] : b.items())
      if (key != "name" && key != "shape" && key != "group")
        fail(at + "/" + key, "unknown key " + json_quote(key) + " (allowed: name, group, shape)");
    if (!b.contains("name") || !b["name"].is_string() || b["name"].get<std::string>().empty())
      fail(at + "/name", "expected a non-empty string");
    KeyframeBody body;
    body.name = b["name"].get<std::string>();
    if (!names.insert(body.name).second) fail(at + "/name", "the body " + json_quote(body.name) + " is named twice");
    if (b.contains("group")) {
      if (!b["group"].is_string()) fail(at + "/group", "expected a string");
      body.group = b["group"].get<std::string>();
    }
    if (!b.contains("shape")) fail(at, "missing key \"shape\"");
    json_shape(doc, b["shape"], label, at + "/shape", k.dim);  // a shape of the scene format, checked here
    body.shape = nlohmann::ordered_json::parse(b["shape"].dump());
    k.bodies.push_back(std::move(body));
  }
  if (root.contains("pairs"))
    k.pairs = nlohmann::ordered_json::parse(root["pairs"].dump());  // checked with the animation
  return k;
}

namespace {

// One data line of a poses CSV, read.
struct PoseRow {
  Rational t;
  std::size_t body;
  KeyframePose pose;
  long line;
};

// The comma-separated fields of a CSV line, each trimmed.
std::vector<std::string> csv_fields(const std::string& t) {
  std::vector<std::string> fields;
  std::size_t a = 0;
  while (true) {
    const std::size_t c = t.find(',', a);
    fields.push_back(trim(t.substr(a, c == std::string::npos ? std::string::npos : c - a)));
    if (c == std::string::npos) break;
    a = c + 1;
  }
  return fields;
}

// The key times of the rows, increasing, into k.times; each body's pose at
// each of them, exactly once (a repeated or missing pose throws SceneError).
void set_poses_by_time(std::vector<PoseRow>& rows, const std::string& csv_label, Keyframes& k) {
  std::map<Rational, std::size_t> time_index;
  for (const PoseRow& r : rows) time_index.emplace(r.t, 0);
  std::size_t n = 0;
  for (auto& [t, i] : time_index) {
    i = n++;
    k.times.push_back(canonical_number(t));
  }
  std::vector<std::vector<long>> line_of(k.bodies.size(), std::vector<long>(n, 0));
  for (auto& b : k.bodies) b.poses.assign(n, KeyframePose{});
  for (PoseRow& r : rows) {
    const std::size_t ti = time_index[r.t];
    long& seen = line_of[r.body][ti];
    if (seen)
      throw SceneError(csv_label + ": line " + std::to_string(r.line) + ": body " + json_quote(k.bodies[r.body].name) +
                       " at time " + k.times[ti] + " again (its pose is on line " + std::to_string(seen) + ")");
    seen = r.line;
    k.bodies[r.body].poses[ti] = std::move(r.pose);
  }
  if (time_index.size() < 2)
    throw SceneError(csv_label + ": the poses are all at one time (" + k.times[0] +
                     "): an animation needs at least two key times");
  for (std::size_t b = 0; b < k.bodies.size(); ++b)
    for (std::size_t ti = 0; ti < n; ++ti)
      if (!line_of[b][ti])
        throw SceneError(csv_label + ": body " + json_quote(k.bodies[b].name) + " has no pose at time " + k.times[ti] +
                         " (every body needs one pose at every time of the file)");
}

}  // namespace

Keyframes pose_keyframes_from_csv(const std::string& csv_text, const std::string& csv_label, Keyframes k) {
  const int dim = k.dim;
  static const std::vector<std::string> names3{"time", "body", "x", "y", "z", "qw", "qx", "qy", "qz"};
  static const std::vector<std::string> names2{"time", "body", "x", "y", "angle"};
  const std::vector<std::string>& columns = dim == 3 ? names3 : names2;
  std::string header;
  for (std::size_t i = 0; i < columns.size(); ++i) header += (i ? ", " : "") + columns[i];
  std::map<std::string, std::size_t> body_index;
  for (std::size_t i = 0; i < k.bodies.size(); ++i) body_index[k.bodies[i].name] = i;

  std::vector<PoseRow> rows;
  std::size_t start = 0;
  long line = 0;
  bool seen_data = false;
  while (start <= csv_text.size()) {
    std::size_t end = csv_text.find('\n', start);
    if (end == std::string::npos) end = csv_text.size();
    const std::string text = csv_text.substr(start, end - start);
    start = end + 1;
    ++line;
    const std::string where = csv_label + ": line " + std::to_string(line);
    if (text.find('\0') != std::string::npos)
      throw SceneError(where + ": a NUL byte (a binary file, not a CSV of poses)");
    const std::string t = trim(text);
    if (t.empty() || t[0] == '#') {
      if (end == csv_text.size()) break;
      continue;
    }
    const std::vector<std::string> fields = csv_fields(t);
    if (!seen_data && (fields[0] == "time" || fields[0] == "t")) {  // a header line
      seen_data = true;
      continue;
    }
    seen_data = true;
    if (fields.size() != columns.size())
      throw SceneError(where + ": expected " + std::to_string(columns.size()) + " columns (" + header + ") for a " +
                       std::to_string(dim) + "D shapes file, found " + std::to_string(fields.size()));
    auto number = [&](std::size_t col) {
      try {
        return parse_rational(fields[col]);
      } catch (const std::invalid_argument& e) {
        throw SceneError(where + ", column " + std::to_string(col + 1) + " (" + columns[col] +
                         "): " + json_quote(fields[col]) + ": " + e.what());
      }
    };
    PoseRow r;
    r.line = line;
    r.t = number(0);
    const auto it = body_index.find(fields[1]);
    if (it == body_index.end()) {
      std::string known;
      for (const auto& b : k.bodies) known += (known.empty() ? "" : ", ") + b.name;
      throw SceneError(where + ", column 2 (body): " + json_quote(fields[1]) +
                       " is not a body of the shapes file (its bodies: " + known + ")");
    }
    r.body = it->second;
    for (int i = 0; i < dim; ++i) r.pose.position.push_back(canonical_number(number(std::size_t(2 + i))));
    if (dim == 3) {
      bool zero = true;
      for (int i = 0; i < 4; ++i) {
        const Rational q = number(std::size_t(5 + i));
        zero = zero && q == 0;
        r.pose.orientation.push_back(canonical_number(q));
      }
      if (zero)
        throw SceneError(where + ", columns 6-9 (qw, qx, qy, qz): the quaternion is zero, which is no rotation");
    } else {
      const Rational angle = number(4);
      r.pose.orientation = orientation_of_angle(nearest_double(angle));
    }
    rows.push_back(std::move(r));
  }
  if (rows.empty()) throw SceneError(csv_label + ": no poses (expected lines of " + header + ")");

  set_poses_by_time(rows, csv_label, k);
  return k;
}

}  // namespace eccd
