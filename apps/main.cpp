// suspend: the command-line program. Thin: parse, build objects, run.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include "apps/commands.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/hdf5.hpp"

int main(int argc, char** argv) {
  suspend::io::h5::initialize_library();
  CLI::App app{"suspend: rheology of dense non-Brownian suspensions (lubrication-DEM and FCM)"};
  app.set_version_flag("--version", std::string("suspend ") + suspend::version + " (git " + suspend::git_commit + ")");
  app.require_subcommand(1);
  suspend::app::add_run_command(app);
  suspend::app::add_crossval_command(app);
  suspend::app::add_sweep_command(app);
  suspend::app::add_phim_command(app);
  suspend::app::add_analyze_command(app);
  suspend::app::add_export_command(app);
  suspend::app::add_check_command(app);
  suspend::app::add_pair_command(app);
  suspend::app::add_mobility_command(app);
  // CLI11 would say "a subcommand is required" for `suspend --bogus`: name the option instead.
  if (argc > 1 && argv[1][0] == '-') {
    const std::string first = argv[1];
    if (first != "--help" && first != "-h" && first != "--version") {
      std::cerr << "error: " << first << ": unknown option; suspend takes a subcommand first (";
      for (std::size_t k = 0; k < app.get_subcommands({}).size(); ++k)
        std::cerr << (k ? ", " : "") << app.get_subcommands({})[k]->get_name();
      std::cerr << "; see suspend --help)\n";
      return suspend::exit_input_error;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {  // --help, --version: their text must arrive too
      app.exit(e);
      if (!std::cout.flush() || std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::cerr << "error: writing the standard output failed: " << std::strerror(errno) << "\n";
        return suspend::exit_output_error;
      }
      return 0;
    }
    std::cerr << "error: " << e.what() << " (see suspend --help)\n";
    return suspend::exit_input_error;
  } catch (const suspend::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return suspend::exit_input_error;
  } catch (const suspend::NumericalError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return suspend::exit_numerical_error;
  } catch (const suspend::OutputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return suspend::exit_output_error;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  // A result that never reached its reader is not a success: standard output on a full device (or a closed pipe)
  // fails here, when the buffered text is written.
  if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout.flush()) {
    std::cerr << "error: writing the standard output failed: " << std::strerror(errno) << "\n";
    return suspend::exit_output_error;
  }
  return 0;
}
