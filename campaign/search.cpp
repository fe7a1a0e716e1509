#include "campaign/search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"

#include "campaign/point_record.hpp"
#include "campaign/table.hpp"

namespace suspend::campaign {

namespace fs = std::filesystem;

bool SearchedValue::decided() const { return flowed + jammed == static_cast<int>(points.size()); }

bool SearchedValue::flows() const { return decided() && 2 * flowed > static_cast<int>(points.size()); }

namespace {
std::vector<Assignment> at_value(const std::vector<Assignment>& group, const Search& s, double v, int seed) {
  std::vector<Assignment> a = group;
  a.push_back({s.key, format_value(v)});
  a.push_back({"run.seed", std::to_string(seed)});
  return a;
}

// The overrides that start a point from another run's state (particles.initial text) instead of a packing.
std::vector<Assignment> started_from(const std::string& initial) {
  return {{"particles.initial", initial}, {"particles.count", "null"}, {"box", "null"}};
}
}  // namespace

std::vector<GroupSearch> plan_search(const Campaign& c, const fs::path& out_dir) {
  const Search& s = *c.search;
  std::vector<GroupSearch> plan;
  for (const std::vector<Assignment>& group : c.groups) {
    GroupSearch g;
    g.group = group;
    g.name = group.empty() ? "base" : c.make_point(group).name;
    // A value's seeds, read from their records (a failed one stops the search of the group). A seed starts from
    // its own last flowing state when that is at most from_flowing below (issue 34: dense points start from a state
    // that flowed, not from a packing that may be arrested before it ever flows).
    auto visit = [&](double v) -> const SearchedValue* {
      SearchedValue sv;
      sv.value = v;
      for (int seed = 1; seed <= s.seeds; ++seed) {
        const Point* flowing = nullptr;
        double below = -1.0;
        for (const SearchedValue& earlier : g.values)
          if (earlier.value < v && earlier.value > below && v - earlier.value <= s.from_flowing * (1.0 + 1e-9) &&
              v <= 1.1 * earlier.value &&  // within what particles.initial.compress takes
              // a folder restored from a table (tools/restore_campaign.py) has the record, not the run
              fs::exists(point_dir(out_dir, earlier.points[static_cast<std::size_t>(seed - 1)]) / "run.h5") &&
              read_record(point_dir(out_dir, earlier.points[static_cast<std::size_t>(seed - 1)])).status == "done") {
            below = earlier.value;
            flowing = &earlier.points[static_cast<std::size_t>(seed - 1)];
          }
        std::vector<Assignment> start;
        if (flowing)
          start = started_from("{from: file, file: " +
                               fs::absolute(point_dir(out_dir, *flowing) / "run.h5").lexically_normal().string() +
                               ", compress: true}");
        Point p = c.make_point(at_value(group, s, v, seed), start);
        // (the folder is named by the parameters alone, so the record is found whatever the start)
        const PointRecord record = read_record(point_dir(out_dir, p));
        const std::string& status = record.status;
        // A finished point whose source run is gone (a folder restored from a table) started where its record
        // says: listed so, not validated.
        if (!flowing && !record.initial.empty() && (status == "done" || status == "jammed" || status == "failed")) {
          const std::vector<Assignment> recorded = started_from(record.initial);
          p.parameters.insert(p.parameters.end(), recorded.begin(), recorded.end());
        }
        if (status == "done") ++sv.flowed;
        else if (status == "jammed") ++sv.jammed;
        else if (status == "failed") g.state = "stopped: point " + p.name + " failed (see its log; --retry-failed)";
        sv.points.push_back(p);
      }
      g.values.push_back(sv);
      return &g.values.back();
    };
    // Both ends first (together), then bisection on the grid.
    const SearchedValue lo = *visit(s.lo);
    const SearchedValue hi = *visit(s.hi);
    if (!g.state.empty()) {
      plan.push_back(std::move(g));
      continue;
    }
    if (!lo.decided() || !hi.decided()) {
      g.state = "searching";
      if (!lo.decided()) g.next.push_back(s.lo);
      if (!hi.decided()) g.next.push_back(s.hi);
      plan.push_back(std::move(g));
      continue;
    }
    const std::string& key = c.search->key;
    if (!s.flows_above && !lo.flows()) g.state = "below lo: " + key + " = " + format_value(s.lo) + " already jams";
    else if (!s.flows_above && hi.flows()) g.state = "above hi: " + key + " = " + format_value(s.hi) + " still flows";
    else if (s.flows_above && lo.flows()) g.state = "below lo: " + key + " = " + format_value(s.lo) + " still flows";
    else if (s.flows_above && !hi.flows()) g.state = "above hi: " + key + " = " + format_value(s.hi) + " already jams";
    if (!g.state.empty()) {
      plan.push_back(std::move(g));
      continue;
    }
    g.bracketed = true;
    g.flow_end = s.flows_above ? s.hi : s.lo;
    g.jam_end = s.flows_above ? s.lo : s.hi;
    const double grid = s.grid();
    for (;;) {
      const double bottom = std::min(g.flow_end, g.jam_end), top = std::max(g.flow_end, g.jam_end);
      if (top - bottom <= s.tolerance * (1.0 + 1e-9)) {
        g.state = "converged";
        break;
      }
      // The midpoint on the grid, strictly inside the bracket.
      const double steps = std::round((0.5 * (bottom + top) - s.lo) / grid);
      const double mid = std::round((s.lo + steps * grid) * 1e9) / 1e9;
      if (!(mid > bottom + 1e-12 && mid < top - 1e-12)) {
        g.state = "converged";
        break;
      }
      const SearchedValue m = *visit(mid);
      if (!g.state.empty()) break;
      if (!m.decided()) {
        g.state = "searching";
        g.next.push_back(mid);
        break;
      }
      (m.flows() ? g.flow_end : g.jam_end) = mid;
    }
    plan.push_back(std::move(g));
  }
  return plan;
}

Campaign with_search_points(const Campaign& c, const std::vector<GroupSearch>& plan) {
  Campaign out = c;
  out.points.clear();
  for (const GroupSearch& g : plan)
    for (const SearchedValue& v : g.values) out.points.insert(out.points.end(), v.points.begin(), v.points.end());
  return out;
}

int points_to_come(const Campaign& c, const std::vector<GroupSearch>& plan) {
  if (!c.search) return 0;
  const Search& s = *c.search;
  // Halvings that bring a bracket of this width within the tolerance.
  auto rounds = [&](double width) {
    return width <= s.tolerance * (1.0 + 1e-9) ? 0 : static_cast<int>(std::ceil(std::log2(width / s.tolerance) - 1e-9));
  };
  int points = 0;
  for (const GroupSearch& g : plan) {
    if (g.state != "searching") continue;
    // Not yet bracketed: the two ends are the planned values, every halving of hi - lo is to come. Bracketed: the
    // planned midpoint is the first halving.
    const int to_come = g.bracketed ? rounds(std::abs(g.jam_end - g.flow_end)) - 1 : rounds(s.hi - s.lo);
    points += s.seeds * std::max(0, to_come);
  }
  return points;
}

std::string describe_search(const Campaign& c, const std::vector<GroupSearch>& plan) {
  std::string out;
  for (const GroupSearch& g : plan) {
    std::string line = g.name + ": ";
    line += g.state;
    if (g.bracketed)
      line += ", bracket [" + format_value(std::min(g.flow_end, g.jam_end)) + ", " +
              format_value(std::max(g.flow_end, g.jam_end)) + "]" +
              (c.search->flows_above ? " (flows above)" : "");
    if (!g.next.empty()) {
      line += ", next";
      for (double v : g.next) {
        line += ' ';
        line += format_value(v);
      }
      line += " (" + std::to_string(c.search->seeds) + " seed(s) each)";
    }
    out += line + "\n";
  }
  return out;
}

int run_search_sweep(const Campaign& c, const SweepOptions& o) {
  int code = 0;
  std::size_t finished_before = static_cast<std::size_t>(-1);
  for (;;) {
    const std::vector<GroupSearch> plan = plan_search(c, o.out_dir);
    const Campaign round = with_search_points(c, plan);
    std::size_t finished = 0, to_run = 0;
    for (const Point& p : round.points) {
      const std::string s = read_record(point_dir(o.out_dir, p)).status;
      if (s == "done" || s == "jammed") ++finished;
      else if (s != "failed" || o.retry_failed) ++to_run;
    }
    // Nothing left, or a round that ended nothing (its points held by another process): the search waits for them.
    if (to_run == 0 || finished == finished_before) {
      check_and_record_points(round, o.out_dir);
      write_table(round, o.out_dir);
      if (!o.quiet) std::printf("%s", describe_search(c, plan).c_str()), std::fflush(stdout);
      return code;
    }
    finished_before = finished;
    if (!o.quiet) std::printf("%s", describe_search(c, plan).c_str()), std::fflush(stdout);
    code = run_sweep(round, o);
    if (code > 128 || code == exit_output_error) return code;  // stopped, the disk full, or the program missing
  }
}

}  // namespace suspend::campaign
