// `eccd report`'s worker pool (app/report_parts.hpp): `--jobs` worker processes
// (fork) take tasks from a counter in shared memory, so a slow scene does not
// hold up the others; each writes its rows to its own file (read back by
// read_worker_files, also for --resume). Also the failure map's cells and the
// kinds of task the time-left estimate and the schedule use.
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
#include "kernel/answer.hpp"
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
  f.x0 = nearest_double(parse_rational(m[0][2][0].get<std::string>()));  // the map's centre: the nearest double
  f.y0 = nearest_double(parse_rational(m[1][2][0].get<std::string>()));
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
    std::string kind = br.timed_out        ? "undecided"
                       : !br.error.empty() ? "error"
                                           : answer_kind(br.got);  // a time-out decides nothing
    out.push_back("M" + csv_line({p, std::to_string(t.ix), std::to_string(t.iy), std::to_string(t.ix - h),
                                  std::to_string(t.iy - h), kind, exact}));
  }
  return out;
}

volatile sig_atomic_t g_interrupted = 0;
void on_interrupt(int sig) { g_interrupted = sig; }
int g_lock_fd = -1;

// A worker's file (NAME.partial/worker-SESSION-W.txt) holds the output of the
// tasks it ran, one line per row: "TASK<tab>TEXT", TEXT with its backslashes
// and line breaks escaped (a quoted CSV field may hold a line break), and after
// the last row of a task "TASK<tab>#done<tab>MICROSECONDS". A task counts as
// finished only with its #done line, complete with its line break: a worker
// killed mid-write (Ctrl-C, kill -9) leaves at most an unfinished task, which
// --resume runs again. Rows start with R, M or E, so "#done" is unambiguous.
std::string escape_line(const std::string& s) {
  std::string o;
  for (char c : s)
    o += c == '\\'   ? std::string("\\\\")
         : c == '\n' ? std::string("\\n")
         : c == '\r' ? std::string("\\r")
                     : std::string(1, c);
  return o;
}
std::string unescape_line(const std::string& s) {
  std::string o;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k] != '\\' || k + 1 == s.size()) {
      o += s[k];
      continue;
    }
    char c = s[++k];
    o += c == 'n' ? '\n' : c == 'r' ? '\r' : c;
  }
  return o;
}

// Parses a worker file name "worker-SESSION-W.txt"; -1 if it is not one.
int worker_file_session(const std::string& n) {
  if (n.rfind("worker-", 0) != 0 || n.size() < 12 || n.substr(n.size() - 4) != ".txt") return -1;
  std::string mid = n.substr(7, n.size() - 11);
  auto dash = mid.find('-');
  if (dash == std::string::npos || dash == 0 || dash + 1 == mid.size() ||
      mid.find_first_not_of("0123456789-") != std::string::npos || mid.find('-', dash + 1) != std::string::npos ||
      dash > 6)
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
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos;
         start = end + 1) {  // a last line without '\n' is dropped
      std::string line = text.substr(start, end - start);
      auto tab = line.find('\t');
      long k = -1;
      if (tab != std::string::npos && tab > 0 && tab <= 9 && line.find_first_not_of("0123456789") == tab)
        k = std::stol(line.substr(0, tab));
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

std::string signal_name() {
  return g_interrupted == SIGINT ? "SIGINT" : g_interrupted == SIGHUP ? "SIGHUP" : "SIGTERM";
}

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Shared memory: the counters, per worker the task it runs and since when,
// per scheduled task its cost (-1 until finished).
struct Shared {
  std::atomic<long> next, done;
};
struct Slot {
  std::atomic<long> task;
  std::atomic<std::int64_t> since;
};

// Worker `w` of run_tasks, in its own process (after fork): takes task numbers
// from the shared counter until `n` are taken, appends each task's rows and its
// #done line to its file, and exits (status 0 when every write succeeded).
[[noreturn]] void run_worker(const std::vector<Task>& tasks, const std::vector<long>& todo, const ReportArgs& a,
                             const FailureMap* map, const fs::path& work, int session, int w, long n, Shared* sh,
                             Slot* slots, std::atomic<std::int64_t>* cost_ns) {
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
        for (const auto& l : run_task(tasks[std::size_t(k)], a, map))
          text += std::to_string(k) + "\t" + escape_line(l) + "\n";
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

// The time left of a run: the measured costs so far, the tasks not started
// and the running ones; per kind (est.wall), checked against the run's own
// rate so far (the larger of the two).
std::optional<double> time_left_now(TimeLeft& est, std::vector<char>& seen, std::vector<long>& queued,
                                    const std::vector<long>& todo, const std::vector<std::size_t>& kind_of, long n,
                                    const Shared* sh, const Slot* slots, const std::atomic<std::int64_t>* cost_ns,
                                    int jobs, double el) {
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
  if (std::optional<double> by_rate = est.wall_by_rate(queued, busy_kinds, el); left && by_rate)
    left = std::max(*left, *by_rate);
  return left;
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
  const std::size_t bytes =
      sizeof(Shared) + sizeof(Slot) * std::size_t(jobs) + sizeof(std::atomic<std::int64_t>) * std::size_t(n);
  void* mem = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (mem == MAP_FAILED) throw std::runtime_error("mmap failed");
  struct Unmap {
    void* m;
    std::size_t b;
    ~Unmap() { munmap(m, b); }
  } unmap{mem, bytes};
  auto* sh = new (mem) Shared{{0}, {0}};
  auto* slots = reinterpret_cast<Slot*>(static_cast<char*>(mem) + sizeof(Shared));
  auto* cost_ns =
      reinterpret_cast<std::atomic<std::int64_t>*>(reinterpret_cast<char*>(slots) + sizeof(Slot) * std::size_t(jobs));
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
      run_worker(tasks, todo, a, map, work, session, w, n, sh, slots, cost_ns);
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
    if (!show || !cadence.due(std::min(total - 1, before + sh->done.load()), el))
      continue;  // the end has its own line below
    const std::optional<double> left = time_left_now(est, seen, queued, todo, kind_of, n, sh, slots, cost_ns, jobs, el);
    std::fprintf(stderr, "%s[%ld/%ld] %s elapsed, %s (%d worker%s)%s", cadence.begin(), before + sh->done.load(), total,
                 fmt_duration(el).c_str(), time_left_text(left).c_str(), jobs, jobs == 1 ? "" : "s",
                 cadence.end(false));
    std::fflush(stderr);
  }
  const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long finished = sh->done.load();
  if (show)
    std::fprintf(stderr, "%s[%ld/%ld] done in %s%s\n", cadence.begin(), before + finished, total,
                 fmt_duration(el).c_str(), tty ? "\x1b[K" : "");
  if (bad || finished != n)
    throw std::runtime_error("a worker process failed (" + std::to_string(bad) + " of " + std::to_string(jobs) +
                             "); the finished tasks are kept in " + work.string() + " for --resume");
}

}  // namespace eccd::report_detail
