#pragma once
// The harness on scenes of the motion families: a cycloidal motion
// (003 section V) or independent motions A(s), B(t) (001 section 4). Their
// pipelines and ground truth differ from the rational shared-parameter
// scenes of compare/harness.hpp, which hands them over (run_scene).
//
// Statement. Ground truth is a proved answer, never a guess:
//   cycloidal    exact arithmetic cannot represent the motion, so the ground
//                truth is the certified answer (certified/ladder.hpp,
//                run_certified_cycloidal: MPFI enclosures, proved brackets of
//                the simple roots of Δ). Its row is the pipeline `certified`
//                with reason "ground truth: ..." (the report leaves it out of
//                the tables: it is compared with itself). Pipelines: double
//                and MPFR at each --mpfr precision, labelled
//                ARITH/cycloidal (basis pointwise, method cd-disc-cycloidal),
//                input rounded only (the scene's numbers are rounded to the
//                arithmetic; there is no prepared form of a cycloidal motion).
//   independent  the exact answer (s_intervals, t_intervals: api/solve.cpp;
//                exact/independent_balls.hpp for two balls on straight lines).
//                Pipelines: exact (first) and the subdivision of F(u, s, t) in
//                double and MPFR (floating/independent_ccd.hpp), labelled
//                ARITH/independent (basis bernstein, method
//                bezier-independent), input prepared (F is built from the
//                exactly prepared pair). Answers are compared by
//                api/answer_difference.hpp, which matches s_intervals and
//                t_intervals like collision intervals; the CSV's `intervals`
//                counts both lists. These runs are bounded by the deadline
//                alone (not isolated in a child process: the pipeline asks
//                the deadline, and its undecided answers do not survive the
//                child's JSON round trip).
// A scene whose ground truth cannot be had — the exact pipeline throws
// std::invalid_argument (independent ellipsoids before exact answers them),
// or the certified answer leaves a stretch undecided (a cycloidal touch or
// near miss within ε: a double root of Δ is never proved) — still gets a row
// per pipeline (what each said), with outcome `no_ground_truth`, the
// exact_collides and exact_intervals fields empty and the reason
// "no ground truth: WHY"; the report counts those scenes (meta.json
// "no_ground_truth") and keeps them out of every table.
// Requirements: a scene with a cycloidal motion or independent motions.
#include "compare/harness.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace eccd {

inline constexpr const char* kNoGroundTruthOutcome = "no_ground_truth";
inline constexpr const char* kNoGroundTruthReason = "no ground truth: ";

// Is the scene one the motion families' harness runs (a cycloidal motion, or independent motions)?
bool motion_family_scene(const Scene& s);
// Its pipelines, the ground truth first (label certified or exact).
std::vector<PipelineSpec> motion_family_pipelines(const Scene& s, const HarnessOptions& opt);
// The rows of one such scene (see above); throws BudgetExhausted when the
// ground truth's budget (exact_budget_s) runs out, like run_scene.
std::vector<ResultRow> run_motion_family_scene(const Scene& s, const SceneInfo& info, const HarnessOptions& opt);

// meta.json's "no_ground_truth" from results.csv records: {"scenes": N, "list": [{"scene", "reason"}]}, one
// entry per scene whose rows have outcome no_ground_truth (the reason of its first row).
nlohmann::json no_ground_truth_meta(const std::vector<std::string>& csv_rows);

}  // namespace eccd
