// `suspend analyze RUN_DIR [--snapshot K|last|all] [--json] [--no-distributions]`: the microstructure of a run's
// snapshots (analysis/report.hpp; docs/output.md, "Microstructure"): a line per snapshot, or with --json an array
// of one object per snapshot.
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
  bool json_output = false, no_distributions = false;
};

// The report of the chosen snapshots, printed.
void analyze(const AnalyzeOptions& opt, const std::string& file) {
  io::h5::File h5 = io::h5::File::open(file, false);
  if (io::h5::exists(h5.id(), "particles/position") && !io::h5::exists(h5.id(), "snapshots"))
    throw InputError("analyze: " + file + " is a checkpoint, not a run; give the run's folder or its run.h5");
  const std::vector<std::size_t> which = chosen_snapshots(opt.snapshot, io::snapshot_count(h5.id()), file);
  analysis::ReportOptions options;
  options.distributions = !opt.no_distributions;
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
