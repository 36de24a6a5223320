// `eccd generate` (placeholder until its issue-4 implementation lands).
#include "app/commands.hpp"

namespace eccd {

Command add_generate_command(CLI::App& app) {
  Command c;
  c.sub = app.add_subcommand("generate", "(not implemented yet)");
  c.run = [] { return 1; };
  return c;
}

}  // namespace eccd
