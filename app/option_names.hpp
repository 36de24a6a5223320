#pragma once
// One name per option across the commands (docs/cli/README.md, "One name per
// option"): --mpfr-bits, --jobs, --out FILE against --out-dir DIR. A renamed
// option keeps its old spelling for one version as a hidden alias: it writes
// the same variable, is not listed by --help, and warns on stderr (unless
// --quiet) that the old name goes away.
#include "app/commands.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace eccd {

// `names` is the old spelling as CLI11 takes it ("--mpfr", "-o,--output"),
// `shown` how the warning quotes it, `now` the current name.
template <class T>
CLI::Option* add_old_spelling(CLI::App* sub, const std::string& names, const std::string& shown, const std::string& now,
                              T& target) {
  const std::string command = sub->get_name();
  return sub
      ->add_option_function<T>(
          names,
          [&target, command, shown, now](const T& value) {
            target = value;
            warn(command,
                 shown + " is renamed " + now + "; the old name still works in this version and goes away in the next");
          },
          "old name of " + now)
      ->group("");
}

}  // namespace eccd
