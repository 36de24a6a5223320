#pragma once
// Certify a scene and check a certificate, typed (what `eccd certify` and
// `eccd check-certificate` do, README "Certify a critical scene").
//
// certify runs the exact pipeline with its root isolation recorded and
// returns the certificate (format eccd-certificate/2, certificate/write/exact_certificate.hpp) as
// JSON text together with the typed Solution it certifies (its answer carries
// the certificate's refined rational brackets). The certificate quotes the
// scene's own JSON, so the Scene must have been read by read_scene /
// scene_from_text (Scene::source_text). check_certificate re-checks a
// certificate against its scene without the solver (certificate/check_certificate.hpp).
// Errors: CertificationError (a claim cannot be made provable), std::invalid_argument
// (a cycloidal motion, a scene built in code without its JSON text).
// The certificate is not re-checked by certify; check_certificate does that.
#include "api/solution.hpp"
#include "certificate/certificate_result.hpp"
#include "kernel/scene.hpp"

#include <string>

namespace eccd {

struct Certificate {
  std::string text;   // the certificate, JSON (format eccd-certificate/2)
  Solution solution;  // the exact answer it proves, with the run's diagnostics
};

Certificate certify(const Scene& scene);
// The checker's verdict (a failed claim names itself); a certificate that is
// not JSON at all throws SceneError "certificate: line L, column C: ...".
CertificateCheck check_certificate(const Scene& scene, const std::string& certificate_text);

}  // namespace eccd
