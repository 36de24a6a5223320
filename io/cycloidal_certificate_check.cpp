// The cycloidal certificate's checker (io/cycloidal_certificate.hpp) is eccd-check's
// library (certificate/check/cycloidal_certificate.cpp: its own MPFI enclosures of
// Δ, Δ' and the static test; no code shared with the writer or the solver).
#include "io/cycloidal_certificate.hpp"

#include "io/certificate_check.hpp"

namespace eccd {

CertificateCheck check_cycloidal_certificate(const Scene& s, const nlohmann::json& scene_doc, const nlohmann::json& cert) {
  return check_certificate(s, scene_doc, cert);
}

}  // namespace eccd
