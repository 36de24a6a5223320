#pragma once
// The certificate of an exact answer: everything a simpler program needs to
// re-check it without the solver (certificate/check/ checks it; certificate/write/prover_self_check.hpp is the
// prover-side self-check).
//
// Statement. The exact pipeline (exact/cd_disc_exact.hpp in 2D,
// kernel/ccd_projection.hpp in 3D) decides the status of two moving objects
// on the timeline instant, cell, instant, ..., instant over [0, 1]
// (kernel/collision_timeline.hpp): the instants are 0, 1 and the real roots of
// the projection polynomial P(t) (exact/certificate_algebra.hpp), the cells
// the open intervals between them. The certificate writes down:
//   - the scene it is about (dim, a, b, verbatim) and f's coefficients g_k;
//   - P with exact integer coefficients, the polynomials that vanished
//     identically before it, and P's square-free factorisation
//     P = c · Π F_i^m_i;
//   - for each root a rational bracket [lo, hi] refined until Descartes' rule
//     (exact/descartes.hpp) proves it: exactly one root of its factor F_i
//     (sign variations 1) and none of the other factors (variations 0);
//     P(lo), P(hi) ≠ 0 (a rational root is written [r, r]);
//   - gap points splitting the gaps between brackets into pieces where every
//     factor has 0 variations: so P has no other root in [0, 1];
//   - one rational sample per cell with its status (exact static test);
//   - at each instant its status and the evidence: the static test at a
//     rational instant, or at an irrational root the signs of the evidence
//     polynomials (2D: P and D of 003 Theorem 6; 3D: the subresultant
//     coefficients of kernel/quartic_touch_rule.hpp). A non-zero sign is
//     provable on the bracket (the polynomial has 0 variations on it and that
//     sign at lo); a zero sign comes with a common factor h of the polynomial
//     and F_i that has its one root in the bracket;
//   - the answer, which must follow from the timeline.
// Brackets are refined (never moved) until all these claims hold, so the
// certificate's brackets may be narrower than `eccd solve`'s.
// Requirements: a scene with rational motions.
#include "solution/solution.hpp"
#include "certificate/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>
#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace eccd {

// Size bounds of a certificate, relative to its scene (denial of service,
// docs/certificate-format.md): every rational it holds (bracket ends, cell samples, gap points)
// has numerator and denominator of at most certificate_max_bits(n, τ) bits,
// n the degree of the projection polynomial (of P·D for a 2D Δ ≡ 0) and τ the
// bit size of its primitive integer coefficients; there are at most
// certificate_max_gap_points(n) gap points. The bound is four times τ plus a
// constant, and at most what keeps the checker's Descartes tests (about n²
// multiplications of n·b-bit by b-bit integers each) to seconds: n²·b <= 2^24,
// but never below 256 bits. Measured on paper 002's example (n = 216, four
// roots, four polynomials tested per bracket): the genuine certificate (64-bit
// brackets) checks in 0.4 s, a forged one with every bracket at the bound
// (~254 bits) in 1.4 s; without the bound, ~500 bits took 5.7 s and ~1400
// bits 40 s. Genuine brackets are 64 to 128 bits (all 129 shipped cases
// certify within the bound); the writer refines no further than the bound and
// otherwise cannot certify (exit 4).
inline std::size_t certificate_max_bits(std::size_t n, std::size_t tau) {
  const std::size_t by_size = 4 * tau + 1024;
  const std::size_t by_work = std::max<std::size_t>(256, (std::size_t(1) << 24) / std::max<std::size_t>(n * n, 1));
  return std::min(by_size, by_work);
}
inline std::size_t certificate_max_gap_points(std::size_t n) { return 8 * n + 64; }

// Runs the exact pipeline with the root isolation recorded and returns the
// certificate (format "eccd-certificate/2": format 1 plus approx inside its
// bracket, contact_intervals in the answer and the continuous_touching claim
// of a 2D Δ ≡ 0; the checker refuses format 1). scene_doc is the scene file's
// JSON (its dim, a and b are copied into the certificate).
// If `solved` is given it receives the exact run's typed Solution (what was run
// aside: api/certify.cpp), with the certificate's refined brackets as its answer.
nlohmann::json make_certificate(const Scene& s, const nlohmann::json& scene_doc, Solution* solved = nullptr);

}  // namespace eccd
