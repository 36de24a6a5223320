// eccd-check's dispatcher (certificate/check/verdict.hpp): reads the scene and
// the certificate strictly, picks the kind's checker by the certificate's
// format from kKinds, and turns its outcome into a Verdict.
#include "certificate/check/verdict.hpp"

#include "certificate/check/claims.hpp"
#include "certificate/check/kinds.hpp"
#include "certificate/check/scene.hpp"
#include "certificate/check/strict_json.hpp"

#include <fstream>
#include <sstream>

namespace eccd::check {

namespace {

struct Kind {
  const char* format;    // the format this checker covers
  const char* replaces;  // an older version of it, refused with a message saying so ("" for none)
  KindChecker check;
};

// One row per kind of certificate (certificate/check/kinds.hpp).
const Kind kKinds[] = {
    {"eccd-certificate/2", "eccd-certificate/1", check_exact_certificate},
    {"eccd-bezier-certificate/2", "eccd-bezier-certificate/1", check_bezier_certificate},
    {"eccd-cycloidal-certificate/2", "eccd-cycloidal-certificate/1", check_cycloidal_certificate},
    {"eccd-independent-certificate/3", "eccd-independent-certificate/2", check_independent_certificate},
};

std::string read_file(const std::string& path, bool& ok) {
  std::ifstream in(path, std::ios::binary);
  ok = bool(in);
  std::ostringstream o;
  if (ok) o << in.rdbuf();
  return o.str();
}

std::string covered_list() {
  std::string s;
  for (const Kind& k : kKinds) s += (s.empty() ? "" : ", ") + std::string(k.format);
  return s;
}

}  // namespace

bool covers_format(const std::string& format) {
  for (const Kind& k : kKinds)
    if (format == k.format) return true;
  return false;
}

Verdict check_certificate_text(const std::string& scene_text, const std::string& scene_label,
                               const std::string& cert_text, const std::string& cert_label) {
  Verdict v;
  CheckScene sc;
  StrictDocument cert;
  try {
    StrictDocument sd = parse_strict(scene_text, scene_label);
    if (!sd.structure_problem.empty()) throw SceneReadError(scene_label + ": " + sd.structure_problem);
    sc = read_check_scene(sd.value, scene_label);
    cert = parse_strict(cert_text, cert_label);
  } catch (const std::exception& e) {
    v.outcome = Outcome::unreadable;
    v.claim = "input";
    v.reason = e.what();
    return v;
  }
  try {
    if (!cert.structure_problem.empty()) reject("certificate format", cert.structure_problem);
    if (!cert.value.is_object()) reject("certificate format", "top level: expected an object");
    const json& fmt = at(cert.value, "format", "certificate");
    const Kind* kind = nullptr;
    for (const Kind& k : kKinds) {
      if (fmt == k.format)
        kind = &k;
      else if (*k.replaces && fmt == k.replaces)
        reject("certificate format", std::string("format: expected \"") + k.format + "\", got " + shown(fmt) +
                                         " (an older version, no longer accepted: its checker needed the prover's code "
                                         "or a search; run `eccd certify` again)");
    }
    if (!kind) {
      v.outcome = Outcome::unreadable;
      v.claim = "certificate format";
      v.reason = "format " + shown(fmt) + " is not covered by this checker (it covers " + covered_list() + ")";
      return v;
    }
    kind->check(sc, cert.value, v.checked);
    v.outcome = Outcome::valid;
  } catch (const Rejected& r) {
    v.outcome = Outcome::rejected;
    v.claim = r.claim;
    v.reason = r.reason;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (
      const std::exception& e) {  // arithmetic refused (a division by zero in a forged input): rejected, not a crash
    v.outcome = Outcome::rejected;
    v.claim = "certificate format";
    v.reason = std::string("the certificate cannot be checked: ") + e.what();
  }
  return v;
}

Verdict check_certificate_files(const std::string& scene_path, const std::string& cert_path) {
  bool ok1 = false, ok2 = false;
  const std::string s = read_file(scene_path, ok1), c = read_file(cert_path, ok2);
  if (!ok1 || !ok2) {
    Verdict v;
    v.outcome = Outcome::unreadable;
    v.claim = "input";
    v.reason = (!ok1 ? scene_path : cert_path) + ": cannot be read";
    return v;
  }
  return check_certificate_text(s, scene_path, c, cert_path);
}

}  // namespace eccd::check
