// suspend: the command-line program. Thin: parse, build objects, run.
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "apps/commands.hpp"
#include "core/error.hpp"
#include "core/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"suspend: rheology of dense non-Brownian suspensions (lubrication-DEM and FCM)"};
  app.set_version_flag("--version", std::string("suspend ") + suspend::version + " (git " + suspend::git_commit + ")");
  app.require_subcommand(1);
  suspend::app::add_mobility_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : suspend::exit_input_error;
  }
  return 0;
}
