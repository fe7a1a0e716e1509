// `suspend sweep CAMPAIGN --out DIR --status`: the state of every point and the time left, read from the point
// records, the run logs and the point locks, without starting or changing anything.
#pragma once
#include <filesystem>
#include <string>

#include "campaign/campaign.hpp"

namespace suspend::campaign {

// Where a point's run got to, from the last progress line of its log ("strain S of T (P%), ..., ETA ...").
struct RunProgress {
  bool known = false;
  double strain = 0.0, target = 0.0;
  double eta_seconds = -1.0;  // the run's own estimate of its time left; < 0 when it has none
};
RunProgress read_progress(const std::filesystem::path& log);

// Prints one line per point (done, jammed, failed, running with its strain and strain per hour, interrupted,
// pending) and the estimated time left at `jobs` points at a time, counting `to_come` points a search will still add
// (points_to_come, campaign/search.hpp). Returns the number of points not yet finished.
int print_status(const Campaign& c, const std::filesystem::path& out_dir, int jobs, int to_come = 0);

}  // namespace suspend::campaign
