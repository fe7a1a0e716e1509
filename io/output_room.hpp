// Room for a run's output. A write that fails half-way can leave run.h5 with objects HDF5 cannot read back, even
// ones written long before (its metadata is updated in place); so a run stops at a checkpoint, with every file
// complete, when the disk (or the process's file size limit) has less room left than the next checkpoint interval
// would write: twice the largest growth of run.h5 between two checkpoints so far, plus two checkpoints (the new one
// is written next to the old before replacing it). A write that fails anyway (a disk filled by someone else) stops
// the run too (OutputError, exit code 5), and the restart rebuilds run.h5 from what the checkpoint knew.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace suspend::io {

class OutputRoom {
 public:
  // After a checkpoint: a message when the next interval may not fit, else nothing. The first call only measures.
  std::optional<std::string> after_checkpoint(const std::string& run_path, const std::string& checkpoint_path);

 private:
  std::uintmax_t last_run_size_ = 0, largest_growth_ = 0;
  bool measured_ = false;
};

// Bytes that can still be written to `path`: free space of its file system for this user, and at most the file
// size limit (RLIMIT_FSIZE) minus its size.
std::uintmax_t room_for(const std::string& path);

}  // namespace suspend::io
