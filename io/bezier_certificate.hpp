#pragma once
// The certificate of a 3D scene's answer proved by the interval Bézier method
// (issue 18 point 4; docs/certificate-format.md, "Bézier certificates"), its
// writer and its checker.
//
// Statement. Paper 001, section 4: with F(u, t) = det((u - 1)A(t) - uB(t))
// (kernel/ellipsoid_function.hpp, degree 4 in u), the ellipsoids are separate
// at t iff max_u F(u, t) > 0. The proof is certified/bezier_proof.hpp's (its
// prose block has the argument); the certificate lists its pieces, and the
// checker re-checks every claim on F's net, which it builds itself from the
// scene file in exact rationals (kernel/characteristic_polynomial.hpp,
// kernel/ellipsoid_function.hpp) and encloses in MPFI at `precision_bits`
// (outward rounding), restricting it to each claimed box by de Casteljau in
// intervals (the convex hull property):
//   - pieces [lo, hi] in order covering [0, 1] without gaps:
//       "out": boxes U_i x T_i, every control point > 0, the T_i covering
//       [lo, hi] (separate on the strip);
//       "in": boxes U_i x T_j, every control point < 0, grouped by t-range:
//       the groups' t-ranges cover [lo, hi], each group's u-ranges cover
//       [0, 1] (overlapping on the strip);
//       "end": between an in and an out piece; F(0, t), F(1, t) < 0 on the
//       run (control points of the restricted faces); a Krawczyk chain on
//       (F, F_u) in (u, t) with K(X) inside X's interior and X's t-range
//       covering [lo, hi] (io/krawczyk_claims.hpp); the exclusion re-run
//       (certified/exclusion.hpp: F or F_u of one sign on every box of a
//       bounded subdivision of [0, 1] x [lo, hi] outside X's u-range); the
//       bracket inside [lo, hi] holding [lo, hi] ∩ Y_k's t-range;
//   - the answer: the timeline of the pieces (cells between the ends, each
//     end a touching instant with its bracket) assembled as every pipeline
//     does (kernel/collision_timeline.hpp) must be the certificate's answer.
// Nothing is searched but the exclusion's bounded subdivision; the checker
// shares no code with the engine's search (certified/bezier_proof.cpp).
// Requirements: a 3D scene with shared parameters and rational motions; the
// writer refuses (CertificationError) when the proof does not decide the scene.
#include "certified/solution.hpp"
#include "io/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>

namespace eccd {

inline constexpr const char* kBezierCertificateFormat = "eccd-bezier-certificate/1";

// A 3D scene with shared parameters (the scenes this certificate can be for).
bool bezier_certificate_scene(const Scene& s);

// The certificate; `solved` receives the proof's Solution. Throws CertificationError when prove_bezier does not
// decide the scene (the caller falls back to the exact certificate).
nlohmann::json make_bezier_certificate(const Scene& s, const nlohmann::json& scene_doc, Solution* solved = nullptr);

// `eccd certify --arith certified`: the Bézier certificate when the scene is one and prove_bezier decides it,
// else make_certificate's (io/certificate.hpp: exact, cycloidal or independent). `route` receives "bezier",
// "exact", "cycloidal" or "independent"; `why` why the Bézier route was not taken ("" when it was).
nlohmann::json make_certified_mode_certificate(const Scene& s, const nlohmann::json& scene_doc, std::string& route, std::string& why,
                                               Solution* solved = nullptr);

// The checker's verdict on `cert` for scene `s` (scene_doc: the scene file's JSON).
CertificateCheck check_bezier_certificate(const Scene& s, const nlohmann::json& scene_doc, const nlohmann::json& cert);

// Bounds (denial of service): precision 64..1024 bits, rationals of at most 1024 bits, at most 200000 pieces and
// 2000000 boxes, Krawczyk chains of at most 64 boxes, the exclusion of one end at most 60000 boxes, 40 levels deep.
inline constexpr int kBezierMinBits = 64, kBezierMaxBits = 1024;
inline constexpr std::size_t kBezierMaxRationalBits = 1024, kBezierMaxPieces = 200000, kBezierMaxBoxes = 2000000, kBezierMaxChain = 64;
inline constexpr long kBezierMaxExclusionBoxes = 60000;
inline constexpr int kBezierMaxExclusionDepth = 40;

}  // namespace eccd
