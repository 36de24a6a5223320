#pragma once
// What certifying a scene and checking a certificate report, without JSON (so
// that api/certify.hpp can name them): CertificationError when a claim
// cannot be made provable (certificate/write/exact_certificate.hpp), and the checker's verdict
// (certificate/check_certificate.hpp).
#include <stdexcept>
#include <string>
#include <vector>

namespace eccd {

// Thrown when a claim cannot be made provable (e.g. refinement limit reached).
struct CertificationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CertificateCheck {
  bool valid = false;
  std::vector<std::string> checked;  // one line per claim group that holds
  std::string failed_claim, reason;  // the first claim that does not
};

}  // namespace eccd
