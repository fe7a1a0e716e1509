// The boundary search of a campaign (docs/campaigns.md, "Searching for phi_m"): per group, bisection of the searched
// key between the value nearest the boundary that flows and the one that jams. The state is replayed from the points'
// records each time, so a resumed or repeated sweep decides exactly as the first one did.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "campaign/campaign.hpp"
#include "campaign/sweep.hpp"

namespace suspend::campaign {

struct SearchedValue {
  double value = 0.0;
  int flowed = 0, jammed = 0;  // seeds that ended done / jammed
  std::vector<Point> points;        // its points, seed 1 first
  bool decided() const;             // every seed ended (done or jammed)
  bool flows() const;               // decided, and a strict majority of the seeds flowed
};

struct GroupSearch {
  std::vector<Assignment> group;       // the group's parameters
  std::string name;                    // its parameters as the points name them ("base" when none)
  std::vector<SearchedValue> values;   // in the order the search tried them
  std::vector<double> next;            // values whose seeds are still to run (empty once the search stopped)
  std::string state;                   // "searching", "converged", "below lo", "above hi", "stopped: ..."
  // The bracket so far (meaningful once both ends were decided): the value nearest the boundary that flowed and the
  // one that jammed (flowing < jammed, or the other way round with Search::flows_above).
  double flow_end = 0.0, jam_end = 0.0;
  bool bracketed = false;
};

// The search of every group, from the records under out_dir (no records yet: the first values to try).
std::vector<GroupSearch> plan_search(const Campaign& c, const std::filesystem::path& out_dir);

// The campaign with its points: every point the search has tried or will try next.
Campaign with_search_points(const Campaign& c, const std::vector<GroupSearch>& plan);

// About how many points the searching groups will still add once their pending values end: per group, the seeds of
// every further bisection its bracket (hi - lo before both ends are decided) needs to come within the tolerance,
// beyond the values already planned. An estimate: the grid may save a round. For `sweep --status`.
int points_to_come(const Campaign& c, const std::vector<GroupSearch>& plan);

// One line per group: its state, bracket and next values (for --list and the sweep's progress).
std::string describe_search(const Campaign& c, const std::vector<GroupSearch>& plan);

// A sweep of a campaign with a search: rounds of run_sweep over the points decided so far, each round adding the
// values the finished ones call for, until every group has converged or stopped. Same exit codes as run_sweep.
int run_search_sweep(const Campaign& c, const SweepOptions& o);

}  // namespace suspend::campaign
