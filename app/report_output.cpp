// `eccd report`'s output (app/report_parts.hpp): the output folder (never
// replacing what is not ours), results.csv's fixed order, meta.json's parts,
// the scene files behind the rows, and the Python steps that write report.md,
// the figures and report.html.
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

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
std::string read_command_output(const std::string& cmd) {
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[256];
    while (fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}
std::string command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(in)), {}), out;
  std::size_t start = 0;
  while (start < all.size()) {  // arguments are NUL-terminated; quote the empty or spaced ones
    std::size_t end = all.find('\0', start);
    if (end == std::string::npos) end = all.size();
    std::string arg = all.substr(start, end - start);
    if (!out.empty()) out += ' ';
    out += (arg.empty() || arg.find_first_of(" '\"") != std::string::npos) ? shell_quote(arg) : arg;
    start = end + 1;
  }
  return out;
}
nlohmann::json machine_info() {
  nlohmann::json m;
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      m["cpu"] = line.substr(line.find(':') + 2);
      break;
    }
  if (!m.contains("cpu")) m["cpu"] = "unknown";
  m["cores"] = std::thread::hardware_concurrency();
  m["os"] = read_command_output("uname -srm 2>/dev/null");
  return m;
}
std::string now_iso() {
  std::time_t t = std::time(nullptr);
  char b[64];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return b;
}
void write_file(const fs::path& p, const std::string& text) {
  std::ofstream o(p);
  o << text;
  if (!o) throw OutputError(p.string() + ": cannot write: " + errno_text(errno));
}
std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> v;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) v.push_back(cur);
  if (!s.empty() && s.back() == sep) v.push_back("");
  return v;
}
std::string fmt_duration(double s) {
  char b[32];
  if (s >= 3600)
    std::snprintf(b, sizeof b, "%dh%02dm", int(s / 3600), int(std::fmod(s, 3600) / 60));
  else if (s >= 60)
    std::snprintf(b, sizeof b, "%dm%02ds", int(s / 60), int(std::fmod(s, 60)));
  else
    std::snprintf(b, sizeof b, "%.0fs", s);
  return b;
}

// Sort key of a results.csv line: the scene's place in the plan (rows of one
// scene keep their pipeline order under a stable sort).
std::vector<std::string> scene_key(const std::string& line) {
  auto f = csv_split(line, "results.csv row");
  static const std::map<std::string, std::string> fam{
      {"colliding", "0"}, {"free", "1"},     {"touch", "2"}, {"near-miss", "3"},  {"overlap", "4"},     {"graze", "5"},
      {"decimal", "6"},   {"keyframe", "7"}, {"case", "8"},  {"cycloidal", "9a"}, {"independent", "9b"}};
  auto pad = [](const std::string& x) { return std::string(8 - std::min<std::size_t>(8, x.size()), '0') + x; };
  std::string d = f.size() > 6 && !f[6].empty() ? pad(f[6].substr(3)) : "";
  std::string digits = f.size() > 27 ? pad(f[27]) : "";  // results_csv_header(): column 28 is digits
  return {f[1], f[2], pad(f[3]), fam.count(f[4]) ? fam.at(f[4]) : f[4], f[5], d, digits, f[0]};
}
void sort_results(std::vector<std::string>& lines) {
  std::stable_sort(lines.begin(), lines.end(),
                   [](const std::string& a, const std::string& b) { return scene_key(a) < scene_key(b); });
}
void sort_map(std::vector<std::string>& lines, const std::vector<std::string>& order) {
  auto key = [&](const std::string& l) {
    auto f = csv_split(l, "failure_map.csv row");
    long p = std::find(order.begin(), order.end(), f[0]) - order.begin();
    return std::make_tuple(p, std::stoi(f[1]), std::stoi(f[2]));
  };
  std::stable_sort(lines.begin(), lines.end(),
                   [&](const std::string& a, const std::string& b) { return key(a) < key(b); });
}

// The scene files behind the rows, for report.html's links (compare/plots/report_html.py):
// scenes/NAME.json for each generated scene and the failure map's scene (they exist nowhere
// else), and scenes/index.json, each scene's name -> its file relative to the report folder
// `out` (a scene file given by --cases or --scenes links to that file: the link holds while the
// report stays where it was written, beside them).
void write_scene_files(const fs::path& partial, const fs::path& out, const std::vector<Task>& tasks,
                       const FailureMap* map) {
  const fs::path dir = partial / "scenes";
  fs::create_directories(dir);
  const fs::path out_abs = fs::absolute(out).lexically_normal();
  nlohmann::ordered_json index = nlohmann::ordered_json::object();
  auto own_file = [&](const std::string& name, const std::string& text) {
    write_file(dir / (name + ".json"), text.back() == '\n' ? text : text + "\n");
    index[name] = "scenes/" + name + ".json";
  };
  for (const auto& t : tasks) {
    if (t.kind != Task::SceneTask) continue;
    std::error_code ec;
    if (fs::is_regular_file(t.label, ec)) {
      const auto doc = nlohmann::json::parse(t.text, nullptr, false);
      const std::string name = doc.is_object() && doc.contains("name") && doc["name"].is_string()
                                   ? doc["name"].get<std::string>()
                                   : fs::path(t.label).stem().string();
      index[name] = fs::absolute(t.label).lexically_normal().lexically_relative(out_abs).generic_string();
    } else if (t.label.find('/') == std::string::npos && t.label.find("..") == std::string::npos) {
      own_file(t.label, nlohmann::ordered_json::parse(t.text).dump(1));  // the scene format's key order, as written
    }
  }
  if (map && !index.contains(map->scene)) own_file(map->scene, map->doc.dump(1));
  nlohmann::ordered_json j;
  stamp_format(j, "eccd-report-scenes/1");
  j["scenes"] = index;
  write_file(dir / "index.json", j.dump(1) + "\n");
}

// A part's scenes/index.json (eccd-report-scenes/1), or an empty object when the part has none (a part
// written before shards wrote their scenes: the merged report then links fewer scenes, nothing fails).
nlohmann::ordered_json read_scene_index(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return nlohmann::ordered_json::object();
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(text.str(), nullptr, false);
  if (!j.is_object() || j.value("format", "") != "eccd-report-scenes/1" || !j.contains("scenes") ||
      !j["scenes"].is_object())
    throw std::invalid_argument(
        file.string() + ": not an eccd-report-scenes/1 index (expected an object with \"format\" and \"scenes\")");
  for (const auto& [name, rel] : j["scenes"].items())
    if (!rel.is_string()) throw std::invalid_argument(file.string() + ": /scenes/" + name + ": expected a file name");
  return j["scenes"];
}

// --merge: the parts' scene files into the merged report's scenes/ and one index. `parts`: each part's
// folder and its index (read_scene_index, read while the parts are checked, before anything is written).
// A part's own file (scenes/NAME.json) is copied; a link to a file given by --cases or --scenes is made
// relative to the merged report `out` (the part's link was relative to the part).
void merge_scene_files(const fs::path& partial, const fs::path& out,
                       const std::vector<std::pair<fs::path, nlohmann::ordered_json>>& parts) {
  const fs::path dir = partial / "scenes";
  fs::create_directories(dir);
  const fs::path out_abs = fs::absolute(out).lexically_normal();
  nlohmann::ordered_json index = nlohmann::ordered_json::object();
  for (const auto& [d, scenes] : parts) {
    for (const auto& [name, rel_json] : scenes.items()) {
      if (index.contains(name)) continue;  // the map's scene is in every part
      const std::string rel = rel_json.get<std::string>();
      const fs::path own = fs::path(rel).lexically_normal();
      std::error_code ec;
      if (own.parent_path() == "scenes" && own.extension() == ".json") {
        if (!fs::is_regular_file(d / own, ec)) {
          warn("report",
               (d / own).string() +
                   ": missing (listed in the part's scenes/index.json): the merged report does not link scene " + name);
          continue;
        }
        fs::copy_file(d / own, partial / own, fs::copy_options::overwrite_existing);
        index[name] = own.generic_string();
      } else {
        index[name] = fs::absolute(d / rel).lexically_normal().lexically_relative(out_abs).generic_string();
      }
    }
  }
  nlohmann::ordered_json j;
  stamp_format(j, "eccd-report-scenes/1");
  j["scenes"] = index;
  write_file(dir / "index.json", j.dump(1) + "\n");
}

// The failure map's scene as a picture (as `eccd plot` draws it: the two ellipses along the motion and
// Δ(t)): scenes/NAME.png, listed in scenes/index.json under "pictures" so that report.html links each map
// cell to it (a cell is that scene with two inputs moved by a few ulps). One picture per report, about a
// second. When it cannot be drawn the report says so on stderr and the cells link to the scene file.
void write_map_picture(const fs::path& partial, const std::string& scene) {
  const fs::path file = partial / "scenes" / "index.json";
  nlohmann::ordered_json j;
  j["scenes"] = read_scene_index(file);
  if (scene.empty() || scene.find('/') != std::string::npos || scene.find("..") != std::string::npos ||
      !j["scenes"].contains(scene))
    return;
  j = nlohmann::ordered_json::parse(std::ifstream(file, std::ios::binary));  // as written, its keys in order
  const fs::path png = partial / "scenes" / (scene + ".png");
  std::string why;
  try {
    if (int rc = draw_scene_picture((partial / j["scenes"][scene].get<std::string>()).string(), png.string()); rc != 0)
      why = "eccd plot exit status " + std::to_string(rc);
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (!why.empty()) {
    warn("report",
         "the failure map's scene " + scene + " could not be drawn (" + why + "): its cells link to the scene file");
    return;
  }
  j["pictures"] = {{scene, "scenes/" + scene + ".png"}};
  write_file(file, j.dump(1) + "\n");
}

// Runs report_figures.py on DIR. Its stderr is passed on and kept: on failure
// the error says the script failed, with the tail of its stderr, and says that
// matplotlib (or numpy) is missing only when that import is what failed.
void run_script(const fs::path& dir, const std::string& name);
// report.md and the figures, then report.html from them.
void run_figures(const fs::path& dir) {
  run_script(dir, "report_figures.py");
  run_script(dir, "report_html.py");
}
void run_script(const fs::path& dir, const std::string& name) {
  fs::path script = fs::path(plots_dir()) / name;
  if (!fs::exists(script))
    throw std::runtime_error(script.string() + ": the report script is missing (set ECCD_PLOTS_DIR?)");
  std::string cmd = "python3 " + shell_quote(script.string()) + " " + shell_quote(dir.string());
  std::fflush(nullptr);
  std::string err;
  int rc = -1;
  if (FILE* p =
          popen((cmd + " 3>&1 1>&2 2>&3").c_str(), "r")) {  // the script's stderr into the pipe, its stdout to ours
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) {
      if (!quiet()) std::fwrite(buf, 1, n, stderr);
      err.append(buf, n);
    }
    rc = pclose(p);
  }
  if (rc == 0) return;
  std::string why = "the report step failed (" + cmd +
                    (rc == -1        ? ": could not be started"
                     : WIFEXITED(rc) ? ": exit status " + std::to_string(WEXITSTATUS(rc))
                                     : ": killed by a signal") +
                    "); results.csv is in " + dir.string();
  if (err.find("No module named 'matplotlib") != std::string::npos)
    why += ". matplotlib is missing: apt-get install python3-matplotlib";
  else if (err.find("No module named 'numpy") != std::string::npos)
    why += ". numpy is missing: apt-get install python3-numpy";
  while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
  if (!err.empty()) {  // the last lines of the script's stderr
    std::size_t pos = err.size();
    for (int lines = 0; lines < 8 && pos != std::string::npos && pos > 0; ++lines) pos = err.rfind('\n', pos - 1);
    why += ". The script's stderr ends with:\n" + (pos == std::string::npos ? err : err.substr(pos + 1));
  } else {
    why += " (the script wrote nothing to stderr)";
  }
  throw std::runtime_error(why);
}

bool looks_like_old_report(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_regular_file(dir / "meta.json", ec)) return false;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (!e.is_regular_file()) return false;
    if (n != "report.md" && n != "results.csv" && n != "failure_map.csv" && n != "meta.json" &&
        e.path().extension() != ".png")
      return false;
  }
  return !ec;
}

// Where the output goes, validated before anything is touched: --out-dir PATH;
// reports/NAME with --name (SUFFIX appended: a shard's part); without either a
// new folder reports/run-YYYYMMDD-HHMMSS (UTC, "-2", "-3" ... if taken), so a
// run never replaces an earlier one, and only an explicit --name default
// refreshes the checked-in example; under --resume without either, the newest
// reports/run-*SUFFIX.partial. `name` is set to the report's name.
fs::path output_folder(const ReportArgs& a, const std::string& suffix, std::string& name) {
  if (a.out_given) {
    check_output_path("--out-dir", a.out);
    name = a.name_given ? a.name : fs::path(a.out).lexically_normal().filename().string();
    return fs::path(a.out);
  }
  if (a.name_given) {
    check_output_name("--name", a.name);
    name = a.name;
    return fs::path("reports") / (a.name + suffix);
  }
  std::error_code ec;
  if (a.resume) {
    const std::regex run("run-[0-9]{8}-[0-9]{6}(-[0-9]+)?" + suffix + "\\.partial");
    std::string newest;
    for (const auto& e : fs::directory_iterator("reports", ec)) {
      std::string n = e.path().filename().string();
      if (std::regex_match(n, run) && e.is_directory() && n > newest) newest = n;
    }
    if (newest.empty())
      throw std::invalid_argument(
          "--resume: nothing to resume: no reports/run-*" + suffix +
          ".partial folder (an interrupted run keeps one; give --name or --out-dir to resume another)");
    name = newest.substr(0, newest.size() - suffix.size() - 8);
    return fs::path("reports") / (name + suffix);
  }
  std::time_t t = std::time(nullptr);
  char b[32];
  std::strftime(b, sizeof b, "run-%Y%m%d-%H%M%S", std::gmtime(&t));
  name = b;
  for (int k = 2; fs::exists(fs::path("reports") / (name + suffix), ec) ||
                  fs::exists(fs::path("reports") / (name + suffix + ".partial"), ec);
       ++k)
    name = std::string(b) + "-" + std::to_string(k);
  return fs::path("reports") / (name + suffix);
}

// Makes a fresh NAME.partial (a leftover one of ours is removed), marked as ours.
void start_partial(const fs::path& partial, const fs::path& out) {
  check_replaceable(out, kMarker, looks_like_old_report);
  remove_our_folder(partial, kMarker);
  std::error_code ec;
  fs::create_directories(partial, ec);
  if (ec) throw OutputError(partial.string() + ": cannot create the output folder: " + ec.message());
  std::ofstream m(partial / kMarker);
  m << "written by eccd report; a folder with this file may be replaced by the next eccd report of the same name\n";
  if (!m) throw OutputError((partial / kMarker).string() + ": cannot write: " + errno_text(errno));
}

void finish_output(const fs::path& partial, const fs::path& out) {
  replace_output_folder(partial, out, kMarker, looks_like_old_report);
}

// ---- FCL in meta.json (branch fcl; contract-19: "fcl" key) ------------------
// {"available", "version", "tolerances", "skipped": {"fcl/ccd:N": scenes without a row}}; the reason when absent.
nlohmann::json fcl_meta(const HarnessOptions& h, const std::vector<std::string>& labels,
                        const std::vector<std::string>& rows) {
  const FclAvailability fa = fcl_availability();
  nlohmann::json j = {{"available", fa.available},
                      {"version", fa.available ? nlohmann::json(fa.version) : nlohmann::json(nullptr)}};
  if (!fa.available)
    j["reason"] = fa.reason;
  else if (!h.fcl)
    j["reason"] = "FCL is built in but was not run (--no-fcl)";
  j["tolerances"] = fcl_tolerances();
  j["samples"] = h.fcl && fa.available ? h.fcl_samples : std::vector<int>{};
  j["skipped"] = nlohmann::json::object();
  for (const auto& [label, n] : fcl_skipped(labels, rows)) j["skipped"][label] = n;
  j["skipped_note"] = "scenes whose motions FCL's translation motion (CCDM_TRANS) cannot express: no fcl/ccd row";
  return j;
}

// meta.json's "externals" (report --external): per engine its name, its folder, how many scenes it answered
// (rows "ext:NAME") and how many scenes of the report it did not (no answer file). `engines` holds name and dir.
nlohmann::json externals_meta(const nlohmann::json& engines, const std::vector<std::string>& rows) {
  std::map<std::string, std::size_t> answered;
  std::set<std::string> scenes;
  for (const auto& r : rows) {
    auto f = csv_split(r, "results.csv row");
    scenes.insert(f[0]);
    if (f[8].rfind("ext:", 0) == 0) ++answered[f[8].substr(4)];
  }
  nlohmann::json out = nlohmann::json::array();
  for (const auto& e : engines) {
    if (!e.is_object() || !e.contains("name") || !e["name"].is_string()) continue;
    const std::string name = e["name"].get<std::string>();
    const std::size_t n = answered.count(name) ? answered[name] : 0;
    out.push_back({{"name", name}, {"dir", e.value("dir", "")}, {"answers", n}, {"missing", scenes.size() - n}});
  }
  return out;
}

// meta.json of a run (eccd-report-meta/1, docs/report-files.md): its options, pipelines, machine, revision,
// times, counts, failures, externals and the failure map.
nlohmann::json report_meta(const ReportArgs& a, const std::string& name, const std::string& started,
                           std::chrono::steady_clock::time_point t_start, int shard_n, std::size_t generated,
                           std::size_t from_cases, const std::vector<std::string>& failures,
                           const std::vector<std::string>& rows, const std::vector<std::string>& cells,
                           const WorkerFiles& reused, const std::optional<FailureMap>& map) {
  nlohmann::json meta;
  stamp_format(meta, "eccd-report-meta/1");  // "format" and "version" (the program's)
  meta["name"] = name;
  meta["command"] = command_line();
  meta["seed"] = a.plan.seed;
  meta["mpfr_bits"] = a.harness.mpfr_bits;
  meta["degrees"] = a.plan.degrees;
  meta["dims"] = a.plan.dims;
  meta["families"] = a.plan.families;
  meta["separations"] = a.plan.d_exponents;
  meta["overlap_depths"] = a.plan.depth_exponents;
  meta["digits"] = a.plan.digits;
  meta["inputs"] = a.harness.inputs;
  meta["guards"] = a.harness.guards;
  meta["input_modes_in_solver"] = solver_has_input_modes();
  meta["budget_seconds"] = a.harness.budget_s;
  meta["exact_budget_seconds"] = a.harness.exact_budget_s;
  meta["count_per_combination"] = a.plan.count;
  meta["grid"] = a.harness.grid;
  std::vector<std::string> labels;
  for (int dim : a.plan.dims)
    for (const auto& p : harness_pipelines(dim, a.harness))
      if (std::find(labels.begin(), labels.end(), p.label) == labels.end()) labels.push_back(p.label);
  meta["pipelines"] = labels;
  meta["fcl"] = fcl_meta(a.harness, labels, rows);
  meta["machine"] = machine_info();
  std::string ver =
      read_command_output("git -C " + shell_quote(fs::path(plots_dir()).parent_path().parent_path().string()) +
                          " describe --always --dirty 2>/dev/null");
  meta["revision"] = ver.empty() ? program_revision() : ver;  // git describe of the source tree
  meta["started"] = started;
  meta["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  meta["shards"] = shard_n;
  meta["shard"] = shard_n > 1 ? nlohmann::json(a.shard) : nlohmann::json(nullptr);
  meta["scene_count"] = generated + from_cases;
  meta["failed"] = failures;
  meta["no_ground_truth"] = no_ground_truth_meta(rows);  // scenes whose ground truth is refused or undecided
  meta["result_rows"] = rows.size();                     // --merge checks a part's row counts against these
  meta["map_rows"] = cells.size();
  {
    nlohmann::json ext = nlohmann::json::array();
    for (const auto& e : a.harness.externals) ext.push_back({{"name", e.name}, {"dir", e.dir}});
    meta["externals"] = externals_meta(ext, rows);
  }
  meta["resumed_tasks"] = reused.done.size();  // finished by an interrupted run and reused (--resume)
  if (map) {
    meta["failure_map"] = {{"scene", map->scene},
                           {"x_input", "constant coefficient of B's x-translation entry m[0][2] (nearest double " +
                                           std::to_string(map->x0) + ")"},
                           {"y_input", "constant coefficient of B's y-translation entry m[1][2] (nearest double " +
                                           std::to_string(map->y0) + ")"},
                           {"n", map->n},
                           {"pipelines", map->pipelines},
                           {"note",
                            "2D touch-and-separate scene of motion degree 2; cell (ix, iy) moves the two inputs by "
                            "ix - n/2 and iy - n/2 units in the last place of the nearest doubles; every cell is "
                            "solved exactly and by each pipeline"}};
  } else {
    meta["failure_map"] = nullptr;
  }
  return meta;
}

}  // namespace eccd::report_detail
