// `eccd separate SCENE --at T [--arith A] [--json]`: a separating plane (2D:
// line) of the scene's two objects at the instant T (paper 000 section 3;
// api/separate.hpp), with the inequalities that prove it, or the exact
// statement that they touch or overlap. Exit 0 (separate, touching,
// overlapping, or undecided in a floating arithmetic, which says why), 2 bad
// input (T not a rational in [0, 1], a bad scene), 3 refused (a cycloidal or
// independent-motions scene), 4 exact/certified could not prove a plane.
#include "app/commands.hpp"
#include "api/separate.hpp"
#include "api/separate_json.hpp"
#include "io/scene_reader.hpp"
#include "kernel/budget.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <sstream>

namespace eccd {

namespace {

struct SeparateArgs {
  std::string scene, at, arith = "exact";
  bool json = false;
};

std::string tuple_text(const std::vector<mpq_class>& v, bool exact) {
  std::string r = "(";
  for (std::size_t i = 0; i < v.size(); ++i) r += (i ? ", " : "") + (exact ? v[i].get_str() : decimal_string(v[i], 17));
  return r + ")";
}

}  // namespace

Command add_separate_command(CLI::App& app) {
  auto args = std::make_shared<SeparateArgs>();
  Command c;
  c.sub = app.add_subcommand(
      "separate",
      "A separating plane (2D: line) of the scene's two objects at one instant (paper 000 section 3), with the "
      "inequalities that prove it; or the exact statement that they touch or overlap. Exit 0, 2 bad input, "
      "3 refused (cycloidal or independent motions), 4 exact could not prove a plane.");
  c.sub->add_option("SCENE", args->scene, "Scene file (format ellipse-ccd-scene/1); - reads standard input")
      ->required();
  c.sub->add_option("--at", args->at, "The instant t in [0, 1], an exact rational: 1/3, 0.25, 1e-3")->required();
  c.sub
      ->add_option("--arith", args->arith,
                   "Arithmetic: exact (default: a plane with rational coefficients, proved), certified "
                   "(proved too: the double plane when its error-bounded checks hold, else exact), double or mpfr:BITS "
                   "(checked with a running error bound; undecided where "
                   "it cannot decide)")
      ->capture_default_str();
  c.sub->add_flag("--json", args->json, "Print one JSON object (format eccd-separate/1)");
  c.run = [args]() -> int {
    SolveOptions opt;
    opt.arith = parse_arithmetic(args->arith);
    mpq_class t;
    try {
      t = parse_rational(args->at);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--at " + args->at + ": " + e.what() +
                                  " (expected a rational in [0, 1] such as 1/3 or 0.25)");
    }
    if (sgn(t) < 0 || t > 1) throw std::invalid_argument("--at " + args->at + ": the instant must lie in [0, 1]");
    const SceneSource src = read_scene_source(args->scene);
    Scene scene = parse_scene(src.text, src.label);
    Separation sep;
    try {
      ScopedDeadline deadline(run_budget().time_limit_s);
      sep = separate_at(scene, t, opt);
    } catch (const std::invalid_argument& e) {  // valid options, valid scene: refused (cycloidal, independent)
      throw ExitError(3, "separate: " + src.label + ": " + cli_message(e));
    }
    const bool exact = !opt.arith.floating();
    if (exact && sep.status == "undecided") throw ExitError(4, "separate: " + src.label + ": " + sep.why);
    if (args->json) {
      nlohmann::ordered_json j;
      stamp_format(j, kSeparateFormat);
      const nlohmann::ordered_json body =
          separation_to_json(scene, src.label, t, opt.arith, sep);  // api/separate_json.hpp
      for (const auto& it : body.items()) j[it.key()] = it.value();
      std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
      return 0;
    }
    std::ostringstream o;
    o << "scene " << scene.name << " (" << scene.dim << "D) at t = " << t.get_str() << ", " << opt.arith.name()
      << " arithmetic: " << sep.status << "\n";
    if (sep.plane) {
      o << "  separating " << (scene.dim == 2 ? "line" : "plane")
        << " n.x + o = 0 (a on the negative side, b on the positive side):\n"
        << "    n = " << tuple_text(sep.plane->normal, true) << "\n    o = " << sep.plane->offset.get_str() << "\n";
      if (sep.tangent_points.size() == 2)
        o << "  tangent points (000 section 3): a " << tuple_text(sep.tangent_points[0], false) << ", b "
          << tuple_text(sep.tangent_points[1], false) << "\n";
      bool bounded = !exact;  // certified: the double plane's checks carry error bounds (api/separate.hpp)
      for (const auto& k : sep.checks) bounded = bounded || k.error_bound > 0;
      o << (!bounded
                ? "  proof (exact; q = M(t)^T (n, o), M the scene's motion matrix, Q its shape matrix, det Q < 0):\n"
            : exact ? "  proof (in double with a running error bound that holds for the scene's exact numbers; q = "
                      "M(t)^T (n, o)):\n"
                    : "  checks (computed in " + opt.arith.name() + " with a running error bound):\n");
      for (const auto& k : sep.checks) {
        o << "    " << k.object << ": " << k.quantity << " = "
          << (!bounded ? k.value.get_str() : decimal_string(k.value, 17));
        if (bounded) o << " (error bound " << k.error_bound << ")";
        o << " " << k.relation;
        if (!k.centre.empty()) o << ", c = " << tuple_text(k.centre, !bounded);
        o << "\n";
      }
    } else if (!sep.why.empty()) {
      o << "  why: " << sep.why << "\n";
    }
    std::cout << o.str();
    return 0;
  };
  return c;
}

}  // namespace eccd
