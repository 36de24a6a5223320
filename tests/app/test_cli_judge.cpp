// `eccd judge SCENE ANSWER` as a script uses it: exit 0 agrees, 1 differs,
// 2 bad input (the message names the file and the JSON place), 3 refused;
// --json keys; the answer from stdin; a scene file as the answer.
// The answer files are tests/data/judge/ (README.md there says what each is).
#include "tests/app/cli_run.hpp"

#include <nlohmann/json.hpp>

namespace ECCD_UNITY_ID {
using namespace eccd::clitest;

namespace {
const std::string crossing = q(src("cases/spheres/spheres-crossing.json"));
std::string answer(const std::string& f) { return q(src("tests/data/judge/" + f)); }
}  // namespace

TEST_CASE("eccd judge: a correct answer agrees (exit 0)", "[cli-judge]") {
  Run r = run_eccd("judge " + crossing + " " + answer("correct.json"));
  CHECK(r.code == 0);
  CHECK(r.out.find("verdict: agrees") != std::string::npos);
  CHECK(r.out.find("a bare answer object") != std::string::npos);
  CHECK(r.out.find("collision interval: [0.131567933670262626 in [") != std::string::npos);  // the certified brackets
  // A scene file is an answer too (its stored "answer"), and the stored answer can stand for the certified one.
  Run s = run_eccd("judge " + crossing + " " + crossing + " --use-stored");
  CHECK(s.code == 0);
  CHECK(s.out.find("the \"answer\" of a scene file") != std::string::npos);
  CHECK(s.out.find("certified answer (stored answer)") != std::string::npos);
}

TEST_CASE("eccd judge: a wrong answer differs (exit 1) with each difference in words", "[cli-judge]") {
  Run r = run_eccd("judge " + crossing + " " + answer("wrong-end.json") + " --name mysim");
  CHECK(r.code == 1);
  CHECK(r.out.find("verdict: differs: 1 difference(s)") != std::string::npos);
  CHECK(r.out.find("collision interval 1 end off by 0.001 (certified 0.8684320663, mysim 0.8694320663)") !=
        std::string::npos);
  // A coarser tolerance accepts it.
  CHECK(run_eccd("judge " + crossing + " " + answer("wrong-end.json") + " --tol 0.01").code == 0);

  Run t = run_eccd("judge " + q(src("cases/touch3d/touch-and-separate.json")) + " " +
                   answer("fcl-sampled-touch-and-separate-7.json"));
  CHECK(t.code == 1);
  CHECK(t.out.find("verdict: wrong collides") != std::string::npos);
  CHECK(t.out.find("collides: certified true, yours false") != std::string::npos);
}

TEST_CASE("eccd judge --json: the judgement's keys", "[cli-judge]") {
  Run r = run_eccd("judge " + crossing + " " + answer("fcl-sampled-spheres-crossing-10.json") + " --name fcl --json");
  REQUIRE(r.code == 1);
  nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* k :
       {"format", "scene", "engine", "agrees", "verdict", "differences", "counts", "certified_answer", "tolerance"})
    CHECK(j.contains(k));
  CHECK(j["format"] == "eccd-judgement/1");
  CHECK(j["scene"] == "spheres-crossing");
  CHECK(j["engine"] == "fcl");
  CHECK(j["agrees"] == false);
  CHECK(j["verdict"] == "differs: 2 difference(s)");
  CHECK(j["differences"].size() == 2);
  CHECK(j["counts"]["endpoints_off"] == 2);
  CHECK(j["counts"]["missed_contacts"] == 2);
  CHECK(j["counts"]["max_endpoint_error"].get<double>() > 0.06);
  CHECK(j["certified_answer"]["collides"] == true);
  CHECK(j["certified_answer"]["intervals"][0][0]["lo"].is_string());
  CHECK(j["tolerance"].get<double>() == 1e-6);
}

TEST_CASE("eccd judge: the answer from stdin", "[cli-judge]") {
  Run r = run_eccd("judge " + crossing + " - --json < " + answer("correct.json"));
  CHECK(r.code == 0);
  nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["agrees"] == true);
  CHECK(j["answer_file"] == "<stdin>");
  Run bad = run_eccd("judge " + crossing + " - < " + answer("malformed.json"));
  CHECK(bad.code == 2);
  CHECK(bad.err.find("<stdin>: /intervals/0/1:") != std::string::npos);
}

TEST_CASE("eccd judge: bad input exits 2 naming the file and the place", "[cli-judge]") {
  Run m = run_eccd("judge " + crossing + " " + answer("malformed.json"));
  CHECK(m.code == 2);
  CHECK(m.out.empty());
  CHECK(m.err.find("malformed.json: /intervals/0/1: lo and hi must both be") != std::string::npos);

  TempDir d;
  spit(d.path / "notjson.json", "{\"collides\": true,");
  Run n = run_eccd("judge " + crossing + " " + q((d.path / "notjson.json").string()));
  CHECK(n.code == 2);
  CHECK(n.err.find("notjson.json: line") != std::string::npos);

  spit(d.path / "other.json", "{\"intervals\": []}");
  Run o = run_eccd("judge " + crossing + " " + q((d.path / "other.json").string()));
  CHECK(o.code == 2);
  CHECK(o.err.find("other.json: top level: neither an answer") != std::string::npos);

  Run missing = run_eccd("judge " + crossing + " " + q((d.path / "absent.json").string()));
  CHECK(missing.code == 2);
  CHECK(missing.err.find("absent.json") != std::string::npos);

  Run scene = run_eccd("judge " + q(bad("json_syntax.json")) + " " + answer("correct.json"));
  CHECK(scene.code == 2);
  CHECK(scene.err.find("json_syntax.json: line") != std::string::npos);
}

TEST_CASE("eccd judge: a scene the exact pipeline refuses exits 3", "[cli-judge]") {
  Run r = run_eccd("judge " + q(bad("cycloidal_exact.json")) + " " + answer("correct.json"));
  CHECK(r.code == 3);
  CHECK(r.out.empty());
  CHECK(r.err.find("cycloidal_exact.json") != std::string::npos);
}

}  // namespace ECCD_UNITY_ID
