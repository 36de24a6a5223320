#pragma once
// A Solution (solution/solution.hpp, the API's api/solution.hpp) as JSON and
// as text: exactly the object `eccd solve --json` prints (the scene format's
// answer keys, docs/answer-format.md, plus the run's diagnostics), the spec's
// stored answer out of it, and the few lines `eccd solve` prints.
// Requirements: nlohmann json 3.11 (JSON stays in io/ and above).
#include "solution/solution.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace eccd {

// The format name of that report: the command line adds "format" (this) and
// "version" (the program's) to every solution object it prints.
inline constexpr const char* kSolutionFormat = "eccd-solution/1";
// The full JSON report of a solve (what `eccd solve --json` prints).
nlohmann::json solution_to_json(const Solution& solution);
// The spec's answer (collides, intervals, first_contact, contacts, in that
// order; contact_intervals only when there is continuous touching): what a
// scene file stores under "answer".
nlohmann::ordered_json stored_answer_of(const Solution& solution);
// The same out of a report written by solution_to_json.
nlohmann::ordered_json stored_answer_of(const nlohmann::json& report);
// The Solution back from that JSON (a report of `eccd solve --json`, or a run
// sent between processes by the harness): what was run, the answer with its
// contact points, contact intervals and undecided instants, the diagnostics,
// the timings and the certified ladder's rungs. Throws SceneError naming
// `label` and the JSON place for a report it cannot read.
Solution solution_from_json(const nlohmann::json& report, const std::string& label);
// A few human-readable lines (what `eccd solve` prints without --json).
std::string summary_text(const Solution& solution);

}  // namespace eccd
