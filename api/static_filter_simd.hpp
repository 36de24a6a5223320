#pragma once
// The 3D static filter (kernel/static_filter3d.hpp) compiled for AVX-512
// (F, DQ, VL) with AVX2 and FMA in its own translation unit,
// api/static_filter_simd.cpp, which CMakeLists.txt builds with those flags;
// api/static_status.cpp calls it only when __builtin_cpu_supports says the CPU
// has all of them, and the default build otherwise. AVX-512, not
// AVX2: GCC 12 if-converts and vectorises the lane loop's compares with
// AVX-512's mask registers only (with -mavx2 -mfma: "control flow in loop").
// Why a translation unit and not target attributes: GCC does not inline a
// function compiled for the default target (std::array's operator[], the
// program's templates) into one with target("avx2"), so the lane loop kept
// calls and did not vectorise. In this unit everything is compiled for AVX-512
// and flattened into its one entry point, so the unit emits no shared
// (weak) instantiation that the linker could pick for default-target code
// (checked with nm: the unit defines only the entry point).
// FMA contraction is off in this unit (-ffp-contract=off): the lanes then
// round exactly as the single pair's program in the default build (lane 0 of
// ValueMagnitude is the double run, lane 1 the Magnitude run), so the batch
// decides exactly the pairs static_status decides (contraction would keep the
// bounds, number/static_bound.hpp, but could move a pair at a bound's edge).
// The same lanes compiled for AVX2 + FMA (no AVX-512) in
// api/static_filter_avx2.cpp, written with explicit 4-lane vectors
// (number/lane_vector.hpp) since GCC's vectoriser does not take this loop under
// AVX2; same flags otherwise (-ffp-contract=off: each lane rounds as the one
// pair does). The batch picks the widest instruction set the CPU runs
// (static_batch_isa); a lower limit can be set for benchmarks and tests.
// Inputs: in[k][l] is input k of lane l as numbered by kernel/static_filter3d.hpp (static_axis_a, ...).
// Results: a status code, 0 uncertain, 1 separate, 2 overlapping.
namespace eccd::simd {

inline constexpr int kSimdLanes = 8;
bool has_avx512();  // the CPU runs this unit's code (defined in api/static_status.cpp, compiled for any CPU)
bool has_avx2();    // the CPU runs api/static_filter_avx2.cpp's code (AVX2 and FMA)
void static_filter3d_lanes_avx512(const double (&in)[30][kSimdLanes], double (&code)[kSimdLanes]);
void static_filter3d_lanes_avx2(const double (&in)[30][kSimdLanes], double (&code)[kSimdLanes]);

// The instruction sets of the batched static test, narrowest first; none: pair by pair.
enum class Isa { none, avx2, avx512 };
const char* to_string(Isa isa);
Isa cpu_isa();                               // the widest this CPU runs
Isa static_batch_isa();                      // what static_status_batch uses: min(cpu_isa(), the limit)
void set_static_batch_isa_limit(Isa limit);  // for benchmarks and tests (default: avx512); not thread-safe

}  // namespace eccd::simd
