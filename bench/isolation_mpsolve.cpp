// MPSolve 3 (Debian libmps-dev) as a root isolator for the benchmark's
// isolation groups (bench/isolation.hpp).
//
// What is measured: one mps_mpsolve() call with output goal "isolate" on the
// exact integer polynomial (coefficients passed as GMP rationals, so MPSolve
// treats the input as exact), secular-equation algorithm (MPSolve's default
// for a monomial polynomial), from a fresh context each run, including the
// creation and release of the context. MPSolve returns `degree` inclusion
// discs, pairwise disjoint, one root each: all complex roots, not only the
// real ones in [0, 1] the workbench needs. It may run its thread pool on both
// cores, so the benchmark charges it process CPU time (all threads) and also
// reports wall time. Anchor: the workbench's own isolation (CGAL
// Algebraic_kernel_d_1 over GMP + MPFI) on the same polynomial, in the same
// process (bench/group_isolation.cpp, group isolation-*).
#include "bench/isolation.hpp"

#include <mps/mps.h>

#include <cmath>
#include <stdexcept>

namespace eccd_bench {

namespace {

class MpsolveIsolation : public PreparedIsolation {
 public:
  explicit MpsolveIsolation(const std::vector<mpz_class>& c) : coeffs_(c) {
    if (coeffs_.size() < 2) throw std::invalid_argument("mpsolve: degree must be at least 1");
  }
  IsolationOutcome run() override {
    mps_context* ctx = mps_context_new();
    const long n = long(coeffs_.size()) - 1;
    mps_monomial_poly* poly = mps_monomial_poly_new(ctx, n);
    mpq_t re, im;
    mpq_init(re);
    mpq_init(im);
    for (long i = 0; i <= n; ++i) {
      mpq_set_z(re, coeffs_[std::size_t(i)].get_mpz_t());
      mps_monomial_poly_set_coefficient_q(ctx, poly, i, re, im);
    }
    mpq_clear(re);
    mpq_clear(im);
    mps_context_set_input_poly(ctx, MPS_POLYNOMIAL(poly));
    mps_context_select_algorithm(ctx, MPS_ALGORITHM_SECULAR_GA);
    mps_context_set_output_goal(ctx, MPS_OUTPUT_GOAL_ISOLATE);
    mps_context_set_output_prec(ctx, 64);
    mps_mpsolve(ctx);
    if (mps_context_has_errors(ctx)) {
      std::string msg = mps_context_error_msg(ctx);
      mps_context_free(ctx);
      throw std::runtime_error("MPSolve: " + msg);
    }
    IsolationOutcome out;
    cplx_t* roots = nullptr;
    double* radius = nullptr;
    mps_context_get_roots_d(ctx, &roots, &radius);
    out.roots = int(n);
    for (long i = 0; i < n; ++i) {
      double x = cplx_Re(roots[i]), y = cplx_Im(roots[i]), r = radius[i];
      if (std::fabs(y) <= r && x + r >= 0 && x - r <= 1) ++out.in_unit;
    }
    cplx_vfree(roots);
    free(radius);
    mps_context_free(ctx);  // also frees the polynomial
    return out;
  }

 private:
  std::vector<mpz_class> coeffs_;
};

}  // namespace

std::unique_ptr<PreparedIsolation> prepare_mpsolve(const std::vector<mpz_class>& coeffs) {
  return std::make_unique<MpsolveIsolation>(coeffs);
}

std::string mpsolve_version() {
  return "MPSolve " + std::to_string(MPS_MAJOR_VERSION) + "." + std::to_string(MPS_MINOR_VERSION) + "." +
         std::to_string(MPS_PATCH_VERSION);
}

}  // namespace eccd_bench
