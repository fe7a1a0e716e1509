// One function per subcommand of the `suspend` program; each lives in its own apps/cmd_*.cpp.
#pragma once
#include <CLI/CLI.hpp>

namespace suspend::app {
}  // namespace suspend::app
