// A campaign file (docs/campaigns.md): a base case and the points to run from it, each point a set of `--set`
// overrides. Points come from the product of the `vary` lists, then from the explicit `points` list; every point
// is validated as a case when the campaign is read, so a bad value fails before anything runs.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace suspend::campaign {

struct Assignment {
  std::string key;    // dotted case key, e.g. particles.phi
  std::string value;  // YAML text, e.g. 0.45
  bool operator==(const Assignment&) const = default;
};

struct Point {
  std::string name;                    // readable from its parameters, e.g. phi0.45_sigma_star2; a folder name
  std::vector<Assignment> parameters;  // what this point varies (vary values, then its explicit overrides)
  std::string identity;                // the resolved case, less what does not change results (point_identity)
};

// A boundary search (docs/campaigns.md, "Searching for phi_m"): in each group of the vary product, `key` is bisected
// between the flowing and the jammed side (the highest value that flows and the lowest that jams, or the other way
// round with `flows: above`), `seeds` packings (run.seed 1..seeds) per value.
struct Search {
  std::string key;           // e.g. particles.phi
  double lo = 0.0, hi = 0.0;  // the range searched
  double tolerance = 0.0;    // the search stops once the bracket is at most this wide
  int seeds = 1;
  // Values at most this far above one where the same seed flowed start from that run's last state, rescaled
  // (particles.initial.compress); 0: every point starts from a generated packing.
  double from_flowing = 0.0;
  // Which side of the boundary flows: below (phi: dilute flows, dense jams) or above (flow.shear_stress at fixed
  // phi: a suspension with a yield stress flows above it and arrests below, so the bracket is sigma_Y).
  bool flows_above = false;
  // Values tried lie on a grid of tolerance / 2 from lo, so that they have short, stable names.
  double grid() const { return tolerance / 2.0; }
};

struct Campaign {
  std::string source;     // the campaign file
  std::string case_file;  // the base case (relative paths in the campaign file are taken from its folder)
  std::vector<Assignment> set;          // overrides of every point
  std::vector<Point> points;            // in file order: the vary product (first key outermost), then `points`
  std::vector<std::string> varied_keys;  // keys any point varies, in order of first appearance
  // With a search: its settings, and the groups it searches in (the vary product and `points`, each a parameter
  // set); `points` then holds only the points the search has decided on so far (campaign/search.hpp).
  std::optional<Search> search;
  std::vector<std::vector<Assignment>> groups;

  // The `--set` list that makes a point's case from the base case: `set`, then the point's parameters.
  std::vector<std::string> overrides(const Point& p) const;
  const Point* find(const std::string& name) const;  // nullptr when absent
  // The point of these parameters (named as the campaign names points, validated as a case); `unnamed` are further
  // overrides that do not enter its name (how a searched point starts).
  Point make_point(const std::vector<Assignment>& parameters, const std::vector<Assignment>& unnamed = {}) const;
};

// A searched value as it goes into a point (6 significant digits: 0.515, 0.4).
std::string format_value(double v);

// Reads and validates a campaign file (InputError naming the key or point on any problem).
Campaign load_campaign(const std::string& path);

}  // namespace suspend::campaign
