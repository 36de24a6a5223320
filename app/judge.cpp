// `eccd judge SCENE ANSWER`: any engine's answer (FCL's, the user's
// simulator's, a floating pipeline's) compared with the scene's certified
// answer (api/judge.hpp); prints the certified answer, the verdict and each
// difference, and for an `eccd solve --json` report the face it ran in
// ("guard": as published or guarded). Exit 0 agrees, 1 differs, 2 bad input, 3 refused, 5 budget.
#include "app/commands.hpp"
#include "api/judge.hpp"
#include "io/scene_reader.hpp"
#include "kernel/budget.hpp"

#include <sys/time.h>

#include <fstream>
#include <iostream>
#include <sstream>

namespace eccd {

namespace {

struct JudgeArgs {
  std::string scene, answer;
  double tol = 1e-6;
  std::string name = "yours";
  bool json = false, use_stored = false;
};

std::string instant_text(const Instant& i) {
  if (!i.certified()) return i.approx;
  if (*i.lo == *i.hi) return i.lo->get_str();
  return i.approx + " in [" + i.lo->get_str() + ", " + i.hi->get_str() + "]";
}

std::string answer_text(const Answer& a) {
  std::ostringstream o;
  o << "  collides: " << (a.collides ? "yes" : "no") << "\n";
  for (const auto& [x, y] : a.intervals)
    o << "  collision interval: [" << instant_text(x) << ", " << instant_text(y) << "]\n";
  if (a.first_contact) o << "  first contact: " << instant_text(*a.first_contact) << "\n";
  for (const auto& [x, y] : a.contact_intervals)
    o << "  continuous touching (contact interval): [" << instant_text(x) << ", " << instant_text(y) << "]\n";
  if (a.contacts.empty()) o << "  external contacts: none\n";
  for (const auto& c : a.contacts) o << "  external contact: " << instant_text(c) << "\n";
  return o.str();
}

nlohmann::ordered_json counts_json(const AnswerDifference& d) {
  nlohmann::ordered_json c = {{"collides_differs", d.collides_differs},
                              {"missed", d.missed},
                              {"false", d.spurious},
                              {"split", d.split},
                              {"merged", d.merged},
                              {"endpoints_off", d.endpoints_off},
                              {"undecided", d.undecided},
                              {"contact_intervals_differ", d.contact_intervals_differ},
                              {"missed_contacts", d.missed_contacts},
                              {"false_contacts", d.false_contacts},
                              {"intervals", d.intervals},
                              {"certified_intervals", d.reference_intervals}};
  c["first_contact_error"] =
      d.first_contact_error ? nlohmann::ordered_json(*d.first_contact_error) : nlohmann::ordered_json(nullptr);
  c["max_endpoint_error"] =
      d.max_endpoint_error ? nlohmann::ordered_json(*d.max_endpoint_error) : nlohmann::ordered_json(nullptr);
  return c;
}

// The face of a judged `eccd solve --json` report (its "guard": "none" as published, "bound" guarded) and its
// arithmetic, "" for any other answer (and for standard input, which read_answer has consumed).
std::pair<std::string, std::string> report_face(const std::string& path) {
  if (path == "-") return {"", ""};
  std::ifstream in(path, std::ios::binary);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("guard") || !j["guard"].is_string()) return {"", ""};
  return {j["guard"].get<std::string>(),
          j.contains("arith") && j["arith"].is_string() ? j["arith"].get<std::string>() : ""};
}

}  // namespace

Command add_judge_command(CLI::App& app) {
  auto args = std::make_shared<JudgeArgs>();
  Command c;
  c.sub = app.add_subcommand(
      "judge",
      "Compare an answer in the scene format (from FCL, your simulator, another pipeline) with the scene's "
      "certified answer and print the verdict: wrong collides, missed or false intervals and contacts, ends "
      "off by more than --tol. Exit 0 agrees, 1 differs, 2 bad input, 3 refused (cycloidal), 5 budget.");
  auto* s = c.sub;
  s->add_option("SCENE", args->scene,
                "Scene file (ellipse-ccd-scene/1); - reads standard input (then ANSWER must be a file)")
      ->required();
  s->add_option("ANSWER", args->answer,
                "Answer to judge: a JSON answer object, a scene file with an \"answer\", or an `eccd solve --json` "
                "report; - for stdin")
      ->required();
  s->add_option("--tol", args->tol, "Tolerance on instants: a decimal within tol of the certified bracket matches")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  s->add_option("--name", args->name, "Name of the engine that gave the answer (used in the differences)")
      ->capture_default_str()
      ->check(
          [](const std::string& n) { return n.empty() ? std::string("expected a non-empty name") : std::string(); });
  s->add_flag("--json", args->json, "Print one JSON object (format eccd-judgement/1) instead of text");
  s->add_flag("--use-stored", args->use_stored,
              "Compare with the scene's stored answer instead of solving exactly (when the scene has one; regress "
              "keeps it exact)");
  c.run = [args]() {
    if (args->scene == "-" && args->answer == "-")
      throw std::invalid_argument(
          "judge: SCENE and ANSWER are both - (standard input): at most one of them can be read from it");
    const SceneSource src = read_scene_source(args->scene);
    Scene scene = parse_scene(src.text, src.label);
    AnswerInput in = read_answer(args->answer);
    const std::string label = args->answer == "-" ? std::string("<stdin>") : args->answer;
    const auto [face, face_arith] = report_face(args->answer);
    JudgeOptions options;
    options.tol = args->tol;
    options.name = args->name;
    options.use_stored = args->use_stored;
    if (args->use_stored && !scene.answer)
      warn("judge", src.label + " has no stored answer; --use-stored ignored, solving exactly");
    Judgement j;
    arm_backstop(run_budget().time_limit_s);
    try {
      ScopedDeadline deadline(run_budget().time_limit_s);
      j = judge(scene, in.answer, options);
    } catch (const std::invalid_argument& e) {
      std::cerr << "eccd: judge: " << src.label << ": " << e.what()
                << " (judge compares with the exact answer, so it refuses this scene)\n";
      return 3;
    }
    {
      itimerval off{};
      setitimer(ITIMER_REAL, &off, nullptr);
    }
    const AnswerDifference& d = j.difference;
    if (args->json) {
      nlohmann::ordered_json out = {
          {"format", "eccd-judgement/1"},
          {"version", program_version()},
          {"scene", scene.name},
          {"scene_file", src.label},
          {"answer_file", label},
          {"answer_taken", in.taken},
          {"answer_guard", face.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(face)},
          {"engine", args->name},
          {"agrees", j.agrees},
          {"verdict", j.verdict},
          {"differences", d.differences},
          {"counts", counts_json(d)},
          {"certified_from", j.certified_from},
          {"certified_answer", nlohmann::ordered_json::parse(answer_to_json(j.certified.answer).dump())},
          {"tolerance", args->tol}};
      std::cout << out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else {
      std::ostringstream o;
      o << "scene " << scene.name << " (" << scene.dim << "D): certified answer (" << j.certified_from << ")\n"
        << answer_text(j.certified.answer);
      o << "judged: " << label << " (" << in.taken
        << (face == "none"    ? ", " + face_arith + " as published, no guard"
            : face == "bound" ? ", " + face_arith + " guarded"
                              : "")
        << "), engine " << args->name << ", tolerance " << args->tol << "\n";
      o << "verdict: " << j.verdict << "\n";
      for (const auto& x : d.differences) o << "  - " << x << "\n";
      std::cout << o.str();
    }
    return j.agrees ? 0 : 1;
  };
  return c;
}

}  // namespace eccd
