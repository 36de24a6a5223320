#pragma once
// The one comparison of two answers: how an answer differs from a
// reference answer, counted and in words. Every place that compares answers
// uses it: the report's metrics (compare/metrics.hpp), the verdicts of
// `eccd certify` and `eccd regress --floating` (compare/verdict.hpp), the
// regression against stored answers (compare/regress.hpp), the side-by-side
// table of `eccd table`, the Python module.
//
// Statement. Both answers are in the spec's form (scene-format.md, "The
// answer"; kernel/answer.hpp). Two instants match when
//   - both carry a rational bracket: the brackets overlap (exactly, no
//     tolerance: a certified bracket holds exactly one root of the
//     projection, so overlapping certified brackets hold the same instant);
//   - one carries a bracket [lo, hi]: the other's decimal, read exactly,
//     lies in [lo - tol, hi + tol];
//   - neither does: their decimals differ by at most tol.
// An interval of one answer and one of the other correspond when they
// overlap after widening by tol (certified ends: their brackets). Each
// reference interval with no partner is "missed", each answer interval with
// none is "false"; one matched by several is "split", several merged into
// one "merges"; of a one-to-one pair, an end whose instants do not match is
// "off by" the difference of the decimals. External contacts are matched one
// to one (nearest first); a contact at an instant already reported through an
// interval is not reported twice. First contact: presence must agree, and
// the instants match unless the difference was reported already. Continuous
// touching (contact_intervals, docs/answer-format.md): the counts must agree
// and then their ends match. Every undecided instant of the answer is a
// difference. The answers agree iff there is no difference.
// Independent motions (Answer::independent): answers of different
// kinds never agree; the s_intervals and then the t_intervals are matched
// exactly as collision intervals are ("s-interval 1 end off by ..."), and
// `intervals` / `reference_intervals` count both lists.
// Decisions between certified instants are exact (rationals); decimals are
// compared as doubles (reporting: the answer being judged is a floating one,
// or a stored decimal, which is no proof either way).
// Requirements: none beyond kernel/answer.hpp (Instant::value filled: the
// pipelines and the answer reader fill it).
#include "kernel/answer.hpp"

#include <optional>
#include <string>
#include <vector>

namespace eccd {

struct DifferenceOptions {
  double tol = 1e-6;                   // on decimals (see above); brackets overlap exactly
  std::string answer_name = "answer";  // how the differences name the two ("recomputed", "double/bezier", ...)
  std::string reference_name = "reference";
};

struct AnswerDifference {
  bool agrees = false;
  std::vector<std::string> differences;  // in words, in the order found; empty iff agrees
  bool collides_differs = false;         // both claim `collides` (collides_claim) and the claims differ
  // Intervals and contacts of the reference with no partner in the answer
  // (missed) and of the answer with none in the reference (spurious), each
  // counted once (a contact inside a missed interval is not counted again).
  int missed = 0, spurious = 0;
  int split = 0, merged = 0, endpoints_off = 0, undecided = 0;
  int contact_intervals_differ = 0;
  // One-to-one matching of the contacts alone (all of them, nothing skipped).
  int missed_contacts = 0, false_contacts = 0;
  int intervals = 0, reference_intervals = 0;
  // |answer - reference| of the first contacts' decimals when both have one.
  std::optional<double> first_contact_error;
  // Every interval matched one to one with its reference: the largest
  // difference of an end's decimals (also when within tol).
  std::optional<double> max_endpoint_error;
};

// Do two instants match (the rule above)?
bool instants_match(const Instant& a, const Instant& b, double tol);

AnswerDifference answer_difference(const Answer& answer, const Answer& reference, const DifferenceOptions& opt = {});

}  // namespace eccd
