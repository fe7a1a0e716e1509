// `suspend run CASE.yaml --out DIR [--set KEY=VALUE]... [--restart CHECKPOINT] [--threads N] [--quiet]`
#include <cstdlib>

#include "apps/commands.hpp"
#include "io/case.hpp"
#include "io/runner.hpp"

namespace suspend::app {

void add_run_command(CLI::App& app) {
  struct Options {
    std::string case_file;
    std::vector<std::string> overrides;
    io::RunOptions run;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("run", "Run a case and write DIR/run.h5, run.xdmf, summary.json, checkpoint.h5");
  cmd->add_option("case", opt->case_file, "case file (YAML, see docs/cases.md)")->required();
  cmd->add_option("--out,-o", opt->run.out_dir, "output directory (default with --restart: the checkpoint's)");
  cmd->add_option("--set,-s", opt->overrides, "override a case key by its dotted path, e.g. particles.phi=0.52")
      ->take_all();
  cmd->add_option("--restart", opt->run.restart, "continue from this checkpoint (DIR/checkpoint.h5)");
  cmd->add_option("--threads,-t", opt->run.threads, "OpenMP threads (default: run.threads, else all cores)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--quiet,-q", opt->run.quiet, "no progress output");
  cmd->callback([opt] {
    const io::Case c = io::load_case(opt->case_file, opt->overrides);
    const int code = io::run_case(c, opt->run);
    if (code != 0) std::exit(code);
  });
}

}  // namespace suspend::app
