// `eccd report`: the robustness report. Generates the scenes (compare/
// scene_generator.hpp), adds the shipped cases, runs every pipeline on each
// (compare/harness.hpp) in worker processes, computes the failure map, writes
// results.csv, failure_map.csv and meta.json, then has
// compare/plots/report_figures.py write report.md and the PNG figures.
//
// Parallelism: `--jobs` worker processes (fork) take tasks from a counter in
// shared memory, so a slow scene does not hold up the others; each writes its
// rows to its own file and the parent sorts them into a fixed order, so the
// output does not depend on the schedule. `--shard i/n` runs every n-th task
// (for several machines) and writes only the raw part; `--merge` joins parts.
// Output goes to OUT.partial and replaces OUT only when everything succeeded.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "compare/csv.hpp"
#include "compare/harness.hpp"
#include "compare/scene_generator.hpp"
#include "kernel/budget.hpp"
#include "io/scene_reader.hpp"

#include <signal.h>
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
#include <thread>

namespace fs = std::filesystem;

namespace eccd {

namespace {

struct ReportArgs {
  std::string name = "default";
  std::string out;
  bool out_given = false;  // --out given (even as '')
  GeneratePlan plan;
  HarnessOptions harness;
  std::string cases = "cases";
  std::string scenes;
  int jobs = 0;
  std::string shard;
  std::vector<std::string> merge;
  int map_size = 32;
  bool no_map = false, no_figures = false;
  std::vector<std::string> externals;  // --external NAME=DIR, parsed into harness.externals before any work
};

// ---- tasks -------------------------------------------------------------------

struct Task {
  enum Kind { SceneTask, MapCell } kind = SceneTask;
  std::string text, label;  // scene JSON and its file label
  std::string source;       // generated | cases
  int ix = 0, iy = 0;       // map cell
};

// The failure map (Kettner et al. 2004): a 2D scene that touches at one
// instant; the constant coefficients of B's x- and y-translation entries are
// replaced by the double nearest to them moved by ix and iy units in the last
// place. Every cell is a rational scene, solved exactly and by each pipeline.
struct FailureMap {
  nlohmann::ordered_json doc;
  std::string scene;
  double x0 = 0, y0 = 0;
  int n = 0;
  std::vector<std::string> pipelines{"double/power", "double/bernstein", "double/scaled-bernstein", "mpfr:64/bernstein",
                                     "mpfr:128/bernstein"};
};

double step_ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

FailureMap make_failure_map(std::uint64_t seed, int n) {
  FailureMap f;
  GeneratorSpec s;
  s.dim = 2;
  s.degree = 2;
  s.family = "touch";
  s.motion = "kinematic";
  s.seed = scene_seed(seed, s, 999);
  GeneratedScene g = generate_scene(s);
  f.doc = g.doc;
  f.scene = g.name;
  f.n = n;
  auto& m = f.doc["b"]["motion"]["m"];
  f.x0 = parse_rational(m[0][2][0].get<std::string>()).get_d();
  f.y0 = parse_rational(m[1][2][0].get<std::string>()).get_d();
  return f;
}

std::string map_cell_scene(const FailureMap& f, int ix, int iy) {
  nlohmann::ordered_json d = f.doc;
  int h = f.n / 2;
  auto& m = d["b"]["motion"]["m"];
  m[0][2][0] = mpq_class(step_ulps(f.x0, ix - h)).get_str();
  m[1][2][0] = mpq_class(step_ulps(f.y0, iy - h)).get_str();
  d["name"] = f.scene + "-map-" + std::to_string(ix) + "-" + std::to_string(iy);
  return d.dump();
}

// The failure map's classes of an answer: separate, touching (only isolated
// touches), colliding, undecided; "error" without an answer.
std::string answer_kind(const std::optional<Solution>& r) {
  if (!r) return "error";
  if (!r->answer.undecided.empty()) return "undecided";
  if (!r->answer.collides) return "separate";
  for (const auto& [a, b] : r->answer.intervals)
    if (a.approx != b.approx) return "colliding";
  return "touching";
}

// ---- running a task (in a worker) -------------------------------------------

std::vector<std::string> run_task(const Task& t, const ReportArgs& a, const FailureMap* map) {
  std::vector<std::string> out;
  Scene s = parse_scene(t.text, t.label);
  if (t.kind == Task::SceneTask) {
    for (const auto& row : run_scene(s, scene_info(s, t.source), a.harness)) out.push_back("R" + results_csv_line(row));
    return out;
  }
  SolveOptions ex;
  ex.arith = parse_arithmetic("exact");
  std::string exact;
  {
    ScopedDeadline budget(a.harness.exact_budget_s);
    exact = answer_kind(solve(s, ex));
  }
  int h = map->n / 2;
  for (const auto& p : map->pipelines) {
    SolveOptions o;
    auto slash = p.find('/');
    o.arith = parse_arithmetic(p.substr(0, slash));
    o.basis = parse_basis(p.substr(slash + 1));
    BoundedRun br = run_bounded(s, o, a.harness.budget_s, a.harness.isolate);
    std::string kind = br.timed_out ? "undecided" : !br.error.empty() ? "error" : answer_kind(br.got);  // a time-out decides nothing
    out.push_back("M" + csv_line({p, std::to_string(t.ix), std::to_string(t.iy), std::to_string(t.ix - h), std::to_string(t.iy - h),
                                  kind, exact}));
  }
  return out;
}

// ---- helpers -----------------------------------------------------------------

// SIGINT / SIGTERM while the workers run: the parent forwards the signal to its
// workers, waits for them, removes NAME.partial and exits 130 (128 + SIGINT).
volatile sig_atomic_t g_interrupted = 0;
void on_interrupt(int sig) { g_interrupted = sig; }

struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};


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
    if (line.rfind("model name", 0) == 0) { m["cpu"] = line.substr(line.find(':') + 2); break; }
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
  if (s >= 3600) std::snprintf(b, sizeof b, "%dh%02dm", int(s / 3600), int(std::fmod(s, 3600) / 60));
  else if (s >= 60) std::snprintf(b, sizeof b, "%dm%02ds", int(s / 60), int(std::fmod(s, 60)));
  else std::snprintf(b, sizeof b, "%.0fs", s);
  return b;
}

// Sort key of a results.csv line: the scene's place in the plan (rows of one
// scene keep their pipeline order under a stable sort).
std::vector<std::string> scene_key(const std::string& line) {
  auto f = csv_split(line, "results.csv row");
  static const std::map<std::string, std::string> fam{{"colliding", "0"}, {"free", "1"}, {"touch", "2"}, {"near-miss", "3"},
                                                       {"overlap", "4"}, {"graze", "5"}, {"decimal", "6"}, {"keyframe", "7"},
                                                       {"case", "8"}};
  auto pad = [](const std::string& x) { return std::string(8 - std::min<std::size_t>(8, x.size()), '0') + x; };
  std::string d = f.size() > 6 && !f[6].empty() ? pad(f[6].substr(3)) : "";
  std::string digits = f.size() > 27 ? pad(f[27]) : "";  // results_csv_header(): column 28 is digits
  return {f[1], f[2], pad(f[3]), fam.count(f[4]) ? fam.at(f[4]) : f[4], f[5], d, digits, f[0]};
}
void sort_results(std::vector<std::string>& lines) {
  std::stable_sort(lines.begin(), lines.end(), [](const std::string& a, const std::string& b) { return scene_key(a) < scene_key(b); });
}
void sort_map(std::vector<std::string>& lines, const std::vector<std::string>& order) {
  auto key = [&](const std::string& l) {
    auto f = csv_split(l, "failure_map.csv row");
    long p = std::find(order.begin(), order.end(), f[0]) - order.begin();
    return std::make_tuple(p, std::stoi(f[1]), std::stoi(f[2]));
  };
  std::stable_sort(lines.begin(), lines.end(), [&](const std::string& a, const std::string& b) { return key(a) < key(b); });
}

// A worker's file holds one task output per line: "TASK<tab>TEXT", TEXT with
// its backslashes and line breaks escaped (a quoted CSV field may hold a line break).
std::string escape_line(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '\\' ? std::string("\\\\") : c == '\n' ? std::string("\\n") : c == '\r' ? std::string("\\r") : std::string(1, c);
  return o;
}
std::string unescape_line(const std::string& s) {
  std::string o;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k] != '\\' || k + 1 == s.size()) { o += s[k]; continue; }
    char c = s[++k];
    o += c == 'n' ? '\n' : c == 'r' ? '\r' : c;
  }
  return o;
}

// The workers. Returns the output lines ("R..." rows, "M..." map cells) in task order.
std::vector<std::string> run_tasks(const std::vector<Task>& tasks, const ReportArgs& a, const FailureMap* map,
                                   const fs::path& work, std::vector<std::string>& failures) {
  int jobs = a.jobs > 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = std::max(1, std::min<int>(jobs, int(tasks.size())));
  struct Shared { std::atomic<long> next, done; };
  void* mem = mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (mem == MAP_FAILED) throw std::runtime_error("mmap failed");
  auto* sh = new (mem) Shared{{0}, {0}};
  std::fflush(nullptr);
  std::vector<pid_t> kids;
  g_interrupted = 0;
  struct sigaction sa {}, old_int{}, old_term{};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  struct Restore {
    struct sigaction i, t;
    ~Restore() { sigaction(SIGINT, &i, nullptr); sigaction(SIGTERM, &t, nullptr); }
  } restore{old_int, old_term};
  for (int w = 0; w < jobs; ++w) {
    pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
      signal(SIGINT, SIG_DFL);
      signal(SIGTERM, SIG_DFL);
      prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the parent
      if (getppid() == 1) _exit(1);
      try {
      std::ofstream o(work / ("worker-" + std::to_string(w) + ".txt"));
      for (long k; (k = sh->next.fetch_add(1)) < long(tasks.size());) {
        try {
          ScopedDeadline deadline(run_budget().time_limit_s);
          for (const auto& l : run_task(tasks[k], a, map)) o << k << "\t" << escape_line(l) << "\n";
        } catch (const std::exception& e) {
          std::string msg = e.what();
          std::replace(msg.begin(), msg.end(), '\n', ' ');
          o << k << "\tE" << tasks[k].label << ": " << msg << "\n";
        }
        o.flush();
        sh->done.fetch_add(1);
      }
      o.close();
      _exit(o ? 0 : 1);
      } catch (...) {
        _exit(1);
      }
    }
    kids.push_back(pid);
  }
  auto start = std::chrono::steady_clock::now();
  bool tty = isatty(2);
  double last_print = -1e9;
  int running = jobs, bad = 0;
  while (running > 0) {
    if (g_interrupted) {  // stop the workers now, then report the interruption
      for (pid_t k : kids) kill(k, SIGKILL);
      for (pid_t k : kids) waitpid(k, nullptr, 0);
      munmap(mem, sizeof(Shared));
      throw Interrupted(std::string("interrupted by ") + (g_interrupted == SIGINT ? "SIGINT" : "SIGTERM"));
    }
    int status = 0;
    pid_t r = waitpid(-1, &status, WNOHANG);
    if (r > 0) {
      --running;
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) ++bad;
      continue;
    }
    if (!g_interrupted) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    long done = sh->done.load();
    if (el - last_print >= (tty ? 0.5 : 10.0)) {
      last_print = el;
      double rate = done / std::max(el, 1e-9);
      std::string eta = done > 0 ? fmt_duration((tasks.size() - done) / rate) : "?";
      std::fprintf(stderr, "%s[%ld/%zu] %.2f tasks/s, %s elapsed, about %s left (%d workers)%s", tty ? "\r" : "", done,
                   tasks.size(), rate, fmt_duration(el).c_str(), eta.c_str(), jobs, tty ? "   " : "\n");
      std::fflush(stderr);
    }
  }
  double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "%s[%ld/%zu] done in %s\n", tty ? "\r" : "", sh->done.load(), tasks.size(), fmt_duration(el).c_str());
  long finished = sh->done.load();
  munmap(mem, sizeof(Shared));
  if (bad || finished != long(tasks.size())) throw std::runtime_error("a worker process failed (" + std::to_string(bad) + " of " + std::to_string(jobs) + ")");
  std::vector<std::pair<long, std::string>> all;
  for (int w = 0; w < jobs; ++w) {
    std::ifstream in(work / ("worker-" + std::to_string(w) + ".txt"));
    std::string line;
    long order = 0;
    while (std::getline(in, line)) {
      auto tab = line.find('\t');
      all.push_back({std::stol(line.substr(0, tab)) * 100000 + order++, unescape_line(line.substr(tab + 1))});
    }
    fs::remove(work / ("worker-" + std::to_string(w) + ".txt"));
  }
  std::stable_sort(all.begin(), all.end(), [](auto& x, auto& y) { return x.first / 100000 < y.first / 100000; });
  std::vector<std::string> lines;
  for (auto& [k, l] : all) {
    if (l[0] == 'E') failures.push_back(l.substr(1));
    else lines.push_back(l);
  }
  return lines;
}

// Runs report_figures.py on DIR. Its stderr is passed on and kept: on failure
// the error says the script failed, with the tail of its stderr, and says that
// matplotlib (or numpy) is missing only when that import is what failed.
void run_figures(const fs::path& dir) {
  fs::path script = fs::path(plots_dir()) / "report_figures.py";
  if (!fs::exists(script)) throw std::runtime_error(script.string() + ": the report script is missing (set ECCD_PLOTS_DIR?)");
  std::string cmd = "python3 " + shell_quote(script.string()) + " " + shell_quote(dir.string());
  std::fflush(nullptr);
  std::string err;
  int rc = -1;
  if (FILE* p = popen((cmd + " 3>&1 1>&2 2>&3").c_str(), "r")) {  // the script's stderr into the pipe, its stdout to ours
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) {
      std::fwrite(buf, 1, n, stderr);
      err.append(buf, n);
    }
    rc = pclose(p);
  }
  if (rc == 0) return;
  std::string why = "the report step failed (" + cmd + (rc == -1 ? ": could not be started" : WIFEXITED(rc) ? ": exit status " + std::to_string(WEXITSTATUS(rc)) : ": killed by a signal") + "); results.csv is in " + dir.string();
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

// Output folders: every folder `report` writes carries this marker, and only
// a folder with it (or an older report folder holding nothing but report files)
// is ever replaced or removed (issue 15, item 1).
const char* const kMarker = ".eccd-report";

bool looks_like_old_report(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_regular_file(dir / "meta.json", ec)) return false;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (!e.is_regular_file()) return false;
    if (n != "report.md" && n != "results.csv" && n != "failure_map.csv" && n != "meta.json" && e.path().extension() != ".png")
      return false;
  }
  return !ec;
}

// Where the output goes, validated before anything is touched.
fs::path output_folder(const ReportArgs& a, const std::string& name) {
  if (a.out_given) {
    check_output_path("--out", a.out);
    return fs::path(a.out);
  }
  check_output_name("--name", a.name);
  return fs::path("reports") / name;
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

void finish_output(const fs::path& partial, const fs::path& out) { replace_output_folder(partial, out, kMarker, looks_like_old_report); }

// ---- FCL in meta.json (branch fcl; contract-19: "fcl" key) ------------------
// {"available", "version", "tolerances", "skipped": {"fcl/ccd:N": scenes without a row}}; the reason when absent.
nlohmann::json fcl_meta(const HarnessOptions& h, const std::vector<std::string>& labels, const std::vector<std::string>& rows) {
  const FclAvailability fa = fcl_availability();
  nlohmann::json j = {{"available", fa.available}, {"version", fa.available ? nlohmann::json(fa.version) : nlohmann::json(nullptr)}};
  if (!fa.available) j["reason"] = fa.reason;
  else if (!h.fcl) j["reason"] = "FCL is built in but was not run (--no-fcl)";
  j["tolerances"] = fcl_tolerances();
  j["samples"] = h.fcl && fa.available ? h.fcl_samples : std::vector<int>{};
  j["skipped"] = nlohmann::json::object();
  for (const auto& [label, n] : fcl_skipped(labels, rows)) j["skipped"][label] = n;
  j["skipped_note"] = "scenes whose motions FCL's translation motion (CCDM_TRANS) cannot express: no fcl/ccd row";
  return j;
}

// ---- the two modes -----------------------------------------------------------

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

int run_report(const ReportArgs& a) {
  auto t_start = std::chrono::steady_clock::now();
  std::string started = now_iso();
  int shard_i = 0, shard_n = 1;
  if (!a.shard.empty()) {
    auto p = split(a.shard, '/');
    try {
      if (p.size() != 2) throw std::invalid_argument("");
      shard_i = std::stoi(p[0]);
      shard_n = std::stoi(p[1]);
    } catch (const std::exception&) {
      throw std::invalid_argument("--shard " + a.shard + ": expected i/n with 0 <= i < n");
    }
    if (shard_n < 1 || shard_i < 0 || shard_i >= shard_n) throw std::invalid_argument("--shard " + a.shard + ": expected i/n with 0 <= i < n");
  }
  if (a.scenes.empty()) check_plan(a.plan);
  fs::path out = output_folder(a, shard_n > 1 ? a.name + "-shard-" + std::to_string(shard_i) + "-of-" + std::to_string(shard_n) : a.name);
  fs::path partial = out;
  partial += ".partial";
  check_replaceable(out, kMarker, looks_like_old_report);  // before any work: never replace what is not ours
  check_replaceable(partial, kMarker);

  // Tasks: generated scenes (or scene files), the shipped cases, the map cells.
  std::vector<Task> tasks;
  std::size_t generated = 0, from_cases = 0;
  if (a.scenes.empty()) {
    for (const auto& sp : plan_scenes(a.plan)) {
      GeneratedScene g = generate_scene(sp);
      tasks.push_back({Task::SceneTask, g.doc.dump(), g.name, "generated"});
      ++generated;
    }
  }
  auto add_dir = [&](const std::string& dir, const std::string& source) {
    if (!fs::is_directory(dir)) throw std::invalid_argument(dir + ": not a folder of scene files");
    std::vector<fs::path> files;
    for (auto& e : fs::recursive_directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::size_t corpus = 0;
    for (const auto& f : files) {
      std::string text = read_file_bytes(f.string());  // read once: the bytes checked are the bytes run
      Scene s = parse_scene(text, f.string());  // a bad file stops the run before any work (exit 2)
      if (source == "cases" && spec_from_note(s.note)) {  // cases/generated: the report generates its own
        ++corpus;
        continue;
      }
      if (scene_degree(s) < 0) {
        std::fprintf(stderr, "eccd report: %s: skipped (cycloidal motion: no exact ground truth)\n", f.string().c_str());
        continue;
      }
      tasks.push_back({Task::SceneTask, text, f.string(), source});
      source == "cases" ? ++from_cases : ++generated;
    }
    if (corpus)
      std::fprintf(stderr, "eccd report: %s: %zu generated corpus scene(s) left out (the report generates its own; "
                           "--scenes %s/generated includes them)\n", dir.c_str(), corpus, dir.c_str());
  };
  if (!a.scenes.empty()) add_dir(a.scenes, "generated");
  if (!a.cases.empty()) add_dir(a.cases, "cases");
  std::optional<FailureMap> map;
  if (!a.no_map) {
    map = make_failure_map(a.plan.seed, a.map_size);
    for (int ix = 0; ix < a.map_size; ++ix)
      for (int iy = 0; iy < a.map_size; ++iy) {
        Task t{Task::MapCell, map_cell_scene(*map, ix, iy), map->scene + " (map cell)", "map"};
        t.ix = ix;
        t.iy = iy;
        tasks.push_back(t);
      }
  }
  std::vector<Task> mine;
  for (std::size_t k = 0; k < tasks.size(); ++k)
    if (int(k % shard_n) == shard_i) mine.push_back(tasks[k]);
  std::fprintf(stderr, "eccd report: %zu generated scene(s), %zu case(s), %d failure-map cell(s)%s -> %s\n", generated, from_cases,
               map ? a.map_size * a.map_size : 0,
               shard_n > 1 ? (", shard " + a.shard + ": " + std::to_string(mine.size()) + " task(s)").c_str() : "",
               out.string().c_str());

  start_partial(partial, out);
  std::vector<std::string> failures;
  std::vector<std::string> lines;
  try {
    lines = run_tasks(mine, a, map ? &*map : nullptr, partial, failures);
  } catch (const Interrupted&) {
    std::error_code ec;
    fs::remove_all(partial, ec);
    throw;
  }
  for (const auto& f : failures) std::fprintf(stderr, "eccd report: failed: %s\n", f.c_str());

  std::vector<std::string> rows, cells;
  for (auto& l : lines) (l[0] == 'R' ? rows : cells).push_back(l.substr(1));
  sort_results(rows);
  std::string csv = results_csv_header() + "\n";
  for (auto& r : rows) csv += r + "\n";
  write_file(partial / "results.csv", csv);
  if (map) {
    sort_map(cells, map->pipelines);
    std::string m = "pipeline,ix,iy,dx_ulps,dy_ulps,answer,exact\n";
    for (auto& c : cells) m += c + "\n";
    write_file(partial / "failure_map.csv", m);
  }

  nlohmann::json meta;
  meta["name"] = a.name;
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
  std::string ver = read_command_output("git -C " + shell_quote(fs::path(plots_dir()).parent_path().parent_path().string()) +
                                        " describe --always --dirty 2>/dev/null");
  meta["version"] = ver.empty() ? "unknown" : ver;
  meta["started"] = started;
  meta["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  meta["shards"] = shard_n;
  meta["shard"] = shard_n > 1 ? nlohmann::json(a.shard) : nlohmann::json(nullptr);
  meta["scene_count"] = generated + from_cases;
  meta["failed"] = failures;
  meta["result_rows"] = rows.size();  // --merge checks a part's row counts against these
  meta["map_rows"] = cells.size();
  {
    nlohmann::json ext = nlohmann::json::array();
    for (const auto& e : a.harness.externals) ext.push_back({{"name", e.name}, {"dir", e.dir}});
    meta["externals"] = externals_meta(ext, rows);
  }
  if (map) {
    meta["failure_map"] = {{"scene", map->scene},
                           {"x_input", "constant coefficient of B's x-translation entry m[0][2] (nearest double " + std::to_string(map->x0) + ")"},
                           {"y_input", "constant coefficient of B's y-translation entry m[1][2] (nearest double " + std::to_string(map->y0) + ")"},
                           {"n", map->n},
                           {"pipelines", map->pipelines},
                           {"note", "2D touch-and-separate scene of motion degree 2; cell (ix, iy) moves the two inputs by "
                                    "ix - n/2 and iy - n/2 units in the last place of the nearest doubles; every cell is "
                                    "solved exactly and by each pipeline"}};
  } else {
    meta["failure_map"] = nullptr;
  }
  write_file(partial / "meta.json", meta.dump(2) + "\n");
  if (shard_n == 1 && !a.no_figures) run_figures(partial);
  finish_output(partial, out);
  std::fprintf(stderr, "eccd report: wrote %s%s\n", out.string().c_str(),
               shard_n > 1 ? " (a shard: join the parts with eccd report --merge)" : "");
  std::cout << (out / (shard_n == 1 && !a.no_figures ? "report.md" : "results.csv")).string() << "\n";
  return failures.empty() ? 0 : 1;
}

// A file of a part, read whole (merge validation needs the exact bytes).
std::string read_part_file(const fs::path& p, bool required) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) {
    if (!required) return {};
    throw std::invalid_argument(p.string() + ": missing (not an `eccd report --shard` part)");
  }
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::invalid_argument(p.string() + ": cannot read the file: " + errno_text(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Strict "i/n": digits only, 0 <= i < n <= 100000.
std::pair<int, int> parse_shard_text(const std::string& t, const std::string& where) {
  auto bad = [&]() -> std::pair<int, int> {
    throw std::invalid_argument(where + ": shard \"" + t.substr(0, 40) + "\" is not i/n with 0 <= i < n");
  };
  auto slash = t.find('/');
  if (slash == std::string::npos) return bad();
  auto num = [&](const std::string& d) {
    if (d.empty() || d.size() > 6 || d.find_first_not_of("0123456789") != std::string::npos) bad();
    return std::stoi(d);
  };
  int i = num(t.substr(0, slash)), n = num(t.substr(slash + 1));
  if (n < 1 || n > 100000 || i >= n) return bad();
  return {i, n};
}

// The records of a CSV part after its header (compare/csv.hpp reads them, quoting
// and all), each written back as csv_line writes it; a truncated last line, bad
// quoting or a row with the wrong number of fields is an error naming the file
// and the line.
std::vector<std::string> csv_rows(const std::string& text, const std::string& header, const fs::path& file) {
  if (!text.empty() && text.back() != '\n')
    throw std::invalid_argument(file.string() + ": truncated (the last line is incomplete)");
  std::vector<CsvRecord> recs = csv_records(text, file.string());
  std::vector<std::string> head = csv_split(header);
  if (recs.empty() || recs[0].fields != head) throw std::invalid_argument(file.string() + ": line 1: not the expected header");
  std::vector<std::string> rows;
  for (std::size_t k = 1; k < recs.size(); ++k) {
    if (recs[k].fields.size() != head.size())
      throw std::invalid_argument(file.string() + ": line " + std::to_string(recs[k].line) + ": " + std::to_string(recs[k].fields.size()) +
                                  " fields, expected " + std::to_string(head.size()) + " (truncated or edited?)");
    rows.push_back(csv_line(recs[k].fields));
  }
  return rows;
}

int run_merge(const ReportArgs& a) {
  if (a.merge.size() < 1) throw std::invalid_argument("--merge needs the part folders");
  fs::path out = output_folder(a, a.name);
  fs::path partial = out;
  partial += ".partial";
  check_replaceable(out, kMarker, looks_like_old_report);
  check_replaceable(partial, kMarker);
  std::vector<std::string> rows, cells;
  nlohmann::json meta;
  std::vector<std::string> seen;  // part folder per shard index
  double wall = 0;
  std::string header = results_csv_header();
  const std::string map_header = "pipeline,ix,iy,dx_ulps,dy_ulps,answer,exact";
  for (const auto& dir : a.merge) {
    fs::path d(dir);
    const fs::path mp = d / "meta.json";
    std::error_code ec;
    if (!fs::is_directory(d, ec)) throw std::invalid_argument(dir + ": not a folder (an `eccd report --shard` part)");
    std::string mtext = read_part_file(mp, true);
    nlohmann::json m;
    try {
      m = nlohmann::json::parse(mtext);
    } catch (const nlohmann::json::exception& e) {
      throw std::invalid_argument(mp.string() + ": malformed JSON (truncated?): " + std::string(e.what()));
    }
    if (!m.is_object()) throw std::invalid_argument(mp.string() + ": not a report's meta.json (expected a JSON object)");
    const nlohmann::json& shards = m["shards"];
    if (!shards.is_number_unsigned() || shards.get<std::uint64_t>() < 1 || shards.get<std::uint64_t>() > 100000)
      throw std::invalid_argument(mp.string() + ": /shards: expected a positive integer");
    int n = shards.get<int>(), i = 0;
    if (m["shard"].is_string()) {
      auto [si, sn] = parse_shard_text(m["shard"].get<std::string>(), mp.string() + ": /shard");
      if (sn != n) throw std::invalid_argument(mp.string() + ": /shard says " + std::to_string(sn) + " shards but /shards is " + std::to_string(n));
      i = si;
    } else if (!m["shard"].is_null() || n != 1) {
      throw std::invalid_argument(mp.string() + ": /shard: expected \"i/n\"");
    }
    if (!m["command"].is_string()) throw std::invalid_argument(mp.string() + ": /command: expected a string");
    if (!m["wall_seconds"].is_number()) throw std::invalid_argument(mp.string() + ": /wall_seconds: expected a number");
    if (meta.is_null()) {
      meta = m;
      seen.assign(std::size_t(n), "");
    } else {
      for (const char* k : {"seed", "mpfr_bits", "degrees", "dims", "families", "separations", "count_per_combination", "grid", "shards", "failure_map"})
        if (m[k] != meta[k]) throw std::invalid_argument(dir + ": was run with a different " + std::string(k) + " than " + a.merge[0]);
    }
    if (!seen[std::size_t(i)].empty())
      throw std::invalid_argument(dir + ": shard " + std::to_string(i) + "/" + std::to_string(n) + " given twice (also " + seen[std::size_t(i)] + ")");
    seen[std::size_t(i)] = dir;
    wall += m["wall_seconds"].get<double>();
    const fs::path rp = d / "results.csv";
    std::vector<std::string> r = csv_rows(read_part_file(rp, true), header, rp);
    if (m.contains("result_rows") && (!m["result_rows"].is_number_unsigned() || m["result_rows"].get<std::uint64_t>() != r.size()))
      throw std::invalid_argument(rp.string() + ": " + std::to_string(r.size()) + " row(s), but " + mp.string() + " says " +
                                  m["result_rows"].dump() + " (truncated?)");
    rows.insert(rows.end(), r.begin(), r.end());
    const fs::path fp = d / "failure_map.csv";
    std::string ftext = read_part_file(fp, !m["failure_map"].is_null());
    if (!ftext.empty() || !m["failure_map"].is_null()) {
      std::vector<std::string> c = csv_rows(ftext, map_header, fp);
      if (m.contains("map_rows") && (!m["map_rows"].is_number_unsigned() || m["map_rows"].get<std::uint64_t>() != c.size()))
        throw std::invalid_argument(fp.string() + ": " + std::to_string(c.size()) + " row(s), but " + mp.string() + " says " +
                                    m["map_rows"].dump() + " (truncated?)");
      cells.insert(cells.end(), c.begin(), c.end());
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (seen[i].empty()) throw std::invalid_argument("--merge: shard " + std::to_string(i) + "/" + std::to_string(seen.size()) + " is missing");
  if (!meta["failure_map"].is_null() &&
      (!meta["failure_map"].is_object() || !meta["failure_map"]["pipelines"].is_array() ||
       !std::all_of(meta["failure_map"]["pipelines"].begin(), meta["failure_map"]["pipelines"].end(), [](const nlohmann::json& x) { return x.is_string(); })))
    throw std::invalid_argument((fs::path(a.merge[0]) / "meta.json").string() + ": /failure_map/pipelines: expected an array of strings");
  for (const auto& c : cells) {  // sort_map reads ix and iy as integers
    auto f = csv_split(c, "failure_map.csv row");
    for (int k : {1, 2})
      if (f[std::size_t(k)].empty() || f[std::size_t(k)].size() > 6 || f[std::size_t(k)].find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument("--merge: failure_map.csv row \"" + c.substr(0, 80) + "\": ix and iy must be small non-negative integers");
  }
  sort_results(rows);
  start_partial(partial, out);
  std::string csv = header + "\n";
  for (auto& r : rows) csv += r + "\n";
  write_file(partial / "results.csv", csv);
  if (!cells.empty()) {
    sort_map(cells, meta["failure_map"]["pipelines"].get<std::vector<std::string>>());
    std::string m = "pipeline,ix,iy,dx_ulps,dy_ulps,answer,exact\n";
    for (auto& c : cells) m += c + "\n";
    write_file(partial / "failure_map.csv", m);
  }
  meta["name"] = a.name;
  meta["command"] = meta["command"].get<std::string>() + "  (parts joined by: " + command_line() + ")";
  meta["wall_seconds"] = wall;
  meta["shard"] = nullptr;
  meta["result_rows"] = rows.size();
  meta["map_rows"] = cells.size();
  if (meta.contains("externals") && meta["externals"].is_array()) meta["externals"] = externals_meta(meta["externals"], rows);
  if (meta.contains("fcl") && meta["fcl"].is_object() && meta["pipelines"].is_array()) {  // the parts' counts, recounted over all rows
    meta["fcl"]["skipped"] = nlohmann::json::object();
    for (const auto& [label, n] : fcl_skipped(meta["pipelines"].get<std::vector<std::string>>(), rows)) meta["fcl"]["skipped"][label] = n;
  }
  write_file(partial / "meta.json", meta.dump(2) + "\n");
  if (!a.no_figures) run_figures(partial);
  finish_output(partial, out);
  std::fprintf(stderr, "eccd report: joined %zu part(s) into %s\n", a.merge.size(), out.string().c_str());
  std::cout << (out / (a.no_figures ? "results.csv" : "report.md")).string() << "\n";
  return 0;
}

}  // namespace

Command add_report_command(CLI::App& app) {
  auto a = std::make_shared<ReportArgs>();
  // The main job's defaults (scripts/run-main.sh, reports/default): one scene per plan entry, three MPFR
  // precisions and 2 s per floating run, so that the report of every family in both input modes takes
  // minutes, not an hour, on 2 cores; --count, --mpfr, --budget and --map-size widen it.
  a->plan.count = 1;
  a->harness.mpfr_bits = {64, 128, 256};
  a->harness.budget_s = 2;
  a->map_size = 16;
  Command c;
  c.sub = app.add_subcommand(
      "report",
      "Robustness report: generate seeded scenes (2D and 3D, motion degrees 2-6, families colliding / free / touch / "
      "near-miss, overlap / graze (linear translations, degree 1), and the realistic-input families decimal / keyframe), "
      "add the shipped cases, run every pipeline (2D: double power / Bernstein / scaled Bernstein and MPFR "
      "power / Bernstein at many precisions; 3D: the Bezier method with f set up in Bernstein form (double, MPFR) and in "
      "power form (double), the sampling and marching baselines), each floating one per input mode (--input) and under a "
      "time budget (--budget), against the exact pipeline, and write "
      "reports/NAME/: report.md, results.csv, failure_map.csv, meta.json and PNG figures.");
  auto* s = c.sub;
  s->add_option("--name", a->name,
                "Report name: the output goes to reports/NAME (a plain name: no '/', no '..'; an existing reports/NAME is "
                "replaced only if an earlier eccd report wrote it)")->capture_default_str();
  auto* out_opt = s->add_option("--out", a->out,
                                "Output folder instead of reports/NAME (replaced only when the run succeeds, and only if an "
                                "earlier eccd report wrote it); no '..'");
  s->add_option("--seed", a->plan.seed, "Run seed (same seed, same scenes, same numbers apart from timings)")
      ->capture_default_str()->check(check_seed_text);
  s->add_option("--count", a->plan.count, "Generated scenes per dimension x degree x family x motion (x separation)")
      ->capture_default_str()->check(CLI::Range(0, 100000));
  add_plan_options(s, a->plan);
  s->add_option("--mpfr", a->harness.mpfr_bits, "MPFR precisions in bits")->delimiter(',')->capture_default_str()->check(CLI::Range(53, 65536));
  s->add_option("--input", a->harness.inputs,
                "Input modes of the floating pipelines, each a row of its own: rounded (the scene's numbers rounded to "
                "the arithmetic) and prepared (coefficients prepared exactly, then rounded); a solver without input "
                "modes runs prepared only")
      ->delimiter(',')->capture_default_str()->check(CLI::IsMember({"rounded", "prepared"}));
  s->add_option("--budget", a->harness.budget_s, "Time budget of one floating pipeline run in seconds (a run that hits it is undecided, reason time budget)")
      ->capture_default_str()->check(CLI::Range(0.001, 86400.0));
  s->add_option("--exact-budget", a->harness.exact_budget_s, "Time budget of the exact run of one scene in seconds (exhausted: the scene fails)")
      ->capture_default_str()->check(CLI::Range(0.001, 864000.0));
  s->add_option("--grid", a->harness.grid, "N of the 3D sampling:N and marching:N baselines")->capture_default_str()->check(CLI::Range(1, 100000));
  s->add_option("--cases", a->cases, "Also run the scene files under this folder (their stored answers are not used: exact is recomputed; scenes written by eccd generate are left out, see --scenes); '' for none")
      ->capture_default_str();
  s->add_option("--scenes", a->scenes, "Run the scene files under this folder instead of generating scenes");
  s->add_option("--jobs", a->jobs, "Worker processes (default: the number of cores)");
  s->add_option("--shard", a->shard, "i/n: run only every n-th task starting at i and write the raw part (results.csv, meta.json) for --merge");
  s->add_option("--merge", a->merge, "Join the part folders written by --shard runs into one report")->expected(1, -1);
  s->add_option("--map-size", a->map_size, "Failure map: n x n cells (units in the last place around the touching input)")
      ->capture_default_str()->check(CLI::Range(2, 1024));
  s->add_flag("--no-map", a->no_map, "Skip the failure map");
  s->add_flag("--no-figures", a->no_figures, "Write the CSV and meta.json only (no report.md, no PNG)");
  s->add_option("--external", a->externals,
                "NAME=DIR: your engine's answers as rows ext:NAME in every table and plot, judged against the exact answer "
                "like eccd's pipelines; DIR holds one answer file per scene, DIR/<scene name>.json, in any form `eccd judge` "
                "reads (docs/answer-format.md), optionally with \"time_us\"; scenes without a file get no row "
                "(meta.json counts them). Repeat for several engines. `eccd generate --out DIR` writes the generated "
                "scenes for your engine to answer.")
      ->expected(1, -1);
  // Peer pipelines (compare/harness.hpp): certified, and FCL when it is built in.
  auto* fcl_opt = s->add_option("--fcl-samples", a->harness.fcl_samples,
                "N of the FCL pipelines fcl/sample:N and fcl/ccd:N, a comma list (when FCL is built in; docs/fcl.md)")
      ->delimiter(',')->capture_default_str()->check(CLI::Range(2, 1000000));
  s->add_flag_callback("--no-fcl", [a] { a->harness.fcl = false; }, "Skip the FCL pipelines (meta.json still says whether FCL is built in)");
  s->add_flag_callback("--no-certified", [a] { a->harness.certified = false; }, "Skip the certified pipeline (arith certified)");
  s->parse_complete_callback([a, fcl_opt] {  // a warning for an option that changes nothing
    if (fcl_opt->count() && !fcl_availability().available) warn("report", "--fcl-samples is ignored: " + fcl_availability().reason);
    else if (fcl_opt->count() && !a->harness.fcl) warn("report", "--fcl-samples is ignored: --no-fcl");
  });
  c.run = [a, out_opt]() {
    a->out_given = out_opt->count() > 0;
    for (const auto& spec : a->externals) {  // checked before any work: a bad spec is exit 2
      ExternalEngine e = parse_external(spec);
      for (const auto& other : a->harness.externals)
        if (other.name == e.name) throw std::invalid_argument("--external " + spec + ": the name " + e.name + " is given twice");
      a->harness.externals.push_back(e);
    }
    try {
      return a->merge.empty() ? run_report(*a) : run_merge(*a);
    } catch (const Interrupted& e) {
      std::fprintf(stderr, "eccd report: %s: workers stopped, the unfinished output removed\n", e.what());
      return 130;
    }
  };
  return c;
}

}  // namespace eccd
