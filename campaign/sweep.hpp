// `suspend sweep`: runs the points of a campaign, each as a child `suspend run` process in DIR/points/NAME, up to
// `jobs` at a time, and keeps DIR/campaign.json/.csv up to date. Resumable after anything: finished points are
// skipped, interrupted ones continue from their checkpoints (bit for bit on the same thread count), failed ones
// only with retry_failed. A campaign file changed since DIR was started is refused, except for added points.
#pragma once
#include <filesystem>
#include <string>

#include "campaign/campaign.hpp"

namespace suspend::campaign {

struct SweepOptions {
  std::filesystem::path out_dir;
  int jobs = 1;                // points run at once
  int threads = 1;             // OpenMP threads of each point
  bool quiet = false;
  bool retry_failed = false;
  double point_seconds = 0.0;  // wall-clock budget of one run of a point (0: none); over it the point is stopped
                               // at a checkpoint and marked failed
  std::string only_point;      // run this point alone (scheduler arrays); empty: every point
  std::string executable;      // the suspend program run for each point; empty: this process's own
};

// Returns 0 when every selected point ended done or jammed, 3 when some failed, 128 + signal when stopped, and
// exit_output_error when a point's run could not be started (the program missing): that point stays pending.
int run_sweep(const Campaign& c, const SweepOptions& o);

// The path of this program, as the sweep runs it for each point. A binary replaced at that path while the sweep runs
// (a rename over it, as tools/resume_campaigns.sh installs one) makes /proc/self/exe read "PATH (deleted)": the
// path is what runs next, so the suffix is dropped.
std::string own_executable();

// Refuses (InputError, naming the point and the keys) a campaign whose points differ from those DIR was started
// with, other than added points; check_points only reads (for --status), check_and_record_points then records the
// campaign's points in DIR/sweep.json.
void check_points(const Campaign& c, const std::filesystem::path& dir);
void check_and_record_points(const Campaign& c, const std::filesystem::path& dir);

}  // namespace suspend::campaign
