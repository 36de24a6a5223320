// Judge any engine's answer against the certified one: api/judge.hpp.
#include "api/judge.hpp"

#include "api/solve.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"

namespace eccd {

Judgement judge(const Scene& scene, const Answer& theirs, const JudgeOptions& options) {
  Judgement j;
  if (options.use_stored && scene.answer) {
    Solution& s = j.certified;
    s.scene = scene.name;
    s.file = scene.path;
    s.dim = scene.dim;
    s.arith = Arithmetic::exact();
    s.basis = "exact";
    s.method = "stored";
    s.answer = *scene.answer;
    s.certified = true;
    j.certified_from = "stored answer";
  } else {
    j.certified = solve(scene, SolveOptions{});  // exact by default
    j.certified_from = "exact pipeline";
  }
  DifferenceOptions d;
  d.tol = options.tol;
  d.answer_name = options.name;
  d.reference_name = "certified";
  j.difference = answer_difference(theirs, j.certified.answer, d);
  j.agrees = j.difference.agrees;
  if (j.agrees) j.verdict = "agrees";
  else if (j.difference.collides_differs) j.verdict = "wrong collides";
  else j.verdict = "differs: " + std::to_string(j.difference.differences.size()) + " difference(s)";
  return j;
}

AnswerInput answer_from_text(const std::string& json_text, const std::string& label) {
  const nlohmann::json doc = parse_json_document(json_text, label);
  if (!doc.is_object())
    throw SceneError(label + ": top level: expected a JSON object: an answer {\"collides\", \"intervals\", ...} or a scene file with an \"answer\"");
  AnswerInput in;
  if (doc.contains("answer")) {
    if (doc["answer"].is_null()) throw SceneError(label + ": /answer: is null: the scene file has no answer to judge");
    in.answer = answer_from_json(doc["answer"], label, "/answer");
    in.taken = doc.contains("format") && doc["format"].is_string() && doc["format"] != "ellipse-ccd-scene/1"
                   ? "the \"answer\" of an " + doc["format"].get<std::string>() + " object"
                   : "the \"answer\" of a scene file";
  } else if (doc.contains("collides") && doc.contains("arith")) {
    in.answer = solution_from_json(doc, label).answer;
    in.taken = "the answer of an `eccd solve --json` report";
  } else if (doc.contains("collides")) {
    in.answer = answer_from_json(doc, label, "");
    in.taken = "a bare answer object";
  } else {
    throw SceneError(label +
                     ": top level: neither an answer (no \"collides\" key) nor a scene file with an \"answer\" key; "
                     "expected {\"collides\": ..., \"intervals\": [...], \"first_contact\": ..., \"contacts\": [...]}");
  }
  return in;
}

AnswerInput read_answer(const std::string& path) {
  if (path == "-") return answer_from_text(read_file_bytes("/dev/stdin"), "<stdin>");
  return answer_from_text(read_file_bytes(path), path);
}

}  // namespace eccd
