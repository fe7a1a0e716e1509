// The campaign table, gathered from the point folders: DIR/campaign.json
// {"points": [{"name", "status", "parameters": {key: value}, "case": {...}, "summary": {...}, "derived": {...}}]}
// and DIR/campaign.csv, one row a point (docs/campaigns.md lists the columns). Both are written atomically and
// depend only on the points' files, so any process may rewrite them at any time.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>

#include "campaign/campaign.hpp"

namespace suspend::campaign {

nlohmann::ordered_json gather_table(const Campaign& c, const std::filesystem::path& dir);
std::string table_csv(const Campaign& c, const nlohmann::ordered_json& table);
void write_table(const Campaign& c, const std::filesystem::path& dir);

// The folder of a point.
inline std::filesystem::path point_dir(const std::filesystem::path& dir, const Point& p) {
  return dir / "points" / p.name;
}

}  // namespace suspend::campaign
