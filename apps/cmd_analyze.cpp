// `suspend analyze RUN_DIR [--snapshot K|last|all] [--json] [--no-distributions] [--bins N] [--profile]`: the
// microstructure of a run's snapshots (analysis/report.hpp; docs/output.md, "Microstructure"): a line per snapshot,
// or with --json an array of one object per snapshot; --profile adds the mean gradient profile.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/report.hpp"
#include "apps/commands.hpp"
#include "apps/run_argument.hpp"
#include "core/error.hpp"
#include "io/hdf5.hpp"
#include "io/snapshot_reader.hpp"

namespace suspend::app {

using json = nlohmann::ordered_json;

namespace {

std::vector<std::size_t> chosen_snapshots(const std::string& choice, std::size_t count, const std::string& file) {
  if (count == 0) throw InputError("analyze: " + file + " has no snapshots");
  if (choice == "all") {
    std::vector<std::size_t> all(count);
    for (std::size_t k = 0; k < count; ++k) all[k] = k;
    return all;
  }
  if (choice == "last") return {count - 1};
  std::size_t used = 0;
  long k = -1;
  try {
    k = std::stol(choice, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != choice.size() || k < 0 || static_cast<std::size_t>(k) >= count)
    throw InputError("analyze: --snapshot '" + choice + "': allowed are 0 to " + std::to_string(count - 1) +
                     ", last or all");
  return {static_cast<std::size_t>(k)};
}

std::string axes(const json& p) {
  std::string s;
  for (const char* a : {"x", "y", "z"})
    if (p[a].get<bool>()) s += a;
  return s.empty() ? "-" : s;
}

struct AnalyzeOptions {
  std::string run, snapshot = "last";
  bool json_output = false, no_distributions = false, profile = false;
  int bins = 8;
};

// The gradient profiles of the chosen snapshots averaged: phi and the particle count per slab, and u_x in units of
// each snapshot's own shear rate (so that snapshots of a stress-controlled run, whose rate fluctuates, average to
// y - y_0 for a homogeneous shear), with the slope between neighbouring slabs over the mean slope (1 everywhere
// without banding).
void print_mean_profile(const json& all) {
  const json& first = all.front()["gradient_profile"];
  const std::size_t bins = first["y"].size();
  std::vector<double> phi(bins, 0.0), count(bins, 0.0), y(bins, 0.0), u(bins, 0.0);
  std::vector<int> y_n(bins, 0), u_n(bins, 0);
  for (const json& r : all) {
    const json& g = r["gradient_profile"];
    const double rate = g["shear_rate"].is_number() ? g["shear_rate"].get<double>() : 0.0;
    for (std::size_t k = 0; k < bins; ++k) {
      phi[k] += g["phi"][k].get<double>() / all.size();
      count[k] += g["count"][k].get<double>() / all.size();
      if (!g["mean_y"][k].is_number()) continue;
      y[k] += g["mean_y"][k].get<double>();
      ++y_n[k];
      if (rate != 0.0 && g["velocity"][k].is_number()) {
        u[k] += g["velocity"][k].get<double>() / rate;
        ++u_n[k];
      }
    }
  }
  std::vector<double> slope(bins, std::nan(""));
  double first_y = 0.0, last_y = 0.0, first_u = 0.0, last_u = 0.0;
  bool any = false;
  for (std::size_t k = 0; k < bins; ++k) {
    y[k] = y_n[k] ? y[k] / y_n[k] : std::nan("");
    u[k] = u_n[k] ? u[k] / u_n[k] : std::nan("");
    if (std::isfinite(u[k])) {
      if (!any) first_y = y[k], first_u = u[k];
      last_y = y[k], last_u = u[k];
      any = true;
    }
  }
  const double mean_slope = last_y > first_y ? (last_u - first_u) / (last_y - first_y) : std::nan("");
  for (std::size_t k = 0; k + 1 < bins; ++k)
    if (std::isfinite(u[k]) && std::isfinite(u[k + 1]) && y[k + 1] > y[k])
      slope[k] = (u[k + 1] - u[k]) / (y[k + 1] - y[k]) / mean_slope;
  std::printf("\ngradient profile, mean of %zu snapshot(s), %zu slabs of width %.4g across y:\n", all.size(), bins,
              first["width"].get<double>());
  std::printf("%9s %8s %10s %12s %22s\n", "y", "phi", "particles", "u_x/rate", "slope to next / mean");
  for (std::size_t k = 0; k < bins; ++k)
    std::printf("%9.4g %8.4f %10.2f %12.4g %22.4g\n", first["y"][k].get<double>(), phi[k], count[k], u[k], slope[k]);
}

// The report of the chosen snapshots, printed.
void analyze(const AnalyzeOptions& opt, const std::string& file) {
  io::h5::File h5 = io::h5::File::open(file, false);
  if (io::h5::exists(h5.id(), "particles/position") && !io::h5::exists(h5.id(), "snapshots"))
    throw InputError("analyze: " + file + " is a checkpoint, not a run; give the run's folder or its run.h5");
  const std::vector<std::size_t> which = chosen_snapshots(opt.snapshot, io::snapshot_count(h5.id()), file);
  analysis::ReportOptions options;
  options.distributions = !opt.no_distributions;
  options.profile_bins = opt.bins;
  // Every snapshot read before anything is printed: a damaged one stops the command with nothing half-written.
  json all = json::array();
  for (std::size_t k : which) {
    json r;
    r["snapshot"] = k;
    r.update(analysis::report(io::read_configuration(h5.id(), k), options));
    all.push_back(std::move(r));
  }
  if (!opt.json_output)
    std::printf("%8s %9s %7s %8s %8s %8s %8s %7s %10s %12s\n", "snapshot", "strain", "Z", "rattlers", "sliding",
                "clusters", "largest", "spans", "fabric_xy", "Sigma^c_xy");
  const auto number = [](const json& v, const char* format) {
    char buf[32] = "-";
    if (v.is_number()) std::snprintf(buf, sizeof buf, format, v.get<double>());
    return std::string(buf);
  };
  for (const json& r : all) {
    if (opt.json_output) break;
    std::printf("%8zu %9.4g %7.3f %8.3f %8s %8zu %8zu %7s %10.4f %12s\n", r["snapshot"].get<std::size_t>(),
                r["strain"].get<double>(), r["contacts_per_particle"].get<double>(),
                r["rattler_fraction"].get<double>(), number(r["sliding_fraction"], "%.3f").c_str(),
                r["clusters"]["count"].get<std::size_t>(), r["clusters"]["largest"].get<std::size_t>(),
                axes(r["clusters"]["percolates"]).c_str(), r["fabric"]["xy"].get<double>(),
                number(r["contact_stress"]["xy"], "%.5g").c_str());
  }
  if (opt.json_output) std::printf("%s\n", all.dump(1).c_str());
  if (!opt.json_output && opt.profile) print_mean_profile(all);
}

}  // namespace

void add_analyze_command(CLI::App& app) {
  auto opt = std::make_shared<AnalyzeOptions>();
  CLI::App* cmd = app.add_subcommand("analyze", "Contact network, clusters, fabric and distributions of a run's snapshots");
  cmd->add_option("run", opt->run, "run directory (or its run.h5)")->required();
  cmd->add_option("--snapshot,-s", opt->snapshot, "snapshot index (from 0), last (default) or all");
  cmd->add_flag("--json", opt->json_output, "print an array of one object per snapshot (docs/output.md)");
  cmd->add_flag("--no-distributions", opt->no_distributions,
                "leave out the force, gap and pair distributions (scalars, tensors and clusters only)");
  cmd->add_option("--bins", opt->bins, "slabs across y of the gradient profile (phi and u_x against y; default 8)")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--profile", opt->profile,
                "also print the gradient profile averaged over the chosen snapshots (shear banding, migration)");
  cmd->callback([opt] {
    const std::string file = run_file_argument(opt->run, "analyze");
    // A damaged or foreign file is bad input naming the file (exit 2), whatever layer finds it.
    try {
      analyze(*opt, file);
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(what.find(file) == std::string::npos ? "analyze: " + file + ": " + what : what);
    } catch (const std::runtime_error& e) {
      throw InputError("analyze: " + file + " is not a readable run (" + e.what() + ")");
    }
  });
}

}  // namespace suspend::app
