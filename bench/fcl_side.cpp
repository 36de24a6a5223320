#include "bench/fcl_side.hpp"

#include <stdexcept>

#ifdef ECCD_BENCH_HAVE_FCL
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/narrowphase/collision.h>
#endif

namespace eccd_bench {

#ifdef ECCD_BENCH_HAVE_FCL
namespace {

fcl::Transform3d transform_of(const FclBody& b) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  fcl::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = b.rotation[i][j];
  tf.linear() = r;
  tf.translation() = fcl::Vector3d(b.centre[0], b.centre[1], b.centre[2]);
  return tf;
}

class Pairs final : public PreparedFclPairs {
 public:
  Pairs(const std::vector<FclBody>& a, const std::vector<FclBody>& b, bool indep) {
    if (a.size() != b.size()) throw std::invalid_argument("prepare_fcl_pairs: a and b differ in size");
    if (indep) request_.gjk_solver_type = fcl::GST_INDEP;
    for (std::size_t i = 0; i < a.size(); ++i) {
      ea_.emplace_back(a[i].radii[0], a[i].radii[1], a[i].radii[2]);
      eb_.emplace_back(b[i].radii[0], b[i].radii[1], b[i].radii[2]);
      ta_.push_back(transform_of(a[i]));
      tb_.push_back(transform_of(b[i]));
    }
  }
  bool collide(std::size_t i) override {
    fcl::CollisionResultd result;
    return fcl::collide(&ea_[i], ta_[i], &eb_[i], tb_[i], request_, result) > 0;
  }
  std::size_t size() const override { return ea_.size(); }

 private:
  fcl::CollisionRequestd request_;  // FCL's defaults, as compare/fcl_engine.cpp and a user call it
  std::vector<fcl::Ellipsoidd> ea_, eb_;
  std::vector<fcl::Transform3d, Eigen::aligned_allocator<fcl::Transform3d>> ta_, tb_;
};

}  // namespace

std::string fcl_bench_unavailable() { return ""; }
std::unique_ptr<PreparedFclPairs> prepare_fcl_pairs(const std::vector<FclBody>& a, const std::vector<FclBody>& b,
                                                    bool indep_solver) {
  return std::make_unique<Pairs>(a, b, indep_solver);
}
#else
std::string fcl_bench_unavailable() {
  return "FCL (CMake package fcl, Debian libfcl-dev) was not found when build-bench was configured";
}
std::unique_ptr<PreparedFclPairs> prepare_fcl_pairs(const std::vector<FclBody>&, const std::vector<FclBody>&, bool) {
  throw std::runtime_error(fcl_bench_unavailable());
}
#endif

}  // namespace eccd_bench
