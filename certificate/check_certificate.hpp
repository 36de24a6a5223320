#pragma once
// Checking a certificate of any kind from the prover's side of the house: the
// door from eccd's types (a Scene, its JSON document, CertificateCheck) to the
// independent checker (certificate/check/verdict.hpp, the library of
// eccd-check), which shares no code with the prover and sees only the scene's
// text and the certificate's. `eccd check-certificate`, `regress --certify`,
// the API (api/certify.hpp) and the writers' own check of what they wrote
// (certificate/write/) call it. Every kind: eccd-certificate/2 (2D and 3D),
// the Bézier, cycloidal and independent-motion certificates
// (docs/certificate-format.md, docs/checking.md).
#include "certificate/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace eccd {

// Checks a certificate of any kind against its scene with the independent
// checker; a cycloidal scene accepts only a cycloidal certificate (the
// verdict names the format expected).
CertificateCheck check_certificate(const Scene& s, const nlohmann::json& scene_doc, const nlohmann::json& cert);
// The same from the certificate's bytes (read once by the caller): a duplicate
// key or over-deep nesting is REJECTED naming its JSON place; malformed JSON
// throws SceneError "LABEL: line L, column C: ..." (an unreadable file).
CertificateCheck check_certificate_text(const Scene& s, const nlohmann::json& scene_doc, const std::string& cert_text,
                                        const std::string& cert_label);

}  // namespace eccd
