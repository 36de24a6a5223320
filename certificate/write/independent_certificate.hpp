#pragma once
// The certificate of an independent-motion scene's proved answer
// (docs/certificate-format.md, "Independent scenes") and its writer; the
// checker is eccd-check's (certificate/check/independent_certificate.cpp),
// which shares no code with the proof.
//
// Statement. Paper 001, section 4: with F(u, s, t) = det((1 - u) A(s) +
// u B(t)) (kernel/trivariate_bernstein.hpp; H = 4 for ellipsoids, 3 for
// ellipses), P_s = { s : F(., s, t) <= 0 on (0, 1) for some t } and P_t
// likewise. The proof is certified/independent_proof.hpp's (its prose block
// has the argument); the certificate lists everything a checker needs without
// a search:
//   - net: F's exact tensor Bernstein net with the shapes and inverse motions
//     it is built from (the checker verifies them against the scene and the
//     net against det(...) at integer points);
//   - reduced: the parameters whose body does not move as a set (A(s) =
//     c(s) A(0), c > 0: static, or turning in place), held at 0 in the net
//     (kernel/trivariate_bernstein.hpp, hold_still);
//   - s_proof and t_proof: strips "in" / "out" with their boxes, and ends
//     with their system, Krawczyk chain, exclusion tree and bracket;
//   - the answer: collides, s_intervals, t_intervals. A certificate is always
//     complete: the writer refuses (CertificationError) when the proof leaves
//     anything undecided, so it never claims "collides": false unproved.
// Requirements: a 2D or 3D scene with "parameters": "independent" and
// rational motions. Formats /1 and /2 (checked with the prover's code) are
// refused by eccd-check with a message that says so.
#include "solution/solution.hpp"
#include "certificate/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>

namespace eccd {

inline constexpr const char* kIndependentCertificateFormat = "eccd-independent-certificate/3";

// A scene (2D or 3D) with independent parameters: the scenes this certificate is for.
bool independent_certificate_scene(const Scene& s);

// The certificate; `solved` receives the proved run's Solution. Throws CertificationError when the proof leaves a
// range undecided (nothing is certified then).
nlohmann::json make_independent_certificate(const Scene& s, const nlohmann::json& scene_doc,
                                            Solution* solved = nullptr);

// eccd-check's verdict on `cert` for scene `s` (scene_doc: the scene file's JSON).
CertificateCheck check_independent_certificate(const Scene& s, const nlohmann::json& scene_doc,
                                               const nlohmann::json& cert);

// Bounds of the writer: at most this many exclusion boxes per end, trees at most this deep (eccd-check allows 40).
inline constexpr std::size_t kIndependentMaxBoxes = 2000000;
inline constexpr int kIndependentMaxTreeDepth = 38;

}  // namespace eccd
