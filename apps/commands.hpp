// One function per subcommand of the `suspend` program; each lives in its own apps/cmd_*.cpp.
#pragma once
#include <CLI/CLI.hpp>

namespace suspend::app {
void add_run_command(CLI::App& app);
void add_check_command(CLI::App& app);
}  // namespace suspend::app
