// The data of `eccd plot` (see app/plot_data.hpp; how each part is computed:
// the opening comment of app/plot.cpp).
#include "app/plot_data.hpp"

#include "api/solve.hpp"
#include "api/static_status.hpp"
#include "io/solution_json.hpp"
#include "number/double_traits.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/cycloidal_motion.hpp"
#include "kernel/budget.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "kernel/motion.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/quadric.hpp"
#include "io/scene_reader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace eccd::plot_data {
namespace {

using json = nlohmann::json;

constexpr int kDeltaSamples = 2000;  // 2D: Δ at k / 2000, k = 0..2000, plus the critical instants
constexpr int kGrid = 200;           // 3D: F on (i / 200, k / 200), plus the critical instants in t
constexpr int kFine = 4000;          // 3D: fine pass in u that finds where F > 0
constexpr int kOutline = 181;        // points per outline
constexpr int kPath = 241;           // points per centre path

// Short decimal for the data file (7 significant digits; the drawing needs no more).
double round7(double x) {
  if (!std::isfinite(x) || x == 0) return x;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", x);
  return std::strtod(buf, nullptr);
}
json rounded(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(round7(x));
  return a;
}

// p at each rational t, exactly: integer Horner on L·p (L = lcm of the denominators).
std::vector<Rational> exact_values(const Poly<Rational>& p, const std::vector<Rational>& ts) {
  std::vector<Rational> out(ts.size(), Rational(0));
  if (p.is_zero()) return out;
  mpz_class l = 1;
  for (const auto& c : p.c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  std::vector<mpz_class> a;
  for (const auto& c : p.c) a.push_back(c.get_num() * (l / c.get_den()));
  const int d = p.degree();
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const mpz_class& num = ts[k].get_num();
    const mpz_class& den = ts[k].get_den();
    mpz_class s = a[d], dp = 1;
    for (int i = d - 1; i >= 0; --i) {
      dp *= den;
      s = s * num + a[i] * dp;
    }
    Rational v(s, dp * l);
    v.canonicalize();
    out[k] = v;
  }
  return out;
}

// Every value divided (exactly) by the largest absolute value, then rounded to double.
std::vector<double> normalised(const std::vector<Rational>& v, Rational& max_abs) {
  max_abs = 0;
  for (const auto& x : v) max_abs = std::max<Rational>(max_abs, abs(x));
  std::vector<double> r(v.size(), 0.0);
  if (max_abs == 0) return r;
  for (std::size_t k = 0; k < v.size(); ++k) r[k] = scalar_traits<double>::from_rational(Rational(v[k] / max_abs));
  return r;
}

// The grid k / n, k = 0..n, with extra instants (approximations) merged in, sorted, no duplicates.
std::vector<Rational> grid_with(int n, const std::vector<double>& extra) {
  std::vector<Rational> ts;
  for (int k = 0; k <= n; ++k) {
    Rational t(k, n);
    t.canonicalize();
    ts.push_back(t);
  }
  for (double x : extra)
    if (x >= 0 && x <= 1) ts.push_back(Rational(x));  // exact value of the double
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

// ---- small dense linear algebra (N <= 4) ----

template <class T>
using Mat = std::vector<std::vector<T>>;

// Gauss-Jordan with pivoting, exact; throws if singular.
Mat<Rational> inverse(Mat<Rational> a) {
  using T = Rational;
  const std::size_t n = a.size();
  Mat<T> inv(n, std::vector<T>(n, T(0)));
  for (std::size_t i = 0; i < n; ++i) inv[i][i] = T(1);
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (a[p][c] == 0 && a[r][c] != 0) p = r;
    if (a[p][c] == T(0)) throw std::runtime_error("singular matrix while computing an outline");
    std::swap(a[p], a[c]);
    std::swap(inv[p], inv[c]);
    T piv = a[c][c];
    for (std::size_t j = 0; j < n; ++j) {
      a[c][j] = a[c][j] / piv;
      inv[c][j] = inv[c][j] / piv;
    }
    for (std::size_t r = 0; r < n; ++r) {
      if (r == c) continue;
      T f = a[r][c];
      if (f == T(0)) continue;
      for (std::size_t j = 0; j < n; ++j) {
        a[r][j] = a[r][j] - f * a[c][j];
        inv[r][j] = inv[r][j] - f * inv[c][j];
      }
    }
  }
  return inv;
}

double det3(const Mat<double>& m, int r0, int r1, int r2, int c0, int c1, int c2) {
  return m[r0][c0] * (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) -
         m[r0][c1] * (m[r1][c0] * m[r2][c2] - m[r1][c2] * m[r2][c0]) +
         m[r0][c2] * (m[r1][c0] * m[r2][c1] - m[r1][c1] * m[r2][c0]);
}

// A null vector of a (nearly) rank-3 4x4 matrix: the largest column of its adjugate.
std::vector<double> null_vector4(const Mat<double>& m) {
  std::vector<double> best(4, 0.0);
  double bestn = -1;
  for (int j = 0; j < 4; ++j) {  // column j of adj(m): cofactors C(j, i), i = 0..3
    std::vector<double> col(4);
    for (int i = 0; i < 4; ++i) {
      int rr[3], cc[3];
      for (int r = 0, k = 0; r < 4; ++r)
        if (r != j) rr[k++] = r;
      for (int c = 0, k = 0; c < 4; ++c)
        if (c != i) cc[k++] = c;
      double d = det3(m, rr[0], rr[1], rr[2], cc[0], cc[1], cc[2]);
      col[i] = ((i + j) % 2 ? -d : d);
    }
    double n = 0;
    for (double x : col) n += std::fabs(x);
    if (n > bestn) {
      bestn = n;
      best = col;
    }
  }
  return best;
}

// ---- outlines ----

// An object in its own frame: centre x0 and Σ, the solid being (x - x0)ᵀ Σ⁻¹ (x - x0) <= 1.
struct Shape {
  std::vector<double> x0;
  Mat<double> sigma;
};

Shape object_shape(const SceneObject& o, int d) {
  Mat<Rational> s(d, std::vector<Rational>(d));
  std::vector<Rational> b(d);
  for (int i = 0; i < d; ++i) {
    for (int j = 0; j < d; ++j) s[i][j] = o.Q[i][j];
    b[i] = o.Q[i][d];
  }
  const Rational c = o.Q[d][d];
  Mat<Rational> si = inverse(s);
  std::vector<Rational> x0(d, Rational(0));
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) x0[i] -= si[i][j] * b[j];
  Rational k = c;
  for (int i = 0; i < d; ++i) k += b[i] * x0[i];  // Q's value at the centre: negative for a real solid
  Shape sh;
  sh.x0.resize(d);
  sh.sigma.assign(d, std::vector<double>(d));
  for (int i = 0; i < d; ++i) {
    sh.x0[i] = scalar_traits<double>::from_rational(x0[i]);
    for (int j = 0; j < d; ++j) sh.sigma[i][j] = scalar_traits<double>::from_rational(Rational(-k * si[i][j]));
  }
  return sh;
}

// The world-frame centre and the projected 2x2 Σ at t, from M(t) = [[w L, w v], [0, w]].
template <int N>
std::pair<std::vector<double>, Mat<double>> moved(const Shape& sh, const PolyMatrix<double, N>& m, double t) {
  constexpr int d = N - 1;
  const double w = m[d][d](t);
  double L[d][d], v[d];
  for (int i = 0; i < d; ++i) {
    for (int j = 0; j < d; ++j) L[i][j] = m[i][j](t) / w;
    v[i] = m[i][d](t) / w;
  }
  std::vector<double> c(d, 0.0);
  for (int i = 0; i < d; ++i) {
    c[i] = v[i];
    for (int j = 0; j < d; ++j) c[i] += L[i][j] * sh.x0[j];
  }
  Mat<double> s2(2, std::vector<double>(2, 0.0));  // (L Σ Lᵀ) restricted to x, y
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < d; ++k)
        for (int l = 0; l < d; ++l) s2[i][j] += L[i][k] * sh.sigma[k][l] * L[j][l];
  return {c, s2};
}

json outline_json(const std::vector<double>& c, const Mat<double>& s2) {
  const double a = s2[0][0], b = 0.5 * (s2[0][1] + s2[1][0]), e = s2[1][1];
  const double th = 0.5 * std::atan2(2 * b, a - e);
  const double mid = 0.5 * (a + e), rad = std::hypot(0.5 * (a - e), b);
  const double r1 = std::sqrt(std::max(0.0, mid + rad)), r2 = std::sqrt(std::max(0.0, mid - rad));
  std::vector<double> xs, ys;
  for (int k = 0; k < kOutline; ++k) {
    double ph = 2 * std::numbers::pi * k / (kOutline - 1);
    double p = r1 * std::cos(ph), q = r2 * std::sin(ph);
    xs.push_back(c[0] + p * std::cos(th) - q * std::sin(th));
    ys.push_back(c[1] + p * std::sin(th) + q * std::cos(th));
  }
  return {{"centre", {round7(c[0]), round7(c[1])}}, {"x", rounded(xs)}, {"y", rounded(ys)}};
}

// Snapshot instants: K evenly spaced, every contact, the first contact; the
// flag marks the contact instants (drawn thick).
std::vector<std::pair<double, bool>> snapshot_instants(int k, const Solution& rep) {
  std::vector<std::pair<double, bool>> ts;
  if (k == 1) ts.push_back({0.0, false});
  for (int i = 0; k > 1 && i < k; ++i) ts.push_back({double(i) / (k - 1), false});
  std::vector<std::pair<double, bool>> special;
  for (const auto& c : rep.answer.contacts) special.push_back({c.value, true});
  if (rep.answer.first_contact) special.push_back({rep.answer.first_contact->value, false});
  for (auto [s, contact] : special) {
    bool merged = false;
    for (auto& [t, flag] : ts)
      if (std::fabs(t - s) < 1e-9) {
        flag = flag || contact;
        merged = true;
      }
    if (!merged) ts.push_back({s, contact});
  }
  std::sort(ts.begin(), ts.end());
  return ts;
}

// A cycloidal motion (scene-format.md) at t as a constant matrix M(t): the
// rotation by π(θ0 + θ1 t) about the centre x0, then the translation (display only).
PolyMatrix<double, 3> cycloidal_matrix_at(const CycloidalMotion& m, const std::vector<double>& x0, double t) {
  auto d = [](const Rational& q) { return q.get_d(); };
  const double a = std::numbers::pi * (d(m.theta0) + d(m.theta1) * t), c = std::cos(a), sn = std::sin(a);
  const double vx = d(m.x[0]) + d(m.x[1]) * t, vy = d(m.y[0]) + d(m.y[1]) * t;
  const double rows[3][3] = {
      {c, -sn, x0[0] - (c * x0[0] - sn * x0[1]) + vx}, {sn, c, x0[1] - (sn * x0[0] + c * x0[1]) + vy}, {0, 0, 1}};
  PolyMatrix<double, 3> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = Poly<double>(std::vector<double>{rows[i][j]});
  return r;
}

template <int N>
void add_objects(json& data, const Scene& s, const Solution& rep, int k) {
  constexpr int d = N - 1;
  auto conv = [](const Rational& q) { return scalar_traits<double>::from_rational(q); };
  const Shape sa = object_shape(s.a, d), sb = object_shape(s.b, d);
  // M(t) of an object: its polynomial matrix, or for a cycloidal motion the matrix at t.
  auto matrix_of = [&](const SceneObject& o, const Shape& sh) {
    std::function<PolyMatrix<double, N>(double)> f;
    if constexpr (N == 3) {
      if (auto* cm = std::get_if<CycloidalMotion>(&o.motion)) {
        CycloidalMotion m = *cm;
        std::vector<double> x0 = sh.x0;
        f = [m, x0](double t) { return cycloidal_matrix_at(m, x0, t); };
        return f;
      }
    }
    PolyMatrix<double, N> pm = motion_matrix<double, N>(o.motion, conv);
    f = [pm](double) { return pm; };
    return f;
  };
  const auto ma = matrix_of(s.a, sa), mb = matrix_of(s.b, sb);
  json snaps = json::array();
  for (auto [t, special] : snapshot_instants(k, rep)) {
    auto [ca, pa] = moved<N>(sa, ma(t), t);
    auto [cb, pb] = moved<N>(sb, mb(t), t);
    snaps.push_back({{"t", t}, {"contact", special}, {"a", outline_json(ca, pa)}, {"b", outline_json(cb, pb)}});
  }
  data["snapshots"] = snaps;
  std::vector<double> ts, ax, ay, bx, by;
  for (int i = 0; i < kPath; ++i) {
    double t = double(i) / (kPath - 1);
    ts.push_back(t);
    auto ca = moved<N>(sa, ma(t), t).first, cb = moved<N>(sb, mb(t), t).first;
    ax.push_back(ca[0]);
    ay.push_back(ca[1]);
    bx.push_back(cb[0]);
    by.push_back(cb[1]);
  }
  data["paths"] = {{"t", rounded(ts)},
                   {"a", {{"x", rounded(ax)}, {"y", rounded(ay)}}},
                   {"b", {{"x", rounded(bx)}, {"y", rounded(by)}}}};
}

std::vector<double> critical_approx(const Solution& rep) {
  std::vector<double> v;
  for (const auto& c : rep.critical) v.push_back(c.t.value);
  return v;
}

// 2D: Δ exactly, sampled exactly (a cycloidal Δ, transcendental: enclosed in
// MPFI at 128 bits and drawn at the enclosures' mid-points); contact points
// from the report (Lemma 5 of 003).
void add_curve_2d(json& data, const Scene& s, const Solution& rep) {
  std::vector<Rational> ts = grid_with(kDeltaSamples, critical_approx(rep));
  Rational max_abs;
  std::vector<double> td;
  for (const auto& t : ts) td.push_back(t.get_d());
  if (has_cycloidal_motion(s)) {
    const MpfiInterval like(Rational(0), 128);
    const CycloidalPair<MpfiInterval> cp = cycloidal_pair<MpfiInterval>(s, like);
    std::vector<Rational> vals;
    for (const auto& t : ts) {
      MpfiInterval v = cycloidal_delta<MpfiInterval>(cp, MpfiInterval(t, 128));
      mpfr_t mid;
      mpfr_init2(mid, 128);
      mpfi_mid(mid, v.get());
      Rational q;
      mpfr_get_q(q.get_mpq_t(), mid);
      mpfr_clear(mid);
      vals.push_back(q);
    }
    std::vector<double> val = normalised(vals, max_abs);
    data["curve"] = {{"kind", "discriminant"},
                     {"degree", -1},
                     {"identically_zero", false},
                     {"max_abs", decimal_string(max_abs, 6)},
                     {"how",
                      "cycloidal motion: Δ(t) is not a polynomial; enclosed in MPFI at 128 bits at each instant "
                      "and drawn at the mid-points, divided by its largest sampled |value|"},
                     {"t", rounded(td)},
                     {"value", val}};
  } else {
    PreparedPair<3> p = prepare_pair<3>(s);
    MovingPair<Rational, 3> m = to_arithmetic<Rational, 3>(p, Rational(1));
    std::vector<Poly<Rational>> g = characteristic_of(m);
    Poly<Rational> delta = cubic_discriminant(g[3], g[2], g[1], g[0]);
    std::vector<double> val = normalised(exact_values(delta, ts), max_abs);
    data["curve"] = {{"kind", "discriminant"},
                     {"degree", delta.degree()},
                     {"identically_zero", delta.is_zero()},
                     {"max_abs", decimal_string(max_abs, 6)},
                     {"how", "built and evaluated exactly, then divided by its largest sampled |value|"},
                     {"t", rounded(td)},
                     {"value", val}};  // full double: near a root the small values matter on a log scale
  }
  json contacts = json::array();
  const Answer& ans = rep.answer;
  for (std::size_t i = 0; i < ans.contacts.size(); ++i) {
    json c = {{"t", ans.contacts[i].value}};
    if (i < ans.contact_points.size() &&
        ans.contact_points[i].x.size() == 2)  // decimal text of Lemma 5's point, display only
      // (an interval "[lo, hi]" from a certified run: its lower end, for display)
      c["point"] = {std::stod(ans.contact_points[i].x[0].substr(ans.contact_points[i].x[0].rfind('[') + 1)),
                    std::stod(ans.contact_points[i].x[1].substr(ans.contact_points[i].x[1].rfind('[') + 1))};
    contacts.push_back(c);
  }
  data["contacts"] = contacts;
}

// F's u-coefficients at the grid instants: exactly, and as doubles divided
// (exactly) by the largest absolute value.
struct UCoefficients {
  std::vector<std::vector<Rational>> rows;  // rows[i][k] = i-th u-coefficient at ts[k]
  Rational max_abs = 0;
  int m_u = 0;
  Bern<double> at(std::size_t k) const {
    Bern<double> q;
    for (int i = 0; i <= m_u; ++i) q.b.push_back(scalar_traits<double>::from_rational(Rational(rows[i][k] / max_abs)));
    return q;
  }
};

// Contact points (display only): u0 = argmax F(., t0), λ0 = (u0 - 1)/u0, null vector of λ0 A - B.
json contacts_3d(const PreparedPair<4>& p, const std::vector<double>& contact_t, const std::vector<Rational>& ts,
                 const UCoefficients& uc) {
  const MovingPair<double, 4> md = to_arithmetic<double, 4>(p, 1.0);
  const PolyMatrix<double, 4> A = moving_quadric<double, 4>(md.qa, md.na), B = moving_quadric<double, 4>(md.qb, md.nb);
  json contacts = json::array();
  for (double t0 : contact_t) {
    std::size_t k = std::lower_bound(ts.begin(), ts.end(), Rational(t0)) - ts.begin();
    if (k >= ts.size()) k = ts.size() - 1;
    Bern<double> q = uc.at(k);
    double best = 0.5, fbest = -INFINITY;
    for (int i = 1; i < 2000; ++i) {
      double u = i / 2000.0, f = q(u);
      if (f > fbest) {
        fbest = f;
        best = u;
      }
    }
    double lo = std::max(1e-12, best - 1.0 / 2000), hi = std::min(1 - 1e-12, best + 1.0 / 2000);
    for (int it = 0; it < 100; ++it) {  // golden section on the unimodal piece
      double a = hi - 0.618033988749895 * (hi - lo), b = lo + 0.618033988749895 * (hi - lo);
      if (q(a) > q(b))
        hi = b;
      else
        lo = a;
    }
    double u0 = 0.5 * (lo + hi), lam = (u0 - 1) / u0;
    Mat<double> mm(4, std::vector<double>(4));
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) mm[i][j] = lam * A[i][j](t0) - B[i][j](t0);
    std::vector<double> v = null_vector4(mm);
    json c = {{"t", t0}, {"u", u0}};
    if (std::fabs(v[3]) > 0) c["point"] = {v[0] / v[3], v[1] / v[3], v[2] / v[3]};
    contacts.push_back(c);
  }
  return contacts;
}

// The u-window: where F > 0 on a fine pass (the relative scale of A and B can
// squeeze the whole zero set into a sliver next to u = 0 or u = 1), widened
// by a margin; the whole [0, 1] if that covers more than half of it.
std::pair<double, double> u_window(const std::vector<Rational>& ts, const UCoefficients& uc, const json& contacts) {
  double u_lo = 1, u_hi = 0;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    Bern<double> q = uc.at(k);
    for (int i = 1; i < kFine; ++i) {
      double u = double(i) / kFine;
      if (q(u) > 0) {
        u_lo = std::min(u_lo, u);
        u_hi = std::max(u_hi, u);
      }
    }
  }
  for (const auto& c : contacts) {
    u_lo = std::min(u_lo, c["u"].get<double>());
    u_hi = std::max(u_hi, c["u"].get<double>());
  }
  double w0 = 0, w1 = 1;
  if (u_hi >= u_lo) {
    double margin = std::max(0.15 * (u_hi - u_lo), 2.0 / kFine);
    w0 = std::max(0.0, u_lo - margin);
    w1 = std::min(1.0, u_hi + margin);
    if (w1 - w0 > 0.5) {
      w0 = 0;
      w1 = 1;
    }
  }
  return {w0, w1};
}

// 3D: F's u-Bernstein coefficients exactly, sampled exactly in t; F in u by de Casteljau.
void add_curve_3d(json& data, const Scene& s, const Solution& rep) {
  PreparedPair<4> p = prepare_pair<4>(s);
  MovingPair<Rational, 4> m = to_arithmetic<Rational, 4>(p, Rational(1));
  std::vector<Poly<Rational>> g = characteristic_of(m);
  BiBern<Rational> F = ellipsoid_function(g, Rational(1));
  std::vector<double> extra = critical_approx(rep);
  std::vector<double> contact_t;
  for (const auto& c : rep.answer.contacts) contact_t.push_back(c.value);
  extra.insert(extra.end(), contact_t.begin(), contact_t.end());
  std::vector<Rational> ts = grid_with(kGrid, extra);
  UCoefficients uc;
  uc.m_u = F.degree_u();
  for (int i = 0; i <= uc.m_u; ++i) uc.rows.push_back(exact_values(to_power(Bern<Rational>(F.b[i])), ts));
  for (const auto& r : uc.rows)
    for (const auto& x : r) uc.max_abs = std::max<Rational>(uc.max_abs, abs(x));
  if (uc.max_abs == 0) throw std::logic_error("F(u, t) vanishes identically");
  const json contacts = contacts_3d(p, contact_t, ts, uc);
  data["contacts"] = contacts;
  const auto [w0, w1] = u_window(ts, uc, contacts);
  std::vector<double> us, td;
  for (int i = 0; i <= kGrid; ++i) us.push_back(w0 + (w1 - w0) * i / kGrid);
  json values = json::array();
  for (std::size_t k = 0; k < ts.size(); ++k) {
    td.push_back(ts[k].get_d());
    Bern<double> q = uc.at(k);
    std::vector<double> row;
    for (double u : us) row.push_back(q(u));
    values.push_back(rounded(row));
  }
  data["curve"] = {{"kind", "F"},
                   {"degree_t", F.degree_t()},
                   {"how",
                    "Bernstein coefficients in u built and evaluated exactly in t, divided by the largest, rounded to "
                    "double, then de Casteljau in u"},
                   {"u_window", {w0, w1}},
                   {"u", us},
                   {"t", rounded(td)},
                   {"value", values}};
}

// Independent motions (001 section 4): where A(s) and B(t) meet, on an n x n grid of the
// (s, t) square, by the double static test (api/static_status.hpp, status_at: 001 Appendix A with its error
// bound) on the shared-parameter scene with A fixed at A(s), and the exact static test where double's error
// bound cannot decide (two balls: f always has a double root): 1 meets (touching or overlapping), 0 separate. The zero
// set of F(u, s, t) = det((u-1)A(s) - uB(t)) projected on (s, t) is the boundary of that region (F > 0 for some u iff
// separate). The same in 2D (ellipses, H = 3) and 3D (H = 4): the object fixed at its position x of its path.
constexpr int kStGrid = 64;
template <int H>
SceneObject fixed_at(const SceneObject& o, const Rational& x) {
  SceneObject f = o;
  auto M = motion_matrix<Rational, H>(o.motion, [](const Rational& q) { return q; });
  MatrixMotion mm;
  mm.m.assign(H, std::vector<RPoly>(H));
  for (int i = 0; i < H; ++i)
    for (int j = 0; j < H; ++j) mm.m[i][j] = RPoly::constant(M[i][j](x));
  f.motion = mm;
  return f;
}
void add_st_grid(json& data, const Scene& s) {
  auto fixed = [&](const SceneObject& o, const Rational& x) {
    return s.dim == 3 ? fixed_at<4>(o, x) : fixed_at<3>(o, x);
  };
  std::vector<Rational> g;
  for (int k = 0; k < kStGrid; ++k) g.push_back(Rational(2 * k + 1, 2 * kStGrid));  // cell centres
  for (auto& x : g) x.canonicalize();
  json meets = json::array();  // meets[i][k]: s = g[i], t = g[k]
  int unsure = 0;
  for (const auto& sv : g) {
    Scene sh = s;
    sh.independent = false;
    sh.answer.reset();
    sh.a = fixed(s.a, sv);
    json row = json::array();
    for (const auto& tv : g) {
      Status st = status_at(sh, tv, Arithmetic::double_precision());
      if (st == Status::uncertain) {  // e.g. two balls: f always has a double root, which double cannot tell apart
        ++unsure;
        st = status_at(sh, tv, Arithmetic::exact());
      }
      row.push_back(st == Status::uncertain ? -1 : in_collision(st) ? 1 : 0);
    }
    meets.push_back(row);
  }
  std::vector<double> axis;
  for (const auto& x : g) axis.push_back(x.get_d());
  data["st_grid"] = {{"n", kStGrid},
                     {"s", axis},
                     {"t", axis},
                     {"meets", meets},
                     {"uncertain", unsure},
                     {"how",
                      "static test at each cell's centre: double (001 App. A, error-bounded), exact where double "
                      "cannot decide (" +
                          std::to_string(unsure) + " cells)"}};
}

}  // namespace

void add_scene_data(json& data, const Scene& s, const Solution& rep, int k) {
  if (s.independent) {
    data["kind"] = "independent";
    add_st_grid(data, s);
  } else if (s.dim == 2) {
    add_objects<3>(data, s, rep, k);
    add_curve_2d(data, s, rep);
  } else {
    add_objects<4>(data, s, rep, k);
    add_curve_3d(data, s, rep);
  }
}

}  // namespace eccd::plot_data
