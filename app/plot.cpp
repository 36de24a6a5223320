// `eccd plot` (placeholder until its issue-4 implementation lands).
#include "app/commands.hpp"

#include <cstdlib>

namespace eccd {

Command add_plot_command(CLI::App& app) {
  Command c;
  c.sub = app.add_subcommand("plot", "(not implemented yet)");
  c.run = [] { return 1; };
  return c;
}

}  // namespace eccd

namespace eccd {
std::string plots_dir() {
  if (const char* e = std::getenv("ECCD_PLOTS_DIR")) return e;
  return ECCD_PLOTS_DIR;
}
}  // namespace eccd
