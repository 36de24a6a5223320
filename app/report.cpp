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
// The most expensive kinds of task run first (a shorter tail); the time left
// is estimated per kind of task (app/time_left.hpp).
// Output: a new reports/run-YYYYMMDD-HHMMSS unless --name or --out-dir says
// otherwise. It goes to OUT.partial and replaces OUT only when everything
// succeeded. OUT.partial holds a plan file and the workers' files, so that an
// interrupted run (Ctrl-C, SIGTERM, kill -9) continues with `--resume`.
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

namespace eccd {

namespace {

struct ReportArgs {
  std::string name;        // --name; without --name and --out-dir: a new reports/run-YYYYMMDD-HHMMSS
  std::string out;
  bool out_given = false;  // --out-dir given (even as '')
  bool name_given = false;
  bool resume = false;     // --resume
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
  int dim = 2, degree = 2;  // the scene's (task_kind)
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

// The largest file report reads back of its own (a part's meta.json and CSVs,
// a worker file, the plan): a bound on memory against a file replaced by
// something else; the real ones are kilobytes to a few megabytes.
constexpr std::size_t kMaxReportFileBytes = std::size_t(256) << 20;

// SIGINT / SIGTERM / SIGHUP (InterruptGuard below): the parent stops its workers, keeps
// NAME.partial if it can be resumed (a plan file and finished tasks; it prints
// the command that resumes) or removes it, and exits 130.
volatile sig_atomic_t g_interrupted = 0;
void on_interrupt(int sig) { g_interrupted = sig; }
int g_lock_fd = -1;  // PartialLock's descriptor: closed in the workers, so their own children (run_bounded) never hold it

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
                                                       {"case", "8"}, {"cycloidal", "9a"}, {"independent", "9b"}};
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

// A worker's file (NAME.partial/worker-SESSION-W.txt) holds the output of the
// tasks it ran, one line per row: "TASK<tab>TEXT", TEXT with its backslashes
// and line breaks escaped (a quoted CSV field may hold a line break), and after
// the last row of a task "TASK<tab>#done<tab>MICROSECONDS". A task counts as
// finished only with its #done line, complete with its line break: a worker
// killed mid-write (Ctrl-C, kill -9) leaves at most an unfinished task, which
// --resume runs again. Rows start with R, M or E, so "#done" is unambiguous.
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

struct TaskOutput {
  std::vector<std::string> lines;  // "R..." rows, "M..." map cells, "E..." a failure
  double seconds = 0;              // the task's wall time in its worker
};
struct WorkerFiles {
  std::map<long, TaskOutput> done;  // by task number (the place in the plan)
  int sessions = 0;                 // highest SESSION among the files
};

// Parses a worker file name "worker-SESSION-W.txt"; -1 if it is not one.
int worker_file_session(const std::string& n) {
  if (n.rfind("worker-", 0) != 0 || n.size() < 12 || n.substr(n.size() - 4) != ".txt") return -1;
  std::string mid = n.substr(7, n.size() - 11);
  auto dash = mid.find('-');
  if (dash == std::string::npos || dash == 0 || dash + 1 == mid.size() ||
      mid.find_first_not_of("0123456789-") != std::string::npos || mid.find('-', dash + 1) != std::string::npos || dash > 6)
    return -1;
  return std::stoi(mid.substr(0, dash));
}

// The finished tasks in the worker files of `work` (task numbers below `tasks`).
WorkerFiles read_worker_files(const fs::path& work, long tasks) {
  WorkerFiles r;
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(work, ec)) {
    int s = worker_file_session(e.path().filename().string());
    if (s < 0) continue;
    r.sessions = std::max(r.sessions, s);
    files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::string text;
    try {  // a regular file of bounded size only: never a FIFO (blocks), /dev/zero (balloons) or a folder
      text = read_bounded_file(f.string(), kMaxReportFileBytes, "the limit of a report's own file");
    } catch (const SceneError& e) {
      throw std::invalid_argument(std::string("--resume: ") + e.what() + "; run without --resume to start afresh");
    }
    long cur = -1;
    TaskOutput pending;
    std::size_t start = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {  // a last line without '\n' is dropped
      std::string line = text.substr(start, end - start);
      auto tab = line.find('\t');
      long k = -1;
      if (tab != std::string::npos && tab > 0 && tab <= 9 && line.find_first_not_of("0123456789") == tab) k = std::stol(line.substr(0, tab));
      if (k < 0 || k >= tasks) {  // not a line of ours: drop the task it interrupts
        cur = -1;
        continue;
      }
      std::string body = line.substr(tab + 1);
      if (k != cur) {
        cur = k;
        pending = {};
      }
      if (body.rfind("#done\t", 0) == 0) {
        try {
          pending.seconds = double(std::stoll(body.substr(6))) * 1e-6;
        } catch (const std::exception&) {
          cur = -1;
          continue;
        }
        r.done.emplace(k, std::move(pending));  // the first finished copy wins
        pending = {};
        cur = -1;
      } else {
        pending.lines.push_back(unescape_line(body));
      }
    }
  }
  return r;
}

// The kind of a task, for the time-left estimate and the schedule, and its
// prior cost: seconds per task on 2 cores at the main job's options
// (reports/default of 2026-11; time_us summed per scene). Only the ratios
// matter: the estimate scales them by what it measures (app/time_left.hpp).
std::pair<std::string, double> task_kind(const Task& t, int dim, int degree) {
  if (t.kind == Task::MapCell) return {"map cell", 0.4};
  if (t.source == "cases") return {"case " + std::to_string(dim) + "D", dim == 2 ? 6.0 : 0.8};
  static const double d2[] = {0.03, 0.03, 0.14, 1.1, 3.9, 7.4, 4.7}, d3[] = {0.44, 0.44, 0.57, 0.97, 3.6, 4.3, 23.5};
  const double* tab = dim == 2 ? d2 : d3;
  double prior = degree <= 6 ? tab[std::max(0, degree)] : tab[6] * std::pow(2.0, degree - 6);
  return {std::to_string(dim) + "D deg " + std::to_string(degree), prior};
}

// SIGINT / SIGTERM / SIGHUP (a closed terminal) from the moment the output
// folder exists: the handler only notes the signal; the parent stops its
// workers (run_tasks), then keeps or removes NAME.partial (run_report) and
// exits 130.
struct InterruptGuard {
  struct sigaction old_int {}, old_term {}, old_hup {};
  InterruptGuard() {
    g_interrupted = 0;
    struct sigaction sa {};
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    sigaction(SIGHUP, &sa, &old_hup);
  }
  ~InterruptGuard() {
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
    sigaction(SIGHUP, &old_hup, nullptr);
  }
};
std::string signal_name() { return g_interrupted == SIGINT ? "SIGINT" : g_interrupted == SIGHUP ? "SIGHUP" : "SIGTERM"; }

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Runs the tasks `todo` (numbers into `tasks`, most expensive kind first) in
// worker processes that write session `session`'s files into `work`; `reused`
// tasks were finished by an earlier session. Prints the progress line unless
// --quiet. Throws Interrupted on SIGINT / SIGTERM (workers stopped) and
// runtime_error if a worker failed.
void run_tasks(const std::vector<Task>& tasks, const std::vector<long>& todo, const std::vector<std::size_t>& kind_of,
               const std::vector<std::string>& kind_names, const std::vector<double>& prior, const WorkerFiles& reused,
               const ReportArgs& a, const FailureMap* map, const fs::path& work, int session) {
  TimeLeft est(prior);
  for (const auto& [k, t] : reused.done) est.add(kind_of[std::size_t(k)], t.seconds);
  const long n = long(todo.size()), total = long(tasks.size()), before = long(reused.done.size());
  int jobs = a.jobs > 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = std::max(1, std::min<int>(jobs, int(std::max(n, 1L))));
  const bool show = !quiet(), tty = isatty(2);
  auto start = std::chrono::steady_clock::now();
  if (n == 0) {
    if (show) std::fprintf(stderr, "[%ld/%ld] every task was finished by the earlier run\n", before, total);
    return;
  }
  // Shared memory: the counters, per worker the task it runs and since when,
  // per scheduled task its cost (-1 until finished).
  struct Shared { std::atomic<long> next, done; };
  struct Slot { std::atomic<long> task; std::atomic<std::int64_t> since; };
  const std::size_t bytes = sizeof(Shared) + sizeof(Slot) * std::size_t(jobs) + sizeof(std::atomic<std::int64_t>) * std::size_t(n);
  void* mem = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (mem == MAP_FAILED) throw std::runtime_error("mmap failed");
  struct Unmap { void* m; std::size_t b; ~Unmap() { munmap(m, b); } } unmap{mem, bytes};
  auto* sh = new (mem) Shared{{0}, {0}};
  auto* slots = reinterpret_cast<Slot*>(static_cast<char*>(mem) + sizeof(Shared));
  auto* cost_ns = reinterpret_cast<std::atomic<std::int64_t>*>(reinterpret_cast<char*>(slots) + sizeof(Slot) * std::size_t(jobs));
  for (int w = 0; w < jobs; ++w) new (&slots[w]) Slot{{-1}, {0}};
  for (long j = 0; j < n; ++j) new (&cost_ns[j]) std::atomic<std::int64_t>(-1);
  std::fflush(nullptr);
  std::vector<pid_t> kids;
  auto stop_all = [&] {
    for (pid_t k : kids) kill(k, SIGKILL);
    for (pid_t k : kids) waitpid(k, nullptr, 0);
  };
  for (int w = 0; w < jobs; ++w) {
    pid_t pid = fork();
    if (pid < 0) {
      stop_all();
      throw std::runtime_error("fork failed");
    }
    if (pid == 0) {
      signal(SIGINT, SIG_DFL);
      signal(SIGTERM, SIG_DFL);
      signal(SIGHUP, SIG_DFL);
      prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the parent
      if (getppid() == 1) _exit(1);
      if (g_lock_fd >= 0) ::close(g_lock_fd);
      try {
        std::ofstream o(work / ("worker-" + std::to_string(session) + "-" + std::to_string(w) + ".txt"), std::ios::binary);
        for (long j; (j = sh->next.fetch_add(1)) < n;) {
          const long k = todo[std::size_t(j)];
          const std::int64_t t0 = now_ns();
          slots[w].since = t0;
          slots[w].task = j;
          std::string text;
          try {
            ScopedDeadline deadline(run_budget().time_limit_s);
            for (const auto& l : run_task(tasks[std::size_t(k)], a, map)) text += std::to_string(k) + "\t" + escape_line(l) + "\n";
          } catch (const std::exception& e) {
            std::string msg = e.what();
            std::replace(msg.begin(), msg.end(), '\n', ' ');
            text = std::to_string(k) + "\tE" + escape_line(tasks[std::size_t(k)].label + ": " + msg) + "\n";
          }
          const std::int64_t took = now_ns() - t0;
          text += std::to_string(k) + "\t#done\t" + std::to_string(took / 1000) + "\n";
          o << text;
          o.flush();
          if (!o) _exit(1);
          cost_ns[j] = took;
          slots[w].task = -1;
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
  std::vector<char> seen(std::size_t(n), 0);
  std::vector<long> queued(kind_names.size(), 0);
  ProgressCadence cadence(tty, total);
  int running = jobs, bad = 0;
  while (running > 0) {
    if (g_interrupted) {  // stop the workers now; run_report keeps or removes the output
      stop_all();
      throw Interrupted(signal_name());
    }
    int status = 0;
    pid_t r = waitpid(-1, &status, WNOHANG);
    if (r > 0) {
      --running;
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) ++bad;
      continue;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!show || !cadence.due(std::min(total - 1, before + sh->done.load()), el)) continue;  // the end has its own line below
    // Measured costs so far, the tasks not started and the running ones.
    const long next = std::min(sh->next.load(), n);
    for (long j = 0; j < next; ++j)
      if (!seen[std::size_t(j)] && cost_ns[j].load() >= 0) {
        seen[std::size_t(j)] = 1;
        est.add(kind_of[std::size_t(todo[std::size_t(j)])], double(cost_ns[j].load()) * 1e-9);
      }
    std::fill(queued.begin(), queued.end(), 0);
    for (long j = next; j < n; ++j) ++queued[kind_of[std::size_t(todo[std::size_t(j)])]];
    std::vector<std::pair<std::size_t, double>> busy;
    std::vector<std::size_t> busy_kinds;
    const std::int64_t now = now_ns();
    for (int w = 0; w < jobs; ++w) {
      long j = slots[w].task.load();
      if (j >= 0 && j < n) {
        busy.push_back({kind_of[std::size_t(todo[std::size_t(j)])], double(now - slots[w].since.load()) * 1e-9});
        busy_kinds.push_back(busy.back().first);
      }
    }
    // Per kind (est.wall), checked against the run's own rate so far: the larger of the two.
    std::optional<double> left = est.wall(queued, busy, jobs);
    if (std::optional<double> by_rate = est.wall_by_rate(queued, busy_kinds, el); left && by_rate) left = std::max(*left, *by_rate);
    std::fprintf(stderr, "%s[%ld/%ld] %s elapsed, %s (%d worker%s)%s", cadence.begin(), before + sh->done.load(), total,
                 fmt_duration(el).c_str(), time_left_text(left).c_str(), jobs, jobs == 1 ? "" : "s", cadence.end(false));
    std::fflush(stderr);
  }
  const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long finished = sh->done.load();
  if (show) std::fprintf(stderr, "%s[%ld/%ld] done in %s%s\n", cadence.begin(), before + finished, total, fmt_duration(el).c_str(),
                        tty ? "\x1b[K" : "");
  if (bad || finished != n)
    throw std::runtime_error("a worker process failed (" + std::to_string(bad) + " of " + std::to_string(jobs) + "); the finished tasks are kept in " +
                             work.string() + " for --resume");
}

// The scene files behind the rows, for report.html's links (compare/plots/report_html.py):
// scenes/NAME.json for each generated scene and the failure map's scene (they exist nowhere
// else), and scenes/index.json, each scene's name -> its file relative to the report folder
// `out` (a scene file given by --cases or --scenes links to that file: the link holds while the
// report stays where it was written, beside them).
void write_scene_files(const fs::path& partial, const fs::path& out, const std::vector<Task>& tasks, const FailureMap* map) {
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
      const std::string name = doc.is_object() && doc.contains("name") && doc["name"].is_string() ? doc["name"].get<std::string>()
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
  if (!j.is_object() || j.value("format", "") != "eccd-report-scenes/1" || !j.contains("scenes") || !j["scenes"].is_object())
    throw std::invalid_argument(file.string() + ": not an eccd-report-scenes/1 index (expected an object with \"format\" and \"scenes\")");
  for (const auto& [name, rel] : j["scenes"].items())
    if (!rel.is_string()) throw std::invalid_argument(file.string() + ": /scenes/" + name + ": expected a file name");
  return j["scenes"];
}

// --merge: the parts' scene files into the merged report's scenes/ and one index. `parts`: each part's
// folder and its index (read_scene_index, read while the parts are checked, before anything is written).
// A part's own file (scenes/NAME.json) is copied; a link to a file given by --cases or --scenes is made
// relative to the merged report `out` (the part's link was relative to the part).
void merge_scene_files(const fs::path& partial, const fs::path& out, const std::vector<std::pair<fs::path, nlohmann::ordered_json>>& parts) {
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
          warn("report", (d / own).string() + ": missing (listed in the part's scenes/index.json): the merged report does not link scene " + name);
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
  if (scene.empty() || scene.find('/') != std::string::npos || scene.find("..") != std::string::npos || !j["scenes"].contains(scene)) return;
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
    warn("report", "the failure map's scene " + scene + " could not be drawn (" + why + "): its cells link to the scene file");
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
  if (!fs::exists(script)) throw std::runtime_error(script.string() + ": the report script is missing (set ECCD_PLOTS_DIR?)");
  std::string cmd = "python3 " + shell_quote(script.string()) + " " + shell_quote(dir.string());
  std::fflush(nullptr);
  std::string err;
  int rc = -1;
  if (FILE* p = popen((cmd + " 3>&1 1>&2 2>&3").c_str(), "r")) {  // the script's stderr into the pipe, its stdout to ours
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) {
      if (!quiet()) std::fwrite(buf, 1, n, stderr);
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
      throw std::invalid_argument("--resume: nothing to resume: no reports/run-*" + suffix +
                                  ".partial folder (an interrupted run keeps one; give --name or --out-dir to resume another)");
    name = newest.substr(0, newest.size() - suffix.size() - 8);
    return fs::path("reports") / (name + suffix);
  }
  std::time_t t = std::time(nullptr);
  char b[32];
  std::strftime(b, sizeof b, "run-%Y%m%d-%H%M%S", std::gmtime(&t));
  name = b;
  for (int k = 2; fs::exists(fs::path("reports") / (name + suffix), ec) || fs::exists(fs::path("reports") / (name + suffix + ".partial"), ec); ++k)
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

// ---- resuming ----------------------------------------------------------------

// NAME.partial/plan.json: what decides a run's results, written before the
// first task runs, so that --resume can tell whether the finished tasks in the
// worker files belong to the run it is asked for. "options" are compared key
// by key (the first difference is named); "tasks_digest" (FNV-1a over every
// task's kind, label, source and scene text) catches a changed --cases or
// --scenes folder. Options that do not change a result (--jobs, --name, --out-dir,
// --no-figures, --quiet) are not in it.
const char* const kPlanFile = "plan.json";

nlohmann::ordered_json report_plan(const ReportArgs& a, const std::vector<Task>& mine, const std::string& shard, const std::string& started) {
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
    throw std::invalid_argument("--resume: nothing to resume: " + p + " does not exist (an interrupted eccd report keeps it; "
                                "a finished or never started one has none)");
  if (fs::is_symlink(partial, ec) || !fs::is_directory(partial, ec) || !has_marker(partial, kMarker))
    throw std::invalid_argument("--resume: " + p + " was not written by eccd report (no " + kMarker + " marker): refusing to use it");
  if (!fs::is_regular_file(partial / kPlanFile, ec))
    throw std::invalid_argument("--resume: " + p + " cannot be resumed: it has no " + kPlanFile +
                                " (written by --merge or by an eccd without --resume); run without --resume to start afresh");
  nlohmann::ordered_json old;
  try {
    old = parse_json_document(read_bounded_file((partial / kPlanFile).string(), kMaxReportFileBytes, "the limit of a report's own file"),
                              (partial / kPlanFile).string());
  } catch (const std::exception& e) {
    throw std::invalid_argument("--resume: " + (partial / kPlanFile).string() + ": unreadable (" + e.what() + "); run without --resume to start afresh");
  }
  const std::string again = "; resuming would mix two different runs: give the same options, or run without --resume to start afresh";
  if (!old.is_object() || old.value("format", "") != plan["format"])
    throw std::invalid_argument("--resume: " + (partial / kPlanFile).string() + ": not a plan of this eccd (format " +
                                (old.is_object() && old.contains("format") ? old["format"].dump() : std::string("missing")) + ")" + again);
  auto shown = [](const nlohmann::ordered_json& j) {
    std::string s = j.dump();
    return s.size() > 120 ? s.substr(0, 120) + "..." : s;
  };
  const auto& oo = old["options"];
  for (const auto& [k, v] : plan["options"].items())
    if (!oo.is_object() || !oo.contains(k) || oo[k] != v)
      throw std::invalid_argument("--resume: " + p + " was started with a different " + k + " (" +
                                  (oo.is_object() && oo.contains(k) ? shown(oo[k]) : std::string("not recorded")) + "; this run: " + shown(v) + ")" + again);
  if (old["revision"] != plan["revision"])
    throw std::invalid_argument("--resume: " + p + " was started by another build of eccd (git " + shown(old["revision"]) + "; this one: " +
                                shown(plan["revision"]) + ")" + again);
  if (old["tasks"] != plan["tasks"] || old["tasks_digest"] != plan["tasks_digest"])
    throw std::invalid_argument("--resume: " + p + " was started on other scenes (" + shown(old["tasks"]) + " task(s), digest " +
                                shown(old["tasks_digest"]) + "; this run: " + shown(plan["tasks"]) + ", " + shown(plan["tasks_digest"]) +
                                "; did the files under --cases or --scenes change?)" + again);
  return read_worker_files(partial, plan["tasks"].get<long>());
}

// A running report holds an exclusive flock on its NAME.partial/plan.json
// (released by the kernel however the process ends, kill -9 included), so
// that neither --resume nor a fresh run of the same name touches the folder
// of a run still in progress.
struct PartialLock {
  int fd = -1;
  PartialLock() = default;
  PartialLock(const PartialLock&) = delete;
  PartialLock& operator=(const PartialLock&) = delete;
  ~PartialLock() {
    if (fd >= 0) ::close(fd);
    g_lock_fd = -1;
  }
  // Takes the lock on `partial`'s plan file; false if another process holds it
  // (a missing file is not locked: true).
  bool take(const fs::path& partial) {
    if (fd >= 0) ::close(fd);
    g_lock_fd = fd = ::open((partial / kPlanFile).c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return true;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) return true;
    ::close(fd);
    g_lock_fd = fd = -1;
    return false;
  }
};
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
  std::string name;
  fs::path out = output_folder(a, shard_n > 1 ? "-shard-" + std::to_string(shard_i) + "-of-" + std::to_string(shard_n) : "", name);
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
      tasks.back().dim = sp.dim;
      tasks.back().degree = sp.degree;
      ++generated;
    }
  }
  auto add_dir = [&](const std::string& dir, const std::string& source) {
    if (!fs::is_directory(dir)) throw std::invalid_argument(dir + ": not a folder of scene files");
    std::vector<fs::path> files;
    std::map<fs::path, std::string> texts;  // each scene's bytes, read once: the bytes checked are the bytes run
    for (auto& e : fs::recursive_directory_iterator(dir)) {
      if (!e.is_regular_file() || e.path().extension() != ".json") continue;
      std::string text, why;
      FileKind k = classify_file(e.path(), text, why);  // animations, certificates, answers: not scenes, left out
      if (k == FileKind::Broken) throw SceneError(e.path().string() + ": " + why);  // exit 2 before any work
      if (k == FileKind::NotScene) continue;
      texts[e.path()] = std::move(text);
      files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    std::size_t corpus = 0;
    for (const auto& f : files) {
      const std::string& text = texts[f];
      Scene s = parse_scene(text, f.string());  // a bad file stops the run before any work (exit 2)
      if (source == "cases" && spec_from_note(s.note)) {  // cases/generated: the report generates its own
        ++corpus;
        continue;
      }
      tasks.push_back({Task::SceneTask, text, f.string(), source});
      tasks.back().dim = s.dim;
      tasks.back().degree = scene_degree(s);
      source == "cases" ? ++from_cases : ++generated;
    }
    if (corpus && !quiet())
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
  if (!quiet())
    std::fprintf(stderr, "eccd report: %zu generated scene(s), %zu case(s), %d failure-map cell(s)%s -> %s\n", generated, from_cases,
                 map ? a.map_size * a.map_size : 0,
                 shard_n > 1 ? (", shard " + a.shard + ": " + std::to_string(mine.size()) + " task(s)").c_str() : "",
                 out.string().c_str());

  // The output folder: fresh with its plan file, or (--resume) the one an
  // interrupted run left, with the tasks it finished.
  const nlohmann::ordered_json plan = report_plan(a, mine, shard_n > 1 ? a.shard : "", started);
  InterruptGuard guard;
  WorkerFiles reused;
  PartialLock lock;
  if (a.resume) {
    if (!lock.take(partial)) refuse_busy(partial);
    reused = check_resume(partial, plan);
    if (!quiet())
      std::fprintf(stderr, "eccd report: resuming %s: %zu of %zu task(s) finished earlier, %zu to run\n", partial.string().c_str(),
                   reused.done.size(), mine.size(), mine.size() - reused.done.size());
  } else {
    std::error_code ec;
    if (!lock.take(partial)) refuse_busy(partial);
    if (!quiet() && fs::is_regular_file(partial / kPlanFile, ec) && has_marker(partial, kMarker))
      if (std::size_t left = read_worker_files(partial, long(mine.size())).done.size())
        std::fprintf(stderr, "eccd report: removing the interrupted %s (%zu task(s) finished; --resume would have reused them)\n",
                     partial.string().c_str(), left);
    start_partial(partial, out);
    write_text_atomically(partial / kPlanFile, plan.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    if (!lock.take(partial)) refuse_busy(partial);
  }
  // Interrupted: keep the folder if a later --resume can use it, else remove it.
  auto interrupted = [&]() {
    std::size_t finished = read_worker_files(partial, long(mine.size())).done.size();
    std::string why = "interrupted by " + signal_name() + ": ";
    if (finished > 0) {
      throw Interrupted(why + std::to_string(finished) + " of " + std::to_string(mine.size()) + " task(s) finished are kept in " +
                        partial.string() + "; resume with:\n  " + resume_command(a, name));
    }
    std::error_code ec;
    fs::remove_all(partial, ec);
    throw Interrupted(why + "workers stopped before any task finished; " + partial.string() + " removed");
  };

  // Kinds (the estimate and the schedule): the expensive kinds first, which
  // shortens the run's tail and lets the estimate measure them early; the
  // output order does not depend on it (rows are sorted below).
  std::vector<std::string> kind_names;
  std::vector<double> prior;
  std::vector<std::size_t> kind_of;
  for (const auto& t : mine) {
    auto [kn, pr] = task_kind(t, t.dim, t.degree);
    auto it = std::find(kind_names.begin(), kind_names.end(), kn);
    if (it == kind_names.end()) {
      kind_names.push_back(kn);
      prior.push_back(pr);
      it = kind_names.end() - 1;
    }
    kind_of.push_back(std::size_t(it - kind_names.begin()));
  }
  std::vector<long> todo;
  for (long k = 0; k < long(mine.size()); ++k)
    if (!reused.done.count(k)) todo.push_back(k);
  std::stable_sort(todo.begin(), todo.end(), [&](long x, long y) { return prior[kind_of[std::size_t(x)]] > prior[kind_of[std::size_t(y)]]; });
  try {
    run_tasks(mine, todo, kind_of, kind_names, prior, reused, a, map ? &*map : nullptr, partial, reused.sessions + 1);
  } catch (const Interrupted&) {
    interrupted();
  }
  // Every task's output, in the plan's order.
  WorkerFiles all = read_worker_files(partial, long(mine.size()));
  std::vector<std::string> failures, lines;
  for (long k = 0; k < long(mine.size()); ++k) {
    auto it = all.done.find(k);
    if (it == all.done.end())
      throw std::runtime_error("task " + std::to_string(k) + " (" + mine[std::size_t(k)].label + ") has no output in " + partial.string() +
                               " (a worker file was changed?); run with --resume to run it again");
    for (auto& l : it->second.lines) {
      if (l.empty()) continue;
      if (l[0] == 'E') failures.push_back(l.substr(1));
      else lines.push_back(l);
    }
  }
  for (const auto& f : failures) std::fprintf(stderr, "eccd: report: failed: %s\n", f.c_str());

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
  std::string ver = read_command_output("git -C " + shell_quote(fs::path(plots_dir()).parent_path().parent_path().string()) +
                                        " describe --always --dirty 2>/dev/null");
  meta["revision"] = ver.empty() ? program_revision() : ver;  // git describe of the source tree
  meta["started"] = started;
  meta["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  meta["shards"] = shard_n;
  meta["shard"] = shard_n > 1 ? nlohmann::json(a.shard) : nlohmann::json(nullptr);
  meta["scene_count"] = generated + from_cases;
  meta["failed"] = failures;
  meta["no_ground_truth"] = no_ground_truth_meta(rows);  // issue 20: scenes whose ground truth is refused or undecided
  meta["result_rows"] = rows.size();  // --merge checks a part's row counts against these
  meta["map_rows"] = cells.size();
  {
    nlohmann::json ext = nlohmann::json::array();
    for (const auto& e : a.harness.externals) ext.push_back({{"name", e.name}, {"dir", e.dir}});
    meta["externals"] = externals_meta(ext, rows);
  }
  meta["resumed_tasks"] = reused.done.size();  // finished by an interrupted run and reused (--resume)
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
  write_file(partial / "meta.json", meta.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  write_scene_files(partial, out, mine, map ? &*map : nullptr);  // a shard: its own scenes, joined by --merge
  if (g_interrupted) interrupted();
  if (shard_n == 1 && !a.no_figures) {
    try {
      if (map) write_map_picture(partial, map->scene);
      run_figures(partial);
    } catch (const std::exception& e) {
      if (g_interrupted) interrupted();  // Ctrl-C reaches the script too
      throw std::runtime_error(std::string(e.what()) + "\nThe finished tasks are kept; once fixed, this redoes only the report step:\n  " +
                               resume_command(a, name));
    }
  }
  if (g_interrupted) interrupted();
  // The worker files and the plan are the resumable state, not part of the report.
  for (const auto& e : fs::directory_iterator(partial))
    if (worker_file_session(e.path().filename().string()) >= 0) fs::remove(e.path());
  fs::remove(partial / kPlanFile);
  finish_output(partial, out);
  if (!quiet())
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
  try {  // a regular file of bounded size only: never a FIFO (blocks), /dev/zero (balloons)
    return read_bounded_file(p.string(), kMaxReportFileBytes, "the limit of a report's own file");
  } catch (const SceneError& e) {
    throw std::invalid_argument(e.what());
  }
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
  if (a.resume) throw std::invalid_argument("--resume: not with --merge (a merge only joins finished parts: run it again)");
  std::string name;
  fs::path out = output_folder(a, "", name);
  fs::path partial = out;
  partial += ".partial";
  check_replaceable(out, kMarker, looks_like_old_report);
  check_replaceable(partial, kMarker);
  for (const auto& dir : a.merge) {  // the output replaces OUT: never one of the parts it reads
    std::error_code ec;
    for (const fs::path& o : {out, partial})
      if (fs::exists(o, ec) && fs::equivalent(o, fs::path(dir), ec))
        throw OutputError(o.string() + ": refusing to write the merged report there: it is the part " + dir +
                          " given to --merge (choose another --name or --out)");
  }
  std::vector<std::string> rows, cells;
  nlohmann::json meta;
  std::vector<std::string> seen;  // part folder per shard index
  std::vector<std::pair<fs::path, nlohmann::ordered_json>> scene_indexes;  // each part's scenes/index.json
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
    try {  // nesting bounded (io/scene_reader.hpp): 100 000 '[' are refused at the 65th
      m = parse_json_document(mtext, mp.string());
    } catch (const SceneError& e) {
      throw std::invalid_argument(std::string(e.what()) + " (a report's meta.json; truncated?)");
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
    scene_indexes.emplace_back(d, read_scene_index(d / "scenes" / "index.json"));
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
  InterruptGuard guard;  // a merge is quick and not resumable: interrupted, its partial output is removed
  auto interrupted = [&]() {
    std::error_code ec;
    fs::remove_all(partial, ec);
    throw Interrupted("interrupted by " + signal_name() + ": " + partial.string() + " removed (run the merge again)");
  };
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
  stamp_format(meta, "eccd-report-meta/1");
  meta["name"] = name;
  meta["command"] = meta["command"].get<std::string>() + "  (parts joined by: " + command_line() + ")";
  meta["wall_seconds"] = wall;
  meta["shard"] = nullptr;
  meta["result_rows"] = rows.size();
  meta["no_ground_truth"] = no_ground_truth_meta(rows);
  meta["map_rows"] = cells.size();
  if (meta.contains("externals") && meta["externals"].is_array()) meta["externals"] = externals_meta(meta["externals"], rows);
  if (meta.contains("fcl") && meta["fcl"].is_object() && meta["pipelines"].is_array()) {  // the parts' counts, recounted over all rows
    meta["fcl"]["skipped"] = nlohmann::json::object();
    for (const auto& [label, n] : fcl_skipped(meta["pipelines"].get<std::vector<std::string>>(), rows)) meta["fcl"]["skipped"][label] = n;
  }
  write_file(partial / "meta.json", meta.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  merge_scene_files(partial, out, scene_indexes);
  if (!a.no_figures) {
    try {
      if (meta["failure_map"].is_object() && meta["failure_map"]["scene"].is_string())
        write_map_picture(partial, meta["failure_map"]["scene"].get<std::string>());
      run_figures(partial);
    } catch (const std::exception&) {
      if (g_interrupted) interrupted();
      throw;
    }
  }
  if (g_interrupted) interrupted();
  finish_output(partial, out);
  if (!quiet()) std::fprintf(stderr, "eccd report: joined %zu part(s) into %s\n", a.merge.size(), out.string().c_str());
  std::cout << (out / (a.no_figures ? "results.csv" : "report.md")).string() << "\n";
  return 0;
}

}  // namespace

Command add_report_command(CLI::App& app) {
  auto a = std::make_shared<ReportArgs>();
  // The main job's defaults (scripts/run-main.sh, reports/default): one scene per plan entry, three MPFR
  // precisions and 2 s per floating run, so that the report of every family in both input modes takes
  // minutes, not an hour, on 2 cores; --count, --mpfr-bits, --budget and --map-size widen it.
  a->plan.count = 1;
  a->harness.mpfr_bits = {64, 128, 256};
  a->harness.budget_s = 2;
  a->map_size = 16;
  Command c;
  c.sub = app.add_subcommand(
      "report",
      "Robustness report: generate seeded scenes (2D and 3D, motion degrees 2-6, families colliding / free / touch / "
      "near-miss, overlap / graze (linear translations, degree 1), and the realistic-input families decimal / keyframe; "
      "--families cycloidal,independent adds issue 20's motions, against the certified resp. exact answer), "
      "add the shipped cases, run every pipeline (2D: double power / Bernstein / scaled Bernstein and MPFR "
      "power / Bernstein at many precisions; 3D: the Bezier method with f set up in Bernstein form (double, MPFR) and in "
      "power form (double), the sampling and marching baselines), each floating one as published and guarded (--guard), "
      "per input mode (--input) and under a "
      "time budget (--budget), against the exact pipeline, and write "
      "a new folder reports/run-YYYYMMDD-HHMMSS/ (or reports/NAME/ with --name, --out-dir PATH): report.md, results.csv, "
      "failure_map.csv, meta.json and PNG figures. Progress and time left go to stderr (--quiet: none); Ctrl-C keeps "
      "the finished tasks for --resume.");
  auto* s = c.sub;
  auto* name_opt = s->add_option("--name", a->name,
                "Report name: the output goes to reports/NAME (a plain name: no '/', no '..'; an existing reports/NAME is "
                "replaced only if an earlier eccd report wrote it). Without --name and --out-dir every run writes a new folder "
                "reports/run-YYYYMMDD-HHMMSS (UTC start time); --name default refreshes the checked-in example reports/default");
  auto* out_opt = s->add_option("--out-dir", a->out,
                                "Output folder instead of reports/NAME (replaced only when the run succeeds, and only if an "
                                "earlier eccd report wrote it); no '..'");
  auto* old_out_opt = add_old_spelling(s, "--out", "--out", "--out-dir", a->out);
  s->add_option("--seed", a->plan.seed, "Run seed (same seed, same scenes, same numbers apart from timings)")
      ->capture_default_str()->check(check_seed_text);
  s->add_option("--count", a->plan.count, "Generated scenes per dimension x degree x family x motion (x separation)")
      ->capture_default_str()->check(CLI::Range(0, 100000));
  add_plan_options(s, a->plan);
  s->add_option("--mpfr-bits", a->harness.mpfr_bits, "MPFR precisions in bits")->delimiter(',')->capture_default_str()->check(CLI::Range(53, 65536));
  add_old_spelling(s, "--mpfr", "--mpfr", "--mpfr-bits", a->harness.mpfr_bits)->delimiter(',')->check(CLI::Range(53, 65536));
  s->add_option("--input", a->harness.inputs,
                "Input modes of the floating pipelines, each a row of its own: rounded (the scene's numbers rounded to "
                "the arithmetic) and prepared (coefficients prepared exactly, then rounded); a solver without input "
                "modes runs prepared only")
      ->delimiter(',')->capture_default_str()->check(CLI::IsMember({"rounded", "prepared"}));
  s->add_option("--guard", a->harness.guards,
                "Faces of the double and MPFR pipelines, each a row of its own: none (the algorithm as published, in plain "
                "double or MPFR: its errors are the measurement; labels ending in /published) and bound (guarded by the "
                "running error bound: an unsure sign is undecided); the report's guard record needs both")
      ->delimiter(',')->capture_default_str()->check(CLI::IsMember({"none", "bound"}));
  s->add_option("--budget", a->harness.budget_s, "Time budget of one floating pipeline run in seconds of its processor time (a run that hits it is undecided, reason time budget; processor time, so a busy machine does not change the report)")
      ->capture_default_str()->check(CLI::Range(0.001, 86400.0));
  s->add_option("--exact-budget", a->harness.exact_budget_s, "Time budget of the exact run of one scene in seconds (exhausted: the scene fails)")
      ->capture_default_str()->check(CLI::Range(0.001, 864000.0));
  s->add_option("--grid", a->harness.grid, "N of the 3D sampling:N and marching:N baselines")->capture_default_str()->check(CLI::Range(1, 100000));
  s->add_option("--cases", a->cases, "Also run the scene files under this folder (their stored answers are not used: exact is recomputed; scenes written by eccd generate are left out, see --scenes); '' for none")
      ->capture_default_str();
  s->add_option("--scenes", a->scenes, "Run the scene files under this folder instead of generating scenes");
  s->add_option("--jobs", a->jobs, "Worker processes (default: the number of cores)");
  add_old_spelling(s, "--threads", "--threads", "--jobs", a->jobs);
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
                "(meta.json counts them). Repeat for several engines. `eccd generate --out-dir DIR` writes the generated "
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
  s->add_flag("--resume", a->resume,
              "Continue an interrupted run (Ctrl-C, SIGTERM, a crash): reuse the tasks it finished in its NAME.partial folder "
              "and run the rest. Give the same options (and --name/--out-dir; without them the newest reports/run-*.partial); "
              "a folder of another plan (seed, options, scenes, build) is refused with exit 2");
  c.run = [a, out_opt, old_out_opt, name_opt]() {
    a->out_given = out_opt->count() > 0 || old_out_opt->count() > 0;
    a->name_given = name_opt->count() > 0;
    for (const auto& spec : a->externals) {  // checked before any work: a bad spec is exit 2
      ExternalEngine e = parse_external(spec);
      for (const auto& other : a->harness.externals)
        if (other.name == e.name) throw std::invalid_argument("--external " + spec + ": the name " + e.name + " is given twice");
      a->harness.externals.push_back(e);
    }
    try {
      return a->merge.empty() ? run_report(*a) : run_merge(*a);
    } catch (const Interrupted& e) {
      std::fprintf(stderr, "\neccd: report: %s\n", e.what());
      return 130;
    }
  };
  return c;
}

}  // namespace eccd
