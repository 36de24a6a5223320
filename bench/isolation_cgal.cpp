// CGAL's Algebraic_kernel_d_1 in two configurations, called directly, for
// the benchmark's isolation groups (bench/isolation.hpp). The one other CGAL
// translation unit besides exact/algebraic_roots.cpp; built only with the
// eccd_bench target.
//
// What is measured: one solve_1 call (square-free factorisation by modular
// gcd, then Bitstream Descartes isolation of every real root, with
// multiplicities) on a polynomial converted once beforehand, from a freshly
// constructed kernel each run (so no state of an earlier run helps):
//   - Algebraic_kernel_d_1<CGAL::Gmpz> with CGAL_USE_MPFI (GMP integers, MPFI
//     bigfloat intervals): the other kernel CGAL offers, for comparison;
//   - Algebraic_kernel_d_1<CORE::BigInt> (CORE's BigInt / BigFloat arithmetic
//     kernel, header-only inside CGAL 5.5; anchor: about 7 ms for a random
//     degree-200 integer polynomial on this machine): the kernel the
//     workbench uses. The difference to the workbench's row
//     (eccd::real_roots, baseline of each isolation group) is the workbench's
//     own work around it: Poly<Rational> -> integer conversion, the roots that
//     can lie in [0, 1] refined to width 2^-64 (quadratic interval
//     refinement, exact/algebraic_roots.cpp), the rational-root check.
// Counted: distinct real roots, and those in [0, 1] (compared exactly with
// the kernel's compare_1 against the rationals 0 and 1).
#include "bench/isolation.hpp"

#include <CGAL/Algebraic_kernel_d_1.h>
#include <CGAL/CORE_BigInt.h>
#include <CGAL/CORE_arithmetic_kernel.h>
#include <CGAL/Gmpz.h>

#include <iterator>
#include <utility>
#include <vector>

namespace eccd_bench {

namespace {

template <class Coefficient>
class CgalIsolation : public PreparedIsolation {
 public:
  using AK = CGAL::Algebraic_kernel_d_1<Coefficient>;
  using Poly = typename AK::Polynomial_1;
  using Real = typename AK::Algebraic_real_1;
  using Bound = typename AK::Bound;

  explicit CgalIsolation(const std::vector<Coefficient>& c) {
    using PT = CGAL::Polynomial_traits_d<Poly>;
    poly_ = typename PT::Construct_polynomial()(c.begin(), c.end());
  }
  IsolationOutcome run() override {
    AK ak;  // fresh each run
    std::vector<std::pair<Real, typename AK::Multiplicity_type>> roots;
    ak.solve_1_object()(poly_, std::back_inserter(roots));
    IsolationOutcome out;
    out.roots = int(roots.size());
    auto cmp = ak.compare_1_object();
    const Real zero(Bound(0)), one(Bound(1));
    for (const auto& r : roots)
      if (cmp(r.first, zero) != CGAL::SMALLER && cmp(r.first, one) != CGAL::LARGER) ++out.in_unit;
    return out;
  }

 private:
  Poly poly_;
};

}  // namespace

std::unique_ptr<PreparedIsolation> prepare_cgal_gmp_mpfi(const std::vector<mpz_class>& coeffs) {
  std::vector<CGAL::Gmpz> c;
  for (const auto& x : coeffs) c.emplace_back(x.get_mpz_t());
  return std::make_unique<CgalIsolation<CGAL::Gmpz>>(c);
}

std::unique_ptr<PreparedIsolation> prepare_cgal_core(const std::vector<mpz_class>& coeffs) {
  std::vector<CORE::BigInt> c;
  for (const auto& x : coeffs) c.emplace_back(x.get_str().c_str());
  return std::make_unique<CgalIsolation<CORE::BigInt>>(c);
}

}  // namespace eccd_bench
