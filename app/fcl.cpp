// `eccd fcl SCENE [--samples N [--gjk-tolerance X] | --ccd N] [--json]`: FCL's answer for a scene
// (compare/fcl_engine.hpp, docs/fcl.md), in the scene format's answer form,
// so that `eccd judge SCENE ANSWER` judges the real FCL. It prints one object
// with "format" ("eccd-fcl-answer/1"), "version", the engine, FCL's version and tolerances
// ("gjk_tolerance": the one fcl::collide received) and the answer under "answer" (judge reads it from there;
// for --ccd only collides and first_contact: FCL's continuous collision claims nothing else); --json changes nothing.
// Exit 0, 2 bad option or scene, 3 refused: FCL is not built in, a motion --ccd cannot express, a pose that is not an
// ellipsoid in double.
#include "app/commands.hpp"
#include "compare/fcl_engine.hpp"
#include "io/scene_reader.hpp"

#include <iostream>
#include <memory>

namespace eccd {

namespace {

struct FclArgs {
  std::string scene;
  int samples = 100, ccd = 0;
  double gjk_tolerance = 0;
  bool json = false;
  CLI::Option *samples_opt = nullptr, *ccd_opt = nullptr, *gjk_opt = nullptr;
};

}  // namespace

Command add_fcl_command(CLI::App& app) {
  auto args = std::make_shared<FclArgs>();
  Command c;
  c.sub = app.add_subcommand(
      "fcl",
      "FCL's answer for a scene (FCL 0.7 as a peer engine, docs/fcl.md), in the scene format's answer "
      "form, for `eccd judge SCENE ANSWER`. Exit 0, 2 bad input, 3 refused (FCL not built in, a motion "
      "--ccd cannot express).");
  auto* s = c.sub;
  s->add_option("SCENE", args->scene, "Scene file (ellipse-ccd-scene/1); - reads standard input")->required();
  args->samples_opt =
      s->add_option("--samples", args->samples,
                    "fcl::collide at t = k/N, k = 0..N, colliding samples merged into intervals (fcl/sample:N)")
          ->capture_default_str()
          ->check(CLI::Range(1, 10000000));
  args->ccd_opt =
      s->add_option("--ccd", args->ccd,
                    "fcl::continuousCollide, naive solver, N iterations, translation motion (fcl/ccd:N): collides "
                    "and first contact only; only for constant shapes moving by a translation linear in t")
          ->check(CLI::Range(2, 10000000));
  args->samples_opt->excludes(args->ccd_opt);
  args->gjk_opt =
      s->add_option("--gjk-tolerance", args->gjk_tolerance,
                    "FCL's CollisionRequest::gjk_tolerance for fcl::collide (default FCL's own, 1e-6), e.g. 1e-12; "
                    "not with --ccd (FCL's continuous collision uses a default request inside)")
          ->check(CLI::PositiveNumber);
  args->gjk_opt->excludes(args->ccd_opt);
  s->add_flag("--json", args->json,
              "Print one JSON object (format eccd-fcl-answer/1) with the answer under \"answer\"; the output is that "
              "object with or without --json (eccd judge reads it)");
  c.run = [args]() -> int {
    const SceneSource src = read_scene_source(args->scene);
    Scene scene = parse_scene(src.text, src.label);
    const FclAvailability fa = fcl_availability();
    if (!fa.available) throw ExitError(3, "fcl: " + fa.reason);
    const bool ccd = args->ccd_opt->count() > 0;
    const int n = ccd ? args->ccd : args->samples;
    const std::string engine = std::string(ccd ? "fcl/ccd:" : "fcl/sample:") + std::to_string(n);
    FclOptions fo;
    fo.gjk_tolerance = args->gjk_tolerance;
    Answer a;
    try {
      a = ccd ? fcl_ccd(scene, n, fo) : fcl_sample(scene, n, fo);
    } catch (
        const std::invalid_argument& e) {  // a valid scene FCL is not given: inexpressible motion, not an ellipsoid
      throw ExitError(3, "fcl: " + src.label + ": " + engine + ": " + e.what());
    }
    nlohmann::ordered_json ans = nlohmann::ordered_json::parse(answer_to_json(a).dump());
    if (ccd) {  // FCL's continuous collision gives collides and the time of contact only
      ans.erase("intervals");
      ans.erase("contacts");
    }
    {  // with or without --json: one object with format and version; eccd judge takes its "answer"
      nlohmann::ordered_json out;
      stamp_format(out, "eccd-fcl-answer/1");
      out["scene"] = scene.name;
      out["scene_file"] = src.label;
      out["engine"] = engine;
      out["fcl_version"] = fa.version;
      out["tolerances"] = fcl_tolerances(fo);
      out["gjk_tolerance"] = fcl_gjk_tolerance(fo);
      out["answer"] = ans;
      std::cout << out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    }
    return 0;
  };
  return c;
}

}  // namespace eccd
