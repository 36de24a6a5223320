// eccd: the workbench's command-line front door: the dispatch to the
// sub-commands, each in its own file, and the exit statuses.
//   eccd solve SCENE [--arith ...] [--basis ...] [--input ...] [--variant N] [--json]   app/solve.cpp
//   eccd table [DIR] [--mpfr BITS ...] [--json]   every scene of DIR in every arithmetic, side by side; app/table.cpp
//   eccd generate / report / plot                 app/generate.cpp, app/report.cpp, app/plot.cpp
//   eccd certify / check-certificate              app/certify.cpp
//   eccd regress [DIR]                            app/regress.cpp
// Exit status (README "Exit codes", docs/exit-codes.md): 0 success; 1 a
// rejected certificate (check-certificate), a regression (regress) or an answer
// that differs (judge); 70 an internal error (a bug: any exception nobody
// expected, caught here or by the terminate handler, never an abort); 2 bad
// input or a bad option, including input beyond the input limits and output
// paths that cannot be written; 3 a request the pipeline refuses (e.g. a
// cycloidal motion in exact arithmetic, also by certify); 4 a scene the
// certifier cannot certify; 5 a resource budget (time, memory) exhausted while
// solving; 130 report interrupted (SIGINT/SIGTERM). Nothing is written to
// stdout unless the command succeeds, except under --json: a failing command
// then prints one object {"format": "eccd-error/1", "error", "exit_code"} on
// stdout (the message is on stderr too). Every message is made valid UTF-8
// first (io/utf8_text.hpp: a file name or a quoted byte that is not UTF-8 is
// shown as \xNN, and the message says so), on stderr and in the JSON alike.
//
// eccd --version prints the version and the git revision of the source tree
// at configure time; --quiet (of eccd and every sub-command) keeps progress
// and warnings off stderr (errors are still printed).
//
// Resource budget: --time-limit SECONDS per pipeline run (default
// 300), --memory-limit MIB for the process (setrlimit RLIMIT_AS, default 4096),
// --max-file-bytes / --max-digits / --max-degree for scene files
// (io/scene_reader.hpp InputLimits). They are options of `eccd` and of
// every sub-command.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "kernel/budget.hpp"
#include "io/scene_reader.hpp"
#include "io/utf8_text.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <sstream>

namespace fs = std::filesystem;
using namespace eccd;

namespace {

// The backstop of --time-limit for commands that are one pipeline run (solve,
// certify, check-certificate): if a loop does not ask the deadline
// (kernel/budget.hpp), SIGALRM at 1.5 x the limit + 2 s ends the process with
// exit 5 (nothing on stdout; output files are only ever renamed into place).
void on_backstop(int) {
  remove_pending_output();  // a temporary output file being written (app/atomic_write.hpp)
  static const char msg[] =
      "eccd: resource budget exhausted: the time limit passed (--time-limit) and the run did not stop by itself; "
      "ended\n";
  ssize_t n = write(2, msg, sizeof msg - 1);
  (void)n;
  _exit(5);
}
}  // namespace

void eccd::arm_backstop(double seconds) {
  if (seconds <= 0) return;
  double at = seconds * 1.5 + 2;
  struct sigaction sa {};
  sa.sa_handler = on_backstop;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGALRM, &sa, nullptr);
  itimerval t{};
  t.it_value.tv_sec = time_t(at);
  t.it_value.tv_usec = suseconds_t((at - double(time_t(at))) * 1e6);
  setitimer(ITIMER_REAL, &t, nullptr);
}

const char* eccd::program_version() {
#ifdef ECCD_VERSION
  return ECCD_VERSION;
#else
  return "unknown";
#endif
}
const char* eccd::program_revision() {
#ifdef ECCD_GIT_REVISION
  return ECCD_GIT_REVISION;
#else
  return "unknown";
#endif
}
void eccd::warn(const std::string& command, const std::string& text) {
  if (!quiet()) std::cerr << "eccd " << command << ": warning: " << text << "\n";
}

SceneSource eccd::read_scene_source(const std::string& path) {
  if (path != "-") return {path, read_file_bytes(path)};
  try {
    return {"<stdin>", read_file_bytes("/dev/stdin")};
  } catch (const SceneError& e) {
    std::string m = e.what();
    const std::string dev = "/dev/stdin";
    if (m.rfind(dev, 0) == 0) m = "<stdin>" + m.substr(dev.size());
    throw SceneError(m);
  }
}

namespace {

// A message for stderr: at most 2000 characters (a user's 10 MB key is not echoed whole).
std::string cut_message(const std::string& m) { return m.size() > 2000 ? m.substr(0, 2000) + "... (cut)" : m; }

// Exit 70 for what nobody caught (an exception thrown from a thread or a
// noexcept function, an exception while one is in flight): the message of the
// exception if there is one, never an abort. Only async-signal-safe calls
// after the message is formed (the process may be in any state).
bool g_json_mode = false;
[[noreturn]] void on_terminate() {
  std::string m = "internal error: terminated";
  if (std::exception_ptr p = std::current_exception()) {
    try {
      std::rethrow_exception(p);
    } catch (const std::exception& e) {
      m = std::string("internal error: ") + e.what();
    } catch (...) {
      m = "internal error: an exception of unknown type";
    }
  }
  m = utf8_for_json(cut_message(m));
  std::string line = "eccd: " + m + "\n";
  ssize_t n = write(2, line.data(), line.size());
  if (g_json_mode) {
    nlohmann::json j = {{"format", "eccd-error/1"}, {"version", program_version()}, {"error", m}, {"exit_code", 70}};
    std::string t = j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    std::fflush(stdout);
    n = write(1, t.data(), t.size());
  }
  (void)n;
  _exit(70);
}

}  // namespace

namespace {
int run_main(int argc, char** argv);
}

int main(int argc, char** argv) {
  std::set_terminate(on_terminate);
  try {
    return run_main(argc, argv);
  } catch (const std::exception& e) {  // thrown while setting up the options, or by the error path itself
    std::string m = utf8_for_json(cut_message(std::string("internal error: ") + e.what()));
    std::cerr << "eccd: " << m << "\n";
    return 70;
  } catch (...) {
    std::cerr << "eccd: internal error: an exception of unknown type\n";
    return 70;
  }
}

namespace {
// The program's own options and behaviour: one sub-command, errors that
// start with "eccd: ", --version, --quiet, and the budget (options of eccd
// and, through fallthrough, of every sub-command).
void configure_app(CLI::App& app) {
  app.require_subcommand(1);
  // Parser errors (an unknown option, a bad value) start with "eccd: " like every other error.
  app.failure_message(
      [](const CLI::App* a, const CLI::Error& e) { return "eccd: " + CLI::FailureMessage::simple(a, e); });
  app.fallthrough();  // before the sub-commands are added: they inherit it (the budget options below work after them
                      // too)
  app.set_version_flag("--version", std::string("eccd ") + program_version() + " (git " + program_revision() + ")",
                       "Print the program's version and the git revision it was built from, and exit");
  app.add_flag("-q,--quiet", quiet(), "No progress and no warnings on stderr, only errors");

  // The budget: options of eccd and (through fallthrough) of every sub-command.
  InputLimits& lim = input_limits();
  app.add_option("--time-limit", run_budget().time_limit_s,
                 "Seconds each pipeline run may take (a solve, a certify, one scene of regress, one task of report); "
                 "beyond it the exact pipeline stops with exit 5 and floating ones report undecided; 0 = none")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e9));
  app.add_option("--memory-limit", run_budget().memory_limit_mb,
                 "Address space of the process in MiB (setrlimit RLIMIT_AS); exhausted: exit 5; 0 = none")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t(0), std::size_t(1) << 30));
  app.add_option("--max-file-bytes", lim.max_file_bytes, "Largest scene file read (bytes); larger: exit 2")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
  app.add_option("--max-digits", lim.max_digits,
                 "Most decimal digits in the numerator or denominator of a scene's number (its exact value in lowest "
                 "terms); more: exit 2")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 24));
  app.add_option("--max-degree", lim.max_degree, "Highest degree of a polynomial in a scene file; higher: exit 2")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
}

// --memory-limit: the address space of the process (never above a hard limit already set).
void apply_memory_limit() {
  if (run_budget().memory_limit_mb > 0) {
    rlimit rl{};
    rl.rlim_cur = rl.rlim_max = rlim_t(run_budget().memory_limit_mb) << 20;
    rlimit old{};
    if (getrlimit(RLIMIT_AS, &old) == 0 && old.rlim_max != RLIM_INFINITY && old.rlim_max < rl.rlim_max)
      rl.rlim_cur = rl.rlim_max = old.rlim_max;
    setrlimit(RLIMIT_AS, &rl);
  }
}

// The input file of the command that runs (SCENE or ANIMATION), for messages that do not name it (exit 5).
std::string input_of_command(const std::vector<Command>& commands) {
  for (auto& c : commands)
    if (*c.sub)
      for (const char* n : {"SCENE", "ANIMATION"})
        if (const CLI::Option* o = c.sub->get_option_no_throw(n); o && o->count() > 0) {
          const std::string v = o->as<std::string>();
          return v == "-" ? "<stdin>" : v;
        }
  return "";
}

// Runs the chosen command under its deadline; check-certificate's refusals name the scene.
int run_command(Command& c) {
  // certify and check-certificate are one pipeline run each; regress and
  // report set the deadline per scene / task themselves.
  const bool one_run = c.sub->get_name() == "certify" || c.sub->get_name() == "check-certificate";
  ScopedDeadline deadline(one_run ? run_budget().time_limit_s : 0);
  if (one_run) arm_backstop(run_budget().time_limit_s);
  if (c.sub->get_name() != "check-certificate") return c.run();
  try {
    return c.run();
  } catch (const IndependentMotionsRefused& e) {  // a valid scene the certificate algebra refuses: exit 3
    throw ExitError(3, c.sub->get_option("SCENE")->as<std::string>() + ": " + e.what());
  } catch (const std::invalid_argument& e) {  // e.g. a cycloidal scene: name the file if the message does not
    const std::string scene = c.sub->get_option("SCENE")->as<std::string>();
    std::string m = cli_message(e);
    if (m.find(scene) == std::string::npos) throw std::invalid_argument(scene + ": " + m);
    throw;
  }
}

int run_main(int argc, char** argv) {
  CLI::App app{
      "eccd: exact-arithmetic verification workbench for continuous collision detection of moving ellipses and "
      "ellipsoids"};
  configure_app(app);

  std::vector<Command> commands{add_solve_command(app),
                                add_table_command(app),
                                add_generate_command(app),
                                add_report_command(app),
                                add_plot_command(app),
                                add_certify_command(app),
                                add_check_certificate_command(app),
                                add_regress_command(app),
                                add_judge_command(app),
                                add_fcl_command(app),
                                add_animate_command(app)};
  commands.push_back(add_separate_command(app));      // app/separate.cpp
  commands.push_back(add_import_poses_command(app));  // app/import_poses.cpp

  // Under --json a failure is also one JSON object on stdout (README "Exit codes").
  bool json_mode = false;
  for (int i = 1; i < argc; ++i) json_mode = json_mode || std::string(argv[i]) == "--json";
  auto fail = [&json_mode](int code, const std::string& raw) {
    const std::string message = utf8_for_json(raw);
    std::cerr << "eccd: " << message << "\n";
    if (json_mode) {
      nlohmann::json j = {
          {"format", "eccd-error/1"}, {"version", program_version()}, {"error", message}, {"exit_code", code}};
      std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    }
    return code;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    if (!json_mode) return app.exit(e) == 0 ? 0 : 2;
    return fail(2, e.what());
  }
  json_mode = false;  // from here: --json of the command that runs (not a file or value named "--json")
  for (auto& c : commands)
    if (*c.sub)
      if (const CLI::Option* o = c.sub->get_option_no_throw("--json")) json_mode = o->count() > 0;
  g_json_mode = json_mode;
  apply_memory_limit();

  std::ostringstream hint;
  hint << " (--time-limit " << run_budget().time_limit_s << " s, --memory-limit " << run_budget().memory_limit_mb
       << " MiB)";
  const std::string budget_hint = hint.str();
  try {
    for (auto& c : commands)
      if (*c.sub) return run_command(c);
  } catch (const ExitError& e) {  // 3 refused, 4 cannot certify (the message names the scene)
    return fail(e.code, cut_message(e.what()));
  } catch (const SceneError& e) {
    return fail(2, cut_message(e.what()));
  } catch (const OutputError& e) {
    return fail(2, cut_message(e.what()));
  } catch (const std::invalid_argument& e) {
    return fail(2, cut_message(cli_message(e)));
  } catch (const fs::filesystem_error& e) {  // a file or folder the user named: missing, unreadable, read-only
    std::string p = e.path1().string();
    if (!e.path2().empty()) p += " -> " + e.path2().string();
    return fail(2, cut_message(p) + ": " + e.code().message());
  } catch (const nlohmann::json::parse_error& e) {
    return fail(2, "malformed JSON: " + cut_message(e.what()));
  } catch (const BudgetExhausted& e) {
    std::string m = e.what();
    if (const std::string in = input_of_command(commands); !in.empty() && m.find(in) == std::string::npos)
      m = in + ": " + m;
    return fail(5, "resource budget exhausted: " + cut_message(m) + budget_hint);
  } catch (const std::bad_alloc&) {
    const std::string in = input_of_command(commands);
    return fail(
        5, "resource budget exhausted: " + (in.empty() ? std::string() : in + ": ") + "out of memory" + budget_hint);
  } catch (const std::exception& e) {
    return fail(70, "internal error: " + cut_message(e.what()));
  } catch (...) {
    return fail(70, "internal error: an exception of unknown type");
  }
  return 0;
}
}  // namespace
