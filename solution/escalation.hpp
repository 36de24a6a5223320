#pragma once
// Escalation: one rung of the certified ladder (certified/ladder.hpp) that
// gave up on a scene before the rung that decided it, as a certified run's
// Solution (solution/solution.hpp) lists them: the rung's name as the
// command line writes it ("interval", "mpfi:256", ...), why it gave up (or
// "skipped: ..." when it was not tried), the time it took and the time it
// was allowed (the ladder's cost guarantee). It is a record of the run, not
// a claim: the answer is the deciding rung's.
#include <string>

namespace eccd {

struct Escalation {
  std::string rung;      // "interval", "mpfi:256", ...
  std::string reason;    // why that rung gave up ("skipped: ..." when it was not tried)
  double spent_ms = 0;   // the time the rung took before it gave up (0 when skipped)
  double budget_ms = 0;  // the time it was allowed (certified/ladder.hpp, "Cost guarantee"; 0: not tried)
};

}  // namespace eccd
