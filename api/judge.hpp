#pragma once
// Judge any engine's answer against the certified one:
// an answer in the scene format (scene-format.md "The answer",
// docs/answer-format.md) from FCL, from the user's simulator or from one of
// eccd's floating pipelines, compared with the scene's certified answer.
//
// Statement. The certified answer is the exact pipeline's (api/solve.hpp,
// Arithmetic::exact(): every instant a rational bracket proved to hold it),
// or, when JudgeOptions::use_stored is set and the scene has one, the scene's
// stored answer (which `eccd regress` keeps equal to the exact one). The
// comparison is THE one answer difference (api/answer_difference.hpp) with
// the judged answer named JudgeOptions::name ("yours") and the reference
// "certified", and tolerance tol on decimals (an instant of the judged answer
// matches a certified one when its decimal, read exactly, lies within tol of
// the certified bracket). The verdict is "agrees", "wrong collides" (the
// one difference that makes every other one moot), or "differs: N
// difference(s)".
// Reading the judged answer: a JSON object that is a bare answer
// ({"collides", "intervals", ...}), a whole scene file with an "answer" key,
// or a report of `eccd solve --json` (its answer with its undecided
// instants); io/scene_reader.hpp's answer_from_json checks it, so an error
// names the file and the JSON place ("yours.json: /intervals/0/1: ...").
// Errors: SceneError for an answer or scene that cannot be read;
// std::invalid_argument (NotRationalMotion) for a scene the exact pipeline
// refuses (a cycloidal motion); BudgetExhausted when the exact run passes the
// deadline (kernel/budget.hpp).
// Requirements: none beyond the API's (no JSON in this header).
#include "api/answer_difference.hpp"
#include "api/solution.hpp"
#include "kernel/scene.hpp"

#include <string>

namespace eccd {

struct JudgeOptions {
  double tol = 1e-6;           // on decimals; certified brackets widened by it
  std::string name = "yours";  // how the differences name the judged answer (the engine's name)
  bool use_stored = false;     // the scene's stored answer as the certified one, when it has one
};

struct Judgement {
  AnswerDifference difference;  // counts and the differences in words
  Solution certified;           // the certified answer it was compared with (and the run's diagnostics)
  std::string certified_from;   // "exact pipeline" or "stored answer"
  std::string verdict;          // "agrees" | "wrong collides" | "differs: N difference(s)"
  bool agrees = false;
};

Judgement judge(const Scene& scene, const Answer& theirs, const JudgeOptions& options = {});

// An answer to judge, read from JSON text, and which part of the text it was.
struct AnswerInput {
  Answer answer;
  std::string taken;  // "a bare answer object" | "the \"answer\" of a scene file" | "the answer of an `eccd solve
                      // --json` report"
};
// Throws SceneError "LABEL: PLACE: what is wrong"; the instants' numbers are
// checked as the scene reader checks numbers (a decimal approx, no NaN or
// hexadecimal float, everything in [0, 1]).
AnswerInput answer_from_text(const std::string& json_text, const std::string& label);
// The same from a file; "-" reads standard input (named "<stdin>" in errors).
AnswerInput read_answer(const std::string& path);

}  // namespace eccd
