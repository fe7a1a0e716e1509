#include "campaign/point_record.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"

namespace suspend::campaign {

namespace fs = std::filesystem;

PointRecord read_record(const fs::path& point_dir) {
  PointRecord r;
  std::ifstream in(point_dir / "point.json");
  if (!in) return r;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return r;  // written atomically, so only a hand edit gets here
  r.status = j.value("status", r.status);
  r.exit_code = j.value("exit_code", r.exit_code);
  r.message = j.value("message", r.message);
  r.wall_seconds = j.value("wall_seconds", r.wall_seconds);
  r.cpu_seconds = j.value("cpu_seconds", r.cpu_seconds);
  r.runs = j.value("runs", r.runs);
  r.initial = j.value("initial", r.initial);
  return r;
}

void write_record(const fs::path& point_dir, const PointRecord& r) {
  nlohmann::ordered_json j = {{"status", r.status},   {"exit_code", r.exit_code}, {"message", r.message},
                              {"wall_seconds", r.wall_seconds}, {"cpu_seconds", r.cpu_seconds},
                              {"runs", r.runs}};
  if (!r.initial.empty()) j["initial"] = r.initial;
  io::write_text_atomically((point_dir / "point.json").string(), j.dump(2) + "\n");
}

io::FolderLock lock_point(const fs::path& point_dir) { return io::FolderLock(point_dir / ".lock", "suspend sweep"); }

bool locked_elsewhere(const fs::path& point_dir) {
  if (!fs::exists(point_dir / ".lock")) return false;
  return !lock_point(point_dir).held();
}

}  // namespace suspend::campaign
