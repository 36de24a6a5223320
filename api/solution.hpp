#pragma once
// Solution: everything one solve returns, typed. The answer (the spec's four
// keys plus continuous touching, contact points and undecided instants:
// kernel/answer.hpp) and the diagnostics of the run: the projection
// polynomial and its roots in [0, 1] (critical instants) with their status,
// the cells between them with their status, why parts are undecided, the
// work done and the time taken; for a certified run, the rung of the ladder
// that decided and why the lower rungs gave up.
// io/solution_json.hpp writes it as `eccd solve --json` does.
#include "api/options.hpp"
#include "kernel/answer.hpp"
#include "kernel/contact_status.hpp"

#include <string>
#include <utility>
#include <vector>

namespace eccd {

struct Escalation {
  std::string rung;    // "interval", "mpfi:256", ...
  std::string reason;  // why that rung gave up ("skipped: ..." when it was not tried)
};

struct Solution {
  // What was run.
  std::string scene, file;  // the scene's name and file ("" if built in code)
  int dim = 2;
  Arithmetic arith;
  InputMode input = InputMode::prepared;  // what a floating run started from (exact and certified: prepared)
  std::string basis;   // "power" | "bernstein" | "scaled-bernstein" | "exact"
  std::string method;  // "cd-disc" (2D) | "projection" | "bezier" | "sampling:N" | "marching:N"
  Variant variant = Variant::answer;
  bool certified = false;  // every instant carries a proved rational bracket
  bool sampled = false;    // a sampled baseline: nothing is claimed between its instants

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
  struct Critical { Instant t; Status status = Status::uncertain; int multiplicity = 0; };
  std::vector<Critical> critical;
  struct Cell { Instant sample; Status status = Status::uncertain; };
  std::vector<Cell> cells;
  std::vector<std::string> undecided_reasons;
  std::vector<std::pair<std::string, long>> work;  // counters of the method
  double time_ms = 0, setup_ms = 0;

  // Certified runs.
  std::string decided_in;  // "interval", "mpfi:256", "exact"
  std::vector<Escalation> escalations;

  bool decided() const { return answer.undecided.empty(); }
};

}  // namespace eccd
