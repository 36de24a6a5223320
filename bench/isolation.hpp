#pragma once
// Real root isolation by other libraries, behind one small interface, for the
// side-by-side comparison in bench/group_isolation.cpp (group "isolation-*").
//
// What is measured. The same integer polynomial (a positive multiple of the
// exact Δ(t) of a 2D scene, of the projection polynomial of a 3D scene, or a
// random integer polynomial of degree 200) is handed to
//   - CGAL's Algebraic_kernel_d_1 over CGAL::Gmpz with MPFI intervals: the
//     configuration the workbench itself uses (exact/algebraic_roots.cpp),
//     called here directly (no conversion from Poly<Rational>, no bracket
//     refinement to 2^-64, no restriction to [0, 1]);
//   - the same kernel over CORE::BigInt (CORE's BigInt/BigFloat, shipped
//     inside CGAL's headers; anchor: about 7 ms for a random degree-200
//     integer polynomial, measured on this machine);
//   - MPSolve 3 (Debian libmps-dev), output goal "isolate": pairwise disjoint
//     inclusion discs for all complex roots.
// Each prepare_* converts the coefficients once (not timed); run() does one
// complete isolation from scratch (a fresh kernel / a fresh MPSolve context,
// so that no cache of a previous run helps) and returns what it found.
// CGAL isolates the real roots only; MPSolve isolates all `degree` complex
// roots, a larger task: its real-root count here is the number of discs that
// meet the real segment [0, 1] (MPSolve's public API of 3.2.1 does not expose
// its "real roots only" search set), a plausibility check, not a proof.
#include <gmpxx.h>

#include <memory>
#include <string>
#include <vector>

namespace eccd_bench {

struct IsolationOutcome {
  int roots = 0;    // CGAL: distinct real roots; MPSolve: inclusion discs (= degree)
  int in_unit = 0;  // of those, in [0, 1] (MPSolve: discs meeting [0, 1])
};

class PreparedIsolation {
 public:
  virtual ~PreparedIsolation() = default;
  virtual IsolationOutcome run() = 0;
};

// coeffs: integer coefficients, lowest degree first, degree >= 1.
std::unique_ptr<PreparedIsolation> prepare_cgal_gmp_mpfi(const std::vector<mpz_class>& coeffs);
std::unique_ptr<PreparedIsolation> prepare_cgal_core(const std::vector<mpz_class>& coeffs);
std::unique_ptr<PreparedIsolation> prepare_mpsolve(const std::vector<mpz_class>& coeffs);

// "MPSolve 3.2.1" etc., for the report.
std::string mpsolve_version();

}  // namespace eccd_bench
