// A campaign file (docs/campaigns.md): a base case and the points to run from it, each point a set of `--set`
// overrides. Points come from the product of the `vary` lists, then from the explicit `points` list; every point
// is validated as a case when the campaign is read, so a bad value fails before anything runs.
#pragma once
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

struct Campaign {
  std::string source;     // the campaign file
  std::string case_file;  // the base case (relative paths in the campaign file are taken from its folder)
  std::vector<Assignment> set;          // overrides of every point
  std::vector<Point> points;            // in file order: the vary product (first key outermost), then `points`
  std::vector<std::string> varied_keys;  // keys any point varies, in order of first appearance

  // The `--set` list that makes a point's case from the base case: `set`, then the point's parameters.
  std::vector<std::string> overrides(const Point& p) const;
  const Point* find(const std::string& name) const;  // nullptr when absent
};

// Reads and validates a campaign file (InputError naming the key or point on any problem).
Campaign load_campaign(const std::string& path);

}  // namespace suspend::campaign
