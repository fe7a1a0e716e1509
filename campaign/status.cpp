#include "campaign/status.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <vector>

#include "campaign/point_record.hpp"
#include "campaign/table.hpp"

namespace suspend::campaign {

namespace fs = std::filesystem;

namespace {
// "01:02:03" or "02:03" -> seconds; -1 for "--:--".
double clock_seconds(const std::string& t) {
  std::vector<double> parts;
  std::size_t i = 0;
  while (i < t.size()) {
    const std::size_t j = t.find(':', i);
    const std::string part = t.substr(i, j == std::string::npos ? std::string::npos : j - i);
    if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos) return -1.0;
    parts.push_back(std::stod(part));
    if (j == std::string::npos) break;
    i = j + 1;
  }
  double s = 0.0;
  for (double p : parts) s = 60.0 * s + p;
  return parts.empty() ? -1.0 : s;
}

std::string hours_text(double seconds) {
  char b[32];
  if (seconds < 0) return "unknown";
  if (seconds < 60)
    std::snprintf(b, sizeof b, "%.0f s", seconds);
  else if (seconds < 3600)
    std::snprintf(b, sizeof b, "%.0f min", seconds / 60.0);
  else
    std::snprintf(b, sizeof b, "%.1f h", seconds / 3600.0);
  return b;
}
}  // namespace

RunProgress read_progress(const fs::path& log) {
  static const std::regex line(R"(^strain (\S+) of (\S+) \(.*ETA ([0-9:\-]+),)");
  RunProgress p;
  std::ifstream in(log);
  std::string s;
  std::smatch m;
  while (std::getline(in, s)) {
    if (!std::regex_search(s, m, line)) continue;
    try {
      p.strain = std::stod(m[1].str());
      p.target = std::stod(m[2].str());
    } catch (const std::exception&) {
      continue;
    }
    p.eta_seconds = clock_seconds(m[3].str());
    p.known = true;
  }
  return p;
}

int print_status(const Campaign& c, const fs::path& out_dir, int jobs, int to_come) {
  std::map<std::string, int> counts;
  double finished_seconds = 0.0, running_left = 0.0;
  int finished = 0, waiting = 0, running = 0, failed = 0;
  int width = 5;
  for (const Point& p : c.points) width = std::max(width, static_cast<int>(p.name.size()));
  std::printf("%-*s %-12s %s\n", width, "point", "status", "progress");
  for (const Point& p : c.points) {
    const fs::path pd = point_dir(out_dir, p);
    const PointRecord r = read_record(pd);
    const RunProgress g = read_progress(pd / "log.txt");
    std::string status = r.status, detail;
    char b[160];
    if (status == "running" && !locked_elsewhere(pd)) status = "interrupted";  // its process died: resumes
    if (status == "done" || status == "jammed") {
      finished_seconds += r.wall_seconds;
      ++finished;
      std::snprintf(b, sizeof b, "%s of point time", hours_text(r.wall_seconds).c_str());
      detail = b;
      if (status == "jammed" && !r.message.empty()) detail += "; " + r.message;
    } else {
      if (status == "failed") {
        ++failed;
        detail = r.message;
      } else if (status == "running" && g.known) {
        const double rate = g.eta_seconds > 0 ? (g.target - g.strain) / g.eta_seconds * 3600.0 : -1.0;
        if (rate > 0)
          std::snprintf(b, sizeof b, "strain %.4g of %.4g, %.3g strain/h, %s left", g.strain, g.target, rate,
                        hours_text(g.eta_seconds).c_str());
        else
          std::snprintf(b, sizeof b, "strain %.4g of %.4g", g.strain, g.target);
        detail = b;
        ++running;
        running_left += g.eta_seconds > 0 ? g.eta_seconds : 0.0;
      } else {
        if (g.known) {
          std::snprintf(b, sizeof b, "continues from strain %.4g of %.4g", g.strain, g.target);
          detail = b;
        }
        ++waiting;
      }
    }
    ++counts[status];
    std::printf("%-*s %-12s %s\n", width, p.name.c_str(), status.c_str(), detail.c_str());
  }
  std::string line;
  for (const auto& [s, n] : counts) line += (line.empty() ? "" : ", ") + std::to_string(n) + " " + s;
  std::printf("%zu point(s): %s\n", c.points.size(), line.c_str());
  if (failed > 0) std::printf("%d failed point(s) wait for `suspend sweep ... --retry-failed`\n", failed);
  if (to_come > 0)
    std::printf("the search will add about %d more point(s) as it bisects (counted in the time left)\n", to_come);
  if (waiting == 0 && running == 0 && to_come == 0) {
    std::printf("nothing left to run: %s of point time in all\n", hours_text(finished_seconds).c_str());
  } else if (finished == 0) {
    std::printf("time left: unknown until a point finishes (running points: %s)\n", hours_text(running_left).c_str());
  } else {
    // Points still to start are taken to cost what the finished ones cost on average (failed ones are not
    // counted: they wait for --retry-failed).
    const double per_point = finished_seconds / finished;
    const double left = (waiting + to_come) * per_point + running_left;
    std::printf("time left: about %s of point time (%d to start at %s each, as the %d finished took; running "
                "points %s), %s at %d point(s) at a time\n",
                hours_text(left).c_str(), waiting + to_come, hours_text(per_point).c_str(), finished,
                hours_text(running_left).c_str(), hours_text(left / std::max(1, jobs)).c_str(), jobs);
  }
  return waiting + running + failed + to_come;
}

}  // namespace suspend::campaign
