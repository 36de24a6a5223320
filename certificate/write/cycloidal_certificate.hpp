#pragma once
// The certificate of a cycloidal scene's certified answer (003 section V;
// docs/certificate-format.md, "Cycloidal scenes"), its writer and its checker.
//
// Statement. A cycloidal motion (003 section V) is not rational, so Δ(t), the
// discriminant of f(λ; t) = det(λA(t) - B(t)), is not a polynomial and the
// exact certificate (certificate/write/exact_certificate.hpp: Descartes' rule on integer
// polynomials) cannot apply. Its claims are proved instead by interval
// evaluation in MPFI at the certificate's `precision_bits` (outward rounding:
// every enclosure holds the exact value), of Δ, Δ' (forward-mode derivative)
// and g_0..g_3 at rational instants or over rational intervals, with the
// formulas of kernel/cycloidal_motion.hpp (003 section V). The timeline is
// instant, cell, ..., instant over [0, 1] as in the exact certificate:
//   - a root bracket [lo, hi] (kind "simple_root"): Δ(lo) and Δ(hi) have
//     proved opposite signs and Δ' is proved non-zero on [lo, hi], so Δ has
//     exactly one root there, a simple one; its status from the proved signs
//     of P and D over [lo, hi] (003 Theorem 6: touching iff the double root
//     P/(2D) of f is negative);
//   - an undecided stretch [lo, hi] (kind "undecided"): a possible double root
//     of Δ (a touch, a near miss or close roots), which no enclosure proves;
//     the certificate claims only |Δ(t)| <= ε on [lo, hi] with the stated ε
//     (proved by one enclosure), status "uncertain": "touch or near miss
//     within ε", never a touch;
//   - 0 and 1 (kind "end"), unless an undecided stretch reaches them: the
//     status by the MPFI static test (kernel/contact_status.hpp) proved there;
//   - a cell: a rational sample strictly between its brackets, its status by
//     the static test proved at the sample;
//   - gap points cut every gap between brackets (and [0, 1] outside them) into
//     pieces, each proved root-free: an enclosure of Δ over the piece (natural,
//     or the mean-value form Δ(m) + Δ'([a, b])([a, b] - m)) excludes 0, or Δ'
//     is proved non-zero there and Δ(a), Δ(b) have the same proved sign;
//   - the answer, assembled from the checked timeline (an undecided stretch is
//     an undecided instant of it; `complete` is false then).
// The writer takes the brackets of the certified pipeline
// (certified/ladder.hpp, run_certified_cycloidal) and recomputes every claim
// itself (cells, gap pieces by bisection, ε); the checker re-checks them with
// nothing but these enclosures and the timeline-to-answer step: no
// subdivision search, no refinement, no solver.
// Requirements: a 2D scene whose motions are static or cycloidal.
#include "solution/solution.hpp"
#include "certificate/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>

namespace eccd {

inline constexpr const char* kCycloidalCertificateFormat = "eccd-cycloidal-certificate/2";

// A 2D scene with a cycloidal motion (and shared parameters): the scenes this certificate is for.
bool cycloidal_certificate_scene(const Scene& s);

// The certificate; `solved` receives the certified run's Solution with the
// certificate's answer. Throws CertificationError when a claim cannot be proved.
nlohmann::json make_cycloidal_certificate(const Scene& s, const nlohmann::json& scene_doc, Solution* solved = nullptr);

// Bounds (denial of service): precision 64..1024 bits, rationals of at most
// 1024 bits, at most 20000 gap points and 4000 timeline entries.
inline constexpr int kCycloidalMinBits = 64, kCycloidalMaxBits = 1024;
inline constexpr std::size_t kCycloidalMaxRationalBits = 1024, kCycloidalMaxGapPoints = 20000,
                             kCycloidalMaxTimeline = 4001;

}  // namespace eccd
