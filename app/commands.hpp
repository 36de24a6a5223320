#pragma once
// Sub-commands of `eccd` that live in their own source file. Each adds its
// CLI11 sub-command to the app and returns the function that runs it (called
// by app/main.cpp inside its error handling: SceneError / std::invalid_argument
// -> exit 2, any other exception -> exit 1). `run` returns the exit status.
#include "compare/scene_generator.hpp"

#include <CLI/CLI.hpp>

#include <functional>

namespace eccd {

struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
};

Command add_generate_command(CLI::App& app);  // app/generate.cpp
Command add_report_command(CLI::App& app);    // app/report.cpp
Command add_plot_command(CLI::App& app);      // app/plot.cpp
Command add_certify_command(CLI::App& app);            // app/certify.cpp
Command add_check_certificate_command(CLI::App& app);  // app/certify.cpp
Command add_regress_command(CLI::App& app);            // app/regress.cpp

// The generator options shared by `generate` and `report` (--dims, --degrees,
// --families, --motions, --separations); app/generate.cpp.
void add_plan_options(CLI::App* sub, GeneratePlan& plan);

// Folder of the Python drawing scripts (compare/plots): $ECCD_PLOTS_DIR if
// set, otherwise the source tree's folder compiled in at build time.
std::string plots_dir();

}  // namespace eccd
