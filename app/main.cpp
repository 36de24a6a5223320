// eccd: the workbench's command-line front door.
//   eccd solve SCENE [--arith double|mpfr:BITS|exact] [--basis ...] [--input rounded|prepared] [--variant N] [--json]
//   eccd table [DIR] [--mpfr BITS ...] [--json]   every scene of DIR in every arithmetic, side by side
//   eccd generate / report / plot                 app/generate.cpp, app/report.cpp, app/plot.cpp
//   eccd certify / check-certificate              app/certify.cpp
//   eccd regress [DIR]                            app/regress.cpp
// Exit status (README "Exit codes"): 0 success; 1 an internal error (a bug),
// a rejected certificate (check-certificate) or a regression (regress); 2 bad
// input or a bad option, including input beyond the input limits and output
// paths that cannot be written; 3 a request the pipeline refuses (e.g. a
// cycloidal motion in exact arithmetic, also by certify); 4 a scene the
// certifier cannot certify; 5 a resource budget (time, memory) exhausted while
// solving; 130 report interrupted (SIGINT/SIGTERM). Nothing is written to
// stdout unless the command succeeds.
//
// Resource budget (issue 15): --time-limit SECONDS per pipeline run (default
// 300), --memory-limit MIB for the process (setrlimit RLIMIT_AS, default 4096),
// --max-file-bytes / --max-digits / --max-degree for scene files
// (io/scene_reader.hpp InputLimits). They are options of `eccd` and of
// every sub-command.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/json_text.hpp"
#include "api/solve.hpp"
#include "io/solution_json.hpp"
#include "kernel/budget.hpp"
#include "io/scene_reader.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <tuple>
#include <sstream>

namespace fs = std::filesystem;
using namespace eccd;

namespace {

// The backstop of --time-limit for commands that are one pipeline run (solve,
// certify, check-certificate): if a loop does not ask the deadline
// (kernel/budget.hpp), SIGALRM at 1.5 x the limit + 2 s ends the process with
// exit 5 (nothing on stdout; output files are only ever renamed into place).
void on_backstop(int) {
  static const char msg[] =
      "eccd: resource budget exhausted: the time limit passed (--time-limit) and the run did not stop by itself; ended\n";
  ssize_t n = write(2, msg, sizeof msg - 1);
  (void)n;
  _exit(5);
}
void arm_backstop(double seconds) {
  if (seconds <= 0) return;
  double at = seconds * 1.5 + 2;
  struct sigaction sa {};
  sa.sa_handler = on_backstop;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGALRM, &sa, nullptr);
  itimerval t{};
  t.it_value.tv_sec = time_t(at);
  t.it_value.tv_usec = suseconds_t((at - double(time_t(at))) * 1e6);
  setitimer(ITIMER_REAL, &t, nullptr);
}

// A message for stderr: at most 2000 characters (a user's 10 MB key is not echoed whole).
std::string cut_message(const std::string& m) { return m.size() > 2000 ? m.substr(0, 2000) + "... (cut)" : m; }

std::string short_answer(const nlohmann::json& r) {
  if (!r.contains("collides")) return "error";
  std::ostringstream o;
  o << (r["collides"].get<bool>() ? "collides" : "free");
  if (r["intervals"].is_array() && !r["intervals"].empty()) {
    o << " " << r["intervals"].size() << "iv";
    std::string fc = r["first_contact"]["approx"].get<std::string>();
    o << " t0=" << fc.substr(0, std::min<std::size_t>(fc.size(), 10));
  }
  if (!r["undecided"].empty()) o << " ?" << r["undecided"].size();
  return o.str();
}

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

int run_table(const std::string& dir, const std::vector<int>& mpfr_bits, bool json) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) throw std::invalid_argument(dir + ": not a directory");
  for (auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  struct Col { std::string label; SolveOptions opt; };
  std::vector<Col> cols;
  auto col = [](const std::string& arith, Basis basis) {
    SolveOptions o;
    o.arith = parse_arithmetic(arith);
    o.basis = basis;
    return o;
  };
  cols.push_back({"exact", col("exact", Basis::bernstein)});
  cols.push_back({"double/power", col("double", Basis::power)});
  cols.push_back({"double/bernstein", col("double", Basis::bernstein)});
  cols.push_back({"double/scaled", col("double", Basis::scaled_bernstein)});
  for (int b : mpfr_bits) cols.push_back({"mpfr:" + std::to_string(b), col("mpfr:" + std::to_string(b), Basis::bernstein)});
  nlohmann::json all = nlohmann::json::array();
  std::vector<std::vector<std::string>> rows;
  std::size_t done = 0;
  for (const auto& f : files) {
    std::vector<std::string> row{f.filename().string()};
    nlohmann::json js;
    js["file"] = f.string();
    std::optional<Solution> exact;
    try {
      Scene s = read_scene_file(f.string());
      for (const auto& c : cols) {
        try {
          ScopedDeadline deadline(run_budget().time_limit_s);
          Solution sol = solve(s, c.opt);
          nlohmann::json r = solution_to_json(sol);
          js[c.label] = r;
          std::string cell = short_answer(r);
          if (c.label == "exact") exact = sol;
          // TODO(issue 16): eccd::answer_difference (api/answer_difference.hpp) once it lands.
          if (c.label != "exact" && exact) {
            const Answer &got = sol.answer, &ex = exact->answer;
            bool same = got.collides == ex.collides && got.intervals.size() == ex.intervals.size();
            auto near = [](const Instant& a, const Instant& b) { return std::abs(a.value - b.value) <= 1e-6; };
            if (same && got.first_contact && ex.first_contact) same = near(*got.first_contact, *ex.first_contact);
            for (std::size_t k = 0; same && k < got.intervals.size(); ++k)
              same = near(got.intervals[k].first, ex.intervals[k].first) && near(got.intervals[k].second, ex.intervals[k].second);
            if (!same) cell = "!" + cell;
          }
          row.push_back(cell);
        } catch (const std::exception& e) {
          js[c.label] = {{"error", e.what()}};
          row.push_back("n/a");
        }
      }
    } catch (const SceneError& e) {
      js["error"] = e.what();
      row.push_back(std::string("bad scene: ") + e.what());
    }
    all.push_back(js);
    rows.push_back(row);
    ++done;
    std::fprintf(stderr, "\r[%zu/%zu] %s", done, files.size(), f.filename().string().c_str());
    std::fflush(stderr);
  }
  std::fprintf(stderr, "\n");
  if (json) { std::cout << all.dump(2) << "\n"; return 0; }
  std::vector<std::string> head{"scene"};
  for (auto& c : cols) head.push_back(c.label);
  std::vector<std::size_t> w(head.size(), 0);
  for (std::size_t i = 0; i < head.size(); ++i) w[i] = head[i].size();
  for (auto& r : rows) for (std::size_t i = 0; i < r.size() && i < w.size(); ++i) w[i] = std::max(w[i], r[i].size());
  auto line = [&](const std::vector<std::string>& r) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      std::cout << r[i];
      if (i + 1 < r.size()) std::cout << std::string(w[i] - r[i].size() + 2, ' ');
    }
    std::cout << "\n";
  };
  line(head);
  for (auto& r : rows) line(r);
  std::cout << "\n'!' marks a floating answer whose `collides` or number of intervals differs from the exact one,\n"
               "or whose first contact or an interval end is more than 1e-6 away from the exact one;\n"
               "3D scenes: floating columns run 001's Bezier method with f built in power or Bernstein form\n"
               "(scaled Bernstein is a 2D discriminant construction: n/a); exact is the certified projection;\n"
               "'?N' counts instants a floating pipeline could not classify; iv = collision intervals, t0 = first contact.\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"eccd: exact-arithmetic verification workbench for continuous collision detection of moving ellipses and ellipsoids"};
  app.require_subcommand(1);
  app.fallthrough();  // before the sub-commands are added: they inherit it (the budget options below work after them too)

  std::string scene_path, arith = "exact", basis = "bernstein";
  int variant = 0;
  bool json = false;
  auto* solve = app.add_subcommand("solve", "Solve one scene: collision intervals, first contact and external contacts over t in [0, 1].");
  solve->add_option("SCENE", scene_path, "Scene file (format ellipse-ccd-scene/1)")->required();
  solve->add_option("--arith", arith, "Arithmetic: double, mpfr:BITS (53..65536), exact (certified brackets) or certified (interval arithmetic with certified brackets: intervals of doubles, then MPFI intervals of 256 bits, then exact, each rung only where a sign stayed uncertain; certified:B1,B2,... other MPFI rungs, certified:none no MPFI rung)")->capture_default_str();
  solve->add_option("--basis", basis, "Floating only: basis in which the discriminant (2D) or projection (3D --method projection) is built: power, bernstein or scaled-bernstein")->capture_default_str();
  solve->add_option("--variant", variant, "2D: 0: full answer with intervals; 1: collides? only; 2: first contact; 3: all external contacts (003 VI-C). 3D: 2 = --first-contact")->capture_default_str();
  solve->add_flag("--json", json, "Print exactly one JSON object (the spec's answer plus timing, degree of the discriminant, contact points)");
  std::string method = "bezier";
  solve->add_option("--method", method,
                    "3D floating only: bezier (001 section 4: sampling, Bezier shooting, subdivision, Gaussian-circle test), "
                    "projection (discriminant roots, as the exact pipeline), sampling:N (static tests at N+1 instants) or "
                    "marching:N (marching squares on an N x N grid of F(u,t), 002 section IV)")->capture_default_str();
  bool first_contact = false;
  solve->add_flag("--first-contact", first_contact, "3D: compute the first collision interval only (first-contact mode of 001 section 4)");
  std::string input = "rounded";
  auto* input_opt = solve->add_option("--input", input,
                    "Floating only: rounded (each number of the scene rounded to the arithmetic, everything after computed in it: "
                    "what a user's program does) or prepared (the scene prepared exactly, then rounded)")->capture_default_str();
  bool store = false;
  solve->add_flag("--write-answer", store, "Store the answer in the scene file under \"answer\" (exact arithmetic only)");

  std::string dir = "cases";
  std::vector<int> mpfr_bits{128};
  bool table_json = false;
  auto* table = app.add_subcommand("table", "Solve every scene under DIR in exact, double (power, Bernstein, scaled Bernstein) and MPFR arithmetic and print a side-by-side table.");
  table->add_option("DIR", dir, "Folder of scene files")->capture_default_str();
  table->add_option("--mpfr", mpfr_bits, "MPFR precisions in bits (repeatable)")->capture_default_str();
  table->add_flag("--json", table_json, "Print all results as one JSON array instead of the table");

  // The budget: options of eccd and (through fallthrough) of every sub-command.
  InputLimits& lim = input_limits();
  app.add_option("--time-limit", run_budget().time_limit_s,
                 "Seconds each pipeline run may take (a solve, a certify, one scene of regress, one task of report); "
                 "beyond it the exact pipeline stops with exit 5 and floating ones report undecided; 0 = none")
      ->capture_default_str()->check(CLI::Range(0.0, 1e9));
  app.add_option("--memory-limit", run_budget().memory_limit_mb,
                 "Address space of the process in MiB (setrlimit RLIMIT_AS); exhausted: exit 5; 0 = none")
      ->capture_default_str()->check(CLI::Range(std::size_t(0), std::size_t(1) << 30));
  app.add_option("--max-file-bytes", lim.max_file_bytes, "Largest scene file read (bytes); larger: exit 2")
      ->capture_default_str()->check(CLI::Range(std::size_t(1), std::size_t(1) << 40));
  app.add_option("--max-digits", lim.max_digits,
                 "Most decimal digits in the numerator or denominator of a scene's number (its exact value in lowest terms); more: exit 2")
      ->capture_default_str()->check(CLI::Range(std::size_t(1), std::size_t(1) << 24));
  app.add_option("--max-degree", lim.max_degree, "Highest degree of a polynomial in a scene file; higher: exit 2")
      ->capture_default_str()->check(CLI::Range(0, 100000));

  std::vector<Command> commands{add_generate_command(app),  add_report_command(app),           add_plot_command(app),
                                add_certify_command(app),   add_check_certificate_command(app), add_regress_command(app)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (run_budget().memory_limit_mb > 0) {
    rlimit rl{};
    rl.rlim_cur = rl.rlim_max = rlim_t(run_budget().memory_limit_mb) << 20;
    rlimit old{};
    if (getrlimit(RLIMIT_AS, &old) == 0 && old.rlim_max != RLIM_INFINITY && old.rlim_max < rl.rlim_max) rl.rlim_cur = rl.rlim_max = old.rlim_max;
    setrlimit(RLIMIT_AS, &rl);
  }

  std::ostringstream hint;
  hint << " (--time-limit " << run_budget().time_limit_s << " s, --memory-limit " << run_budget().memory_limit_mb << " MiB)";
  const std::string budget_hint = hint.str();
  try {
    if (*solve) {
      SolveOptions opt;
      opt.arith = parse_arithmetic(arith);
      opt.variant = Variant(variant);
      std::tie(opt.method, opt.grid) = parse_method(method);
      opt.first_contact = first_contact || (variant == 2);
      opt.input = parse_input_mode(input);
      if (input_opt->count() && opt.arith.kind != Arithmetic::Double && opt.arith.kind != Arithmetic::Mpfr)
        std::cerr << "eccd solve: warning: --input applies to double and mpfr only; " << opt.arith.name()
                  << " starts from the exactly prepared scene\n";
      arm_backstop(run_budget().time_limit_s);
      Scene s = read_scene_file(scene_path);
      Solution r;
      try {
        opt.basis = parse_basis(basis);
        ScopedDeadline deadline(run_budget().time_limit_s);
        r = eccd::solve(s, opt);
      } catch (const std::invalid_argument& e) {
        std::cerr << "eccd solve: " << scene_path << ": " << e.what() << "\n";
        return 3;
      }
      { itimerval off{}; setitimer(ITIMER_REAL, &off, nullptr); }  // solved: the backstop is not needed for writing
      if (store) {
        if (opt.arith.kind != Arithmetic::Exact) throw std::invalid_argument("--write-answer stores exact answers only: use --arith exact");
        write_answer(scene_path, r);
      }
      if (json) std::cout << solution_to_json(r).dump(2) << "\n";
      else std::cout << summary_text(r);
      return 0;
    }
    if (*table) return run_table(dir, mpfr_bits, table_json);
    for (auto& c : commands)
      if (*c.sub) {
        // certify and check-certificate are one pipeline run each; regress and
        // report set the deadline per scene / task themselves.
        const bool one_run = c.sub->get_name() == "certify" || c.sub->get_name() == "check-certificate";
        ScopedDeadline deadline(one_run ? run_budget().time_limit_s : 0);
        if (one_run) arm_backstop(run_budget().time_limit_s);
        if (c.sub->get_name() != "check-certificate") return c.run();
        try {
          return c.run();
        } catch (const std::invalid_argument& e) {  // e.g. a cycloidal scene: name the file if the message does not
          const std::string scene = c.sub->get_option("SCENE")->as<std::string>();
          std::string m = e.what();
          if (m.find(scene) == std::string::npos) throw std::invalid_argument(scene + ": " + m);
          throw;
        }
      }
  } catch (const SceneError& e) {
    std::cerr << "eccd: " << cut_message(e.what()) << "\n";
    return 2;
  } catch (const OutputError& e) {
    std::cerr << "eccd: " << cut_message(e.what()) << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "eccd: " << cut_message(e.what()) << "\n";
    return 2;
  } catch (const fs::filesystem_error& e) {  // a file or folder the user named: missing, unreadable, read-only
    std::string p = e.path1().string();
    if (!e.path2().empty()) p += " -> " + e.path2().string();
    std::cerr << "eccd: " << cut_message(p) << ": " << e.code().message() << "\n";
    return 2;
  } catch (const nlohmann::json::parse_error& e) {
    std::cerr << "eccd: malformed JSON: " << cut_message(e.what()) << "\n";
    return 2;
  } catch (const BudgetExhausted& e) {
    std::cerr << "eccd: resource budget exhausted: " << cut_message(e.what()) << budget_hint << "\n";
    return 5;
  } catch (const std::bad_alloc&) {
    std::cerr << "eccd: resource budget exhausted: out of memory" << budget_hint << "\n";
    return 5;
  } catch (const std::exception& e) {
    std::cerr << "eccd: internal error: " << cut_message(e.what()) << "\n";
    return 1;
  }
  return 0;
}
