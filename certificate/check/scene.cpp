// The checker's own reading of a scene file (certificate/check/scene.hpp).
#include "certificate/check/scene.hpp"

#include <cctype>

namespace eccd::check {

namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& label, const std::string& place, const std::string& what) {
  throw SceneReadError(label + ": " + (place.empty() ? std::string("top level") : place) + ": " + what);
}

const json& member(const json& j, const char* key, const std::string& label, const std::string& place) {
  if (!j.is_object()) fail(label, place, "expected an object");
  if (!j.contains(key)) fail(label, place, std::string("missing key \"") + key + "\"");
  return j.at(key);
}

bool all_digits(const std::string& s, std::size_t a, std::size_t b) {
  if (a >= b) return false;
  for (std::size_t i = a; i < b; ++i)
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
  return true;
}

// "[+-]digits", "[+-]digits/digits" (non-zero denominator) or a decimal "[+-][digits][.digits][e[+-]digits]".
bool parse_exact(const std::string& s, mpq_class& out) {
  if (s.empty() || s.size() > 100000) return false;
  std::size_t i = 0;
  bool neg = false;
  if (s[0] == '+' || s[0] == '-') neg = s[i++] == '-';
  const std::size_t slash = s.find('/');
  if (slash != std::string::npos) {
    if (!all_digits(s, i, slash) || !all_digits(s, slash + 1, s.size())) return false;
    mpz_class n(s.substr(i, slash - i), 10), d(s.substr(slash + 1), 10);
    if (d == 0) return false;
    out = mpq_class(neg ? mpz_class(-n) : n, d);
    out.canonicalize();
    return true;
  }
  std::string digits;
  long places = 0;
  bool dot = false, any = false;
  for (; i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || (s[i] == '.' && !dot)); ++i) {
    if (s[i] == '.') {
      dot = true;
      continue;
    }
    digits += s[i];
    any = true;
    if (dot) ++places;
  }
  if (!any) return false;
  long ex = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) eneg = s[i++] == '-';
    const std::size_t start = i;
    for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i)
      if (ex <= 100000) ex = ex * 10 + (s[i] - '0');
    if (i == start || ex > 10000) return false;
    if (eneg) ex = -ex;
  }
  if (i != s.size()) return false;
  const long e = ex - places;
  mpz_class m(digits, 10), p10;
  mpz_ui_pow_ui(p10.get_mpz_t(), 10, (unsigned long)(e < 0 ? -e : e));
  if (neg) m = -m;
  out = e < 0 ? mpq_class(m, p10) : mpq_class(m * p10);
  out.canonicalize();
  return true;
}

QPoly bernstein_to_power(const std::vector<mpq_class>& b) {
  const int n = int(b.size()) - 1;
  QPoly p;
  for (int i = 0; i <= n; ++i) {
    // C(n, i) t^i (1 - t)^(n - i)
    mpz_class binom;
    mpz_bin_uiui(binom.get_mpz_t(), (unsigned long)n, (unsigned long)i);
    std::vector<mpq_class> term(std::size_t(n) + 1);
    for (int k = 0; k <= n - i; ++k) {
      mpz_class c;
      mpz_bin_uiui(c.get_mpz_t(), (unsigned long)(n - i), (unsigned long)k);
      term[std::size_t(i + k)] = mpq_class((k % 2 ? -1 : 1) * c * binom) * b[std::size_t(i)];
    }
    p = p + QPoly(std::move(term));
  }
  return p;
}

QPoly poly_of(const json& j, const std::string& label, const std::string& place) {
  if (j.is_object()) {
    const json& b = member(j, "bernstein", label, place);
    if (!b.is_array() || b.empty()) fail(label, place + "/bernstein", "expected a non-empty array of coefficients");
    std::vector<mpq_class> c;
    for (std::size_t i = 0; i < b.size(); ++i)
      c.push_back(scene_number(b[i], label, place + "/bernstein/" + std::to_string(i)));
    return bernstein_to_power(c);
  }
  if (j.is_array()) {
    if (j.empty()) fail(label, place, "expected a non-empty array of coefficients");
    std::vector<mpq_class> c;
    for (std::size_t i = 0; i < j.size(); ++i) c.push_back(scene_number(j[i], label, place + "/" + std::to_string(i)));
    return QPoly(std::move(c));
  }
  return QPoly::constant(scene_number(j, label, place));
}

QMatrix shape_of(const json& j, int H, const std::string& label, const std::string& place) {
  QMatrix q(static_cast<std::size_t>(H), std::vector<mpq_class>(static_cast<std::size_t>(H)));
  if (!j.is_object() || j.size() != 1)
    fail(label, place, "a shape takes exactly one of semi_axes, semi_axes_squared, matrix");
  if (j.contains("semi_axes") || j.contains("semi_axes_squared")) {
    const bool squared = j.contains("semi_axes_squared");
    const json& v = j.begin().value();
    const std::string p = place + "/" + j.begin().key();
    if (!v.is_array() || int(v.size()) != H - 1) fail(label, p, "expected " + std::to_string(H - 1) + " entries");
    for (int i = 0; i < H - 1; ++i) {
      mpq_class x = scene_number(v[std::size_t(i)], label, p + "/" + std::to_string(i));
      if (sgn(x) <= 0) fail(label, p + "/" + std::to_string(i), "must be positive");
      q[std::size_t(i)][std::size_t(i)] = squared ? mpq_class(1 / x) : mpq_class(1 / (x * x));
    }
    q[std::size_t(H - 1)][std::size_t(H - 1)] = -1;
    return q;
  }
  const json& m = member(j, "matrix", label, place);
  if (!m.is_array() || int(m.size()) != H) fail(label, place + "/matrix", "expected " + std::to_string(H) + " rows");
  for (int r = 0; r < H; ++r) {
    if (!m[std::size_t(r)].is_array() || int(m[std::size_t(r)].size()) != H)
      fail(label, place + "/matrix/" + std::to_string(r), "expected " + std::to_string(H) + " entries");
    for (int c = 0; c < H; ++c)
      q[std::size_t(r)][std::size_t(c)] = scene_number(
          m[std::size_t(r)][std::size_t(c)], label, place + "/matrix/" + std::to_string(r) + "/" + std::to_string(c));
  }
  for (int r = 0; r < H; ++r)
    for (int c = 0; c < r; ++c)
      if (q[std::size_t(r)][std::size_t(c)] != q[std::size_t(c)][std::size_t(r)])
        fail(label, place + "/matrix", "not symmetric");
  return q;
}

PolyMatrix identity(int H) {
  PolyMatrix m(static_cast<std::size_t>(H), std::vector<QPoly>(static_cast<std::size_t>(H)));
  for (int i = 0; i < H; ++i) m[std::size_t(i)][std::size_t(i)] = QPoly::constant(1);
  return m;
}

void motion_of(const json& j, int H, CheckObject& o, bool& cycloidal, const std::string& label,
               const std::string& place) {
  const json& type = member(j, "type", label, place);
  if (!type.is_string()) fail(label, place + "/type", "expected a string");
  o.motion_type = type.get<std::string>();
  auto P = [&](const json& x, const std::string& p) { return poly_of(x, label, p); };
  if (o.motion_type == "static") {
    o.M = identity(H);
  } else if (o.motion_type == "matrix") {
    const json& m = member(j, "m", label, place);
    if (!m.is_array() || int(m.size()) != H) fail(label, place + "/m", "expected " + std::to_string(H) + " rows");
    o.M = identity(H);
    for (int r = 0; r < H; ++r) {
      if (!m[std::size_t(r)].is_array() || int(m[std::size_t(r)].size()) != H)
        fail(label, place + "/m/" + std::to_string(r), "expected " + std::to_string(H) + " entries");
      for (int c = 0; c < H; ++c)
        o.M[std::size_t(r)][std::size_t(c)] =
            P(m[std::size_t(r)][std::size_t(c)], place + "/m/" + std::to_string(r) + "/" + std::to_string(c));
    }
    for (int c = 0; c + 1 < H; ++c)
      if (!o.M[std::size_t(H - 1)][std::size_t(c)].zero())
        fail(label, place + "/m", "the last row must be (0, ..., 0, w(t))");
  } else if (o.motion_type == "kinematic") {
    if (H != 3) fail(label, place, "a kinematic motion is 2D only");
    const json& d = member(j, "d", label, place);
    if (!d.is_array() || d.size() != 4) fail(label, place + "/d", "expected 4 polynomials");
    QPoly d0 = P(d[0], place + "/d/0"), d1 = P(d[1], place + "/d/1"), d2 = P(d[2], place + "/d/2"),
          d3 = P(d[3], place + "/d/3");
    const mpq_class two = 2;
    QPoly c = d2 * d2 - d3 * d3, s = two * (d2 * d3);
    o.M = {{c, s, two * (d0 * d3 - d1 * d2)},
           {mpq_class(-1) * s, c, two * (d0 * d2 + d1 * d3)},
           {QPoly(), QPoly(), d2 * d2 + d3 * d3}};
  } else if (o.motion_type == "euler") {
    if (H != 4) fail(label, place, "an euler motion is 3D only");
    const json& ej = member(j, "e", label, place);
    const json& vj = member(j, "translation", label, place);
    if (!ej.is_array() || ej.size() != 4) fail(label, place + "/e", "expected 4 polynomials");
    if (!vj.is_array() || vj.size() != 3) fail(label, place + "/translation", "expected 3 polynomials");
    QPoly e[4], v[3];
    for (int i = 0; i < 4; ++i) e[i] = P(ej[std::size_t(i)], place + "/e/" + std::to_string(i));
    for (int i = 0; i < 3; ++i) v[i] = P(vj[std::size_t(i)], place + "/translation/" + std::to_string(i));
    QPoly v3 = j.contains("translation_denominator")
                   ? P(j["translation_denominator"], place + "/translation_denominator")
                   : QPoly::constant(1);
    const mpq_class two = 2;
    QPoly e00 = e[0] * e[0], e11 = e[1] * e[1], e22 = e[2] * e[2], e33 = e[3] * e[3];
    QPoly R[3][3] = {{e00 + e11 - e22 - e33, two * (e[1] * e[2] - e[0] * e[3]), two * (e[1] * e[3] + e[0] * e[2])},
                     {two * (e[1] * e[2] + e[0] * e[3]), e00 - e11 + e22 - e33, two * (e[2] * e[3] - e[0] * e[1])},
                     {two * (e[1] * e[3] - e[0] * e[2]), two * (e[2] * e[3] + e[0] * e[1]), e00 - e11 - e22 + e33}};
    QPoly E = e00 + e11 + e22 + e33;
    o.M = identity(4);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) o.M[std::size_t(r)][std::size_t(c)] = v3 * R[r][c];
      o.M[std::size_t(r)][3] = E * v[r];
      o.M[3][std::size_t(r)] = QPoly();
    }
    o.M[3][3] = E * v3;
  } else if (o.motion_type == "cycloidal") {
    cycloidal = true;
    if (H != 3) fail(label, place, "a cycloidal motion is 2D only");
    const json& a = member(j, "angle_over_pi", label, place);
    const json& tr = member(j, "translation", label, place);
    if (!a.is_array() || a.size() != 2) fail(label, place + "/angle_over_pi", "expected [theta0, theta1]");
    if (!tr.is_array() || tr.size() != 2 || !tr[0].is_array() || tr[0].size() != 2 || !tr[1].is_array() ||
        tr[1].size() != 2)
      fail(label, place + "/translation", "expected [[x0, x1], [y0, y1]]");
    o.cycloid = {scene_number(a[0], label, place + "/angle_over_pi/0"),
                 scene_number(a[1], label, place + "/angle_over_pi/1"),
                 scene_number(tr[0][0], label, place + "/translation/0/0"),
                 scene_number(tr[0][1], label, place + "/translation/0/1"),
                 scene_number(tr[1][0], label, place + "/translation/1/0"),
                 scene_number(tr[1][1], label, place + "/translation/1/1")};
  } else {
    fail(label, place + "/type", "unknown motion type \"" + o.motion_type + "\"");
  }
}

}  // namespace

mpq_class scene_number(const json& j, const std::string& label, const std::string& place) {
  mpq_class q;
  if (j.is_number_integer()) {
    if (j.is_number_unsigned()) return mpq_class(mpz_class(std::to_string(j.get<std::uint64_t>()), 10));
    return mpq_class(mpz_class(std::to_string(j.get<std::int64_t>()), 10));
  }
  if (j.is_string() && parse_exact(j.get<std::string>(), q)) return q;
  if (j.is_string() && j.get<std::string>().rfind("json-float:", 0) == 0)
    fail(label, place, "a JSON number with a fraction part or exponent is not exact: write it as a string");
  fail(label, place, "expected an exact number (\"-63\", \"3/7\", \"1.8\"), got " + j.dump().substr(0, 40));
}

CheckScene read_check_scene(const json& doc, const std::string& label) {
  CheckScene s;
  s.doc = doc;
  if (!doc.is_object()) fail(label, "", "expected a scene object");
  const json& fmt = member(doc, "format", label, "");
  if (fmt != "ellipse-ccd-scene/1") fail(label, "/format", "expected \"ellipse-ccd-scene/1\"");
  const mpq_class dim = scene_number(member(doc, "dim", label, ""), label, "/dim");
  if (dim != 2 && dim != 3) fail(label, "/dim", "expected 2 or 3");
  s.dim = int(dim.get_num().get_si());
  if (doc.contains("parameters")) {
    const json& p = doc["parameters"];
    if (p != "shared" && p != "independent") fail(label, "/parameters", "expected \"shared\" or \"independent\"");
    s.independent = p == "independent";
  }
  const int H = s.dim + 1;
  for (const char* k : {"a", "b"}) {
    CheckObject& o = k[0] == 'a' ? s.a : s.b;
    const json& obj = member(doc, k, label, "");
    const std::string place = std::string("/") + k;
    o.Q = shape_of(member(obj, "shape", label, place), H, label, place + "/shape");
    motion_of(member(obj, "motion", label, place), H, o, s.cycloidal, label, place + "/motion");
  }
  return s;
}

}  // namespace eccd::check
