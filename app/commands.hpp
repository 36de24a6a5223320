#pragma once
// Sub-commands of `eccd` that live in their own source file. Each adds its
// CLI11 sub-command to the app and returns the function that runs it (called
// by app/main.cpp inside its error handling, README "Exit codes": SceneError,
// OutputError, std::invalid_argument, filesystem errors -> exit 2;
// BudgetExhausted, std::bad_alloc -> exit 5; any other exception -> exit 1, an
// internal error). `run` returns the exit status.
#include "compare/scene_generator.hpp"
#include "kernel/prepared_scene.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <functional>
#include <stdexcept>
#include <string>

namespace eccd {

// The resource budget of this run (README "Limits"), set by app/main.cpp from
// --time-limit and --memory-limit: each pipeline run (a solve, a certify, one
// scene of regress, one task of report) gets time_limit_s seconds
// (kernel/budget.hpp ScopedDeadline; 0 = none); the process's address space is
// capped at memory_limit_mb MiB (0 = none).
struct RunBudget {
  double time_limit_s = 300;
  std::size_t memory_limit_mb = 4096;
};
inline RunBudget& run_budget() {
  static RunBudget b;
  return b;
}

// The backstop of --time-limit for commands that are one pipeline run (solve,
// certify, check-certificate): SIGALRM at 1.5 x the limit + 2 s ends the
// process with exit 5; app/main.cpp.
void arm_backstop(double seconds);

// Validates the generator options (also for report) before any work: exit 2
// for a combination that generates no scene; app/generate.cpp.
void check_plan(const GeneratePlan& plan);
// CLI11 check of a --seed text: "" if it is a decimal integer 0 .. 2^64-1.
std::string check_seed_text(const std::string& text);

// The message of an exception as the command line prints it: a scene the
// exact pipeline refuses (kernel/prepared_scene.hpp, NotRationalMotion)
// already carries the advice (--arith double, mpfr:BITS or certified).
inline std::string cli_message(const std::exception& e) { return e.what(); }

// The program's version (CMake project version) and the source tree's git
// revision at configure time ("unknown" without git); app/main.cpp.
const char* program_version();
const char* program_revision();

// Every JSON object the command line prints carries "format" (what it is, with
// the format's own version: "eccd-solution/1") and "version" (the program's);
// keys are added, none removed (docs/answer-format.md).
template <class Json>
void stamp_format(Json& j, const char* format) {
  j["format"] = format;
  j["version"] = program_version();
}

// --quiet (an option of eccd and of every sub-command): no progress and no
// warnings on stderr, only errors. warn() prints "eccd CMD: warning: TEXT"
// unless quiet.
inline bool& quiet() {
  static bool q = false;
  return q;
}
void warn(const std::string& command, const std::string& text);

// A failure with its exit status (README "Exit codes"): 3 a request the
// pipeline refuses on a valid scene, 4 a scene that cannot be certified.
// app/main.cpp prints it like every error (stderr; and a JSON object on
// stdout under --json) and exits with `code`.
struct ExitError : std::runtime_error {
  int code;
  ExitError(int c, const std::string& m) : std::runtime_error(m), code(c) {}
};

// A scene file's bytes, read once; SCENE "-" reads standard input, and the
// scene's label (in messages and in the answer's "file") is then "<stdin>".
struct SceneSource {
  std::string label, text;
};
SceneSource read_scene_source(const std::string& path);  // app/main.cpp

struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
};

Command add_solve_command(CLI::App& app);              // app/solve.cpp
Command add_table_command(CLI::App& app);              // app/table.cpp
Command add_generate_command(CLI::App& app);           // app/generate.cpp
Command add_report_command(CLI::App& app);             // app/report.cpp
Command add_plot_command(CLI::App& app);               // app/plot.cpp
Command add_certify_command(CLI::App& app);            // app/certify.cpp
Command add_check_certificate_command(CLI::App& app);  // app/certify.cpp
Command add_regress_command(CLI::App& app);            // app/regress.cpp
Command add_judge_command(CLI::App& app);              // app/judge.cpp
Command add_fcl_command(CLI::App& app);                // app/fcl.cpp
Command add_separate_command(CLI::App& app);           // app/separate.cpp
Command add_animate_command(CLI::App& app);            // app/animate.cpp
Command add_import_poses_command(CLI::App& app);       // app/import_poses.cpp

// The generator options shared by `generate` and `report` (--dims, --degrees,
// --families, --motions, --separations); app/generate.cpp.
void add_plan_options(CLI::App* sub, GeneratePlan& plan);

// Folder of the Python drawing scripts (compare/plots): $ECCD_PLOTS_DIR if
// set, otherwise the source tree's folder compiled in at build time.
std::string plots_dir();

// Draws the scene file SCENE into the PNG file PNG as `eccd plot SCENE --out PNG` does (defaults, exact
// arithmetic), printing nothing on stdout; returns plot's exit status (0 written, else nothing written:
// the reason is on stderr). app/plot.cpp; `eccd report` draws the failure map's scene with it.
int draw_scene_picture(const std::string& scene, const std::string& png);

}  // namespace eccd
