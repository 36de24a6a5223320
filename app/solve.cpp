// `eccd solve`: one scene, one arithmetic, one answer (the typed API's
// Solution, printed by io/solution_json.hpp as text or JSON). Exit 2 for a
// bad option, a bad option value or bad input (checked before the scene is
// solved), 3 for a request the pipeline refuses on a valid scene (a cycloidal
// motion in exact arithmetic, a 3D basis the method does not take). An option
// that the given combination ignores gets a warning on stderr (ignored_options).
// SCENE "-" reads the scene from standard input (labelled "<stdin>").
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/json_text.hpp"
#include "api/solve.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"
#include "kernel/budget.hpp"
#include "kernel/cycloidal_motion.hpp"

#include <sys/time.h>

#include <fstream>
#include <iostream>
#include <memory>
#include <tuple>

namespace eccd {

namespace {

struct SolveArgs {
  std::string scene_path, arith = "exact", basis = "bernstein", method = "bezier", input = "rounded", guard = "bound";
  int variant = 0;
  bool json = false, first_contact = false, store = false;
  CLI::Option *input_opt = nullptr, *guard_opt = nullptr, *basis_opt = nullptr, *method_opt = nullptr,
              *variant_opt = nullptr;
};

// The options the combination of arithmetic, dimension and method does not
// use (api/solve.cpp): each is a warning, none changes the answer.
std::vector<std::string> ignored_options(const SolveArgs& a, const SolveOptions& opt, int dim) {
  std::vector<std::string> w;
  const bool floating = opt.arith.floating();
  const std::string arith = opt.arith.name();
  if (a.input_opt->count() && !floating)
    w.push_back("--input applies to double and mpfr only; " + arith + " starts from the exactly prepared scene");
  if (a.guard_opt->count() && !floating)
    w.push_back("--guard applies to double and mpfr only; " + arith + " has no floating face");
  if (a.basis_opt->count() && !floating)
    w.push_back("--basis applies to double and mpfr only; " + arith + " computes with exact coefficients");
  if (a.method_opt->count() && (!floating || dim == 2))
    w.push_back("--method is ignored: it chooses among the 3D floating methods; " +
                std::string(dim == 2 ? "2D scenes run CD-DISC (003)" : arith + " runs the exact projection"));
  if (a.first_contact && dim == 2)
    w.push_back("--first-contact is ignored in 2D; use --variant 2 (first contact, 003 VI-C)");
  if (a.variant_opt->count() && dim == 3 && a.variant != 0 && a.variant != 2)
    w.push_back("--variant " + std::to_string(a.variant) + " is ignored in 3D (only 2 = --first-contact applies)");
  return w;
}

// Stores the spec's answer (the four keys) into the scene file: written to a
// temporary file first and renamed, so a failure leaves the file untouched.
// The scene file is replaced by design (it is the input). What would be
// written is read back first by the scene reader, under the same limits: a
// file eccd would then refuse (over --max-file-bytes, --max-digits) is not
// written, and the message says why.
void write_answer(const std::string& path, const Solution& report) {
  const std::string bytes = read_file_bytes(path);  // bounded, and only a regular file
  nlohmann::ordered_json doc;
  try {
    doc = nlohmann::ordered_json::parse(bytes);
  } catch (const nlohmann::json::exception& e) {
    throw SceneError(path + ": the file changed while it was solved (" + e.what() + "): the answer is not written");
  }
  doc["answer"] = stored_answer_of(report);
  const std::string text = compact_json(doc) + "\n";
  try {
    (void)parse_scene(text, path);
  } catch (const SceneError& e) {
    throw SceneError(std::string(e.what()) +
                     " (in the scene with its answer, as --write-answer would write it: the file is left unchanged)");
  }
  write_text_atomically(path, text);
}

void add_solve_options(CLI::App* sub, SolveArgs& args) {
  sub->add_option("SCENE", args.scene_path, "Scene file (format ellipse-ccd-scene/1); - reads standard input")
      ->required();
  sub->add_option(
         "--arith", args.arith,
         "Arithmetic: double, mpfr:BITS (53..65536), exact (certified brackets) or certified (interval arithmetic "
         "with certified brackets: intervals of doubles, then MPFI intervals of 256 bits, then exact, each rung only "
         "where a sign stayed uncertain; certified:B1,B2,... other MPFI rungs, certified:none no MPFI rung)")
      ->capture_default_str();
  args.basis_opt = sub->add_option("--basis", args.basis,
                                   "Floating only: basis in which the discriminant (2D) or projection (3D --method "
                                   "projection) is built: power, bernstein or scaled-bernstein")
                       ->capture_default_str();
  args.variant_opt = sub->add_option("--variant", args.variant,
                                     "2D: 0: full answer with intervals; 1: collides? only; 2: first contact; 3: all "
                                     "external contacts (003 VI-C). 3D: 2 = --first-contact")
                         ->capture_default_str();
  sub->add_flag(
      "--json", args.json,
      "Print exactly one JSON object (the spec's answer plus timing, degree of the discriminant, contact points)");
  args.method_opt =
      sub->add_option(
             "--method", args.method,
             "3D floating only: bezier (001 section 4: sampling, Bezier shooting, subdivision, Gaussian-circle test), "
             "projection (discriminant roots, as the exact pipeline), sampling:N (static tests at N+1 instants) or "
             "marching:N (marching squares on an N x N grid of F(u,t), 002 section IV)")
          ->capture_default_str();
  sub->add_flag("--first-contact", args.first_contact,
                "3D: compute the first collision interval only (first-contact mode of 001 section 4)");
  args.input_opt =
      sub->add_option("--input", args.input,
                      "Floating only: rounded (each number of the scene rounded to the arithmetic, everything after "
                      "computed in it: "
                      "what a user's program does) or prepared (the scene prepared exactly, then rounded)")
          ->capture_default_str();
  args.guard_opt =
      sub->add_option("--guard", args.guard,
                      "Floating only: bound (guarded: a running error bound on every value, a sign it cannot decide "
                      "makes that place undecided) or none (the published algorithm in plain double or MPFR, nothing "
                      "added: its answer can be wrong; undecided only where the algorithm gives up: a work bound, a "
                      "value that is not finite, the time budget). Cycloidal scenes have the guarded face only")
          ->capture_default_str();
  sub->add_flag("--write-answer", args.store,
                "Store the answer in the scene file under \"answer\" (exact arithmetic only; the scene file is "
                "replaced by design, and "
                "left unchanged if the scene reader would refuse the result, e.g. beyond --max-file-bytes)");
}

}  // namespace

Command add_solve_command(CLI::App& app) {
  auto args = std::make_shared<SolveArgs>();
  Command c;
  c.sub = app.add_subcommand(
      "solve", "Solve one scene: collision intervals, first contact and external contacts over t in [0, 1].");
  add_solve_options(c.sub, *args);

  c.run = [args]() -> int {
    // Every option value is checked before the scene is read: a bad one is exit 2.
    SolveOptions opt;
    opt.arith = parse_arithmetic(args->arith);
    if (args->variant < 0 || args->variant > 3)
      throw std::invalid_argument("--variant " + std::to_string(args->variant) + ": expected 0, 1, 2 or 3");
    opt.variant = Variant(args->variant);
    std::tie(opt.method, opt.grid) = parse_method(args->method);
    opt.first_contact = args->first_contact || (args->variant == 2);
    try {
      opt.input = parse_input_mode(args->input);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--input ") + e.what());
    }
    opt.guard = parse_guard(args->guard);
    try {
      opt.basis = parse_basis(args->basis);
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      throw std::invalid_argument("--basis " + args->basis + ": " + m);
    }
    if (args->store && opt.arith.kind != Arithmetic::Exact && opt.arith.kind != Arithmetic::Certified)
      throw std::invalid_argument(
          "--write-answer stores exact answers only: use --arith exact (certified for a cycloidal scene)");
    if (args->store && args->scene_path == "-")
      throw std::invalid_argument("--write-answer needs a scene file, not - (standard input)");
    arm_backstop(run_budget().time_limit_s);
    const SceneSource src = read_scene_source(args->scene_path);
    Scene s = parse_scene(src.text, src.label);
    // The stored answer is the exact one; a cycloidal scene has none, so its certified answer is stored instead.
    if (args->store && opt.arith.kind == Arithmetic::Certified && !(s.dim == 2 && has_cycloidal_motion(s)))
      throw std::invalid_argument(
          "--write-answer stores exact answers only: use --arith exact (certified only for a cycloidal scene)");
    if (s.dim == 3 && opt.arith.floating() && opt.basis == Basis::scaled_bernstein && opt.method != Method::projection)
      throw std::invalid_argument("--basis scaled-bernstein: in 3D it applies to --method projection only");
    for (const auto& w : ignored_options(*args, opt, s.dim)) warn("solve", w);
    Solution r;
    try {
      ScopedDeadline deadline(run_budget().time_limit_s);
      r = eccd::solve(s, opt);
    } catch (const std::invalid_argument& e) {  // valid options, valid scene: the pipeline refuses the request
      throw ExitError(3, "solve: " + src.label + ": " + cli_message(e));
    }
    {
      itimerval off{};
      setitimer(ITIMER_REAL, &off, nullptr);
    }  // solved: the backstop is not needed for writing
    if (args->store) write_answer(args->scene_path, r);
    if (args->json) {
      nlohmann::json j = solution_to_json(r);
      stamp_format(j, kSolutionFormat);
      std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else {
      std::cout << summary_text(r);
    }
    return 0;
  };
  return c;
}

}  // namespace eccd
