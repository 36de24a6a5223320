// The 3D static filter compiled for AVX2 and FMA, 4 lanes per vector register (api/static_filter_simd.hpp).
#include "api/static_filter_simd.hpp"

#include "kernel/static_filter3d.hpp"

namespace eccd::simd {

static_assert(kStaticInputs == 30 && kSimdLanes % 4 == 0);

[[gnu::flatten]] void static_filter3d_lanes_avx2(const double (&in)[30][kSimdLanes], double (&code)[kSimdLanes]) {
  static_filter3d_vector_lanes<4, kSimdLanes>(in, code);
}

}  // namespace eccd::simd
