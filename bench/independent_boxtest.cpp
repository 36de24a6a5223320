// The cost of one box test of the independent-motion subdivision
// (floating/independent_ccd.hpp), guarded double against guarded mpfr:128, on
// the 3D scenes of cases/independent. The target ratio (MPFR at most 20x
// double) is per box test: the two arithmetics run the same walk, but a run
// under the default budget stops at a different place in each. Here F's net is
// built once (as eccd::solve builds it: the pair prepared exactly, a body that
// turns in place held, then rounded), outside the timing, and each iteration
// runs ccd_independent with one fixed work bound (kTests box tests) and no
// deadline; counter `ns_per_test` is CPU time per box test. Groups
// independent-boxtest/SCENE/{double,mpfr:128}; run with repetitions, e.g.
//   build/bench/eccd_bench --benchmark_filter='independent-boxtest' --benchmark_repetitions=3
#include "floating/independent_ccd.hpp"
#include "io/scene_reader.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/trivariate_bernstein.hpp"
#include "number/running_error.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace eccd;

constexpr long kTests = 20000;

template <class T>
TriBern<T> net_of(const std::string& file, const T& like) {
  Scene shared = read_scene_file(file);
  shared.independent = false;  // prepare_pair takes the shared-parameter form; the net pairs A's s with B's t
  PreparedPair<4> p = prepare_pair<4>(shared);
  hold_still_pair(p);
  return independent_ellipsoid_function<T, 4>(to_arithmetic_bernstein<T, 4>(p, like));
}

template <class T>
void run(benchmark::State& st, const TriBern<T>& F, const T& like) {
  IndependentOptions o;
  o.max_tests = kTests;
  long tests = 0;
  for (auto _ : st) {
    IndependentResult r = ccd_independent(F, like, o);
    benchmark::DoNotOptimize(r);
    tests += r.counters.front().second;
  }
  st.counters["box_tests"] = benchmark::Counter(double(tests), benchmark::Counter::kAvgIterations);
  st.counters["ns_per_test"] =
      benchmark::Counter(double(tests) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

const bool registered = [] {
  for (const char* scene :
       {"ellipsoids-cross", "ellipsoids-turning", "spheres-cross", "ellipsoids-apart", "spheres-end"}) {
    const std::string file = std::string(ECCD_SOURCE_DIR) + "/cases/independent/" + scene + ".json";
    const std::string grp = std::string("independent-boxtest/") + scene;
    benchmark::RegisterBenchmark((grp + "/double").c_str(), [file](benchmark::State& st) {
      const Bounded<double> like(1.0, 0);
      const TriBern<Bounded<double>> F = net_of(file, like);
      run(st, F, like);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((grp + "/mpfr:128").c_str(), [file](benchmark::State& st) {
      const Bounded<Mpfr> like(Mpfr(mpq_class(1), 128), 0);
      const TriBern<Bounded<Mpfr>> F = net_of(file, like);
      run(st, F, like);
    })->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
