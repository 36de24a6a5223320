#pragma once
// The speed target rows (bench/speed_targets.cpp), registered through the
// registry of bench/groups.hpp (groups, rows, the results of the last
// iteration) by the three hooks below, which bench/eccd_bench.cpp defines.
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace eccd_bench {

// cost: 0 fast (nanosecond rows), 1 slow, 2 very slow, 3 heavy (as eccd_bench.cpp's Cost).
void add_group(const std::string& id, const std::string& title, const std::string& description,
               const std::string& anchor);
void add_row(const std::string& grp, const std::string& label, bool baseline, int cost, const std::string& note,
             std::function<void(benchmark::State&)> fn, bool process_cpu = false);
void record_result(const std::string& key, const nlohmann::json& summary);
std::string source_path(const std::string& rel);  // a file of the source tree

void register_speed_targets();

}  // namespace eccd_bench
