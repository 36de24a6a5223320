// `eccd table`: every scene of a folder in exact, double (power, Bernstein,
// scaled Bernstein) and MPFR arithmetic, side by side, each floating column
// as published and guarded (--guard); '!' marks a floating
// answer that differs from the exact one. Each scene's row is printed as soon
// as the scene is done (--json: JSON Lines, one eccd-table-row/1 object per
// scene); progress and the time left go to stderr (app/time_left.hpp).
#include "app/commands.hpp"
#include "app/option_names.hpp"
#include "app/scene_files.hpp"
#include "app/time_left.hpp"
#include "api/answer_difference.hpp"
#include "api/solve.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"
#include "kernel/budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

namespace eccd {

namespace {

// One scene's line of `eccd table --json` (JSON Lines: one object per line, printed when the scene is done).
constexpr const char* kTableRowFormat = "eccd-table-row/1";

std::string short_answer(const Solution& r) {
  std::ostringstream o;
  o << (r.answer.collides ? "collides" : "free");
  if (!r.answer.intervals.empty()) {
    o << " " << r.answer.intervals.size() << "iv";
    if (r.answer.first_contact) {
      const std::string& fc = r.answer.first_contact->approx;
      o << " t0=" << fc.substr(0, std::min<std::size_t>(fc.size(), 10));
    }
  }
  if (!r.answer.undecided.empty()) o << " ?" << r.answer.undecided.size();
  return o.str();
}

// The scenes under dir, sorted (animations, certificates and answers left out).
std::vector<fs::path> table_scene_files(const std::string& dir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) throw std::invalid_argument(dir + ": not a directory");
  for (auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file() || e.path().extension() != ".json") continue;
    std::string text, why;
    FileKind k = classify_file(e.path(), text, why);  // animations, certificates, answers: not scenes, left out
    if (k == FileKind::Broken) throw SceneError(e.path().string() + ": " + why);
    if (k == FileKind::Scene) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// One column of the table: its label and how it solves.
struct TableColumn {
  std::string label;
  SolveOptions opt;
};

// exact, then each floating column in each face asked for.
std::vector<TableColumn> table_columns(const std::vector<int>& mpfr_bits, const std::vector<std::string>& guards) {
  std::vector<TableColumn> cols;
  auto col = [](const std::string& arith, Basis basis, Guard guard = Guard::bound) {
    SolveOptions o;
    o.arith = parse_arithmetic(arith);
    o.basis = basis;
    o.guard = guard;
    return o;
  };
  cols.push_back({"exact", col("exact", Basis::bernstein)});
  // Each floating column in each face asked for: as published (label ".../published") and guarded.
  auto floating = [&](const std::string& label, const std::string& arith, Basis basis) {
    for (const auto& g : guards) {
      const Guard face = parse_guard(g);
      cols.push_back({face == Guard::none ? label + "/published" : label, col(arith, basis, face)});
    }
  };
  floating("double/power", "double", Basis::power);
  floating("double/bernstein", "double", Basis::bernstein);
  floating("double/scaled", "double", Basis::scaled_bernstein);
  for (int b : mpfr_bits) floating("mpfr:" + std::to_string(b), "mpfr:" + std::to_string(b), Basis::bernstein);
  return cols;
}

// One scene in every column: its cells (row) and its JSON object (js).
void table_cells(const std::vector<TableColumn>& cols, const fs::path& f, std::vector<std::string>& row,
                 nlohmann::json& js) {
  std::optional<Solution> exact;
  try {
    Scene s = read_scene_file(f.string());
    for (const auto& c : cols) {
      try {
        ScopedDeadline deadline(run_budget().time_limit_s);
        Solution sol = solve(s, c.opt);
        js[c.label] = solution_to_json(sol);
        stamp_format(js[c.label], kSolutionFormat);
        std::string cell = short_answer(sol);
        if (c.label == "exact") exact = sol;
        // '!': the one answer comparison (api/answer_difference.hpp) finds a difference other
        // than undecided instants (counted by '?N').
        if (c.label != "exact" && exact) {
          AnswerDifference d = answer_difference(sol.answer, exact->answer);
          if (d.differences.size() > std::size_t(d.undecided)) cell = "!" + cell;
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
}

int run_table(const std::string& dir, const std::vector<int>& mpfr_bits, const std::vector<std::string>& guards,
              bool json) {
  const std::vector<fs::path> files = table_scene_files(dir);
  const std::vector<TableColumn> cols = table_columns(mpfr_bits, guards);
  // Each scene's row goes to stdout as soon as it is finished (a line of the table, or with --json one JSON
  // object per line, JSON Lines); progress goes to stderr. Column widths are fixed up front so that rows
  // can be printed one by one: the longest file name, and each column at least as wide as its label.
  std::vector<std::string> head{"scene"};
  for (auto& c : cols) head.push_back(c.label);
  std::vector<std::size_t> w(head.size(), 0);
  for (std::size_t i = 0; i < head.size(); ++i) w[i] = std::max<std::size_t>(head[i].size(), i == 0 ? 0 : 22);
  for (const auto& f : files) w[0] = std::max(w[0], f.filename().string().size());
  auto line = [&](const std::vector<std::string>& r) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      std::cout << r[i];
      if (i + 1 < r.size()) std::cout << std::string(r[i].size() < w[i] ? w[i] - r[i].size() + 2 : 2, ' ');
    }
    std::cout << std::endl;  // flushed: a reader of the pipe sees each row when it is done
  };
  if (!json) line(head);
  const bool tty = isatty(2);
  ProgressCadence cadence(tty, long(files.size()));
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::size_t done = 0;
  for (const auto& f : files) {
    if (!quiet() && tty) {  // on a terminal: which scene is running now
      std::fprintf(stderr, "\r[%zu/%zu] %s ...\x1b[K", done, files.size(), f.filename().string().c_str());
      std::fflush(stderr);
    }
    std::vector<std::string> row{f.filename().string()};
    nlohmann::json js;
    stamp_format(js, kTableRowFormat);
    js["folder"] = dir;
    js["file"] = f.string();
    table_cells(cols, f, row, js);
    ++done;
    if (!quiet() && tty) std::fprintf(stderr, "\r\x1b[K");  // the row replaces the progress line on a shared terminal
    if (json)
      std::cout << js.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;
    else
      line(row);
    const double el = seconds();
    if (!quiet() && cadence.due(long(done), el)) {
      std::optional<double> left;
      if (done < files.size())
        left = el / double(done) * double(files.size() - done);  // the measured rate per scene
      else
        left = 0.0;
      std::fprintf(stderr, "%s[%zu/%zu] %s, %.0f s elapsed, %s%s", cadence.begin(), done, files.size(),
                   f.filename().string().c_str(), el, time_left_text(left).c_str(), tty ? "" : "\n");
      std::fflush(stderr);
    }
  }
  if (!quiet() && tty) std::fprintf(stderr, "\n");
  if (json) return 0;
  std::cout
      << "\n'!' marks a floating answer that differs from the exact one (api/answer_difference.hpp: collides,\n"
         "an interval missed, false, split or merged, an end, the first contact or a contact more than 1e-6 away);\n"
         "3D scenes: floating columns run 001's Bezier method with f built in power or Bernstein form\n"
         "(scaled Bernstein is a 2D discriminant construction: n/a); exact is the certified projection;\n"
         "'?N' counts instants a floating pipeline could not classify; iv = collision intervals, t0 = first contact;\n"
         "'/published': the algorithm as published (plain double or MPFR, no guard), the other floating columns are\n"
         "guarded (an error bound makes every unsure sign undecided). A cycloidal scene has no as-published face "
         "(n/a).\n";
  return 0;
}

}  // namespace

Command add_table_command(CLI::App& app) {
  struct Args {
    std::string dir = "cases";
    std::vector<int> mpfr_bits{128};
    std::vector<std::string> guards{"none", "bound"};
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  Command c;
  c.sub =
      app.add_subcommand("table",
                         "Solve every scene under DIR in exact, double (power, Bernstein, scaled Bernstein) and MPFR "
                         "arithmetic, each floating column as published and guarded, and print a side-by-side table.");
  c.sub->add_option("DIR", args->dir, "Folder of scene files")->capture_default_str();
  c.sub->add_option("--mpfr-bits", args->mpfr_bits, "MPFR precisions in bits (repeatable, or a comma list: 64,128)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(53, 65536));
  add_old_spelling(c.sub, "--mpfr", "--mpfr", "--mpfr-bits", args->mpfr_bits)
      ->delimiter(',')
      ->check(CLI::Range(53, 65536));
  c.sub->add_flag("--json", args->json,
                  "JSON Lines instead of the table: one object per scene file, printed as soon as it is solved (format "
                  "eccd-table-row/1: folder, file, and a solution per column, keyed by the column's label)");
  c.sub
      ->add_option(
          "--guard", args->guards,
          "Faces of the floating columns, a comma list: none (the algorithm as published, plain double or MPFR; "
          "columns .../published) and bound (guarded by an error bound)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "bound"}));
  c.run = [args]() { return run_table(args->dir, args->mpfr_bits, args->guards, args->json); };
  return c;
}

}  // namespace eccd
