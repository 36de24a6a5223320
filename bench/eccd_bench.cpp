// eccd_bench: the performance benchmark of the workbench (issue 6, parts 1
// and 3). Separate from the tests: built only by `cmake --build B --target
// eccd_bench` (bench/ is added with EXCLUDE_FROM_ALL) and run by
// scripts/run-benchmarks.sh, which turns its summary into
// reports/performance.md (bench/performance_report.py).
//
// Why Google Benchmark (Debian libbenchmark-dev 1.7.1) and not Catch2's
// BENCHMARK: it repeats every measurement (repetitions) and computes the
// median over them itself, chooses the iteration count per repetition from a
// minimum time, measures per-thread or per-process CPU time as well as wall
// time, writes machine-readable JSON, and runs benchmarks registered at run
// time from tables (which is how the groups below are built), all without
// pulling the test framework and its test discovery into the measurement.
//
// What is measured. Every group has one baseline row, run in the same process
// as the other rows of its group; the repetitions of all rows are interleaved
// in random order (Google Benchmark's random interleaving: a burst of load from
// another user of the machine becomes a few outlying repetitions spread over
// many rows); the summary reports each row's median over
// the repetitions (CPU time of the benchmark thread; process CPU time, all
// threads, for the isolation rows, since MPSolve may use a thread pool; wall
// time alongside) and its ratio to the baseline's median. Groups:
//   static2d, static3d   the static tests in double on a batch of 1024 random
//        pairs (half separate): the generic determinant expansion of
//        det(λA - B) (kernel/characteristic_polynomial.hpp) against, in 3D,
//        001 Appendix A's 40-multiplication coefficients (kernel/fast_quartic.hpp,
//        A in standard position), each followed by the status decision
//        (kernel/contact_status.hpp cubic rule in 2D; Sturm count of the
//        negative roots, kernel/quartic_status.hpp, in 3D). Anchor: 001 "less
//        than 1 microsecond" on a 3 GHz Pentium IV for the whole static
//        procedure including the motion matrices.
//   ccd2d-degK-vV   2D CD-DISC (kernel/cd_disc.hpp) for motion degree K = 2,
//        4, 6 (general rational Euclidean motions in the kinematic image, 003
//        eq. (3), so that Δ has the full degree 24K: 48, 96, 144) and 003's
//        Variants V = 1 (collides?), 2 (first contact), 3 (all external
//        contacts), plus V = 0 (the full scene answer: intervals too), in
//        double, MPFR at 128 and 256 bits (Δ in Bernstein form, the default)
//        and exact rationals (certified); baseline: double. Anchor: 003 Fig. 8
//        (2.2 GHz Intel): degree 6, Δ of degree 144, under 1 ms (Variant 1),
//        5 ms (Variant 2), 7 ms (Variant 3).
//   ccd3d-SCENE     3D CCD for motion degree 2 and 4 and paper 002's example
//        (degree 4, projection of degree 216): in double each method (001's
//        Bézier zero-set method with f in Bernstein and in power form, the
//        projection pipeline, sampling:64 and marching:64, and Bézier in
//        first-contact mode) and exact (projection, certified); baseline:
//        double Bézier. Anchors: 001 3.7 ms (all four intervals, degree-4 affine
//        pair, Fig. 3) and 0.9 ms (first contact only); 002 Table I: 4.748 s
//        for degree 4 (Pentium 4, 2 GHz).
//   isolation-POLY  exact real root isolation of the very polynomials the
//        exact pipeline isolates (Δ(t) of the 2D scenes above, the 3D
//        projection polynomials) and of a random degree-200 integer polynomial:
//        the workbench's eccd::real_roots (CGAL Algebraic_kernel_d_1 over GMP
//        + MPFI, the baseline) against the same CGAL kernel called directly,
//        CGAL's kernel over CORE::BigInt, and MPSolve (isolation goal).
//        Anchor: CORE about 7 ms on a random degree-200 integer polynomial.
//   phases-*        the pipelines of the targets split into their public
//        steps, each timed alone on the same inputs (what dominates).
//   product-*       the target rows (issue 30): eccd::solve from the scene, what
//        a user waits for, on the 2D degree-6 scene (Variant 3) and paper
//        002's example; double as published and guarded, rounded and
//        prepared input, certified and exact. Baseline: double as published,
//        rounded input (the guarded row's ratio is the guard's cost).
//   solve_scene-*   rows through eccd::solve_scene (what `eccd solve` runs,
//        JSON building included), from a table of (label, SolveOptions),
//        kSolveSceneRows below: double, MPFR, exact and the certified interval
//        mode (`--arith certified`, issue 6 part 2; its rows go there).
//   plane-check, animate-boxers  issue 17: the kept plane's check over one
//        frame per pair-frame (baseline: the continuous test in double) and
//        the boxers' animation per frame in double, double without planes and
//        certified (baseline: double); with static-certified-2d/3d (the
//        static test from two poses) they form the report's "Animations"
//        section (bench/performance_report.py ANIMATION_GROUPS).
//   fcl-static3d, fcl-table2-main, fcl-table2-graze  issue 21: FCL side by
//        side in the same process: fcl::collide on the static3d pairs (per
//        pair, against eccd::static_status), and per frame of 000 Table 2's
//        orbit (bench/data/table2-*-40.anim.json): eccd::animate double and
//        certified, eccd::solve per frame, FCL sampled and continuous, with
//        the frames each misclassifies against the certified animation.
//        bench/fcl_side.* holds the FCL calls (FCL's headers stay there).
// What "pipeline" means in the ccd rows: what api/solve.cpp runs after the
// scene is read and prepared (prepare_pair<N>: exact, done once per scene, not
// timed): 2D to_arithmetic<T, 3> + cd_disc with FloatingPolicy<T> (Bernstein
// basis) or ExactPolicy; 3D characteristic_bernstein<T, 4> + ccd_bezier /
// ccd_sampling / ccd_marching, or to_arithmetic<T, 4> + ccd_projection. No JSON.
//
// Options (besides Google Benchmark's --benchmark_*):
//   --eccd_summary=FILE   write the summary JSON (groups, rows, medians,
//                         ratios, what each row answered) for the report
//   --eccd_quick          3 repetitions and short minimum times (development)
//   --eccd_list           print the selected scenes and exit
//   --eccd_profile_seconds=S  one repetition of at least S seconds per row
//                         (the report runs a missed target's row so under perf)
#include "api/solve.hpp"
#include "api/static_test.hpp"
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
#include "independent.hpp"  // issue 33

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

namespace {

// ---------------------------------------------------------------------------
// Registry: groups, rows, and what each row answered.

enum class Cost { fast, slow, very_slow, heavy };  // repetitions / minimum time policy (heavy: seconds per iteration, 3 repetitions)

struct Group {
  std::string id, title, description, anchor;
};
struct Row {
  std::string key, group, label, note;
  bool baseline = false;
};

std::vector<Group> g_groups;
std::vector<Row> g_rows;
std::map<std::string, json> g_results;  // key -> what the row computed (last timed iteration)
std::map<std::string, json> g_scenes;   // scene id -> description
bool g_quick = false;
double g_profile_seconds = 0;  // > 0: one repetition of at least this long per row (for perf)

void group(const std::string& id, const std::string& title, const std::string& description, const std::string& anchor) {
  g_groups.push_back({id, title, description, anchor});
}

// Registers one benchmark "group/label"; fn runs the timing loop.
void row(const std::string& grp, const std::string& label, bool baseline, Cost cost, const std::string& note,
         std::function<void(benchmark::State&)> fn, bool process_cpu = false) {
  std::string key = grp + "/" + label;
  g_rows.push_back({key, grp, label, note, baseline});
  auto* b = benchmark::RegisterBenchmark(key.c_str(), [fn](benchmark::State& st) { fn(st); });
  int reps = cost == Cost::fast ? 10 : (cost == Cost::slow ? 9 : (cost == Cost::very_slow ? 5 : 3));
  double min_time = cost == Cost::fast ? 0.1 : 0.05;
  if (g_quick) { reps = 3; min_time = 0.01; }
  if (g_profile_seconds > 0) { reps = 1; min_time = g_profile_seconds; }
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

std::string short_instant(const Instant& i) { return i.approx.substr(0, std::min<std::size_t>(i.approx.size(), 10)); }

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
json summarise_solution(const Solution& s) {
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

std::string src(const std::string& rel) { return std::string(ECCD_SOURCE_DIR) + "/" + rel; }

// A general rational Euclidean motion of degree 2m in the kinematic image
// (003 eq. (3)): d0..d3 polynomials of degree m with integer coefficients, so
// that every entry of M(t) has degree 2m and, generically, Δ(t) has degree 24
// times the motion degree (003 Table I). The centre is shifted by (cx, 0):
// d0 += cx d3 / 2, d1 -= cx d2 / 2 (the centre (x, y) of 003 eq. (3) is
// linear in d0, d1 for given d2, d3).
ojson kinematic_motion(std::mt19937_64& rng, int m, int cx) {
  std::uniform_int_distribution<int> small(-2, 2), lead(2, 4), wide(-4, 4);
  std::array<std::vector<mpq_class>, 4> d;
  for (int k = 0; k < 4; ++k) d[k].assign(m + 1, 0);
  for (int i = 0; i <= m; ++i) {
    d[2][i] = i == 0 ? lead(rng) : small(rng);
    d[3][i] = small(rng);
    d[0][i] = wide(rng);
    d[1][i] = wide(rng);
  }
  for (int k : {2, 3}) if (d[k][m] == 0) d[k][m] = 1;  // full degree m
  for (int i = 0; i <= m; ++i) {
    mpq_class a = d[0][i] + mpq_class(cx) * d[3][i] / 2, b = d[1][i] - mpq_class(cx) * d[2][i] / 2;
    d[0][i] = a;
    d[1][i] = b;
  }
  ojson arr = ojson::array();
  for (int k = 0; k < 4; ++k) {
    ojson p = ojson::array();
    for (auto& c : d[k]) { c.canonicalize(); p.push_back(c.get_str()); }
    arr.push_back(p);
  }
  return ojson{{"type", "kinematic"}, {"d", arr}};
}

Scene kinematic_scene(int motion_degree, std::uint64_t seed, bool apart) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> axis(2, 5);
  int m = motion_degree / 2;
  ojson s;
  s["format"] = "ellipse-ccd-scene/1";
  s["name"] = "bench-2d-deg" + std::to_string(motion_degree) + (apart ? "-free-" : "-colliding-") + std::to_string(seed);
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

PipelineResult<double> run2d_double(const PreparedPair<3>& p, Variant v, Basis basis = Basis::bernstein) {
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
PipelineResult<Rational> run2d_exact(const PreparedPair<3>& p, Variant v) {
  ExactPolicy pol;
  MovingPair<Rational, 3> m = to_arithmetic<Rational, 3>(p, Rational(1));
  return cd_disc(m, pol, v);
}

// The first seed from `seed` on whose scene the exact answer has the wanted
// kind (separate at t = 0, then colliding with >= 2 external contacts; or free), Δ has the full degree
// 24 K, and double CD-DISC agrees on collides and the number of contacts.
Scene2D select_2d(int degree, bool apart, std::uint64_t seed) {
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
    out.info = {{"dim", 2}, {"motion_degree", degree}, {"family", apart ? "free" : "colliding"}, {"seed", seed},
                {"tries", tries + 1}, {"projection_degree", e.projection_degree}, {"exact_answer", summarise_ccd(e)},
                {"source", "generated in-process (bench/eccd_bench.cpp kinematic_scene), general kinematic-image motion"}};
    return out;
  }
  throw std::runtime_error("no 2D scene of degree " + std::to_string(degree) + " found");
}

Scene2D scene2d_from_file(const std::string& id, const std::string& rel) {
  Scene sc = read_scene_file(src(rel));
  PreparedPair<3> p = prepare_pair<3>(sc);
  auto e = run2d_exact(p, Variant::answer);
  Scene2D out{id, sc, p, json::object()};
  out.info = {{"dim", 2}, {"file", rel}, {"projection_degree", e.projection_degree}, {"exact_answer", summarise_ccd(e)}};
  return out;
}

struct Scene3D {
  std::string id;
  Scene scene;
  PreparedPair<4> p;
  json info;
};

Scene3D scene3d_from_file(const std::string& id, const std::string& rel, const std::string& what) {
  Scene sc = read_scene_file(src(rel));
  Scene3D out{id, sc, prepare_pair<4>(sc), json::object()};
  out.info = {{"dim", 3}, {"file", rel}, {"what", what}};
  return out;
}

// Seeds found by select_2d's search (it starts here and takes the first fit).
constexpr std::uint64_t kSeed2D = 6001;

Lazy<Scene2D> s2d_deg2([] { return select_2d(2, false, kSeed2D); });
Lazy<Scene2D> s2d_deg4([] { return select_2d(4, false, kSeed2D); });
Lazy<Scene2D> s2d_deg6([] { return select_2d(6, false, kSeed2D); });
Lazy<Scene2D> s2d_deg6_free([] { return select_2d(6, true, kSeed2D); });
Lazy<Scene2D> s2d_paper003([] { return scene2d_from_file("paper003-example2", "cases/paper003/example2.json"); });

Lazy<Scene3D> s3d_deg2([] {
  return scene3d_from_file("3d-deg2-affine", "cases/generated/3d-affine/3d-deg2-colliding-affine-2295206434708192.json",
                           "generated corpus, degree-2 affine motions: separate at t = 0, one collision interval, two contacts");
});
Lazy<Scene3D> s3d_deg4([] {
  return scene3d_from_file("3d-deg4-euler", "cases/generated/3d-euler/3d-deg4-colliding-euler-8020579862790034.json",
                           "generated corpus, degree-4 Euler-parameter motions: separate at t = 0, one collision interval");
});
Lazy<Scene3D> s3d_deg4_affine([] {
  return scene3d_from_file("3d-deg4-affine", "cases/generated/3d-affine/3d-deg4-colliding-affine-6989596756321537.json",
                           "generated corpus, degree-4 affine motions, colliding (001 Fig. 3 is a degree-4 affine pair)");
});
Lazy<Scene3D> s3d_paper002([] {
  return scene3d_from_file("paper002-example", "cases/paper002/example.json",
                           "paper 002's numerical example (degree-4 Euler motions, projection of degree 216)");
});

Lazy<Scene2D>* scene2d_by_degree(int k) { return k == 2 ? &s2d_deg2 : (k == 4 ? &s2d_deg4 : &s2d_deg6); }

void note_scene(const Scene2D& s) { g_scenes[s.id] = s.info; }
void note_scene(const Scene3D& s, const std::string& group) {
  json j = s.info;
  j["group"] = group;  // the report takes Δ's degree and the exact answer from the group's exact row
  g_scenes[s.id] = j;
}

// ---------------------------------------------------------------------------
// Static tests: batches of random pairs in double.

constexpr int kBatch = 1024;

using M3 = std::array<std::array<double, 3>, 3>;
using M4 = std::array<std::array<double, 4>, 4>;

// A: axis-aligned at the origin (standard position, diag(1/a², ..., -1)); B:
// rotated by a random unit quaternion (or angle), semi-axes in [1, 3], centre
// at a random distance in [0, 7] (about half the pairs separate).
struct Static3D {
  std::vector<std::array<double, 3>> e;  // ea, eb, ec of A
  std::vector<M4> a, b;                  // A = diag(ea, eb, ec, -1) and B in A's frame
  std::vector<std::vector<double>> coeffs;  // Appendix A coefficients (for the status-only row)
  std::vector<Ellipsoid> pa, pb;            // the same pairs as a user gives them: semi-axes and poses (the API's input)
};
struct Static2D {
  std::vector<M3> a, b;
  std::vector<std::vector<double>> coeffs;
  std::vector<Ellipse> pa, pb;
};

Static3D make_static3d() {
  std::mt19937_64 rng(3003);
  std::uniform_real_distribution<double> ax(1.0, 3.0), dist(0.0, 7.0), nrm(-1.0, 1.0);
  Static3D s;
  for (int n = 0; n < kBatch; ++n) {
    double a1 = ax(rng), a2 = ax(rng), a3 = ax(rng);
    std::array<double, 3> ea{1 / (a1 * a1), 1 / (a2 * a2), 1 / (a3 * a3)};
    double q[4];
    double qn = 0;
    for (double& x : q) { x = nrm(rng); qn += x * x; }
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
    { auto c = appendix_a_coefficients(ea[0], ea[1], ea[2], B); s.coeffs.emplace_back(c.begin(), c.end()); }
  }
  return s;
}

Static2D make_static2d() {
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

Lazy<Static3D> static3d(make_static3d);
Lazy<Static2D> static2d(make_static2d);

json status_counts(const std::vector<Status>& v) {
  std::map<std::string, int> c;
  for (Status s : v) c[to_string(s)]++;
  json j = json::object();
  for (auto& [k, n] : c) j[k] = n;
  return j;
}

void register_static() {
  group("static3d", "3D static separation test in double (per pair)",
        "A batch of 1024 random ellipsoid pairs, A in standard position (diag(1/a², 1/b², 1/c², -1)), B rotated and "
        "translated into A's frame; one pair per iteration. The target row 'Appendix A + Sturm' times the API, "
        "eccd::static_status from the two ellipsoids' semi-axes and poses (api/static_test.hpp: both shapes as unit balls "
        "under their axis-scaled poses, the relative pose by the adjugate and 001 Appendix A in plain double with static "
        "error bounds, Descartes and the discriminant's sign, kernel/static_filter3d.hpp; the running-bound Sturm test "
        "only where that is uncertain). Row "
        "'static_status_batch' is the batched API, 64 pairs per iteration. The other rows "
        "split plain double on B given in A's frame: coefficients of f(λ) = det(λA - B) by the generic "
        "determinant expansion (2^4 column choices, kernel/characteristic_polynomial.hpp) or by 001 Appendix A "
        "(kernel/fast_quartic.hpp, 40 multiplications + det B by cofactors); status from the Sturm count of the "
        "negative roots (kernel/quartic_status.hpp). Rows 'coefficients only' and 'status only' split the time.",
        "001: the whole static procedure (motion matrices of degree 4 included) in under 1 µs on a 3 GHz Pentium IV; "
        "issue 21 target: at most 40 ns per pair (batched: 15 ns per pair)");
  auto all3 = [](auto status_of) {
    const Static3D& s = static3d.get();
    std::vector<Status> v;
    for (int i = 0; i < kBatch; ++i) v.push_back(status_of(i));
    return status_counts(v);
  };
  row("static3d", "generic det + Sturm", true, Cost::fast, "characteristic_coefficients_in<double,4> + quartic_contact_status",
      [all3](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return quartic_contact_status(characteristic_coefficients_in<double, 4>(s.a[i], s.b[i], 0.0));
        };
        timed(st, "static3d/generic det + Sturm", f, [&](Status) {
          return all3([&](int k) { return quartic_contact_status(characteristic_coefficients_in<double, 4>(s.a[k], s.b[k], 0.0)); });
        });
      });
  // The target row: what a user's program runs, eccd::static_status (api/static_test.hpp) from the two
  // ellipsoids' semi-axes and poses: B's pose relative to A's, 001 Appendix A and the Sturm count, in
  // Bounded<double> (uncertain where double's error bound is not decisive).
  row("static3d", "Appendix A + Sturm", false, Cost::fast,
      "eccd::static_status(a, b) from two poses (the API: relative pose, Appendix A, Sturm, with error bound; the target row)",
      [all3](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return static_status(s.pa[i], s.pb[i]);
        };
        timed(st, "static3d/Appendix A + Sturm", f, [&](Status) { return all3([&](int k) { return static_status(s.pa[k], s.pb[k]); }); });
      });
  // Issue 21: the batched API, 64 pairs per iteration (the figure per pair is the median / 64; target 15 ns per pair).
  row("static3d", "static_status_batch (API, 64 pairs per iteration)", false, Cost::fast,
      "eccd::static_status_batch over 64 pairs from two poses (blocks of 8 lanes in structure of arrays through the static "
      "filter compiled for AVX-512 where the CPU has it, api/static_filter_simd.hpp; pair by pair otherwise); divide by 64 "
      "for the time per pair",
      [all3](benchmark::State& st) {
        const Static3D& s = static3d.get();
        std::size_t i = 0;
        std::array<Status, 64> out;
        auto f = [&] {
          i = (i + 64) & (kBatch - 1);
          static_status_batch(std::span<const Ellipsoid>(s.pa).subspan(i, 64), std::span<const Ellipsoid>(s.pb).subspan(i, 64),
                              std::span<Status>(out));
          return out[0];
        };
        timed(st, "static3d/static_status_batch (API, 64 pairs per iteration)", f, [&](Status) {
          std::vector<Status> v(kBatch);
          static_status_batch(std::span<const Ellipsoid>(s.pa), std::span<const Ellipsoid>(s.pb), std::span<Status>(v));
          return status_counts(v);
        });
      });
  row("static3d", "Appendix A + Sturm, plain double, B given in A's frame", false, Cost::fast,
      "appendix_a_coefficients + quartic_contact_status in plain double on precomputed B (no pose, no error bound)",
      [all3](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          return quartic_contact_status(appendix_a_coefficients(s.e[i][0], s.e[i][1], s.e[i][2], s.b[i]));
        };
        timed(st, "static3d/Appendix A + Sturm, plain double, B given in A's frame", f, [&](Status) {
          return all3([&](int k) { return quartic_contact_status(appendix_a_coefficients(s.e[k][0], s.e[k][1], s.e[k][2], s.b[k])); });
        });
      });
  row("static3d", "generic det, coefficients only", false, Cost::fast, "characteristic_coefficients_in<double,4>",
      [](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] { i = (i + 1) & (kBatch - 1); return characteristic_coefficients_in<double, 4>(s.a[i], s.b[i], 0.0); };
        timed(st, "static3d/generic det, coefficients only", f, [](const std::vector<double>&) { return json(); });
      });
  row("static3d", "Appendix A, coefficients only", false, Cost::fast, "appendix_a_coefficients (001 Appendix A)",
      [](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] { i = (i + 1) & (kBatch - 1); return appendix_a_coefficients(s.e[i][0], s.e[i][1], s.e[i][2], s.b[i]); };
        timed(st, "static3d/Appendix A, coefficients only", f, [](const std::array<double, 5>&) { return json(); });
      });
  row("static3d", "Sturm status only", false, Cost::fast, "quartic_contact_status on precomputed coefficients",
      [](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] { i = (i + 1) & (kBatch - 1); return quartic_contact_status(s.coeffs[i]); };
        timed(st, "static3d/Sturm status only", f, [](Status) { return json(); });
      });

  group("static2d", "2D static separation test in double (per pair)",
        "A batch of 1024 random pairs of ellipses, A axis-aligned at the origin, B rotated and translated; one pair per "
        "iteration. Coefficients g0..g3 of the cubic f(λ) = det(λA - B) by the generic determinant expansion "
        "(2^3 column choices), status by 003 Theorem 6 from signs only (discriminant, Descartes; "
        "kernel/contact_status.hpp). Row 'static_status (API, two poses)' is what a user's program runs: "
        "eccd::static_status from the semi-axes and poses (api/static_test.hpp: B relative to A, the 3x3 analogue "
        "of 001 Appendix A, with double's error bound).",
        "003 gives no static timing; 000: about 8 µs per static 3D test with root solving (for scale)");
  auto all2 = [](auto status_of) {
    std::vector<Status> v;
    for (int i = 0; i < kBatch; ++i) v.push_back(status_of(i));
    return status_counts(v);
  };
  row("static2d", "generic det + cubic rule", true, Cost::fast, "characteristic_coefficients_in<double,3> + cubic_contact_status",
      [all2](benchmark::State& st) {
        const Static2D& s = static2d.get();
        int i = 0;
        auto st_of = [&](int k) {
          std::vector<double> g = characteristic_coefficients_in<double, 3>(s.a[k], s.b[k], 0.0);
          return cubic_contact_status(g[3], g[2], g[1], g[0]);
        };
        auto f = [&] { i = (i + 1) & (kBatch - 1); return st_of(i); };
        timed(st, "static2d/generic det + cubic rule", f, [&](Status) { return all2(st_of); });
      });
  row("static2d", "static_status (API, two poses)", false, Cost::fast,
      "eccd::static_status(a, b) from two poses (the API: relative pose, closed-form cubic, 003 Theorem 6 rule, with error bound)",
      [all2](benchmark::State& st) {
        const Static2D& s = static2d.get();
        int i = 0;
        auto st_of = [&](int k) { return static_status(s.pa[k], s.pb[k]); };
        auto f = [&] { i = (i + 1) & (kBatch - 1); return st_of(i); };
        timed(st, "static2d/static_status (API, two poses)", f, [&](Status) { return all2(st_of); });
      });
  row("static2d", "static_status_batch (API, 64 pairs per iteration)", false, Cost::fast,
      "eccd::static_status_batch over 64 pairs from two poses; divide by 64 for the time per pair",
      [](benchmark::State& st) {
        const Static2D& s = static2d.get();
        std::size_t i = 0;
        std::array<Status, 64> out;
        auto f = [&] {
          i = (i + 64) & (kBatch - 1);
          static_status_batch(std::span<const Ellipse>(s.pa).subspan(i, 64), std::span<const Ellipse>(s.pb).subspan(i, 64),
                              std::span<Status>(out));
          return out[0];
        };
        timed(st, "static2d/static_status_batch (API, 64 pairs per iteration)", f, [&](Status) {
          std::vector<Status> v(kBatch);
          static_status_batch(std::span<const Ellipse>(s.pa), std::span<const Ellipse>(s.pb), std::span<Status>(v));
          return status_counts(v);
        });
      });
  row("static2d", "generic det, coefficients only", false, Cost::fast, "characteristic_coefficients_in<double,3>",
      [](benchmark::State& st) {
        const Static2D& s = static2d.get();
        int i = 0;
        auto f = [&] { i = (i + 1) & (kBatch - 1); return characteristic_coefficients_in<double, 3>(s.a[i], s.b[i], 0.0); };
        timed(st, "static2d/generic det, coefficients only", f, [](const std::vector<double>&) { return json(); });
      });
  row("static2d", "cubic rule only", false, Cost::fast, "cubic_contact_status on precomputed coefficients",
      [](benchmark::State& st) {
        const Static2D& s = static2d.get();
        int i = 0;
        auto f = [&] {
          i = (i + 1) & (kBatch - 1);
          const auto& g = s.coeffs[i];
          return cubic_contact_status(g[3], g[2], g[1], g[0]);
        };
        timed(st, "static2d/cubic rule only", f, [](Status) { return json(); });
      });
}

// ---------------------------------------------------------------------------
// 2D CCD.

const char* variant_title(int v) {
  switch (v) {
    case 1: return "Variant 1 (collides?)";
    case 2: return "Variant 2 (first contact)";
    case 3: return "Variant 3 (all external contacts)";
    default: return "full answer (intervals, first contact, contacts)";
  }
}

void add_2d_rows(const std::string& grp, Lazy<Scene2D>* sc, int v, bool mpfr = true) {
  Variant var = Variant(v);
  auto note = [sc](const std::string& what) { return what; };
  row(grp, "double", true, Cost::slow, note("to_arithmetic<double,3> + cd_disc, FloatingPolicy<double> (Bernstein)"),
      [sc, var, grp](benchmark::State& st) {
        const Scene2D& s = sc->get();
        note_scene(s);
        timed(st, grp + "/double", [&] { return run2d_double(s.p, var); }, [](const auto& r) { return summarise_ccd(r); });
      });
  if (mpfr)
    for (int bits : {128, 256}) {
      std::string label = "mpfr:" + std::to_string(bits);
      row(grp, label, false, Cost::slow, "to_arithmetic<Mpfr,3> + cd_disc, FloatingPolicy<Mpfr> (Bernstein)",
          [sc, var, grp, label, bits](benchmark::State& st) {
            const Scene2D& s = sc->get();
            note_scene(s);
            Mpfr like(mpq_class(1), bits);
            timed(st, grp + "/" + label, [&] { return run2d_floating<Mpfr>(s.p, var, Basis::bernstein, bits, like); },
                  [](const auto& r) { return summarise_ccd(r); });
          });
    }
  row(grp, "exact", false, Cost::slow, "to_arithmetic<Rational,3> + cd_disc, ExactPolicy (certified)",
      [sc, var, grp](benchmark::State& st) {
        const Scene2D& s = sc->get();
        note_scene(s);
        timed(st, grp + "/exact", [&] { return run2d_exact(s.p, var); }, [](const auto& r) { return summarise_ccd(r); });
      });
}

void register_2d() {
  for (int k : {2, 4, 6}) {
    for (int v : {1, 2, 3, 0}) {
      std::string grp = "ccd2d-deg" + std::to_string(k) + "-v" + std::to_string(v);
      std::string anchor = k == 6 ? (v == 1 ? "003 Fig. 8: under 1 ms (degree 6, 2.2 GHz Intel)"
                                   : v == 2 ? "003 Fig. 8: under 5 ms"
                                   : v == 3 ? "003 Fig. 8: under 7 ms; issue 21 target: double at most 50 µs (issue 6: 0.5 ms)"
                                            : "issue 21 target: exact certified answer at most 5 ms (issue 6: 50 ms)")
                                 : "003 Fig. 8 (curves for degrees 2 and 4 lie below the degree-6 figures)";
      group(grp, "2D CCD, motion degree " + std::to_string(k) + ", " + variant_title(v),
            "CD-DISC on a colliding pair of ellipses under general rational Euclidean motions of degree " +
                std::to_string(k) + " (Δ of degree " + std::to_string(24 * k) +
                ", two or more external contacts); baseline: double.",
            anchor);
      add_2d_rows(grp, scene2d_by_degree(k), v);
    }
  }
  group("ccd2d-deg6-free", "2D CCD, motion degree 6, a collision-free pair",
        "The same pipelines on a pair that never collides (Δ of degree 144 without roots in [0, 1]: 003 Fig. 8(b)).",
        "003 Fig. 8(b): collision-free pairs, degree 6");
  {
    Lazy<Scene2D>* sc = &s2d_deg6_free;
    for (int v : {1, 3}) {
      std::string label = "double v" + std::to_string(v);
      row("ccd2d-deg6-free", label, v == 3, Cost::slow, "to_arithmetic + cd_disc, double, Bernstein",
          [sc, v, label](benchmark::State& st) {
            const Scene2D& s = sc->get();
            note_scene(s);
            timed(st, "ccd2d-deg6-free/" + label, [&] { return run2d_double(s.p, Variant(v)); },
                  [](const auto& r) { return summarise_ccd(r); });
          });
    }
    row("ccd2d-deg6-free", "exact v0", false, Cost::slow, "to_arithmetic + cd_disc, ExactPolicy", [sc](benchmark::State& st) {
      const Scene2D& s = sc->get();
      note_scene(s);
      timed(st, "ccd2d-deg6-free/exact v0", [&] { return run2d_exact(s.p, Variant::answer); },
            [](const auto& r) { return summarise_ccd(r); });
    });
  }
  group("ccd2d-deg6-basis", "2D CCD, motion degree 6, Variant 3: how Δ is built (003 VI-C)",
        "Double CD-DISC with g_i and Δ in Bernstein form (the default), in power form (converted for the "
        "subdivision), and in scaled Bernstein form (003's choice for Variant 1); MPFR at 128 bits in power form.",
        "003 Fig. 8 (dashed lines: time to obtain Δ in Bernstein and scaled Bernstein form)");
  {
    Lazy<Scene2D>* sc = &s2d_deg6;
    struct B { const char* label; Basis basis; int bits; };
    for (B b : {B{"double bernstein", Basis::bernstein, 53}, B{"double power", Basis::power, 53},
                B{"double scaled-bernstein", Basis::scaled_bernstein, 53}, B{"mpfr:128 power", Basis::power, 128}}) {
      std::string label = b.label;
      row("ccd2d-deg6-basis", label, b.basis == Basis::bernstein, Cost::slow, std::string("cd_disc, basis ") + to_string(b.basis),
          [sc, b, label](benchmark::State& st) {
            const Scene2D& s = sc->get();
            note_scene(s);
            if (b.bits == 53)
              timed(st, "ccd2d-deg6-basis/" + label, [&] { return run2d_double(s.p, Variant::all_contacts, b.basis); },
                    [](const auto& r) { return summarise_ccd(r); });
            else {
              Mpfr like(mpq_class(1), b.bits);
              timed(st, "ccd2d-deg6-basis/" + label,
                    [&] { return run2d_floating<Mpfr>(s.p, Variant::all_contacts, b.basis, b.bits, like); },
                    [](const auto& r) { return summarise_ccd(r); });
            }
          });
    }
  }
  group("ccd2d-paper003", "2D CCD, paper 003's Example 2 (degree 4, Δ of degree 96, touch at t = 1/2)",
        "cases/paper003/example2.json: Variant 3 and the full answer.", "003 section VI-C, Example 2");
  add_2d_rows("ccd2d-paper003", &s2d_paper003, 3, false);
}

// ---------------------------------------------------------------------------
// 3D CCD.

template <class T>
PipelineResult<T> run3d_floating(const PreparedPair<4>& p, const std::string& method, Basis basis, int bits, const T& like,
                               bool first_contact) {
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
PipelineResult<Rational> run3d_exact(const PreparedPair<4>& p, bool first_contact = false) {
  ExactPolicy pol;
  return ccd_projection(to_arithmetic<Rational, 4>(p, Rational(1)), pol, first_contact);
}

void register_3d() {
  struct S { Lazy<Scene3D>* sc; const char* id; const char* title; const char* anchor; };
  for (S s : {S{&s3d_deg2, "ccd3d-deg2", "3D CCD, motion degree 2 (affine), colliding",
                "002 Table I: degree 2, 1.113 s (Pentium 4, 2 GHz)"},
              S{&s3d_deg4, "ccd3d-deg4", "3D CCD, motion degree 4 (Euler parameters), colliding",
                "002 Table I: degree 4, 4.748 s"},
              S{&s3d_deg4_affine, "ccd3d-deg4-affine", "3D CCD, motion degree 4 (affine deformation), colliding",
                "001 Fig. 3: degree-4 affine pair, all four intervals 3.7 ms, first contact 0.9 ms (3 GHz Pentium IV)"},
              S{&s3d_paper002, "ccd3d-paper002", "3D CCD, paper 002's example (degree 4, projection of degree 216)",
                "issue 21 targets: double at most 0.3 ms, exact at most 25 ms, certified at most 3x double (issue 6: 2 ms, 1 s); "
                "001: 3.7 ms for a degree-4 affine pair; 002: 4.7 s (Table I, degree 4)"}}) {
    group(s.id, s.title,
          "Phase rows, not targets: all collision intervals (and contacts) from the exactly prepared pair, in plain "
          "double (the method as published, no guard) by each method, and the certified answer in exact arithmetic "
          "(projection); baseline: double Bézier (001 section 4, f in Bernstein form). What `eccd solve` runs (guarded, "
          "from the scene) is timed in the product-* groups.",
          s.anchor);
    struct M { const char* label; const char* method; Basis basis; bool fc; };
    for (M m : {M{"double bezier", "bezier", Basis::bernstein, false}, M{"double bezier power", "bezier", Basis::power, false},
                M{"double projection", "projection", Basis::bernstein, false},
                M{"double sampling:64", "sampling:64", Basis::bernstein, false},
                M{"double marching:64", "marching:64", Basis::bernstein, false},
                M{"double bezier first-contact", "bezier", Basis::bernstein, true}}) {
      std::string grp = s.id, label = m.label;
      // Not run: double projection on the affine scenes did not finish within
      // 60 s (eccd solve --method projection neither, on every scene of
      // cases/generated/3d-affine; perf: 98% in eccd::split<double>, the de
      // Casteljau subdivision of floating/bernstein_roots.hpp). Reported in
      // reports/performance.md.
      if ((s.sc == &s3d_deg4_affine || s.sc == &s3d_deg2) && std::string(m.method) == "projection") continue;
      Lazy<Scene3D>* sc = s.sc;
      row(grp, label, std::string(m.label) == "double bezier", Cost::slow,
          std::string(m.method == std::string("projection") ? "to_arithmetic<double,4> + ccd_projection"
                                                            : "characteristic_bernstein<double,4> + ccd_") +
              (m.method == std::string("projection") ? "" : m.method) + (m.fc ? " (first contact only)" : ""),
          [sc, m, grp, label](benchmark::State& st) {
            const Scene3D& sd = sc->get();
            note_scene(sd, grp);
            timed(st, grp + "/" + label, [&] { return run3d_floating<double>(sd.p, m.method, m.basis, 53, 1.0, m.fc); },
                  [](const auto& r) { return summarise_ccd(r); });
          });
    }
    std::string grp = s.id;
    Lazy<Scene3D>* sc = s.sc;
    // Issue 21: the certified mode on paper 002's example, from the same prepared pair as the double rows
    // (run_certified, what solve runs for --arith certified after prepare_pair; no JSON), so that
    // certified / double bezier is a ratio of like with like.
    if (sc == &s3d_paper002)
      row(grp, "certified", false, Cost::slow,
          "run_certified<4>(prepared pair, MPFI rungs {256}): interval Bézier proof, escalating to MPFI / exact where undecided",
          [sc, grp](benchmark::State& st) {
            const Scene3D& sd = sc->get();
            note_scene(sd, grp);
            const std::vector<int> rungs = Arithmetic::certified().mpfi_rungs;
            timed(st, grp + "/certified", [&] { return run_certified<4>(sd.p, rungs, Variant::answer, false); },
                  [](const Solution& r) { return summarise_solution(r); });
          });
    row(grp, "exact", false, Cost::very_slow, "to_arithmetic<Rational,4> + ccd_projection, ExactPolicy (certified)",
        [sc, grp](benchmark::State& st) {
          const Scene3D& sd = sc->get();
          note_scene(sd, grp);
          timed(st, grp + "/exact", [&] { return run3d_exact(sd.p); }, [](const auto& r) { return summarise_ccd(r); });
        });
  }
}

// ---------------------------------------------------------------------------
// Exact real root isolation.

struct IsoPoly {
  std::string id, what;
  Poly<Rational> p;
  std::vector<mpz_class> z;  // primitive integer coefficients
};

IsoPoly iso_from(const std::string& id, const std::string& what, const Poly<Rational>& p) {
  IsoPoly ip{id, what, p, {}};
  for (const auto& s : integer_coefficients(p)) ip.z.emplace_back(s);
  return ip;
}

Lazy<IsoPoly> iso_deg2([] { return iso_from("2d-deg2", "Δ(t) of the 2D degree-2 scene", certificate_algebra(s2d_deg2.get().scene).projection); });
Lazy<IsoPoly> iso_deg4([] { return iso_from("2d-deg4", "Δ(t) of the 2D degree-4 scene", certificate_algebra(s2d_deg4.get().scene).projection); });
Lazy<IsoPoly> iso_deg6([] { return iso_from("2d-deg6", "Δ(t) of the 2D degree-6 scene", certificate_algebra(s2d_deg6.get().scene).projection); });
Lazy<IsoPoly> iso_3d_deg2([] {
  return iso_from("3d-deg2", "projection of the 3D degree-2 affine scene", certificate_algebra(s3d_deg2.get().scene).projection);
});
Lazy<IsoPoly> iso_paper002([] {
  return iso_from("paper002", "projection (discriminant) of paper 002's example", certificate_algebra(s3d_paper002.get().scene).projection);
});
Lazy<IsoPoly> iso_random200([] {
  std::mt19937_64 rng(200);
  std::uniform_int_distribution<long> c(-1000, 1000);
  Poly<Rational> p;
  for (int i = 0; i <= 200; ++i) p.c.push_back(Rational(c(rng)));
  if (p.c.back() == 0) p.c.back() = 1;
  return iso_from("random200", "random integer polynomial of degree 200, coefficients uniform in [-1000, 1000] (seed 200)", p);
});

json iso_info(const IsoPoly& ip) {
  std::size_t bits = 0;
  for (const auto& z : ip.z) bits = std::max(bits, mpz_sizeinbase(z.get_mpz_t(), 2));
  return {{"what", ip.what}, {"degree", ip.p.degree()}, {"max_coefficient_bits", bits}};
}

void register_isolation() {
  struct P { Lazy<IsoPoly>* poly; const char* id; };
  for (P pp : {P{&iso_deg2, "isolation-2d-deg2"}, P{&iso_deg4, "isolation-2d-deg4"}, P{&iso_deg6, "isolation-2d-deg6"},
               P{&iso_3d_deg2, "isolation-3d-deg2"}, P{&iso_paper002, "isolation-paper002"},
               P{&iso_random200, "isolation-random200"}}) {
    std::string grp = pp.id;
    group(grp, std::string("Exact real root isolation: ") + (grp.substr(10)),
          "The same integer polynomial isolated by the workbench (eccd::real_roots on [0, 1], brackets of width "
          "2^-64: CGAL Algebraic_kernel_d_1 over CORE::BigInt isolates, the workbench refines the roots in [0, 1] "
          "by quadratic interval refinement), by CGAL's kernel over GMP + MPFI (all real roots), by CGAL's kernel over "
          "CORE::BigInt called directly (all real roots) and by MPSolve (isolating discs for all complex "
          "roots). Process CPU time (all threads).",
          grp == "isolation-random200" ? "issue 6: CGAL with CORE about 7 ms on a random degree-200 integer polynomial (this machine)"
                                       : "the workbench's own isolation (baseline)");
    Lazy<IsoPoly>* poly = pp.poly;
    row(grp, "workbench real_roots (CGAL CORE + own refinement)", true, Cost::slow,
        "eccd::real_roots(p, 0, 1, 64): conversion, solve_1, brackets to 2^-64, restriction to [0, 1]",
        [poly, grp](benchmark::State& st) {
          const IsoPoly& ip = poly->get();
          timed(st, grp + "/workbench real_roots (CGAL CORE + own refinement)", [&] { return real_roots(ip.p, Rational(0), Rational(1), 64); },
                [&](const std::vector<AlgebraicRoot>& r) {
                  json j = iso_info(ip);
                  j["in_unit"] = r.size();
                  return j;
                });
        },
        true);
    struct L { const char* label; std::unique_ptr<eccd_bench::PreparedIsolation> (*prep)(const std::vector<mpz_class>&); const char* note; };
    for (L l : {L{"CGAL GMP+MPFI solve_1", eccd_bench::prepare_cgal_gmp_mpfi, "Algebraic_kernel_d_1<Gmpz>, CGAL_USE_MPFI, fresh kernel"},
                L{"CGAL CORE solve_1", eccd_bench::prepare_cgal_core, "Algebraic_kernel_d_1<CORE::BigInt>, fresh kernel"},
                L{"MPSolve isolate", eccd_bench::prepare_mpsolve, "mps_mpsolve, goal isolate, secular GA, all complex roots"}}) {
      std::string label = l.label;
      row(grp, label, false, Cost::slow, l.note,
          [poly, grp, label, l](benchmark::State& st) {
            const IsoPoly& ip = poly->get();
            auto prepared = l.prep(ip.z);
            timed(st, grp + "/" + label, [&] { return prepared->run(); }, [&](const eccd_bench::IsolationOutcome& o) {
              json j = iso_info(ip);
              j["roots"] = o.roots;
              j["in_unit"] = o.in_unit;
              return j;
            });
          },
          true);
    }
  }
}

// ---------------------------------------------------------------------------
// Phases: the targets' pipelines split into their public steps.

template <class T, class Policy>
void add_phases_2d(const std::string& grp, Lazy<Scene2D>* sc, Variant var, std::function<Policy()> make_pol,
                   std::function<T()> make_like) {
  struct In {
    MovingPair<T, 3> m;
    std::vector<Poly<T>> g;
    typename Policy::Rep delta, P, D;
    std::vector<typename Policy::Root> roots;
  };
  auto in = std::make_shared<Lazy<In>>([sc, make_pol, make_like] {
    const Scene2D& s = sc->get();
    Policy pol = make_pol();
    In x{to_arithmetic<T, 3>(s.p, make_like()), {}, {}, {}, {}, {}};
    x.g = characteristic_coefficients<T, 3>(moving_quadric<T, 3>(x.m.qa, x.m.na), moving_quadric<T, 3>(x.m.qb, x.m.nb));
    x.delta = discriminant_of(x.g, pol);
    x.P = build_cubic(pol, x.g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) { return double_root_numerator(g3, g2, g1, g0); });
    x.D = build_cubic(pol, x.g, [](const auto& g3, const auto& g2, const auto& g1, const auto&) { return double_root_denominator(g3, g2, g1); });
    x.roots = pol.roots(x.delta, false);
    return x;
  });
  auto none = [](const auto&) { return json(); };
  row(grp, "total pipeline", true, Cost::slow, "to_arithmetic + cd_disc", [=](benchmark::State& st) {
    const Scene2D& s = sc->get();
    T like = make_like();
    timed(st, grp + "/total pipeline", [&] {
      Policy pol = make_pol();
      MovingPair<T, 3> m = to_arithmetic<T, 3>(s.p, like);
      return cd_disc(m, pol, var);
    }, [](const auto& r) { return summarise_ccd(r); });
  });
  row(grp, "1 to_arithmetic", false, Cost::slow, "the exact scene rounded to the arithmetic", [=](benchmark::State& st) {
    const Scene2D& s = sc->get();
    T like = make_like();
    timed(st, grp + "/1 to_arithmetic", [&] { return to_arithmetic<T, 3>(s.p, like); }, none);
  });
  row(grp, "2 g = det(λA - B)", false, Cost::slow, "moving_quadric x 2 + characteristic_coefficients (power form)",
      [=](benchmark::State& st) {
        const In& x = in->get();
        timed(st, grp + "/2 g = det(λA - B)", [&] {
          return characteristic_coefficients<T, 3>(moving_quadric<T, 3>(x.m.qa, x.m.na), moving_quadric<T, 3>(x.m.qb, x.m.nb));
        }, none);
      });
  row(grp, "3 Δ build", false, Cost::slow, "discriminant_of(g, policy)", [=](benchmark::State& st) {
    const In& x = in->get();
    Policy pol = make_pol();
    timed(st, grp + "/3 Δ build", [&] { return discriminant_of(x.g, pol); }, none);
  });
  row(grp, "4 P, D build", false, Cost::slow, "policy.build of P = 9g3g0 - g2g1 and D = g2² - 3g3g1", [=](benchmark::State& st) {
    const In& x = in->get();
    Policy pol = make_pol();
    timed(st, grp + "/4 P, D build", [&] {
      auto P = build_cubic(pol, x.g, [](const auto& g3, const auto& g2, const auto& g1, const auto& g0) { return double_root_numerator(g3, g2, g1, g0); });
      auto D = build_cubic(pol, x.g, [](const auto& g3, const auto& g2, const auto& g1, const auto&) { return double_root_denominator(g3, g2, g1); });
      return std::make_pair(std::move(P), std::move(D));
    }, none);
  });
  row(grp, "5 roots of Δ", false, Cost::slow, "policy.roots(Δ)", [=](benchmark::State& st) {
    const In& x = in->get();
    Policy pol = make_pol();
    timed(st, grp + "/5 roots of Δ", [&] { return pol.roots(x.delta, false); },
          [](const auto& r) { return json{{"roots", r.size()}}; });
  });
  row(grp, "6 signs of P, D at the roots", false, Cost::slow, "policy.sign_at(P, r), policy.sign_at(D, r) for every root",
      [=](benchmark::State& st) {
        const In& x = in->get();
        Policy pol = make_pol();
        timed(st, grp + "/6 signs of P, D at the roots", [&] {
          int n = 0;
          for (const auto& r : x.roots) n += int(pol.sign_at(x.P, r)) + int(pol.sign_at(x.D, r));
          return n;
        }, none);
      });
}

void register_phases() {
  group("phases-2d-deg6-double-v3", "Where the time goes: 2D degree 6, Variant 3, double",
        "The steps of cd_disc timed one by one on the same inputs; the remainder (static tests at the samples, "
        "contact points, answer assembly) is the total minus the steps.",
        "issue 21 target for the total: at most 50 µs (issue 6: 0.5 ms)");
  add_phases_2d<double, FloatingPolicy<double>>("phases-2d-deg6-double-v3", &s2d_deg6, Variant::all_contacts,
                                                [] { return FloatingPolicy<double>(Basis::bernstein, 53, 1.0); },
                                                [] { return 1.0; });
  group("phases-2d-deg6-exact-v0", "Where the time goes: 2D degree 6, full answer, exact",
        "The steps of cd_disc with ExactPolicy timed one by one on the same inputs (roots: the square-free "
        "part by FLINT, CGAL's isolation and refinement; signs: exact signs at algebraic numbers).",
        "issue 21 target for the total: at most 5 ms (issue 6: 50 ms)");
  add_phases_2d<Rational, ExactPolicy>("phases-2d-deg6-exact-v0", &s2d_deg6, Variant::answer, [] { return ExactPolicy(); },
                                       [] { return Rational(1); });

  // 3D paper 002, double Bézier: setup of g, F(u, t), the zero-set analysis.
  std::string grp = "phases-paper002-double-bezier";
  group(grp, "Where the time goes: paper 002's example, double Bézier",
        "characteristic_bernstein (g_0..g_4 in Bernstein form from N(t) converted exactly to Bernstein form), "
        "F(u, t) = det((u-1)A - uB) as a bivariate Bernstein polynomial (BezierZeroSet's constructor), and the "
        "analysis (static tests at 33 samples, shooting, subdivision, Gaussian-circle tests); the remainder is "
        "ccd_bezier's answer assembly.",
        "issue 21 target for the total: at most 0.3 ms (issue 6: 2 ms)");
  auto g002 = std::make_shared<Lazy<std::vector<Bern<double>>>>([] { return characteristic_bernstein<double, 4>(s3d_paper002.get().p, false, 1.0); });
  row(grp, "total pipeline", true, Cost::slow, "characteristic_bernstein + ccd_bezier", [grp](benchmark::State& st) {
    const Scene3D& s = s3d_paper002.get();
    timed(st, grp + "/total pipeline", [&] { return run3d_floating<double>(s.p, "bezier", Basis::bernstein, 53, 1.0, false); },
          [](const auto& r) { return summarise_ccd(r); });
  });
  row(grp, "1 setup g (characteristic_bernstein)", false, Cost::slow, "", [grp](benchmark::State& st) {
    const Scene3D& s = s3d_paper002.get();
    timed(st, grp + "/1 setup g (characteristic_bernstein)", [&] { return characteristic_bernstein<double, 4>(s.p, false, 1.0); },
          [](const auto&) { return json(); });
  });
  row(grp, "1a to_arithmetic_bernstein (part of 1)", false, Cost::slow, "N(t) converted to Bernstein form exactly, then rounded", [grp](benchmark::State& st) {
    const Scene3D& s = s3d_paper002.get();
    timed(st, grp + "/1a to_arithmetic_bernstein (part of 1)", [&] { return to_arithmetic_bernstein<double, 4>(s.p, 1.0); },
          [](const auto&) { return json(); });
  });
  row(grp, "2 zero-set analysis (BezierZeroSet: F build + run)", false, Cost::slow,
      "BezierZeroSet<double>(g, ...).run(): static tests at the samples, shooting, subdivision, Gaussian-circle tests",
      [grp, g002](benchmark::State& st) {
        const auto& g = g002->get();
        timed(st, grp + "/2 zero-set analysis (BezierZeroSet: F build + run)", [&] {
          BezierZeroSet<double> z(g, 1.0, 53, BezierOptions{});
          return z.run().size();
        }, [](std::size_t n) { return json{{"timeline_nodes", n}}; });
      });
  row(grp, "2a F(u,t) build (part of 2)", false, Cost::slow, "BezierZeroSet constructor (ellipsoid_function)", [grp, g002](benchmark::State& st) {
    const auto& g = g002->get();
    timed(st, grp + "/2a F(u,t) build (part of 2)", [&] { return BezierZeroSet<double>(g, 1.0, 53, BezierOptions{}).F().degree_t(); },
          [](int d) { return json{{"degree_t", d}}; });
  });

  // 3D paper 002, exact projection.
  grp = "phases-paper002-exact";
  group(grp, "Where the time goes: paper 002's example, exact projection",
        "ccd_projection with ExactPolicy split: the exact g_k, the discriminant of the quartic (degree 216, built in "
        "FLINT), its isolation on [0, 1] (square-free factors by FLINT, isolation by CGAL), and the rest (exact Sturm counts in the cells, subresultant signs at the roots).",
        "issue 21 target for the total: at most 25 ms (issue 6: 1 s)");
  auto gx = std::make_shared<Lazy<std::vector<Poly<Rational>>>>([] {
    return characteristic_of(to_arithmetic<Rational, 4>(s3d_paper002.get().p, Rational(1)));
  });
  auto projx = std::make_shared<Lazy<Poly<Rational>>>([gx] {
    const auto& g = gx->get();
    return quartic_discriminant(g[4], g[3], g[2], g[1], g[0]);
  });
  row(grp, "total pipeline", true, Cost::very_slow, "to_arithmetic + ccd_projection, ExactPolicy", [grp](benchmark::State& st) {
    const Scene3D& s = s3d_paper002.get();
    timed(st, grp + "/total pipeline", [&] { return run3d_exact(s.p); }, [](const auto& r) { return summarise_ccd(r); });
  });
  row(grp, "1 g = det(λA - B)", false, Cost::slow, "to_arithmetic<Rational,4> + characteristic_of", [grp](benchmark::State& st) {
    const Scene3D& s = s3d_paper002.get();
    timed(st, grp + "/1 g = det(λA - B)", [&] { return characteristic_of(to_arithmetic<Rational, 4>(s.p, Rational(1))); },
          [](const auto&) { return json(); });
  });
  row(grp, "2 projection build", false, Cost::slow, "ExactPolicy::build of quartic_discriminant (FLINT, as the pipeline)", [grp, gx](benchmark::State& st) {
    const auto& g = gx->get();
    timed(st, grp + "/2 projection build", [&] { return ExactPolicy().build(g, [](const auto& G) { return quartic_discriminant(G[4], G[3], G[2], G[1], G[0]); }); },
          [](const Poly<Rational>& p) { return json{{"degree", p.degree()}}; });
  });
  row(grp, "3 roots of the projection", false, Cost::slow, "ExactPolicy::roots (real_roots on [0, 1] + refinement)",
      [grp, projx](benchmark::State& st) {
        const auto& p = projx->get();
        ExactPolicy pol;
        timed(st, grp + "/3 roots of the projection", [&] { return pol.roots(p, false); },
              [](const auto& r) { return json{{"roots", r.size()}}; });
      });
  // The rest of ccd_projection: at every interior root the touch rule
  // (negative_multiple_root) asks for signs of subresultant coefficients
  // s(j, i) there, and every cell is decided by the exact static test at its
  // sample. The plan (which s(j, i), which samples) is recorded once.
  struct Plan {
    std::vector<AlgebraicRoot> roots;  // interior roots
    std::vector<std::pair<int, int>> needed;
    std::vector<std::tuple<std::size_t, int, int>> calls;  // (root, j, i)
    std::map<std::pair<int, int>, Poly<Rational>> s;
    std::vector<Rational> samples;  // 0, the cell samples, 1
  };
  auto plan = std::make_shared<Lazy<Plan>>([gx, projx] {
    const auto& g = gx->get();
    ExactPolicy pol;
    Plan pl;
    for (auto& r : pol.roots(projx->get(), false))
      if (!pol.at_zero(r) && !pol.at_one(r)) pl.roots.push_back(r);
    for (std::size_t n = 0; n < pl.roots.size(); ++n)
      negative_multiple_root(0, [&](int j, int i) {
        auto key = std::make_pair(j, i);
        if (!pl.s.count(key)) { pl.s[key] = subresultant_evidence(g, j, i); pl.needed.push_back(key); }
        pl.calls.emplace_back(n, j, i);
        return pol.sign_at(pl.s[key], pl.roots[n]);
      });
    pl.samples.push_back(Rational(0));
    for (std::size_t i = 0; i <= pl.roots.size(); ++i)
      pl.samples.push_back(pol.sample_between(i ? &pl.roots[i - 1] : nullptr, i < pl.roots.size() ? &pl.roots[i] : nullptr));
    pl.samples.push_back(Rational(1));
    return pl;
  });
  row(grp, "4 s(j,i) build (those the touch rule asks for)", false, Cost::slow,
      "ExactPolicy::build of subresultant_evidence(g, j, i) (FLINT, as the pipeline), for each distinct (j, i) asked at the roots", [grp, gx, plan](benchmark::State& st) {
        const auto& g = gx->get();
        const Plan& pl = plan->get();
        timed(st, grp + "/4 s(j,i) build (those the touch rule asks for)", [&] {
          std::vector<Poly<Rational>> out;
          for (auto [j, i] : pl.needed) out.push_back(ExactPolicy().build(g, [j, i](const auto& G) { return subresultant_evidence(G, j, i); }));
          return out;
        }, [&](const auto&) {
          json j = json::array();
          for (auto [a, b] : pl.needed) j.push_back(subresultant_evidence_name(a, b) + " of degree " + std::to_string(pl.s.at({a, b}).degree()));
          return json{{"built", j}, {"interior_roots", pl.roots.size()}};
        });
      });
  row(grp, "5 signs of s(j,i) at the roots", false, Cost::slow, "ExactPolicy::sign_at (CGAL sign at an algebraic number)",
      [grp, plan](benchmark::State& st) {
        const Plan& pl = plan->get();
        ExactPolicy pol;
        timed(st, grp + "/5 signs of s(j,i) at the roots", [&] {
          int n = 0;
          for (auto [r, j, i] : pl.calls) n += int(pol.sign_at(pl.s.at({j, i}), pl.roots[r]));
          return n;
        }, [&](int) { return json{{"sign_evaluations", pl.calls.size()}}; });
      });
  row(grp, "6 static tests at 0, the cell samples and 1", false, Cost::slow, "quartic_status_at (exact Sturm count)",
      [grp, gx, plan](benchmark::State& st) {
        const auto& g = gx->get();
        const Plan& pl = plan->get();
        timed(st, grp + "/6 static tests at 0, the cell samples and 1", [&] {
          int n = 0;
          for (const auto& t : pl.samples) n += int(quartic_status_at(g, t));
          return n;
        }, [&](int) { return json{{"static_tests", pl.samples.size()}}; });
      });
}

// ---------------------------------------------------------------------------
// Rows through eccd::solve_scene: a table of (label, SolveOptions).
//
// >>> ISSUE 6 part 2: the certified interval mode (`--arith certified`,
// >>> certified/certified_policy.hpp and api/solve.cpp) is measured HERE, through
// >>> solve_scene, like `eccd solve` runs it (it may escalate to exact; the JSON
// >>> says so and the row's result shows it). More of its rows go into
// >>> kSolveSceneRows below; a target for it goes into TARGETS in
// >>> bench/performance_report.py.

struct SolveRow {
  const char* group;
  const char* label;
  int dim;  // 2: the 2D degree-6 scene; 3: paper 002's example
  SolveOptions (*options)();
};

SolveOptions opts(const char* arith, int variant, const char* method = "bezier") {
  SolveOptions o;
  o.arith = parse_arithmetic(arith);
  o.variant = Variant(variant);
  std::tie(o.method, o.grid) = parse_method(method);
  return o;
}

const SolveRow kSolveSceneRows[] = {
    {"solve_scene-2d-deg6", "double v3", 2, [] { return opts("double", 3); }},
    {"solve_scene-2d-deg6", "mpfr:128 v3", 2, [] { return opts("mpfr:128", 3); }},
    {"solve_scene-2d-deg6", "exact v3", 2, [] { return opts("exact", 3); }},
    {"solve_scene-2d-deg6", "exact v0", 2, [] { return opts("exact", 0); }},
    {"solve_scene-2d-deg6", "certified v3", 2, [] { return opts("certified", 3); }},
    {"solve_scene-2d-deg6", "certified v0", 2, [] { return opts("certified", 0); }},
    {"solve_scene-paper002", "double bezier", 3, [] { return opts("double", 0); }},
    {"solve_scene-paper002", "exact", 3, [] { return opts("exact", 0); }},
    {"solve_scene-paper002", "certified", 3, [] { return opts("certified", 0); }},
    // further certified rows go here (see above)
};

void register_solve_scene() {
  group("solve_scene-2d-deg6", "eccd::solve_scene on the 2D degree-6 scene (JSON included)",
        "What `eccd solve` computes, through solve(scene, SolveOptions) then solution_to_json: the pipeline plus preparation of the "
        "scene (prepare_pair) and the JSON report; rows of the certified interval mode (`--arith certified`) included.",
        "the first row of the table (double)");
  group("solve_scene-paper002", "eccd::solve_scene on paper 002's example (JSON included)",
        "As above, 3D.", "the first row of the table (double Bézier)");
  std::map<std::string, bool> seen;
  for (const SolveRow& r : kSolveSceneRows) {
    std::string grp = r.group, label = r.label;
    bool baseline = !seen[grp];
    seen[grp] = true;
    SolveOptions o = r.options();
    int dim = r.dim;
    row(grp, label, baseline, label.find("exact") != std::string::npos && dim == 3 ? Cost::very_slow : Cost::slow,
        "solve_scene, arith " + o.arith.name() + (dim == 2 ? ", variant " + std::to_string(int(o.variant)) : ", method " + o.method_name()),
        [grp, label, o, dim](benchmark::State& st) {
          const Scene& sc = dim == 2 ? s2d_deg6.get().scene : s3d_paper002.get().scene;
          timed(st, grp + "/" + label, [&] { return solution_to_json(solve(sc, o)); }, [](const json& j) {
            json r{{"collides", j["collides"]}, {"time_ms_inside", j["time_ms"]},
                   {"contacts", j["contacts"].is_array() ? j["contacts"].size() : 0},
                   {"intervals", j["intervals"].is_array() ? j["intervals"].size() : 0}};
            for (const char* k : {"escalated", "decided_in", "escalation_reason", "certified"})
              if (j.contains(k)) r[k] = j[k];
            return r;
          });
        });
  }
}

// ---------------------------------------------------------------------------
// The plane check of 000 section 4 (issue 17): per pair-frame cost of
// eccd::plane_separates_on_frame (api/separate.hpp) on a 000 Table 1 pair
// (semi-axes 3, 3, 5, centres 8 apart, each rotating about its own axis by
// about 0.1 rad over the frame: quaternions (1, t/20, 0, 0) and (1, 0, t/20, 0),
// motion degree 2, h_a and h_b of degree 4), the kept plane being the exact
// plane of separate_at at t = 0. Baseline: the continuous test of the same
// pair-frame in double (eccd::solve, Bézier method), which a plane that
// separates saves (000 section 4).
void register_planes() {
  group("plane-check", "Plane check over one frame (000 section 4), per pair-frame",
        "eccd::plane_separates_on_frame(scene, plane, arith) for a kept plane on a 000 Table 1 pair-frame (semi-axes 3, 3, 5, "
        "centres 8 apart, rotations of about 0.1 rad per frame, motion degree 2): h_a, h_b built from M(t) and adj(Q), Bernstein "
        "signs (double: with error bounds; exact: rationals, Sturm only if a coefficient is not positive). The plane is "
        "separate_at(scene, 0, exact). Baseline: the continuous test of the same pair-frame in double (eccd::solve, Bézier).",
        "000 Table 1: separating planes save the characteristic-equation solve in most frames (µs per frame with and without "
        "planes)");
  static Lazy<std::pair<Scene, SeparatingPlane>> pair([] {
    Scene s = scene_from_text(R"({"format": "ellipse-ccd-scene/1", "name": "table1-pair", "dim": 3,
      "a": {"shape": {"semi_axes": ["3", "3", "5"]}, "motion": {"type": "euler", "e": ["1", ["0", "1/20"], "0", "0"], "translation": ["-4", "0", "0"]}},
      "b": {"shape": {"semi_axes": ["3", "3", "5"]}, "motion": {"type": "euler", "e": ["1", "0", ["0", "1/20"], "0"], "translation": ["4", "0", "0"]}}})",
                              "table1-pair");
    SolveOptions ex;
    Separation sep = separate_at(s, 0, ex);
    if (!sep.plane) throw std::runtime_error("bench plane-check: the pair is not separate at t = 0");
    // The measured case is a kept plane that holds over the frame (the check's whole work, no early refutation).
    if (plane_separates_on_frame(s, *sep.plane, ex) != PlaneCheck::separates)
      throw std::runtime_error("bench plane-check: the plane of t = 0 does not separate over the frame");
    return std::make_pair(s, *sep.plane);
  });
  auto opts = [](const char* a) { SolveOptions o; o.arith = parse_arithmetic(a); return o; };
  row("plane-check", "continuous test, double (baseline)", true, Cost::slow, "eccd::solve(scene, double): the Bézier method",
      [opts](benchmark::State& st) {
        const SolveOptions o = opts("double");
        timed(st, "plane-check/continuous test, double (baseline)", [&] { return solve(pair.get().first, o).answer.collides; },
              [](bool c) { return json{{"collides", c}}; });
      });
  for (const char* a : {"double", "exact", "certified", "mpfr:128"}) {
    const std::string label = std::string("plane check, ") + a;
    row("plane-check", label, false, Cost::slow, std::string("eccd::plane_separates_on_frame, arith ") + a,
        [opts, a, label](benchmark::State& st) {
          const SolveOptions o = opts(a);
          timed(st, "plane-check/" + label, [&] { return int(plane_separates_on_frame(pair.get().first, pair.get().second, o)); },
                [](int r) { return json{{"result", to_string(PlaneCheck(r))}}; });
        });
  }
  row("plane-check", "new plane, separate_at exact", false, Cost::slow, "eccd::separate_at(scene, 1, exact): a new proved plane",
      [opts](benchmark::State& st) {
        const SolveOptions o = opts("exact");
        timed(st, "plane-check/new plane, separate_at exact", [&] { return separate_at(pair.get().first, 1, o).status; },
              [](const std::string& s) { return json{{"status", s}}; });
      });
}

// ---------------------------------------------------------------------------
// Issue 21: one 3D continuous query of two ellipsoids translating linearly
// (motion degree 1; B also turned by a fixed rotation), colliding on about
// [0.32, 0.67], through eccd::solve in double (the default 3D method, the
// Bézier zero-set analysis, with everything `eccd solve` does per call:
// rounding the scene, g_k, F(u, t), the contact points). Baseline: the same
// call; the row "pipeline only" times characteristic_bernstein + ccd_bezier
// from the prepared pair (what the call adds around it is the difference).
void register_translation3d() {
  const char* grp = "ccd3d-deg1-translation";
  group(grp, "3D CCD, both ellipsoids translating linearly (motion degree 1), colliding, one query",
        "eccd::solve(scene, double) on two ellipsoids (semi-axes 1, 2, 3 and 2, 1, 1, B turned by a fixed rotation) "
        "translating towards each other along x, colliding on about [0.32, 0.67]: the default 3D method (001 section 4, "
        "the Bézier zero-set analysis). Baseline: the same call. Rows certified: the same call with --arith certified, and the certified ladder (run_certified) from the prepared pair.",
        "issue 21: double at most 50 µs, certified at most 150 µs; FCL's continuous test (1000 samples) 0.39 ms");
  static Lazy<Scene3D> sc([] {
    Scene s = scene_from_text(R"({"format": "ellipse-ccd-scene/1", "name": "deg1-translating-pair", "dim": 3,
      "a": {"shape": {"semi_axes": ["1", "2", "3"]}, "motion": {"type": "euler", "e": ["1", "0", "0", "0"], "translation": [["-4", "8"], "0", "0"]}},
      "b": {"shape": {"semi_axes": ["2", "1", "1"]}, "motion": {"type": "euler", "e": ["1", "1/3", "0", "1/5"], "translation": [["4", "-8"], ["1/2", "0"], "0"]}}})",
                              "deg1-translating-pair");
    Scene3D out{"deg1-translating-pair", s, prepare_pair<4>(s), json::object()};
    out.info = {{"dim", 3}, {"file", "(inline, bench/eccd_bench.cpp)"}, {"what", "two ellipsoids translating linearly, colliding"}};
    return out;
  });
  row(grp, "double solve (API)", true, Cost::slow, "eccd::solve(scene, double): the Bézier method, contact points included",
      [grp](benchmark::State& st) {
        note_scene(sc.get(), grp);
        SolveOptions o;
        o.arith = parse_arithmetic("double");
        timed(st, std::string(grp) + "/double solve (API)", [&] { return solve(sc.get().scene, o).answer.collides; },
              [](bool c) { return json{{"collides", c}}; });
      });
  // Issue 21: the certified query, target 150 µs: the same call with --arith certified, and the ladder alone.
  row(grp, "certified solve (API)", false, Cost::slow, "eccd::solve(scene, certified): the certified ladder (interval Bézier proof first)",
      [grp](benchmark::State& st) {
        SolveOptions o;
        o.arith = Arithmetic::certified();
        timed(st, std::string(grp) + "/certified solve (API)", [&] { return solve(sc.get().scene, o); },
              [](const Solution& r) { return summarise_solution(r); });
      });
  row(grp, "certified ladder only (run_certified)", false, Cost::slow, "run_certified<4> from the prepared pair",
      [grp](benchmark::State& st) {
        const std::vector<int> rungs = Arithmetic::certified().mpfi_rungs;
        timed(st, std::string(grp) + "/certified ladder only (run_certified)",
              [&] { return run_certified<4>(sc.get().p, rungs, Variant::answer, false); },
              [](const Solution& r) { return summarise_solution(r); });
      });
  // Issue 21's anchor (FCL's continuous test of such a pair, 1000 samples, 0.39 ms) in the same run.
  row(grp, "FCL continuous, 1000 samples (fcl_ccd)", false, Cost::slow,
      "compare/fcl_engine fcl_ccd(scene, 1000): fcl::continuousCollide, CCDC_NAIVE, CCDM_TRANS (first contact only)",
      [grp](benchmark::State& st) {
        const std::string why = eccd_bench::fcl_bench_unavailable(), bad = why.empty() ? fcl_ccd_inexpressible(sc.get().scene) : "";
        if (!why.empty() || !bad.empty()) { st.SkipWithError((why + bad).c_str()); return; }
        timed(st, std::string(grp) + "/FCL continuous, 1000 samples (fcl_ccd)", [&] { return fcl_ccd(sc.get().scene, 1000); },
              [](const Answer& a) {
                json j{{"collides", a.collides}};
                if (a.first_contact) j["first_contact"] = short_instant(*a.first_contact);
                return j;
              });
      });
  row(grp, "double pipeline only", false, Cost::slow, "characteristic_bernstein<double,4> + ccd_bezier from the prepared pair",
      [grp](benchmark::State& st) {
        timed(st, std::string(grp) + "/double pipeline only",
              [&] { return run3d_floating<double>(sc.get().p, "bezier", Basis::bernstein, 53, 1.0, false); },
              [](const auto& r) { return summarise_ccd(r); });
      });
}

// ---------------------------------------------------------------------------
// The product path (issue 30): what a user waits for, eccd::solve(scene,
// options) from the read scene to the typed answer (preparation, the
// pipeline, contact points; no JSON), on the 2D degree-6 scene (Variant 3,
// all external contacts) and paper 002's example. Each floating row names its
// face (as published: the paper's algorithm in plain double; guarded: the
// running error bound, the default of `eccd solve`) and its input mode
// (rounded: the scene's numbers rounded to double, the default; prepared: the
// exactly prepared pair rounded). Baseline: double as published, rounded
// input, so that the guarded row's ratio is the guard's cost.
struct ProductRow {
  const char* label;
  const char* arith;
  Guard guard;
  InputMode input;
  int variant;
};

const ProductRow kProductRows[] = {
    {"double as published, rounded input", "double", Guard::none, InputMode::rounded, 3},
    {"double guarded, rounded input", "double", Guard::bound, InputMode::rounded, 3},
    {"double as published, prepared input", "double", Guard::none, InputMode::prepared, 3},
    {"double guarded, prepared input", "double", Guard::bound, InputMode::prepared, 3},
    {"certified", "certified", Guard::bound, InputMode::prepared, 3},
    {"exact", "exact", Guard::bound, InputMode::prepared, 3},
    {"exact v0 (full answer)", "exact", Guard::bound, InputMode::prepared, 0},
};

void register_product() {
  group("product-2d-deg6-v3", "eccd::solve on the 2D degree-6 scene (Δ of degree 144), Variant 3, as a user runs it",
        "eccd::solve(scene, options) from the read scene: preparation, CD-DISC (Bernstein form), the answer; each floating "
        "row names its face and input mode. Baseline: double as published, rounded input; the guarded row's ratio is the "
        "guard's cost.",
        "issue 21: double at most 50 µs; issue 30: guarded / as published at most ×1.5 (median)");
  group("product-paper002", "eccd::solve on paper 002's example (degree 4, 3D), as a user runs it",
        "eccd::solve(scene, options) from the read scene: preparation, the Bézier method (001 section 4) or the exact "
        "projection, contact points and normals; each floating row names its face and input mode. Baseline: double as "
        "published, rounded input.",
        "issue 21: double at most 0.3 ms, exact 25 ms; issue 30: guarded / as published at most ×1.5 (median)");
  for (int dim : {2, 3}) {
    const std::string grp = dim == 2 ? "product-2d-deg6-v3" : "product-paper002";
    bool first = true;
    for (const ProductRow& r : kProductRows) {
      if (dim == 3 && r.variant == 0) continue;  // 3D: one answer
      SolveOptions o;
      o.arith = parse_arithmetic(r.arith);
      o.guard = r.guard;
      o.input = r.input;
      o.variant = dim == 2 ? Variant(r.variant) : Variant::answer;
      std::string label = r.label;
      const bool floating = o.arith.floating();
      row(grp, label, first, std::string(r.arith) == "exact" && dim == 3 ? Cost::very_slow : Cost::slow,
          "eccd::solve(scene, arith " + o.arith.name() + (floating ? std::string(", guard ") + to_string(o.guard) + ", input " + to_string(o.input) : std::string()) +
              (dim == 2 ? ", variant " + std::to_string(int(o.variant)) : std::string(", method bezier")) + ")",
          [grp, label, o, dim](benchmark::State& st) {
            const Scene& sc = dim == 2 ? s2d_deg6.get().scene : s3d_paper002.get().scene;
            if (dim == 2) note_scene(s2d_deg6.get());
            else note_scene(s3d_paper002.get(), grp);
            timed(st, grp + "/" + label, [&] { return solve(sc, o); }, [](const Solution& s) { return summarise_solution(s); });
          });
      first = false;
    }
  }
}

// ---------------------------------------------------------------------------
// Reproduction (c) of issue 17 (paper 001 section 5 in spirit): the boxers,
// two figures of 24 ellipsoids (make_repro.py boxers), 576 pairs per frame,
// through eccd::animate (api/animate.hpp: bounding spheres, the kept plane,
// the continuous test), one thread. The input is bench/data/boxers-10.anim.json
// (`python3 cases/animations/make_repro.py boxers --frames 10`): keys 0..10,
// so frames 0..9, the same as the first ten frames of the report's 1000-frame
// animation (a key's pose depends on its index only; the arms' period is 20
// keys, the legs' 40). One iteration animates all ten frames; the report
// divides by "frames" in the result. Baseline: double. CPU time of the whole
// process (animate's stages 2-3 run on a worker thread, even with threads 1).
void register_animation() {
  const char* rel = "bench/data/boxers-10.anim.json";
  group("animate-boxers", "Animation of the boxers (001 section 5 in spirit), 576 pairs per frame, frames 0-9",
        "eccd::animate(animation, arith, threads 1) on bench/data/boxers-10.anim.json (make_repro.py boxers --frames 10: "
        "two figures of 24 ellipsoids, pairs between the groups, frames 0 to 9 of the report's animation): per frame "
        "the bounding spheres of the swept volumes, the separating plane kept from the previous frame, then the "
        "continuous test of the surviving pairs (first contact). One iteration is the ten frames; the per-frame cost is "
        "the median divided by 10 (CPU time of the process: the pair-frames run on a worker thread). Baseline: double. "
        "The row without planes shows what the kept planes save.",
        "001 section 5: 3.4 ms per frame (1000 frames, 576 pairs, 3 GHz Pentium IV, double)");
  static Lazy<Animation> anim([rel] { return read_animation(src(rel)); });
  struct R {
    const char* label;
    const char* arith;
    bool planes, baseline;
    Cost cost;
  };
  for (const R& r : {R{"double, 10 frames (baseline)", "double", true, true, Cost::slow},
                     R{"double without planes, 10 frames", "double", false, false, Cost::slow},
                     R{"certified, 10 frames", "certified", true, false, Cost::heavy}}) {
    const std::string label = r.label, key = "animate-boxers/" + label;
    AnimateOptions o;
    o.solve.arith = parse_arithmetic(r.arith);
    o.threads = 1;
    o.planes = r.planes;
    row("animate-boxers", label, r.baseline, r.cost,
        std::string("eccd::animate, arith ") + r.arith + (r.planes ? "" : ", planes off") + ", threads 1, " + rel,
        [key, o](benchmark::State& st) {
          timed(st, key, [&] { return animate(anim.get(), o); }, [](const AnimationResult& a) {
            return json{{"frames", a.per_frame.size()},
                        {"pairs_per_frame", a.pairs_per_frame},
                        {"bounding_volumes", a.bounding_volumes},
                        {"separating_plane", a.separating_plane},
                        {"continuous_test", a.continuous_test},
                        {"events", a.events.size()},
                        {"undecided", a.undecided.size()}};
          });
        },
        true);  // process CPU time: animate runs its pair-frames on a worker std::thread even with threads 1
  }
}

// ---------------------------------------------------------------------------
// Issue 21: side by side with FCL (Debian libfcl-dev 0.7) in the same process.
//
// (1) fcl-static3d: the static test per pair on the 1024 random pairs of the
// static3d group: eccd::static_status from two poses in double (the baseline)
// against fcl::collide on the same ellipsoids and poses, built once
// (bench/fcl_side.hpp: FCL's default request, GJK solver libccd, default
// tolerance, as compare/fcl_engine.cpp calls it; and FCL's own GJK,
// GST_INDEP). The result column counts, once after the timing, the pairs where
// each answer differs from eccd's certified static test (exact where double
// cannot decide).
// (2) fcl-table2-main / fcl-table2-graze: per frame of paper 000's Table 2
// set-up (a unit sphere orbiting an ellipsoid 4.5, 4, 2 at radius 5.49, and
// the grazing orbit 5.4999999: 1e-7 deep), frames 0 to 39 of
// scripts/run-animation-report.sh's orbits (bench/data/table2-*-40.anim.json,
// `make_repro.py table2 --frames 40 --radius R`): eccd::animate in double (the
// baseline) and certified (first contact, planes kept, one thread), eccd::solve
// on each pair-frame's scene in double without the plane stage, and FCL on the
// same pair-frame scenes: fcl::collide at t = k/N, k = 0..N (N = 1, 10; the
// poses computed once by compare/fcl_engine's fcl_pose_at, not timed: only
// FCL's own work is timed) and FCL's naive continuous collision with 1000
// samples (compare/fcl_engine's fcl_ccd, pose included). One iteration does
// all 40 frames; the report divides by "frames". After the timing each row's
// per-frame answer (collides in the frame or not) is compared once with the
// certified animation's: frames_in_collision, misclassified (missed, false
// collisions).

// undecided (eccd's floating runs): frames with an undecided pair-frame, which say "cannot tell" rather than
// answer; they are counted apart (undecided_frames), not as misclassified.
json disagreements_with_certified(const std::vector<bool>& collides, const std::vector<bool>& reference,
                                  const std::vector<bool>& undecided = {}) {
  int missed = 0, false_hits = 0, hits = 0, open = 0;
  for (std::size_t k = 0; k < collides.size(); ++k) {
    hits += collides[k];
    if (!collides[k] && k < undecided.size() && undecided[k]) { ++open; continue; }
    if (reference[k] && !collides[k]) ++missed;
    if (!reference[k] && collides[k]) ++false_hits;
  }
  json j{{"frames", collides.size()}, {"frames_in_collision", hits}, {"misclassified", missed + false_hits},
         {"missed", missed}, {"false_collisions", false_hits}};
  if (!undecided.empty()) j["undecided_frames"] = open;
  return j;
}

eccd_bench::FclBody fcl_body_of(const Ellipsoid& e) {
  eccd_bench::FclBody b;
  b.radii = e.semi_axes;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) b.rotation[i][j] = e.pose[i][j];
    b.centre[i] = e.pose[i][3];
  }
  return b;
}
eccd_bench::FclBody fcl_body_of(const FclPose& p) { return {p.radii, p.rotation, p.centre}; }

void register_fcl_static() {
  const char* grp = "fcl-static3d";
  group(grp, "Side by side with FCL: the static 3D test per pair",
        "The 1024 random pairs of the static3d group, one pair per iteration: eccd::static_status(a, b) from the semi-axes "
        "and poses in double (the baseline, the same call as the static3d target row) against fcl::collide on the same "
        "ellipsoids and poses (fcl::Ellipsoidd and Transform3d built once, not timed; FCL's default CollisionRequestd: "
        "GJK solver libccd, gjk_tolerance 1e-6, as compare/fcl_engine.cpp calls it; and the same request with FCL's own "
        "GJK, GST_INDEP). Result: per row the pairs whose answer differs from eccd's certified static test.",
        "issue 21: eccd 144 ns against 549 ns for FCL's fastest ellipsoid test (measured side by side before issue 21)");
  // The certified answers, once: collides = not separate.
  static Lazy<std::vector<bool>> reference([] {
    const Static3D& s = static3d.get();
    std::vector<bool> r;
    for (int k = 0; k < kBatch; ++k) r.push_back(static_status(s.pa[k], s.pb[k], Arithmetic::certified()) != Status::separate);
    return r;
  });
  auto pair_counts = [](const std::vector<bool>& c, const std::vector<bool>& uncertain = {}) {
    json j = disagreements_with_certified(c, reference.get(), uncertain);
    json out{{"pairs", j["frames"]}, {"collide", j["frames_in_collision"]}, {"differ_from_certified", j["misclassified"]}};
    return out;
  };
  row(grp, "eccd double static_status (API, two poses)", true, Cost::fast, "eccd::static_status(a, b) in double",
      [grp, pair_counts](benchmark::State& st) {
        const Static3D& s = static3d.get();
        int i = 0;
        auto f = [&] { i = (i + 1) & (kBatch - 1); return static_status(s.pa[i], s.pb[i]); };
        timed(st, std::string(grp) + "/eccd double static_status (API, two poses)", f, [&](Status) {
          std::vector<bool> c, open;
          int uncertain = 0;
          for (int k = 0; k < kBatch; ++k) {
            Status x = static_status(s.pa[k], s.pb[k]);
            uncertain += x == Status::uncertain;
            c.push_back(x != Status::separate && x != Status::uncertain);
            open.push_back(x == Status::uncertain);
          }
          json j = pair_counts(c, open);
          j["uncertain"] = uncertain;  // "cannot tell": not counted as differing from the certified test
          return j;
        });
      });
  const std::string why = eccd_bench::fcl_bench_unavailable();
  for (bool indep : {false, true}) {
    const std::string label = indep ? "FCL collide, GJK indep (GST_INDEP)" : "FCL collide, GJK libccd (default request)";
    row(grp, label, false, Cost::fast,
        std::string("fcl::collide(Ellipsoidd, Transform3d, ...), ") + (indep ? "GST_INDEP" : "default request (GST_LIBCCD)"),
        [grp, label, indep, why, pair_counts](benchmark::State& st) {
          if (!why.empty()) { st.SkipWithError(why.c_str()); return; }
          const Static3D& s = static3d.get();
          std::vector<eccd_bench::FclBody> a, b;
          for (int k = 0; k < kBatch; ++k) { a.push_back(fcl_body_of(s.pa[k])); b.push_back(fcl_body_of(s.pb[k])); }
          auto pairs = eccd_bench::prepare_fcl_pairs(a, b, indep);
          int i = 0;
          auto f = [&] { i = (i + 1) & (kBatch - 1); return pairs->collide(i); };
          timed(st, std::string(grp) + "/" + label, f, [&](bool) {
            std::vector<bool> c;
            for (int k = 0; k < kBatch; ++k) c.push_back(pairs->collide(k));
            return pair_counts(c);
          });
        });
  }
}

// Per frame: does the certified animation see a collision in frame k?
std::vector<bool> frames_colliding(const AnimationResult& a) {
  std::vector<bool> c(a.frames, false);
  for (const auto& e : a.events) c.at(e.frame) = true;
  return c;
}

void register_fcl_table2() {
  struct Orbit { const char* id; const char* rel; const char* what; };
  for (Orbit orbit : {Orbit{"fcl-table2-main", "bench/data/table2-main-40.anim.json", "orbit radius 5.49 (collides near the 4.5 axis)"},
                      Orbit{"fcl-table2-graze", "bench/data/table2-graze-40.anim.json",
                            "orbit radius 5.4999999 (grazing: 1e-7 deep at the end of the 4.5 axis)"}}) {
    const std::string grp = orbit.id, rel = orbit.rel;
    group(grp, std::string("Side by side with FCL: paper 000 Table 2 per frame, ") + orbit.what + ", frames 0-39",
          "A unit sphere orbiting a static ellipsoid 4.5, 4, 2 (0.01 rad per frame, the centre on the chord between keys), "
          "frames 0 to 39 of scripts/run-animation-report.sh's orbit (" + rel + ", make_repro.py table2 --frames 40). "
          "eccd::animate (first contact, kept planes, one thread; process CPU time) in double (baseline) and certified; "
          "eccd::solve in double on each pair-frame scene (no planes); FCL on the same pair-frame scenes: fcl::collide at "
          "t = k/N, k = 0..N (poses from compare/fcl_engine's fcl_pose_at, computed once, not timed) and fcl_ccd with 1000 "
          "samples (FCL's naive continuous collision, CCDM_TRANS). One iteration is the 40 frames. Result: frames in "
          "collision and frames misclassified against the certified animation (counted once, after the timing).",
          "000 Table 2: EECD 2.12 µs per frame, GJK on polyhedra 15.2 to 54.3 µs per frame (Pentium 4); issue 21: FCL's "
          "continuous test of a translating pair (1000 samples) 0.39 ms");
    struct Data {
      Animation anim;
      std::vector<Scene> frames;  // the pair-frame scenes (sphere, ellipsoid)
      std::vector<bool> reference;
    };
    auto data = std::make_shared<Lazy<Data>>([rel] {
      Data d{read_animation(src(rel)), {}, {}};
      for (std::size_t k = 0; k < d.anim.times.size() - 1; ++k) d.frames.push_back(pair_frame_scene(d.anim, 0, 1, k));
      AnimateOptions o;
      o.solve.arith = Arithmetic::certified();
      o.threads = 1;
      d.reference = frames_colliding(animate(d.anim, o));
      return d;
    });
    for (const char* arith : {"double", "certified"}) {
      const bool dbl = std::string(arith) == "double";
      const std::string label = std::string("eccd ") + arith + ", animate" + (dbl ? " (baseline)" : "");
      AnimateOptions o;
      o.solve.arith = parse_arithmetic(arith);
      o.threads = 1;
      row(grp, label, dbl, dbl ? Cost::slow : Cost::very_slow, std::string("eccd::animate, arith ") + arith + ", threads 1, " + rel,
          [grp, label, o, data](benchmark::State& st) {
            const Data& d = data->get();
            timed(st, grp + "/" + label, [&] { return animate(d.anim, o); }, [&](const AnimationResult& a) {
              std::vector<bool> open(a.frames, false);
              for (const auto& u : a.undecided) open.at(u.frame) = true;
              json j = disagreements_with_certified(frames_colliding(a), d.reference, open);
              j["undecided"] = a.undecided.size();  // pair-frames
              j["separating_plane"] = a.separating_plane;
              return j;
            });
          },
          true);
    }
    row(grp, "eccd double, solve per frame (no planes)", false, Cost::slow,
        "eccd::solve(pair-frame scene, double, first contact) on each frame",
        [grp, data](benchmark::State& st) {
          const Data& d = data->get();
          SolveOptions o;
          o.arith = Arithmetic::double_precision();
          o.first_contact = true;
          auto f = [&] {
            std::vector<bool> c;
            for (const Scene& s : d.frames) c.push_back(solve(s, o).answer.collides);
            return c;
          };
          timed(st, grp + "/eccd double, solve per frame (no planes)", f,
                [&](const std::vector<bool>& c) { return disagreements_with_certified(c, d.reference); });
        });
    const std::string why = eccd_bench::fcl_bench_unavailable();
    for (int n : {1, 10}) {
      const std::string label = "FCL collide at t = k/" + std::to_string(n) + " (sample:" + std::to_string(n) + ")";
      row(grp, label, false, Cost::slow, "fcl::collide at " + std::to_string(n + 1) + " poses per frame, default request",
          [grp, label, n, data, why](benchmark::State& st) {
            if (!why.empty()) { st.SkipWithError(why.c_str()); return; }
            const Data& d = data->get();
            std::vector<eccd_bench::FclBody> a, b;
            for (const Scene& s : d.frames)
              for (int k = 0; k <= n; ++k) {
                FclScenePose p = fcl_pose_at(s, double(k) / n);
                a.push_back(fcl_body_of(p.a));
                b.push_back(fcl_body_of(p.b));
              }
            auto pairs = eccd_bench::prepare_fcl_pairs(a, b, false);
            auto f = [&] {
              std::vector<bool> c(d.frames.size(), false);
              std::size_t i = 0;
              for (std::size_t fr = 0; fr < d.frames.size(); ++fr)
                for (int k = 0; k <= n; ++k, ++i)
                  if (pairs->collide(i)) c[fr] = true;  // every sample, as fcl_sample does
              return c;
            };
            timed(st, grp + "/" + label, f, [&](const std::vector<bool>& c) { return disagreements_with_certified(c, d.reference); });
          });
    }
    row(grp, "FCL continuous, 1000 samples (fcl_ccd)", false, Cost::slow,
        "compare/fcl_engine fcl_ccd(scene, 1000): fcl::continuousCollide, CCDC_NAIVE, CCDM_TRANS",
        [grp, data, why](benchmark::State& st) {
          if (!why.empty()) { st.SkipWithError(why.c_str()); return; }
          const Data& d = data->get();
          for (const Scene& s : d.frames) {
            std::string bad = fcl_ccd_inexpressible(s);
            if (!bad.empty()) { st.SkipWithError(("fcl_ccd cannot express the frame: " + bad).c_str()); return; }
          }
          auto f = [&] {
            std::vector<bool> c;
            for (const Scene& s : d.frames) c.push_back(fcl_ccd(s, 1000).collides);
            return c;
          };
          timed(st, grp + "/FCL continuous, 1000 samples (fcl_ccd)", f,
                [&](const std::vector<bool>& c) { return disagreements_with_certified(c, d.reference); });
        });
  }
}

// ---------------------------------------------------------------------------
// The certified mode's own target (issue 6): its median cost against the
// double pipeline over the degree-4 generated sets of the corpus. One group per
// set; per scene a row `SCENE double` (what `eccd solve` runs by default: 2D
// double Bernstein CD-DISC, 3D double Bézier) and a row `SCENE certified`
// (`--arith certified`, through solve_scene). The report takes the per-scene
// ratio certified / double and its median over the set
// (bench/performance_report.py, SET_TARGETS).

void register_certified_sets() {
  struct Set {
    const char* id;
    const char* title;
    std::vector<const char*> dirs;
    const char* prefix;
  };
  const Set sets[] = {
      {"certified-set-2d-deg4", "certified mode against double on the degree-4 2D generated set", {"cases/generated/2d"}, "2d-deg4-"},
      {"certified-set-3d-deg4", "certified mode against double on the degree-4 3D generated set",
       {"cases/generated/3d-euler", "cases/generated/3d-affine"}, "3d-deg4-"},
  };
  for (const Set& set : sets) {
    std::vector<std::string> files;
    for (const char* d : set.dirs)
      for (const auto& e : std::filesystem::directory_iterator(src(d)))
        if (e.path().extension() == ".json" && e.path().filename().string().rfind(set.prefix, 0) == 0)
          files.push_back(std::string(d) + "/" + e.path().filename().string());
    std::sort(files.begin(), files.end());
    group(set.id, set.title,
          "Per scene of the set (every scene of `cases/` whose name starts with the set's prefix), `eccd::solve_scene` "
          "with --arith double (2D: CD-DISC with Δ in Bernstein form; 3D: the Bézier method) and with --arith certified "
          "(intervals of doubles, escalating to MPFI and then exact where a sign is uncertain). The report gives each "
          "scene's ratio certified / double and their median.",
          "issue 6 target: median cost of the certified mode at most 3x the double pipeline");
    bool first = true;
    for (const std::string& rel : files) {
      std::string name = std::filesystem::path(rel).stem().string();
      auto sc = std::make_shared<Lazy<Scene>>([rel] { return read_scene_file(src(rel)); });
      for (const char* arith : {"double", "certified"}) {
        SolveOptions o = opts(arith, 0);
        bool is_double = std::string(arith) == "double";
        row(set.id, name + " " + arith, first && is_double, is_double ? Cost::slow : Cost::very_slow,
            std::string("solve_scene, arith ") + arith + ", " + rel,
            [key = std::string(set.id) + "/" + name + " " + arith, sc, o](benchmark::State& st) {
              timed(st, key, [&] { return solution_to_json(solve(sc->get(), o)); }, [](const json& j) {
                json r{{"collides", j["collides"]}, {"time_ms_inside", j["time_ms"]},
                       {"contacts", j["contacts"].is_array() ? j["contacts"].size() : 0},
                       {"intervals", j["intervals"].is_array() ? j["intervals"].size() : 0}};
                for (const char* k : {"escalated", "decided_in", "escalation_reason"})
                  if (j.contains(k)) r[k] = j[k];
                return r;
              });
            });
        first = false;
      }
    }
  }
}

// ---------------------------------------------------------------------------
// The certified static test (issue 18 point 5, api/static_test.hpp): the
// filtered predicate (double with its error bound, exact only where that is
// uncertain) next to the double test, on the same batches of random pairs as
// static2d / static3d. Baseline: the double test through the API.

void register_static_certified() {
  for (int dim : {2, 3}) {
    std::string grp = "static-certified-" + std::to_string(dim) + "d";
    group(grp, std::string("certified static test from two poses, ") + (dim == 2 ? "2D" : "3D") + " (per pair)",
          "The batch of 1024 random pairs of the static" + std::to_string(dim) + "d group, one pair per iteration: "
          "eccd::static_status(a, b) from the semi-axes and poses in double (Bounded<double>, uncertain where the error "
          "bound cannot decide; the baseline) and certified (the same double test, then the exact test — world quadrics "
          "and exact signs — only where the double one is uncertain). The result column counts the statuses and how many "
          "pairs went to the exact test.",
          "issue 18: the certified static test costs at most 1.5x the double static test on random pairs");
    for (const char* arith : {"double", "certified"}) {
      std::string label = std::string(arith) + " static_status (API, two poses)";
      Arithmetic a = std::string(arith) == "double" ? Arithmetic::double_precision() : Arithmetic::certified();
      row(grp, label, std::string(arith) == "double", Cost::fast, std::string("eccd::static_status(a, b, ") + arith + ")",
          [grp, label, a, dim](benchmark::State& st) {
            auto status_of = [&](int k) {
              return dim == 2 ? static_status(static2d.get().pa[k], static2d.get().pb[k], a)
                              : static_status(static3d.get().pa[k], static3d.get().pb[k], a);
            };
            int i = 0;
            auto f = [&] { i = (i + 1) & (kBatch - 1); return status_of(i); };
            timed(st, grp + "/" + label, f, [&](Status) {
              std::vector<Status> v;
              int to_exact = 0;
              for (int k = 0; k < kBatch; ++k) {
                v.push_back(status_of(k));
                Status d = dim == 2 ? static_status(static2d.get().pa[k], static2d.get().pb[k])
                                    : static_status(static3d.get().pa[k], static3d.get().pb[k]);
                to_exact += d == Status::uncertain;
              }
              json j = status_counts(v);
              if (a.kind == Arithmetic::Certified) j["went_to_exact"] = to_exact;
              return j;
            });
          });
    }
  }
}

// ---------------------------------------------------------------------------
// The certified ladder's cost guarantee (issue 18 point 1,
// certified/ladder.hpp): certified against exact on the same scene, over a
// sample of short overlaps, near misses and grazes (the generator's families
// near-miss, overlap and graze at gap / depth 1e-3 ... 1e-12, 2D degrees 2, 4,
// 6 and 3D degrees 2, 4; the short-overlap cases of issue 18) and the corpus
// scenes where the MPFI rung used to cost more than exact. Per scene a row
// `SCENE exact` and a row `SCENE certified`, both through solve_scene; the
// report gives the ratio certified / exact per scene, its median, and the
// ratio to the guarantee's bound exact + 2 x (interval rung).

void register_certified_cost() {
  std::vector<std::pair<std::string, std::shared_ptr<Lazy<Scene>>>> scenes;
  auto file = [&](const std::string& rel) {
    scenes.push_back({std::filesystem::path(rel).stem().string(),
                      std::make_shared<Lazy<Scene>>([rel] { return read_scene_file(src(rel)); })});
  };
  auto generated = [&](int dim, int degree, const char* family, const char* motion, int e) {
    GeneratorSpec g;
    g.dim = dim;
    g.degree = degree;
    g.family = family;
    g.motion = motion;
    g.d_exponent = e;
    g.seed = 1800 + 100 * dim + 10 * degree + e;
    GeneratedScene gs = generate_scene(g);
    std::string text = gs.doc.dump();
    scenes.push_back({gs.name, std::make_shared<Lazy<Scene>>([text, name = gs.name] { return parse_scene(text, name); })});
  };
  for (const auto& e : std::filesystem::directory_iterator(src("cases/short-overlap")))
    if (e.path().extension() == ".json") file("cases/short-overlap/" + e.path().filename().string());
  // The corpus scenes where the MPFI rung was slower than exact before the budgets (reports/performance.md).
  for (const char* rel : {"cases/generated/2d/2d-deg4-colliding-kinematic-572211152701880.json",
                          "cases/generated/2d/2d-deg6-near-miss-1e-10-kinematic-3150273877033932.json",
                          "cases/generated/3d-affine/3d-deg2-colliding-affine-2295206434708192.json",
                          "cases/generated/3d-affine/3d-deg3-colliding-affine-8679402440173936.json"})
    if (std::filesystem::exists(src(rel))) file(rel);
  for (int e : {3, 6, 9, 12}) {
    for (int deg : {2, 4, 6}) generated(2, deg, "near-miss", "kinematic", e);
    for (int deg : {2, 4}) generated(3, deg, "near-miss", "euler", e);
    for (int dim : {2, 3}) generated(dim, 1, "overlap", "translation", e);
  }
  for (int dim : {2, 3}) generated(dim, 1, "graze", "translation", 0);
  std::sort(scenes.begin(), scenes.end());
  const char* grp = "certified-cost";
  group(grp, "the certified ladder against exact on short overlaps, near misses and grazes",
        "Per scene, `eccd::solve_scene` with --arith exact and with --arith certified (the ladder with its budgets: "
        "certified/ladder.hpp, \"Cost guarantee\"). The report gives each scene's ratio certified / exact, their median, "
        "and certified / (exact + 2 x the interval rung's time), the guarantee's bound (at most 1 up to a constant).",
        "issue 18: the certified ladder never costs much more than exact (guarantee: exact + 2 x the interval rung + c)");
  bool first = true;
  for (const auto& [name, sc] : scenes) {
    for (const char* arith : {"exact", "certified"}) {
      SolveOptions o = opts(arith, 0);
      std::string key = std::string(grp) + "/" + name + " " + arith;
      row(grp, name + " " + arith, first, Cost::very_slow, std::string("solve_scene, arith ") + arith,
          [key, sc = sc, o](benchmark::State& st) {
            timed(st, key, [&] { return solution_to_json(solve(sc->get(), o)); }, [](const json& j) {
              json r{{"collides", j["collides"]}, {"time_ms_inside", j["time_ms"]},
                     {"intervals", j["intervals"].is_array() ? j["intervals"].size() : 0}};
              if (j.contains("decided_in")) {
                r["decided_in"] = j["decided_in"];
                if (j.contains("escalation_reason")) r["escalation_reason"] = j["escalation_reason"];
                // The interval rung's time (the guarantee's I): its escalation, or the whole run when it decided.
                double interval_ms = j["time_ms"].get<double>();
                for (const auto& e : j["escalations"])
                  if (e["rung"] == "interval") interval_ms = e.value("spent_ms", 0.0);
                r["interval_ms"] = interval_ms;
              }
              return r;
            });
          });
      first = false;
    }
  }
}

// ---------------------------------------------------------------------------
// Reporter: medians per row (console shows only the medians) and the summary.

struct Median {
  double cpu_ns = 0, real_ns = 0;
  long long iterations = 0;
  long long repetitions = 0;
  std::vector<double> rep_cpu_ns;
  std::string error;
};
std::map<std::string, Median> g_medians;

class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  SummaryReporter() : ConsoleReporter(isatty(fileno(stdout)) ? OO_Defaults : OO_Tabular) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    std::vector<Run> shown;
    for (const auto& r : runs) {
      const std::string key = r.run_name.function_name;
      Median& m = g_medians[key];
      if (r.error_occurred) {
        m.error = r.error_message;
        shown.push_back(r);
        continue;
      }
      const double to_ns = 1e9 / benchmark::GetTimeUnitMultiplier(r.time_unit);
      if (r.run_type == Run::RT_Iteration) {
        m.rep_cpu_ns.push_back(r.GetAdjustedCPUTime() * to_ns);
        m.iterations += r.iterations;
      } else if (r.aggregate_name == "median") {
        m.cpu_ns = r.GetAdjustedCPUTime() * to_ns;
        m.real_ns = r.GetAdjustedRealTime() * to_ns;
        m.repetitions = r.repetitions;
        shown.push_back(r);
      }
    }
    if (!shown.empty()) ConsoleReporter::ReportRuns(shown);
    GetOutputStream().flush();  // progress through a pipe (bench/performance_report.py)
  }
};

std::string now_iso() {
  std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S%z", std::localtime(&t));
  return buf;
}

json summary(const std::string& started) {
  json out;
  out["started"] = started;
  out["finished"] = now_iso();
  out["compiler"] = std::string("g++ ") + __VERSION__;
  out["build_type"] = ECCD_BUILD_TYPE;
  out["gmp"] = gmp_version;
  out["mpfr"] = mpfr_get_version();
  out["mpsolve"] = eccd_bench::mpsolve_version();
  out["quick"] = g_quick;
  json groups = json::array();
  for (const Group& g : g_groups) {
    json jg{{"id", g.id}, {"title", g.title}, {"description", g.description}, {"anchor", g.anchor}};
    json rows = json::array();
    double base = 0;
    for (const Row& r : g_rows)
      if (r.group == g.id && r.baseline && g_medians.count(r.key) && g_medians[r.key].error.empty()) base = g_medians[r.key].cpu_ns;
    for (const Row& r : g_rows) {
      if (r.group != g.id || !g_medians.count(r.key)) continue;
      const Median& m = g_medians[r.key];
      json jr{{"key", r.key}, {"label", r.label}, {"baseline", r.baseline}, {"note", r.note}};
      if (!m.error.empty()) {
        jr["error"] = m.error;
      } else {
        jr["median_cpu_ns"] = m.cpu_ns;
        jr["median_real_ns"] = m.real_ns;
        jr["repetitions"] = m.repetitions;
        jr["iterations"] = m.iterations;
        if (!m.rep_cpu_ns.empty()) {
          jr["min_cpu_ns"] = *std::min_element(m.rep_cpu_ns.begin(), m.rep_cpu_ns.end());
          jr["max_cpu_ns"] = *std::max_element(m.rep_cpu_ns.begin(), m.rep_cpu_ns.end());
        }
        jr["ratio"] = base > 0 ? json(m.cpu_ns / base) : json();
      }
      if (g_results.count(r.key)) jr["result"] = g_results[r.key];
      rows.push_back(jr);
    }
    if (rows.empty()) continue;
    jg["rows"] = rows;
    groups.push_back(jg);
  }
  out["groups"] = groups;
  out["scenes"] = g_scenes;
  return out;
}

void print_ratios(const json& s) {
  if (s["groups"].empty()) return;
  std::printf("\nMedians (CPU time) and ratios to each group's baseline:\n");
  for (const auto& g : s["groups"]) {
    std::printf("\n[%s] %s\n", g["id"].get<std::string>().c_str(), g["title"].get<std::string>().c_str());
    for (const auto& r : g["rows"]) {
      if (r.contains("error")) { std::printf("  %-44s ERROR %s\n", r["label"].get<std::string>().c_str(), r["error"].get<std::string>().c_str()); continue; }
      double ns = r["median_cpu_ns"];
      char t[32];
      if (ns < 1e4) std::snprintf(t, sizeof t, "%.1f ns", ns);
      else if (ns < 1e7) std::snprintf(t, sizeof t, "%.3f ms", ns / 1e6);
      else std::snprintf(t, sizeof t, "%.1f ms", ns / 1e6);
      char ratio[32] = "-";
      if (!r["ratio"].is_null()) std::snprintf(ratio, sizeof ratio, "%.3g", r["ratio"].get<double>());
      std::printf("  %-44s %14s  x%-10s%s\n", r["label"].get<std::string>().c_str(), t, ratio,
                  r["baseline"].get<bool>() ? "  (baseline)" : "");
    }
  }
}

}  // namespace

// The hooks of bench/speed_targets.hpp (issue 36's rows).
void eccd_bench::add_group(const std::string& id, const std::string& title, const std::string& description, const std::string& anchor) {
  group(id, title, description, anchor);
}
void eccd_bench::add_row(const std::string& grp, const std::string& label, bool baseline, int cost, const std::string& note,
                         std::function<void(benchmark::State&)> fn, bool process_cpu) {
  row(grp, label, baseline, Cost(cost), note, std::move(fn), process_cpu);
}
void eccd_bench::record_result(const std::string& key, const nlohmann::json& summary) { g_results[key] = summary; }
std::string eccd_bench::source_path(const std::string& rel) { return src(rel); }

int main(int argc, char** argv) {
  std::string started = now_iso();
  std::string summary_path;
  bool list = false;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (a.rfind("--eccd_summary=", 0) == 0) summary_path = a.substr(15);
    else if (a == "--eccd_quick") g_quick = true;
    else if (a == "--eccd_list") list = true;
    else if (a.rfind("--eccd_profile_seconds=", 0) == 0) g_profile_seconds = std::stod(a.substr(23));
    else args.push_back(argv[i]);
  }
  // Repetitions of all rows run interleaved in random order (unless the
  // command line says otherwise): on a shared machine a burst of load from
  // another user then spreads over many rows as single outlying repetitions,
  // which the medians discard, instead of spoiling every repetition of one row.
  bool interleave_given = false;
  for (char* a : args) interleave_given |= std::string(a).rfind("--benchmark_enable_random_interleaving", 0) == 0;
  static char interleave[] = "--benchmark_enable_random_interleaving=true";
  if (!interleave_given && g_profile_seconds == 0) args.push_back(interleave);
  int n = int(args.size());
  benchmark::Initialize(&n, args.data());
  if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 1;

  if (list) {
    for (Lazy<Scene2D>* s : {&s2d_deg2, &s2d_deg4, &s2d_deg6, &s2d_deg6_free, &s2d_paper003}) {
      const Scene2D& x = s->get();
      std::cout << x.id << ": " << x.info.dump() << "\n";
    }
    return 0;
  }

  register_static();
  register_2d();
  register_3d();
  register_isolation();
  register_phases();
  register_solve_scene();
  register_certified_sets();
  register_static_certified();
  register_certified_cost();
  register_translation3d();  // issue 21: one degree-1 translating 3D query
  register_product();  // issue 30: eccd::solve from the scene, both faces and input modes (the target rows)
  register_planes();  // 000 section 4: the plane check per pair-frame (issue 17)
  register_animation();  // 001 section 5 in spirit: the boxers per frame, double and certified (issue 17)
  register_fcl_static();  // issue 21: FCL's static ellipsoid test on the static3d pairs
  register_fcl_table2();  // issue 21: per frame of 000 Table 2, eccd and FCL, misclassified frames
  eccd_bench::register_poses({group, [](const std::string& g, const std::string& l, bool b, const std::string& n,
                                        std::function<void(benchmark::State&)> f) { row(g, l, b, Cost::slow, n, f, true); },
                              [](const std::string& k, const json& j) { g_results[k] = j; }, ECCD_SOURCE_DIR});  // issue 36
  eccd_bench::register_table1_frames();  // 000 Table 1 as an animation, per frame (bench/table1_frames.cpp)
  eccd_bench::register_speed_targets();  // issue 36: the targets on the product path (bench/speed_targets.cpp)
  eccd_bench::register_independent({group,  // issue 33: cases/independent in four arithmetics (bench/independent.cpp)
                                    [](auto& g, auto& l, bool b, bool heavy, auto& n, auto fn) { row(g, l, b, heavy ? Cost::heavy : Cost::slow, n, fn); },
                                    [](const std::string& k, const json& j) { g_results[k] = j; }});

  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  json s = summary(started);
  print_ratios(s);
  if (!summary_path.empty()) {
    std::ofstream f(summary_path);
    f << s.dump(1) << "\n";
    if (!f) { std::cerr << "cannot write " << summary_path << "\n"; return 1; }
  }
  benchmark::Shutdown();
  return 0;
}
