// The sweep's own record of one point, DIR/points/NAME/point.json: its status and how it ended. The run's files
// (run.h5, checkpoint.h5, summary.json) sit beside it, as `suspend run` writes them.
#pragma once
#include <filesystem>
#include <string>
#include <utility>

#include "io/folder_lock.hpp"

namespace suspend::campaign {

// done: ran to run.strain; jammed: an imposed-stress run that stopped flowing (its summary averages what it did);
// failed: numerical failure, bad input, wall-clock budget or a kill (continued with --retry-failed);
// running: a sweep process holds it now; pending: not started, or interrupted (continued from its checkpoint).
struct PointRecord {
  std::string status = "pending";
  int exit_code = -1;  // of the last run; -1 when none ended yet
  std::string message;  // why it failed or jammed, from the run's last error line
  double wall_seconds = 0.0;  // summed over every run of the point
  // The CPU time (user + system) of its runs, summed: the cost of the point, which wall time overstates while the
  // machine is shared or the sweep is paused (SIGSTOP) or its record restored from a table that had only wall time.
  double cpu_seconds = 0.0;
  int runs = 0;               // times it was started (1 + restarts)
  // The particles.initial the point started from when it is not its own packing (a searched point started from a
  // flowing state, campaign/search.hpp); empty otherwise. Kept so that a replayed search lists the start of a
  // finished point after its source run is gone (a folder restored from a table, tools/restore_campaign.py).
  std::string initial;
};

PointRecord read_record(const std::filesystem::path& point_dir);
void write_record(const std::filesystem::path& point_dir, const PointRecord& r);

// An exclusive lock on a point, held while a process runs it (DIR/points/NAME/.lock, see io/folder_lock.hpp).
// A sweep skips points locked by another process; the run it starts inherits the lock.
io::FolderLock lock_point(const std::filesystem::path& point_dir);

// Whether another process holds the point's lock now.
bool locked_elsewhere(const std::filesystem::path& point_dir);

}  // namespace suspend::campaign
