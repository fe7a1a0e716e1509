// Where a run starts: a fresh state from the case's initial configuration, or a checkpoint continued in its own
// folder or branched into a new one. Every check on the input happens here, before the output folder is touched.
#pragma once
#include <filesystem>
#include <string>

#include "core/rng.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "io/folder_lock.hpp"
#include "io/runner.hpp"

namespace suspend::io {

struct RunStart {
  std::filesystem::path dir;
  SimulationState state;
  Box box;
  OutputClock clock;
  Rng rng{0};
  std::string origin;      // one line for the log: what the run started from
  bool restarting = false;
  bool branching = false;  // a checkpoint continued into a new folder (a new run.h5)
  FolderLock lock;         // held when the folder already held this run (continued in place)
};

RunStart prepare_run_start(const Case& c, const RunOptions& o, int threads, const std::string& fingerprint);

// Takes the folder's run lock or refuses, naming the process that holds it.
FolderLock lock_run_folder(const std::filesystem::path& dir);

}  // namespace suspend::io
