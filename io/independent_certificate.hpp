#pragma once
// The certificate of an independent-motion scene's proved answer (issue 20
// point 3; docs/certificate-format.md, "Independent scenes"), its writer and
// its checker.
//
// Statement. Paper 001, section 4: with F(u, s, t) = (-1)^H det((1 - u)A(s) +
// uB(t)) (kernel/trivariate_bernstein.hpp; H = 4 for ellipsoids, 3 for
// ellipses: one sign convention in both), P_s = { s : F(., s, t) <= 0 on (0, 1)
// for some t } and P_t likewise. The proof is certified/independent_proof.hpp's
// (its prose block has the argument); the certificate lists what it found,
// and the checker re-checks every claim on F's net, which it builds itself
// from the scene file in exact rationals and encloses in MPFI at
// `precision_bits` (outward rounding), restricting it to each claimed box by
// de Casteljau in intervals (the convex hull property):
//   - reduced: where a body does not move as a set, F = p G with p of one
//     sign along its parameter (TriBern::without_positive_factor, exact); the
//     proof and every claim below are about G (same sign as F everywhere),
//     and the certificate must name the parameters so divided out;
//   - faces: F(0, s, t) = det A(s) and F(1, s, t) = det B(t) < 0 (exact
//     control points of the net's faces u = 0 and u = 1, halved exactly
//     where the whole face's hull does not show it);
//   - for s (and for t, on F with s and t exchanged) a list of strips
//     [lo, hi] and ends, in order, covering [0, 1] without gaps:
//       "in": boxes U_i x [lo, hi] x T with one t-range T whose u-ranges
//       cover [0, 1], every control point < 0 (every s of the strip meets
//       B(t) for t in T);
//       "out": boxes U_i x [lo, hi] x T_i, every control point > 0, whose
//       t-ranges cover [0, 1] (every (s, t) separate);
//       an end: a run [lo, hi] between an "in" and an "out" strip, the
//       system ("fold": F = F_u = F_t = 0 in (u, s, t); "0" or "1": F = F_u =
//       0 in (u, s) at t = 0 or 1; "free": F = F_u = 0 in (u, s) where the
//       reduced F does not depend on t), a chain of boxes X = Y_0, ..., Y_k with
//       Krawczyk's K(X) inside the interior of X (exactly one zero in X),
//       Y_{i+1} containing Y_i ∩ K(Y_i) (the zero stays in the chain), X's
//       s-range covering [lo, hi], the side conditions (F_uu < 0 on X for a
//       fold and t inside (0, 1); F_t (or F_t / t, F_t / (1 - t) where F_t
//       vanishes on that face) and F_uu of one sign near t = 0 / 1; none
//       for "free"),
//       and the bracket, containing [lo, hi] ∩ Y_k's s-range, inside [lo, hi];
//   - the answer: the maximal runs of "in" strips, each end an exact strip
//     end or an end's bracket, must be the certificate's s_intervals and
//     t_intervals (and collides: either list non-empty).
// What the checker re-runs rather than reads: the exclusion of other extreme
// points from each end's run (certified/independent_proof.hpp step 3c, a
// bounded subdivision of the nets of F, F_u, F_t, F_uu over the run); the
// certificate does not list those boxes. Nothing else is searched.
// Requirements: a 2D or 3D scene with "parameters": "independent" and
// rational motions; format /1 (3D only, never reduced) is refused by name; the writer refuses (CertificationError) when the proof leaves
// anything undecided.
#include "certified/solution.hpp"
#include "io/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>

namespace eccd {

inline constexpr const char* kIndependentCertificateFormat = "eccd-independent-certificate/2";

// A scene (2D or 3D) with independent parameters: the scenes this certificate is for.
bool independent_certificate_scene(const Scene& s);

// The certificate; `solved` receives the proved run's Solution. Throws CertificationError when the proof leaves a
// range undecided (nothing is certified then).
nlohmann::json make_independent_certificate(const Scene& s, const nlohmann::json& scene_doc, Solution* solved = nullptr);

// The checker's verdict on `cert` for scene `s` (scene_doc: the scene file's JSON).
CertificateCheck check_independent_certificate(const Scene& s, const nlohmann::json& scene_doc, const nlohmann::json& cert);

// Bounds (denial of service): precision 64..1024 bits, rationals of at most 1024 bits, at most 200000 strips and
// 2000000 boxes per projection, Krawczyk chains of at most 64 boxes.
inline constexpr int kIndependentMinBits = 64, kIndependentMaxBits = 1024;
inline constexpr std::size_t kIndependentMaxRationalBits = 1024, kIndependentMaxStrips = 200000, kIndependentMaxBoxes = 2000000,
                             kIndependentMaxChain = 64;

}  // namespace eccd
