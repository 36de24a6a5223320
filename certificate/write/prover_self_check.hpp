#pragma once
// The prover-side self-check of eccd-certificate/2: re-checks a certificate
// (certificate/write/exact_certificate.hpp) against its scene without calling
// the solver, on the prover's own exact algebra. It is not the independent
// checker (certificate/check/, eccd-check, which shares no code with the
// prover and is what the commands call: certificate/check_certificate.hpp);
// it is a second opinion for the mutation campaign
// (tests/certificate/test_mutation_campaign.cpp).
//
// Statement. It trusts only the scene reader and the exact algebra of
// exact/certificate_algebra.hpp (f, the projection polynomial, the evidence
// polynomials, the static tests 003 Theorem 6 / 002 Theorem 1), Descartes'
// rule of signs (exact/descartes.hpp), polynomial multiplication and division
// over the rationals, and the timeline-to-answer step
// (kernel/collision_timeline.hpp). It does not isolate roots (no CGAL), does
// not run CD-DISC or the projection CCD. Claims, in order:
//   scene      the certificate's dim, a, b equal the scene file's;
//   f          each g_k equals the one recomputed from the scene;
//   projection its name (the candidates before it vanish identically) and
//              its integer coefficients equal the recomputed ones;
//   factors    Π F_i^m_i equals the projection up to a non-zero constant;
//   timeline   instant, cell, ..., instant from [0, 0] to [1, 1]; each cell
//              sample lies strictly between its two brackets;
//   instant k  a root: lo = hi and P(lo) = 0, or P(lo), P(hi) ≠ 0 and Descartes
//              gives 1 for its factor and 0 for the others on (lo, hi); not a
//              root (0 or 1 only): P ≠ 0 there;
//   gaps       the gap points split the gaps into pieces where every factor
//              has 0 sign variations (so P has no other root in [0, 1]);
//   cell k     the exact static test at the sample gives the claimed status;
//   status of instant k
//              rational: the static test; irrational: each evidence sign is
//              proved (0 variations on (lo, hi) and that sign at lo; or a
//              common factor of the polynomial and F_i with its root in the
//              bracket), then the status follows by 003 Theorem 6 (2D) or by
//              kernel/quartic_touch_rule.hpp and the neighbouring cells (3D);
//   answer     the answer assembled from the checked timeline equals the
//              certificate's.
//   continuous touching (2D, Δ ≡ 0)
//              P·D has no root in [0, 1] (gap points, Descartes) and the static
//              test at one sample gives the status: touching means the answer
//              has the contact interval [0, 1] (docs/answer-format.md);
// Every approx is a decimal inside its bracket; every integer is range
// checked (no truncation); duplicate keys are refused (one strict parse);
// every rational has at most certificate_max_bits(n, τ) bits
// (certificate/write/exact_certificate.hpp: 4τ + 1024, and n²·b <= 2^24 but >= 256; τ the bit
// size of the projection's integer coefficients, n its degree), every factor
// coefficient τ + 2n + 64, at most 8n + 64 gap points,
// multiplicities at most n = deg P and their degree sum equal to n, before
// any arithmetic, so a forged certificate cannot make the checker slow.
// The first claim that fails is reported by name with the reason and the JSON
// place; a malformed part is REJECTED, never an internal error.
#include "certificate/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>

namespace eccd {

// The checker of eccd-certificate/2 described above, on the prover's algebra
// (exact/certificate_algebra.hpp).
CertificateCheck prover_self_check(const Scene& s, const nlohmann::json& scene_doc, const nlohmann::json& cert);

}  // namespace eccd
