#pragma once
// Solution: everything one solve returns, typed. The answer (the spec's four
// keys plus continuous touching, contact points and undecided instants:
// kernel/answer.hpp) and the diagnostics of the run: the projection
// polynomial and its roots in [0, 1] (critical instants) with their status,
// the cells between them with their status, why parts are undecided, the
// work done and the time taken; for a certified run, the rung of the ladder
// that decided and why the lower rungs gave up.
// solution_of turns any pipeline's PipelineResult<T> (kernel/cd_disc.hpp;
// double, MPFR, intervals or rationals) into one; api/solve.cpp fills in what
// was run, io/solution_json.hpp writes it as `eccd solve --json` does.
// It lives in solution/, just above kernel/, because several layers share it:
// the certified ladder (certified/ladder.hpp) returns it, io/ writes it, the
// certificate writers (certificate/write/) fill it and api/ returns it
// (api/solution.hpp is its public name).
#include "solution/arithmetic.hpp"
#include "solution/escalation.hpp"
#include "kernel/answer.hpp"
#include "kernel/cd_disc.hpp"
#include "kernel/contact_status.hpp"
#include "kernel/prepared_scene.hpp"

#include <string>
#include <utility>
#include <vector>

namespace eccd {

struct Solution {
  // What was run.
  std::string scene, file;  // the scene's name and file ("" if built in code)
  int dim = 2;
  Arithmetic arith;
  InputMode input = InputMode::prepared;  // what a floating run started from (exact and certified: prepared)
  std::string basis;                      // "power" | "bernstein" | "scaled-bernstein" | "exact"
  std::string method;                     // "cd-disc" (2D) | "projection" | "bezier" | "sampling:N" | "marching:N"
  Variant variant = Variant::answer;
  bool certified = false;  // every instant carries a proved rational bracket (any arithmetic; docs/architecture.md)
  bool sampled = false;    // a sampled baseline: nothing is claimed between its instants
  // The face of a floating run (api/options.hpp Guard): "none" (the algorithm
  // as published, in plain T) or "bound" (guarded, Bounded<T>); "" for exact
  // and certified runs, which have no face.
  std::string guard;

  Answer answer;

  // Diagnostics.
  Status status_at_0 = Status::uncertain;
  // The univariate polynomial whose roots in [0, 1] are the critical instants:
  // 2D Δ (003 eq. (2)); 3D Δ or the first principal subresultant coefficient
  // that is not identically zero (psc_k); "bezier" for the Bézier zero-set
  // method, which has no univariate projection (its degree is then F(u,t)'s
  // degree in t).
  std::string projection = "discriminant";
  int projection_degree = -1;
  bool projection_identically_zero = false;
  struct Critical {
    Instant t;
    Status status = Status::uncertain;
    int multiplicity = 0;
  };
  std::vector<Critical> critical;
  struct Cell {
    Instant sample;
    Status status = Status::uncertain;
  };
  std::vector<Cell> cells;
  std::vector<std::string> undecided_reasons;
  std::vector<std::pair<std::string, long>> work;  // counters of the method
  double time_ms = 0, setup_ms = 0;

  // Certified runs.
  std::string decided_in;  // "interval", "mpfi:256", "exact"
  std::vector<Escalation> escalations;
  // Decisions the deciding rung made locally, exactly at one rational instant
  // instead of escalating the scene (certified/certified_policy.hpp), by kind.
  std::vector<std::pair<std::string, long>> local_decisions;
  // Proved independent-motion answers (certified/independent_proof.hpp): how each end was proved.
  std::vector<std::string> proofs;

  bool decided() const { return answer.undecided.empty(); }
};

// 2D variant names as the JSON writes them.
inline const char* variant_name(Variant v) {
  switch (v) {
    case Variant::collides:
      return "collides";
    case Variant::first_contact:
      return "first-contact";
    case Variant::all_contacts:
      return "all-contacts";
    default:
      return "answer";
  }
}

// The typed result of one pipeline run (dim 2 or 3): answer, diagnostics, work
// and time. What was run (scene, arithmetic, basis, method) is the caller's.
template <class T>
Solution solution_of(const PipelineResult<T>& r, int dim) {
  Solution s;
  s.dim = dim;
  s.answer = r.answer;
  s.variant = r.variant;
  s.status_at_0 = r.status_at_0;
  s.projection = r.projection_index == 0 ? std::string("discriminant") : "psc_" + std::to_string(r.projection_index);
  s.projection_degree = r.projection_degree;
  s.projection_identically_zero = r.projection_identically_zero;
  for (const auto& c : r.critical) s.critical.push_back({c.t, c.status, c.multiplicity});
  for (const auto& c : r.cells) s.cells.push_back({c.sample, c.status});
  s.undecided_reasons = r.undecided_reasons;
  s.work = r.counters;
  s.time_ms = r.seconds * 1e3;
  return s;
}

}  // namespace eccd
