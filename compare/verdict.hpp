#pragma once
// Verdicts: how a floating pipeline's answer differs from the certified one,
// in words a user can act on ("missed contact near t ∈ [lo, hi]", "false
// contact", "collision interval 2 end off by 1.3e-3", "collides: certified
// true, double/power false"), with the counters the tables of `eccd regress
// --floating` and `eccd certify` show.
//
// Statement. The comparison itself is api/answer_difference.hpp's (the one
// comparison of answers: intervals matched by overlap widened by tol,
// contacts one to one, continuous touching, undecided instants); a verdict
// names the pipeline and its face (as published or guarded: the label of an
// as-published pipeline ends in "/published", compare/harness.hpp), keeps its
// time and its failure, and counts what the tables count. "agrees" iff there is no difference. This is reporting, not
// deciding: doubles are fine here (docs/architecture.md, "Doubles for display only").
#include "api/answer_difference.hpp"
#include "kernel/answer.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace eccd {

struct Verdict {
  std::string pipeline;
  std::string guard;  // the face of the floating run: "none" (as published) | "bound" (guarded)
  bool agrees = false;
  std::string error;                     // the pipeline failed (exception message)
  std::vector<std::string> differences;  // empty iff agrees (and no error)
  std::optional<double> max_endpoint_error;
  double time_ms = 0;
  // Counters for tables (eccd regress --floating).
  bool wrong_collides = false;
  int missed = 0, spurious = 0, endpoints_off = 0, undecided = 0;

  nlohmann::json to_json() const {
    nlohmann::json j = {{"pipeline", pipeline}, {"agrees", agrees}, {"differences", differences}, {"time_ms", time_ms}};
    j["max_endpoint_error"] = max_endpoint_error ? nlohmann::json(*max_endpoint_error) : nlohmann::json(nullptr);
    if (!guard.empty()) j["guard"] = guard;
    if (!error.empty()) j["error"] = error;
    return j;
  }
  // "agrees (endpoints within 8.3e-16)" or "differs: ...; ..."
  std::string text() const {
    if (!error.empty()) return "failed: " + error;
    char buf[64];
    if (agrees) {
      if (!max_endpoint_error) return "agrees";
      std::snprintf(buf, sizeof buf, "agrees (interval ends within %.2g)", *max_endpoint_error);
      return buf;
    }
    std::string s = "differs: ";
    for (std::size_t i = 0; i < differences.size(); ++i) s += (i ? "; " : "") + differences[i];
    return s;
  }
};

// got: a pipeline's answer; certified: the certified answer; time_ms: the
// pipeline's time. The comparison is api/answer_difference.hpp's.
inline Verdict judge(const std::string& pipeline, const Answer& got, const Answer& certified, double tol,
                     double time_ms = 0) {
  Verdict v;
  v.pipeline = pipeline;
  v.time_ms = time_ms;
  DifferenceOptions o;
  o.tol = tol;
  o.answer_name = pipeline;
  o.reference_name = "certified";
  AnswerDifference d = answer_difference(got, certified, o);
  v.agrees = d.agrees;
  v.differences = d.differences;
  v.max_endpoint_error = d.max_endpoint_error;
  v.wrong_collides = d.collides_differs;
  v.missed = d.missed + d.split;
  v.spurious = d.spurious + d.merged;
  v.endpoints_off = d.endpoints_off;
  v.undecided = d.undecided;
  return v;
}
// A pipeline that failed (its exception message).
inline Verdict failed_verdict(const std::string& pipeline, const std::string& error, double time_ms = 0) {
  Verdict v;
  v.pipeline = pipeline;
  v.error = error;
  v.time_ms = time_ms;
  return v;
}

}  // namespace eccd
