// Scene reader (see io/scene_reader.hpp for the statement and the choices):
// the validating Reader of scenes and stored answers, over the strict JSON of
// io/strict_json.cpp and the numbers of io/scene_numbers.cpp.
#include "io/scene_reader.hpp"

#include "io/json_messages.hpp"

#include "kernel/bernstein.hpp"
#include "kernel/quadric_classification.hpp"
#include "kernel/ring_determinant.hpp"
#include "exact/algebraic_roots.hpp"
#include "kernel/budget.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <unordered_map>
#include <vector>

namespace eccd {

using json = nlohmann::json;

namespace {

using json_messages::child;
using json_messages::join;
using json_messages::place_text;
using json_messages::quote;
using json_messages::shorten_digits;
using json_messages::type_name;

std::string approx_text(const mpq_class& q) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", q.get_d());
  return buf;
}

// "17 t^2 + 66 t - 63", shortened for messages.
std::string poly_text(const RPoly& p) {
  if (p.is_zero()) return "0";
  std::string r;
  for (int i = p.degree(); i >= 0; --i) {
    const mpq_class& c = p.c[i];
    if (sgn(c) == 0) continue;
    mpq_class a = abs(c);
    std::string term;
    if (i == 0 || a != 1) term = a.get_str();
    if (i > 0) {  // appended piece by piece: GCC 12's -Wrestrict misfires on "^" + std::to_string(i) here
      term += term.empty() ? "t" : " t";
      if (i > 1) term += '^' + std::to_string(i);
    }
    if (r.empty())
      r = (sgn(c) < 0 ? "-" : "") + term;
    else
      r += (sgn(c) < 0 ? " - " : " + ") + term;
    if (r.size() > 200) return r + " ...";
  }
  return r;
}

// The roots of p (not identically zero) in [0, 1], isolated by the exact
// root isolation (exact/algebraic_roots.hpp: CGAL, guarded and bounded) with
// brackets of width <= 2^-30 (Sturm sequences over the rationals take minutes
// on motions with 100-digit coefficients).
std::vector<AlgebraicRoot> roots_in_unit(const RPoly& p) {
  if (p.degree() < 1) return {};
  return real_roots(p, mpq_class(0), mpq_class(1), 30);
}

// Where p (not identically zero) vanishes on [0, 1], given its roots there.
std::string locate_root(const std::vector<AlgebraicRoot>& roots) {
  const AlgebraicRoot& r = roots.front();
  if (r.is_rational()) return "at t = " + r.lo.get_str();
  mpq_class mid = (r.lo + r.hi) / 2;
  return "at t in [" + r.lo.get_str() + ", " + r.hi.get_str() + "] (t ~ " + approx_text(mid) + ")";
}

class Reader {
 public:
  Reader(std::string label, const std::unordered_map<std::string, std::string>* float_text)
      : label_(std::move(label)), float_text_(float_text) {}

  [[noreturn]] void fail(const std::string& ptr, const std::string& what) const {
    throw SceneError(label_ + ": " + place_text(ptr) + ": " + shorten_digits(what));
  }

  Scene scene(const json& root);
  std::vector<std::vector<Rational>> shape_of_dim(const json& j, const std::string& ptr,
                                                  int dim) {  // parse_strict_json users
    dim_ = dim;
    return shape(j, ptr);
  }
  Rational number_at(const json& j, const std::string& ptr) const { return number(j, ptr); }
  // independent: the scene's "parameters" (nullopt: from the keys, for an answer file).
  Answer answer(const json& j, const std::string& ptr, std::optional<bool> independent = std::nullopt);
  Answer independent_answer(const json& j, const std::string& ptr);
  std::vector<std::pair<Instant, Instant>> interval_list(const json& j, const std::string& ptr,
                                                         const std::string& name) const;
  Instant instant(const json& j, const std::string& ptr) const;

 private:
  std::string label_;
  const std::unordered_map<std::string, std::string>* float_text_;
  int dim_ = 2;

  // --- structure helpers
  void require_object(const json& j, const std::string& ptr, const std::string& what) const {
    if (!j.is_object()) fail(ptr, what + " must be a JSON object {...}, got " + type_name(j));
  }
  void check_keys(const json& j, const std::string& ptr, const std::vector<std::string>& allowed,
                  const std::string& what) const {
    for (auto it = j.begin(); it != j.end(); ++it) {
      bool ok = false;
      for (const auto& a : allowed) ok = ok || a == it.key();
      if (!ok)
        fail(child(ptr, it.key()),
             "unknown key " + quote(it.key()) + " in " + what + "; allowed keys: " + join(allowed));
    }
  }
  const json* find(const json& j, const std::string& key) const {
    auto it = j.find(key);
    return it == j.end() ? nullptr : &*it;
  }
  const json& member(const json& j, const std::string& ptr, const std::string& key, const std::string& what) const {
    const json* m = find(j, key);
    if (!m) fail(ptr, "missing required key " + quote(key) + " in " + what);
    return *m;
  }
  const json& array_of(const json& j, const std::string& ptr, std::size_t n, const std::string& what,
                       const std::string& why = "") const {
    if (!j.is_array()) fail(ptr, what + " must be an array of " + std::to_string(n) + " entries, got " + type_name(j));
    if (j.size() != n)
      fail(ptr, what + " must have " + std::to_string(n) + " entries" + why + ", got " + std::to_string(j.size()));
    return j;
  }

  // --- values
  Rational number(const json& j, const std::string& ptr) const;
  RPoly poly(const json& j, const std::string& ptr) const;
  std::vector<RPoly> polys(const json& j, const std::string& ptr, std::size_t n, const std::string& what) const {
    array_of(j, ptr, n, what);
    std::vector<RPoly> r;
    for (std::size_t i = 0; i < n; ++i) r.push_back(poly(j[i], child(ptr, i)));
    return r;
  }
  std::vector<AlgebraicRoot> unit_roots(const RPoly& p, const std::string& ptr, const std::string& name) const {
    try {
      return roots_in_unit(p);
    } catch (const BudgetExhausted& e) {
      fail(ptr, name + " cannot be checked for roots on [0, 1]: " + e.what() + " (beyond the input limits)");
    }
  }
  void check_nonvanishing(const RPoly& p, const std::string& ptr, const std::string& name,
                          const std::string& consequence) const {
    if (p.is_zero()) fail(ptr, name + " is identically zero" + consequence);
    if (auto roots = unit_roots(p, ptr, name); !roots.empty())
      fail(ptr, name + " vanishes on [0, 1]: " + name + " = 0 " + locate_root(roots) + consequence);
  }

  std::vector<std::vector<Rational>> shape(const json& j, const std::string& ptr) const;
  Motion motion(const json& j, const std::string& ptr) const;
  MatrixMotion matrix_motion(const json& j, const std::string& ptr, const std::string& what) const;
  SceneObject object(const json& j, const std::string& ptr) const;
};

Rational Reader::number(const json& j, const std::string& ptr) const {
  if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    try {
      return parse_rational(s);
    } catch (const std::invalid_argument& e) {
      const bool limit = std::string(e.what()).find("input limit") != std::string::npos;
      fail(ptr, quote(s) + (limit ? ": " : " is not an exact number: ") + e.what());
    }
  }
  if (j.is_number_integer()) {  // signed or unsigned: exact
    std::string digits = j.is_number_unsigned() ? std::to_string(j.get<json::number_unsigned_t>())
                                                : std::to_string(j.get<json::number_integer_t>());
    return parse_rational(digits);
  }
  if (j.is_number_float()) {
    std::string raw;
    if (float_text_) {
      auto it = float_text_->find(ptr);
      if (it != float_text_->end()) raw = it->second;
    }
    if (raw.empty()) raw = j.dump();
    const bool integer_text = raw.find_first_of(".eE") == std::string::npos;
    if (integer_text) {  // an integer too large for 64 bits: the raw digits are exact
      try {
        return parse_rational(raw);
      } catch (const std::invalid_argument&) {}
    }
    fail(ptr, "the JSON number " + raw +
                  " has a fraction part or exponent, and a JSON parser may already have rounded it; "
                  "write it as a string \"" +
                  raw + "\" for its exact decimal value");
  }
  fail(ptr, "expected a number (a string such as \"-3/7\" or \"1.8\", or a JSON integer), got " + type_name(j));
}

RPoly Reader::poly(const json& j, const std::string& ptr) const {
  const auto too_long = [&](const json& arr, const std::string& p) {
    if (arr.size() > std::size_t(input_limits().max_degree) + 1)
      fail(p, "a polynomial of degree " + std::to_string(arr.size() - 1) + ", beyond the input limit of degree " +
                  std::to_string(input_limits().max_degree) + " (--max-degree)");
  };
  if (j.is_array()) {
    if (j.empty()) fail(ptr, "empty coefficient array; write [\"0\"] for the zero polynomial");
    too_long(j, ptr);
    std::vector<Rational> c;
    for (std::size_t i = 0; i < j.size(); ++i) c.push_back(number(j[i], child(ptr, i)));
    return RPoly(std::move(c));
  }
  if (j.is_object()) {
    check_keys(j, ptr, {"bernstein"}, "a polynomial in Bernstein form");
    const std::string bp = child(ptr, "bernstein");
    const json& b = member(j, ptr, "bernstein", "a polynomial in Bernstein form");
    if (!b.is_array()) fail(bp, "Bernstein coefficients must be an array [\"c0\", ..., \"cn\"], got " + type_name(b));
    if (b.empty()) fail(bp, "empty Bernstein coefficient array");
    too_long(b, bp);
    Bern<Rational> q;
    for (std::size_t i = 0; i < b.size(); ++i) q.b.push_back(number(b[i], child(bp, i)));
    return to_power(q);
  }
  if (j.is_string() || j.is_number()) return RPoly::constant(number(j, ptr));
  fail(ptr,
       "expected a polynomial: an array of coefficients [\"c0\", \"c1\", ...] (lowest degree first), "
       "{\"bernstein\": [...]}, or a number string, got " +
           type_name(j));
}

std::vector<std::vector<Rational>> Reader::shape(const json& j, const std::string& ptr) const {
  require_object(j, ptr, "a shape");
  const std::vector<std::string> kinds = {"semi_axes", "semi_axes_squared", "matrix"};
  check_keys(j, ptr, kinds, "a shape");
  std::vector<std::string> given;
  for (const auto& k : kinds)
    if (find(j, k)) given.push_back(k);
  if (given.empty()) fail(ptr, "a shape needs exactly one of the keys semi_axes, semi_axes_squared, matrix");
  if (given.size() > 1)
    fail(ptr,
         "a shape takes exactly one of semi_axes, semi_axes_squared, matrix; this one has " + join(given, " and "));
  const std::string& kind = given[0];
  const std::string kp = child(ptr, kind);
  const json& v = *find(j, kind);
  const std::string dims = " (dim " + std::to_string(dim_) + ")";
  const std::size_t n = std::size_t(dim_) + 1;
  std::vector<std::vector<Rational>> Q(n, std::vector<Rational>(n, Rational(0)));

  if (kind == "semi_axes" || kind == "semi_axes_squared") {
    const bool squared = kind == "semi_axes_squared";
    array_of(v, kp, std::size_t(dim_), kind, dims);
    for (int i = 0; i < dim_; ++i) {
      Rational a = number(v[i], child(kp, std::size_t(i)));
      if (sgn(a) <= 0)
        fail(child(kp, std::size_t(i)),
             std::string(squared ? "a squared semi-axis" : "a semi-axis") + " must be positive, got " + a.get_str());
      Rational s = squared ? a : Rational(a * a);
      Q[i][i] = 1 / s;
    }
    Q[dim_][dim_] = -1;
    return Q;
  }
  // matrix
  const std::string sz = std::to_string(n) + "x" + std::to_string(n);
  if (!v.is_array() || v.size() != n)
    fail(kp, "the shape matrix must be a symmetric " + sz + " array of rows" + dims + ", got " +
                 (v.is_array() ? std::to_string(v.size()) + " rows" : type_name(v)));
  for (std::size_t r = 0; r < n; ++r) {
    const std::string rp = child(kp, r);
    const json& row = v[r];
    if (!row.is_array() || row.size() != n)
      fail(rp, "each row of the shape matrix must have " + std::to_string(n) + " entries" + dims + ", got " +
                   (row.is_array() ? std::to_string(row.size()) : type_name(row)));
    for (std::size_t c = 0; c < n; ++c) Q[r][c] = number(row[c], child(rp, c));
  }
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < r; ++c)
      if (Q[r][c] != Q[c][r])
        fail(child(child(kp, r), c), "the shape matrix is not symmetric: entry [" + std::to_string(r) + "][" +
                                         std::to_string(c) + "] = " + Q[r][c].get_str() + " but [" + std::to_string(c) +
                                         "][" + std::to_string(r) + "] = " + Q[c][r].get_str());
  QuadricClass qc = classify_quadric(Q, dim_);
  if (!qc.ok()) {
    const std::string what = dim_ == 2 ? "conic" : "quadric";
    const std::string want = dim_ == 2 ? "a real, non-degenerate ellipse" : "a real, non-degenerate ellipsoid";
    fail(kp, "this " + what + " " + qc.description + "; a shape must be " + want + " with X^T Q X < 0 inside");
  }
  return Q;
}

// A "matrix" motion: m, (dim+1) x (dim+1) polynomials, with last row (0, ..., 0, w(t)),
// w(t) and the determinant of the affine block non-vanishing on [0, 1].
MatrixMotion Reader::matrix_motion(const json& j, const std::string& ptr, const std::string& what) const {
  const std::size_t n = std::size_t(dim_) + 1;
  const std::string dims = "dim " + std::to_string(dim_);
  check_keys(j, ptr, {"type", "m"}, what);
  const std::string mp = child(ptr, "m");
  const json& m = member(j, ptr, "m", what);
  const std::string sz = std::to_string(n) + "x" + std::to_string(n);
  if (!m.is_array() || m.size() != n)
    fail(mp, "the motion matrix m must be a " + sz + " array of rows of polynomials (" + dims + "), got " +
                 (m.is_array() ? std::to_string(m.size()) + " rows" : type_name(m)));
  MatrixMotion mm;
  for (std::size_t r = 0; r < n; ++r) {
    const std::string rp = child(mp, r);
    const json& row = m[r];
    if (!row.is_array() || row.size() != n)
      fail(rp, "each row of the motion matrix must have " + std::to_string(n) + " polynomials (" + dims + "), got " +
                   (row.is_array() ? std::to_string(row.size()) : type_name(row)));
    std::vector<RPoly> prow;
    for (std::size_t c = 0; c < n; ++c) prow.push_back(poly(row[c], child(rp, c)));
    mm.m.push_back(std::move(prow));
  }
  const std::string last_row = dim_ == 2 ? "(0, 0, w(t))" : "(0, 0, 0, w(t))";
  for (std::size_t c = 0; c + 1 < n; ++c)
    if (!mm.m[n - 1][c].is_zero())
      fail(child(child(mp, n - 1), c), "the last row of the motion matrix must be " + last_row +
                                           ": this entry must be 0, got " + poly_text(mm.m[n - 1][c]));
  check_nonvanishing(mm.m[n - 1][n - 1], child(child(mp, n - 1), n - 1), "w(t)",
                     " (the last row of M(t) is " + last_row + ", and w(t) must not vanish on [0, 1])");
  std::vector<std::vector<RPoly>> block(n - 1);
  for (std::size_t r = 0; r + 1 < n; ++r) block[r].assign(mm.m[r].begin(), mm.m[r].end() - 1);
  RPoly d = ring_det(block, RPoly());  // kernel/ring_determinant.hpp
  const std::string bs = std::to_string(dim_) + "x" + std::to_string(dim_);
  if (d.is_zero())
    fail(mp, "singular affine block for every t: the upper-left " + bs + " block of M(t) has determinant 0");
  if (auto roots = unit_roots(d, mp, "the determinant of the affine block"); !roots.empty())
    fail(mp, "singular affine block " + locate_root(roots) + ": the upper-left " + bs +
                 " block of M(t) must be non-singular on [0, 1] (its determinant is " + poly_text(d) + ")");
  return mm;
}

Motion Reader::motion(const json& j, const std::string& ptr) const {
  require_object(j, ptr, "a motion");
  const std::vector<std::string> types = {"static", "matrix", "kinematic", "euler", "cycloidal"};
  const std::string tp = child(ptr, "type");
  const json* t = find(j, "type");
  if (!t) fail(ptr, "missing required key \"type\" in a motion (one of " + join(types) + ")");
  if (!t->is_string()) fail(tp, "the motion type must be a string (one of " + join(types) + "), got " + type_name(*t));
  const std::string& type = t->get_ref<const std::string&>();
  bool known = false;
  for (const auto& k : types) known = known || k == type;
  if (!known) fail(tp, "unknown motion type " + quote(type) + "; allowed types: " + join(types));
  const std::string dims = "dim " + std::to_string(dim_);
  const std::string allowed_here = dim_ == 2 ? "static, matrix, kinematic, cycloidal" : "static, matrix, euler";
  if ((type == "kinematic" || type == "cycloidal") && dim_ != 2)
    fail(tp, "motion type " + quote(type) + " is for dim 2 only, but this scene has " + dims + " (allowed for " + dims +
                 ": " + allowed_here + ")");
  if (type == "euler" && dim_ != 3)
    fail(tp, "motion type \"euler\" is for dim 3 only, but this scene has " + dims + " (allowed for " + dims + ": " +
                 allowed_here + ")");
  const std::string what = "a " + type + " motion";

  if (type == "static") {
    check_keys(j, ptr, {"type"}, what);
    return StaticMotion{};
  }
  if (type == "matrix") return matrix_motion(j, ptr, what);
  if (type == "kinematic") {
    check_keys(j, ptr, {"type", "d"}, what);
    const std::string dp = child(ptr, "d");
    std::vector<RPoly> d = polys(member(j, ptr, "d", what), dp, 4, "d = [d0, d1, d2, d3]");
    RPoly s = d[2] * d[2] + d[3] * d[3];
    check_nonvanishing(s, dp, "d2(t)^2 + d3(t)^2", " (the motion matrix is singular there)");
    KinematicMotion km;
    for (int i = 0; i < 4; ++i) km.d[i] = d[i];
    return km;
  }
  if (type == "euler") {
    check_keys(j, ptr, {"type", "e", "translation", "translation_denominator"}, what);
    const std::string ep = child(ptr, "e"), vp = child(ptr, "translation"), v3p = child(ptr, "translation_denominator");
    std::vector<RPoly> e = polys(member(j, ptr, "e", what), ep, 4, "e = [e0, e1, e2, e3]");
    std::vector<RPoly> v = polys(member(j, ptr, "translation", what), vp, 3, "translation = [v0, v1, v2]");
    const json* v3j = find(j, "translation_denominator");
    RPoly v3 = v3j ? poly(*v3j, v3p) : RPoly::constant(Rational(1));
    RPoly E = e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3];
    check_nonvanishing(E, ep, "E(t) = e0^2 + e1^2 + e2^2 + e3^2", " (the rotation is undefined there)");
    check_nonvanishing(v3, v3p, "the translation denominator v3(t)", "");
    EulerMotion em;
    for (int i = 0; i < 4; ++i) em.e[i] = e[i];
    for (int i = 0; i < 3; ++i) em.v[i] = v[i];
    em.v3 = v3;
    return em;
  }
  // cycloidal
  check_keys(j, ptr, {"type", "angle_over_pi", "translation"}, what);
  const std::string ap = child(ptr, "angle_over_pi"), trp = child(ptr, "translation");
  const json& a = array_of(member(j, ptr, "angle_over_pi", what), ap, 2, "angle_over_pi = [theta0, theta1]");
  const json& tr = array_of(member(j, ptr, "translation", what), trp, 2, "translation = [[x0, x1], [y0, y1]]");
  CycloidalMotion cm;
  cm.theta0 = number(a[0], child(ap, 0));
  cm.theta1 = number(a[1], child(ap, 1));
  const json& tx = array_of(tr[0], child(trp, 0), 2, "the x translation [x0, x1]");
  const json& ty = array_of(tr[1], child(trp, 1), 2, "the y translation [y0, y1]");
  for (std::size_t i = 0; i < 2; ++i) {
    cm.x[i] = number(tx[i], child(child(trp, 0), i));
    cm.y[i] = number(ty[i], child(child(trp, 1), i));
  }
  return cm;
}

SceneObject Reader::object(const json& j, const std::string& ptr) const {
  const std::string what = "object " + ptr.substr(1);
  require_object(j, ptr, what);
  check_keys(j, ptr, {"shape", "motion"}, what);
  const json& s = member(j, ptr, "shape", what);
  const json& m = member(j, ptr, "motion", what);
  SceneObject o;
  o.Q = shape(s, child(ptr, "shape"));
  o.motion = motion(m, child(ptr, "motion"));
  return o;
}

Instant Reader::instant(const json& j, const std::string& ptr) const {
  const std::string what = "an instant {\"approx\": ..., \"lo\": ..., \"hi\": ...}";
  if (!j.is_object()) fail(ptr, "expected " + what + ", got " + type_name(j));
  check_keys(j, ptr, {"approx", "lo", "hi"}, "an instant");
  const json& ap = member(j, ptr, "approx", "an instant");
  if (!ap.is_string()) fail(child(ptr, "approx"), "approx must be a decimal string, got " + type_name(ap));
  Instant in;
  in.approx = ap.get<std::string>();
  {  // Instant::value, for display and reports (never to decide): the approx text as a double, NaN if it is none
    char* end = nullptr;
    double v = std::strtod(in.approx.c_str(), &end);
    if (end != in.approx.c_str() && *end == '\0') in.value = v;
  }
  const json* lo = find(j, "lo");
  const json* hi = find(j, "hi");
  const bool has_lo = lo && !lo->is_null(), has_hi = hi && !hi->is_null();
  if (has_lo) in.lo = number(*lo, child(ptr, "lo"));
  if (has_hi) in.hi = number(*hi, child(ptr, "hi"));
  if (has_lo != has_hi)
    fail(ptr, std::string("lo and hi must both be rational strings (certified) or both null; here ") +
                  (has_lo ? "hi" : "lo") + " is null");
  if (has_lo && *in.lo > *in.hi) fail(ptr, "lo > hi: lo = " + in.lo->get_str() + ", hi = " + in.hi->get_str());
  return in;
}

std::vector<std::pair<Instant, Instant>> Reader::interval_list(const json& j, const std::string& ptr,
                                                               const std::string& name) const {
  if (!j.is_array()) fail(ptr, name + " must be an array of [start, end] pairs of instants, got " + type_name(j));
  std::vector<std::pair<Instant, Instant>> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string p = child(ptr, i);
    const json& pair = j[i];
    if (!pair.is_array() || pair.size() != 2)
      fail(p, "an interval of " + name + " must be [start, end], an array of 2 instants, got " +
                  (pair.is_array() ? std::to_string(pair.size()) + " entries" : type_name(pair)));
    out.emplace_back(instant(pair[0], child(p, 0)), instant(pair[1], child(p, 1)));
  }
  return out;
}

// The answer of a scene with "parameters": "independent" (scene-format.md,
// "Independent motions"): collides, s_intervals, t_intervals (each [] when
// missing); collides = false requires both empty, collides = true with an
// explicitly empty list is an error (as for intervals).
Answer Reader::independent_answer(const json& j, const std::string& ptr) {
  const std::string what = "an answer of independent motions";
  for (const char* k : {"intervals", "first_contact", "contacts", "contact_intervals"})
    if (find(j, k))
      fail(child(ptr, k),
           std::string("\"") + k +
               "\" does not apply to independent motions (\"parameters\": \"independent\"): their answer is "
               "collides, s_intervals and t_intervals");
  check_keys(j, ptr, {"collides", "s_intervals", "t_intervals"}, what);
  const json& c = member(j, ptr, "collides", what);
  if (!c.is_boolean()) fail(child(ptr, "collides"), "collides must be true or false, got " + type_name(c));
  Answer a;
  a.independent = true;
  a.collides = c.get<bool>();
  for (const char* k : {"s_intervals", "t_intervals"}) {
    const json* v = find(j, k);
    if (!v) continue;
    auto list = interval_list(*v, child(ptr, k), k);
    if (!a.collides && !list.empty()) fail(child(ptr, k), std::string("collides is false but ") + k + " is not empty");
    if (a.collides && list.empty()) fail(child(ptr, k), std::string("collides is true but ") + k + " is empty");
    (std::string(k) == "s_intervals" ? a.s_intervals : a.t_intervals) = std::move(list);
  }
  return a;
}

Answer Reader::answer(const json& j, const std::string& ptr, std::optional<bool> independent) {
  const std::string what = "an answer";
  require_object(j, ptr, what);
  if (!independent) independent = find(j, "s_intervals") || find(j, "t_intervals");
  if (*independent) return independent_answer(j, ptr);
  for (const char* k : {"s_intervals", "t_intervals"})
    if (find(j, k))
      fail(child(ptr, k),
           std::string("\"") + k +
               "\" applies to independent motions only; this scene's \"parameters\" is \"shared\" (the default)");
  check_keys(j, ptr, {"collides", "intervals", "first_contact", "contacts", "contact_intervals"}, what);
  const json& c = member(j, ptr, "collides", what);
  if (!c.is_boolean()) fail(child(ptr, "collides"), "collides must be true or false, got " + type_name(c));
  Answer a;
  a.collides = c.get<bool>();
  const std::string ip = child(ptr, "intervals"), fp = child(ptr, "first_contact"), cp = child(ptr, "contacts");
  const json* iv = find(j, "intervals");
  if (iv) {
    if (!iv->is_array())
      fail(ip, "intervals must be an array of [start, end] pairs of instants, got " + type_name(*iv));
    for (std::size_t i = 0; i < iv->size(); ++i) {
      const std::string p = child(ip, i);
      const json& pair = (*iv)[i];
      if (!pair.is_array() || pair.size() != 2)
        fail(p, "an interval must be [start, end], an array of 2 instants, got " +
                    (pair.is_array() ? std::to_string(pair.size()) + " entries" : type_name(pair)));
      a.intervals.emplace_back(instant(pair[0], child(p, 0)), instant(pair[1], child(p, 1)));
    }
  }
  // contact_intervals (docs/answer-format.md): [start, end] pairs like intervals; missing = [].
  if (const json* ci = find(j, "contact_intervals")) {
    const std::string cip = child(ptr, "contact_intervals");
    if (!ci->is_array())
      fail(cip, "contact_intervals must be an array of [start, end] pairs of instants, got " + type_name(*ci));
    for (std::size_t i = 0; i < ci->size(); ++i) {
      const std::string p = child(cip, i);
      const json& pair = (*ci)[i];
      if (!pair.is_array() || pair.size() != 2)
        fail(p, "a contact interval must be [start, end], an array of 2 instants, got " +
                    (pair.is_array() ? std::to_string(pair.size()) + " entries" : type_name(pair)));
      a.contact_intervals.emplace_back(instant(pair[0], child(p, 0)), instant(pair[1], child(p, 1)));
    }
    if (!a.collides && !a.contact_intervals.empty()) fail(cip, "collides is false but contact_intervals is not empty");
  }
  const json* fc = find(j, "first_contact");
  if (fc && !fc->is_null()) a.first_contact = instant(*fc, fp);
  const json* ct = find(j, "contacts");
  if (ct) {
    if (!ct->is_array()) fail(cp, "contacts must be an array of instants, got " + type_name(*ct));
    for (std::size_t i = 0; i < ct->size(); ++i) a.contacts.push_back(instant((*ct)[i], child(cp, i)));
  }
  if (!a.collides) {
    if (!a.intervals.empty()) fail(ip, "collides is false but intervals is not empty");
    if (a.first_contact) fail(fp, "collides is false but first_contact is not null");
    if (!a.contacts.empty()) fail(cp, "collides is false but contacts is not empty");
  } else if (iv && a.intervals.empty()) {
    fail(ip, "collides is true but intervals is empty");
  }
  return a;
}

Scene Reader::scene(const json& root) {
  const std::string fmt = "ellipse-ccd-scene/1";
  if (!root.is_object()) fail("", "a scene must be a JSON object {...}, got " + type_name(root));
  const json* f = find(root, "format");
  if (!f) fail("", "missing required key \"format\" (it must be \"" + fmt + "\")");
  if (!f->is_string() || f->get_ref<const std::string&>() != fmt)
    fail("/format", "unsupported format " + (f->is_string() ? quote(f->get<std::string>()) : type_name(*f)) +
                        "; this program reads \"" + fmt + "\"");
  const std::string what = "a scene";
  check_keys(root, "", {"format", "name", "dim", "a", "b", "note", "parameters", "answer"}, what);
  const json& name = member(root, "", "name", what);
  const json& dim = member(root, "", "dim", what);
  const json& a = member(root, "", "a", what);
  const json& b = member(root, "", "b", what);

  Scene s;
  s.path = label_;
  if (!name.is_string() || name.get_ref<const std::string&>().empty())
    fail("/name", "name must be a non-empty string, got " + (name.is_string() ? std::string("\"\"") : type_name(name)));
  s.name = name.get<std::string>();
  Rational d = number(dim, "/dim");
  if (d != 2 && d != 3) fail("/dim", "dim must be 2 (ellipses) or 3 (ellipsoids), got " + d.get_str());
  dim_ = d == 2 ? 2 : 3;
  s.dim = dim_;
  if (const json* note = find(root, "note")) {
    if (!note->is_string()) fail("/note", "note must be a string, got " + type_name(*note));
    s.note = note->get<std::string>();
  }
  if (const json* par = find(root, "parameters")) {  // scene-format.md, "Independent motions"
    if (!par->is_string() ||
        (par->get_ref<const std::string&>() != "shared" && par->get_ref<const std::string&>() != "independent"))
      fail("/parameters",
           "parameters must be \"shared\" (one t for both objects, the default) or \"independent\" "
           "(A(s) and B(t)), got " +
               (par->is_string() ? quote(par->get<std::string>()) : type_name(*par)));
    s.independent = par->get_ref<const std::string&>() == "independent";
  }
  s.a = object(a, "/a");
  s.b = object(b, "/b");
  if (const json* ans = find(root, "answer"); ans && !ans->is_null()) s.answer = answer(*ans, "/answer", s.independent);
  return s;
}

}  // namespace

Answer answer_from_json(const json& j, const std::string& file_label, const std::string& place) {
  Reader r(file_label, nullptr);
  try {
    return r.answer(j, place);
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {  // safety net: never let a library exception escape
    r.fail(place, std::string("internal error while reading the answer: ") + e.what());
  }
}

Instant instant_from_json(const json& j, const std::string& file_label, const std::string& place) {
  Reader r(file_label, nullptr);
  return r.instant(j, place);
}

Scene parse_scene(const std::string& json_text, const std::string& file_label) {
  StrictJson doc = parse_strict_json(json_text, file_label);
  Reader r(file_label, &doc.raw_numbers);
  try {
    Scene s = r.scene(doc.root);
    s.source_text = json_text;  // certify needs the scene's own JSON (api/certify.hpp)
    return s;
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {  // safety net
    throw SceneError(file_label + ": top level: internal error while reading the scene: " + std::string(e.what()));
  }
}

Rational json_rational(const StrictJson& doc, const json& j, const std::string& file_label, const std::string& place) {
  return Reader(file_label, &doc.raw_numbers).number_at(j, place);
}
std::vector<std::vector<Rational>> json_shape(const StrictJson& doc, const json& j, const std::string& file_label,
                                              const std::string& place, int dim) {
  return Reader(file_label, &doc.raw_numbers).shape_of_dim(j, place, dim);
}

Scene read_scene_file(const std::string& path) { return parse_scene(read_file_bytes(path), path); }

}  // namespace eccd
