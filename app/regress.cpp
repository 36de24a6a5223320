// `eccd regress [DIR]`: every scene under DIR with a stored answer is
// recomputed exactly and compared with it (compare/regress.hpp); with
// --floating, every floating pipeline is also judged against the stored
// answers (compare/verdict.hpp) and tabulated.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/scene_files.hpp"
#include "api/solve.hpp"
#include "io/solution_json.hpp"
#include "compare/harness.hpp"
#include "compare/regress.hpp"
#include "compare/verdict.hpp"
#include "kernel/budget.hpp"
#include "kernel/cycloidal_motion.hpp"
#include "certificate/write/bezier_certificate.hpp"
#include "certificate/write/exact_certificate.hpp"
#include "certificate/check_certificate.hpp"
#include "io/scene_reader.hpp"

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

namespace fs = std::filesystem;

namespace eccd {

namespace {

struct RegressArgs {
  std::string dir = "cases";
  bool floating = false, json = false, certify = false;
  std::string arith = "exact";
  std::string keep_certificates;  // --certify: also write the certificates into this folder
  std::vector<int> mpfr_bits{128};
  double tol = 1e-6;
};

std::string answer_summary(const Answer& a) {
  std::string s = a.collides ? "collides" : "free";
  if (a.independent)  // independent motions: s- and t-intervals
    return s + ", " + std::to_string(a.s_intervals.size()) + " s-interval(s), " + std::to_string(a.t_intervals.size()) +
           " t-interval(s)";
  if (a.collides) s += ", " + std::to_string(a.intervals.size()) + " interval(s)";
  s += ", " + std::to_string(a.contacts.size()) + " contact(s)";
  return s;
}

// --certify: what writing and checking the certificates of one kind cost.
struct CertificateCost {
  int count = 0;
  double prove_s = 0, check_s = 0, worst_ratio = 0;
};
// The kind of a certificate: its format, and for eccd-certificate/2 the dimension.
std::string certificate_kind(const nlohmann::json& cert, int dim) {
  std::string f = cert.is_object() && cert.contains("format") && cert["format"].is_string()
                      ? cert["format"].get<std::string>()
                      : "unknown";
  if (f == "eccd-certificate/2") f += dim == 2 ? " 2D" : " 3D";
  return f;
}

struct PipelineTally {
  int scenes = 0, agree = 0, wrong_collides = 0, missed = 0, spurious = 0, endpoints_off = 0, undecided = 0, errors = 0;
  double max_err = 0;
  std::vector<double> ms;
};

// What regress counts over the scenes, and the rows it reports.
struct RegressTotals {
  int agree = 0, differ = 0, failed = 0, skipped = 0, escalated = 0;
  std::map<std::string, int> decided_in;        // certified mode: scenes per deciding rung
  std::map<std::string, long> local_decisions;  // certified mode: decisions made locally, by kind (summed over scenes)
  int local_scenes = 0;                         // certified mode: scenes decided with at least one local decision
  int exact_only = 0;  // certified mode: scenes run exactly (independent motions), in decided_in too
  std::map<std::string, CertificateCost> certificate_cost;  // --certify: proving and checking time per kind
  nlohmann::json kept = nlohmann::json::array();            // --keep-certificates: the index
  nlohmann::json rows = nlohmann::json::array();
  std::vector<std::string> pipeline_order;
  std::map<std::string, PipelineTally> tally;
};

void add_regress_options(CLI::App* s, RegressArgs& args) {
  s->add_option("DIR", args.dir, "Folder searched recursively for scene files (*.json)")->capture_default_str();
  s->add_flag("--floating", args.floating,
              "Also run every double and MPFR pipeline, as published (labels .../published) and guarded, and tabulate "
              "how each fares against the stored answers");
  s->add_option(
       "--arith", args.arith,
       "Certified arithmetic that recomputes the answers: exact, or certified (intervals of doubles, escalating to "
       "MPFI intervals of 256 bits, then to exact; certified:B1,B2,... or certified:none choose the MPFI rungs; the "
       "summary says where each scene was decided)")
      ->capture_default_str()
      ->check([](const std::string& a) -> std::string {
        if (a != "exact" && a.rfind("certified", 0) != 0) return "expected exact or certified[:BITS,...]";
        try {
          parse_arithmetic(a);
        } catch (const std::exception& e) {
          return e.what();
        }
        return "";
      });
  s->add_flag(
      "--certify", args.certify,
      "Also write each scene's certificate (in memory) and re-check it with the certificate checker; a certificate "
      "that cannot be made or fails its check fails the scene; with --arith certified a 3D scene's certificate is "
      "the interval Bezier proof's (eccd-bezier-certificate/2) when that proof decides it, else the exact one "
      "(the route is reported per scene)");
  s->add_option(
      "--keep-certificates", args.keep_certificates,
      "With --certify: also write each certificate into this folder (created if missing; file name: the scene's path "
      "under DIR with / replaced by __, then .cert.json) and an index.json listing scene, certificate and format, so "
      "that other checkers (eccd-check, tools/check_certificate.py --index) can re-check them");
  s->add_option("--mpfr-bits", args.mpfr_bits, "MPFR precisions for --floating")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(53, 65536));
  s->add_option("--tol", args.tol, "--floating: tolerance on instants (an interval end further off counts as off)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  s->add_flag("--json", args.json,
              "Print one JSON object (per-scene results, summary, floating table) instead of text");
}

// The scene files under dir, sorted: each scene's bytes, read once, and the
// files that may be scenes but cannot be read as such (with why).
struct SceneFiles {
  std::vector<fs::path> files;
  std::map<fs::path, std::string> broken;
  std::map<fs::path, std::string> texts;
};

SceneFiles find_scene_files(const std::string& dir) {
  SceneFiles out;
  std::vector<fs::path>& files = out.files;
  std::map<fs::path, std::string>& broken = out.broken;
  std::map<fs::path, std::string>& texts = out.texts;
  // The walk never stops at one entry: a *.json that is a symbolic link loop,
  // a dangling link or not a regular file (a FIFO, a device) is a scene that
  // fails, with what it is; a name that looks like JSON in another case
  // (*.JSON) is skipped with a warning; folder links are not followed.
  std::vector<std::string> skipped_names;
  {
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
    if (ec) throw std::invalid_argument(dir + ": cannot read the folder: " + ec.message());
    for (; it != end; it.increment(ec)) {
      const fs::path p = it->path();
      std::string ext = p.extension().string();
      std::string lower = ext;
      for (auto& ch : lower) ch = char(std::tolower(static_cast<unsigned char>(ch)));
      std::error_code sec;
      const fs::file_status ls = it->symlink_status(sec);
      if (lower != ".json" || fs::is_directory(ls)) continue;
      if (ext != ".json") {
        skipped_names.push_back(p.string());
        continue;
      }
      const fs::file_status st = fs::status(p, sec);
      if (sec || !fs::is_regular_file(st)) {
        std::string why;
        if (sec.value() == ELOOP)
          why = "a symbolic link loop: cannot read it";
        else if (fs::is_symlink(ls) && !fs::exists(st))
          why = "a dangling symbolic link (its target does not exist)";
        else if (sec)
          why = "cannot read it: " + sec.message();
        else if (fs::is_directory(st))
          continue;  // a link to a folder named *.json: not followed
        else
          why = "not a regular file (a FIFO, device or socket): not read";
        broken[p] = why;
        files.push_back(p);
        continue;
      }
      std::string why, text;
      FileKind k = classify_file(p, text, why);
      if (k == FileKind::NotScene) continue;
      if (k == FileKind::Broken)
        broken[p] = why;
      else
        texts[p] = std::move(text);
      files.push_back(p);
    }
    if (ec)
      warn("regress",
           dir + ": the folder walk stopped early: " + ec.message() + " (the scenes found so far are checked)");
  }
  std::sort(skipped_names.begin(), skipped_names.end());
  for (const auto& n : skipped_names)
    warn("regress", n + ": skipped: only files named *.json (lower case) are read; rename it to check it");
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw std::invalid_argument(dir + ": no scene found (no *.json file with \"format\": \"ellipse-ccd-scene/1\")");
  return out;
}

// Certified mode: the ladder's keys into the row and the totals; returns how
// the scene was decided, for its line.
std::string ladder_note(const Solution& sol, bool certified_mode, nlohmann::json& row, RegressTotals& tot) {
  std::string how;
  if (sol.arith.kind == Arithmetic::Certified) {
    const nlohmann::json r = solution_to_json(sol);  // the ladder's keys as `eccd solve --json` writes them
    for (const char* k : {"escalated", "decided_in", "escalations"}) row[k] = r[k];
    if (r.contains("local_decisions")) row["local_decisions"] = r["local_decisions"];
    for (const auto& [kind, n] : sol.local_decisions) tot.local_decisions[kind] += n;
    if (!sol.local_decisions.empty()) ++tot.local_scenes;
    ++tot.decided_in[sol.decided_in];
    if (r["escalated"].get<bool>()) {
      ++tot.escalated;
      row["escalation_reason"] = r["escalation_reason"];
      how = "  (decided in " + sol.decided_in + "; escalated: " + r["escalation_reason"].get<std::string>() + ")";
    } else {
      how =
          sol.decided_in == "interval" ? "  (decided in interval arithmetic)" : "  (decided in " + sol.decided_in + ")";
    }
  }
  if (certified_mode && sol.arith.kind != Arithmetic::Certified) {  // an independent scene, run exactly
    ++tot.decided_in["exact (independent motions)"];
    ++tot.exact_only;
  }
  return how;
}

// --keep-certificates: the certificate into the folder, and into the index.
void keep_certificate(const RegressArgs& args, const fs::path& f, const std::string& name, const nlohmann::json& cert,
                      RegressTotals& tot) {
  std::string file;
  for (char ch : name) file += ch == '/' || ch == '\\' ? std::string("__") : std::string(1, ch);
  file = file.substr(0, file.size() - (file.size() > 5 && file.compare(file.size() - 5, 5, ".json") == 0 ? 5 : 0)) +
         ".cert.json";
  fs::create_directories(args.keep_certificates);
  write_text_atomically(fs::path(args.keep_certificates) / file, cert.dump(1) + "\n");
  tot.kept.push_back(
      {{"scene", fs::absolute(f).string()}, {"certificate", file}, {"format", cert.value("format", "")}});
}

// --certify: the scene's certificate, written and checked (also for a
// cycloidal scene, certificate/write/cycloidal_certificate.hpp, and an
// independent one, certificate/write/independent_certificate.hpp); a
// certificate that fails its check, or proves another answer than the stored
// one, fails the scene.
void certify_scene(const RegressArgs& args, const fs::path& f, const std::string& name, const std::string& text,
                   const Scene& sc, const std::vector<std::string>& diff, nlohmann::json& row, std::string& line,
                   RegressTotals& tot) {
  const bool certified_mode = args.arith != "exact";
  nlohmann::json doc = nlohmann::json::parse(text);
  auto c0 = std::chrono::steady_clock::now();
  nlohmann::json cert;
  std::string route, route_why;
  try {
    // certified mode: the certified route's certificate (certificate/write/bezier_certificate.hpp), else the
    // exact one
    cert = certified_mode ? make_certified_mode_certificate(sc, doc, route, route_why) : make_certificate(sc, doc);
  } catch (const CertificationError& e) {  // the proof left a range undecided: nothing certified, and said so
    if (!sc.independent) throw;
    cert = nullptr;
    row["certificate"] = {{"valid", nullptr}, {"reason", e.what()}};
    line += std::string(", no certificate (") + e.what() + ")";
  }
  if (!cert.is_null() && !args.keep_certificates.empty()) keep_certificate(args, f, name, cert, tot);
  if (!cert.is_null()) {
    const auto c1 = std::chrono::steady_clock::now();
    CertificateCheck chk = check_certificate(sc, doc, cert);
    const auto c2 = std::chrono::steady_clock::now();
    double cs = std::chrono::duration<double>(c2 - c0).count();
    const double prove_s = std::chrono::duration<double>(c1 - c0).count(),
                 check_s = std::chrono::duration<double>(c2 - c1).count();
    CertificateCost& cost = tot.certificate_cost[certificate_kind(cert, sc.dim)];
    ++cost.count;
    cost.prove_s += prove_s;
    cost.check_s += check_s;
    cost.worst_ratio = std::max(cost.worst_ratio, check_s / std::max(prove_s, 1e-9));
    row["certificate"] = {
        {"valid", chk.valid}, {"seconds", cs}, {"prove_seconds", prove_s}, {"check_seconds", check_s}};
    if (certified_mode) row["certificate"]["route"] = route;
    char buf[80];
    std::snprintf(buf, sizeof buf, ", certificate%s%s checked (%.2f s)", route.empty() ? "" : " ", route.c_str(), cs);
    std::vector<std::string> cdiff;  // the certified route's certificate proves an answer: it must be the stored one
    if (chk.valid && route == "bezier")
      cdiff = regress_differences(*sc.answer, answer_from_json(cert["answer"], name, "/answer"));
    if (!cdiff.empty()) {
      row["certificate"]["differences"] = cdiff;
      if (diff.empty()) {
        --tot.agree;
        ++tot.differ;
        row["result"] = "differs";
      }
      line = "FAIL  " + name + ": its Bezier certificate proves an answer other than the stored one:";
      for (const auto& d : cdiff) line += "\n        " + d;
    } else if (chk.valid) {
      line += buf;
    } else {
      row["certificate"]["failed_claim"] = chk.failed_claim;
      row["certificate"]["reason"] = chk.reason;
      if (diff.empty()) {
        --tot.agree;
        ++tot.differ;
        row["result"] = "differs";
      }
      line = "FAIL  " + name + ": its certificate fails the checker: " + chk.failed_claim + ": " + chk.reason;
    }
  }
}

// --floating: every double and MPFR pipeline judged against the stored answer.
void judge_floating(const RegressArgs& args, const Scene& sc, nlohmann::json& row, RegressTotals& tot) {
  if (args.floating && sc.independent) {  // the harness's pipelines are shared-parameter methods
    row["floating"] = "skipped: independent motions (eccd solve --arith double|mpfr:BITS answers them)";
  } else if (args.floating) {
    nlohmann::json vs = nlohmann::json::array();
    HarnessOptions ho;
    ho.mpfr_bits = args.mpfr_bits;
    for (const auto& p : harness_pipelines(sc.dim, ho)) {
      if (!p.opt.arith.floating()) continue;  // double and MPFR only: not exact, nor the peers certified and fcl/
      Verdict v;
      try {
        const Solution g = solve(sc, p.opt);
        v = judge(p.label, g.answer, *sc.answer, args.tol, g.time_ms);
      } catch (const std::exception& e) {
        v = failed_verdict(p.label, e.what());
      }
      v.guard = p.guard;
      if (!tot.tally.count(p.label)) tot.pipeline_order.push_back(p.label);
      PipelineTally& t = tot.tally[p.label];
      ++t.scenes;
      t.agree += v.agrees;
      t.wrong_collides += v.wrong_collides;
      t.missed += v.missed;
      t.spurious += v.spurious;
      t.endpoints_off += v.endpoints_off;
      t.undecided += v.undecided;
      t.errors += !v.error.empty();
      if (v.max_endpoint_error) t.max_err = std::max(t.max_err, *v.max_endpoint_error);
      t.ms.push_back(v.time_ms);
      vs.push_back(v.to_json());
    }
    row["floating"] = vs;
  }
}

// One scene: recomputed and compared with its stored answer, then certified
// and judged as asked; its row and its line. false: a scene without a stored
// answer, skipped (its row already added and its line printed).
bool regress_scene(const RegressArgs& args, const SceneFiles& sf, const fs::path& f, const std::string& name,
                   nlohmann::json& row, std::string& line, RegressTotals& tot) {
  if (auto b = sf.broken.find(f); b != sf.broken.end()) throw SceneError(f.string() + ": " + b->second);
  ScopedDeadline deadline(run_budget().time_limit_s);
  Scene sc = parse_scene(sf.texts.at(f), f.string());
  if (!sc.answer) {
    ++tot.skipped;
    row["result"] = "skipped";
    row["reason"] = "no stored answer";
    if (!args.json) std::cout << "skip  " << name << ": no stored answer\n" << std::flush;
    tot.rows.push_back(row);
    return false;
  }
  SolveOptions opt;
  opt.arith = parse_arithmetic(args.arith);
  // A cycloidal scene has no exact answer (not rational): its stored
  // answer is the certified one, and it is recomputed in certified mode.
  if (opt.arith.kind == Arithmetic::Exact && sc.dim == 2 && has_cycloidal_motion(sc)) {
    opt.arith = Arithmetic::certified();
    row["arith"] = "certified";
    row["arith_reason"] = "cycloidal motion: no exact answer, the ground truth is the certified one";
  }
  // independent motions: exact is their certified pipeline (certificate:
  // certificate/write/independent_certificate.hpp)
  if (sc.independent) opt.arith = Arithmetic::exact();
  const Solution sol = solve(sc, opt);
  const std::string how = ladder_note(sol, args.arith != "exact", row, tot);
  const Answer& got = sol.answer;
  std::vector<std::string> diff = regress_differences(*sc.answer, got);
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.0f ms", sol.time_ms);
  row["time_ms"] = sol.time_ms;
  if (diff.empty()) {
    ++tot.agree;
    row["result"] = "ok";
    line = "ok    " + name + "  " + std::to_string(sc.dim) + "D  " + answer_summary(got) + "  " + ms + how;
  } else {
    ++tot.differ;
    row["result"] = "differs";
    row["differences"] = diff;
    line = "FAIL  " + name + ": the stored answer differs from the recomputed " + args.arith + " one:";
    for (const auto& d : diff) line += "\n        " + d;
  }
  if (args.certify) certify_scene(args, f, name, sf.texts.at(f), sc, diff, row, line, tot);
  judge_floating(args, sc, row, tot);
  return true;
}

// --floating: one row per pipeline, in the order they first ran.
nlohmann::json floating_table(RegressTotals& tot) {
  nlohmann::json table = nlohmann::json::array();
  for (const auto& label : tot.pipeline_order) {
    PipelineTally& t = tot.tally[label];
    std::sort(t.ms.begin(), t.ms.end());
    double med = t.ms.empty() ? 0 : t.ms[t.ms.size() / 2];
    table.push_back({{"pipeline", label},
                     {"scenes", t.scenes},
                     {"agree", t.agree},
                     {"wrong_collides", t.wrong_collides},
                     {"missed", t.missed},
                     {"false", t.spurious},
                     {"endpoints_off", t.endpoints_off},
                     {"undecided", t.undecided},
                     {"errors", t.errors},
                     {"max_endpoint_error", t.max_err},
                     {"median_ms", med}});
  }
  return table;
}

int print_json(const RegressArgs& args, const RegressTotals& tot, const nlohmann::json& table, double secs) {
  const bool certified_mode = args.arith != "exact";
  const int bad = tot.differ + tot.failed;
  nlohmann::json j = {{"dir", args.dir},        {"arith", args.arith},  {"scenes", tot.rows},
                      {"agree", tot.agree},     {"differ", tot.differ}, {"errors", tot.failed},
                      {"skipped", tot.skipped}, {"seconds", secs},      {"passed", bad == 0}};
  if (certified_mode) {
    j["escalated"] = tot.escalated;
    j["decided_in"] = tot.decided_in;
    j["local_decisions"] = tot.local_decisions;
    j["local_scenes"] = tot.local_scenes;
  }
  if (args.floating) j["floating"] = {{"tolerance", args.tol}, {"pipelines", table}};
  if (args.certify) {
    nlohmann::json cj = nlohmann::json::array();
    for (const auto& [kind, c] : tot.certificate_cost)
      cj.push_back({{"kind", kind},
                    {"certificates", c.count},
                    {"prove_seconds", c.prove_s},
                    {"check_seconds", c.check_s},
                    {"check_over_prove", c.check_s / std::max(c.prove_s, 1e-9)},
                    {"worst_check_over_prove", c.worst_ratio}});
    j["certificate_cost"] = cj;
  }
  stamp_format(j, "eccd-regress/1");
  std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return bad ? 1 : 0;
}

int print_text(const RegressArgs& args, const RegressTotals& tot, const nlohmann::json& table, double secs) {
  const bool certified_mode = args.arith != "exact";
  const int bad = tot.differ + tot.failed;
  if (args.floating && !table.empty()) {
    std::cout << "\nfloating pipelines against the stored exact answers (tolerance " << args.tol << "):\n";
    std::printf("  %-22s %6s %6s %6s %6s %6s %6s %6s %6s %10s %10s\n", "pipeline", "scenes", "agree", "wrongC",
                "missed", "false", "endOff", "undec", "errors", "max end err", "median ms");
    for (const auto& r : table)
      std::printf("  %-22s %6d %6d %6d %6d %6d %6d %6d %6d %10.2g %10.2f\n", r["pipeline"].get<std::string>().c_str(),
                  r["scenes"].get<int>(), r["agree"].get<int>(), r["wrong_collides"].get<int>(), r["missed"].get<int>(),
                  r["false"].get<int>(), r["endpoints_off"].get<int>(), r["undecided"].get<int>(),
                  r["errors"].get<int>(), r["max_endpoint_error"].get<double>(), r["median_ms"].get<double>());
    std::cout << "  (wrongC: wrong `collides`; missed / false: collision intervals or contacts missed or invented; "
                 "endOff: interval ends off by more than the tolerance)\n";
  }
  if (args.certify && !tot.certificate_cost.empty()) {
    std::printf(
        "\ncertificate cost (checking / proving time, per kind; proving = writing the certificate, its exact or "
        "interval run included):\n");
    int w = 4;  // the kind column as wide as its longest name (eccd-independent-certificate/3 is 30 characters)
    for (const auto& kc : tot.certificate_cost) w = std::max(w, int(kc.first.size()));
    std::printf("  %-*s %6s %11s %11s %12s %12s\n", w, "kind", "certs", "prove s", "check s", "check/prove",
                "worst ratio");
    for (const auto& [kind, c] : tot.certificate_cost)
      std::printf("  %-*s %6d %11.2f %11.2f %12.3f %12.3f\n", w, kind.c_str(), c.count, c.prove_s, c.check_s,
                  c.check_s / std::max(c.prove_s, 1e-9), c.worst_ratio);
  }
  std::printf(
      "\nregress %s: %d scene(s) checked, %d agree, %d differ, %d failed, %d without a stored answer (%.1f s)\n",
      args.dir.c_str(), tot.agree + tot.differ + tot.failed, tot.agree, tot.differ, tot.failed, tot.skipped, secs);
  if (certified_mode) {
    std::printf(
        "certified mode: %d of %d scene(s) decided in intervals of doubles, %d escalated, %d run exactly "
        "(independent motions); decided in:",
        tot.agree + tot.differ - tot.escalated - tot.exact_only, tot.agree + tot.differ, tot.escalated, tot.exact_only);
    for (const auto& [rung, n] : tot.decided_in) std::printf(" %s %d", rung.c_str(), n);
    std::printf("\n");
    if (tot.local_scenes) {
      std::printf("decided with local exact decisions: %d scene(s);", tot.local_scenes);
      for (const auto& [kind, n] : tot.local_decisions) std::printf(" %s %ld", kind.c_str(), n);
      std::printf("\n");
    }
  }
  if (bad) std::printf("REGRESSION: %d scene(s) do not match their stored answers (FAIL lines above)\n", bad);
  return bad ? 1 : 0;
}

}  // namespace

Command add_regress_command(CLI::App& app) {
  auto args = std::make_shared<RegressArgs>();
  Command c;
  c.sub = app.add_subcommand(
      "regress",
      "Recompute every scene under DIR that has a stored answer with the exact pipeline and compare: same "
      "collides, same numbers of intervals and contacts, each recomputed bracket overlapping the stored one. "
      "One line per scene, then a summary; exit 1 if any scene differs or fails (a scene over --time-limit, a file "
      "that "
      "looks like a scene but does not read as one, e.g. a misspelled format, fails); exit 2 if DIR has no scene.");
  auto* s = c.sub;
  add_regress_options(s, *args);
  c.run = [args]() {
    if (!fs::is_directory(args->dir)) throw std::invalid_argument(args->dir + ": not a directory");
    const SceneFiles sf = find_scene_files(args->dir);
    auto t0 = std::chrono::steady_clock::now();
    RegressTotals tot;
    std::size_t done = 0;
    for (const auto& f : sf.files) {
      ++done;
      // lexically: a symbolic link loop or a dangling link is named, not followed
      std::string name = f.lexically_relative(args->dir).string();
      if (name.empty() || name.rfind("..", 0) == 0) name = f.string();
      nlohmann::json row = {{"scene", name}};
      std::string line;
      try {
        if (!regress_scene(*args, sf, f, name, row, line, tot)) continue;
      } catch (const std::exception& e) {  // a bad scene file or a pipeline failure: a failure of this scene
        ++tot.failed;
        row["result"] = "error";
        row["error"] = e.what();
        line = "FAIL  " + name + ": " + e.what();
      }
      tot.rows.push_back(row);
      if (!args->json)
        std::cout << line << "\n" << std::flush;
      else if (!quiet())
        std::fprintf(stderr, "\r[%zu/%zu] %s", done, sf.files.size(), name.c_str());
    }
    if (args->json && !quiet()) std::fprintf(stderr, "\n");
    if (!args->keep_certificates.empty() && args->certify) {
      fs::create_directories(args->keep_certificates);
      write_text_atomically(fs::path(args->keep_certificates) / "index.json",
                            nlohmann::json{{"certificates", tot.kept}}.dump(1) + "\n");
    }
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const nlohmann::json table = floating_table(tot);
    return args->json ? print_json(*args, tot, table, secs) : print_text(*args, tot, table, secs);
  };
  return c;
}

}  // namespace eccd
