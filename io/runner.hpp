// Runs a case from start (or from a checkpoint) to its final strain, writing DIR/run.h5, DIR/run.xdmf,
// DIR/summary.json and DIR/checkpoint.h5. Input problems are raised as InputError before DIR is touched.
#pragma once
#include <string>

#include "io/case.hpp"

namespace suspend::io {

struct RunOptions {
  std::string out_dir;
  std::string restart;  // checkpoint to continue from; empty for a fresh run
  int threads = 0;      // 0: the case's run.threads (0 there: all cores)
  bool quiet = false;
};

// Returns the process exit code: 0 done, 3 numerical failure (state saved), 128 + signal when stopped by a signal.
int run_case(const Case& c, const RunOptions& options);

// The command that continues a run from its checkpoint exactly: the case file, its --set overrides (shell-quoted)
// and the thread count the run used.
std::string restart_command(const Case& c, const std::string& checkpoint, int threads);

// Installs SIGINT/SIGTERM handlers that ask the running case to checkpoint and stop.
void install_stop_handlers();

}  // namespace suspend::io
