#pragma once
// What the groups of eccd_bench share (bench/eccd_bench.cpp runs them; each group of rows is
// registered by a file of its own, bench/group_*.cpp, declared at the end): the registry of groups,
// rows and what each row answered, the timing loop, lazily built inputs, the summaries of a CCD
// run, and the scenes several groups use.
#include "api/solve.hpp"
#include "api/static_status.hpp"
#include "api/separate.hpp"
#include "api/animate.hpp"
#include "certified/ladder.hpp"
#include "io/solution_json.hpp"
#include "bench/isolation.hpp"
#include "bench/fcl_side.hpp"
#include "bench/poses.hpp"
#include "bench/speed_targets.hpp"
#include "bench/table1_frames.hpp"
#include "compare/fcl_engine.hpp"
#include "exact/algebraic_roots.hpp"
#include "exact/cd_disc_exact.hpp"
#include "exact/certificate_algebra.hpp"
#include "floating/ccd3_baselines.hpp"
#include "floating/cd_disc_floating.hpp"
#include "number/double_traits.hpp"
#include "number/mpfr_real.hpp"
#include "floating/bezier_ccd.hpp"
#include "kernel/ccd_projection.hpp"
#include "kernel/characteristic_polynomial.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/fast_quartic.hpp"
#include "kernel/quartic_status.hpp"
#include "io/scene_reader.hpp"
#include "compare/scene_generator.hpp"
#include "independent.hpp"  // bench/independent.cpp

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <span>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <tuple>
#include <unistd.h>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#ifndef ECCD_SOURCE_DIR
#define ECCD_SOURCE_DIR "."
#endif
#ifndef ECCD_BUILD_TYPE
#define ECCD_BUILD_TYPE "unknown"
#endif

using namespace eccd;
using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

namespace eccd_bench::groups {

// ---------------------------------------------------------------------------
// Registry: groups, rows, and what each row answered.

enum class Cost {
  fast,
  slow,
  very_slow,
  heavy
};  // repetitions / minimum time policy (heavy: seconds per iteration, 3 repetitions)

struct Group {
  std::string id, title, description, anchor;
};
struct Row {
  std::string key, group, label, note;
  bool baseline = false;
};

inline std::vector<Group> g_groups;
inline std::vector<Row> g_rows;
inline std::map<std::string, json> g_results;  // key -> what the row computed (last timed iteration)
inline std::map<std::string, json> g_scenes;   // scene id -> description
inline bool g_quick = false;
inline double g_profile_seconds = 0;  // > 0: one repetition of at least this long per row (for perf)

inline void group(const std::string& id, const std::string& title, const std::string& description,
                  const std::string& anchor) {
  g_groups.push_back({id, title, description, anchor});
}

// Registers one benchmark "group/label"; fn runs the timing loop.
inline void row(const std::string& grp, const std::string& label, bool baseline, Cost cost, const std::string& note,
                std::function<void(benchmark::State&)> fn, bool process_cpu = false) {
  std::string key = grp + "/" + label;
  g_rows.push_back({key, grp, label, note, baseline});
  auto* b = benchmark::RegisterBenchmark(key.c_str(), [fn](benchmark::State& st) { fn(st); });
  int reps = cost == Cost::fast ? 10 : (cost == Cost::slow ? 9 : (cost == Cost::very_slow ? 5 : 3));
  double min_time = cost == Cost::fast ? 0.1 : 0.05;
  if (g_quick) {
    reps = 3;
    min_time = 0.01;
  }
  if (g_profile_seconds > 0) {
    reps = 1;
    min_time = g_profile_seconds;
  }
  b->Repetitions(reps)->MinTime(min_time)->Unit(cost == Cost::fast ? benchmark::kNanosecond : benchmark::kMicrosecond);
  // Nanosecond rows: a short warm-up (first touches of the batch, the allocator) before each repetition.
  if (cost == Cost::fast && g_profile_seconds == 0) b->MinWarmUpTime(g_quick ? 0.01 : 0.05);
  if (process_cpu) b->MeasureProcessCPUTime();
}

// The timing loop for a function returning a result R; the last result is
// summarised (after the loop, not timed) into g_results[key].
template <class F, class S>
void timed(benchmark::State& st, const std::string& key, F f, S summarise) {
  using R = decltype(f());
  std::optional<R> last;
  for (auto _ : st) {
    R r = f();
    benchmark::DoNotOptimize(r);
    last.emplace(std::move(r));
  }
  if (last) g_results[key] = summarise(*last);
}

// Lazily built, shared inputs (a filtered run builds only what it uses).
template <class T>
class Lazy {
 public:
  explicit Lazy(std::function<T()> make) : make_(std::move(make)) {}
  const T& get() {
    std::call_once(once_, [this] { value_ = std::make_unique<T>(make_()); });
    return *value_;
  }

 private:
  std::function<T()> make_;
  std::once_flag once_;
  std::unique_ptr<T> value_;
};

// ---------------------------------------------------------------------------
// What a CCD run answered (for the report: the rows must agree on the scene).

inline std::string short_instant(const Instant& i) {
  return i.approx.substr(0, std::min<std::size_t>(i.approx.size(), 10));
}

template <class T>
json summarise_ccd(const PipelineResult<T>& r) {
  json j;
  j["collides"] = r.answer.collides;
  j["intervals"] = r.answer.intervals.size();
  j["contacts"] = r.answer.contacts.size();
  j["undecided"] = r.answer.undecided.size();
  j["critical"] = r.critical.size();
  j["projection_degree"] = r.projection_degree;
  if (r.answer.first_contact) j["first_contact"] = short_instant(*r.answer.first_contact);
  json iv = json::array();
  for (const auto& [a, b] : r.answer.intervals) iv.push_back(short_instant(a) + ".." + short_instant(b));
  j["interval_list"] = iv;
  json c = json::object();
  for (const auto& [k, v] : r.counters) c[k] = v;
  if (!c.empty()) j["work"] = c;
  return j;
}

// What a certified run answered (run_certified / solve with --arith certified).
inline json summarise_solution(const Solution& s) {
  json j;
  j["collides"] = s.answer.collides;
  j["intervals"] = s.answer.intervals.size();
  j["contacts"] = s.answer.contacts.size();
  j["undecided"] = s.answer.undecided.size();
  json iv = json::array();
  for (const auto& [a, b] : s.answer.intervals) iv.push_back(short_instant(a) + ".." + short_instant(b));
  j["interval_list"] = iv;
  if (!s.decided_in.empty()) j["decided_in"] = s.decided_in;
  return j;
}

// ---------------------------------------------------------------------------
// Scenes.

inline std::string src(const std::string& rel) { return std::string(ECCD_SOURCE_DIR) + "/" + rel; }

// A general rational Euclidean motion of degree 2m in the kinematic image
// (003 eq. (3)): d0..d3 polynomials of degree m with integer coefficients, so
// that every entry of M(t) has degree 2m and, generically, Δ(t) has degree 24
// times the motion degree (003 Table I). The centre is shifted by (cx, 0):
// d0 += cx d3 / 2, d1 -= cx d2 / 2 (the centre (x, y) of 003 eq. (3) is
// linear in d0, d1 for given d2, d3).
inline ojson kinematic_motion(std::mt19937_64& rng, int m, int cx) {
  std::uniform_int_distribution<int> small(-2, 2), lead(2, 4), wide(-4, 4);
  std::array<std::vector<mpq_class>, 4> d;
  for (int k = 0; k < 4; ++k) d[k].assign(m + 1, 0);
  for (int i = 0; i <= m; ++i) {
    d[2][i] = i == 0 ? lead(rng) : small(rng);
    d[3][i] = small(rng);
    d[0][i] = wide(rng);
    d[1][i] = wide(rng);
  }
  for (int k : {2, 3})
    if (d[k][m] == 0) d[k][m] = 1;  // full degree m
  for (int i = 0; i <= m; ++i) {
    mpq_class a = d[0][i] + mpq_class(cx) * d[3][i] / 2, b = d[1][i] - mpq_class(cx) * d[2][i] / 2;
    d[0][i] = a;
    d[1][i] = b;
  }
  ojson arr = ojson::array();
  for (int k = 0; k < 4; ++k) {
    ojson p = ojson::array();
    for (auto& c : d[k]) {
      c.canonicalize();
      p.push_back(c.get_str());
    }
    arr.push_back(p);
  }
  return ojson{{"type", "kinematic"}, {"d", arr}};
}

inline Scene kinematic_scene(int motion_degree, std::uint64_t seed, bool apart) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> axis(2, 5);
  int m = motion_degree / 2;
  ojson s;
  s["format"] = "ellipse-ccd-scene/1";
  s["name"] =
      "bench-2d-deg" + std::to_string(motion_degree) + (apart ? "-free-" : "-colliding-") + std::to_string(seed);
  s["dim"] = 2;
  int gap = apart ? 9 : 4;
  for (const char* obj : {"a", "b"}) {
    ojson o;
    o["shape"] = ojson{{"semi_axes", {std::to_string(axis(rng)), std::to_string(axis(rng))}}};
    o["motion"] = kinematic_motion(rng, m, std::strcmp(obj, "a") == 0 ? -gap : gap);
    s[obj] = o;
  }
  return parse_scene(s.dump(), s["name"].get<std::string>());
}

struct Scene2D {
  std::string id;
  Scene scene;
  PreparedPair<3> p;
  json info;
};

inline PipelineResult<double> run2d_double(const PreparedPair<3>& p, Variant v, Basis basis = Basis::bernstein) {
  FloatingPolicy<double> pol(basis, 53, 1.0);
  MovingPair<double, 3> m = to_arithmetic<double, 3>(p, 1.0);
  return cd_disc(m, pol, v);
}
template <class T>
PipelineResult<T> run2d_floating(const PreparedPair<3>& p, Variant v, Basis basis, int bits, const T& like) {
  FloatingPolicy<T> pol(basis, bits, like);
  MovingPair<T, 3> m = to_arithmetic<T, 3>(p, like);
  return cd_disc(m, pol, v);
}
inline PipelineResult<Rational> run2d_exact(const PreparedPair<3>& p, Variant v) {
  ExactPolicy pol;
  MovingPair<Rational, 3> m = to_arithmetic<Rational, 3>(p, Rational(1));
  return cd_disc(m, pol, v);
}

// The first seed from `seed` on whose scene the exact answer has the wanted
// kind (separate at t = 0, then colliding with >= 2 external contacts; or free), Δ has the full degree
// 24 K, and double CD-DISC agrees on collides and the number of contacts.
inline Scene2D select_2d(int degree, bool apart, std::uint64_t seed) {
  for (int tries = 0; tries < 400; ++tries, ++seed) {
    Scene sc;
    try {
      sc = kinematic_scene(degree, seed, apart);
    } catch (const SceneError&) {
      continue;  // d2² + d3² vanishes somewhere on [0, 1]: not a motion
    }
    PreparedPair<3> p = prepare_pair<3>(sc);
    auto d = run2d_double(p, Variant::answer);
    if (d.projection_degree != 24 * degree) continue;
    if (apart ? d.answer.collides : (!d.answer.collides || d.answer.contacts.size() < 2)) continue;
    if (d.status_at_0 != Status::separate) continue;  // Variants 1 and 2 must search for the first root
    if (!d.answer.undecided.empty()) continue;
    auto e = run2d_exact(p, Variant::answer);
    if (e.projection_degree != 24 * degree) continue;
    if (e.answer.collides != d.answer.collides || e.answer.contacts.size() != d.answer.contacts.size()) continue;
    if (e.status_at_0 != Status::separate) continue;
    Scene2D out{sc.name, sc, p, json::object()};
    out.info = {{"dim", 2},
                {"motion_degree", degree},
                {"family", apart ? "free" : "colliding"},
                {"seed", seed},
                {"tries", tries + 1},
                {"projection_degree", e.projection_degree},
                {"exact_answer", summarise_ccd(e)},
                {"source", "generated in-process (bench/groups.hpp kinematic_scene), general kinematic-image motion"}};
    return out;
  }
  throw std::runtime_error("no 2D scene of degree " + std::to_string(degree) + " found");
}

inline Scene2D scene2d_from_file(const std::string& id, const std::string& rel) {
  Scene sc = read_scene_file(src(rel));
  PreparedPair<3> p = prepare_pair<3>(sc);
  auto e = run2d_exact(p, Variant::answer);
  Scene2D out{id, sc, p, json::object()};
  out.info = {
      {"dim", 2}, {"file", rel}, {"projection_degree", e.projection_degree}, {"exact_answer", summarise_ccd(e)}};
  return out;
}

struct Scene3D {
  std::string id;
  Scene scene;
  PreparedPair<4> p;
  json info;
};

inline Scene3D scene3d_from_file(const std::string& id, const std::string& rel, const std::string& what) {
  Scene sc = read_scene_file(src(rel));
  Scene3D out{id, sc, prepare_pair<4>(sc), json::object()};
  out.info = {{"dim", 3}, {"file", rel}, {"what", what}};
  return out;
}

// Seeds found by select_2d's search (it starts here and takes the first fit).
constexpr std::uint64_t kSeed2D = 6001;

inline Lazy<Scene2D> s2d_deg2([] { return select_2d(2, false, kSeed2D); });
inline Lazy<Scene2D> s2d_deg4([] { return select_2d(4, false, kSeed2D); });
inline Lazy<Scene2D> s2d_deg6([] { return select_2d(6, false, kSeed2D); });
inline Lazy<Scene2D> s2d_deg6_free([] { return select_2d(6, true, kSeed2D); });
inline Lazy<Scene2D> s2d_paper003([] {
  return scene2d_from_file("paper003-example2", "cases/paper003/example2.json");
});

inline Lazy<Scene3D> s3d_deg2([] {
  return scene3d_from_file(
      "3d-deg2-affine", "cases/generated/3d-affine/3d-deg2-colliding-affine-2295206434708192.json",
      "generated corpus, degree-2 affine motions: separate at t = 0, one collision interval, two contacts");
});
inline Lazy<Scene3D> s3d_deg4([] {
  return scene3d_from_file(
      "3d-deg4-euler", "cases/generated/3d-euler/3d-deg4-colliding-euler-8020579862790034.json",
      "generated corpus, degree-4 Euler-parameter motions: separate at t = 0, one collision interval");
});
inline Lazy<Scene3D> s3d_deg4_affine([] {
  return scene3d_from_file(
      "3d-deg4-affine", "cases/generated/3d-affine/3d-deg4-colliding-affine-6989596756321537.json",
      "generated corpus, degree-4 affine motions, colliding (001 Fig. 3 is a degree-4 affine pair)");
});
inline Lazy<Scene3D> s3d_paper002([] {
  return scene3d_from_file("paper002-example", "cases/paper002/example.json",
                           "paper 002's numerical example (degree-4 Euler motions, projection of degree 216)");
});

inline Lazy<Scene2D>* scene2d_by_degree(int k) { return k == 2 ? &s2d_deg2 : (k == 4 ? &s2d_deg4 : &s2d_deg6); }

inline void note_scene(const Scene2D& s) { g_scenes[s.id] = s.info; }
inline void note_scene(const Scene3D& s, const std::string& group) {
  json j = s.info;
  j["group"] = group;  // the report takes Δ's degree and the exact answer from the group's exact row
  g_scenes[s.id] = j;
}

// ---------------------------------------------------------------------------
// The static tests' inputs (groups static2d/static3d, fcl-static3d, static-certified-*): batches of
// random pairs in double.

constexpr int kBatch = 1024;

using M3 = std::array<std::array<double, 3>, 3>;
using M4 = std::array<std::array<double, 4>, 4>;

// A: axis-aligned at the origin (standard position, diag(1/a², ..., -1)); B:
// rotated by a random unit quaternion (or angle), semi-axes in [1, 3], centre
// at a random distance in [0, 7] (about half the pairs separate).
struct Static3D {
  std::vector<std::array<double, 3>> e;     // ea, eb, ec of A
  std::vector<M4> a, b;                     // A = diag(ea, eb, ec, -1) and B in A's frame
  std::vector<std::vector<double>> coeffs;  // Appendix A coefficients (for the status-only row)
  std::vector<Ellipsoid> pa, pb;  // the same pairs as a user gives them: semi-axes and poses (the API's input)
};
struct Static2D {
  std::vector<M3> a, b;
  std::vector<std::vector<double>> coeffs;
  std::vector<Ellipse> pa, pb;
};

inline Static3D make_static3d() {
  std::mt19937_64 rng(3003);
  std::uniform_real_distribution<double> ax(1.0, 3.0), dist(0.0, 7.0), nrm(-1.0, 1.0);
  Static3D s;
  for (int n = 0; n < kBatch; ++n) {
    double a1 = ax(rng), a2 = ax(rng), a3 = ax(rng);
    std::array<double, 3> ea{1 / (a1 * a1), 1 / (a2 * a2), 1 / (a3 * a3)};
    double q[4];
    double qn = 0;
    for (double& x : q) {
      x = nrm(rng);
      qn += x * x;
    }
    qn = std::sqrt(qn);
    for (double& x : q) x /= qn;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    double dir[3] = {nrm(rng), nrm(rng), nrm(rng)};
    double dn = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]) + 1e-12;
    double r = dist(rng), c[3];
    for (int i = 0; i < 3; ++i) c[i] = r * dir[i] / dn;
    double b1 = ax(rng), b2 = ax(rng), b3 = ax(rng);
    double qb[4] = {1 / (b1 * b1), 1 / (b2 * b2), 1 / (b3 * b3), -1};
    // B's frame: Y = Rᵀ (X - c); T = [[Rᵀ, -Rᵀ c], [0, 1]]; B = Tᵀ diag(qb) T.
    double T[4][4] = {};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) T[i][j] = R[j][i];
      T[i][3] = -(R[0][i] * c[0] + R[1][i] * c[1] + R[2][i] * c[2]);
    }
    T[3][3] = 1;
    M4 B{}, A{};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        double acc = 0;
        for (int k = 0; k < 4; ++k) acc += T[k][i] * qb[k] * T[k][j];
        B[i][j] = acc;
      }
    for (int i = 0; i < 3; ++i) A[i][i] = ea[i];
    A[3][3] = -1;
    s.e.push_back(ea);
    s.a.push_back(A);
    s.b.push_back(B);
    // Poses: A at the origin, B's frame mapped to the world by X = R Y + c.
    Ellipsoid pa{{a1, a2, a3}, {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}};
    Ellipsoid pb{{b1, b2, b3}, {}};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) pb.pose[i][j] = R[i][j];
      pb.pose[i][3] = c[i];
    }
    pb.pose[3] = {0, 0, 0, 1};
    s.pa.push_back(pa);
    s.pb.push_back(pb);
    {
      auto coeffs = appendix_a_coefficients(ea[0], ea[1], ea[2], B);
      s.coeffs.emplace_back(coeffs.begin(), coeffs.end());
    }
  }
  return s;
}

inline Static2D make_static2d() {
  std::mt19937_64 rng(2002);
  std::uniform_real_distribution<double> ax(1.0, 3.0), dist(0.0, 7.0), ang(0.0, 6.283185307179586);
  Static2D s;
  for (int n = 0; n < kBatch; ++n) {
    double a1 = ax(rng), a2 = ax(rng), b1 = ax(rng), b2 = ax(rng), th = ang(rng), ph = ang(rng), r = dist(rng);
    double c[2] = {r * std::cos(ph), r * std::sin(ph)};
    double R[2][2] = {{std::cos(th), -std::sin(th)}, {std::sin(th), std::cos(th)}};
    double qb[3] = {1 / (b1 * b1), 1 / (b2 * b2), -1};
    double T[3][3] = {};
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) T[i][j] = R[j][i];
      T[i][2] = -(R[0][i] * c[0] + R[1][i] * c[1]);
    }
    T[2][2] = 1;
    M3 A{}, B{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double acc = 0;
        for (int k = 0; k < 3; ++k) acc += T[k][i] * qb[k] * T[k][j];
        B[i][j] = acc;
      }
    A[0][0] = 1 / (a1 * a1);
    A[1][1] = 1 / (a2 * a2);
    A[2][2] = -1;
    s.a.push_back(A);
    s.b.push_back(B);
    s.coeffs.push_back(characteristic_coefficients_in<double, 3>(A, B, 0.0));
    s.pa.push_back(Ellipse{{a1, a2}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}});
    s.pb.push_back(Ellipse{{b1, b2}, {{{R[0][0], R[0][1], c[0]}, {R[1][0], R[1][1], c[1]}, {0, 0, 1}}}});
  }
  return s;
}

inline Lazy<Static3D> static3d(make_static3d);
inline Lazy<Static2D> static2d(make_static2d);

inline json status_counts(const std::vector<Status>& v) {
  std::map<std::string, int> c;
  for (Status s : v) c[to_string(s)]++;
  json j = json::object();
  for (auto& [k, n] : c) j[k] = n;
  return j;
}

// The 3D pipelines as the ccd3d, phases and translation groups run them.

template <class T>
PipelineResult<T> run3d_floating(const PreparedPair<4>& p, const std::string& method, Basis basis, int bits,
                                 const T& like, bool first_contact) {
  if (method == "projection") {
    FloatingPolicy<T> pol(basis, bits, like);
    return ccd_projection(to_arithmetic<T, 4>(p, like), pol, first_contact);
  }
  std::vector<Bern<T>> g = characteristic_bernstein<T, 4>(p, basis == Basis::power, like);
  if (method == "bezier") {
    BezierOptions bo;
    bo.first_contact_only = first_contact;
    return ccd_bezier(g, like, bits, bo);
  }
  if (method.rfind("sampling:", 0) == 0) return ccd_sampling(g, like, std::stoi(method.substr(9)), first_contact);
  return ccd_marching(g, like, std::stoi(method.substr(9)), first_contact);
}
inline PipelineResult<Rational> run3d_exact(const PreparedPair<4>& p, bool first_contact = false) {
  ExactPolicy pol;
  return ccd_projection(to_arithmetic<Rational, 4>(p, Rational(1)), pol, first_contact);
}

// The options of a solve row (groups solve_scene-*, certified sets and cost).
inline SolveOptions opts(const char* arith, int variant, const char* method = "bezier") {
  SolveOptions o;
  o.arith = parse_arithmetic(arith);
  o.variant = Variant(variant);
  std::tie(o.method, o.grid) = parse_method(method);
  return o;
}

void register_static();            // bench/group_static.cpp
void register_2d();                // bench/group_ccd2d.cpp
void register_3d();                // bench/group_ccd3d.cpp
void register_isolation();         // bench/group_isolation.cpp
void register_phases();            // bench/group_phases.cpp
void register_solve_scene();       // bench/group_solve_scene.cpp
void register_planes();            // bench/group_planes.cpp
void register_translation3d();     // bench/group_translation3d.cpp
void register_product();           // bench/group_product.cpp
void register_animation();         // bench/group_animation.cpp
void register_fcl_static();        // bench/group_fcl.cpp
void register_fcl_table2();        // bench/group_fcl.cpp
void register_certified_sets();    // bench/group_certified_sets.cpp
void register_static_certified();  // bench/group_static_certified.cpp
void register_certified_cost();    // bench/group_certified_cost.cpp

}  // namespace eccd_bench::groups
