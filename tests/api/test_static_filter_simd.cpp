// The batched 3D static filter (api/static_filter_simd.hpp): the lanes
// compiled for AVX-512 and for AVX2 + FMA give, lane by lane, exactly the code
// of the one-pair filter of the default build (kernel/static_filter3d.hpp,
// pair_code), FMA contraction being off in those units. Checked on random
// affine pairs near and far, on exactly touching spheres (uncertain), and on
// inputs the filter's ranges refuse (NaN, infinity, a pose entry above 2^12, a
// semi-axis below 2^-12, zero), for every instruction set this CPU runs; and
// the choice of instruction set: cpu_isa() is the widest of has_avx512() /
// has_avx2(), static_batch_isa() the narrower of it and the limit.
#include "api/static_filter_simd.hpp"

#include "kernel/static_filter3d.hpp"
#include "tests/support/poses.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

using M4 = std::array<std::array<double, 4>, 4>;
constexpr int L = simd::kSimdLanes;

// One block of lanes: random pairs, and every 19th lane one of the edge inputs.
void fill_block(std::mt19937_64& rng, int block, double (&in)[kStaticInputs][L], double (&one)[L], int& edges) {
  std::uniform_real_distribution<double> axis(0.2, 3), q(-1, 1), far(-6, 6), shear(0.5, 2);
  for (int l = 0; l < L; ++l) {
    std::array<double, 3> xa{axis(rng), axis(rng), axis(rng)}, xb{axis(rng), axis(rng), axis(rng)};
    M4 pa = test::pose3({q(rng), q(rng), q(rng), q(rng)}, far(rng), far(rng), far(rng));
    M4 pb = test::pose3({q(rng), q(rng), q(rng), q(rng)}, far(rng), far(rng), far(rng));
    if (rng() % 3 == 0)
      for (int i = 0; i < 3; ++i) pb[i][i] *= shear(rng);  // an affine, not rigid, pose
    const int kind = (block * L + l) % 19;
    switch (kind) {
      case 1:
        pa[2][1] = std::nan("");
        break;
      case 2:
        pb[0][3] = -HUGE_VAL;
        break;
      case 3:
        pa[1][3] = 4097;  // above 2^12
        break;
      case 4:
        xb[2] = 1.0 / 8192;  // below 2^-12
        break;
      case 5:
        xa[0] = 0;
        break;
      case 6:  // spheres of radii 1/2 and 3/4, centres 5/4 apart: touching exactly
        xa = {0.5, 0.5, 0.5};
        xb = {0.75, 0.75, 0.75};
        pa = test::pose3({1, 0, 0, 0}, 0, 0, 0);
        pb = test::pose3({1, 0, 0, 0}, 0, 1.25, 0);
        break;
      default:
        break;
    }
    auto leaf = static_leaves(xa, pa, xb, pb);
    for (int k = 0; k < kStaticInputs; ++k) in[k][l] = leaf(k);
    one[l] = static_filter_detail::pair_code<false>(leaf);
    if (kind >= 1 && kind <= 6) {
      CHECK(one[l] == 0.0);  // the scalar filter leaves them uncertain
      ++edges;
    }
  }
}

}  // namespace

TEST_CASE("static filter simd: AVX-512 and AVX2 lanes give the one-pair filter's codes", "[api][static-filter-simd]") {
  std::vector<simd::Isa> isas;
  if (simd::has_avx2()) isas.push_back(simd::Isa::avx2);
  if (simd::has_avx512()) isas.push_back(simd::Isa::avx512);
  if (isas.empty()) {
    WARN("this CPU runs neither AVX2 + FMA nor AVX-512: only the pair-by-pair filter exists here");
    return;
  }
  std::mt19937_64 rng(4301);
  int edges = 0, separate = 0, overlapping = 0, uncertain = 0;
  for (int block = 0; block < 400; ++block) {
    double in[kStaticInputs][L], one[L];
    fill_block(rng, block, in, one, edges);
    for (simd::Isa isa : isas) {
      double code[L];
      for (double& c : code) c = -1;  // every lane must be written
      if (isa == simd::Isa::avx512)
        simd::static_filter3d_lanes_avx512(in, code);
      else
        simd::static_filter3d_lanes_avx2(in, code);
      for (int l = 0; l < L; ++l) {
        INFO(simd::to_string(isa) << " block " << block << " lane " << l);
        CHECK(code[l] == one[l]);
      }
    }
    for (double c : one) (c == 1.0 ? separate : c == 2.0 ? overlapping : uncertain)++;
  }
  CHECK(edges > 300);
  // Both decided statuses occur often, so the comparison covers them.
  CHECK(separate > 300);
  CHECK(overlapping > 100);
  CHECK(uncertain >= edges);
}

TEST_CASE("static filter simd: the instruction set is the widest the CPU runs, under the limit",
          "[api][static-filter-simd]") {
  using simd::Isa;
  CHECK(std::string(simd::to_string(Isa::avx512)) == "avx512");
  CHECK(std::string(simd::to_string(Isa::avx2)) == "avx2");
  CHECK(std::string(simd::to_string(Isa::none)) == "none (pair by pair)");
  const Isa cpu = simd::cpu_isa();
  CHECK(cpu == (simd::has_avx512() ? Isa::avx512 : simd::has_avx2() ? Isa::avx2 : Isa::none));
  for (Isa limit : {Isa::none, Isa::avx2, Isa::avx512}) {
    simd::set_static_batch_isa_limit(limit);
    CHECK(simd::static_batch_isa() == std::min(cpu, limit));
  }
  simd::set_static_batch_isa_limit(Isa::avx512);  // the default
  CHECK(simd::static_batch_isa() == cpu);
}

}  // namespace ECCD_UNITY_ID
