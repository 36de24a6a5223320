// Certify a scene and check a certificate, typed (api/certify.hpp).
#include "api/certify.hpp"

#include "certificate/write/exact_certificate.hpp"
#include "certificate/check_certificate.hpp"
#include "certificate/write/cycloidal_certificate.hpp"
#include "certificate/write/independent_certificate.hpp"
#include "io/scene_reader.hpp"

#include <chrono>
#include <stdexcept>

namespace eccd {

namespace {
nlohmann::json scene_document(const Scene& scene) {
  if (scene.source_text.empty())
    throw std::invalid_argument(
        "certify: the scene " + (scene.name.empty() ? std::string("(unnamed)") : scene.name) +
        " has no JSON text (built in code); certify a scene read by read_scene or scene_from_text");
  return parse_json_document(scene.source_text, scene.path);
}
}  // namespace

Certificate certify(const Scene& scene) {
  nlohmann::json doc = scene_document(scene);
  auto start = std::chrono::steady_clock::now();
  Certificate c;
  nlohmann::json cert = make_certificate(scene, doc, &c.solution);
  c.text = cert.dump(1) + "\n";
  Solution& s = c.solution;
  s.scene = scene.name;
  s.file = scene.path;
  s.dim = scene.dim;
  s.arith = Arithmetic::exact();
  s.input = InputMode::prepared;
  s.basis = "exact";
  s.method = scene.dim == 3 ? "projection" : "cd-disc";
  s.certified = true;
  if (cycloidal_certificate_scene(scene)) {  // certified (MPFI), not exact: certificate/write/cycloidal_certificate.hpp
    s.arith = Arithmetic::certified();
    s.basis = "pointwise";
    s.method = "cd-disc-cycloidal";
    s.certified = s.answer.undecided.empty();
  }
  if (independent_certificate_scene(
          scene)) {  // interval proofs about the exact F: certificate/write/independent_certificate.hpp
    s.basis = "interval+mpfi";
    s.method = "bezier-independent-proved";
  }
  s.time_ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
  return c;
}

CertificateCheck check_certificate(const Scene& scene, const std::string& certificate_text) {
  return check_certificate_text(scene, scene_document(scene), certificate_text, "certificate");
}

}  // namespace eccd
