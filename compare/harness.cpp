// The comparison harness (see compare/harness.hpp).
#include "compare/harness.hpp"

#include "compare/scene_generator.hpp"
#include "exact/cd_disc_exact.hpp"
#include "floating/cd_disc_floating.hpp"
#include "floating/double_traits.hpp"
#include "floating/mpfr_real.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/discriminant.hpp"
#include "kernel/ellipsoid_function.hpp"
#include "kernel/motion.hpp"
#include "kernel/prepared_scene.hpp"

#include <cstdio>
#include <sstream>

namespace eccd {

namespace {

template <int N>
int motion_degree(const Motion& m) {
  if (std::holds_alternative<CycloidalMotion>(m)) return -1;
  auto M = motion_matrix<Rational, N>(m, [](const Rational& x) { return x; });
  int d = 0;
  for (auto& row : M) for (auto& e : row) d = std::max(d, e.degree());
  return d;
}

// Exact reference coefficients of one scene.
struct Reference2 {
  PreparedPair<3> p;
  std::vector<Poly<Rational>> g;        // power form
  std::vector<Bern<Rational>> g_bern;   // each g_k in Bernstein form of its degree
  Bern<Rational> delta_bern;            // Δ in Bernstein form of its degree
};
struct Reference3 {
  PreparedPair<4> p;
  std::vector<Poly<Rational>> g;        // power form (the projection pipeline's setup)
  std::vector<Bern<Rational>> g_bern;
  BiBern<Rational> F;
};

template <class T>
void coefficients_2d(const Reference2& ref, Basis basis, int bits, const T& like, ResultRow& row) {
  auto m = to_arithmetic<T, 3>(ref.p, like);
  std::vector<Poly<T>> g = characteristic_of(m);
  FloatingPolicy<T> pol(basis, bits, like);
  if (basis == Basis::power) row.coef_err = coefficient_error(g, ref.g);
  else row.coef_err = coefficient_error(to_bernstein_all(g, like), ref.g_bern);
  row.delta_err = coefficient_error(discriminant_of(g, pol), ref.delta_bern);
}

template <class T>
void coefficients_3d(const Reference3& ref, const PipelineSpec& ps, const T& like, ResultRow& row) {
  if (ps.method == "projection") {
    row.coef_err = coefficient_error(characteristic_of(to_arithmetic<T, 4>(ref.p, like)), ref.g);
    return;
  }
  bool power = ps.basis == "power";
  std::vector<Bern<T>> g = characteristic_bernstein<T, 4>(ref.p, power, like);
  row.coef_err = coefficient_error(g, ref.g_bern);
  row.delta_err = coefficient_error(ellipsoid_function(g, like), ref.F);
}

std::string fmt(double x, const char* f = "%.6g") {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace

int scene_degree(const Scene& s) {
  if (s.dim == 2) return std::max(motion_degree<3>(s.a.motion), motion_degree<3>(s.b.motion));
  return std::max(motion_degree<4>(s.a.motion), motion_degree<4>(s.b.motion));
}

SceneInfo scene_info(const Scene& s, const std::string& source) {
  SceneInfo i;
  i.name = s.name;
  i.source = source;
  i.dim = s.dim;
  if (auto sp = spec_from_note(s.note)) {
    i.family = sp->family;
    i.motion = sp->motion;
    i.degree = sp->degree;
    i.d_exponent = sp->family == "near-miss" ? sp->d_exponent : 0;
    i.seed = sp->seed;
  } else {
    i.degree = scene_degree(s);
  }
  return i;
}

std::vector<PipelineSpec> harness_pipelines(int dim, const HarnessOptions& o) {
  std::vector<PipelineSpec> v;
  auto add = [&](const std::string& arith, const std::string& basis, const std::string& method, const std::string& variant) {
    PipelineSpec p;
    p.opt.arith = parse_arithmetic(arith);
    p.opt.basis = basis;
    p.opt.method = method;
    p.basis = arith == "exact" ? "exact" : basis;
    p.method = arith == "exact" ? (dim == 2 ? "cd-disc" : "projection") : method;
    p.label = arith == "exact" ? "exact" : arith + "/" + variant;
    v.push_back(p);
  };
  add("exact", "bernstein", "bezier", "");
  if (dim == 2) {
    add("double", "power", "cd-disc", "power");
    add("double", "bernstein", "cd-disc", "bernstein");
    add("double", "scaled-bernstein", "cd-disc", "scaled-bernstein");
    for (int b : o.mpfr_bits) {
      std::string a = "mpfr:" + std::to_string(b);
      add(a, "power", "cd-disc", "power");
      add(a, "bernstein", "cd-disc", "bernstein");
    }
  } else {
    std::string n = std::to_string(o.grid);
    add("double", "bernstein", "bezier", "bezier");
    add("double", "power", "bezier", "bezier-power");
    add("double", "bernstein", "sampling:" + n, "sampling:" + n);
    add("double", "bernstein", "marching:" + n, "marching:" + n);
    for (int b : o.mpfr_bits) {
      std::string a = "mpfr:" + std::to_string(b);
      add(a, "bernstein", "bezier", "bezier");
      if (o.mpfr_power_3d) add(a, "power", "bezier", "bezier-power");
    }
  }
  return v;
}

std::vector<ResultRow> run_scene(const Scene& s, const SceneInfo& info, const HarnessOptions& opt) {
  std::vector<ResultRow> rows;
  auto pipes = harness_pipelines(s.dim, opt);
  nlohmann::json exact = solve_scene(s, pipes[0].opt);  // throws for a scene the exact pipeline refuses
  Reference2 r2;
  Reference3 r3;
  if (s.dim == 2) {
    r2.p = prepare_pair<3>(s);
    r2.g = characteristic_of(to_arithmetic<Rational, 3>(r2.p, Rational(1)));
    r2.g_bern = to_bernstein_all(r2.g, Rational(1));
    r2.delta_bern = to_bernstein(cubic_discriminant(r2.g[3], r2.g[2], r2.g[1], r2.g[0]));
  } else {
    r3.p = prepare_pair<4>(s);
    r3.g = characteristic_of(to_arithmetic<Rational, 4>(r3.p, Rational(1)));
    r3.g_bern = to_bernstein_all(r3.g, Rational(1));
    r3.F = ellipsoid_function(r3.g_bern, Rational(1));
  }
  for (const auto& ps : pipes) {
    ResultRow row;
    row.scene = info;
    row.pipeline = ps.label;
    row.arith = ps.opt.arith.kind == Arithmetic::Exact ? "exact" : ps.opt.arith.kind == Arithmetic::Mpfr ? "mpfr" : "double";
    row.bits = ps.opt.arith.bits;
    row.basis = ps.basis;
    row.method = ps.method;
    nlohmann::json got;
    if (ps.label == "exact") {
      got = exact;
    } else {
      try {
        got = solve_scene(s, ps.opt);
      } catch (const std::exception& e) {
        row.error = e.what();
        got = nlohmann::json::object();
      }
    }
    row.m = compare_answers(got, exact);
    if (got.contains("time_ms")) row.time_us = got["time_ms"].get<double>() * 1e3;
    if (ps.label != "exact") {
      Basis basis = parse_basis(ps.opt.basis);
      if (ps.opt.arith.kind == Arithmetic::Double) {
        if (s.dim == 2) coefficients_2d<double>(r2, basis, 53, 1.0, row);
        else coefficients_3d<double>(r3, ps, 1.0, row);
      } else {
        Mpfr like(mpq_class(1), ps.opt.arith.bits);
        if (s.dim == 2) coefficients_2d<Mpfr>(r2, basis, ps.opt.arith.bits, like, row);
        else coefficients_3d<Mpfr>(r3, ps, like, row);
      }
    }
    rows.push_back(row);
  }
  return rows;
}

std::string results_csv_header() {
  return "scene,source,dim,degree,family,motion,d,seed,pipeline,arith,bits,basis,method,coef_err,delta_err,outcome,"
         "collides,exact_collides,intervals,exact_intervals,missed_contacts,false_contacts,first_contact_err,"
         "endpoint_err,time_us,structure_ok";
}

std::string results_csv_line(const ResultRow& r) {
  std::ostringstream o;
  const SceneInfo& s = r.scene;
  auto opt = [](const std::optional<double>& x) { return x ? fmt(*x) : std::string(); };
  o << s.name << "," << s.source << "," << s.dim << "," << s.degree << "," << s.family << "," << s.motion << ","
    << (s.family == "near-miss" ? separation_label(s.d_exponent) : "") << "," << (s.seed ? std::to_string(*s.seed) : "")
    << "," << r.pipeline << "," << r.arith << "," << r.bits << "," << r.basis << "," << r.method << "," << opt(r.coef_err)
    << "," << opt(r.delta_err) << "," << r.m.outcome << "," << (r.m.collides ? (*r.m.collides ? "1" : "0") : "") << ","
    << (r.m.exact_collides ? 1 : 0) << "," << r.m.intervals << "," << r.m.exact_intervals << "," << r.m.missed_contacts
    << "," << r.m.false_contacts << "," << opt(r.m.first_contact_err) << "," << opt(r.m.endpoint_err) << ","
    << fmt(r.time_us, "%.1f") << "," << (r.m.structure_ok ? 1 : 0);
  return o.str();
}

}  // namespace eccd
