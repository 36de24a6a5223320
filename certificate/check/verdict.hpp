#pragma once
// eccd-check's verdict on a certificate, and the entry point of the
// independent checker (certificate/check/).
//
// Statement. The checker reads the scene file and the certificate itself
// (certificate/check/scene.hpp, strict_json.hpp) and re-proves every claim
// of the certificate with its own exact algebra (qpoly.hpp, pencil.hpp):
// it shares no code with the provers (no kernel/ pipelines, floating/,
// exact/, certified/, io/, no CGAL; scripts/check-layers.sh enforces it).
// Outcomes: VALID (exit 0), REJECTED naming the first claim that fails and
// why (exit 1), UNREADABLE: a scene or certificate that is not a readable
// file or JSON, or a format this checker does not cover (exit 2).
// Covered: "eccd-certificate/2" (2D and 3D, exact answers: docs/checking.md).
// Requirements: GMP, nlohmann json.
#include <string>
#include <vector>

namespace eccd::check {

enum class Outcome { valid, rejected, unreadable };

struct Verdict {
  Outcome outcome = Outcome::unreadable;
  std::vector<std::string> checked;  // one line per claim that holds
  std::string claim, reason;         // rejected: the first claim that fails; unreadable: what could not be read
};

// The formats check_certificate_text covers.
bool covers_format(const std::string& format);

// Checks the certificate text against the scene text (labels name the files in messages).
Verdict check_certificate_text(const std::string& scene_text, const std::string& scene_label,
                               const std::string& cert_text, const std::string& cert_label);

// The same from two files (unreadable if either cannot be read).
Verdict check_certificate_files(const std::string& scene_path, const std::string& cert_path);

}  // namespace eccd::check
