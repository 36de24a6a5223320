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
  if (j.agrees)
    j.verdict = "agrees";
  else if (j.difference.collides_differs)
    j.verdict = "wrong collides";
  else
    j.verdict = "differs: " + std::to_string(j.difference.differences.size()) + " difference(s)";
  return j;
}

namespace {
// Every instant's numbers as the scene reader takes them: approx a decimal
// number (no NaN, infinity or hexadecimal float: io/scene_reader.hpp
// parse_rational), approx, lo and hi in [0, 1] (the time of a scene).
void check_instants(const Answer& a, const std::string& label, const std::string& base) {
  auto check = [&](const Instant& i, const std::string& place) {
    auto bad = [&](const std::string& what) { throw SceneError(label + ": " + base + place + ": " + what); };
    Rational v;
    try {
      v = parse_rational(i.approx);
    } catch (const std::invalid_argument& e) {
      bad("approx \"" + (i.approx.size() > 40 ? i.approx.substr(0, 40) + "..." : i.approx) +
          "\" is not a decimal number: " + e.what());
    }
    if (v < 0 || v > 1) bad("approx " + i.approx + " is outside [0, 1], the time of a scene");
    if (i.lo && *i.lo < 0) bad("lo " + i.lo->get_str() + " is below 0");
    if (i.hi && *i.hi > 1) bad("hi " + i.hi->get_str() + " is above 1");
  };
  auto pairs = [&](const std::vector<std::pair<Instant, Instant>>& v, const std::string& key) {
    for (std::size_t k = 0; k < v.size(); ++k) {
      check(v[k].first, "/" + key + "/" + std::to_string(k) + "/0");
      check(v[k].second, "/" + key + "/" + std::to_string(k) + "/1");
    }
  };
  pairs(a.intervals, "intervals");
  pairs(a.contact_intervals, "contact_intervals");
  pairs(a.s_intervals, "s_intervals");
  pairs(a.t_intervals, "t_intervals");
  if (a.first_contact) check(*a.first_contact, "/first_contact");
  for (std::size_t k = 0; k < a.contacts.size(); ++k) check(a.contacts[k], "/contacts/" + std::to_string(k));
}
}  // namespace

AnswerInput answer_from_text(const std::string& json_text, const std::string& label) {
  const nlohmann::json doc = parse_json_document(json_text, label);
  if (!doc.is_object())
    throw SceneError(label +
                     ": top level: expected a JSON object: an answer {\"collides\", \"intervals\", ...} or a scene "
                     "file with an \"answer\"");
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
  check_instants(in.answer, label, doc.contains("answer") ? "/answer" : "");
  return in;
}

AnswerInput read_answer(const std::string& path) {
  if (path == "-") return answer_from_text(read_file_bytes("/dev/stdin"), "<stdin>");
  return answer_from_text(read_file_bytes(path), path);
}

}  // namespace eccd
