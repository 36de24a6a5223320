// The prover's door to the independent checker (certificate/check_certificate.hpp).
#include "certificate/check_certificate.hpp"

#include "certificate/check/verdict.hpp"
#include "certificate/write/cycloidal_certificate.hpp"
#include "io/scene_reader.hpp"

namespace eccd {

using json = nlohmann::json;

CertificateCheck check_certificate(const Scene& s, const nlohmann::json& scene_doc, const nlohmann::json& cert) {
  // eccd-certificate/2, eccd-bezier-certificate/2, eccd-cycloidal-certificate/2, eccd-independent-certificate/3
  // (and anything else a shared-parameter scene is given): the independent checker, eccd-check's library
  // (certificate/check/), on the scene's own text and the certificate.
  if (cycloidal_certificate_scene(s)) {  // a cycloidal scene has one kind of certificate: say which when given another
    const json fmt = cert.is_object() && cert.contains("format") ? cert["format"] : json();
    if (fmt != kCycloidalCertificateFormat && fmt != "eccd-cycloidal-certificate/1") {
      CertificateCheck out;
      out.failed_claim = "certificate format";
      out.reason = std::string("format: expected \"") + kCycloidalCertificateFormat + "\" for a cycloidal scene, got " +
                   fmt.dump();
      return out;
    }
  }
  const std::string scene_text = s.source_text.empty() ? scene_doc.dump() : s.source_text;
  const check::Verdict v = check::check_certificate_text(scene_text, s.path.empty() ? std::string("scene") : s.path,
                                                         cert.dump(), "certificate");
  CertificateCheck out;
  out.valid = v.outcome == check::Outcome::valid;
  out.checked = v.checked;
  if (!out.valid) {
    out.failed_claim = v.outcome == check::Outcome::unreadable && v.claim == "input" ? "certificate format" : v.claim;
    out.reason = v.reason;
  }
  return out;
}

CertificateCheck check_certificate_text(const Scene& s, const nlohmann::json& scene_doc, const std::string& cert_text,
                                        const std::string& cert_label) {
  std::string structure;
  nlohmann::json cert = parse_json_document(cert_text, cert_label, &structure);
  if (!structure.empty()) {
    CertificateCheck out;
    out.failed_claim = "certificate format";
    out.reason = structure;
    return out;
  }
  return check_certificate(s, scene_doc, cert);
}

}  // namespace eccd
