#pragma once
// The certified ladder (`--arith certified`, the arithmetic: docs/architecture.md): in 3D first the Bézier proof
// (certified/bezier_proof.hpp: 001 section 4 in intervals, no projection
// polynomial; decided_in "bezier"), then the 2D or 3D projection
// pipeline (kernel/cd_disc.hpp, kernel/ccd_projection.hpp) in interval
// arithmetic, up a ladder of rungs — intervals of doubles, then MPFI
// intervals at each precision of `mpfi_rungs` (increasing) — and, where every
// rung leaves a sign uncertain (Escalate, certified/certified_policy.hpp, or
// an undecided instant), the exact pipeline (exact/cd_disc_exact.hpp). The
// Solution is certified whichever rung decided; decided_in names that rung,
// escalations why each lower rung gave up, its time and its budget.
//
// Cost guarantee. Let I be the time the interval rung took, X the
// time of the exact pipeline on the same prepared pair (run_exact below: what
// `--arith exact` runs after preparing the scene), and δ the longest stretch
// of one rung between two looks at its deadline (one polynomial product or
// one isolation piece in that rung's arithmetic; kernel/budget.hpp). By
// construction (each rung runs under a ScopedDeadline nested in the caller's):
//   - in 3D the Bézier rung has the fixed budget B_Z (LadderBudget::bezier_s),
//     so its time Z <= B_Z + δ (δ there: one strip or box test, one Krawczyk
//     step); in 2D Z = 0;
//   - the interval rung has the fixed budget B_I (LadderBudget::interval_s), so
//     I <= B_I + δ;
//   - all MPFI rungs together have the budget f·I' (LadderBudget::mpfi_factor,
//     f = 1; I' <= I the interval rung's time without its local exact
//     evaluations), each rung what is left; a
//     rung that meets a multiple root, runs out of budget, or gives up with the
//     same reason as the rung below (the same sign still uncertain after the
//     precision raise: not converging) sends the ladder straight to exact;
//   - the exact rung is run_exact itself, once.
// Hence, whichever rung decides,
//     time(certified) <= X + Z + (1 + f)·I + c  <=  X + (B_Z + δ) + 2·min(I, B_I + δ) + c  (f = 1),
// with c the ladder's own overhead plus δ per MPFI rung tried. In words: at
// most exact plus the Bézier rung (3D, capped) plus twice the interval rung,
// which is itself capped. A rung that
// decides is never cut short by the guarantee (its answer is certified), and
// the caller's deadline still ends the whole run (BudgetExhausted).
//
// Local decisions. The interval and MPFI rungs carry an
// exact oracle at rational instants (certified/point_oracle.hpp, filled here
// from the PreparedPair): one sign or one status that the rung's intervals
// leave uncertain at one rational point (an end of [0, 1], a split point of
// the isolation, a cell's sample, an identically-zero test) is decided there
// exactly instead of giving up the scene (certified/certified_policy.hpp,
// "Local decisions"); the Solution lists them by kind (local_decisions). What
// still escalates: a piece with two or more sign changes at 2^-max_depth or
// too flat at depth >= 12 (a multiple root: every touch), a projection that
// vanishes exactly at a rational point where the policy cannot place a root
// (t = 0, t = 1, a split point: kind rational_root, straight to exact like a
// multiple root), and a sign at an irrational root (a touch rule's sign, a
// cell boundary's status) that the intervals cannot decide. The guarantee
// above still holds: each exact evaluation (f's coefficients at the point
// from the motions' rationals, then one formula of them: a few hundred
// products of rationals) runs between two looks at the rung's deadline, so
// it is part of that rung's time and budget; δ also covers one such
// evaluation. Split-point evaluations are capped at max_local_splits (4) per run,
// and an identically-zero test of degree d makes at most d + 1.
// Requirements: a prepared pair (kernel/prepared_scene.hpp), N = 3 (2D) or 4 (3D).
#include "solution/solution.hpp"
#include "kernel/prepared_scene.hpp"
#include "kernel/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace eccd {

// The budgets of the rungs (see "Cost guarantee" above).
struct LadderBudget {
  double bezier_s = 0.25;    // B_Z: the Bézier rung's budget in 3D (seconds; <= 0: none)
  double interval_s = 1.0;   // B_I: the interval rung's budget (seconds; <= 0: none)
  double mpfi_factor = 1.0;  // f: all MPFI rungs together at most f x the interval rung's time
  bool local = true;         // local decisions with the exact oracle at rational instants (false: escalate the scene)
};

template <int N>
Solution run_certified(const PreparedPair<N>& p, const std::vector<int>& mpfi_rungs, Variant variant,
                       bool first_contact, const LadderBudget& budget = {});

// A cycloidal scene (2D, not rational: kernel/cycloidal_cd_disc.hpp) in MPFI
// interval arithmetic at each precision of mpfi_rungs (128 if none) until
// nothing is undecided: every simple root of Δ enclosed in a proved bracket,
// every cell proved; what stays undecided (a possible double root: a touch or
// a near miss) is reported with the proved bound on |Δ| there, never as a
// touch. There is no exact rung (exact arithmetic cannot represent it).
Solution run_certified_cycloidal(const Scene& scene, const std::vector<int>& mpfi_rungs, Variant variant);

// The exact pipeline on a prepared pair: a certified Solution (basis "exact").
template <int N>
Solution run_exact(const PreparedPair<N>& p, Variant variant, bool first_contact);

}  // namespace eccd
