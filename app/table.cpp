// `eccd table`: every scene of a folder in exact, double (power, Bernstein,
// scaled Bernstein) and MPFR arithmetic, side by side; '!' marks a floating
// answer that differs from the exact one.
#include "app/commands.hpp"
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
  c.sub->add_option("--mpfr", args->mpfr_bits, "MPFR precisions in bits (repeatable)")->capture_default_str();
  c.sub->add_flag("--json", args->json, "Print all results as one JSON array instead of the table");
  c.run = [args]() { return run_table(args->dir, args->mpfr_bits, args->json); };
  return c;
}

}  // namespace eccd
