#pragma once
// The benchmark group of independent motions: eccd::solve
// on every scene of cases/independent in double, mpfr:128, exact and
// certified; baseline double, so the report's ratio of the mpfr row is
// MPFR / double on the same scene (target: at most 20).
// Registered from bench/eccd_bench.cpp through the hooks below (the registry
// lives in bench/groups.hpp).
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace eccd_bench {

struct IndependentHooks {
  // group(id, title, description, anchor)
  std::function<void(const std::string&, const std::string&, const std::string&, const std::string&)> group;
  // row(group, label, baseline, heavy, note, fn): heavy = seconds per iteration (few repetitions)
  std::function<void(const std::string&, const std::string&, bool, bool, const std::string&,
                     std::function<void(benchmark::State&)>)>
      row;
  // result(key, what the row answered)
  std::function<void(const std::string&, const nlohmann::json&)> result;
};

// Groups independent-SCENE (every scene of cases/independent) and independent-rotating (generated pairs of
// ellipsoids turning by degree-2 Euler parameters, exact and certified per scene).
void register_independent(const IndependentHooks& h);

}  // namespace eccd_bench
