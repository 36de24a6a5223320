// Certificates for Python: Certificate, CertificateCheck, eccd.certify
// and eccd.check_certificate (through eccd-check's library).
#include "bindings.hpp"

namespace eccd_python {

// Certificate, CertificateCheck, certify and check_certificate.
void bind_certify(py::module_& m) {
  py::class_<eccd::Certificate>(
      m, "Certificate", "certify's result: the certificate (JSON text, eccd-certificate/2) and the Solution it proves")
      .def_readonly("text", &eccd::Certificate::text)
      .def_readonly("solution", &eccd::Certificate::solution)
      .def("__repr__", [](const eccd::Certificate& c) {
        return "Certificate(" + std::to_string(c.text.size()) + " characters, " + answer_repr("", c.solution.answer) +
               ")";
      });
  py::class_<eccd::CertificateCheck>(m, "CertificateCheck",
                                     "The checker's verdict: valid, the claims that hold, the first that does not")
      .def_readonly("valid", &eccd::CertificateCheck::valid)
      .def_readonly("checked", &eccd::CertificateCheck::checked)
      .def_readonly("failed_claim", &eccd::CertificateCheck::failed_claim)
      .def_readonly("reason", &eccd::CertificateCheck::reason)
      .def("__bool__", [](const eccd::CertificateCheck& c) { return c.valid; })
      .def("__repr__", [](const eccd::CertificateCheck& c) {
        return c.valid ? std::string("CertificateCheck(VALID)")
                       : "CertificateCheck(REJECTED: " + c.failed_claim + ": " + c.reason + ")";
      });
  m.def(
      "certify",
      [](const py::object& scene_arg) {
        const eccd::Scene scene = scene_of(scene_arg, "certify");
        py::gil_scoped_release unlocked;
        return eccd::certify(scene);
      },
      py::arg("scene"),
      "Solves the scene (an eccd Scene, a scene dict or a path) exactly and writes a certificate of the answer (raises "
      "CertificationError if a claim cannot be made provable)");
  m.def(
      "check_certificate",
      [](const py::object& scene_arg, const std::string& text) {
        const eccd::Scene scene = scene_of(scene_arg, "check_certificate");
        py::gil_scoped_release unlocked;
        return eccd::check_certificate(scene, text);
      },
      py::arg("scene"), py::arg("text"),
      "Re-checks a certificate (JSON text) against its scene (an eccd Scene, a scene dict or a path) without the "
      "solver; "
      "text that is not JSON raises SceneError");
}

}  // namespace eccd_python
