#pragma once
// The parts of `eccd report` shared by its files: the run's options (ReportArgs), its tasks and
// the failure map, the worker files, interrupts, and the functions each file offers the others.
//   app/report.cpp         the command: plan the tasks, run them, write the report (run_report)
//   app/report_pool.cpp    the worker processes and their files, the failure map's cells, task kinds
//   app/report_resume.cpp  the plan file, --resume's checks and the lock on NAME.partial
//   app/report_output.cpp  the output folder, results.csv's order, meta.json, scene files, the scripts
//   app/report_merge.cpp   --merge: joining the parts written by --shard
#include "compare/harness.hpp"
#include "compare/scene_generator.hpp"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace eccd::report_detail {

namespace fs = std::filesystem;

struct ReportArgs {
  std::string name;  // --name; without --name and --out-dir: a new reports/run-YYYYMMDD-HHMMSS
  std::string out;
  bool out_given = false;  // --out-dir given (even as '')
  bool name_given = false;
  bool resume = false;  // --resume
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

struct TaskOutput {
  std::vector<std::string> lines;  // "R..." rows, "M..." map cells, "E..." a failure
  double seconds = 0;              // the task's wall time in its worker
};
struct WorkerFiles {
  std::map<long, TaskOutput> done;  // by task number (the place in the plan)
  int sessions = 0;                 // highest SESSION among the files
};

// The largest file report reads back of its own (a part's meta.json and CSVs,
// a worker file, the plan): a bound on memory against a file replaced by
// something else; the real ones are kilobytes to a few megabytes.
constexpr std::size_t kMaxReportFileBytes = std::size_t(256) << 20;

// SIGINT / SIGTERM / SIGHUP (InterruptGuard below): the parent stops its workers, keeps
// NAME.partial if it can be resumed (a plan file and finished tasks; it prints
// the command that resumes) or removes it, and exits 130.
extern volatile sig_atomic_t g_interrupted;
void on_interrupt(int sig);
extern int
    g_lock_fd;  // PartialLock's descriptor: closed in the workers, so their own children (run_bounded) never hold it

struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// SIGINT / SIGTERM / SIGHUP (a closed terminal) from the moment the output
// folder exists: the handler only notes the signal; the parent stops its
// workers (run_tasks), then keeps or removes NAME.partial (run_report) and
// exits 130.
struct InterruptGuard {
  struct sigaction old_int {
  }, old_term{}, old_hup{};
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
std::string signal_name();

// Output folders: every folder `report` writes carries this marker, and only
// a folder with it (or an older report folder holding nothing but report files)
// is ever replaced or removed (app/atomic_write.hpp).
const char* const kMarker = ".eccd-report";

// NAME.partial/plan.json: what decides a run's results, written before the
// first task runs, so that --resume can tell whether the finished tasks in the
// worker files belong to the run it is asked for. "options" are compared key
// by key (the first difference is named); "tasks_digest" (FNV-1a over every
// task's kind, label, source and scene text) catches a changed --cases or
// --scenes folder. Options that do not change a result (--jobs, --name, --out-dir,
// --no-figures, --quiet) are not in it.
const char* const kPlanFile = "plan.json";

// app/report_pool.cpp
FailureMap make_failure_map(std::uint64_t seed, int n);
std::string map_cell_scene(const FailureMap& f, int ix, int iy);
int worker_file_session(const std::string& n);
WorkerFiles read_worker_files(const fs::path& work, long tasks);
std::pair<std::string, double> task_kind(const Task& t, int dim, int degree);
void run_tasks(const std::vector<Task>& tasks, const std::vector<long>& todo, const std::vector<std::size_t>& kind_of,
               const std::vector<std::string>& kind_names, const std::vector<double>& prior, const WorkerFiles& reused,
               const ReportArgs& a, const FailureMap* map, const fs::path& work, int session);

// app/report_resume.cpp
nlohmann::ordered_json report_plan(const ReportArgs& a, const std::vector<Task>& mine, const std::string& shard,
                                   const std::string& started);
WorkerFiles check_resume(const fs::path& partial, const nlohmann::ordered_json& plan);

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
void refuse_busy(const fs::path& partial);
std::string resume_command(const ReportArgs& a, const std::string& name);

// app/report_output.cpp
std::string shell_quote(const std::string& s);
std::string read_command_output(const std::string& cmd);
std::string command_line();
nlohmann::json machine_info();
std::string now_iso();
void write_file(const fs::path& p, const std::string& text);
std::vector<std::string> split(const std::string& s, char sep);
std::string fmt_duration(double s);
void sort_results(std::vector<std::string>& lines);
void sort_map(std::vector<std::string>& lines, const std::vector<std::string>& order);
void write_scene_files(const fs::path& partial, const fs::path& out, const std::vector<Task>& tasks,
                       const FailureMap* map);
nlohmann::ordered_json read_scene_index(const fs::path& file);
void merge_scene_files(const fs::path& partial, const fs::path& out,
                       const std::vector<std::pair<fs::path, nlohmann::ordered_json>>& parts);
void write_map_picture(const fs::path& partial, const std::string& scene);
void run_figures(const fs::path& dir);
bool looks_like_old_report(const fs::path& dir);
fs::path output_folder(const ReportArgs& a, const std::string& suffix, std::string& name);
void start_partial(const fs::path& partial, const fs::path& out);
void finish_output(const fs::path& partial, const fs::path& out);
nlohmann::json fcl_meta(const HarnessOptions& h, const std::vector<std::string>& labels,
                        const std::vector<std::string>& rows);
nlohmann::json externals_meta(const nlohmann::json& engines, const std::vector<std::string>& rows);
nlohmann::json report_meta(const ReportArgs& a, const std::string& name, const std::string& started,
                           std::chrono::steady_clock::time_point t_start, int shard_n, std::size_t generated,
                           std::size_t from_cases, const std::vector<std::string>& failures,
                           const std::vector<std::string>& rows, const std::vector<std::string>& cells,
                           const WorkerFiles& reused, const std::optional<FailureMap>& map);

// app/report_merge.cpp
int run_merge(const ReportArgs& a);

}  // namespace eccd::report_detail
