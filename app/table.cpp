// `eccd table`: every scene of a folder in exact, double (power, Bernstein,
// scaled Bernstein) and MPFR arithmetic, side by side; '!' marks a floating
// answer that differs from the exact one.
#include "app/commands.hpp"
#include "app/scene_files.hpp"
#include "api/answer_difference.hpp"
#include "api/solve.hpp"
#include "io/scene_reader.hpp"
#include "io/solution_json.hpp"
#include "kernel/budget.hpp"

#include <algorithm>
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

int run_table(const std::string& dir, const std::vector<int>& mpfr_bits, bool json) {
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
    all.push_back(js);
    rows.push_back(row);
    ++done;
    if (!quiet()) {
      std::fprintf(stderr, "\r[%zu/%zu] %s", done, files.size(), f.filename().string().c_str());
      std::fflush(stderr);
    }
  }
  if (!quiet()) std::fprintf(stderr, "\n");
  if (json) {
    nlohmann::json j;
    stamp_format(j, "eccd-table/1");
    j["folder"] = dir;
    j["scenes"] = all;
    std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    return 0;
  }
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
  std::cout << "\n'!' marks a floating answer that differs from the exact one (api/answer_difference.hpp: collides,\n"
               "an interval missed, false, split or merged, an end, the first contact or a contact more than 1e-6 away);\n"
               "3D scenes: floating columns run 001's Bezier method with f built in power or Bernstein form\n"
               "(scaled Bernstein is a 2D discriminant construction: n/a); exact is the certified projection;\n"
               "'?N' counts instants a floating pipeline could not classify; iv = collision intervals, t0 = first contact.\n";
  return 0;
}

}  // namespace

Command add_table_command(CLI::App& app) {
  struct Args {
    std::string dir = "cases";
    std::vector<int> mpfr_bits{128};
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  Command c;
  c.sub = app.add_subcommand("table", "Solve every scene under DIR in exact, double (power, Bernstein, scaled Bernstein) and MPFR arithmetic and print a side-by-side table.");
  c.sub->add_option("DIR", args->dir, "Folder of scene files")->capture_default_str();
  c.sub->add_option("--mpfr", args->mpfr_bits, "MPFR precisions in bits (repeatable, or a comma list: 64,128)")->delimiter(',')->capture_default_str()->check(CLI::Range(53, 65536));
  c.sub->add_flag("--json", args->json, "Print all results as one JSON object instead of the table (format eccd-table/1; \"scenes\": one object per scene file with a solution per column)");
  c.run = [args]() { return run_table(args->dir, args->mpfr_bits, args->json); };
  return c;
}

}  // namespace eccd
