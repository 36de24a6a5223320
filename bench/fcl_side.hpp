#pragma once
// FCL's static ellipsoid test, called directly, for the side-by-side rows of
// bench/group_fcl.cpp (groups "fcl-static3d" and "fcl-table2-*").
//
// What is measured. fcl::collide(&Ellipsoidd, Transform3d, &Ellipsoidd,
// Transform3d, request, result) on bodies built once (not timed) from their
// semi-axes, rotation and centre: the cheapest call FCL offers for one pair of
// ellipsoids (no CollisionObject, no broad phase, no pose computation). The
// request is FCL's default CollisionRequestd, as compare/fcl_engine.cpp makes
// it (GJK solver libccd, gjk_tolerance 1e-6), or the same with FCL's own GJK
// implementation (GST_INDEP), so that the report can name FCL's faster one.
// Kept in its own translation unit so that FCL's and Eigen's headers stay out
// of eccd_bench.cpp; without FCL at configure time (ECCD_BENCH_HAVE_FCL not
// defined) fcl_bench_available() says why and prepare_fcl_pairs throws.
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace eccd_bench {

struct FclBody {
  std::array<double, 3> radii{};
  std::array<std::array<double, 3>, 3> rotation{};  // columns: the body's axes in the world, det +1
  std::array<double, 3> centre{};
};

class PreparedFclPairs {
 public:
  virtual ~PreparedFclPairs() = default;
  virtual bool collide(std::size_t i) = 0;  // pair i: fcl::collide(...) > 0
  virtual std::size_t size() const = 0;
};

// "" when FCL was found at configure time, else why not.
std::string fcl_bench_unavailable();
// indep_solver: GST_INDEP instead of FCL's default GST_LIBCCD.
std::unique_ptr<PreparedFclPairs> prepare_fcl_pairs(const std::vector<FclBody>& a, const std::vector<FclBody>& b,
                                                    bool indep_solver);

}  // namespace eccd_bench
