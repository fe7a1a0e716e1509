// `suspend export RUN_DIR --format extxyz|gsd [--out FILE]`: a run's snapshots for OVITO, ASE and freud. The
// writers are python/suspend/export.py (GSD through Debian's python3-gsd, not a hand-written format); this command
// checks its arguments and hands over to Debian's python3.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/run_argument.hpp"
#include "core/error.hpp"

namespace suspend::app {

namespace fs = std::filesystem;

namespace {
// The installed copy beside the program (PREFIX/share/suspend/python), else the one of the source tree it was built from.
std::string export_script() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path() / SUSPEND_INSTALLED_PYTHON_DIR / "suspend" / "export.py";
    if (fs::is_regular_file(installed)) return fs::weakly_canonical(installed).string();
  }
  return SUSPEND_PYTHON_DIR "/suspend/export.py";
}
}  // namespace

void add_export_command(CLI::App& app) {
  struct Options {
    std::string run, format, out;
    bool force = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("export", "Write a run's snapshots as extended XYZ (OVITO, ASE) or GSD (freud, OVITO)");
  cmd->add_option("run", opt->run, "run directory (or its run.h5)")->required();
  cmd->add_option("--format", opt->format, "extxyz or gsd")->required()->check(CLI::IsMember({"extxyz", "gsd"}));
  cmd->add_option("--out,-o", opt->out,
                  "file to write (default: RUN_DIR/run.xyz or run.gsd); an earlier export of the format is replaced, "
                  "any other existing file only with --force, a run's own files never");
  cmd->add_flag("--force", opt->force, "replace an existing --out that is not an export of this format");
  cmd->callback([opt] {
    const std::string file = run_file_argument(opt->run, "export");
    const std::string python = "/usr/bin/python3", script = export_script();
    if (access(python.c_str(), X_OK) != 0 || !fs::is_regular_file(script))
      throw InputError("export: needs Debian's python3 (" + python + ") and " + script);
    std::vector<std::string> args = {python, script, file, "--format", opt->format};
    if (!opt->out.empty()) args.insert(args.end(), {"--out", opt->out});
    if (opt->force) args.push_back("--force");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::fflush(nullptr);
    execv(python.c_str(), argv.data());
    throw InputError("export: cannot start " + python + ": " + std::strerror(errno));
  });
}

}  // namespace suspend::app
