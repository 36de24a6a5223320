// `eccd certify`: the certified answer of one scene, a verdict for each
// floating pipeline against it, and a certificate that `eccd
// check-certificate` re-checks without the solver (certificate/write/exact_certificate.hpp).
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "api/certify.hpp"
#include "api/solve.hpp"
#include "io/solution_json.hpp"
#include "compare/harness.hpp"
#include "compare/harness_families.hpp"
#include "certificate/write/cycloidal_certificate.hpp"
#include "certificate/write/independent_certificate.hpp"
#include "certificate/write/bezier_certificate.hpp"
#include "compare/verdict.hpp"
#include "certificate/write/exact_certificate.hpp"
#include "certificate/check_certificate.hpp"
#include "io/scene_reader.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace eccd {

namespace {

struct CertifyArgs {
  std::string scene, out;
  std::vector<int> mpfr_bits{128, 256};
  double tol = 1e-6;
  bool json = false, no_floating = false, force = false;
  std::string arith = "exact";
};

// The scene and its JSON from ONE read of the file's bytes: a file that
// changes between two reads (a FIFO serving two scenes, a race) cannot pair
// one scene's certificate or answer with another scene.
struct SceneBytes {
  Scene scene;
  nlohmann::json doc;
};
// SCENE "-" reads standard input (labelled "<stdin>"), once like a file.
SceneBytes read_scene_once(const std::string& path) {
  const SceneSource src = read_scene_source(path);
  SceneBytes r{parse_scene(src.text, src.label), parse_json_document(src.text, src.label)};
  return r;
}

std::string instant_text(const nlohmann::json& i) {
  std::string lo = i["lo"].get<std::string>(), hi = i["hi"].get<std::string>();
  if (lo == hi) return lo;
  return i["approx"].get<std::string>() + " in [" + lo + ", " + hi + "]";
}

// A cycloidal scene's certificate (certificate/write/cycloidal_certificate.hpp): MPFI-proved brackets, stretches left
// undecided.
std::string cycloidal_text(const nlohmann::json& cert) {
  std::ostringstream o;
  const auto& a = cert["answer"];
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f s", cert["seconds"].get<double>());
  o << "scene " << cert["scene"]["name"].get<std::string>() << " (2D, cycloidal): certified in MPFI at "
    << cert["delta"]["precision_bits"].get<int>() << " bits in " << buf << "\n";
  int roots = 0;
  for (const auto& n : cert["timeline"]) {
    if (!n.contains("kind")) continue;
    if (n["kind"] == "simple_root") ++roots;
    if (n["kind"] == "undecided")
      o << "  NOT PROVED: touch or near miss within epsilon = " << n["epsilon"].get<std::string>()
        << " (|Delta| <= epsilon proved) on [" << n["instant"]["lo"].get<std::string>() << ", "
        << n["instant"]["hi"].get<std::string>() << "] (~" << n["instant"]["approx"].get<std::string>()
        << "); nothing is claimed there\n";
  }
  o << "  Delta: " << roots
    << " simple root(s) in [0, 1], each in a bracket proved by opposite signs of Delta at its ends and Delta' != 0 on "
       "it\n";
  o << "  collides: "
    << (a["collides"].is_null()     ? "unknown (no collision proved; a stretch is left undecided)"
        : a["collides"].get<bool>() ? "yes"
                                    : "no")
    << "\n";
  for (const auto& iv : a["intervals"])
    o << "  collision interval: [" << instant_text(iv[0]) << ", " << instant_text(iv[1]) << "]\n";
  if (!a["first_contact"].is_null()) o << "  first contact: " << instant_text(a["first_contact"]) << "\n";
  for (const auto& c : a["contacts"]) o << "  external contact: " << instant_text(c) << "\n";
  if (!cert["complete"].get<bool>())
    o << "  the answer is NOT complete: " << a["undecided"].size() << " stretch(es) undecided\n";
  return o.str();
}

// An independent scene's certificate (certificate/write/independent_certificate.hpp): strips and ends proved, s- and
// t-intervals.
std::string independent_text(const nlohmann::json& cert) {
  std::ostringstream o;
  const auto& a = cert["answer"];
  o << "scene " << cert["scene"]["name"].get<std::string>() << " (" << cert["scene"]["dim"].get<int>()
    << "D, independent motions): proved by interval proofs about the exact F "
    << "(MPFI " << cert["precision_bits"].get<int>() << " bits; " << cert["s_proof"].size() << " s-items, "
    << cert["t_proof"].size() << " t-items)\n";
  o << "  " << (a["collides"].get<bool>() ? "the paths meet" : "the paths do not meet") << "\n";
  for (const char* k : {"s_intervals", "t_intervals"})
    for (const auto& iv : a[k]) o << "  " << k << ": [" << instant_text(iv[0]) << ", " << instant_text(iv[1]) << "]\n";
  return o.str();
}

// A Bézier certificate (certificate/write/bezier_certificate.hpp): pieces of t proved out / in, ends by Krawczyk.
std::string bezier_text(const nlohmann::json& cert) {
  std::ostringstream o;
  const auto& a = cert["answer"];
  int n_in = 0, n_out = 0, n_end = 0;
  for (const auto& p : cert["pieces"]) (p["kind"] == "in" ? n_in : p["kind"] == "out" ? n_out : n_end)++;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f s", cert["seconds"].get<double>());
  o << "scene " << cert["scene"]["name"].get<std::string>()
    << " (3D): certified by the interval Bezier proof about the exact F(u, t) in " << buf << " (MPFI "
    << cert["precision_bits"].get<int>() << " bits; " << n_out << " out, " << n_in << " in pieces, " << n_end
    << " end(s) by Krawczyk)\n";
  o << "  collides: " << (a["collides"].get<bool>() ? "yes" : "no") << "\n";
  for (const auto& iv : a["intervals"])
    o << "  collision interval: [" << instant_text(iv[0]) << ", " << instant_text(iv[1]) << "]\n";
  if (!a["first_contact"].is_null()) o << "  first contact: " << instant_text(a["first_contact"]) << "\n";
  if (a["contacts"].empty()) o << "  external contacts: none\n";
  for (const auto& c : a["contacts"]) o << "  external contact: " << instant_text(c) << "\n";
  return o.str();
}

std::string certified_text(const nlohmann::json& cert) {
  if (cert["format"] == kBezierCertificateFormat) return bezier_text(cert);
  if (cert["format"] == kCycloidalCertificateFormat) return cycloidal_text(cert);
  if (cert["format"] == kIndependentCertificateFormat) return independent_text(cert);
  std::ostringstream o;
  const auto& s = cert["scene"];
  const auto& p = cert["projection"];
  const auto& a = cert["answer"];
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f s", cert["seconds"].get<double>());
  o << "scene " << s["name"].get<std::string>() << " (" << s["dim"].get<int>()
    << "D): certified by the exact pipeline in " << buf << "\n";
  if (p["identically_zero"].get<bool>()) {
    o << "  projection: the discriminant vanishes identically (never separate)\n";
  } else {
    int roots = 0;
    for (const auto& n : cert["timeline"]) roots += n.contains("root_of_factor") && !n["root_of_factor"].is_null();
    o << "  projection: " << p["name"].get<std::string>() << " of degree " << p["degree"].get<int>() << ", " << roots
      << " root(s) in [0, 1], each in a bracket proved by Descartes' rule\n";
  }
  o << "  collides: " << (a["collides"].get<bool>() ? "yes" : "no") << "\n";
  for (const auto& iv : a["intervals"])
    o << "  collision interval: [" << instant_text(iv[0]) << ", " << instant_text(iv[1]) << "]"
      << (iv[0] == iv[1] ? "  (isolated touch)" : "") << "\n";
  if (!a["first_contact"].is_null()) o << "  first contact: " << instant_text(a["first_contact"]) << "\n";
  if (a.contains("contact_intervals"))
    for (const auto& iv : a["contact_intervals"])
      o << "  continuous touching (contact interval): [" << instant_text(iv[0]) << ", " << instant_text(iv[1]) << "]\n";
  if (a["contacts"].empty()) o << "  external contacts: none\n";
  for (const auto& c : a["contacts"]) o << "  external contact: " << instant_text(c) << "\n";
  return o.str();
}

void add_certify_options(CLI::App* s, CertifyArgs& args) {
  s->add_option("SCENE", args.scene, "Scene file (format ellipse-ccd-scene/1); - reads standard input")->required();
  s->add_option(
      "--out", args.out,
      "Where to write the certificate (default: SCENE's file name with .cert.json, in the current folder): a new name, "
      "or with --force an existing regular file that is not the scene (a directory, device, FIFO, socket or symbolic "
      "link: exit 2)");
  s->add_flag("--force", args.force, "Replace an existing certificate file");
  s->add_option("--mpfr-bits", args.mpfr_bits, "MPFR precisions of the floating pipelines judged")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(53, 65536));
  s->add_option("--tol", args.tol, "Tolerance on instants for the verdicts (an interval end further off is reported)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  s->add_option("--arith", args.arith,
                "exact: the exact pipeline's certificate; certified: 3D scenes try the interval Bezier proof first "
                "(eccd-bezier-certificate/2) and fall back to the exact certificate; 2D and independent scenes: the "
                "certificate --arith exact writes")
      ->capture_default_str()
      ->check(CLI::IsMember({"exact", "certified"}));
  s->add_flag("--no-floating", args.no_floating, "Certify only; do not run the floating pipelines");
  s->add_flag("--json", args.json,
              "Print one JSON object (certified answer, verdicts, certificate path) instead of text");
}

// The floating pipelines judged against the certificate's answer (none for
// independent scenes: the harness pipelines are shared-parameter methods).
std::vector<Verdict> floating_verdicts(const CertifyArgs& args, const Scene& scene, nlohmann::json& cert) {
  std::vector<Verdict> verdicts;
  if (!args.no_floating &&
      !scene.independent) {  // independent scenes: the harness pipelines are shared-parameter methods
    nlohmann::json plain = cert["answer"];
    plain.erase("undecided");  // a cycloidal certificate lists its undecided stretches
                               // (certificate/write/cycloidal_certificate.hpp)
    if (plain.contains("collides") && plain["collides"].is_null())
      plain["collides"] = false;  // unknown: no collision proved, some stretch undecided
    Answer certified = answer_from_json(plain, "the certificate", "/answer");
    if (cert["answer"].contains("undecided"))
      for (const auto& u : cert["answer"]["undecided"])
        certified.undecided.push_back(instant_from_json(u, "the certificate", "/answer/undecided"));
    HarnessOptions ho;
    ho.mpfr_bits = args.mpfr_bits;
    for (const auto& p :
         motion_family_scene(scene) ? motion_family_pipelines(scene, ho) : harness_pipelines(scene.dim, ho)) {
      if (!p.opt.arith.floating()) continue;  // double and MPFR only: not exact, nor the peers certified and fcl/
      if (!quiet()) std::cerr << "certify: " << p.label << " ...\n";
      try {
        const Solution got = solve(scene, p.opt);
        verdicts.push_back(judge(p.label, got.answer, certified, args.tol, got.time_ms));
      } catch (const std::exception& e) {
        verdicts.push_back(failed_verdict(p.label, e.what()));
      }
      verdicts.back().guard = p.guard;
    }
  }
  return verdicts;
}

int print_certify_json(const Scene& scene, const fs::path& out, nlohmann::json& cert, const nlohmann::json& vj,
                       const std::string& route, const std::string& route_why) {
  nlohmann::json j = {
      {"scene", scene.path},
      {"certificate", out.string()},
      {"answer", cert["answer"]},
      {"verdicts", vj},
      {"projection", cert.contains("projection") ? cert["projection"]["name"]
                                                 : nlohmann::json(scene.independent   ? "independent-krawczyk"
                                                                  : route == "bezier" ? "bezier-krawczyk"
                                                                                      : "cycloidal-delta")},
      {"certify_seconds", cert["seconds"]},
      {"complete", cert.value("complete", true)},
      {"route", route}};
  if (!route_why.empty()) j["route_reason"] = route_why;
  stamp_format(j, "eccd-certify/1");
  std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

}  // namespace

Command add_certify_command(CLI::App& app) {
  auto args = std::make_shared<CertifyArgs>();
  Command c;
  c.sub = app.add_subcommand(
      "certify",
      "Certify one scene: the exact answer (collision intervals, first contact, external contacts, each "
      "instant a proved rational bracket), a verdict for each double and MPFR pipeline (as published and guarded) "
      "against it, and a "
      "certificate that `eccd check-certificate` re-checks without the solver. A cycloidal scene (not "
      "rational) is certified in MPFI instead (format eccd-cycloidal-certificate/2): proved root brackets "
      "of Delta, and each stretch it cannot prove stated as a touch or near miss within epsilon. An independent "
      "scene (2D or 3D) gets eccd-independent-certificate/3: its s- and t-intervals with the strip and Krawczyk "
      "proofs about the exact F(u, s, t); exit 4 if the proof leaves a range undecided. --arith certified: a 3D scene "
      "with "
      "shared parameters gets eccd-bezier-certificate/2 (the interval Bezier proof's pieces and Krawczyk ends) "
      "when that proof decides it, else the exact certificate; 2D scenes (and independent ones) get the "
      "certificate they get with --arith exact; the route taken is printed (JSON key \"route\").");
  auto* s = c.sub;
  add_certify_options(s, *args);
  c.run = [args]() {
    SceneBytes sb = read_scene_once(args->scene);
    const Scene& scene = sb.scene;
    const nlohmann::json& doc = sb.doc;
    if (args->out.empty() && args->scene == "-")
      throw std::invalid_argument(
          "certify -: name the certificate file with --out (the scene comes from standard input)");
    fs::path out =
        args->out.empty() ? fs::path(fs::path(args->scene).stem().string() + ".cert.json") : fs::path(args->out);
    check_output_file(args->out.empty() ? "" : "--out", out, args->force, {args->scene});  // before any work
    const std::string label = scene.path;
    // Say which prover runs: a cycloidal scene has no exact pipeline (MPFI enclosures prove it), an
    // independent one is proved by interval subdivision and Krawczyk's test.
    if (!quiet())
      std::cerr << (args->arith == "certified" ? "certify: certified route and certificate ...\n"
                    : cycloidal_certificate_scene(scene)
                        ? "certify: MPFI proof of the cycloidal scene and certificate ...\n"
                    : scene.independent ? "certify: interval proofs of the independent motions and certificate ...\n"
                                        : "certify: exact pipeline and certificate ...\n");
    nlohmann::json cert;
    std::string route = "exact", route_why;
    try {
      if (args->arith == "certified")
        cert = make_certified_mode_certificate(scene, doc, route, route_why);
      else
        cert = nlohmann::json::parse(certify(scene).text);
      if (args->arith != "certified")
        route = cycloidal_certificate_scene(scene) ? "cycloidal" : scene.independent ? "independent" : "exact";
    } catch (const CertificationError& e) {
      throw ExitError(4, "certify: " + label + ": " + e.what());
    } catch (const std::invalid_argument& e) {  // a scene the exact pipeline refuses (cycloidal motion)
      throw ExitError(3, "certify: " + label + ": " + cli_message(e));
    }
    // The writer's output must pass the checker before anyone sees it.
    if (!quiet() && route != "bezier") std::cerr << "certify: re-checking the certificate with the checker ...\n";
    // (a Bézier certificate has just passed this very checker inside its writer:
    // certificate/write/bezier_certificate.cpp)
    CertificateCheck chk;
    if (route == "bezier")
      chk.valid = true;
    else
      chk = check_certificate(scene, doc, cert);
    if (!chk.valid)
      throw std::logic_error("the certificate fails its own check (" + chk.failed_claim + ": " + chk.reason + ")");

    const std::vector<Verdict> verdicts = floating_verdicts(*args, scene, cert);
    nlohmann::json vj = nlohmann::json::array();
    for (const auto& v : verdicts) vj.push_back(v.to_json());
    cert["floating_verdicts"] = {{"tolerance", args->tol},
                                 {"note", "informational: not part of what check-certificate proves"},
                                 {"pipelines", vj}};
    write_text_atomically(out, cert.dump(1) + "\n");

    if (args->json) return print_certify_json(scene, out, cert, vj, route, route_why);
    std::cout << certified_text(cert);
    if (args->arith == "certified")
      std::cout << "route: " << route << (route_why.empty() ? "" : " (" + route_why + ")") << "\n";
    if (!verdicts.empty()) {
      char tol[32];
      std::snprintf(tol, sizeof tol, "%g", args->tol);
      std::cout << "floating pipelines against the certified answer (tolerance " << tol << "):\n";
      std::size_t w = 0;
      for (const auto& v : verdicts) w = std::max(w, v.pipeline.size());
      for (const auto& v : verdicts) {
        char ms[32];
        std::snprintf(ms, sizeof ms, "%9.2f ms", v.time_ms);
        std::cout << "  " << v.pipeline << std::string(w - v.pipeline.size() + 2, ' ') << ms << "  " << v.text()
                  << "\n";
      }
    }
    std::cout << "certificate: " << out.string() << " (passes eccd check-certificate " << args->scene << " "
              << out.string() << ")\n";
    return 0;
  };
  return c;
}

Command add_check_certificate_command(CLI::App& app) {
  struct Args {
    std::string scene, cert;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  Command c;
  c.sub = app.add_subcommand(
      "check-certificate",
      "Re-check a certificate written by `eccd certify` against its scene, without the solver: f and the "
      "projection recomputed exactly, one root per bracket and none elsewhere (Descartes' rule), each "
      "cell's status by the exact static test, each instant's evidence, and the answer (a cycloidal scene: "
      "the same claims proved by MPFI enclosures of Delta and Delta'; an independent scene: every strip's "
      "boxes, every end's Krawczyk chain and exclusion, the coverage of [0, 1]; a Bezier certificate from --arith "
      "certified: every "
      "piece's boxes, every end's faces, Krawczyk chain and exclusion, the coverage of [0, 1], the answer). Exit 0 if "
      "every "
      "claim holds, 1 naming the first claim that fails, 2 for an unreadable file.");
  c.sub->add_option("SCENE", args->scene, "Scene file the certificate is about; - reads standard input")->required();
  c.sub
      ->add_option("CERT", args->cert,
                   "Certificate (JSON: eccd-certificate/2, or the cycloidal, independent or Bezier format; the checker "
                   "follows its \"format\")")
      ->required();
  c.sub->add_flag("--json", args->json, "Print one JSON object {valid, checked, failed_claim, reason}");
  c.run = [args]() {
    // Each file read once; a directory or unreadable file is exit 2 with its path (SceneError).
    SceneBytes sb = read_scene_once(args->scene);
    const std::string cert_text = read_file_bytes(args->cert);
    CertificateCheck r;
    try {
      r = check_certificate_text(sb.scene, sb.doc, cert_text, args->cert);
    } catch (const std::invalid_argument& e) {  // a scene the exact algebra refuses (cycloidal motion)
      throw std::invalid_argument(args->scene + ": " + cli_message(e));
    }
    if (args->json) {
      nlohmann::json j = {{"valid", r.valid}, {"checked", r.checked}};
      j["failed_claim"] = r.valid ? nlohmann::json(nullptr) : nlohmann::json(r.failed_claim);
      j["reason"] = r.valid ? nlohmann::json(nullptr) : nlohmann::json(r.reason);
      stamp_format(j, "eccd-certificate-check/1");
      std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else {
      for (const auto& line : r.checked) std::cout << "  ok  " << line << "\n";
      if (r.valid)
        std::cout << "VALID: every claim of " << args->cert << " holds for " << args->scene << "\n";
      else
        std::cout << "REJECTED: " << r.failed_claim << ": " << r.reason << "\n";
    }
    return r.valid ? 0 : 1;
  };
  return c;
}

}  // namespace eccd
