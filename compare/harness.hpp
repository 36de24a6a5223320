#pragma once
// The comparison harness: every pipeline on the same scene, measured against
// the exact pipeline (ground truth).
//
// Statement. For one scene the harness runs
//   2D: exact CD-DISC; double and MPFR CD-DISC with Δ built in power form,
//       Bernstein form and (double) scaled Bernstein form (003 VI-C);
//   3D: the exact projection CCD; the Bézier zero-set method (001 section 4)
//       with f set up in Bernstein form (`bezier`) and in power form
//       (`bezier-power`) in double, the Bernstein setup also in MPFR; the
//       sampling and the marching-squares baselines (002 IV) in double (the
//       floating projection is left out: on degree-6 scenes its root finder
//       can take minutes);
// and records per pipeline the metrics of compare/metrics.hpp: coefficient
// error of g_0..g_n (in the basis the pipeline holds them: power form for
// `power`, Bernstein form otherwise), of Δ as handed to the root finder (2D,
// Bernstein coefficients) or of the control points of F(u, t) (3D), the
// answer comparison, and the time of the query as `eccd solve` reports it.
// Because those coefficient errors are measured in different bases, each row
// also carries coef_err_common: the pipeline's g_0..g_n changed exactly to the
// Bernstein basis on [0, 1] and compared there (compare/metrics.hpp), the one
// column that compares power-form and Bernstein-form pipelines.
// The coefficients are recomputed by the very functions the pipelines call
// (characteristic_of, characteristic_bernstein, discriminant_of,
// ellipsoid_function), in the pipeline's arithmetic.
// Coefficient errors are measured for the prepared input mode only (they are
// recomputed from the prepared scene); rounded rows leave them empty.
// Every run is bounded: each floating run under a
// ScopedDeadline of `budget_s` (kernel/budget.hpp); a run that hits it, or
// comes back later than it, is recorded as undecided with the reason "time
// budget". The exact run has its own, larger budget; when it is exhausted the
// scene has no ground truth and run_scene throws BudgetExhausted.
// Input modes: each floating pipeline runs once per mode
// in `inputs`: "rounded" (the scene's numbers rounded to the arithmetic, as a
// user's program holds them) and "prepared" (coefficients prepared exactly,
// then rounded). The row's `input` is what the pipeline's JSON says it used
// ("input"); a solver without input modes starts from the prepared scene, and
// then only "prepared" rows are written. Rows of the mode "prepared" carry the
// label suffix "@prepared" when both modes are run, so that the report can put
// the error of rounding the input apart from the error of the computation.
// Peer pipelines: `certified` (api/solve.hpp with
// Arithmetic::certified(): interval arithmetic climbing to exact,
// certified/ladder.hpp) runs like a floating run, bounded by the same
// budget_s (a time-out is undecided, not a failure of the scene); bits 0,
// basis none, method ladder, input prepared. When FCL is built in
// (compare/fcl_engine.hpp) `fcl/sample:N` (method sample:N) and `fcl/ccd:N`
// (method ccd:N) for each N of fcl_samples: bits 53, basis none, input
// rounded, run in the harness's process (FCL's calls do not ask a deadline;
// each is bounded by N + 1 GJK queries). fcl/ccd:N answers collides and
// first_contact only, so its row is compared with the exact answer's
// first-contact view (fcl_engine.hpp first_contact_view: collides and first
// contact; intervals and contacts are not claimed, so they are not charged),
// and its structure_ok means collides and the first contact agree. A scene
// whose motions FCL's translation motion cannot express gets no fcl/ccd row
// (fcl_skipped counts them from the rows).
// Faces (docs/architecture.md, "Two faces"): every double and MPFR pipeline runs in each
// face of HarnessOptions::guards, "none" (the algorithm as published, in plain
// T: its errors are the measurement) and "bound" (guarded by the running error
// bound: an unsure sign makes the place undecided). The row's `guard` says
// which; the as-published row's label carries "/published" before any
// "@prepared" ("double/bernstein/published@prepared"), the guarded row keeps
// the plain label ("double/bernstein@prepared"). Exact, certified, FCL and
// external rows have no face (guard empty). Cycloidal pipelines exist in the
// guarded face only (api/solve.cpp).
// Scenes of the motion families (a cycloidal motion, or "parameters":
// "independent") have their own pipelines and ground truth:
// compare/harness_families.hpp (run_scene hands them over).
// Requirements: none beyond a scene the reader accepted.
#include "api/solve.hpp"
#include "compare/external_answers.hpp"
#include "compare/fcl_engine.hpp"
#include "compare/metrics.hpp"
#include "kernel/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace eccd {

struct SceneInfo {
  std::string name;
  std::string source = "generated";  // generated | cases
  int dim = 2, degree = 0;
  std::string family = "case";  // colliding | free | touch | near-miss | overlap | graze | decimal | keyframe | case
  std::string motion = "case";  // kinematic | euler | affine | translation | case
  int d_exponent = 0;           // near-miss: separation 10^-e; overlap: depth 10^-e
  int digits = 0;               // decimal, keyframe: significant digits of the scene's numbers
  std::optional<std::uint64_t> seed;
};

// From the generator's note if it has one, else a "case" with the scene's motion degree.
SceneInfo scene_info(const Scene& s, const std::string& source);
// The motion degree of a scene (highest degree in t of the entries of M_A, M_B).
int scene_degree(const Scene& s);

struct PipelineSpec {
  std::string
      label;  // "double/power", "mpfr:128/bezier", "exact", "double/power@prepared", "certified", "fcl/sample:100", ...
  SolveOptions opt;  // eccd's pipelines (engine solve)
  std::string basis, method;
  std::string input = "prepared";  // rounded | prepared (exact: prepared)
  std::string guard;               // floating: none (as published) | bound (guarded); "" otherwise
  std::string arith;               // the CSV's arith: exact | double | mpfr | certified | fcl
  int bits = 0;                    // the CSV's bits
  enum class Engine { solve, fcl_sample, fcl_ccd } engine = Engine::solve;
  int fcl_n = 0;  // N of fcl/sample:N and fcl/ccd:N
};

// Whether api/solve.hpp's SolveOptions has an input mode (`input`, an enum
// with the values rounded and prepared); if not, floating runs start from the
// prepared scene.
bool solver_has_input_modes();
// The input modes a run uses by default: both where the solver has them.
std::vector<std::string> default_input_modes();
// Sets opt's input mode ("rounded" or "prepared"; std::invalid_argument
// otherwise); a no-op for a solver without input modes.
void apply_input_mode(SolveOptions& opt, const std::string& mode);

// One floating run under a time budget of processor seconds (a ScopedDeadline
// on DeadlineClock::thread_cpu, kernel/budget.hpp: which runs are undecided
// does not depend on what else the machine runs, and report workers running
// side by side do not eat each other's budgets). With `isolate` the run
// happens in a forked child process that is killed once it has used
// 2 x budget + 1 s of processor time (or, as a backstop, after minutes of
// wall-clock time), so that a pipeline which does not ask the deadline (or is
// stuck in a library call) still cannot hold up the caller; without it the
// budget is the ScopedDeadline alone.
// `timed_out`: the run hit its budget (BudgetExhausted), came back after it,
// or was killed; `reason` says which. `error`: the exception message of a run
// that failed otherwise (then `got` is empty). The child sends its Solution
// back as JSON (io/solution_json.hpp, both ways). The child's first run pays
// the fresh process's first touches of memory (copy-on-write pages of the
// parent's heap: up to x10 on a run of half a millisecond, the report's 2D
// degree-6 scenes); a run that answers in under 50 ms and a quarter of its
// budget runs once more in the child, and got->time_ms is the second run's
// (the answer the first's: runs are deterministic).
struct BoundedRun {
  std::optional<Solution> got;  // the run's solution (none: it failed, hit its budget or was killed)
  bool timed_out = false;       // no answer used: the budget ran out (or the answer came after it)
  bool killed = false;          // the run did not stop by itself within 2 x budget + 1 s and was killed
  std::string error, reason;
  double wall_s = 0;
  double cpu_s = 0;  // processor time of the run (the child's user + system time when isolated)
};
BoundedRun run_bounded(const Scene& s, const SolveOptions& opt, double budget_s, bool isolate);

struct HarnessOptions {
  std::vector<int> mpfr_bits{53, 64, 80, 100, 128, 160, 192, 256, 384, 512};
  int grid = 64;                                            // N of the 3D sampling:N and marching:N baselines
  bool mpfr_power_3d = false;                               // also run mpfr:B/bezier-power in 3D
  std::vector<std::string> inputs = default_input_modes();  // input modes of the floating pipelines
  std::vector<std::string> guards{"none", "bound"};         // faces of the floating pipelines (as published, guarded)
  double budget_s = 10;         // time budget of one floating run (processor seconds, run_bounded; <= 0: none)
  double exact_budget_s = 600;  // time budget of the exact run (ground truth)
  bool isolate = true;          // each floating run in a child process killed at 2 x budget + 1 s (run_bounded)
  std::vector<ExternalEngine> externals;        // report --external: a row "ext:NAME" per scene with an answer file
  bool certified = true;                        // the certified pipeline (under budget_s like a floating run)
  bool fcl = fcl_availability().available;      // the fcl/ pipelines (ignored when FCL is not built in)
  std::vector<int> fcl_samples{10, 100, 1000};  // N of fcl/sample:N and fcl/ccd:N (each >= 2)
};

std::vector<PipelineSpec> harness_pipelines(int dim, const HarnessOptions& opt);

// The label suffix of an as-published row ("double/bernstein" + it).
inline constexpr const char* kPublishedSuffix = "/published";
// One floating spec in each face of `guards` ("none", "bound"; std::invalid_argument
// otherwise): opt.guard set, guard named, the as-published label marked (see above).
std::vector<PipelineSpec> in_faces(const PipelineSpec& p, const std::vector<std::string>& guards);

struct ResultRow {
  SceneInfo scene;
  std::string pipeline, arith, basis, method;
  int bits = 0;
  std::optional<double> coef_err, delta_err;
  std::optional<double> coef_err_common;  // coef_err in the common basis (Bernstein on [0, 1]; compare/metrics.hpp)
  AnswerMetrics m;
  double time_us = 0;
  std::string error;   // the pipeline's exception message, if any
  std::string input;   // rounded | prepared: where the floating run started
  std::string reason;  // undecided rows: why (time budget, the pipeline's undecided instants); error rows: the message
  std::string guard;   // floating rows: none (as published) | bound (guarded); "" for the others
  // Guarded rows that answered: 0 when the bound decided alone, else the answer's work counter second_look (1 the
  // second look in 128-bit MPFR ran, 2 it decided; api/solve.cpp); empty for the other rows and for time-outs.
  std::optional<int> second_look;
};

// The row of pipeline `ps` on the scene `info`, before its run: the scene's and the pipeline's columns.
ResultRow pipeline_row(const SceneInfo& info, const PipelineSpec& ps);

// A row's outcome, metrics, time, input and reason from one run (br.got, or
// its time-out or error) against the ground-truth answer `truth`.
void fill_row_from_run(ResultRow& row, BoundedRun&& br, const Answer& truth);

// Every pipeline on one scene; the exact row first, the external engines' rows
// (compare/external_answers.hpp; arith "external", basis "none") last.
std::vector<ResultRow> run_scene(const Scene& s, const SceneInfo& info, const HarnessOptions& opt);

// Per fcl/ccd pipeline label of `labels`, the number of scenes of `csv_rows`
// (results_csv_line records; a scene counts when it has an exact row) that
// have no row of that pipeline: the scenes FCL's motion could not express.
std::vector<std::pair<std::string, int>> fcl_skipped(const std::vector<std::string>& labels,
                                                     const std::vector<std::string>& csv_rows);

// results.csv (the contract with compare/plots/report_figures.py).
std::string results_csv_header();
std::string results_csv_line(const ResultRow& r);

}  // namespace eccd
