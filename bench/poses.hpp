#pragma once
// The per-pose mode's benchmark group (bench/poses.cpp), registered from
// eccd_bench.cpp through these hooks (the registry lives in bench/groups.hpp).
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace eccd_bench {

struct PosesBenchHooks {
  // group(id, title, description, anchor)
  std::function<void(const std::string&, const std::string&, const std::string&, const std::string&)> group;
  // row(group, label, baseline, note, timing loop): a microsecond row, process CPU time
  std::function<void(const std::string&, const std::string&, bool, const std::string&,
                     std::function<void(benchmark::State&)>)>
      row;
  // result(key, what the row computed): after the timing loop
  std::function<void(const std::string&, const nlohmann::json&)> result;
  std::string source_dir;
};

void register_poses(const PosesBenchHooks& hooks);

}  // namespace eccd_bench
