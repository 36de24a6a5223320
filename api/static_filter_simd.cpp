// The 3D static filter compiled for AVX-512 (F, DQ, VL), AVX2 and FMA (api/static_filter_simd.hpp).
#include "api/static_filter_simd.hpp"

#include "kernel/static_filter3d.hpp"

namespace eccd::simd {

static_assert(kStaticInputs == 30);

[[gnu::flatten]] void static_filter3d_lanes_avx512(const double (&in)[30][kSimdLanes], double (&code)[kSimdLanes]) {
  static_filter3d_lanes<kSimdLanes>(in, code);
}

}  // namespace eccd::simd
