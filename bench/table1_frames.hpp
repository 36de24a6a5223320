#pragma once
// Paper 000's Table 1 pair as an animation, per frame (bench/table1_frames.cpp),
// registered through bench/speed_targets.hpp's hooks.
namespace eccd_bench {
void register_table1_frames();
}  // namespace eccd_bench
