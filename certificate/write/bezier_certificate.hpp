#pragma once
// The certificate of a 3D scene's answer proved by the interval Bézier method
// (docs/certificate-format.md, "Bézier certificates"), its
// writer and its checker.
//
// Statement. Paper 001, section 4: with F(u, t) = det((u - 1)A(t) - uB(t))
// (kernel/ellipsoid_function.hpp, degree 4 in u), the ellipsoids are separate
// at t iff max_u F(u, t) > 0. The proof is certified/bezier_proof.hpp's (its
// prose block has the argument); the certificate (format 2) lists its pieces
// (out / in boxes, each end's faces, Krawczyk chain and bracket), F's exact
// net with the shapes and inverse motions it is built from, and for each end
// the exclusion as a subdivision tree, so that the checker needs no search.
// The checker is eccd-check's library (certificate/check/bezier_certificate.cpp,
// which shares no code with the prover); check_bezier_certificate and
// `eccd check-certificate` call it, and the writer checks its own certificate
// with it before writing (a claim it cannot re-prove is never written).
// Requirements: a 3D scene with shared parameters and rational motions; the
// writer refuses (CertificationError) when the proof does not decide the scene.
#include "solution/solution.hpp"
#include "certificate/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>

namespace eccd {

inline constexpr const char* kBezierCertificateFormat = "eccd-bezier-certificate/2";

// A 3D scene with shared parameters (the scenes this certificate can be for).
bool bezier_certificate_scene(const Scene& s);

// The certificate; `solved` receives the proof's Solution. Throws CertificationError when prove_bezier does not
// decide the scene (the caller falls back to the exact certificate).
nlohmann::json make_bezier_certificate(const Scene& s, const nlohmann::json& scene_doc, Solution* solved = nullptr);

// `eccd certify --arith certified`: the Bézier certificate when the scene is one and prove_bezier decides it,
// else make_certificate's (certificate/write/exact_certificate.hpp: exact, cycloidal or independent). `route` receives
// "bezier", "exact", "cycloidal" or "independent"; `why` why the Bézier route was not taken ("" when it was).
nlohmann::json make_certified_mode_certificate(const Scene& s, const nlohmann::json& scene_doc, std::string& route,
                                               std::string& why, Solution* solved = nullptr);

// The checker's verdict on `cert` for scene `s` (scene_doc: the scene file's JSON).
CertificateCheck check_bezier_certificate(const Scene& s, const nlohmann::json& scene_doc, const nlohmann::json& cert);

// Bounds (denial of service): precision 64..1024 bits, rationals of at most 1024 bits, at most 200000 pieces and
// 2000000 boxes, Krawczyk chains of at most 64 boxes, the exclusion tree of one end at most 60000 boxes, 40 levels deep
// (the writer's; the checker's own bounds are in certificate/check/bezier_certificate.cpp).
inline constexpr int kBezierMinBits = 64, kBezierMaxBits = 1024;
inline constexpr std::size_t kBezierMaxRationalBits = 1024, kBezierMaxPieces = 200000, kBezierMaxBoxes = 2000000,
                             kBezierMaxChain = 64;
inline constexpr long kBezierMaxExclusionBoxes = 60000;
inline constexpr int kBezierMaxExclusionDepth = 40;

}  // namespace eccd
