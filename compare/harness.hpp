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
// The coefficients are recomputed by the very functions the pipelines call
// (characteristic_of, characteristic_bernstein, discriminant_of,
// ellipsoid_function), in the pipeline's arithmetic.
// Requirements: a scene with rational motions (the exact pipeline refuses
// cycloidal motions, and so does the harness).
#include "app/solve.hpp"
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
  std::string family = "case";       // colliding | free | touch | near-miss | case
  std::string motion = "case";       // kinematic | euler | affine | case
  int d_exponent = 0;                // near-miss only
  std::optional<std::uint64_t> seed;
};

// From the generator's note if it has one, else a "case" with the scene's motion degree.
SceneInfo scene_info(const Scene& s, const std::string& source);
// The motion degree of a scene (highest degree in t of the entries of M_A, M_B).
int scene_degree(const Scene& s);

struct PipelineSpec {
  std::string label;  // "double/power", "mpfr:128/bezier", "exact", ...
  SolveOptions opt;
  std::string basis, method;
};

struct HarnessOptions {
  std::vector<int> mpfr_bits{53, 64, 80, 100, 128, 160, 192, 256, 384, 512};
  int grid = 64;               // N of the 3D sampling:N and marching:N baselines
  bool mpfr_power_3d = false;  // also run mpfr:B/bezier-power in 3D
};

std::vector<PipelineSpec> harness_pipelines(int dim, const HarnessOptions& opt);

struct ResultRow {
  SceneInfo scene;
  std::string pipeline, arith, basis, method;
  int bits = 0;
  std::optional<double> coef_err, delta_err;
  AnswerMetrics m;
  double time_us = 0;
  std::string error;  // the pipeline's exception message, if any
};

// Every pipeline on one scene; the exact row first.
std::vector<ResultRow> run_scene(const Scene& s, const SceneInfo& info, const HarnessOptions& opt);

// results.csv (the contract with compare/plots/report_figures.py).
std::string results_csv_header();
std::string results_csv_line(const ResultRow& r);

}  // namespace eccd
