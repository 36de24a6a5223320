// eccd_bench: the performance benchmark of the workbench (its rows and the
// report of them). Separate from the tests: built only by `cmake --build B --target
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
//   product-*       the target rows: eccd::solve from the scene, what
//        a user waits for, on the 2D degree-6 scene (Variant 3) and paper
//        002's example; double as published and guarded, rounded and
//        prepared input, certified and exact. Baseline: double as published,
//        rounded input (the guarded row's ratio is the guard's cost).
//   solve_scene-*   rows through eccd::solve_scene (what `eccd solve` runs,
//        JSON building included), from a table of (label, SolveOptions),
//        kSolveSceneRows below: double, MPFR, exact and the certified interval
//        mode (`--arith certified`; its rows go there).
//   plane-check, animate-boxers  the kept plane's check over one
//        frame per pair-frame (baseline: the continuous test in double) and
//        the boxers' animation per frame in double, double without planes and
//        certified (baseline: double); with static-certified-2d/3d (the
//        static test from two poses) they form the report's "Animations"
//        section (bench/perf_report/sections.py ANIMATION_GROUPS).
//   fcl-static3d, fcl-table2-main, fcl-table2-graze  FCL side by
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
#include "bench/groups.hpp"
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
#include "independent.hpp"

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

using namespace eccd;
using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

using namespace eccd_bench::groups;

namespace {

// ---------------------------------------------------------------------------
// Reporter: medians per row (console shows only the medians) and the summary.

struct Median {
  double cpu_ns = 0, real_ns = 0;
  long long iterations = 0;
  long long repetitions = 0;
  std::vector<double> rep_cpu_ns;
  std::map<std::string, double> counters;  // the user counters' medians over the repetitions
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
        for (const auto& [name, c] : r.counters) m.counters[name] = c.value;
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
      if (r.group == g.id && r.baseline && g_medians.count(r.key) && g_medians[r.key].error.empty())
        base = g_medians[r.key].cpu_ns;
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
        if (!m.counters.empty()) jr["counters"] = m.counters;
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
      if (r.contains("error")) {
        std::printf("  %-44s ERROR %s\n", r["label"].get<std::string>().c_str(), r["error"].get<std::string>().c_str());
        continue;
      }
      double ns = r["median_cpu_ns"];
      char t[32];
      if (ns < 1e4)
        std::snprintf(t, sizeof t, "%.1f ns", ns);
      else if (ns < 1e7)
        std::snprintf(t, sizeof t, "%.3f ms", ns / 1e6);
      else
        std::snprintf(t, sizeof t, "%.1f ms", ns / 1e6);
      char ratio[32] = "-";
      if (!r["ratio"].is_null()) std::snprintf(ratio, sizeof ratio, "%.3g", r["ratio"].get<double>());
      std::printf("  %-44s %14s  x%-10s%s\n", r["label"].get<std::string>().c_str(), t, ratio,
                  r["baseline"].get<bool>() ? "  (baseline)" : "");
    }
  }
}

}  // namespace

// The hooks of bench/speed_targets.hpp (the speed target rows).
void eccd_bench::add_group(const std::string& id, const std::string& title, const std::string& description,
                           const std::string& anchor) {
  group(id, title, description, anchor);
}
void eccd_bench::add_row(const std::string& grp, const std::string& label, bool baseline, int cost,
                         const std::string& note, std::function<void(benchmark::State&)> fn, bool process_cpu) {
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
    if (a.rfind("--eccd_summary=", 0) == 0)
      summary_path = a.substr(15);
    else if (a == "--eccd_quick")
      g_quick = true;
    else if (a == "--eccd_list")
      list = true;
    else if (a.rfind("--eccd_profile_seconds=", 0) == 0)
      g_profile_seconds = std::stod(a.substr(23));
    else
      args.push_back(argv[i]);
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
  register_translation3d();  // one degree-1 translating 3D query
  register_product();        // eccd::solve from the scene, both faces and input modes (the target rows)
  register_planes();         // 000 section 4: the plane check per pair-frame
  register_animation();      // 001 section 5 in spirit: the boxers per frame, double and certified
  register_fcl_static();     // FCL's static ellipsoid test on the static3d pairs
  register_fcl_table2();     // per frame of 000 Table 2, eccd and FCL, misclassified frames
  eccd_bench::register_poses({group,
                              [](const std::string& g, const std::string& l, bool b, const std::string& name,
                                 std::function<void(benchmark::State&)> f) { row(g, l, b, Cost::slow, name, f, true); },
                              [](const std::string& k, const json& j) { g_results[k] = j; },
                              ECCD_SOURCE_DIR});  // the per-pose mode (bench/poses.cpp)
  eccd_bench::register_table1_frames();           // 000 Table 1 as an animation, per frame (bench/table1_frames.cpp)
  eccd_bench::register_speed_targets();           // the speed targets on the product path (bench/speed_targets.cpp)
  eccd_bench::register_independent({group,        // cases/independent in four arithmetics (bench/independent.cpp)
                                    [](auto& g, auto& l, bool b, bool heavy, auto& name, auto fn) {
                                      row(g, l, b, heavy ? Cost::heavy : Cost::slow, name, fn);
                                    },
                                    [](const std::string& k, const json& j) { g_results[k] = j; }});

  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  json s = summary(started);
  print_ratios(s);
  if (!summary_path.empty()) {
    std::ofstream f(summary_path);
    f << s.dump(1) << "\n";
    if (!f) {
      std::cerr << "cannot write " << summary_path << "\n";
      return 1;
    }
  }
  benchmark::Shutdown();
  return 0;
}
