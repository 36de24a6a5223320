// The building blocks the scene generators share (see compare/scene_building.hpp).
#include "compare/scene_building.hpp"

#include "kernel/bernstein.hpp"
#include "kernel/sturm.hpp"

#include <algorithm>
#include <cmath>

namespace eccd::scene_building {

RPoly constant(const Rational& c) { return RPoly::constant(c); }
RPoly from_bernstein(const std::vector<Rational>& ctrl) {
  Bern<Rational> b;
  b.b = ctrl;
  return to_power(b);
}
RPoly random_poly(Rng& r, int deg, long lo, long hi, long den) {
  std::vector<Rational> c;
  for (int i = 0; i <= deg; ++i) c.push_back(r.frac(lo, hi, den));
  return RPoly(c);
}
bool vanishes_on_unit_interval(const RPoly& p) {
  return p.is_zero() || count_roots_closed(p, Rational(0), Rational(1)) != 0;
}
// The weight of a motion (d2² + d3², E, det L) must not come close to zero on
// [0, 1]: max/min <= 16 at 65 instants. A weight that nearly vanishes gives a
// motion that spins through most of its rotation in a moment, and scales f by
// a factor of huge range; such motions are not what the families are about.
// (A generation choice only: the exact Sturm check above decides validity.)
bool badly_scaled(const RPoly& w) {
  if (vanishes_on_unit_interval(w)) return true;
  double lo = 1e300, hi = 0;
  for (int k = 0; k <= 64; ++k) {
    double v = std::abs(w(Rational(k, 64)).get_d());
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return !(hi <= 16 * lo);
}

Rational dot(const Vec& a, const Vec& b) {
  Rational s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// A rational unit vector: 2D from a rational half-angle tangent, 3D as the
// image of e_x under the rotation of an integer quaternion.
Vec random_unit(Rng& r, int dim) {
  while (true) {
    if (dim == 2) {
      Rational u = r.frac(-12, 12, 8);
      Rational w = 1 + u * u;
      return {(1 - u * u) / w, 2 * u / w};
    }
    long q[4] = {r.uniform(-4, 4), r.uniform(-4, 4), r.uniform(-4, 4), r.uniform(-4, 4)};
    long e = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    if (e == 0) continue;
    Rational E(e);
    return {Rational(q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3]) / E,
            Rational(2 * (q[1] * q[2] + q[0] * q[3])) / E, Rational(2 * (q[1] * q[3] - q[0] * q[2])) / E};
  }
}

// Squared semi-axes alpha and the point x on x^T diag(1/alpha) x = 1 whose
// outward normal is the unit vector n: x_i = alpha_i n_i / r with
// r^2 = sum alpha_i n_i^2 (one alpha solved so that r is rational).

Tangency shape_with_normal(Rng& r, const Vec& n) {
  int dim = int(n.size());
  int j = 0;
  for (int i = 1; i < dim; ++i)
    if (abs(n[i]) > abs(n[j])) j = i;
  while (true) {
    Tangency t;
    t.alpha.assign(dim, Rational(0));
    Rational rest = 0;
    for (int i = 0; i < dim; ++i)
      if (i != j) {
        t.alpha[i] = r.frac(2, 16, 4);
        rest += t.alpha[i] * n[i] * n[i];
      }
    Rational nj2 = n[j] * n[j];
    Rational want = rest + nj2 * r.frac(3, 10, 4);
    double target = std::sqrt(want.get_d());  // picks r only
    Rational rad(long(std::ceil(target * 16)), 16);
    rad.canonicalize();
    t.alpha[j] = (rad * rad - rest) / nj2;
    if (t.alpha[j] < Rational(1, 4) || t.alpha[j] > 6) continue;
    Rational check = 0;
    for (int i = 0; i < dim; ++i) {
      t.point.push_back(t.alpha[i] * n[i] / rad);
      check += t.point[i] * t.point[i] / t.alpha[i];
    }
    if (check != 1) throw std::logic_error("generator: tangency point not on the ellipse");
    return t;
  }
}

Mat identity(int n) {
  Mat m(n, Vec(n, Rational(0)));
  for (int i = 0; i < n; ++i) m[i][i] = 1;
  return m;
}
Mat mat_mul(const Mat& a, const Mat& b) {
  std::size_t n = a.size();
  Mat r(n, Vec(n, Rational(0)));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}
Vec mat_vec(const Mat& a, const Vec& v) {
  Vec r(a.size(), Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < v.size(); ++j) r[i] += a[i][j] * v[j];
  return r;
}
Mat householder(const Vec& w) {
  Mat h = identity(int(w.size()));
  Rational ww = dot(w, w);
  for (std::size_t i = 0; i < w.size(); ++i)
    for (std::size_t j = 0; j < w.size(); ++j) h[i][j] -= 2 * w[i] * w[j] / ww;
  return h;
}
// A random rational vector orthogonal to the unit vector n (3D).
Vec orthogonal_to(Rng& r, const Vec& n) {
  while (true) {
    Vec u{r.frac(-4, 4, 1), r.frac(-4, 4, 1), r.frac(-4, 4, 1)};
    Rational un = dot(u, n);
    for (int i = 0; i < 3; ++i) u[i] -= un * n[i];
    if (dot(u, u) != 0) return u;
  }
}
// A rational rotation R with R m = -n (unit vectors m, n).
Mat rotation_taking(Rng& r, const Vec& m, const Vec& n) {
  Mat R;
  if (m.size() == 2) {
    Rational c = -dot(n, m), s = n[0] * m[1] - n[1] * m[0];
    R = {{c, -s}, {s, c}};
  } else {
    Vec w{m[0] + n[0], m[1] + n[1], m[2] + n[2]};
    if (dot(w, w) == 0) throw std::domain_error("m = -n");
    R = mat_mul(householder(orthogonal_to(r, n)), householder(w));  // reflections: det +1
  }
  Vec img = mat_vec(R, m);
  for (std::size_t i = 0; i < m.size(); ++i)
    if (img[i] != -n[i]) throw std::logic_error("generator: rotation does not take m to -n");
  return R;
}

// Homogeneous polynomial matrices (size dim + 1).
HMat hmul(const HMat& a, const HMat& b) {
  std::size_t n = a.size();
  HMat r(n, std::vector<RPoly>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k)
        if (!a[i][k].is_zero() && !b[k][j].is_zero()) r[i][j] += a[i][k] * b[k][j];
  return r;
}
HMat hconst(const Mat& rot, const Vec& shift) {
  std::size_t d = rot.size();
  HMat h(d + 1, std::vector<RPoly>(d + 1));
  for (std::size_t i = 0; i < d; ++i) {
    for (std::size_t j = 0; j < d; ++j) h[i][j] = constant(rot[i][j]);
    h[i][d] = constant(shift[i]);
  }
  h[d][d] = constant(1);
  return h;
}

int hdegree(const HMat& h) {
  int d = 0;
  for (auto& row : h)
    for (auto& e : row) d = std::max(d, e.degree());
  return d;
}

// ---- JSON ------------------------------------------------------------------

thread_local bool g_decimal_output = false;
std::string number_text(const Rational& x) { return g_decimal_output ? exact_decimal(x) : Rational(x).get_str(); }

nlohmann::ordered_json poly_json(const RPoly& p) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  if (p.is_zero()) a.push_back("0");
  for (const auto& c : p.c) a.push_back(number_text(Rational(c)));
  return a;
}
// A degree-1 polynomial given by its key values (Bernstein form on [0, 1]).
nlohmann::ordered_json bern_json(const Rational& c0, const Rational& c1) {
  nlohmann::ordered_json j;
  j["bernstein"] = {number_text(c0), number_text(c1)};
  return j;
}
nlohmann::ordered_json motion_json(const Motion& m) {
  nlohmann::ordered_json j;
  if (auto* k = std::get_if<KinematicMotion>(&m)) {
    j["type"] = "kinematic";
    for (auto& d : k->d) j["d"].push_back(poly_json(d));
  } else if (auto* e = std::get_if<EulerMotion>(&m)) {
    j["type"] = "euler";
    for (auto& x : e->e) j["e"].push_back(poly_json(x));
    for (auto& x : e->v) j["translation"].push_back(poly_json(x));
    j["translation_denominator"] = poly_json(e->v3);
  } else if (auto* mm = std::get_if<MatrixMotion>(&m)) {
    j["type"] = "matrix";
    for (auto& row : mm->m) {
      nlohmann::ordered_json jr = nlohmann::ordered_json::array();
      for (auto& x : row) jr.push_back(poly_json(x));
      j["m"].push_back(jr);
    }
  } else {
    j["type"] = "static";
  }
  return j;
}
nlohmann::ordered_json shape_json(const Vec& alpha) {
  nlohmann::ordered_json j;
  for (auto& a : alpha) j["semi_axes_squared"].push_back(Rational(a).get_str());
  return j;
}
nlohmann::ordered_json semi_axes_json(const Vec& axes) {
  nlohmann::ordered_json j;
  for (auto& a : axes) j["semi_axes"].push_back(number_text(a));
  return j;
}

Vec random_axes(Rng& r, int dim) {
  Vec a;
  for (int i = 0; i < dim; ++i) a.push_back(r.frac(2, 16, 4));  // squared semi-axes in [1/2, 4]
  return a;
}

int motion_degree(int dim, const Motion& m) { return dim == 2 ? hdegree(to_hmat<3>(m)) : hdegree(to_hmat<4>(m)); }

}  // namespace eccd::scene_building
