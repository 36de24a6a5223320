// `eccd generate`: seeded, reproducible scene files for the robustness report
// (compare/scene_generator.hpp has the constructions). With --answer each
// scene also carries the exact pipeline's answer (api/solve.hpp), so that a
// folder of generated scenes is a regression corpus.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/json_text.hpp"
#include "app/option_names.hpp"
#include "api/solve.hpp"
#include "io/solution_json.hpp"
#include "compare/scene_generator.hpp"
#include "io/scene_reader.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

namespace fs = std::filesystem;

namespace eccd {

namespace {
struct GenerateArgs {
  GeneratePlan plan;
  std::string out;
  bool force = false, json = false, answer = false;
};
}  // namespace

// A seed is a decimal integer 0 .. 2^64-1 (CLI11 would wrap "-1" to 2^64-1).
std::string check_seed_text(const std::string& t) {
  if (t.empty() || t.size() > 20 || t.find_first_not_of("0123456789") != std::string::npos)
    return "expected a non-negative integer below 2^64, got " + t.substr(0, 40);
  if (t.size() == 20 && t > "18446744073709551615") return "expected a non-negative integer below 2^64, got " + t;
  return "";
}

void check_plan(const GeneratePlan& plan) {
  const std::map<std::string, int> dim_of{{"kinematic", 2}, {"euler", 3}, {"affine", 3}};
  for (const auto& m : plan.motions) {
    int d = dim_of.at(m);
    if (std::find(plan.dims.begin(), plan.dims.end(), d) == plan.dims.end())
      throw std::invalid_argument("--motions " + m + " is a " + std::to_string(d) +
                                  "D motion, but --dims does not include " + std::to_string(d) +
                                  ": that combination generates no scene (kinematic is 2D; euler and affine are 3D)");
  }
  const bool deg1 = std::find(plan.degrees.begin(), plan.degrees.end(), 1) != plan.degrees.end();
  for (const char* f : {"touch", "near-miss"})
    if (deg1 && std::find(plan.families.begin(), plan.families.end(), f) != plan.families.end())
      throw std::invalid_argument(std::string("--degrees 1 with the family ") + f +
                                  ": touch and near-miss scenes need motion degree >= 2 (degree 1 works with "
                                  "--families colliding,free)");
  if (plan.dims.empty() || plan.degrees.empty() || plan.families.empty())
    throw std::invalid_argument("--dims, --degrees and --families must each name at least one value");
}

void add_plan_options(CLI::App* s, GeneratePlan& plan) {
  s->add_option("--dims", plan.dims,
                "Dimensions (2: ellipses, kinematic motions; 3: ellipsoids, euler and affine motions)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({2, 3}));
  s->add_option("--degrees", plan.degrees, "Motion degrees (1..8; the families touch and near-miss need 2..8)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  s->add_option(
       "--families", plan.families,
       "Families: colliding, free, touch, near-miss; overlap (linear translations that just overlap, depth "
       "10^-e, degree 1), graze (linear translations with an isolated touch, degree 1); decimal (a generic "
       "scene with every number rounded to --digits significant digits), keyframe (keyframed rigid motions "
       "with decimal key poses, degrees 2-6); cycloidal (2D, 003 section V) and independent (2D, 3D, \"parameters\": "
       "\"independent\", straight paths A(s), B(t)), not in the default list (compare/motion_families.hpp)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"colliding", "free", "touch", "near-miss", "overlap", "graze", "decimal", "keyframe",
                             "cycloidal", "independent"}));
  s->add_option("--motions", plan.motions, "Restrict motions: kinematic (2D), euler, affine (3D); default all")
      ->delimiter(',')
      ->check(CLI::IsMember({"kinematic", "euler", "affine"}));
  s->add_option("--separations", plan.d_exponents, "Near-miss separations as exponents e of d = 10^-e")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(1, 300));
  s->add_option("--depths", plan.depth_exponents, "Overlap depths as exponents e of 10^-e")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(1, 300));
  s->add_option("--digits", plan.digits, "Significant decimal digits of the decimal and keyframe families")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::Range(1, 30));
}

namespace {

// The output folder exists, or can be created: no file in the way.
void check_out_folder(const std::string& out) {
  std::error_code ec;
  fs::path o(out);
  if (fs::exists(o, ec) && !fs::is_directory(o, ec)) throw OutputError(out + ": exists and is not a folder");
  for (fs::path p = o.parent_path(); !p.empty(); p = p.parent_path()) {
    if (fs::exists(p, ec)) {
      if (!fs::is_directory(p, ec))
        throw OutputError(out + ": cannot create the folder: " + p.string() + " is not a folder");
      break;
    }
    if (p == p.parent_path()) break;
  }
}

}  // namespace

Command add_generate_command(CLI::App& app) {
  auto args = std::make_shared<GenerateArgs>();
  Command c;
  c.sub = app.add_subcommand(
      "generate",
      "Write seeded, reproducible scene files: rational motions of the given degrees in the families "
      "colliding, free (collision-free), touch (touch-and-separate at a constructed instant), "
      "near-miss (minimum separation d = 10^-e, constructed), overlap and graze (linear translations "
      "that just overlap or touch once), and the realistic-input families decimal and keyframe "
      "(numbers written as decimals of 6, 9, 12, 15 significant digits). With --answer each file also "
      "stores the exact pipeline's answer.");
  auto* s = c.sub;
  s->add_option("--out-dir", args->out, "Folder to write the scenes into (created if missing); required");
  add_old_spelling(s, "--out", "--out", "--out-dir", args->out);
  add_plan_options(s, args->plan);
  s->add_option("--count", args->plan.count, "Scenes per combination (per separation for near-miss)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  s->add_option("--seed", args->plan.seed, "Run seed (each scene's seed derives from it and the combination)")
      ->capture_default_str()
      ->check(check_seed_text);
  s->add_flag("--force", args->force, "Overwrite existing scene files");
  s->add_flag("--json", args->json, "Print the written files as JSON (format eccd-generate/1: seed, folder, files)");
  s->add_flag("--answer", args->answer,
              "Solve each scene with the exact pipeline and store its answer (collides, intervals, first_contact, "
              "contacts) in the file under \"answer\"; progress (scene and exact time) goes to stderr. Exact solving "
              "can take seconds per scene at high degree; nothing is written until every scene is solved");
  c.run = [args]() {
    if (args->out.empty())
      throw std::invalid_argument("generate: --out-dir DIR is required (the folder the scenes are written into)");
    check_output_path("--out-dir", args->out);
    check_plan(args->plan);
    check_out_folder(args->out);  // creatable (or existing) before any scene is solved
    auto specs = plan_scenes(args->plan);
    if (specs.empty()) throw std::invalid_argument("the options select no scene to generate");
    // Build and validate everything before writing anything.
    std::vector<std::pair<fs::path, std::string>> files;
    SolveOptions exact;
    exact.arith = parse_arithmetic("exact");
    double total_s = 0;
    for (std::size_t i = 0; i < specs.size(); ++i) {
      GeneratedScene g = generate_scene(specs[i]);
      std::string text = compact_json(g.doc) + "\n";
      fs::path path = fs::path(args->out) / (g.name + ".json");
      if (fs::exists(path) && !args->force)
        throw std::invalid_argument(path.string() + ": exists (use --force to overwrite)");
      Scene scene = parse_scene(text, path.string());  // the reader must accept what we write
      if (args->answer) {
        if (!quiet()) {
          std::fprintf(stderr, "[%zu/%zu] %s: ", i + 1, specs.size(), g.name.c_str());
          std::fflush(stderr);
        }
        auto start = std::chrono::steady_clock::now();
        Solution report = solve(scene, exact);
        double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        total_s += sec;
        g.doc["answer"] = stored_answer_of(report);
        text = compact_json(g.doc) + "\n";
        parse_scene(text, path.string());  // the reader checks the stored answer too
        if (!quiet())
          std::fprintf(stderr, "exact %.3f s, %s, %zu interval(s)\n", sec, report.answer.collides ? "collides" : "free",
                       report.answer.intervals.size());
      }
      files.push_back({path, text});
    }
    if (args->answer && !quiet())
      std::fprintf(stderr, "exact answers: %zu scene(s) in %.3f s\n", specs.size(), total_s);
    {
      std::error_code ec;
      fs::create_directories(args->out, ec);
      if (ec) throw OutputError(args->out + ": cannot create the folder: " + ec.message());
    }
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [path, text] : files) {
      write_text_atomically(path, text);
      list.push_back(path.string());
    }
    if (args->json) {
      nlohmann::ordered_json j;
      stamp_format(j, "eccd-generate/1");
      j["seed"] = args->plan.seed;
      j["folder"] = args->out;
      j["files"] = list;
      std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else
      std::cout << "wrote " << files.size() << " scene(s) to " << args->out << " (seed " << args->plan.seed << ")\n";
    return 0;
  };
  return c;
}

}  // namespace eccd
