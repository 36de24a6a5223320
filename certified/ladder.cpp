// The certified ladder (certified/ladder.hpp).
#include "certified/ladder.hpp"

#include "certified/bezier_proof.hpp"
#include "certified/certified_policy.hpp"
#include "certified/point_oracle.hpp"
#include "exact/cd_disc_exact.hpp"
#include "kernel/budget.hpp"
#include "kernel/ccd_projection.hpp"
#include "kernel/cycloidal_cd_disc.hpp"
#include "number/interval.hpp"
#include "number/mpfi_interval.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

namespace eccd {

namespace {

// What every run of the ladder is: method "cd-disc" in 2D, "projection" in 3D.
template <int N>
Solution& named(Solution& s, const char* basis, bool certified) {
  s.basis = basis;
  s.method = N == 4 ? "projection" : "cd-disc";
  s.certified = certified;
  return s;
}

// One rung: the pipeline in interval type T (Interval or MpfiInterval) with
// subdivision down to 2^-max_depth, within `budget_s` seconds (a deadline
// nested in the caller's: kernel/budget.hpp). A Solution if it decided
// everything; otherwise nothing, with `reason` set, `multiple_root` if it met
// one and `out_of_budget` if its deadline passed. The caller's own deadline
// passing is not this rung's business: BudgetExhausted goes on up.
template <class T, int N>
std::optional<Solution> try_certified_rung(const PreparedPair<N>& p, Variant variant, bool first_contact, const T& like,
                                           int max_depth, double budget_s, bool local, std::string& reason,
                                           bool& multiple_root, bool& out_of_budget, double& local_s) {
  local_s = 0;
  try {
    ScopedDeadline rung_deadline(budget_s);
    if (deadline_passed()) throw BudgetExhausted("certified rung: " + deadline_reason());  // a budget already spent
    CertifiedPolicy<T> pol(like);
    pol.max_depth = max_depth;
    const PreparedPointOracle<N> oracle(p);  // local decisions: exact at one rational instant
    if (local) pol.oracle = &oracle;
    struct Report {  // the oracle's time, also when the rung gives up (Escalate, BudgetExhausted)
      const CertifiedPolicy<T>& pol;
      double& out;
      ~Report() { out = pol.local_seconds; }
    } report{pol, local_s};
    PipelineResult<T> r = projection_pipeline(to_arithmetic<T, N>(p, like), pol, variant, first_contact);
    if (r.answer.undecided.empty()) {
      Solution s = solution_of(r, N - 1);
      s.work.emplace_back("interval_pieces", pol.pieces);
      for (const auto& [kind, count] : pol.local) {
        s.local_decisions.emplace_back(kind, count);
        s.work.emplace_back("local_" + kind, count);
      }
      return named<N>(s, "bernstein", true);
    }
    reason = std::to_string(r.answer.undecided.size()) + " instant(s) undecided";
  } catch (const Escalate& e) {
    reason = e.what();
    multiple_root = e.kind == Escalate::multiple_root || e.kind == Escalate::rational_root;
  } catch (const BudgetExhausted& e) {
    if (deadline_passed()) throw;  // the caller's deadline (the rung's scope has ended): the whole run is over
    reason = std::string("rung budget exhausted (") + e.what() + ")";
    out_of_budget = true;
  }
  return std::nullopt;
}

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The Bézier rung (3D, certified/bezier_proof.hpp) within `budget_s` seconds:
// a Solution if the proof decided [0, 1], else nothing with `reason` set.
std::optional<Solution> try_bezier_rung(const PreparedPair<4>& p, bool first_contact, double budget_s,
                                        std::string& reason) {
  try {
    ScopedDeadline rung_deadline(budget_s);
    if (deadline_passed()) throw BudgetExhausted("bezier rung: " + deadline_reason());
    BezierProofOptions o;
    o.first_contact = first_contact;
    o.record = true;  // the pieces give the cells
    const auto start = Clock::now();
    BezierProofResult r = prove_bezier(p, o);
    if (!r.decided) {
      reason = r.reason;
      return std::nullopt;
    }
    Solution s;
    s.dim = 3;
    s.answer = r.answer;
    s.variant = first_contact ? Variant::first_contact : Variant::answer;
    const bool in_at_0 = !r.answer.intervals.empty() && r.answer.intervals.front().first.lo &&
                         sgn(*r.answer.intervals.front().first.hi) == 0;
    s.status_at_0 = in_at_0 ? Status::overlapping : Status::separate;
    for (const Instant& c : r.answer.contacts) s.critical.push_back({c, Status::touching, 1});
    // one cell per run of proved pieces of one kind (a sample at its middle)
    for (std::size_t i = 0; i < r.pieces.size(); ++i) {
      if (r.pieces[i].kind == BezierPiece::end) continue;
      std::size_t j = i;
      while (j + 1 < r.pieces.size() && r.pieces[j + 1].kind == r.pieces[i].kind) ++j;
      const Rational mid = (r.pieces[i].lo + r.pieces[j].hi) / 2;
      s.cells.push_back({bracketed_instant(mid, mid, mid),
                         r.pieces[i].kind == BezierPiece::in ? Status::overlapping : Status::separate});
      i = j;
    }
    s.work = r.work;
    s.projection = "bezier";
    for (const auto& [k, v] : r.work)
      if (k == "bezier_degree_t") s.projection_degree = int(v);
    s.basis = "bernstein";
    s.method = "bezier";
    s.certified = true;
    s.time_ms = seconds_since(start) * 1e3;
    return s;
  } catch (const BudgetExhausted& e) {
    if (deadline_passed()) throw;  // the caller's deadline: the whole run is over
    reason = std::string("rung budget exhausted (") + e.what() + ")";
  }
  return std::nullopt;
}

}  // namespace

template <int N>
Solution run_exact(const PreparedPair<N>& p, Variant variant, bool first_contact) {
  ExactPolicy pol;
  Solution s =
      solution_of(projection_pipeline(to_arithmetic<Rational, N>(p, Rational(1)), pol, variant, first_contact), N - 1);
  return named<N>(s, "exact", true);
}

template <int N>
Solution run_certified(const PreparedPair<N>& p, const std::vector<int>& mpfi_rungs, Variant variant,
                       bool first_contact, const LadderBudget& budget) {
  const auto start = Clock::now();
  std::vector<Escalation> escalations;
  auto finish = [&](Solution s, const std::string& rung) {
    s.escalations = escalations;
    s.decided_in = rung;
    s.certified = true;
    s.time_ms = seconds_since(start) * 1e3;
    return s;
  };
  std::string reason;
  bool multiple_root = false, out_of_budget = false, not_converging = false;
  // Rung 0 (3D): the Bézier proof in intervals (certified/bezier_proof.hpp), within its fixed budget B_Z.
  if constexpr (N == 4) {
    const auto tb = Clock::now();
    if (auto s = try_bezier_rung(p, first_contact, budget.bezier_s, reason)) return finish(*s, "bezier");
    escalations.push_back({"bezier", reason, seconds_since(tb) * 1e3, budget.bezier_s * 1e3});
  }
  // Rung 1: intervals of doubles, within the fixed budget B_I.
  auto t = Clock::now();
  double local_s = 0;
  if (auto s = try_certified_rung<Interval, N>(p, variant, first_contact, Interval(0), 48, budget.interval_s,
                                               budget.local, reason, multiple_root, out_of_budget, local_s))
    return finish(*s, "interval");
  const double interval_s = seconds_since(t);
  escalations.push_back({"interval", reason, interval_s * 1e3, budget.interval_s * 1e3});
  // The MPFI rungs share one budget: mpfi_factor x the interval rung's time
  // without its local exact evaluations (they decide nothing on the
  // degree-1 graze and overlap rows and would double the MPFI rung's allowance), so
  // that all of them together cost at most that much; each rung gets what is left.
  const double mpfi_total_s = budget.mpfi_factor * std::max(0.0, interval_s - local_s);
  double mpfi_spent_s = 0;
  std::string previous_reason = reason;
  for (int bits : mpfi_rungs) {
    std::string rung = "mpfi:" + std::to_string(bits);
    const double left_s = mpfi_total_s - mpfi_spent_s;
    // Not converging: straight to exact.
    std::string skip;
    if (multiple_root)
      skip = "skipped: the rung below met a multiple root or an exact zero (no precision separates it)";
    else if (not_converging)
      skip = "skipped: the rung below was not converging";
    else if (out_of_budget)
      skip = "skipped: the rung below ran out of its budget";
    else if (left_s <= 0)
      skip = "skipped: the MPFI budget (" + std::to_string(budget.mpfi_factor).substr(0, 4) +
             " x the interval rung's time) is spent";
    if (!skip.empty()) {
      escalations.push_back({rung, skip, 0, 0});
      continue;
    }
    // Deeper subdivision at higher precision (roots closer than 2^-48 can be
    // told apart when the coefficients are known to `bits` bits), but not so
    // deep that a true multiple root (every touch scene) costs much before
    // the exact rung: 2^-64 at the default 256 bits.
    int depth = std::clamp(bits / 4, 48, 256);
    t = Clock::now();
    double mpfi_local_s = 0;
    if (auto s = try_certified_rung<MpfiInterval, N>(p, variant, first_contact, MpfiInterval(Rational(0), bits), depth,
                                                     left_s, budget.local, reason, multiple_root, out_of_budget,
                                                     mpfi_local_s))
      return finish(*s, rung);
    const double rung_s = seconds_since(t);
    mpfi_spent_s += rung_s;
    // The same sign uncertain at the same place after a precision raise: more
    // bits will not decide it either.
    if (reason == previous_reason && !out_of_budget) {
      reason += " (the same as the rung below: not converging)";
      not_converging = true;
    }
    escalations.push_back({rung, reason, rung_s * 1e3, left_s * 1e3});
    previous_reason = reason;
  }
  return finish(run_exact<N>(p, variant, first_contact), "exact");
}

Solution run_certified_cycloidal(const Scene& scene, const std::vector<int>& mpfi_rungs, Variant variant) {
  auto start = std::chrono::steady_clock::now();
  std::vector<int> rungs = mpfi_rungs.empty() ? std::vector<int>{128} : mpfi_rungs;
  std::vector<Escalation> escalations;
  Solution s;
  std::string rung;
  for (std::size_t i = 0; i < rungs.size(); ++i) {
    const int bits = rungs[i];
    rung = "mpfi:" + std::to_string(bits);
    MpfiInterval like(Rational(0), bits);
    CycloidalOptions co;
    co.certified = true;
    co.max_depth = std::clamp(bits / 2, 24, 200);
    co.refine_bits = 64;  // brackets of width 2^-64 where the signs are proved that far
    s = solution_of(cycloidal_cd_disc(cycloidal_pair<MpfiInterval>(scene, like), like, co, variant), 2);
    if (s.answer.undecided.empty() || i + 1 == rungs.size()) break;
    escalations.push_back({rung, std::to_string(s.answer.undecided.size()) + " instant(s) undecided"});
  }
  s.escalations = escalations;
  s.decided_in = rung;
  // Every bracket and status is proved; an undecided stretch is named as such
  // (never a claimed touch), so the run is certified only if none is left.
  s.certified = s.answer.undecided.empty();
  s.basis = "pointwise";
  s.method = "cd-disc-cycloidal";
  s.time_ms = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3;
  return s;
}

template Solution run_exact<3>(const PreparedPair<3>&, Variant, bool);
template Solution run_exact<4>(const PreparedPair<4>&, Variant, bool);
template Solution run_certified<3>(const PreparedPair<3>&, const std::vector<int>&, Variant, bool, const LadderBudget&);
template Solution run_certified<4>(const PreparedPair<4>&, const std::vector<int>&, Variant, bool, const LadderBudget&);

}  // namespace eccd
