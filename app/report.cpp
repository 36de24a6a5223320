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
// The parts are in app/report_parts.hpp and the files it lists.
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

namespace eccd {

namespace report_detail {

// --shard i/n as numbers (0/1 without --shard); std::invalid_argument (exit 2) when it is not i/n with 0 <= i < n.
std::pair<int, int> shard_of(const ReportArgs& a) {
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
    if (shard_n < 1 || shard_i < 0 || shard_i >= shard_n)
      throw std::invalid_argument("--shard " + a.shard + ": expected i/n with 0 <= i < n");
  }
  return {shard_i, shard_n};
}

// The tasks of a run: generated scenes (or the scene files of --scenes), the shipped cases (--cases) and the
// failure map's cells (`map` is set unless --no-map); counts the scenes by where they come from.
std::vector<Task> plan_tasks(const ReportArgs& a, std::size_t& generated, std::size_t& from_cases,
                             std::optional<FailureMap>& map) {
  std::vector<Task> tasks;
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
      Scene s = parse_scene(text, f.string());            // a bad file stops the run before any work (exit 2)
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
      std::fprintf(stderr,
                   "eccd report: %s: %zu generated corpus scene(s) left out (the report generates its own; "
                   "--scenes %s/generated includes them)\n",
                   dir.c_str(), corpus, dir.c_str());
  };
  if (!a.scenes.empty()) add_dir(a.scenes, "generated");
  if (!a.cases.empty()) add_dir(a.cases, "cases");
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
  return tasks;
}

// The output folder: fresh with its plan file, or (--resume) the one an interrupted run left; `lock` holds
// its plan file from here on. Returns the tasks an earlier run finished (none when fresh).
WorkerFiles open_partial(const ReportArgs& a, const fs::path& partial, const fs::path& out,
                         const nlohmann::ordered_json& plan, PartialLock& lock, const std::vector<Task>& mine) {
  WorkerFiles reused;
  if (a.resume) {
    if (!lock.take(partial)) refuse_busy(partial);
    reused = check_resume(partial, plan);
    if (!quiet())
      std::fprintf(stderr, "eccd report: resuming %s: %zu of %zu task(s) finished earlier, %zu to run\n",
                   partial.string().c_str(), reused.done.size(), mine.size(), mine.size() - reused.done.size());
  } else {
    std::error_code ec;
    if (!lock.take(partial)) refuse_busy(partial);
    if (!quiet() && fs::is_regular_file(partial / kPlanFile, ec) && has_marker(partial, kMarker))
      if (std::size_t left = read_worker_files(partial, long(mine.size())).done.size())
        std::fprintf(
            stderr,
            "eccd report: removing the interrupted %s (%zu task(s) finished; --resume would have reused them)\n",
            partial.string().c_str(), left);
    start_partial(partial, out);
    write_text_atomically(partial / kPlanFile,
                          plan.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    if (!lock.take(partial)) refuse_busy(partial);
  }
  return reused;
}

// The kinds of the tasks (kind_names, their prior costs, each task's kind) and the tasks left to run, the
// most expensive kinds first.
std::vector<long> schedule(const std::vector<Task>& mine, const WorkerFiles& reused,
                           std::vector<std::string>& kind_names, std::vector<double>& prior,
                           std::vector<std::size_t>& kind_of) {
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
  std::stable_sort(todo.begin(), todo.end(),
                   [&](long x, long y) { return prior[kind_of[std::size_t(x)]] > prior[kind_of[std::size_t(y)]]; });
  return todo;
}

// Every task's output, in the plan's order: the failures (printed), results.csv's rows and the failure map's
// cells, both written sorted.
void write_rows(const fs::path& partial, const std::vector<Task>& mine, const std::optional<FailureMap>& map,
                std::vector<std::string>& failures, std::vector<std::string>& rows, std::vector<std::string>& cells) {
  WorkerFiles all = read_worker_files(partial, long(mine.size()));
  std::vector<std::string> lines;
  for (long k = 0; k < long(mine.size()); ++k) {
    auto it = all.done.find(k);
    if (it == all.done.end())
      throw std::runtime_error("task " + std::to_string(k) + " (" + mine[std::size_t(k)].label + ") has no output in " +
                               partial.string() + " (a worker file was changed?); run with --resume to run it again");
    for (auto& l : it->second.lines) {
      if (l.empty()) continue;
      if (l[0] == 'E')
        failures.push_back(l.substr(1));
      else
        lines.push_back(l);
    }
  }
  for (const auto& f : failures) std::fprintf(stderr, "eccd: report: failed: %s\n", f.c_str());

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
}

int run_report(const ReportArgs& a) {
  auto t_start = std::chrono::steady_clock::now();
  std::string started = now_iso();
  auto [shard_i, shard_n] = shard_of(a);
  if (a.scenes.empty()) check_plan(a.plan);
  std::string name;
  fs::path out =
      output_folder(a, shard_n > 1 ? "-shard-" + std::to_string(shard_i) + "-of-" + std::to_string(shard_n) : "", name);
  fs::path partial = out;
  partial += ".partial";
  check_replaceable(out, kMarker, looks_like_old_report);  // before any work: never replace what is not ours
  check_replaceable(partial, kMarker);

  // Tasks: generated scenes (or scene files), the shipped cases, the map cells.
  std::size_t generated = 0, from_cases = 0;
  std::optional<FailureMap> map;
  std::vector<Task> tasks = plan_tasks(a, generated, from_cases, map);
  std::vector<Task> mine;
  for (std::size_t k = 0; k < tasks.size(); ++k)
    if (int(k % shard_n) == shard_i) mine.push_back(tasks[k]);
  if (!quiet())
    std::fprintf(stderr, "eccd report: %zu generated scene(s), %zu case(s), %d failure-map cell(s)%s -> %s\n",
                 generated, from_cases, map ? a.map_size * a.map_size : 0,
                 shard_n > 1 ? (", shard " + a.shard + ": " + std::to_string(mine.size()) + " task(s)").c_str() : "",
                 out.string().c_str());

  // The output folder: fresh with its plan file, or (--resume) the one an
  // interrupted run left, with the tasks it finished.
  const nlohmann::ordered_json plan = report_plan(a, mine, shard_n > 1 ? a.shard : "", started);
  InterruptGuard guard;
  PartialLock lock;
  WorkerFiles reused = open_partial(a, partial, out, plan, lock, mine);
  // Interrupted: keep the folder if a later --resume can use it, else remove it.
  auto interrupted = [&]() {
    std::size_t finished = read_worker_files(partial, long(mine.size())).done.size();
    std::string why = "interrupted by " + signal_name() + ": ";
    if (finished > 0) {
      throw Interrupted(why + std::to_string(finished) + " of " + std::to_string(mine.size()) +
                        " task(s) finished are kept in " + partial.string() + "; resume with:\n  " +
                        resume_command(a, name));
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
  std::vector<long> todo = schedule(mine, reused, kind_names, prior, kind_of);
  try {
    run_tasks(mine, todo, kind_of, kind_names, prior, reused, a, map ? &*map : nullptr, partial, reused.sessions + 1);
  } catch (const Interrupted&) {
    interrupted();
  }
  std::vector<std::string> failures, rows, cells;
  write_rows(partial, mine, map, failures, rows, cells);

  nlohmann::json meta =
      report_meta(a, name, started, t_start, shard_n, generated, from_cases, failures, rows, cells, reused, map);
  write_file(partial / "meta.json", meta.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  write_scene_files(partial, out, mine, map ? &*map : nullptr);  // a shard: its own scenes, joined by --merge
  if (g_interrupted) interrupted();
  if (shard_n == 1 && !a.no_figures) {
    try {
      if (map) write_map_picture(partial, map->scene);
      run_figures(partial);
    } catch (const std::exception& e) {
      if (g_interrupted) interrupted();  // Ctrl-C reaches the script too
      throw std::runtime_error(std::string(e.what()) +
                               "\nThe finished tasks are kept; once fixed, this redoes only the report step:\n  " +
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

// `eccd report` once its options are parsed: the --external specs checked (before any work: a bad one is
// exit 2), then a run or a merge; an interrupted one is exit 130.
int run_command(ReportArgs& a) {
  for (const auto& spec : a.externals) {  // checked before any work: a bad spec is exit 2
    ExternalEngine e = parse_external(spec);
    for (const auto& other : a.harness.externals)
      if (other.name == e.name)
        throw std::invalid_argument("--external " + spec + ": the name " + e.name + " is given twice");
    a.harness.externals.push_back(e);
  }
  try {
    return a.merge.empty() ? run_report(a) : run_merge(a);
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "\neccd: report: %s\n", e.what());
    return 130;
  }
}

}  // namespace report_detail

using namespace report_detail;

namespace {

// What each scene is run with: the plan (seed, count, families, ...), the MPFR
// precisions, input modes, guards, time budgets and the baselines' grid.
void add_report_run_options(CLI::App* s, const std::shared_ptr<ReportArgs>& a) {
  s->add_option("--seed", a->plan.seed, "Run seed (same seed, same scenes, same numbers apart from timings)")
      ->capture_default_str()
      ->check(check_seed_text);
  s->add_option("--count", a->plan.count, "Generated scenes per dimension x degree x family x motion (x separation)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  add_plan_options(s, a->plan);
  s->add_option("--mpfr-bits", a->harness.mpfr_bits, "MPFR precisions in bits")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(53, 65536));
  add_old_spelling(s, "--mpfr", "--mpfr", "--mpfr-bits", a->harness.mpfr_bits)
      ->delimiter(',')
      ->check(CLI::Range(53, 65536));
  s->add_option("--input", a->harness.inputs,
                "Input modes of the floating pipelines, each a row of its own: rounded (the scene's numbers rounded to "
                "the arithmetic) and prepared (coefficients prepared exactly, then rounded); a solver without input "
                "modes runs prepared only")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"rounded", "prepared"}));
  s->add_option(
       "--guard", a->harness.guards,
       "Faces of the double and MPFR pipelines, each a row of its own: none (the algorithm as published, in plain "
       "double or MPFR: its errors are the measurement; labels ending in /published) and bound (guarded by the "
       "running error bound: an unsure sign is undecided); the report's guard record needs both")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "bound"}));
  s->add_option("--budget", a->harness.budget_s,
                "Time budget of one floating pipeline run in seconds of its processor time (a run that hits it is "
                "undecided, reason time budget; processor time, so a busy machine does not change the report)")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 86400.0));
  s->add_option("--exact-budget", a->harness.exact_budget_s,
                "Time budget of the exact run of one scene in seconds (exhausted: the scene fails)")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 864000.0));
  s->add_option("--grid", a->harness.grid, "N of the 3D sampling:N and marching:N baselines")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
}

// Which scenes (generated, cases, a folder), how many workers, parts for
// --shard / --merge, the failure map and the figures.
void add_report_scene_options(CLI::App* s, const std::shared_ptr<ReportArgs>& a) {
  s->add_option("--cases", a->cases,
                "Also run the scene files under this folder (their stored answers are not used: exact is recomputed; "
                "scenes written by eccd generate are left out, see --scenes); '' for none")
      ->capture_default_str();
  s->add_option("--scenes", a->scenes, "Run the scene files under this folder instead of generating scenes");
  s->add_option("--jobs", a->jobs, "Worker processes (default: the number of cores)");
  add_old_spelling(s, "--threads", "--threads", "--jobs", a->jobs);
  s->add_option(
      "--shard", a->shard,
      "i/n: run only every n-th task starting at i and write the raw part (results.csv, meta.json) for --merge");
  s->add_option("--merge", a->merge, "Join the part folders written by --shard runs into one report")->expected(1, -1);
  s->add_option("--map-size", a->map_size,
                "Failure map: n x n cells (units in the last place around the touching input)")
      ->capture_default_str()
      ->check(CLI::Range(2, 1024));
  s->add_flag("--no-map", a->no_map, "Skip the failure map");
  s->add_flag("--no-figures", a->no_figures, "Write the CSV and meta.json only (no report.md, no PNG)");
}

// The other engines: --external answers, FCL and the certified pipeline.
void add_report_peer_options(CLI::App* s, const std::shared_ptr<ReportArgs>& a) {
  s->add_option(
       "--external", a->externals,
       "NAME=DIR: your engine's answers as rows ext:NAME in every table and plot, judged against the exact answer "
       "like eccd's pipelines; DIR holds one answer file per scene, DIR/<scene name>.json, in any form `eccd judge` "
       "reads (docs/answer-format.md), optionally with \"time_us\"; scenes without a file get no row "
       "(meta.json counts them). Repeat for several engines. `eccd generate --out-dir DIR` writes the generated "
       "scenes for your engine to answer.")
      ->expected(1, -1);
  // Peer pipelines (compare/harness.hpp): certified, and FCL when it is built in.
  auto* fcl_opt =
      s->add_option(
           "--fcl-samples", a->harness.fcl_samples,
           "N of the FCL pipelines fcl/sample:N and fcl/ccd:N, a comma list (when FCL is built in; docs/fcl.md)")
          ->delimiter(',')
          ->capture_default_str()
          ->check(CLI::Range(2, 1000000));
  s->add_flag_callback(
      "--no-fcl", [a] { a->harness.fcl = false; },
      "Skip the FCL pipelines (meta.json still says whether FCL is built in)");
  s->add_flag_callback(
      "--no-certified", [a] { a->harness.certified = false; }, "Skip the certified pipeline (arith certified)");
  s->parse_complete_callback([a, fcl_opt] {  // a warning for an option that changes nothing
    if (fcl_opt->count() && !fcl_availability().available)
      warn("report", "--fcl-samples is ignored: " + fcl_availability().reason);
    else if (fcl_opt->count() && !a->harness.fcl)
      warn("report", "--fcl-samples is ignored: --no-fcl");
  });
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
      "near-miss, overlap / graze (linear translations, degree 1), and the realistic-input families decimal / "
      "keyframe; "
      "--families cycloidal,independent adds the cycloidal and independent motion families, against the certified "
      "resp. exact answer), "
      "add the shipped cases, run every pipeline (2D: double power / Bernstein / scaled Bernstein and MPFR "
      "power / Bernstein at many precisions; 3D: the Bezier method with f set up in Bernstein form (double, MPFR) and "
      "in "
      "power form (double), the sampling and marching baselines), each floating one as published and guarded "
      "(--guard), "
      "per input mode (--input) and under a "
      "time budget (--budget), against the exact pipeline, and write "
      "a new folder reports/run-YYYYMMDD-HHMMSS/ (or reports/NAME/ with --name, --out-dir PATH): report.md, "
      "results.csv, "
      "failure_map.csv, meta.json and PNG figures. Progress and time left go to stderr (--quiet: none); Ctrl-C keeps "
      "the finished tasks for --resume.");
  auto* s = c.sub;
  auto* name_opt = s->add_option(
      "--name", a->name,
      "Report name: the output goes to reports/NAME (a plain name: no '/', no '..'; an existing reports/NAME is "
      "replaced only if an earlier eccd report wrote it). Without --name and --out-dir every run writes a new folder "
      "reports/run-YYYYMMDD-HHMMSS (UTC start time); --name default refreshes the checked-in example reports/default");
  auto* out_opt =
      s->add_option("--out-dir", a->out,
                    "Output folder instead of reports/NAME (replaced only when the run succeeds, and only if an "
                    "earlier eccd report wrote it); no '..'");
  auto* old_out_opt = add_old_spelling(s, "--out", "--out", "--out-dir", a->out);
  add_report_run_options(s, a);
  add_report_scene_options(s, a);
  add_report_peer_options(s, a);
  s->add_flag(
      "--resume", a->resume,
      "Continue an interrupted run (Ctrl-C, SIGTERM, a crash): reuse the tasks it finished in its NAME.partial folder "
      "and run the rest. Give the same options (and --name/--out-dir; without them the newest reports/run-*.partial); "
      "a folder of another plan (seed, options, scenes, build) is refused with exit 2");
  c.run = [a, out_opt, old_out_opt, name_opt]() {
    a->out_given = out_opt->count() > 0 || old_out_opt->count() > 0;
    a->name_given = name_opt->count() > 0;
    return run_command(*a);
  };
  return c;
}

}  // namespace eccd
