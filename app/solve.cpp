// `eccd solve`: one scene, one arithmetic, one answer (the typed API's
// Solution, printed by io/solution_json.hpp as text or JSON). Exit 3 for a
// request the pipeline refuses (a cycloidal motion in exact arithmetic, a
// basis or variant the method does not take), 2 for bad options or input.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/json_text.hpp"
#include "api/solve.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"
#include "kernel/budget.hpp"

#include <sys/time.h>

#include <fstream>
#include <iostream>
#include <memory>
#include <tuple>

namespace eccd {

namespace {

struct SolveArgs {
  std::string scene_path, arith = "exact", basis = "bernstein", method = "bezier", input = "rounded";
  int variant = 0;
  bool json = false, first_contact = false, store = false;
  CLI::Option* input_opt = nullptr;
};

// Stores the spec's answer (the four keys) into the scene file: written to a
// temporary file first and renamed, so a failure leaves the file untouched.
void write_answer(const std::string& path, const Solution& report) {
  std::ifstream in(path, std::ios::binary);
  nlohmann::ordered_json doc;
  try {
    doc = nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw SceneError(path + ": the file changed while it was solved (" + e.what() + "): the answer is not written");
  }
  doc["answer"] = stored_answer_of(report);
  write_text_atomically(path, compact_json(doc) + "\n");
}

}  // namespace

Command add_solve_command(CLI::App& app) {
  auto args = std::make_shared<SolveArgs>();
  Command c;
  c.sub = app.add_subcommand("solve", "Solve one scene: collision intervals, first contact and external contacts over t in [0, 1].");
  c.sub->add_option("SCENE", args->scene_path, "Scene file (format ellipse-ccd-scene/1)")->required();
  c.sub->add_option("--arith", args->arith, "Arithmetic: double, mpfr:BITS (53..65536), exact (certified brackets) or certified (interval arithmetic with certified brackets: intervals of doubles, then MPFI intervals of 256 bits, then exact, each rung only where a sign stayed uncertain; certified:B1,B2,... other MPFI rungs, certified:none no MPFI rung)")->capture_default_str();
  c.sub->add_option("--basis", args->basis, "Floating only: basis in which the discriminant (2D) or projection (3D --method projection) is built: power, bernstein or scaled-bernstein")->capture_default_str();
  c.sub->add_option("--variant", args->variant, "2D: 0: full answer with intervals; 1: collides? only; 2: first contact; 3: all external contacts (003 VI-C). 3D: 2 = --first-contact")->capture_default_str();
  c.sub->add_flag("--json", args->json, "Print exactly one JSON object (the spec's answer plus timing, degree of the discriminant, contact points)");
  c.sub->add_option("--method", args->method,
                    "3D floating only: bezier (001 section 4: sampling, Bezier shooting, subdivision, Gaussian-circle test), "
                    "projection (discriminant roots, as the exact pipeline), sampling:N (static tests at N+1 instants) or "
                    "marching:N (marching squares on an N x N grid of F(u,t), 002 section IV)")->capture_default_str();
  c.sub->add_flag("--first-contact", args->first_contact, "3D: compute the first collision interval only (first-contact mode of 001 section 4)");
  args->input_opt = c.sub->add_option("--input", args->input,
                    "Floating only: rounded (each number of the scene rounded to the arithmetic, everything after computed in it: "
                    "what a user's program does) or prepared (the scene prepared exactly, then rounded)")->capture_default_str();
  c.sub->add_flag("--write-answer", args->store, "Store the answer in the scene file under \"answer\" (exact arithmetic only)");

  c.run = [args]() -> int {
    SolveOptions opt;
    opt.arith = parse_arithmetic(args->arith);
    opt.variant = Variant(args->variant);
    std::tie(opt.method, opt.grid) = parse_method(args->method);
    opt.first_contact = args->first_contact || (args->variant == 2);
    opt.input = parse_input_mode(args->input);
    if (args->input_opt->count() && opt.arith.kind != Arithmetic::Double && opt.arith.kind != Arithmetic::Mpfr)
      std::cerr << "eccd solve: warning: --input applies to double and mpfr only; " << opt.arith.name()
                << " starts from the exactly prepared scene\n";
    arm_backstop(run_budget().time_limit_s);
    Scene s = read_scene_file(args->scene_path);
    Solution r;
    try {
      opt.basis = parse_basis(args->basis);
      ScopedDeadline deadline(run_budget().time_limit_s);
      r = eccd::solve(s, opt);
    } catch (const std::invalid_argument& e) {
      std::cerr << "eccd solve: " << args->scene_path << ": " << e.what() << "\n";
      return 3;
    }
    { itimerval off{}; setitimer(ITIMER_REAL, &off, nullptr); }  // solved: the backstop is not needed for writing
    if (args->store) {
      if (opt.arith.kind != Arithmetic::Exact) throw std::invalid_argument("--write-answer stores exact answers only: use --arith exact");
      write_answer(args->scene_path, r);
    }
    if (args->json) std::cout << solution_to_json(r).dump(2) << "\n";
    else std::cout << summary_text(r);
    return 0;
  };
  return c;
}

}  // namespace eccd
