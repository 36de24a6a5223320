// `eccd report` (placeholder until its issue-4 implementation lands).
#include "app/commands.hpp"

namespace eccd {

Command add_report_command(CLI::App& app) {
  Command c;
  c.sub = app.add_subcommand("report", "(not implemented yet)");
  c.run = [] { return 1; };
  return c;
}

}  // namespace eccd
