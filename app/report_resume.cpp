// `eccd report --resume` (app/report_parts.hpp): the plan file written before
// the first task runs, the checks that an interrupted NAME.partial belongs to
// the run asked for, the lock that keeps two runs out of one folder, and the
// command that resumes.
#include "app/report_parts.hpp"
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/option_names.hpp"
#include "app/scene_files.hpp"
#include "app/time_left.hpp"
#include "compare/csv.hpp"
#include "compare/harness.hpp"
#include "compare/harness_families.hpp"
#include "compare/scene_generator.hpp"
#include "kernel/budget.hpp"
#include "io/scene_reader.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <regex>
#include <thread>

namespace fs = std::filesystem;

namespace eccd::report_detail {

nlohmann::ordered_json report_plan(const ReportArgs& a, const std::vector<Task>& mine, const std::string& shard,
                                   const std::string& started) {
  nlohmann::ordered_json o;
  o["seed"] = a.plan.seed;
  o["dims"] = a.plan.dims;
  o["degrees"] = a.plan.degrees;
  o["families"] = a.plan.families;
  o["motions"] = a.plan.motions;
  o["separations"] = a.plan.d_exponents;
  o["overlap_depths"] = a.plan.depth_exponents;
  o["digits"] = a.plan.digits;
  o["count_per_combination"] = a.plan.count;
  o["mpfr_bits"] = a.harness.mpfr_bits;
  o["inputs"] = a.harness.inputs;
  o["guards"] = a.harness.guards;
  o["budget_seconds"] = a.harness.budget_s;
  o["exact_budget_seconds"] = a.harness.exact_budget_s;
  o["time_limit_seconds"] = run_budget().time_limit_s;
  o["grid"] = a.harness.grid;
  o["map_size"] = a.no_map ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(a.map_size);
  o["cases"] = a.cases;
  o["scenes"] = a.scenes;
  o["shard"] = shard;
  std::vector<std::string> labels;
  for (int dim : {2, 3})
    for (const auto& p : harness_pipelines(dim, a.harness)) labels.push_back(std::to_string(dim) + "D " + p.label);
  o["pipelines"] = labels;
  nlohmann::ordered_json ext = nlohmann::ordered_json::array();
  for (const auto& e : a.harness.externals) ext.push_back(e.name + "=" + e.dir);
  o["externals"] = ext;
  std::uint64_t h = 14695981039346656037ull;
  auto mix = [&h](const std::string& s) {
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xffu) * 1099511628211ull;  // a separator no text byte sequence can fake across fields
  };
  for (const auto& t : mine) {
    mix(t.kind == Task::MapCell ? "map" : "scene");
    mix(t.label);
    mix(t.source);
    mix(t.text);
  }
  for (const auto& e : a.harness.externals) {  // --external: the answer files are part of what the rows say
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(e.dir, ec))
      if (f.path().extension() == ".json") files.push_back(f.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      mix(f.filename().string());
      std::ifstream in(f, std::ios::binary);
      std::stringstream bytes;
      bytes << in.rdbuf();
      mix(bytes.str());
    }
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  nlohmann::ordered_json p;
  stamp_format(p, "eccd-report-plan/1");
  p["revision"] = program_revision();
  p["command"] = command_line();
  p["started"] = started;
  p["options"] = o;
  p["tasks"] = mine.size();
  p["tasks_digest"] = hex;
  return p;
}

// --resume: PARTIAL must be ours, hold a plan file equal to `plan` (the one
// this run would write), and is then reused; throws std::invalid_argument
// (exit 2) with the reason otherwise. Returns the finished tasks.
WorkerFiles check_resume(const fs::path& partial, const nlohmann::ordered_json& plan) {
  const std::string p = partial.string();
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(partial, ec)))
    throw std::invalid_argument("--resume: nothing to resume: " + p +
                                " does not exist (an interrupted eccd report keeps it; "
                                "a finished or never started one has none)");
  if (fs::is_symlink(partial, ec) || !fs::is_directory(partial, ec) || !has_marker(partial, kMarker))
    throw std::invalid_argument("--resume: " + p + " was not written by eccd report (no " + kMarker +
                                " marker): refusing to use it");
  if (!fs::is_regular_file(partial / kPlanFile, ec))
    throw std::invalid_argument(
        "--resume: " + p + " cannot be resumed: it has no " + kPlanFile +
        " (written by --merge or by an eccd without --resume); run without --resume to start afresh");
  nlohmann::ordered_json old;
  try {
    old = parse_json_document(
        read_bounded_file((partial / kPlanFile).string(), kMaxReportFileBytes, "the limit of a report's own file"),
        (partial / kPlanFile).string());
  } catch (const std::exception& e) {
    throw std::invalid_argument("--resume: " + (partial / kPlanFile).string() + ": unreadable (" + e.what() +
                                "); run without --resume to start afresh");
  }
  const std::string again =
      "; resuming would mix two different runs: give the same options, or run without --resume to start afresh";
  if (!old.is_object() || old.value("format", "") != plan["format"])
    throw std::invalid_argument(
        "--resume: " + (partial / kPlanFile).string() + ": not a plan of this eccd (format " +
        (old.is_object() && old.contains("format") ? old["format"].dump() : std::string("missing")) + ")" + again);
  auto shown = [](const nlohmann::ordered_json& j) {
    std::string s = j.dump();
    return s.size() > 120 ? s.substr(0, 120) + "..." : s;
  };
  const auto& oo = old["options"];
  for (const auto& [k, v] : plan["options"].items())
    if (!oo.is_object() || !oo.contains(k) || oo[k] != v)
      throw std::invalid_argument("--resume: " + p + " was started with a different " + k + " (" +
                                  (oo.is_object() && oo.contains(k) ? shown(oo[k]) : std::string("not recorded")) +
                                  "; this run: " + shown(v) + ")" + again);
  if (old["revision"] != plan["revision"])
    throw std::invalid_argument("--resume: " + p + " was started by another build of eccd (git " +
                                shown(old["revision"]) + "; this one: " + shown(plan["revision"]) + ")" + again);
  if (old["tasks"] != plan["tasks"] || old["tasks_digest"] != plan["tasks_digest"])
    throw std::invalid_argument("--resume: " + p + " was started on other scenes (" + shown(old["tasks"]) +
                                " task(s), digest " + shown(old["tasks_digest"]) +
                                "; this run: " + shown(plan["tasks"]) + ", " + shown(plan["tasks_digest"]) +
                                "; did the files under --cases or --scenes change?)" + again);
  return read_worker_files(partial, plan["tasks"].get<long>());
}

void refuse_busy(const fs::path& partial) {
  throw std::invalid_argument(partial.string() + ": in use by an eccd report still running (it holds " + kPlanFile +
                              "); wait for it or stop it first");
}

// The command that resumes this run: the command line, with --name NAME when
// the name was chosen by the run, and --resume.
std::string resume_command(const ReportArgs& a, const std::string& name) {
  std::string c = command_line();
  if (!a.out_given && !a.name_given) c += " --name " + name;
  if (!a.resume) c += " --resume";
  return c;
}

}  // namespace eccd::report_detail
