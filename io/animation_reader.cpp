// Animation reader (see io/animation_reader.hpp for the statement and the choices).
#include "io/animation_reader.hpp"

#include "exact/algebraic_roots.hpp"
#include "io/scene_reader.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace eccd {

namespace {

using json = nlohmann::json;

std::string child(const std::string& ptr, const std::string& key) {
  std::string r;
  for (char ch : key) r += ch == '~' ? std::string("~0") : ch == '/' ? std::string("~1") : std::string(1, ch);
  return ptr + "/" + r;
}
std::string child(const std::string& ptr, std::size_t i) { return ptr + "/" + std::to_string(i); }

std::string join(const std::vector<std::string>& v) {
  std::string r;
  for (std::size_t i = 0; i < v.size(); ++i) r += (i ? ", " : "") + v[i];
  return r;
}

// Where p (not identically zero) vanishes on [0, 1], or "" if nowhere.
std::string root_in_unit(const RPoly& p) {
  if (p.is_zero()) return "everywhere";
  if (p.degree() < 1) return "";
  std::vector<AlgebraicRoot> roots = real_roots(p, Rational(0), Rational(1), 30);
  if (roots.empty()) return "";
  const AlgebraicRoot& r = roots.front();
  if (r.is_rational()) return "at τ = " + r.lo.get_str();
  return "at τ in [" + r.lo.get_str() + ", " + r.hi.get_str() + "]";
}

class AnimationReader {
 public:
  AnimationReader(std::string label, const StrictJson& doc) : label_(std::move(label)), doc_(doc) {}

  [[noreturn]] void fail(const std::string& ptr, const std::string& what) const {
    throw SceneError(label_ + ": " + json_place(ptr) + ": " + what);
  }

  Animation animation(const json& root);

 private:
  std::string label_;
  const StrictJson& doc_;
  int dim_ = 3;

  void check_keys(const json& j, const std::string& ptr, const std::vector<std::string>& allowed,
                  const std::string& what) const {
    for (auto it = j.begin(); it != j.end(); ++it) {
      bool ok = false;
      for (const auto& a : allowed) ok = ok || a == it.key();
      if (!ok)
        fail(child(ptr, it.key()),
             "unknown key " + json_quote(it.key()) + " in " + what + "; allowed keys: " + join(allowed));
    }
  }
  const json& member(const json& j, const std::string& ptr, const std::string& key, const std::string& what) const {
    auto it = j.find(key);
    if (it == j.end()) fail(ptr, "missing required key " + json_quote(key) + " in " + what);
    return *it;
  }
  void require_object(const json& j, const std::string& ptr, const std::string& what) const {
    if (!j.is_object()) fail(ptr, what + " must be a JSON object {...}, got " + json_type_name(j));
  }
  std::string name_string(const json& j, const std::string& ptr, const std::string& what) const {
    if (!j.is_string() || j.get_ref<const std::string&>().empty())
      fail(ptr, what + " must be a non-empty string, got " + (j.is_string() ? std::string("\"\"") : json_type_name(j)));
    return j.get<std::string>();
  }
  Rational number(const json& j, const std::string& ptr) const { return json_rational(doc_, j, label_, ptr); }
  std::vector<Rational> numbers(const json& j, const std::string& ptr, std::size_t n, const std::string& what) const {
    if (!j.is_array())
      fail(ptr, what + " must be an array of " + std::to_string(n) + " numbers, got " + json_type_name(j));
    if (j.size() != n)
      fail(ptr, what + " must have " + std::to_string(n) + " entries (dim " + std::to_string(dim_) + "), got " +
                    std::to_string(j.size()));
    std::vector<Rational> r;
    for (std::size_t i = 0; i < n; ++i) r.push_back(number(j[i], child(ptr, i)));
    return r;
  }
  KeyPose pose(const json& j, const std::string& ptr) const;
  AnimationBody body(const json& j, const std::string& ptr, std::size_t key_times) const;
  void check_frames(const AnimationBody& b, const std::string& ptr, const std::vector<Rational>& times) const;
  void pairs(Animation& a, const json* j) const;
};

KeyPose AnimationReader::pose(const json& j, const std::string& ptr) const {
  require_object(j, ptr, "a pose");
  const std::string what = "a pose";
  check_keys(j, ptr, {"position", "orientation", "deformation"}, what);
  KeyPose p;
  p.position = numbers(member(j, ptr, "position", what), child(ptr, "position"), std::size_t(dim_), "position");
  const std::string op = child(ptr, "orientation");
  const json& o = member(j, ptr, "orientation", what);
  const std::size_t nq = dim_ == 3 ? 4 : 2;
  p.orientation =
      numbers(o, op, nq, dim_ == 3 ? "orientation (a quaternion [w, x, y, z])" : "orientation (a pair [w, z])");
  bool zero = true;
  for (const auto& x : p.orientation) zero = zero && sgn(x) == 0;
  if (zero)
    fail(op, "the orientation is zero: it must not vanish (any non-zero " +
                 std::string(dim_ == 3 ? "quaternion [w, x, y, z]" : "pair [w, z]") + " gives a rotation; [\"1\", " +
                 (dim_ == 3 ? "\"0\", \"0\", \"0\"]" : "\"0\"]") + " is the identity)");
  if (auto it = j.find("deformation"); it != j.end()) {
    const std::string dp = child(ptr, "deformation");
    const std::string sz = std::to_string(dim_) + "x" + std::to_string(dim_);
    if (!it->is_array() || it->size() != std::size_t(dim_))
      fail(dp, "the deformation must be a " + sz + " array of rows, got " +
                   (it->is_array() ? std::to_string(it->size()) + " rows" : json_type_name(*it)));
    std::vector<std::vector<Rational>> d;
    for (std::size_t r = 0; r < std::size_t(dim_); ++r)
      d.push_back(numbers((*it)[r], child(dp, r), std::size_t(dim_), "a row of the deformation"));
    KeyPose only;
    only.deformation = d;
    const Rational det = keyframe_deformation_det(only, only, dim_)(Rational(0));
    if (sgn(det) <= 0)
      fail(dp, "the deformation must have det D > 0, got det D = " + det.get_str() +
                   (sgn(det) == 0 ? " (singular: it flattens the body)" : " (a reflection)"));
    p.deformation = d;
  }
  return p;
}

// q(τ) and D(τ) of every frame (kernel/keyframe_motion.hpp) must not vanish on [0, 1].
void AnimationReader::check_frames(const AnimationBody& b, const std::string& ptr,
                                   const std::vector<Rational>& times) const {
  for (std::size_t k = 0; k + 1 < b.poses.size(); ++k) {
    const KeyPose& p0 = b.poses[k];
    const KeyPose& p1 = b.poses[k + 1];
    const std::string frame = "body " + json_quote(b.name) + ", frame " + std::to_string(k) + " (t from " +
                              times[k].get_str() + " to " + times[k + 1].get_str() + ")";
    const std::string where = child(child(ptr, "poses"), k + 1);
    const RPoly w = keyframe_weight(p0.orientation, shorter_way(p0.orientation, p1.orientation));
    if (std::string at = root_in_unit(w); !at.empty())
      fail(child(where, "orientation"),
           frame + ": the interpolated orientation q(τ) vanishes " + at +
               " (the key orientations are opposite, a half turn apart): its rotation is undefined there");
    if (!keyframe_is_identity(p0, dim_) || !keyframe_is_identity(p1, dim_)) {
      const RPoly det = keyframe_deformation_det(p0, p1, dim_);
      if (std::string at = root_in_unit(det); !at.empty())
        fail(child(where, "deformation"), frame + ": the interpolated deformation D(τ) is singular: det D(τ) = 0 " +
                                              at + " (det D must stay positive between the key poses)");
    }
  }
}

AnimationBody AnimationReader::body(const json& j, const std::string& ptr, std::size_t key_times) const {
  require_object(j, ptr, "a body");
  const std::string what = "a body";
  check_keys(j, ptr, {"name", "group", "shape", "poses"}, what);
  AnimationBody b;
  b.name = name_string(member(j, ptr, "name", what), child(ptr, "name"), "a body's name");
  if (auto it = j.find("group"); it != j.end()) {
    if (!it->is_string()) fail(child(ptr, "group"), "group must be a string, got " + json_type_name(*it));
    b.group = it->get<std::string>();
    b.has_group = true;
  }
  b.Q = json_shape(doc_, member(j, ptr, "shape", what), label_, child(ptr, "shape"), dim_);
  const std::string pp = child(ptr, "poses");
  const json& poses = member(j, ptr, "poses", what);
  if (!poses.is_array()) fail(pp, "poses must be an array (one pose per key time), got " + json_type_name(poses));
  if (poses.size() != key_times)
    fail(pp, "poses must have exactly one entry per key time: " + std::to_string(key_times) + " key times, got " +
                 std::to_string(poses.size()) + " poses");
  for (std::size_t k = 0; k < poses.size(); ++k) b.poses.push_back(pose(poses[k], child(pp, k)));
  return b;
}

void AnimationReader::pairs(Animation& a, const json* j) const {
  const std::size_t n = a.bodies.size();
  if (!j || (j->is_string() && j->get_ref<const std::string&>() == "all")) {
    a.pairs_rule = "all";
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = i + 1; k < n; ++k) a.pairs.push_back({i, k});
    return;
  }
  if (j->is_string() && j->get_ref<const std::string&>() == "between-groups") {
    a.pairs_rule = "between-groups";
    for (std::size_t i = 0; i < n; ++i)
      if (!a.bodies[i].has_group)
        fail(child(child("/bodies", i), "name"), "pairs is \"between-groups\" but body " +
                                                     json_quote(a.bodies[i].name) +
                                                     " has no group (add \"group\": \"...\")");
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = i + 1; k < n; ++k)
        if (a.bodies[i].group != a.bodies[k].group) a.pairs.push_back({i, k});
    if (a.pairs.empty())
      fail("/pairs", "pairs is \"between-groups\" but every body is in the same group: no pair to check");
    return;
  }
  if (!j->is_array())
    fail("/pairs", "pairs must be \"all\", \"between-groups\" or a list of name pairs [[\"a\", \"b\"], ...], got " +
                       (j->is_string() ? json_quote(j->get<std::string>()) : json_type_name(*j)));
  a.pairs_rule = "list";
  if (j->empty()) fail("/pairs", "the list of pairs is empty: no pair to check");
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < n; ++i) index[a.bodies[i].name] = i;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> seen;
  for (std::size_t e = 0; e < j->size(); ++e) {
    const std::string ep = child("/pairs", e);
    const json& p = (*j)[e];
    if (!p.is_array() || p.size() != 2)
      fail(ep, "a pair must be an array of two body names [\"a\", \"b\"], got " +
                   (p.is_array() ? std::to_string(p.size()) + " entries" : json_type_name(p)));
    std::size_t ids[2];
    for (std::size_t s = 0; s < 2; ++s) {
      const std::string sp = child(ep, s);
      if (!p[s].is_string()) fail(sp, "a body name must be a string, got " + json_type_name(p[s]));
      auto it = index.find(p[s].get<std::string>());
      if (it == index.end())
        fail(sp, "unknown body name " + json_quote(p[s].get<std::string>()) + " (no body of that name)");
      ids[s] = it->second;
    }
    if (ids[0] == ids[1]) fail(ep, "a pair of a body with itself (" + json_quote(a.bodies[ids[0]].name) + ")");
    std::pair<std::size_t, std::size_t> key{std::min(ids[0], ids[1]), std::max(ids[0], ids[1])};
    if (auto it = seen.find(key); it != seen.end())
      fail(ep, "the pair " + json_quote(a.bodies[key.first].name) + ", " + json_quote(a.bodies[key.second].name) +
                   " is listed twice (also at /pairs/" + std::to_string(it->second) + ")");
    seen[key] = e;
  }
  for (const auto& [key, e] : seen) a.pairs.push_back(key);  // std::map: in the order of bodies
}

Animation AnimationReader::animation(const json& root) {
  const std::string fmt = kAnimationFormat;
  if (!root.is_object()) fail("", "an animation must be a JSON object {...}, got " + json_type_name(root));
  auto f = root.find("format");
  if (f == root.end()) fail("", "missing required key \"format\" (it must be \"" + fmt + "\")");
  if (!f->is_string() || f->get_ref<const std::string&>() != fmt)
    fail("/format", "unsupported format " + (f->is_string() ? json_quote(f->get<std::string>()) : json_type_name(*f)) +
                        "; this program reads \"" + fmt + "\"");
  const std::string what = "an animation";
  check_keys(root, "", {"format", "name", "dim", "times", "bodies", "pairs", "note"}, what);
  Animation a;
  a.path = label_;
  a.name = name_string(member(root, "", "name", what), "/name", "name");
  Rational d = number(member(root, "", "dim", what), "/dim");
  if (d != 2 && d != 3) fail("/dim", "dim must be 2 (ellipses) or 3 (ellipsoids), got " + d.get_str());
  dim_ = d == 2 ? 2 : 3;
  a.dim = dim_;
  if (auto note = root.find("note"); note != root.end()) {
    if (!note->is_string()) fail("/note", "note must be a string, got " + json_type_name(*note));
    a.note = note->get<std::string>();
  }
  const json& times = member(root, "", "times", what);
  if (!times.is_array())
    fail("/times", "times must be an array of key times [\"t0\", \"t1\", ...], got " + json_type_name(times));
  if (times.size() < 2)
    fail("/times", "times needs at least two key times (one frame), got " + std::to_string(times.size()));
  for (std::size_t k = 0; k < times.size(); ++k) {
    a.times.push_back(number(times[k], child("/times", k)));
    if (k > 0 && !(a.times[k - 1] < a.times[k]))
      fail(child("/times", k), "times must be strictly increasing: t_" + std::to_string(k) + " = " +
                                   a.times[k].get_str() + " does not exceed t_" + std::to_string(k - 1) + " = " +
                                   a.times[k - 1].get_str());
  }
  const json& bodies = member(root, "", "bodies", what);
  if (!bodies.is_array()) fail("/bodies", "bodies must be an array of bodies, got " + json_type_name(bodies));
  if (bodies.size() < 2)
    fail("/bodies", "an animation needs at least two bodies, got " + std::to_string(bodies.size()));
  std::map<std::string, std::size_t> names;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const std::string bp = child("/bodies", i);
    AnimationBody b = body(bodies[i], bp, a.times.size());
    if (auto it = names.find(b.name); it != names.end())
      fail(child(bp, "name"), "duplicate body name " + json_quote(b.name) + " (also /bodies/" +
                                  std::to_string(it->second) + "); names must be unique");
    names[b.name] = i;
    check_frames(b, bp, a.times);
    a.bodies.push_back(std::move(b));
  }
  auto p = root.find("pairs");
  pairs(a, p == root.end() ? nullptr : &*p);
  return a;
}

}  // namespace

Animation animation_from_text(const std::string& json_text, const std::string& label) {
  StrictJson doc = parse_strict_json(json_text, label);
  AnimationReader r(label, doc);
  try {
    return r.animation(doc.root);
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {  // safety net: never let a library exception escape
    throw SceneError(label + ": top level: internal error while reading the animation: " + std::string(e.what()));
  }
}

Animation read_animation(const std::string& path) { return animation_from_text(read_file_bytes(path), path); }

}  // namespace eccd
