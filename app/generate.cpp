// `eccd generate`: seeded, reproducible scene files for the robustness report
// (compare/scene_generator.hpp has the constructions). With --answer each
// scene also carries the exact pipeline's answer (app/solve.hpp), so that a
// folder of generated scenes is a regression corpus.
#include "app/atomic_write.hpp"
#include "app/commands.hpp"
#include "app/json_text.hpp"
#include "app/solve.hpp"
#include "compare/scene_generator.hpp"
#include "kernel/scene_reader.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;

namespace eccd {

namespace {
struct GenerateArgs {
  GeneratePlan plan;
  std::string out;
  bool force = false, json = false, answer = false;
};
}  // namespace

void add_plan_options(CLI::App* s, GeneratePlan& plan) {
  s->add_option("--dims", plan.dims, "Dimensions (2: ellipses, kinematic motions; 3: ellipsoids, euler and affine motions)")
      ->delimiter(',')->capture_default_str()->check(CLI::IsMember({2, 3}));
  s->add_option("--degrees", plan.degrees, "Motion degrees (1..8)")->delimiter(',')->capture_default_str()->check(CLI::Range(1, 8));
  s->add_option("--families", plan.families,
                "Families: colliding, free, touch, near-miss; overlap (linear translations that just overlap, depth "
                "10^-e, degree 1), graze (linear translations with an isolated touch, degree 1); decimal (a generic "
                "scene with every number rounded to --digits significant digits), keyframe (keyframed rigid motions "
                "with decimal key poses, degrees 2-6)")
      ->delimiter(',')->capture_default_str()
      ->check(CLI::IsMember({"colliding", "free", "touch", "near-miss", "overlap", "graze", "decimal", "keyframe"}));
  s->add_option("--motions", plan.motions, "Restrict motions: kinematic (2D), euler, affine (3D); default all")
      ->delimiter(',')->check(CLI::IsMember({"kinematic", "euler", "affine"}));
  s->add_option("--separations", plan.d_exponents, "Near-miss separations as exponents e of d = 10^-e")
      ->delimiter(',')->capture_default_str()->check(CLI::Range(1, 300));
  s->add_option("--depths", plan.depth_exponents, "Overlap depths as exponents e of 10^-e")
      ->delimiter(',')->capture_default_str()->check(CLI::Range(1, 300));
  s->add_option("--digits", plan.digits, "Significant decimal digits of the decimal and keyframe families")
      ->delimiter(',')->capture_default_str()->check(CLI::Range(1, 30));
}

Command add_generate_command(CLI::App& app) {
  auto args = std::make_shared<GenerateArgs>();
  Command c;
  c.sub = app.add_subcommand("generate",
                             "Write seeded, reproducible scene files: rational motions of the given degrees in the families "
                             "colliding, free (collision-free), touch (touch-and-separate at a constructed instant), "
                             "near-miss (minimum separation d = 10^-e, constructed), overlap and graze (linear translations "
                             "that just overlap or touch once), and the realistic-input families decimal and keyframe "
                             "(numbers written as decimals of 6, 9, 12, 15 significant digits). With --answer each file also "
                             "stores the exact pipeline's answer.");
  auto* s = c.sub;
  s->add_option("--out", args->out, "Folder to write the scenes into (created if missing)")->required();
  add_plan_options(s, args->plan);
  s->add_option("--count", args->plan.count, "Scenes per combination (per separation for near-miss)")->capture_default_str()->check(CLI::Range(1, 100000));
  s->add_option("--seed", args->plan.seed, "Run seed (each scene's seed derives from it and the combination)")->capture_default_str();
  s->add_flag("--force", args->force, "Overwrite existing scene files");
  s->add_flag("--json", args->json, "Print the list of written files as JSON");
  s->add_flag("--answer", args->answer,
              "Solve each scene with the exact pipeline and store its answer (collides, intervals, first_contact, "
              "contacts) in the file under \"answer\"; progress (scene and exact time) goes to stderr. Exact solving "
              "can take seconds per scene at high degree; nothing is written until every scene is solved");
  c.run = [args]() {
    auto specs = plan_scenes(args->plan);
    // Build and validate everything before writing anything.
    std::vector<std::pair<fs::path, std::string>> files;
    SolveOptions exact;
    exact.arith = parse_arithmetic("exact");
    double total_s = 0;
    for (std::size_t i = 0; i < specs.size(); ++i) {
      GeneratedScene g = generate_scene(specs[i]);
      std::string text = compact_json(g.doc.dump(1)) + "\n";
      fs::path path = fs::path(args->out) / (g.name + ".json");
      if (fs::exists(path) && !args->force)
        throw std::invalid_argument(path.string() + ": exists (use --force to overwrite)");
      Scene scene = parse_scene(text, path.string());  // the reader must accept what we write
      if (args->answer) {
        std::fprintf(stderr, "[%zu/%zu] %s: ", i + 1, specs.size(), g.name.c_str());
        std::fflush(stderr);
        auto start = std::chrono::steady_clock::now();
        nlohmann::json report = solve_scene(scene, exact);
        double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        total_s += sec;
        g.doc["answer"] = stored_answer_of(report);
        text = compact_json(g.doc.dump(1)) + "\n";
        parse_scene(text, path.string());  // the reader checks the stored answer too
        std::fprintf(stderr, "exact %.3f s, %s, %zu interval(s)\n", sec,
                     report["collides"].get<bool>() ? "collides" : "free", report["intervals"].size());
      }
      files.push_back({path, text});
    }
    if (args->answer) std::fprintf(stderr, "exact answers: %zu scene(s) in %.3f s\n", specs.size(), total_s);
    fs::create_directories(args->out);
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [path, text] : files) {
      write_text_atomically(path, text);
      list.push_back(path.string());
    }
    if (args->json) std::cout << list.dump(2) << "\n";
    else std::cout << "wrote " << files.size() << " scene(s) to " << args->out << " (seed " << args->plan.seed << ")\n";
    return 0;
  };
  return c;
}

}  // namespace eccd
